// EXT_framebuffer_blit (glBlitFramebufferEXT through blit_framebuffer): a framebuffer object's
// texture blitted to the window 1:1, magnified (nearest and linear), minified and mirrored, at a
// ratio that is not an integer, under the scissor box and past the read buffer's edge; the window
// blitted into itself and, minified 2:1, into a texture; depth and stencil blitted from an object
// into the window and then tested against.
//
// A nearest blit samples each destination pixel's centre; where that falls exactly on a texel
// edge, Mesa's float interpolation takes either texel unless the ratio is a power of two (in a
// sweep of 400 random blits against OSMesa, 13% of such edges went to the lower texel). The
// ratios here avoid those edges (an odd source size over an even destination size never hits
// one) except the 2:1 minifications, whose edges Mesa resolves by the framebuffer's row order.
#include <vector>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// A 16 x 16 texture with a pattern in every texel (so nearest and linear differ), drawn over by
// a framebuffer object with a depth renderbuffer: a lit-like triangle in front of the pattern.
// The object stays bound.
GLuint patterned_framebuffer(GLuint* texture_out) {
  std::vector<uint8_t> rgba(16 * 16 * 4);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      uint8_t* p = &rgba[size_t(y * 16 + x) * 4];
      p[0] = uint8_t(x * 16 + 8);
      p[1] = uint8_t(y * 16 + 8);
      p[2] = uint8_t(((x ^ y) & 1) * 200 + 20);
      p[3] = 255;
    }
  const GLuint texture = texture_2d(GL_RGBA8, 16, 16, rgba);
  GLuint fb = 0, depth = 0;
  glGenFramebuffersEXT(1, &fb);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, texture,
                            0);
  glGenRenderbuffersEXT(1, &depth);
  glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, depth);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 16, 16);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                               depth);
  glViewport(0, 0, 16, 16);
  glClear(GL_DEPTH_BUFFER_BIT);
  ortho_pixels(16, 16);
  rgb_triangle(1.0f, 1.0f, 11.0f, 3.0f, 5.0f, 12.0f);
  *texture_out = texture;
  return fb;
}

}  // namespace

GLPT_SCENE(fbo_blit_scaled_and_mirrored, 128, 64) {
  GLuint texture = 0;
  const GLuint fb = patterned_framebuffer(&texture);
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, 0);
  glViewport(0, 0, 128, 64);
  clear(0.1f, 0.1f, 0.15f);
  // From the object (the read framebuffer) to the window (the draw framebuffer).
  blit_framebuffer(0, 0, 16, 16, 2, 2, 18, 18, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit_framebuffer(0, 0, 16, 16, 20, 2, 52, 34, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit_framebuffer(0, 0, 16, 16, 54, 2, 86, 34, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  blit_framebuffer(0, 0, 16, 16, 96, 10, 88, 2, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit_framebuffer(0, 0, 15, 15, 98, 2, 108, 12, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit_framebuffer(0, 0, 16, 16, 111, 2, 126, 20, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  // A source reaching past the object's edge: only what maps inside it is written.
  blit_framebuffer(8, 8, 24, 24, 2, 36, 18, 52, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  // Under the scissor box.
  glEnable(GL_SCISSOR_TEST);
  glScissor(24, 40, 10, 6);
  blit_framebuffer(0, 0, 16, 15, 20, 36, 52, 62, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glDisable(GL_SCISSOR_TEST);
  // The window into itself (read and draw framebuffer 0), mirrored in y.
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  blit_framebuffer(2, 2, 18, 18, 56, 62, 72, 46, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  // The window into a second texture, shown on a quad.
  GLuint copy = 0;
  glGenTextures(1, &copy);
  glBindTexture(GL_TEXTURE_2D, copy);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, fb);
  glFramebufferTexture2DEXT(GL_DRAW_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, copy,
                            0);
  blit_framebuffer(20, 2, 52, 34, 0, 0, 16, 16, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  ortho_pixels(128, 64);
  glBindTexture(GL_TEXTURE_2D, copy);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  textured_quad(92.0f, 28.0f, 124.0f, 60.0f, 0.0f, 0.0f, 1.0f, 1.0f);  // 2x: no texel edges
  glDisable(GL_TEXTURE_2D);
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteTextures(1, &texture);
  glDeleteTextures(1, &copy);
}

// Depth and stencil drawn into an object (a near quad on the left half, stencil 1 on the right
// half), blitted into the window, then tested there: a far quad over the whole passes only where
// the blitted depth is far; a quad under GL_EQUAL stencil lands only where the stencil is 1.
GLPT_SCENE(fbo_blit_depth_stencil, 64, 48) {
  GLuint color = 0, depth_stencil = 0, fb = 0;
  glGenTextures(1, &color);
  glBindTexture(GL_TEXTURE_2D, color);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 32, 24, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGenFramebuffersEXT(1, &fb);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, color, 0);
  glGenRenderbuffersEXT(1, &depth_stencil);
  glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, depth_stencil);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH24_STENCIL8_EXT, 32, 24);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                               depth_stencil);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_STENCIL_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                               depth_stencil);
  glViewport(0, 0, 32, 24);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  ortho_pixels(32, 24);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColor3f(0.5f, 0.5f, 0.5f);
  quad(0.0f, 0.0f, 16.0f, 24.0f, 0.5f);  // z 0.5 in glOrtho(-1, 1): window depth 0.25
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
  quad(16.0f, 6.0f, 32.0f, 18.0f);
  glDisable(GL_STENCIL_TEST);
  // Into the window, magnified twice (nearest, as depth and stencil must be).
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, 0);
  glViewport(0, 0, 64, 48);
  clear(0.2f, 0.2f, 0.2f);
  blit_framebuffer(0, 0, 32, 24, 0, 0, 64, 48, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                   GL_NEAREST);
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  ortho_pixels(64, 48);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glColor3f(0.9f, 0.3f, 0.1f);
  quad(0.0f, 0.0f, 64.0f, 48.0f, 0.0f);  // window depth 0.5: hidden where the blit put 0.25
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(0.1f, 0.4f, 0.9f);
  quad(8.0f, 4.0f, 60.0f, 44.0f);
  glDisable(GL_STENCIL_TEST);
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteRenderbuffersEXT(1, &depth_stencil);
  glDeleteTextures(1, &color);
}
