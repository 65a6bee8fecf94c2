// EXT_framebuffer_blit: separate draw and read framebuffer bindings, glBlitFramebufferEXT's errors
// in Mesa 25's order (src/mesa/main/blit.c), and what it copies: nearest and linear, scaled and
// mirrored, cut by the scissor box and the read buffer's edge, colour, depth and stencil; reads
// (glReadPixels, glCopyTexSubImage, glCopyPixels) take their source from the read framebuffer.
// Rendered in raster mode on a headless window of 16 x 16 (double-buffered, depth 24, stencil 8).
#include <array>
#include <vector>

#include "array_test_util.hpp"
#include "gl_shim/frame/headless_target.hpp"

namespace {

constexpr GLenum kInvalidFramebufferOperation = 0x0506;

class FramebufferBlitTest : public HeadlessGlTest {
 protected:
  FramebufferBlitTest() : HeadlessGlTest(16, 16) {}
  void SetUp() override {
    HeadlessGlTest::SetUp();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }

  // A framebuffer object with an RGBA8 texture of `width` x `height` whose texels are `texels`
  // (RGBA8, rows bottom to top), bound to both targets.
  GLuint framebuffer_with_texture(GLsizei width, GLsizei height, const std::vector<GLubyte>& texels,
                                  GLuint* texture_out) {
    GLuint texture = 0, fb = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels.empty() ? nullptr : texels.data());
    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, texture,
                              0);
    if (texture_out != nullptr) *texture_out = texture;
    return fb;
  }

  // The window's colour at (x, y), read through the read framebuffer 0.
  std::array<int, 4> window_pixel(int x, int y) {
    glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
    GLubyte p[4] = {};
    glReadBuffer(GL_BACK);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return {p[0], p[1], p[2], p[3]};
  }

  glpt_test::RasterMode raster_mode_;
};

// Texel (x, y) of a 4 x 4 test image: red counts columns, green rows.
std::vector<GLubyte> ramp_4x4() {
  std::vector<GLubyte> t(4 * 4 * 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      GLubyte* p = &t[size_t(y * 4 + x) * 4];
      p[0] = GLubyte(40 + 50 * x);
      p[1] = GLubyte(40 + 50 * y);
      p[2] = 7;
      p[3] = 255;
    }
  return t;
}

TEST_F(FramebufferBlitTest, DrawAndReadBindingsAreSeparate) {
  GLuint fbs[2] = {};
  glGenFramebuffersEXT(2, fbs);
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, fbs[0]);
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, fbs[1]);
  EXPECT_EQ(get_integer(GL_READ_FRAMEBUFFER_BINDING_EXT), GLint(fbs[0]));
  EXPECT_EQ(get_integer(GL_DRAW_FRAMEBUFFER_BINDING_EXT), GLint(fbs[1]));
  EXPECT_EQ(get_integer(GL_FRAMEBUFFER_BINDING_EXT), GLint(fbs[1]));
  // Neither has attachments: both incomplete, each judged for its own target.
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_READ_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT});
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glFramebufferTexture2DEXT(GL_READ_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D,
                            texture, 0);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_READ_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_DRAW_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT});
  GLint name = -1;
  glGetFramebufferAttachmentParameterivEXT(GL_READ_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                                           GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT, &name);
  EXPECT_EQ(name, GLint(texture));
  // glReadBuffer sets the read framebuffer's read buffer; the window's stays.
  glReadBuffer(GL_NONE);
  EXPECT_EQ(get_integer(GL_READ_BUFFER), GL_NONE);
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  EXPECT_EQ(get_integer(GL_READ_BUFFER), GL_BACK);
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, fbs[0]);
  EXPECT_EQ(get_integer(GL_READ_BUFFER), GL_NONE);
  // GL_FRAMEBUFFER_EXT binds both; deleting the read framebuffer binds the window for reading.
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbs[1]);
  EXPECT_EQ(get_integer(GL_READ_FRAMEBUFFER_BINDING_EXT), GLint(fbs[1]));
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, fbs[0]);
  glDeleteFramebuffersEXT(1, &fbs[0]);
  EXPECT_EQ(get_integer(GL_READ_FRAMEBUFFER_BINDING_EXT), 0);
  EXPECT_EQ(get_integer(GL_DRAW_FRAMEBUFFER_BINDING_EXT), GLint(fbs[1]));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  glDeleteFramebuffersEXT(1, &fbs[1]);
  glDeleteTextures(1, &texture);
}

