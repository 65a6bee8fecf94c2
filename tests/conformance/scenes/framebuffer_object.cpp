// EXT_framebuffer_object: drawing into textures and renderbuffers, then using the result in the
// window: a lit, depth-tested scene rendered into a texture with a depth renderbuffer; a texture
// rendered in two passes (the second samples the first's result); a mipmap level drawn into and
// the chain generated from level 0; glReadPixels and glCopyTexSubImage from a framebuffer
// object; completeness answers drawn as swatches.
#include <array>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// A GL_RGBA8 texture of `texels` (RGBA bytes; null: undefined contents), nearest filtering.
GLuint color_texture(GLsizei width, GLsizei height, const GLubyte* texels = nullptr) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  return t;
}

// A framebuffer object drawing into `texture` (level 0) with a depth renderbuffer.
GLuint framebuffer_for(GLuint texture, GLsizei width, GLsizei height, bool depth) {
  GLuint fb = 0;
  glGenFramebuffersEXT(1, &fb);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, texture,
                            0);
  if (depth) {
    GLuint rb = 0;
    glGenRenderbuffersEXT(1, &rb);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                                 rb);
  }
  return fb;
}

// Shows the 2-D texture `t` on a window rectangle (pixel coordinates, GL_REPLACE).
void show_texture(GLuint t, float x0, float y0, float x1, float y1) {
  glBindTexture(GL_TEXTURE_2D, t);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  textured_quad(x0, y0, x1, y1, 0.0f, 0.0f, 1.0f, 1.0f);
  glDisable(GL_TEXTURE_2D);
}

// Back to the window: bound, its whole viewport, cleared to `grey`, pixel coordinates.
void to_window(int width, int height, float grey = 0.0f) {
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  glViewport(0, 0, width, height);
  clear(grey, grey, grey);
  ortho_pixels(width, height);
}

// The bound framebuffer object of `width` x `height` cleared to (r, g, b), pixel coordinates.
void clear_framebuffer(int width, int height, float r, float g, float b) {
  glViewport(0, 0, width, height);
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ortho_pixels(width, height);
}

// Green when `status` is `expected`, red otherwise, as a 6x6 swatch at (x, y).
void status_swatch(GLenum status, GLenum expected, float x, float y) {
  glColor3f(status == expected ? 0.0f : 1.0f, status == expected ? 1.0f : 0.0f, 0.0f);
  quad(x, y, x + 6.0f, y + 6.0f);
}

// A size x size texture with nearest-mipmap filtering, its level 0 drawn by a framebuffer object
// (left as the bound one): cleared to `clear`, one half (the left or the right) in `half`.
GLuint two_halves_into_mipmapped(int size, std::array<float, 3> clear, std::array<float, 3> half,
                                 bool left) {
  const GLuint tex = color_texture(size, size);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  framebuffer_for(tex, size, size, false);
  clear_framebuffer(size, size, clear[0], clear[1], clear[2]);
  glColor3f(half[0], half[1], half[2]);
  const float s = float(size);
  quad(left ? 0.0f : s / 2.0f, 0.0f, left ? s / 2.0f : s, s);
  return tex;
}

}  // namespace

// A lit sphere in front of a lit cube, depth-tested, drawn into a 64x64 texture with a depth
// renderbuffer, then shown twice in the window (at its size and magnified).
GLPT_SCENE(fbo_render_to_texture, 160, 80) {
  const GLuint tex = color_texture(64, 64);
  const GLuint fb = framebuffer_for(tex, 64, 64, true);
  glViewport(0, 0, 64, 64);
  glClearColor(0.2f, 0.3f, 0.5f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  lit_perspective_light0(50.0, 1.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_COLOR_MATERIAL);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -5.0f);
  glColor3f(0.9f, 0.6f, 0.2f);
  sphere(0.9f, 16, 12);
  glTranslatef(0.6f, 0.4f, -1.2f);
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  glColor3f(0.3f, 0.8f, 0.4f);
  cube(0.8f);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glDeleteFramebuffersEXT(1, &fb);  // binds the window
  to_window(160, 80, 0.05f);
  show_texture(tex, 4.0f, 8.0f, 68.0f, 72.0f);
  show_texture(tex, 76.0f, 4.0f, 148.0f, 76.0f);
}

