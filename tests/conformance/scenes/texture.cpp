// Texturing (GL 1.5 3.8): filters, mipmaps and their LOD controls, wrap modes, 1D/3D/cube
// textures, sub-image updates, copies from the framebuffer, sized internal formats, and texture
// objects switched between draws.
#include <cmath>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// A floor receding from the viewer, texture repeated 6 times across: magnified in front,
// minified towards the horizon.
void textured_floor() { receding_floor(6, 12); }

std::vector<uint8_t> coloured_checker(int size) {
  std::vector<uint8_t> out =
      checker(size, size, size / 4, Rgba8{240, 240, 240, 255}, Rgba8{40, 60, 160, 255});
  // A red texel row and a green texel column mark the orientation.
  for (int i = 0; i < size; ++i) {
    uint8_t* row = &out[(1 * size + i) * 4];
    row[0] = 230, row[1] = 40, row[2] = 40;
    uint8_t* col = &out[(i * size + 1) * 4];
    col[0] = 40, col[1] = 200, col[2] = 60;
  }
  return out;
}

void filter_scene(GLenum filter) {
  clear(0.3f, 0.5f, 0.7f);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGB, 16, 16, coloured_checker(16), filter);
  textured_floor();
}

GLPT_SCENE(texture_filter_nearest, 64, 64) { filter_scene(GL_NEAREST); }
GLPT_SCENE(texture_filter_linear, 64, 64) { filter_scene(GL_LINEAR); }

// A 32x32 texture whose mip levels are distinct colours (each with a darker checker), so the
// level chosen at each pixel is visible; magnified with NEAREST.
void coloured_mipmaps(GLenum min_filter) {
  static const Rgba8 kLevelColours[6] = {{255, 255, 255, 255}, {255, 80, 80, 255},
                                         {80, 255, 80, 255},   {80, 80, 255, 255},
                                         {255, 255, 80, 255},  {255, 80, 255, 255}};
  new_texture(GL_TEXTURE_2D, min_filter, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int level = 0, size = 32; size >= 1; ++level, size /= 2) {
    const Rgba8 c = kLevelColours[level];
    const Rgba8 dark{static_cast<uint8_t>(c.r / 2), static_cast<uint8_t>(c.g / 2),
                     static_cast<uint8_t>(c.b / 2), 255};
    const std::vector<uint8_t> texels = checker(size, size, std::max(1, size / 4), c, dark);
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels.data());
  }
}

void mipmap_scene(GLenum min_filter) {
  clear(0.3f, 0.5f, 0.7f);
  glEnable(GL_TEXTURE_2D);
  coloured_mipmaps(min_filter);
  textured_floor();
}

GLPT_SCENE(texture_mipmap_nearest_nearest, 64, 64) { mipmap_scene(GL_NEAREST_MIPMAP_NEAREST); }
GLPT_SCENE(texture_mipmap_linear_nearest, 64, 64) { mipmap_scene(GL_LINEAR_MIPMAP_NEAREST); }
GLPT_SCENE(texture_mipmap_nearest_linear, 64, 64) { mipmap_scene(GL_NEAREST_MIPMAP_LINEAR); }
GLPT_SCENE(texture_mipmap_linear_linear, 64, 64) { mipmap_scene(GL_LINEAR_MIPMAP_LINEAR); }

// LOD controls (GL 1.5 3.8.8): base level 1, LOD clamped to [0.5, 2.5], and a bias of +0.5
// from the texture environment (GL_TEXTURE_FILTER_CONTROL) plus -0.25 from the texture.
GLPT_SCENE(texture_lod_controls, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  glEnable(GL_TEXTURE_2D);
  coloured_mipmaps(GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0.5f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 2.5f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, -0.25f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.5f);
  textured_floor();
}

