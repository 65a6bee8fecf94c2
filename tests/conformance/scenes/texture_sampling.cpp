// Texture sampling where GL state has no direct Vulkan equivalent and raster mode reproduces
// llvmpipe's sampler itself (rt_core/raster/sampler_setup.hpp): GL_CLAMP with nearest, linear
// and mixed filters, border colours of each base format, different minification and
// magnification filters without mipmaps, and depth comparison (GL_ARB_shadow).
#include <algorithm>
#include <cmath>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// 4x4 texels of distinct colours.
std::vector<uint8_t> distinct_texels() {
  std::vector<uint8_t> texels(4 * 4 * 4);
  for (int i = 0; i < 16; ++i) {
    texels[i * 4 + 0] = static_cast<uint8_t>(60 + 60 * (i % 4));
    texels[i * 4 + 1] = static_cast<uint8_t>(60 + 60 * (i / 4));
    texels[i * 4 + 2] = static_cast<uint8_t>(i % 3 == 0 ? 220 : 40);
    texels[i * 4 + 3] = static_cast<uint8_t>(255 - 10 * i);
  }
  return texels;
}

// A floor receding from the viewer with texture coordinates (s, t, r) = (s0..s1, t0..t1, 0.3).
void receding_floor(float s0, float t0, float s1, float t1) {
  perspective(60.0, 1.0, 0.3, 30.0);
  glTranslatef(0, -0.6f, -1.0f);
  glRotatef(-75, 1, 0, 0);
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1);
  glTexCoord3f(s0, t0, 0.3f);
  glVertex3f(-2, -0.5f, 0);
  glTexCoord3f(s1, t0, 0.3f);
  glVertex3f(2, -0.5f, 0);
  glTexCoord3f(s1, t1, 0.3f);
  glVertex3f(2, 12, 0);
  glTexCoord3f(s0, t1, 0.3f);
  glVertex3f(-2, 12, 0);
  glEnd();
}

// A 4x4 texture of distinct texels with GL_CLAMP, `filter` and a magenta border, drawn with
// GL_REPLACE.
void clamped_distinct_texture(GLenum filter) {
  const float border[4] = {1, 0, 1, 1};
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGBA, 4, 4, distinct_texels(), filter, GL_CLAMP);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

// GL_CLAMP with GL_NEAREST samples the edge texels beyond [0, 1] and never the border colour
// (magenta): gallivm treats it as GL_CLAMP_TO_EDGE. Coordinates run from -1 to 2 over 48 pixels,
// so pixel centres fall exactly on s = 1 and t = 1. Left: a 2D texture; right: a 1D texture
// (the last texel repeats to the right edge).
GLPT_SCENE(texture_sampling_clamp_nearest, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  clamped_distinct_texture(GL_NEAREST);
  textured_quad(2, 2, 50, 50, -1, -1, 2, 2);
  glDisable(GL_TEXTURE_2D);
  const float border[4] = {1, 0, 1, 1};
  new_texture(GL_TEXTURE_1D, GL_NEAREST, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  glTexParameterfv(GL_TEXTURE_1D, GL_TEXTURE_BORDER_COLOR, border);
  const std::vector<uint8_t> texels = distinct_texels();
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data() + 16);
  glEnable(GL_TEXTURE_1D);
  glBegin(GL_QUADS);
  glTexCoord1f(-1);
  glVertex2f(52, 2);
  glVertex2f(62, 2);
  glTexCoord1f(2);
  glVertex2f(62, 62);
  glVertex2f(52, 62);
  glEnd();
}

// GL_CLAMP with GL_LINEAR blends the edge texels half with the border (magenta) and is the
// border beyond; the pixel centres fall exactly on the texel edges at s, t = 0 and 1.
GLPT_SCENE(texture_sampling_clamp_linear, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  clamped_distinct_texture(GL_LINEAR);
  textured_quad(2, 2, 62, 62, -0.5f, -0.5f, 1.5f, 1.5f);
}

// GL_CLAMP with a linear minification and a nearest magnification filter (and the other way
// round below): on a floor receding from the viewer the near part is magnified (nearest: edge
// texels, no border) and the far part minified (linear: blended with the border, magenta).
void clamp_mixed_scene(GLenum min_filter, GLenum mag_filter) {
  clear(0.3f, 0.5f, 0.7f);
  const float border[4] = {1, 0, 1, 1};
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGBA, 8, 8, checker(8, 8, 2, Rgba8{240, 240, 240, 255}, Rgba8{40, 60, 160, 255}),
             GL_NEAREST, GL_CLAMP);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min_filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag_filter));
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  receding_floor(-0.2f, -0.1f, 1.2f, 1.1f);
}