// Two passes: a coloured triangle drawn into texture A; A textured onto a rotated quad drawn
// into texture B (of another size) over a cleared background; B shown in the window. The second
// framebuffer object is bound while the first still is (binding switches directly).
GLPT_SCENE(fbo_two_passes, 96, 64) {
  const GLuint a = color_texture(32, 32);
  const GLuint b = color_texture(48, 40);
  framebuffer_for(a, 32, 32, false);
  clear_framebuffer(32, 32, 1.0f, 1.0f, 1.0f);
  rgb_triangle(2.0f, 2.0f, 30.0f, 6.0f, 12.0f, 29.0f);
  framebuffer_for(b, 48, 40, false);
  clear_framebuffer(48, 40, 0.1f, 0.1f, 0.4f);
  glTranslatef(24.0f, 20.0f, 0.0f);
  glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
  glTranslatef(-24.0f, -20.0f, 0.0f);
  show_texture(a, 8.0f, 6.0f, 40.0f, 34.0f);
  glLoadIdentity();
  to_window(96, 64);
  show_texture(b, 4.0f, 4.0f, 52.0f, 44.0f);
  show_texture(a, 60.0f, 30.0f, 92.0f, 62.0f);
}

// Drawing into an existing texture adds to what it holds (no clear): a textured checkerboard
// keeps its texels where the framebuffer object draws nothing.
GLPT_SCENE(fbo_draws_over_texture_contents, 64, 64) {
  GLubyte texels[16 * 16 * 4];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const bool on = ((x / 4) + (y / 4)) % 2 == 0;
      GLubyte* t = &texels[(y * 16 + x) * 4];
      t[0] = on ? 230 : 30;
      t[1] = on ? 200 : 60;
      t[2] = on ? 40 : 120;
      t[3] = 255;
    }
  const GLuint tex = color_texture(16, 16, texels);
  framebuffer_for(tex, 16, 16, false);
  glViewport(0, 0, 16, 16);
  ortho_pixels(16, 16);
  glColor3f(1.0f, 0.0f, 1.0f);
  quad(4.0f, 4.0f, 10.0f, 12.0f);
  to_window(64, 64);
  show_texture(tex, 0.0f, 0.0f, 64.0f, 64.0f);
}

// glReadPixels and glCopyTexSubImage2D while a framebuffer object is bound read it, not the
// window; glCheckFramebufferStatusEXT's answers for complete and incomplete objects as swatches.
GLPT_SCENE(fbo_read_copy_and_status, 96, 48) {
  clear(0.3f, 0.0f, 0.0f);  // the window: what reads must not see
  const GLuint tex = color_texture(16, 16);
  const GLuint fb = framebuffer_for(tex, 16, 16, false);
  const GLenum complete = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
  clear_framebuffer(16, 16, 0.0f, 0.5f, 1.0f);
  rgb_triangle(1.0f, 1.0f, 15.0f, 2.0f, 8.0f, 15.0f);
  GLubyte pixels[16 * 16 * 4];
  glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  const GLuint copy = color_texture(16, 16);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 16, 16);
  // An object without attachments, and one with a level that does not exist.
  GLuint empty = 0;
  glGenFramebuffersEXT(1, &empty);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, empty);
  const GLenum missing = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 3);
  const GLenum bad_level = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  const GLenum window = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteFramebuffersEXT(1, &empty);

  glViewport(0, 0, 96, 48);
  ortho_pixels(96, 48);
  glRasterPos2i(2, 2);
  glDrawPixels(16, 16, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  show_texture(copy, 22.0f, 2.0f, 38.0f, 18.0f);
  show_texture(tex, 42.0f, 2.0f, 74.0f, 34.0f);
  status_swatch(complete, GL_FRAMEBUFFER_COMPLETE_EXT, 2.0f, 40.0f);
  status_swatch(missing, GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT, 10.0f, 40.0f);
  status_swatch(bad_level, GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT, 18.0f, 40.0f);
  status_swatch(window, GL_FRAMEBUFFER_COMPLETE_EXT, 26.0f, 40.0f);
}

