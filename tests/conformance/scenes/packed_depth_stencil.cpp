// EXT_packed_depth_stencil: GL_DEPTH24_STENCIL8 textures sampled as depth textures (depth
// comparison with nearest and linear filters, GL_DEPTH_TEXTURE_MODE), a depth-stencil texture
// copied from the depth/stencil buffer, and glDrawPixels / glCopyPixels of GL_DEPTH_STENCIL whose
// depth and stencil later draws test against.
#include <cmath>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// 8x8 words: a depth ramp (24 bits) above a stencil index that counts the texels.
std::vector<GLuint> depth_stencil_words() {
  std::vector<GLuint> words(64);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const double d = std::fmod(0.13 * x + 0.07 * y, 1.0);
      words[size_t(y * 8 + x)] = GLuint(d * 16777215.0) << 8 | GLuint(y * 8 + x);
    }
  return words;
}

// Texture coordinates from -0.213 to 1.187: no pixel centre falls exactly on a texel edge (where
// the rasterizers' interpolation may round either way).
void textured_quad(float x, float y, float w, float h, float r) {
  constexpr float lo = -0.213f, hi = 1.187f;
  glBegin(GL_QUADS);
  glTexCoord3f(lo, lo, r);
  glVertex2f(x, y);
  glTexCoord3f(hi, lo, r);
  glVertex2f(x + w, y);
  glTexCoord3f(hi, hi, r);
  glVertex2f(x + w, y + h);
  glTexCoord3f(lo, hi, r);
  glVertex2f(x, y + h);
  glEnd();
}

}  // namespace

// Depth comparison of a GL_DEPTH24_STENCIL8 texture: nearest and linear (percentage-closer)
// filtering with two reference values, and the depth values themselves as intensity.
GLPT_SCENE(packed_depth_stencil_texture_compare, 96, 64) {
  clear(0.1f, 0.1f, 0.3f);
  ortho_pixels(96, 64);
  const std::vector<GLuint> words = depth_stencil_words();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor3f(1.0f, 0.9f, 0.6f);
  glEnable(GL_TEXTURE_2D);
  const GLenum filters[2] = {GL_NEAREST, GL_LINEAR};
  for (int f = 0; f < 2; ++f) {
    new_texture(GL_TEXTURE_2D, filters[f], filters[f]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 8, 8, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, words.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    textured_quad(2.0f + 32.0f * float(f), 2.0f, 28.0f, 28.0f, 0.45f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
    textured_quad(2.0f + 32.0f * float(f), 34.0f, 28.0f, 28.0f, 0.7f);
  }
  // Without comparison: the depth as intensity, modulating the colour.
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, 8, 8, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
               words.data());
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  textured_quad(66.0f, 2.0f, 28.0f, 28.0f, 0.0f);
  glDisable(GL_TEXTURE_2D);
}

// glDrawPixels(GL_DEPTH_STENCIL) under a depth test that would reject it, glCopyPixels of the
// result, then quads that test against the depth and stencil written; finally a
// GL_DEPTH24_STENCIL8 texture copied from the depth/stencil buffer, compared and drawn.
GLPT_SCENE(packed_depth_stencil_pixels, 64, 64) {
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  const std::vector<GLuint> words = depth_stencil_words();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glPixelZoom(3.0f, 3.0f);
  glRasterPos2i(2, 2);
  glDrawPixels(8, 8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, words.data());
  glPixelZoom(1.0f, 1.0f);
  glRasterPos2i(34, 2);
  glCopyPixels(2, 2, 24, 24, GL_DEPTH_STENCIL);
  // Stencil: odd indices in red; depth: a quad at z = 0.5 where the buffer is farther.
  glDepthFunc(GL_LESS);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 1);
  glColor3f(0.9f, 0.2f, 0.2f);
  glRecti(0, 0, 64, 30);
  glDisable(GL_STENCIL_TEST);
  glColor3f(0.2f, 0.8f, 0.3f);
  glBegin(GL_QUADS);
  glVertex3f(0, 0, 0.0f);  // window z 0.5 under ortho_pixels' [-1, 1] depth
  glVertex3f(64, 0, 0.0f);
  glVertex3f(64, 30, 0.0f);
  glVertex3f(0, 30, 0.0f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  // The buffer back as a depth-stencil texture.
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 0, 0, 64, 32, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LESS);
  glEnable(GL_TEXTURE_2D);
  glColor3f(0.4f, 0.6f, 1.0f);
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.6f);
  glVertex2f(0, 34);
  glTexCoord3f(1, 0, 0.6f);
  glVertex2f(64, 34);
  glTexCoord3f(1, 1, 0.6f);
  glVertex2f(64, 64);
  glTexCoord3f(0, 1, 0.6f);
  glVertex2f(0, 64);
  glEnd();
  glDisable(GL_TEXTURE_2D);
}