GLPT_SCENE(texture_sampling_clamp_min_linear_mag_nearest, 64, 64) {
  clamp_mixed_scene(GL_LINEAR, GL_NEAREST);
}
GLPT_SCENE(texture_sampling_clamp_min_nearest_mag_linear, 64, 64) {
  clamp_mixed_scene(GL_NEAREST, GL_LINEAR);
}

// Without mipmaps the lod still chooses between a nearest minification and a linear
// magnification filter: a floor (16 texels repeated 6 times across) sharp in the distance and
// smooth in front.
GLPT_SCENE(texture_sampling_min_nearest_mag_linear, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGB, 16, 16, checker(16, 16, 4, Rgba8{240, 240, 240, 255}, Rgba8{40, 60, 160, 255}),
             GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  receding_floor(0, 0, 2, 12);
}

// The border colour of each base format (st_translate_color: RGB has alpha 1, ALPHA no colour,
// LUMINANCE and INTENSITY repeat red), clamped to [0, 1] (a component of 1.5 and one of -0.25):
// one quad per internal format with GL_CLAMP_TO_BORDER, LINEAR, coordinates -0.5 to 1.5, drawn
// with GL_REPLACE so colour and alpha show the texture's.
GLPT_SCENE(texture_sampling_border_color_formats, 128, 64) {
  clear(0.2f, 0.2f, 0.2f, 0.5f);
  ortho_pixels(128, 64);
  glEnable(GL_TEXTURE_2D);
  const std::vector<uint8_t> texels = gradient(4, 4, Rgba8{255, 0, 30, 255}, Rgba8{20, 255, 0, 128},
                                               Rgba8{0, 40, 255, 60}, Rgba8{255, 255, 200, 0}, 0);
  const GLenum formats[8] = {
      GL_RGBA8,      GL_RGB8,     GL_ALPHA8, GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8,
      GL_INTENSITY8, GL_R3_G3_B2, GL_RGBA4};
  const float border[4] = {0.1f, 1.5f, 0.5f, -0.25f};
  const float border2[4] = {0.8f, 0.3f, 0.6f, 0.7f};
  glColor4f(0.9f, 0.6f, 0.3f, 0.4f);
  for (int i = 0; i < 8; ++i) {
    texture_2d(formats[i], 4, 4, texels, GL_LINEAR, GL_CLAMP_TO_BORDER);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, i % 2 == 0 ? border : border2);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    const float x = 2.0f + 32.0f * static_cast<float>(i % 4);
    const float y = i < 4 ? 34.0f : 2.0f;
    textured_quad(x, y, x + 28, y + 28, -0.5f, -0.5f, 1.5f, 1.5f);
  }
}

// A 4x4 depth texture of four depths (0.2, 0.4, 0.6, 0.8 by column) compared with an r that
// runs from -0.2 to 1.2 across each quad (clamped to [0, 1] as Mesa's normalized depth formats
// do): one row per comparison function (GL_NEVER .. GL_ALWAYS), one column per depth texture
// mode (GL_LUMINANCE, GL_INTENSITY, GL_ALPHA), GL_NEAREST, blended over a grey background.
GLPT_SCENE(texture_sampling_depth_compare_funcs, 96, 128) {
  clear(0.4f, 0.4f, 0.4f, 1.0f);
  ortho_pixels(96, 128);
  GLfloat depth[16];
  for (int i = 0; i < 16; ++i) depth[i] = 0.2f * static_cast<float>(i % 4 + 1);
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1.0f, 0.5f, 0.2f, 1.0f);
  const GLenum modes[3] = {GL_LUMINANCE, GL_INTENSITY, GL_ALPHA};
  for (int func = 0; func < 8; ++func) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(GL_NEVER + func));
    for (int m = 0; m < 3; ++m) {
      glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, static_cast<GLint>(modes[m]));
      const float x = 2.0f + 32.0f * static_cast<float>(m);
      const float y = 2.0f + 16.0f * static_cast<float>(func);
      glBegin(GL_QUADS);
      glTexCoord3f(0, 0, -0.2f);
      glVertex2f(x, y);
      glTexCoord3f(1, 0, 1.2f);
      glVertex2f(x + 28, y);
      glTexCoord3f(1, 1, 1.2f);
      glVertex2f(x + 28, y + 14);
      glTexCoord3f(0, 1, -0.2f);
      glVertex2f(x, y + 14);
      glEnd();
    }
  }
}

