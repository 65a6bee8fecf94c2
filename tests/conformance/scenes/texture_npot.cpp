// ARB_texture_non_power_of_two: textures of any size sample with every wrap mode and filter, and
// their mip chains halve each side rounding down (45x27, 22x13, 11x6, 5x3, 2x1, 1x1), as Mesa
// samples them (gallivm wraps non-power-of-two repeats by its own code path, not by masking).
#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

constexpr int kWidth = 37;
constexpr int kHeight = 21;

std::vector<uint8_t> npot_gradient(int width, int height) {
  return gradient(width, height, Rgba8{250, 40, 40, 255}, Rgba8{40, 250, 40, 200},
                  Rgba8{40, 40, 250, 160}, Rgba8{250, 250, 40, 255}, 5);
}

// A quad of window pixels (x0, y0)-(x1, y1) whose texture coordinates run from -1.3 to 2.7:
// edges, wraps and texel centres at places a power-of-two size would not put them.
void wrapped_quad(float x0, float y0, float x1, float y1) {
  textured_quad(x0, y0, x1, y1, -1.3f, -1.3f, 2.7f, 2.7f);
}

void npot_wrap_scene(GLenum filter) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(96, 96);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const std::vector<uint8_t> texels = npot_gradient(kWidth, kHeight);
  const float border[4] = {1, 0, 1, 1};
  const GLenum wraps[4] = {GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP};
  for (int i = 0; i < 4; ++i) {
    texture_2d(GL_RGBA, kWidth, kHeight, texels, filter, wraps[i]);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    const float x = static_cast<float>(2 + (i % 2) * 47);
    const float y = static_cast<float>(2 + (i / 2) * 47);
    wrapped_quad(x, y, x + 45, y + 45);
  }
}

GLPT_SCENE(texture_npot_wrap_nearest, 96, 96) { npot_wrap_scene(GL_NEAREST); }
GLPT_SCENE(texture_npot_wrap_linear, 96, 96) { npot_wrap_scene(GL_LINEAR); }

// Every level of a 45x27 chain given by the program, each of its own colour scheme, so the
// level each pixel picks shows.
void npot_levels(GLenum format) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  int width = 45, height = 27;
  for (int level = 0;; ++level) {
    const uint8_t shade = static_cast<uint8_t>(40 + 30 * level);
    const std::vector<uint8_t> texels =
        convert(gradient(width, height, Rgba8{250, shade, 40, 255}, Rgba8{40, 250, shade, 255},
                         Rgba8{shade, 40, 250, 255}, Rgba8{250, 250, shade, 255}, 3),
                format);
    glTexImage2D(GL_TEXTURE_2D, level, static_cast<GLint>(format), width, height, 0, format,
                 GL_UNSIGNED_BYTE, texels.data());
    if (width == 1 && height == 1) break;
    width = width > 1 ? width / 2 : 1;
    height = height > 1 ? height / 2 : 1;
  }
}

GLPT_SCENE(texture_npot_mipmaps_trilinear, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  npot_levels(GL_RGBA);
  glEnable(GL_TEXTURE_2D);
  receding_floor(5, 9);  // every level of the chain
}

GLPT_SCENE(texture_npot_mipmaps_nearest, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_2D, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  npot_levels(GL_RGB);
  glEnable(GL_TEXTURE_2D);
  receding_floor(5, 9);  // every level of the chain
}

// GL_GENERATE_MIPMAP on a 45x27 image: the reduced levels are the driver's own (odd sizes
// average three texels where a power of two averages two).
GLPT_SCENE(texture_npot_generate_mipmap, 64, 64) {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<uint8_t> texels = npot_gradient(45, 27);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 45, 27, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glEnable(GL_TEXTURE_2D);
  receding_floor(5, 9);  // every level of the chain
}

// 1D (13 texels, repeating) and 3D (5x3x7, a slice between layers) textures of odd sizes, and a
// 29x19 texture copied from the framebuffer.
GLPT_SCENE(texture_npot_1d_3d_copy, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<uint8_t> row = npot_gradient(13, 1);
  new_texture(GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 13, 0, GL_RGBA, GL_UNSIGNED_BYTE, row.data());
  glEnable(GL_TEXTURE_1D);
  textured_quad(2, 2, 30, 30, -0.7f, 0, 1.9f, 1);
  glDisable(GL_TEXTURE_1D);

  const std::vector<uint8_t> volume = npot_gradient(5, 3 * 7);
  new_texture(GL_TEXTURE_3D, GL_LINEAR, GL_LINEAR);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 5, 3, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, volume.data());
  glEnable(GL_TEXTURE_3D);
  glBegin(GL_QUADS);
  glTexCoord3f(-0.4f, -0.4f, 0.37f);
  glVertex2f(34, 2);
  glTexCoord3f(1.6f, -0.4f, 0.37f);
  glVertex2f(62, 2);
  glTexCoord3f(1.6f, 1.6f, 0.63f);
  glVertex2f(62, 30);
  glTexCoord3f(-0.4f, 1.6f, 0.63f);
  glVertex2f(34, 30);
  glEnd();
  glDisable(GL_TEXTURE_3D);

  new_texture(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 5, 29, 19, 0);
  glEnable(GL_TEXTURE_2D);
  textured_quad(2, 34, 62, 62, -0.5f, -0.5f, 1.5f, 1.5f);
  glDisable(GL_TEXTURE_2D);
}

}  // namespace
