// glReadPixels, glCopyTexImage and glCopyTexSubImage read the drawable through read_framebuffer:
// a headless target cleared to a known colour (the renderer reproduces the clear colour exactly).
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "gl_shim/frame/headless_target.hpp"
#include "gl_test_context.hpp"

namespace {

class FramebufferReadTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glpt::make_current_headless(ctx_, target_);
    glClearColor(100 / 255.0f, 50 / 255.0f, 30 / 255.0f, 200 / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  void TearDown() override {
    ctx_.target = nullptr;
    GlTest::TearDown();
  }
  glpt_test::RasterMode raster_mode_;
  glpt::HeadlessTarget target_{8, 8};
};

TEST_F(FramebufferReadTest, ReadPixelsPacksTheColourBuffer) {
  GLubyte rgba[4] = {};
  glReadPixels(2, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(std::vector<int>(rgba, rgba + 4), (std::vector<int>{100, 50, 30, 200}));
  GLubyte la[2] = {};
  glReadPixels(0, 0, 1, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
  EXPECT_EQ(la[0], 180);  // Mesa: R + G + B
  GLushort s565 = 0;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &s565);
  // 100/255*31 = 12.15 -> 12, 50/255*63 = 12.35 -> 12, 30/255*31 = 3.6 -> 4.
  EXPECT_EQ(s565, (12 << 11) | (12 << 5) | 4);
  // Pixel transfer applies.
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[0], 50);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  // Pixels outside the drawable are not written.
  GLubyte row[4 * 4];
  std::fill(std::begin(row), std::end(row), GLubyte(7));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(6, 0, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
  EXPECT_EQ(row[4], 100);  // x = 7, inside
  EXPECT_EQ(row[8], 7);    // x = 8, outside
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(FramebufferReadTest, CopyTexImageReadsThroughPixelTransfer) {
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLubyte texel[4 * 16] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(std::vector<int>(texel, texel + 4), (std::vector<int>{50, 50, 30, 200}));
  GLint w = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 4);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 0, 0, 2, 2, 0);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(texel[0], 100);  // luminance from R
  // Sub-images land at their offset.
  const GLubyte zero[4 * 16] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, zero);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 0, 0, 1, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(texel[(2 * 4 + 1) * 4], 100);
  EXPECT_EQ(texel[(2 * 4 + 0) * 4], 0);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB8, 0, 0, 2, 0);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(std::vector<int>(texel, texel + 4), (std::vector<int>{100, 50, 30, 255}));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(FramebufferReadTest, ReadPixelsReadsDepthAndStencilThroughTransfer) {
  glClearDepth(0.5);
  glClearStencil(5);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  GLushort depth16 = 0;
  glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &depth16);
  EXPECT_EQ(depth16, 32768);
  GLfloat depth = 0;
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.125f);
  glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_NEAR(depth, 0.375f, 1e-6f);
  GLubyte stencil = 0;
  glReadPixels(1, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
  EXPECT_EQ(stencil, 5);
  glPixelTransferi(GL_INDEX_OFFSET, 2);
  glReadPixels(1, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
  EXPECT_EQ(stencil, 7);
  const GLfloat map[8] = {0, 1, 2, 3, 4, 5, 6, 42};
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 8, map);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  glReadPixels(1, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
  EXPECT_EQ(stencil, 42);
  GLubyte bit = 0;  // 42 = 0b101010: the low bit is 0; 7 would give 1
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
  glReadPixels(1, 1, 1, 1, GL_STENCIL_INDEX, GL_BITMAP, &bit);
  EXPECT_EQ(bit, 0x80);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, DepthAndStencilNeedTheBuffers) {
  glpt::rec::DrawableConfig config;
  config.depth_bits = 0;
  config.stencil_bits = 0;
  glpt::HeadlessTarget target(4, 4, config);
  glpt::make_current_headless(ctx_, target);
  GLfloat f[16];
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, f);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_FLOAT, f);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 2, 2, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  ctx_.target = nullptr;
}

TEST_F(FramebufferReadTest, CopyTexImageErrorsMatchMesa) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 3, 0, 0, 4, 4, 0);  // 1..4 are not allowed
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 0, 0, 4, 4, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 2);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -4, 4, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, GL_RGBA, 0, 0, 4, 2, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
}

// GL 1.5 4.2.1: GL_LEFT names the front left and the back left buffer (piglit
// gl-1.0-drawbuffer-modes); a non-stereo drawable has no right buffers.
TEST_F(FramebufferReadTest, DrawBufferLeftWritesFrontAndBack) {
  glDrawBuffer(GL_LEFT);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  glRectf(-1.0f, -1.0f, 0.0f, 0.0f);  // the lower left quarter: pixels (0..3, 0..3)
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  for (GLenum buffer : {GL_FRONT, GL_BACK}) {
    glReadBuffer(buffer);
    GLubyte rgba[4] = {};
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    EXPECT_EQ(std::vector<int>(rgba, rgba + 4), (std::vector<int>{0, 255, 0, 255})) << buffer;
    glReadPixels(6, 6, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    EXPECT_EQ(std::vector<int>(rgba, rgba + 4), (std::vector<int>{0, 0, 255, 255})) << buffer;
  }
  for (GLenum right : {GL_RIGHT, GL_FRONT_RIGHT, GL_BACK_RIGHT}) {
    glDrawBuffer(right);
    EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
    glReadBuffer(right);
    EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  }
  GLint draw_buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &draw_buffer);
  EXPECT_EQ(draw_buffer, GL_LEFT);
}

}  // namespace

namespace {

// piglit streaming-texture-leak: a new 1024x1024 texture at every draw, deleted after it. The
// record must not hold every texture until the frame ends: once its draws sample more than
// 256 MiB of distinct textures it is executed (as when it holds too many vertices).
TEST_F(FramebufferReadTest, DrawsOfReplacedTexturesAreExecutedBeforeTheyFillMemory) {
  constexpr int kSide = 1024;                                      // 4 MiB of texels each
  std::vector<GLuint> texels(size_t{kSide} * kSide, 0xff00ff00u);  // ABGR: opaque green
  glEnable(GL_TEXTURE_2D);
  constexpr int kDraws = 70;  // 280 MiB in all
  size_t most_commands = 0;
  for (int i = 0; i < kDraws; ++i) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, kSide, kSide, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels.data());
    glpt_test::full_viewport_textured_quad();
    glDeleteTextures(1, &texture);
    most_commands = std::max(most_commands, ctx_.recorder.record().commands.size());
  }
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // The clear and at most 64 draws (256 MiB) before the record ran.
  EXPECT_LE(most_commands, 66u);
  EXPECT_LT(ctx_.recorder.record().commands.size(), size_t{kDraws});
  GLubyte rgba[4] = {};
  glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(std::vector<int>(rgba, rgba + 4), (std::vector<int>{0, 255, 0, 255}));
}

}  // namespace