// Automatic mipmap generation (GL 1.4 GL_GENERATE_MIPMAP) from a fine checker: the minified
// levels average towards grey.
GLPT_SCENE(texture_generate_mipmap, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  glEnable(GL_TEXTURE_2D);
  new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const std::vector<uint8_t> texels =
      gradient(32, 32, Rgba8{255, 40, 40, 255}, Rgba8{40, 255, 40, 255}, Rgba8{40, 40, 255, 255},
               Rgba8{255, 255, 40, 255}, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  textured_floor();
}

// A 4x4 texture with a distinct colour per texel on a quad whose coordinates run from -1 to 2:
// the wrap mode decides what lies outside [0, 1]. LINEAR filtering shows how the edge texels
// blend with the border colour (magenta): GL_CLAMP blends half of it in at the edge,
// GL_CLAMP_TO_EDGE never, GL_CLAMP_TO_BORDER everywhere outside.
void wrap_scene(GLenum wrap) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  glEnable(GL_TEXTURE_2D);
  std::vector<uint8_t> texels(4 * 4 * 4);
  for (int i = 0; i < 16; ++i) {
    texels[i * 4 + 0] = static_cast<uint8_t>(60 + 60 * (i % 4));
    texels[i * 4 + 1] = static_cast<uint8_t>(60 + 60 * (i / 4));
    texels[i * 4 + 2] = static_cast<uint8_t>(i % 3 == 0 ? 220 : 40);
    texels[i * 4 + 3] = 255;
  }
  texture_2d(GL_RGBA, 4, 4, texels, GL_LINEAR, wrap);
  const float border[4] = {1, 0, 1, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1);
  glTexCoord2f(-1, -1);
  glVertex2f(2, 2);
  glTexCoord2f(2, -1);
  glVertex2f(62, 2);
  glTexCoord2f(2, 2);
  glVertex2f(62, 62);
  glTexCoord2f(-1, 2);
  glVertex2f(2, 62);
  glEnd();
}

GLPT_SCENE(texture_wrap_repeat, 64, 64) { wrap_scene(GL_REPEAT); }
GLPT_SCENE(texture_wrap_clamp, 64, 64) { wrap_scene(GL_CLAMP); }
GLPT_SCENE(texture_wrap_clamp_to_edge, 64, 64) { wrap_scene(GL_CLAMP_TO_EDGE); }
GLPT_SCENE(texture_wrap_clamp_to_border, 64, 64) { wrap_scene(GL_CLAMP_TO_BORDER); }
GLPT_SCENE(texture_wrap_mirrored_repeat, 64, 64) { wrap_scene(GL_MIRRORED_REPEAT); }

// A 1D texture (a 16-texel rainbow) across quads, repeated, NEAREST above and LINEAR below.
GLPT_SCENE(texture_1d, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  std::vector<uint8_t> texels(16 * 4);
  for (int i = 0; i < 16; ++i) {
    texels[i * 4 + 0] = static_cast<uint8_t>(i < 8 ? 255 - 30 * i : 30 * (i - 8));
    texels[i * 4 + 1] = static_cast<uint8_t>(i < 8 ? 30 * i : 255 - 30 * (i - 8));
    texels[i * 4 + 2] = static_cast<uint8_t>(i % 2 == 0 ? 200 : 50);
    texels[i * 4 + 3] = 255;
  }
  new_texture(GL_TEXTURE_1D, GL_NEAREST, GL_NEAREST);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glEnable(GL_TEXTURE_1D);
  for (int row = 0; row < 2; ++row) {
    const GLint filter = row == 0 ? GL_NEAREST : GL_LINEAR;
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, filter);
    const float y0 = row == 0 ? 34.0f : 4.0f;
    glBegin(GL_QUADS);
    glTexCoord1f(-0.25f);
    glVertex2f(4, y0);
    glTexCoord1f(1.5f);
    glVertex2f(60, y0 + 4);
    glTexCoord1f(1.5f);
    glVertex2f(60, y0 + 26);
    glTexCoord1f(-0.25f);
    glVertex2f(4, y0 + 22);
    glEnd();
  }
}