TEST_F(FramebufferBlitTest, ErrorsComeInMesasOrder) {
  // Incomplete read framebuffer first, even before a bad filter or mask.
  GLuint empty = 0;
  glGenFramebuffersEXT(1, &empty);
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, empty);
  glBlitFramebufferEXT(0, 0, 1, 1, 0, 0, 1, 1, 0x80000000, GL_NEAREST + 7);
  EXPECT_EQ(glGetError(), kInvalidFramebufferOperation);
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  glBlitFramebufferEXT(0, 0, 1, 1, 0, 0, 1, 1, 0x80000000, GL_NEAREST + 7);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glBlitFramebufferEXT(0, 0, 1, 1, 0, 0, 1, 1, 0x80000000, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glBlitFramebufferEXT(0, 0, 1, 1, 0, 0, 1, 1, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glBlitFramebufferEXT(0, 0, 1, 1, 0, 0, 1, 1, GL_STENCIL_BUFFER_BIT, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  // Window to window: every buffer exists in both.
  glBlitFramebufferEXT(0, 0, 1, 1, 2, 2, 3, 3,
                       GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                       GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // A 16-bit depth renderbuffer against the window's 24 bits: the formats do not match.
  GLuint fb = framebuffer_with_texture(16, 16, {}, nullptr);
  const GLuint rb =
      glpt_test::attach_renderbuffer(GL_DEPTH_ATTACHMENT_EXT, GL_DEPTH_COMPONENT16, 16, 16);
  ASSERT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  glBlitFramebufferEXT(0, 0, 1, 1, 0, 0, 1, 1, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  // The object has no stencil: a stencil blit is silently nothing.
  glBlitFramebufferEXT(0, 0, 1, 1, 0, 0, 1, 1, GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteFramebuffersEXT(1, &empty);
  glDeleteRenderbuffersEXT(1, &rb);
}

TEST_F(FramebufferBlitTest, NearestCopiesScalesAndMirrors) {
  GLuint texture = 0;
  const GLuint fb = framebuffer_with_texture(4, 4, ramp_4x4(), &texture);
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, 0);
  ASSERT_EQ(get_integer(GL_READ_FRAMEBUFFER_BINDING_EXT), GLint(fb));
  // 1:1 at (0, 0); twice the size at (4, 0); mirrored in x and y at (12, 0).
  glBlitFramebufferEXT(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBlitFramebufferEXT(0, 0, 4, 4, 4, 0, 12, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBlitFramebufferEXT(0, 0, 4, 4, 16, 4, 12, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(window_pixel(0, 0), (std::array<int, 4>{40, 40, 7, 255}));
  EXPECT_EQ(window_pixel(3, 2), (std::array<int, 4>{190, 140, 7, 255}));
  EXPECT_EQ(window_pixel(4, 0), (std::array<int, 4>{40, 40, 7, 255}));
  EXPECT_EQ(window_pixel(5, 1), (std::array<int, 4>{40, 40, 7, 255}));
  EXPECT_EQ(window_pixel(6, 7), (std::array<int, 4>{90, 190, 7, 255}));
  EXPECT_EQ(window_pixel(12, 0), (std::array<int, 4>{190, 190, 7, 255}));
  EXPECT_EQ(window_pixel(15, 3), (std::array<int, 4>{40, 40, 7, 255}));
  EXPECT_EQ(window_pixel(0, 8), (std::array<int, 4>{0, 0, 0, 0}));  // not written
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteTextures(1, &texture);
}

TEST_F(FramebufferBlitTest, ScissorAndReadBufferEdgeCutTheDestination) {
  GLuint texture = 0;
  const GLuint fb = framebuffer_with_texture(4, 4, ramp_4x4(), &texture);
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, 0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 2, 16);
  glBlitFramebufferEXT(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glDisable(GL_SCISSOR_TEST);
  // A source rectangle reaching past the read buffer: the destination pixels it maps there are
  // not written (Mesa clips both rectangles).
  glBlitFramebufferEXT(2, 0, 6, 1, 8, 0, 12, 1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(window_pixel(1, 0), (std::array<int, 4>{90, 40, 7, 255}));
  EXPECT_EQ(window_pixel(2, 0), (std::array<int, 4>{0, 0, 0, 0}));
  EXPECT_EQ(window_pixel(9, 0), (std::array<int, 4>{190, 40, 7, 255}));
  EXPECT_EQ(window_pixel(10, 0), (std::array<int, 4>{0, 0, 0, 0}));
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteTextures(1, &texture);
}

TEST_F(FramebufferBlitTest, LinearBlendsNeighbours) {
  // Two texels, 0 and 200 in red: magnified four times, the middle pixels blend them.
  const std::vector<GLubyte> texels = {0, 0, 0, 255, 200, 0, 0, 255};
  GLuint texture = 0;
  const GLuint fb = framebuffer_with_texture(2, 1, texels, &texture);
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, 0);
  glBlitFramebufferEXT(0, 0, 2, 1, 0, 0, 8, 1, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // Pixel i samples at (i + 0.5) / 4 - 0.5 texels: clamped 0, 0, 0.125, 0.375, 0.625, ...
  EXPECT_EQ(window_pixel(0, 0)[0], 0);
  EXPECT_EQ(window_pixel(1, 0)[0], 0);
  EXPECT_NEAR(window_pixel(2, 0)[0], 25, 1);
  EXPECT_NEAR(window_pixel(3, 0)[0], 75, 1);
  EXPECT_NEAR(window_pixel(4, 0)[0], 125, 1);
  EXPECT_EQ(window_pixel(7, 0)[0], 200);
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteTextures(1, &texture);
}

TEST_F(FramebufferBlitTest, DepthAndStencilCopyIntoAnObject) {
  // The window's depth and stencil, cleared, go into an object's depth-stencil renderbuffer.
  glClearDepth(0.25);
  glClearStencil(0x5A);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  GLuint texture = 0;
  const GLuint fb = framebuffer_with_texture(16, 16, {}, &texture);
  const GLuint rb =
      glpt_test::attach_renderbuffer(GL_DEPTH_ATTACHMENT_EXT, GL_DEPTH24_STENCIL8_EXT, 16, 16);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_STENCIL_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                               rb);
  ASSERT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  glBlitFramebufferEXT(0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                       GL_NEAREST);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, fb);
  GLfloat depth[2] = {};
  GLubyte stencil[2] = {};
  glReadPixels(7, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glReadPixels(7, 0, 2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  EXPECT_NEAR(depth[0], 0.25f, 1e-6f);
  EXPECT_NEAR(depth[1], 1.0f, 1e-6f);
  EXPECT_EQ(stencil[0], 0x5A);
  EXPECT_EQ(stencil[1], 0);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteRenderbuffersEXT(1, &rb);
  glDeleteTextures(1, &texture);
}

TEST_F(FramebufferBlitTest, BlitIntoATextureAndReadsFromTheReadFramebuffer) {
  // The window, cleared to a colour, goes into the object's texture through a blit.
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  GLuint texture = 0;
  const GLuint fb = framebuffer_with_texture(4, 4, ramp_4x4(), &texture);
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  glBlitFramebufferEXT(0, 0, 2, 2, 0, 0, 2, 2, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  // glReadPixels reads the read framebuffer (the window) while the object is drawn into.
  GLubyte p[4] = {};
  glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(std::vector<int>(p, p + 4), (std::vector<int>{51, 102, 153, 255}));
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  std::vector<GLubyte> texels(4 * 4 * 4);
  glBindTexture(GL_TEXTURE_2D, texture);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(std::vector<int>(texels.begin(), texels.begin() + 4),
            (std::vector<int>{51, 102, 153, 255}));
  EXPECT_EQ(int(texels[(1 * 4 + 1) * 4]), 51);        // (1, 1): blitted
  EXPECT_EQ(int(texels[(2 * 4 + 2) * 4]), 40 + 100);  // (2, 2): the texture's own
  // glCopyTexSubImage2D from the object (the read framebuffer) while the window is drawn into.
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, fb);
  GLuint copy = 0;
  glGenTextures(1, &copy);
  glBindTexture(GL_TEXTURE_2D, copy);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 3, 3, 1, 1);
  GLubyte t[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(std::vector<int>(t, t + 4), (std::vector<int>{190, 190, 7, 255}));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteTextures(1, &texture);
  glDeleteTextures(1, &copy);
}

TEST_F(FramebufferBlitTest, CopyPixelsReadsTheReadFramebuffer) {
  GLuint texture = 0;
  const GLuint fb = framebuffer_with_texture(4, 4, ramp_4x4(), &texture);
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, 0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 16, 0, 16, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRasterPos2i(10, 10);
  glCopyPixels(1, 2, 2, 2, GL_COLOR);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(window_pixel(10, 10), (std::array<int, 4>{90, 140, 7, 255}));
  EXPECT_EQ(window_pixel(11, 11), (std::array<int, 4>{140, 190, 7, 255}));
  EXPECT_EQ(window_pixel(12, 12), (std::array<int, 4>{0, 0, 0, 0}));
  glDeleteFramebuffersEXT(1, &fb);
  glDeleteTextures(1, &texture);
}

// Undefined but safe (EXT_framebuffer_object 4.4.3, EXT_framebuffer_blit): a texture sampled by
// the draws of the framebuffer object it is attached to, a blit whose rectangles overlap in one
// framebuffer, and a blit after the read attachment's texture was deleted: no error but the ones
// named, no crash, and the pixels outside the feedback keep their values.
TEST_F(FramebufferBlitTest, FeedbackLoopsAndDeletedAttachmentsAreSafe) {
  GLuint texture = 0;
  const GLuint fb = framebuffer_with_texture(4, 4, ramp_4x4(), &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glpt_test::full_viewport_textured_quad();  // samples the texture it draws into
  glDisable(GL_TEXTURE_2D);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glBlitFramebufferEXT(0, 0, 3, 3, 1, 1, 4, 4, GL_COLOR_BUFFER_BIT, GL_LINEAR);  // overlapping
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // The read framebuffer loses its only attachment: incomplete, and the blit says so.
  glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, 0);
  glDeleteTextures(1, &texture);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_READ_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT});
  glBlitFramebufferEXT(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), kInvalidFramebufferOperation);
  GLubyte p[4] = {1, 2, 3, 4};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(glGetError(), kInvalidFramebufferOperation);
  EXPECT_EQ(std::vector<int>(p, p + 4), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(window_pixel(0, 0), (std::array<int, 4>{0, 0, 0, 0}));
  // Huge and inverted rectangles are clipped, not allocated.
  glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
  glBlitFramebufferEXT(-2147483647, -2147483647, 2147483647, 2147483647, 2147483647, 2147483647,
                       -2147483647, -2147483647, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glDeleteFramebuffersEXT(1, &fb);
}

}  // namespace