// A framebuffer object drawing into level 0 of a mipmapped texture, glGenerateMipmapEXT, and the
// texture minified so that its smaller levels show.
GLPT_SCENE(fbo_generate_mipmap, 96, 48) {
  const GLuint tex = two_halves_into_mipmapped(32, {0.9f, 0.9f, 0.2f}, {0.1f, 0.2f, 0.9f}, true);
  to_window(96, 48);
  glBindTexture(GL_TEXTURE_2D, tex);
  glGenerateMipmapEXT(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  textured_quad(2.0f, 2.0f, 34.0f, 34.0f, 0.0f, 0.0f, 1.0f, 1.0f);
  textured_quad(40.0f, 2.0f, 48.0f, 10.0f, 0.0f, 0.0f, 1.0f, 1.0f);
  textured_quad(52.0f, 2.0f, 54.0f, 4.0f, 0.0f, 0.0f, 1.0f, 1.0f);
  glDisable(GL_TEXTURE_2D);
}

// Reads of what an attachment stores: a scene drawn into luminance, intensity, alpha and R3G3B2
// textures is read back with glReadPixels (Mesa answers the stored components: luminance in red,
// missing colour 0, missing alpha 1, quantized) and drawn into the window; then a second colour
// attachment, drawn earlier, read while the first is the draw buffer; then a 3-D texture's slice
// drawn into; and glGenerateMipmapEXT while the object that drew level 0 is still bound.
GLPT_SCENE(fbo_stored_components_and_reads, 112, 48) {
  const GLenum formats[] = {GL_LUMINANCE8, GL_INTENSITY8, GL_ALPHA8, GL_R3_G3_B2};
  GLubyte read[4][8 * 8 * 4] = {};
  for (int i = 0; i < 4; ++i) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(formats[i]), 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    framebuffer_for(tex, 8, 8, false);
    clear_framebuffer(8, 8, 0.1f, 0.5f, 0.3f);
    glColor4f(0.7f, 0.45f, 0.9f, 0.6f);
    quad(0.0f, 0.0f, 4.0f, 8.0f);
    glReadPixels(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, read[i]);
  }
  // Two colour attachments: COLOR1 drawn first, then COLOR0 drawn and COLOR1 read.
  const GLuint first = color_texture(8, 8), second = color_texture(8, 8);
  framebuffer_for(first, 8, 8, false);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT1_EXT, GL_TEXTURE_2D, second, 0);
  glDrawBuffer(GL_COLOR_ATTACHMENT1_EXT);
  clear_framebuffer(8, 8, 0.8f, 0.2f, 0.6f);
  glDrawBuffer(GL_COLOR_ATTACHMENT0_EXT);
  clear_framebuffer(8, 8, 0.2f, 0.7f, 0.1f);
  glReadBuffer(GL_COLOR_ATTACHMENT1_EXT);
  GLubyte other[8 * 8 * 4] = {};
  glReadPixels(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, other);
  glReadBuffer(GL_COLOR_ATTACHMENT0_EXT);
  // Slice 2 of a 3-D texture.
  GLuint volume = 0;
  glGenTextures(1, &volume);
  glBindTexture(GL_TEXTURE_3D, volume);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  GLuint fb3d = 0;
  glGenFramebuffersEXT(1, &fb3d);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb3d);
  glFramebufferTexture3DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_3D, volume, 0,
                            2);
  clear_framebuffer(8, 8, 0.3f, 0.3f, 0.9f);
  glColor3f(1.0f, 0.8f, 0.1f);
  quad(4.0f, 0.0f, 8.0f, 4.0f);
  // Level 0 drawn, then its mipmaps generated before the object is unbound.
  const GLuint mipmapped =
      two_halves_into_mipmapped(16, {0.9f, 0.1f, 0.1f}, {0.1f, 0.9f, 0.9f}, false);
  glBindTexture(GL_TEXTURE_2D, mipmapped);
  glGenerateMipmapEXT(GL_TEXTURE_2D);

  to_window(112, 48, 0.25f);
  for (int i = 0; i < 4; ++i) {
    glRasterPos2i(2 + 10 * i, 2);
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, read[i]);
  }
  glRasterPos2i(42, 2);
  glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, other);
  show_texture(first, 52.0f, 2.0f, 60.0f, 10.0f);
  glBindTexture(GL_TEXTURE_3D, volume);
  glEnable(GL_TEXTURE_3D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  const float r = (2.0f + 0.5f) / 4.0f;  // slice 2's centre
  glTexCoord3f(0, 0, r);
  glVertex2f(62, 2);
  glTexCoord3f(1, 0, r);
  glVertex2f(78, 2);
  glTexCoord3f(1, 1, r);
  glVertex2f(78, 18);
  glTexCoord3f(0, 1, r);
  glVertex2f(62, 18);
  glEnd();
  glDisable(GL_TEXTURE_3D);
  glBindTexture(GL_TEXTURE_2D, mipmapped);
  glEnable(GL_TEXTURE_2D);
  textured_quad(80.0f, 2.0f, 84.0f, 6.0f, 0.0f, 0.0f, 1.0f, 1.0f);   // level 2
  textured_quad(86.0f, 2.0f, 94.0f, 10.0f, 0.0f, 0.0f, 1.0f, 1.0f);  // level 1
  glDisable(GL_TEXTURE_2D);
}