// An 8x8x8 3D texture (red along s, green along t, blue along r, with a checker): three quads
// at r = 0.1, 0.5 and 0.9 and one whose r varies across it, LINEAR filtering.
GLPT_SCENE(texture_3d, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  constexpr int kSize = 8;
  std::vector<uint8_t> texels(kSize * kSize * kSize * 4);
  for (int z = 0; z < kSize; ++z) {
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        uint8_t* p = &texels[((z * kSize + y) * kSize + x) * 4];
        const bool dark = (x / 2 + y / 2 + z / 2) % 2 == 1;
        p[0] = static_cast<uint8_t>((x * 255 / 7) / (dark ? 2 : 1));
        p[1] = static_cast<uint8_t>((y * 255 / 7) / (dark ? 2 : 1));
        p[2] = static_cast<uint8_t>((z * 255 / 7) / (dark ? 2 : 1));
        p[3] = 255;
      }
    }
  }
  new_texture(GL_TEXTURE_3D, GL_LINEAR, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, kSize, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texels.data());
  glEnable(GL_TEXTURE_3D);
  const float slices[3] = {0.1f, 0.5f, 0.9f};
  for (int i = 0; i < 3; ++i) {
    const float x0 = 2.0f + 21.0f * i;
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, slices[i]);
    glVertex2f(x0, 34);
    glTexCoord3f(1, 0, slices[i]);
    glVertex2f(x0 + 18, 34);
    glTexCoord3f(1, 1, slices[i]);
    glVertex2f(x0 + 18, 62);
    glTexCoord3f(0, 1, slices[i]);
    glVertex2f(x0, 62);
    glEnd();
  }
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0.2f, 0);
  glVertex2f(2, 4);
  glTexCoord3f(1, 0.2f, 1);
  glVertex2f(62, 4);
  glTexCoord3f(1, 0.8f, 1);
  glVertex2f(62, 30);
  glTexCoord3f(0, 0.8f, 0);
  glVertex2f(2, 30);
  glEnd();
}

// Fills the six faces of the cube map bound to GL_TEXTURE_CUBE_MAP: a face colour each with a
// white cross marking the face's centre.
void cube_map_faces(int size) {
  static const Rgba8 kFaceColours[6] = {{230, 60, 60, 255}, {60, 230, 230, 255},
                                        {60, 230, 60, 255}, {230, 60, 230, 255},
                                        {60, 60, 230, 255}, {230, 230, 60, 255}};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int face = 0; face < 6; ++face) {
    std::vector<uint8_t> texels =
        checker(size, size, size / 4, kFaceColours[face],
                Rgba8{static_cast<uint8_t>(kFaceColours[face].r / 2),
                      static_cast<uint8_t>(kFaceColours[face].g / 2),
                      static_cast<uint8_t>(kFaceColours[face].b / 2), 255});
    for (int i = 0; i < size; ++i) {
      for (const int index : {(size / 2) * size + i, i * size + size / 2}) {
        texels[index * 4] = texels[index * 4 + 1] = texels[index * 4 + 2] = 255;
      }
    }
    glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA, size, size,
                 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
}

// A cube map sampled with explicit (s, t, r) = the direction from the centre of a rotated cube
// through each vertex: each face of the cube shows one face of the map.
GLPT_SCENE(texture_cube_map, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  perspective(40.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  new_texture(GL_TEXTURE_CUBE_MAP, GL_NEAREST, GL_NEAREST);
  cube_map_faces(16);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glTranslatef(0, 0, -4);
  glRotatef(30, 1, 0, 0);
  glRotatef(35, 0, 1, 0);
  // The cube's corners, with texture coordinates equal to their positions.
  static const int kFaces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                   {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  glBegin(GL_QUADS);
  for (const auto& face : kFaces) {
    for (const int corner : face) {
      const float x = (corner & 1) ? 1.0f : -1.0f;
      const float y = (corner & 2) ? 1.0f : -1.0f;
      const float z = (corner & 4) ? 1.0f : -1.0f;
      glTexCoord3f(x, y, z);
      glVertex3f(x, y, z);
    }
  }
  glEnd();
}

// glTexSubImage2D replaces a block of an existing texture; GL_UNPACK_ROW_LENGTH and
// SKIP_PIXELS/ROWS select that block from a larger client image.
GLPT_SCENE(texture_sub_image, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGBA, 16, 16,
             checker(16, 16, 4, Rgba8{220, 220, 220, 255}, Rgba8{60, 60, 60, 255}));
  const std::vector<uint8_t> patch = gradient(12, 12, Rgba8{255, 0, 0, 255}, Rgba8{0, 255, 0, 255},
                                              Rgba8{0, 0, 255, 255}, Rgba8{255, 255, 0, 255}, 0);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 12);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 5, 2, 8, 6, GL_RGBA, GL_UNSIGNED_BYTE, patch.data());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glColor3f(1, 1, 1);
  quad(0, 0, 64, 64);
}

