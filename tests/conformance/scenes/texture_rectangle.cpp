// GL_ARB_texture_rectangle: rectangle textures sampled with texel coordinates (s in [0, w],
// t in [0, h]), nearest and linear, with each wrap mode the extension allows, through the
// texture matrix, coordinate generation and projective q.
#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

constexpr GLenum kRect = GL_TEXTURE_RECTANGLE_ARB;

// A 5x3 texture of distinct texels (sizes that are not powers of two, as rectangles usually
// are), bound to GL_TEXTURE_RECTANGLE_ARB with `filter` and `wrap`, drawn with GL_REPLACE.
void rectangle_texture(GLenum filter, GLenum wrap) {
  std::vector<uint8_t> texels(5 * 3 * 4);
  for (int i = 0; i < 15; ++i) {
    texels[i * 4 + 0] = static_cast<uint8_t>(40 + 50 * (i % 5));
    texels[i * 4 + 1] = static_cast<uint8_t>(40 + 90 * (i / 5));
    texels[i * 4 + 2] = static_cast<uint8_t>(i % 2 == 0 ? 230 : 30);
    texels[i * 4 + 3] = 255;
  }
  new_texture(kRect, filter, filter);
  glTexImage2D(kRect, 0, GL_RGBA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexParameteri(kRect, GL_TEXTURE_WRAP_S, GLint(wrap));
  glTexParameteri(kRect, GL_TEXTURE_WRAP_T, GLint(wrap));
  const float border[4] = {1, 0, 1, 1};
  glTexParameterfv(kRect, GL_TEXTURE_BORDER_COLOR, border);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(kRect);
}

// Each filter with each wrap mode: rows GL_CLAMP_TO_EDGE (the initial mode), GL_CLAMP,
// GL_CLAMP_TO_BORDER (magenta border); columns nearest, linear. Coordinates run from one texel
// before the image to one beyond it, over sizes that are not multiples of the texture's, so
// pixel centres fall on texel edges, on integers and between them.
GLPT_SCENE(texture_rectangle_filters_and_wraps, 96, 144) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(96, 144);
  const GLenum wraps[3] = {GL_CLAMP_TO_EDGE, GL_CLAMP, GL_CLAMP_TO_BORDER};
  const GLenum filters[2] = {GL_NEAREST, GL_LINEAR};
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 2; ++col) {
      rectangle_texture(filters[col], wraps[row]);
      const float x = 2.0f + 48.0f * col, y = 2.0f + 48.0f * row;
      textured_quad(x, y, x + 42, y + 40, -1.0f, -1.0f, 6.0f, 4.0f);
    }
  }
}

// The texture matrix and coordinate generation apply to texel coordinates as to any others:
// left, [0, 1] coordinates scaled to the texture's size by the texture matrix (and rotated a
// little); middle, object-linear coordinates whose planes give texels directly; right,
// projective coordinates (s, t, q) with q varying across the quad. Linear filtering.
GLPT_SCENE(texture_rectangle_matrix_texgen_projective, 144, 48) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(144, 48);
  rectangle_texture(GL_LINEAR, GL_CLAMP_TO_EDGE);
  glMatrixMode(GL_TEXTURE);
  glScalef(5.0f, 3.0f, 1.0f);
  glTranslatef(0.5f, 0.5f, 0.0f);
  glRotatef(15.0f, 0, 0, 1);
  glTranslatef(-0.5f, -0.5f, 0.0f);
  glMatrixMode(GL_MODELVIEW);
  textured_quad(2, 2, 46, 46, 0, 0, 1, 1);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);

  const float s_plane[4] = {5.0f / 44.0f, 0.0f, 0.0f, -50.0f * 5.0f / 44.0f};
  const float t_plane[4] = {0.0f, 3.0f / 44.0f, 0.0f, -2.0f * 3.0f / 44.0f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, s_plane);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, t_plane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  quad(50, 2, 94, 46);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);

  const float q[4] = {1.0f, 2.0f, 1.5f, 0.75f};
  const float corners[4][2] = {{98, 2}, {142, 2}, {142, 46}, {98, 46}};
  const float st[4][2] = {{0, 0}, {5, 0}, {5, 3}, {0, 3}};
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    glTexCoord4f(st[i][0] * q[i], st[i][1] * q[i], 0.0f, q[i]);
    glVertex2f(corners[i][0], corners[i][1]);
  }
  glEnd();
}

// A rectangle texture wins over an enabled 2D texture and loses to an enabled 3D one
// (ARB_texture_rectangle's priority: cube map, 3D, rectangle, 2D, 1D); an incomplete rectangle
// texture (no image) leaves the 2D texture in use. The 2D and 3D textures are single colours.
GLPT_SCENE(texture_rectangle_target_priority, 96, 32) {
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(96, 32);
  const uint8_t green[4] = {0, 200, 0, 255}, blue[4] = {0, 0, 200, 255};
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  new_texture(GL_TEXTURE_3D, GL_NEAREST, GL_NEAREST);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, blue);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(kRect);  // texture 0 of the target: no image
  textured_quad(2, 2, 30, 30, 0, 0, 1, 1);
  rectangle_texture(GL_NEAREST, GL_CLAMP_TO_EDGE);
  glEnable(GL_TEXTURE_2D);
  textured_quad(34, 2, 62, 30, 0, 0, 5, 3);
  glEnable(GL_TEXTURE_3D);
  textured_quad(66, 2, 94, 30, 0, 0, 5, 3);
}

}  // namespace