// Depth comparison with linear filtering: each of the four texels is compared and the results
// are filtered (percentage-closer). A depth ramp texture compared with a constant r on quads
// with GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP and GL_CLAMP_TO_BORDER (border depth 0.3)
// beyond [0, 1], and a projected lookup (q = 2) of a 1D depth texture.
GLPT_SCENE(texture_sampling_depth_compare_linear, 64, 64) {
  clear(0.1f, 0.1f, 0.3f);
  ortho_pixels(64, 64);
  GLfloat depth[64];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      depth[y * 8 + x] =
          std::fmod(0.13f * static_cast<float>(x) + 0.07f * static_cast<float>(y), 1.0f);
  new_texture(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 8, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  const float border[4] = {0.3f, 0.3f, 0.3f, 0.3f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glEnable(GL_TEXTURE_2D);
  const GLenum wraps[4] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_CLAMP_TO_BORDER};
  glColor3f(1.0f, 0.9f, 0.6f);
  for (int i = 0; i < 4; ++i) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(wraps[i]));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(wraps[i]));
    const float x = i % 2 == 0 ? 2.0f : 33.0f;
    const float y = i < 2 ? 33.0f : 10.0f;
    glBegin(GL_QUADS);
    glTexCoord3f(-0.3f, -0.3f, 0.45f);
    glVertex2f(x, y);
    glTexCoord3f(1.3f, -0.3f, 0.45f);
    glVertex2f(x + 29, y);
    glTexCoord3f(1.3f, 1.3f, 0.45f);
    glVertex2f(x + 29, y + 21);
    glTexCoord3f(-0.3f, 1.3f, 0.45f);
    glVertex2f(x, y + 21);
    glEnd();
  }
  glDisable(GL_TEXTURE_2D);
  new_texture(GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT16, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
  glEnable(GL_TEXTURE_1D);
  glBegin(GL_QUADS);
  glTexCoord4f(0, 0, 0.2f, 2);
  glVertex2f(2, 2);
  glTexCoord4f(2, 0, 1.2f, 2);
  glVertex2f(62, 2);
  glVertex2f(62, 8);
  glTexCoord4f(0, 0, 0.2f, 2);
  glVertex2f(2, 8);
  glEnd();
}

// A mipmapped depth texture compared on a floor receding from the viewer
// (GL_LINEAR_MIPMAP_LINEAR): the comparison of two levels, blended by the lod.
GLPT_SCENE(texture_sampling_depth_compare_mipmapped, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  perspective(60.0, 1.0, 0.3, 30.0);
  glTranslatef(0, -0.6f, -1.0f);
  glRotatef(-75, 1, 0, 0);
  new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  for (int level = 0, size = 16; size >= 1; ++level, size /= 2) {
    std::vector<GLfloat> depth(static_cast<size_t>(size) * size);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        depth[static_cast<size_t>(y * size + x)] =
            ((x / 2 + y / 2) % 2 == 0 ? 0.3f : 0.7f) + 0.05f * static_cast<float>(level);
    glTexImage2D(GL_TEXTURE_2D, level, GL_DEPTH_COMPONENT, size, size, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, depth.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LESS);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1);
  glTexCoord3f(0, 0, 0.5f);
  glVertex3f(-2, -0.5f, 0);
  glTexCoord3f(4, 0, 0.5f);
  glVertex3f(2, -0.5f, 0);
  glTexCoord3f(4, 8, 0.5f);
  glVertex3f(2, 12, 0);
  glTexCoord3f(0, 8, 0.5f);
  glVertex3f(-2, 12, 0);
  glEnd();
}