// One depth texture shared by two framebuffer objects: the first draws a near quad into it, the
// second (another colour texture) draws a far quad over the whole with the depth test, which the
// first's depth must stop: the depth texture's contents are loaded into the second's target.
// Then the depth texture itself, compared as a luminance image.
GLPT_SCENE(fbo_shared_depth_texture, 96, 40) {
  GLuint depth = 0;
  glGenTextures(1, &depth);
  glBindTexture(GL_TEXTURE_2D, depth);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
               nullptr);
  const GLuint first = color_texture(16, 16), second = color_texture(16, 16);
  auto depth_framebuffer = [&](GLuint color) {
    framebuffer_for(color, 16, 16, false);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_TEXTURE_2D, depth, 0);
  };
  depth_framebuffer(first);
  glViewport(0, 0, 16, 16);
  glClearColor(0.1f, 0.1f, 0.4f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glColor3f(0.9f, 0.2f, 0.2f);
  glBegin(GL_QUADS);  // near (z -0.5: depth 0.25), the left half, sloping to z 0 at its top
  glVertex3f(-1.0f, -1.0f, -0.5f);
  glVertex3f(0.0f, -1.0f, -0.5f);
  glVertex3f(0.0f, 1.0f, 0.0f);
  glVertex3f(-1.0f, 1.0f, 0.0f);
  glEnd();
  depth_framebuffer(second);
  glClearColor(0.3f, 0.3f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);  // colour only: the depth texture keeps the first's depth
  glColor3f(0.2f, 0.9f, 0.3f);
  glBegin(GL_QUADS);  // at z -0.25 (depth 0.375) over the whole: hidden where the first is nearer
  glVertex3f(-1.0f, -1.0f, -0.25f);
  glVertex3f(1.0f, -1.0f, -0.25f);
  glVertex3f(1.0f, 1.0f, -0.25f);
  glVertex3f(-1.0f, 1.0f, -0.25f);
  glEnd();
  glDisable(GL_DEPTH_TEST);

  to_window(96, 40, 0.0f);
  show_texture(first, 2.0f, 2.0f, 34.0f, 34.0f);
  show_texture(second, 36.0f, 2.0f, 68.0f, 34.0f);
  glBindTexture(GL_TEXTURE_2D, depth);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE_ARB, GL_LUMINANCE);
  show_texture(depth, 70.0f, 2.0f, 86.0f, 18.0f);
}