// glCopyTexImage2D and glCopyTexSubImage2D take texels from the colour buffer: a pattern is
// drawn, copied into a texture, the buffer cleared, and the texture drawn on rotated quads.
GLPT_SCENE(texture_copy_from_framebuffer, 64, 64) {
  clear(0.1f, 0.1f, 0.4f);
  ortho_pixels(64, 64);
  glShadeModel(GL_SMOOTH);
  rgb_triangle(0, 0, 16, 0, 0, 16);
  glColor3f(1, 1, 0);
  glRectf(20, 20, 28, 28);
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 16, 16, 0);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 8, 8, 18, 18, 8, 8);  // part of the yellow square
  clear(0.2f, 0.2f, 0.2f);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
  quad(4, 4, 36, 36);
  glTranslatef(46, 44, 0);
  glRotatef(30, 0, 0, 1);
  quad(-14, -14, 14, 14);
}

// Sized internal formats: the implementation chooses the storage (GL 1.5 3.8.1), and Mesa's
// choice shows in the quantization of a smooth gradient: RGBA4, RGB5_A1, R3_G3_B2,
// LUMINANCE4_ALPHA4 and RGB10_A2 next to RGBA8.
// Measured 97.7%: GL_NEAREST with pixel centres exactly on texel edges (30-pixel quads over 16
// texels: s*16 = 4.0, 8.0, 12.0). Mesa renders window buffers y-flipped, so llvmpipe's attribute
// planes round there to just below the edge (the lower texel wins); glpt takes the upper. glpt
// is bit-identical to OSMesa drawing the same scene into an FBO (0 pixels differ).
GLPT_SCENE_TOLERANCE(texture_sized_internal_formats, 128, 64,
                     glpt::conformance::relaxed(0.97, 2,
                                                "GL_NEAREST exactly on texel edges: which texel "
                                                "wins depends on llvmpipe's flipped-y "
                                                "interpolation rounding")) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(128, 64);
  glEnable(GL_TEXTURE_2D);
  const std::vector<uint8_t> texels =
      gradient(16, 16, Rgba8{255, 0, 30, 255}, Rgba8{20, 255, 0, 128}, Rgba8{0, 40, 255, 60},
               Rgba8{255, 255, 200, 0}, 0);
  const GLenum formats[6] = {GL_RGBA8,   GL_RGBA4, GL_RGB5_A1, GL_R3_G3_B2, GL_LUMINANCE4_ALPHA4,
                             GL_RGB10_A2};
  for (int i = 0; i < 6; ++i) {
    new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(formats[i]), 16, 16, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texels.data());
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    const float x = 2.0f + 42.0f * static_cast<float>(i % 3);
    const float y = i < 3 ? 33.0f : 1.0f;
    quad(x, y, x + 30, y + 30);  // 30 px for 16 texels: no texel edge on a pixel centre
  }
}

// Texture objects switched between draws in one frame, one deleted and its name reused.
GLPT_SCENE(texture_objects_switched_between_draws, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  glEnable(GL_TEXTURE_2D);
  const GLuint a =
      texture_2d(GL_RGB, 4, 4, checker(4, 4, 1, Rgba8{255, 0, 0, 255}, Rgba8{255, 255, 255, 255}));
  const GLuint b =
      texture_2d(GL_RGB, 4, 4, checker(4, 4, 2, Rgba8{0, 0, 255, 255}, Rgba8{255, 255, 0, 255}));
  glColor3f(1, 1, 1);
  glBindTexture(GL_TEXTURE_2D, a);
  quad(4, 36, 28, 60);
  glBindTexture(GL_TEXTURE_2D, b);
  quad(36, 36, 60, 60);
  glBindTexture(GL_TEXTURE_2D, a);
  quad(4, 4, 28, 28);
  glDeleteTextures(1, &b);
  // Which names glGenTextures returns is implementation-defined; the last texture takes a name
  // chosen here (GL 1.x allows binding any unused name), so the state dumps agree.
  texture_2d(GL_RGB, 4, 4, checker(4, 4, 1, Rgba8{0, 200, 0, 255}, Rgba8{0, 0, 0, 255}), GL_NEAREST,
             GL_REPEAT, 40);
  quad(36, 4, 60, 28);
}

}  // namespace