// Coloured levels (a checker of a colour per level) for a texture of `target` whose level 0 is
// size texels wide (and high and deep for 3D: 8).
void coloured_levels(GLenum target, int size) {
  static const Rgba8 kLevelColours[6] = {{255, 255, 255, 255}, {255, 80, 80, 255},
                                         {80, 255, 80, 255},   {80, 80, 255, 255},
                                         {255, 255, 80, 255},  {255, 80, 255, 255}};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int level = 0, n = size; n >= 1; ++level, n /= 2) {
    const Rgba8 c = kLevelColours[level % 6];
    const Rgba8 dark{static_cast<uint8_t>(c.r / 2), static_cast<uint8_t>(c.g / 2),
                     static_cast<uint8_t>(c.b / 2), 255};
    const int depth = target == GL_TEXTURE_3D ? n : 1;
    const std::vector<uint8_t> plane = checker(n, n, std::max(1, n / 4), c, dark);
    std::vector<uint8_t> texels;
    for (int z = 0; z < depth; ++z) texels.insert(texels.end(), plane.begin(), plane.end());
    if (target == GL_TEXTURE_1D)
      glTexImage1D(target, level, GL_RGBA, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    else if (target == GL_TEXTURE_2D)
      glTexImage2D(target, level, GL_RGBA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    else
      glTexImage3D(target, level, GL_RGBA, n, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
}

// The level of detail of mipmapped 1D and 3D lookups (llvmpipe takes the derivatives from its
// y-flipped quads; raster mode passes that lod explicitly).
GLPT_SCENE(texture_sampling_mipmapped_1d, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_1D, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST);
  coloured_levels(GL_TEXTURE_1D, 32);
  glEnable(GL_TEXTURE_1D);
  receding_floor(0, 0, 6, 12);
}
GLPT_SCENE(texture_sampling_mipmapped_3d, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_3D, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR);
  coloured_levels(GL_TEXTURE_3D, 16);
  glEnable(GL_TEXTURE_3D);
  receding_floor(0, 0, 6, 12);
}

// GL_CLAMP on a mipmapped texture with a lod bias: llvmpipe takes the lod from the unclamped
// coordinates (s from -1 to 2), so the clamped region (constant coordinates) is still minified
// in the distance.
GLPT_SCENE(texture_sampling_mipmapped_clamp_bias, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR);
  coloured_levels(GL_TEXTURE_2D, 32);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.7f);
  const float border[4] = {1, 0, 1, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glEnable(GL_TEXTURE_2D);
  receding_floor(-1, 0, 2, 6);
}

// A 32x32 texture of coloured mip levels with the given filters and anisotropy, enabled.
void coloured_anisotropic_texture(GLenum min_filter, GLenum mag_filter, float anisotropy) {
  new_texture(GL_TEXTURE_2D, min_filter, mag_filter);
  coloured_levels(GL_TEXTURE_2D, 32);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, anisotropy);
  glEnable(GL_TEXTURE_2D);
}

// EXT_texture_filter_anisotropic: a floor receding at a grazing angle, trilinear with at most 4
// lookups along the axis of anisotropy (as trigger-rally sets every texture). gallivm's filter
// run from Mesa's quad derivatives (raster_ff.frag anisotropic_2d); lavapipe's own, from its
// implicit derivatives, had 1.2% of these pixels off by up to 148 levels.
GLPT_SCENE(texture_sampling_anisotropic, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  coloured_anisotropic_texture(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 4.0f);
  receding_floor(0, 0, 6, 12);
}

// Anisotropy 2.5 (Mesa keeps the whole part: 2) on a mipmapped nearest texture, and 16.
GLPT_SCENE(texture_sampling_anisotropic_nearest, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  coloured_anisotropic_texture(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, 2.5f);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 32, 64);
  receding_floor(0, 0, 6, 12);
  glLoadIdentity();
  glScissor(32, 0, 32, 64);
  coloured_anisotropic_texture(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, 16.0f);
  receding_floor(0, 0, 6, 12);
  glDisable(GL_SCISSOR_TEST);
}

// The anisotropic filter's other branches (raster_ff.frag anisotropic_2d): GL_CLAMP_TO_BORDER and
// GL_CLAMP (bilinear lookups reach the border), a lod bias and a maximum lod, on a
// non-power-of-two texture (its levels halve rounding down).
GLPT_SCENE(texture_sampling_anisotropic_border_bias, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  static const Rgba8 kColours[4] = {
      {255, 255, 255, 255}, {255, 80, 80, 255}, {80, 255, 80, 255}, {80, 80, 255, 255}};
  for (int level = 0, w = 45, h = 27; w >= 1 || h >= 1; ++level, w /= 2, h /= 2) {
    const int lw = std::max(w, 1), lh = std::max(h, 1);
    const Rgba8 c = kColours[level % 4];
    const Rgba8 dark{static_cast<uint8_t>(c.r / 2), static_cast<uint8_t>(c.g / 2),
                     static_cast<uint8_t>(c.b / 2), 255};
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, lw, lh, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 checker(lw, lh, 3, c, dark).data());
    if (lw == 1 && lh == 1) break;
  }
  const float border[4] = {1, 0, 1, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.6f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 2.5f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 8.0f);
  glEnable(GL_TEXTURE_2D);
  receding_floor(-0.5f, -0.5f, 1.5f, 5);
}

// Anisotropy with the same texture coordinates over whole quads (one glTexCoord per primitive):
// a footprint of no texels, for which gallivm averages no lookups at all, and a mirrored
// repeat on a floor beside it.
GLPT_SCENE(texture_sampling_anisotropic_constant_coords, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  coloured_anisotropic_texture(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 4.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 40, 64);
  receding_floor(-2, 0, 3, 9);
  glDisable(GL_SCISSOR_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1);
  glTexCoord2f(0.3f, 0.6f);
  glVertex2f(0.3f, 0.2f);
  glVertex2f(0.9f, 0.2f);
  glVertex2f(0.9f, 0.9f);
  glVertex2f(0.3f, 0.9f);
  glEnd();
}

