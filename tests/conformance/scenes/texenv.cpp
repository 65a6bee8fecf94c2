// Texture environments (GL 1.5 3.13): MODULATE, DECAL, BLEND, REPLACE and ADD with every base
// internal format (table 3.22), COMBINE with each function, source, operand and scale
// (table 3.23-3.24), and two texture units.
#include <cmath>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// An 8x8 texture whose colour and alpha both vary: red (luminance, intensity) differs at each
// corner, alpha falls from bottom-left to top-right.
std::vector<uint8_t> varied_texels() {
  return gradient(8, 8, Rgba8{255, 40, 40, 255}, Rgba8{40, 255, 60, 90}, Rgba8{60, 80, 255, 200},
                  Rgba8{255, 230, 80, 20}, 0);
}

// A 24x24 quad (3 pixels per texel: no texel boundary on a pixel centre) at (x, y) with a
// different primary colour and alpha at each corner.
void textured_quad(float x, float y, float size = 24) {
  glBegin(GL_QUADS);
  glColor4f(0.7f, 0.7f, 0.7f, 1);
  glTexCoord2f(0, 0);
  glVertex2f(x, y);
  glColor4f(0.8f, 0.2f, 0.2f, 0.8f);
  glTexCoord2f(1, 0);
  glVertex2f(x + size, y);
  glColor4f(0.2f, 0.7f, 0.3f, 0.3f);
  glTexCoord2f(1, 1);
  glVertex2f(x + size, y + size);
  glColor4f(0.3f, 0.3f, 0.9f, 0.6f);
  glTexCoord2f(0, 1);
  glVertex2f(x, y + size);
  glEnd();
}

// A COMBINE function and up to three sources for RGB or alpha (0: leave the source as it is).
struct Combiner {
  GLenum function;
  GLenum sources[3];
};

// Selects GL_COMBINE with the given RGB and alpha combiners (GL 1.5 table 3.23).
void combine(const Combiner& rgb, const Combiner& alpha) {
  static const GLenum kRgbSources[3] = {GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB};
  static const GLenum kAlphaSources[3] = {GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA};
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, static_cast<GLint>(rgb.function));
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, static_cast<GLint>(alpha.function));
  for (int i = 0; i < 3; ++i) {
    if (rgb.sources[i] != 0)
      glTexEnvi(GL_TEXTURE_ENV, kRgbSources[i], static_cast<GLint>(rgb.sources[i]));
    if (alpha.sources[i] != 0)
      glTexEnvi(GL_TEXTURE_ENV, kAlphaSources[i], static_cast<GLint>(alpha.sources[i]));
  }
}

// One quad per base internal format, each with the same texels, in a 4 x 2 grid of 32-pixel
// cells; alpha is part of the read-back image.
void env_mode_scene(GLenum mode, bool colour_formats_only) {
  clear(0.2f, 0.2f, 0.2f, 1.0f);
  ortho_pixels(128, 64);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(mode));
  tex_env_colour(0.2f, 0.6f, 1.0f, 0.5f);
  const GLenum formats[6] = {GL_RGB,   GL_RGBA,     GL_LUMINANCE, GL_LUMINANCE_ALPHA,
                             GL_ALPHA, GL_INTENSITY};
  const std::vector<uint8_t> texels = varied_texels();
  // DECAL is defined for RGB and RGBA only (GL 1.5 table 3.22).
  const int count = colour_formats_only ? 2 : 6;
  for (int i = 0; i < count; ++i) {
    texture_2d(formats[i], 8, 8, texels);
    textured_quad(4.0f + 32.0f * static_cast<float>(i % 4),
                  36.0f - 32.0f * static_cast<float>(i / 4));
  }
}

GLPT_SCENE(texenv_modulate, 128, 64) { env_mode_scene(GL_MODULATE, false); }
GLPT_SCENE(texenv_decal, 128, 64) { env_mode_scene(GL_DECAL, true); }
GLPT_SCENE(texenv_blend, 128, 64) { env_mode_scene(GL_BLEND, false); }
GLPT_SCENE(texenv_replace, 128, 64) { env_mode_scene(GL_REPLACE, false); }
GLPT_SCENE(texenv_add, 128, 64) { env_mode_scene(GL_ADD, false); }

// COMBINE with one function for RGB and alpha: Arg0 = texture, Arg1 = `source1` (the primary
// colour, or the constant colour), Arg2 = the constant colour (INTERPOLATE's weight), on a
// 48x48 quad.
void combine_scene(GLenum rgb_function, GLenum alpha_function, GLenum source1 = GL_PRIMARY_COLOR) {
  clear(0.2f, 0.2f, 0.2f, 1.0f);
  ortho_pixels(64, 64);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGBA, 8, 8, varied_texels());
  combine({rgb_function, {GL_TEXTURE, source1, GL_CONSTANT}},
          {alpha_function, {GL_TEXTURE, source1, GL_CONSTANT}});
  tex_env_colour(0.25f, 0.5f, 0.75f, 0.4f);
  textured_quad(8, 8, 48);
}

GLPT_SCENE(texenv_combine_replace, 64, 64) { combine_scene(GL_REPLACE, GL_REPLACE); }
GLPT_SCENE(texenv_combine_modulate, 64, 64) { combine_scene(GL_MODULATE, GL_MODULATE); }
GLPT_SCENE(texenv_combine_add, 64, 64) { combine_scene(GL_ADD, GL_ADD); }
GLPT_SCENE(texenv_combine_add_signed, 64, 64) { combine_scene(GL_ADD_SIGNED, GL_ADD_SIGNED); }
GLPT_SCENE(texenv_combine_interpolate, 64, 64) { combine_scene(GL_INTERPOLATE, GL_INTERPOLATE); }
// Texture minus the constant colour (0.25, 0.5, 0.75, 0.4): negative results clamp to 0.
GLPT_SCENE(texenv_combine_subtract, 64, 64) {
  combine_scene(GL_SUBTRACT, GL_SUBTRACT, GL_CONSTANT);
}

// DOT3 bump mapping: a normal map (normals encoded as 0.5 + 0.5 n) dotted with a light vector
// carried in the primary colour. DOT3_RGB leaves alpha to the alpha function (MODULATE here);
// DOT3_RGBA writes the dot product into alpha too.
void dot3_scene(GLenum function) {
  clear(0.2f, 0.2f, 0.2f, 1.0f);
  ortho_pixels(64, 64);
  constexpr int kSize = 16;
  std::vector<uint8_t> normals(kSize * kSize * 4);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      // A bump: the normal tilts away from the centre of each 8x8 cell.
      const double dx = (x % 8) - 3.5, dy = (y % 8) - 3.5;
      const double nx = dx / 6, ny = dy / 6, nz = std::sqrt(std::max(0.0, 1 - nx * nx - ny * ny));
      uint8_t* p = &normals[(y * kSize + x) * 4];
      p[0] = static_cast<uint8_t>(std::lround(127.5 + 127.5 * nx));
      p[1] = static_cast<uint8_t>(std::lround(127.5 + 127.5 * ny));
      p[2] = static_cast<uint8_t>(std::lround(127.5 + 127.5 * nz));
      p[3] = static_cast<uint8_t>(64 + 8 * x);
    }
  }
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGBA, kSize, kSize, normals);
  combine({function, {GL_TEXTURE, GL_PRIMARY_COLOR, 0}}, {GL_MODULATE, {0, 0, 0}});
  glShadeModel(GL_SMOOTH);
  glBegin(GL_QUADS);
  // The light vector, encoded: from the upper left at one end, from the right at the other.
  glColor4f(0.5f - 0.35f, 0.5f + 0.35f, 0.5f + 0.25f, 1.0f);
  glTexCoord2f(0, 0);
  glVertex2f(8, 8);
  glColor4f(0.5f + 0.4f, 0.5f, 0.5f + 0.3f, 0.5f);
  glTexCoord2f(1, 0);
  glVertex2f(56, 8);
  glColor4f(0.5f + 0.4f, 0.5f + 0.1f, 0.5f + 0.3f, 0.8f);
  glTexCoord2f(1, 1);
  glVertex2f(56, 56);
  glColor4f(0.5f - 0.3f, 0.5f + 0.3f, 0.5f + 0.3f, 1.0f);
  glTexCoord2f(0, 1);
  glVertex2f(8, 56);
  glEnd();
}

GLPT_SCENE(texenv_combine_dot3_rgb, 64, 64) { dot3_scene(GL_DOT3_RGB); }
GLPT_SCENE(texenv_combine_dot3_rgba, 64, 64) { dot3_scene(GL_DOT3_RGBA); }

// Four textured quads, each drawn after `setup(i)` chose its combiner.
template <typename Setup>
void four_combiner_quads(Setup setup) {
  clear(0.2f, 0.2f, 0.2f, 1.0f);
  ortho_pixels(128, 64);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGBA, 8, 8, varied_texels());
  tex_env_colour(0.9f, 0.5f, 0.1f, 0.6f);
  for (int i = 0; i < 4; ++i) {
    setup(i);
    textured_quad(4.0f + 32.0f * i, 20.0f);
  }
}