// A projective lookup (q varies across the primitive) with anisotropy: the filter takes the
// coordinates after the division by q.
GLPT_SCENE(texture_sampling_anisotropic_projective, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  coloured_anisotropic_texture(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 16.0f);
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1);
  glTexCoord4f(0, 0, 0, 1);
  glVertex2f(-0.9f, -0.9f);
  glTexCoord4f(6, 0, 0, 1);
  glVertex2f(0.9f, -0.9f);
  glTexCoord4f(1.2f, 1.2f, 0, 0.2f);
  glVertex2f(0.9f, 0.9f);
  glTexCoord4f(0, 0.2f, 0, 0.2f);
  glVertex2f(-0.9f, 0.9f);
  glEnd();
}

}  // namespace

namespace {
// `size` x `size` texels of fine detail and alpha stripes, with every mip level given.
void detailed_levels(int size) {
  for (int level = 0, s = size; s >= 1; ++level, s /= 2) {
    std::vector<uint8_t> texels(static_cast<size_t>(s) * s * 4);
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x) {
        const unsigned h = (static_cast<unsigned>(x * 7 + y * 13 + level * 5) * 2654435761u) >> 24;
        uint8_t* t = &texels[(static_cast<size_t>(y) * s + x) * 4];
        t[0] = t[1] = t[2] = static_cast<uint8_t>(h);
        t[3] = static_cast<uint8_t>(((x / 3 + y / 5) & 1) ? 255 : 40);
      }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
}
}  // namespace

// A glyph atlas as trigger-rally's HUD draws it (its numbers: a 1024x1024 atlas with its own mip
// levels, trilinear, anisotropy 4, cells of 1/12 x 1/8 minified about 4.3 times under glOrtho in
// a 640x480 viewport whose top row is the window's), blended over the clear colour under the game's
// fog (exponential, at eye distance 0), culling and depth range. gallivm's anisotropic filter
// spreads its lookups along the longer of the pixel's two derivatives; a glyph minified equally
// in both directions has two equal lengths, and which one wins turns on the last bits of the
// interpolated coordinates, which llvmpipe computes in Mesa's upside-down frame. Drawn upright,
// 99.85 % of the pixels were within 2/255 of Mesa and the rest up to 42 levels apart (what kept
// trigger-rally's HUD text from equalling Mesa's); such draws are now rasterized upside down as
// Mesa does (rt_core/raster/mesa_orientation.cpp), and every pixel must equal Mesa's.
void minified_atlas_anisotropic();
constexpr glpt::conformance::Tolerance kAtlasExact = glpt::conformance::relaxed(
    1.0, 0,
    "exact: the anisotropic filter's ties follow Mesa's interpolation (mesa_orientation.cpp)");
GLPT_SCENE_TOLERANCE(texture_sampling_minified_atlas_anisotropic, 256, 192, kAtlasExact) {
  minified_atlas_anisotropic();
}
// The same in a window of odd height, where Mesa's quads straddle two of an upright buffer's
// rows: upside down they are the same rows.
GLPT_SCENE_TOLERANCE(texture_sampling_minified_atlas_anisotropic_odd_height, 256, 191,
                     kAtlasExact) {
  minified_atlas_anisotropic();
}
void minified_atlas_anisotropic() {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 4.0f);
  detailed_levels(1024);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_DENSITY, 0.002f);
  glEnable(GL_CULL_FACE);
  glDepthRange(0, 0.999);
  glViewport(0, -288, 640, 480);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.333333333333333, 1.333333333333333, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(-1.266667f, 0.89f, 0);
  glScalef(0.125f, 0.125f, 1);
  glTranslatef(0, -1, 0);
  for (int i = 0; i < 4; ++i) {
    glBegin(GL_TRIANGLE_STRIP);
    glTexCoord2f(0.3333333f, 0.375f);
    glVertex2f(0, 0);
    glTexCoord2f(0.4166667f, 0.375f);
    glVertex2f(0.6666667f, 0);
    glTexCoord2f(0.3333333f, 0.5f);
    glVertex2f(0, 1);
    glTexCoord2f(0.4166667f, 0.5f);
    glVertex2f(0.6666667f, 1);
    glEnd();
    glTranslatef(0.6666667f, 0, 0);
  }
  glDisable(GL_BLEND);
}