// Operands: the texture's colour, its complement, its alpha and the alpha's complement as the
// RGB argument; alpha from the texture's alpha or its complement.
GLPT_SCENE(texenv_combine_operands, 128, 64) {
  four_combiner_quads([](int i) {
    const GLenum rgb_operands[4] = {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                    GL_ONE_MINUS_SRC_ALPHA};
    combine({GL_REPLACE, {GL_TEXTURE, 0, 0}}, {GL_REPLACE, {GL_TEXTURE, 0, 0}});
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, static_cast<GLint>(rgb_operands[i]));
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA,
              i % 2 == 0 ? GL_SRC_ALPHA : GL_ONE_MINUS_SRC_ALPHA);
  });
}

// Sources: MODULATE of (texture, constant), (constant, primary colour), (primary colour,
// previous = primary on unit 0) and (texture, texture).
GLPT_SCENE(texenv_combine_sources, 128, 64) {
  four_combiner_quads([](int i) {
    const GLenum source0[4] = {GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_TEXTURE};
    const GLenum source1[4] = {GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS, GL_TEXTURE};
    combine({GL_MODULATE, {source0[i], source1[i], 0}}, {GL_MODULATE, {source0[i], source1[i], 0}});
  });
}

// Scales: MODULATE(texture, primary) with RGB_SCALE 1, 2, 4, 4 and ALPHA_SCALE 1, 1, 2, 4; the
// results clamp to 1.
GLPT_SCENE(texenv_combine_scales, 128, 64) {
  four_combiner_quads([](int i) {
    const float rgb_scale[4] = {1, 2, 4, 4}, alpha_scale[4] = {1, 1, 2, 4};
    combine({GL_MODULATE, {GL_TEXTURE, GL_PRIMARY_COLOR, 0}},
            {GL_MODULATE, {GL_TEXTURE, GL_PRIMARY_COLOR, 0}});
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, rgb_scale[i]);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, alpha_scale[i]);
  });
}

// A quad with its own texture coordinates on units 0 and 1 (unit 1's repeat twice).
void multitextured_quad(float x0, float y0, float x1, float y1) {
  const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  glBegin(GL_QUADS);
  for (const auto& c : corners) {
    glColor3f(0.6f + 0.4f * c[0], 0.8f, 1.0f - 0.4f * c[1]);
    glMultiTexCoord2f(GL_TEXTURE0, c[0], c[1]);
    glMultiTexCoord2f(GL_TEXTURE1, 2 * c[0], 2 * c[1]);
    glVertex2f(x0 + (x1 - x0) * c[0], y0 + (y1 - y0) * c[1]);
  }
  glEnd();
}

// Unit 0: an RGB checker modulated by the primary colour; unit 1: a luminance "light map"
// modulating the result.
GLPT_SCENE(texenv_two_units_modulate, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  glActiveTexture(GL_TEXTURE0);
  texture_2d(GL_RGB, 8, 8, checker(8, 8, 2, Rgba8{250, 200, 60, 255}, Rgba8{60, 90, 200, 255}));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE1);
  texture_2d(GL_LUMINANCE, 8, 8,
             gradient(8, 8, Rgba8{255, 0, 0, 255}, Rgba8{60, 0, 0, 255}, Rgba8{150, 0, 0, 255},
                      Rgba8{20, 0, 0, 255}, 0),
             GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  multitextured_quad(4, 4, 60, 60);
}

// Unit 1 INTERPOLATEs between unit 0's texel (the crossbar source GL_TEXTURE0, GL 1.4) and its
// own, weighted by the previous unit's alpha (unit 0 REPLACEs: its texel's alpha); the alpha
// result is the primary colour's.
GLPT_SCENE(texenv_two_units_combine_crossbar, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  glActiveTexture(GL_TEXTURE0);
  texture_2d(GL_RGBA, 8, 8, varied_texels());
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE1);
  texture_2d(GL_RGB, 8, 8, checker(8, 8, 1, Rgba8{255, 255, 255, 255}, Rgba8{30, 30, 30, 255}));
  combine({GL_INTERPOLATE, {GL_TEXTURE0, GL_TEXTURE, GL_PREVIOUS}},
          {GL_REPLACE, {GL_PRIMARY_COLOR, 0, 0}});
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA);
  glEnable(GL_TEXTURE_2D);
  multitextured_quad(8, 8, 56, 56);
}

}  // namespace
