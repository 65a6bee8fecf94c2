// EXT_packed_depth_stencil: GL_DEPTH_STENCIL / GL_DEPTH24_STENCIL8 textures, the GL_DEPTH_STENCIL
// pixel format with GL_UNSIGNED_INT_24_8 in texture commands, glReadPixels, glDrawPixels and
// glCopyPixels. Every expected value and error was measured on Mesa 25.0.7 (OSMesa, a throwaway
// probe) or follows from the extension's word layout (depth << 8 | stencil).
#include <array>
#include <vector>

#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/textures/texture_snapshot.hpp"
#include "gl_test_context.hpp"

namespace {

using Words = std::vector<GLuint>;

class PackedDepthStencilTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
  }
  void upload(GLint internal_format = GL_DEPTH24_STENCIL8_EXT) {
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, 2, 2, 0, GL_DEPTH_STENCIL_EXT,
                 GL_UNSIGNED_INT_24_8_EXT, kImage.data());
  }
  Words tex_words() {
    Words out(4, 0xEEEEEEEEu);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, out.data());
    return out;
  }
  GLint level_parameter(GLenum pname) {
    GLint v = -7;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, pname, &v);
    return v;
  }
  static constexpr std::array<GLuint, 4> kImage{0x400000BBu, 0x7F0000CCu, 0xC0000011u, 0xFFFFFF22u};
};

GLenum tex_image_error(GLenum target, GLint internal_format, GLenum format, GLenum type) {
  if (target == GL_TEXTURE_3D || target == GL_PROXY_TEXTURE_3D)
    glTexImage3D(target, 0, internal_format, 2, 2, 2, 0, format, type, nullptr);
  else if (target == GL_TEXTURE_1D)
    glTexImage1D(target, 0, internal_format, 2, 0, format, type, nullptr);
  else
    glTexImage2D(target, 0, internal_format, 2, 2, 0, format, type, nullptr);
  return glGetError();
}

TEST_F(PackedDepthStencilTest, TexImageErrorsAreMesas) {
  struct Case {
    GLenum target;
    GLint internal_format;
    GLenum format, type, error;
  };
  const Case cases[] = {
      {GL_TEXTURE_2D, GL_DEPTH24_STENCIL8_EXT, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT,
       GL_NO_ERROR},
      {GL_TEXTURE_2D, GL_RGBA8, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT,
       GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, GL_DEPTH_COMPONENT16, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT,
       GL_NO_ERROR},
      {GL_TEXTURE_2D, GL_DEPTH24_STENCIL8_EXT, GL_DEPTH_COMPONENT, GL_FLOAT, GL_NO_ERROR},
      {GL_TEXTURE_2D, GL_DEPTH24_STENCIL8_EXT, GL_STENCIL_INDEX, GL_INT, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, GL_DEPTH_COMPONENT16, GL_STENCIL_INDEX, GL_INT, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, GL_RGBA, GL_RGBA, GL_UNSIGNED_INT_24_8_EXT, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, GL_RGBA, 0x1234, GL_UNSIGNED_INT_24_8_EXT, GL_INVALID_ENUM},
      {GL_TEXTURE_2D, GL_DEPTH_STENCIL_EXT, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT, GL_INVALID_ENUM},
      {GL_TEXTURE_2D, GL_DEPTH_STENCIL_EXT, GL_DEPTH_STENCIL_EXT, GL_BITMAP, GL_INVALID_ENUM},
      {GL_TEXTURE_3D, GL_DEPTH24_STENCIL8_EXT, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT,
       GL_INVALID_OPERATION},
      {GL_TEXTURE_3D, GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_FLOAT, GL_INVALID_OPERATION},
      {GL_PROXY_TEXTURE_3D, GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_FLOAT, GL_INVALID_OPERATION},
      {GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_DEPTH24_STENCIL8_EXT, GL_DEPTH_STENCIL_EXT,
       GL_UNSIGNED_INT_24_8_EXT, GL_NO_ERROR},
      {GL_TEXTURE_1D, GL_DEPTH_STENCIL_EXT, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT,
       GL_NO_ERROR},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(tex_image_error(c.target, c.internal_format, c.format, c.type), c.error)
        << std::hex << c.internal_format << " " << c.format << " " << c.type;
  }
}

TEST_F(PackedDepthStencilTest, ImagesKeepDepthAndStencil) {
  upload();
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT), GL_DEPTH24_STENCIL8_EXT);
  EXPECT_EQ(level_parameter(GL_TEXTURE_DEPTH_SIZE), 24);
  EXPECT_EQ(level_parameter(GL_TEXTURE_STENCIL_SIZE_EXT), 8);
  EXPECT_EQ(level_parameter(GL_TEXTURE_RED_SIZE), 0);
  EXPECT_EQ(tex_words(), Words(kImage.begin(), kImage.end()));
  // Depth alone: z / (2^24 - 1), as float and as 16 bits.
  std::array<GLfloat, 4> depth{};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  EXPECT_EQ(depth[0], 0x400000 / 16777215.0f);
  EXPECT_EQ(depth[3], 1.0f);
  std::array<GLushort, 4> depth16{};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, depth16.data());
  EXPECT_EQ(depth16, (std::array<GLushort, 4>{16384, 32512, 49151, 65535}));
  // Stencil alone (Mesa allows it: ARB_texture_stencil8), without pixel transfer.
  glPixelTransferi(GL_INDEX_OFFSET, 3);
  std::array<GLubyte, 4> stencil{};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  EXPECT_EQ(stencil, (std::array<GLubyte, 4>{0xBB, 0xCC, 0x11, 0x22}));
  EXPECT_EQ(tex_words(), Words(kImage.begin(), kImage.end()));
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  EXPECT_EQ(tex_words()[0], 0xBB000040u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // A GL_DEPTH_STENCIL image samples as a depth texture.
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glpt::rec::TexturingState s;
  glpt::snapshot_texturing(ctx_, s);
  ASSERT_NE(s.units[0].texture, nullptr);
  EXPECT_EQ(s.units[0].texture->base_format, GLenum{GL_DEPTH_COMPONENT});
  EXPECT_EQ(s.units[0].texture->faces[0][0]->stencil,
            (std::vector<uint8_t>{0xBB, 0xCC, 0x11, 0x22}));
}

TEST_F(PackedDepthStencilTest, UploadsConvertAsMesa) {
  // Index shift/offset reach the stencil indices; depth scale sends depth through floats.
  glPixelTransferi(GL_INDEX_OFFSET, 3);
  upload();
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  EXPECT_EQ(tex_words(), (Words{0x400000BE, 0x7F0000CF, 0xC0000014, 0xFFFFFF25}));
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  upload(GL_DEPTH_STENCIL_EXT);
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
  EXPECT_EQ(tex_words(), (Words{0x200000BB, 0x3F8000CC, 0x60000011, 0x7FFFFF22}));
  // Into a 16-bit depth texture: the float product, truncated.
  upload(GL_DEPTH_COMPONENT16);
  std::array<GLushort, 4> depth16{};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, depth16.data());
  EXPECT_EQ(depth16, (std::array<GLushort, 4>{16383, 32511, 49151, 65535}));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // Sub-images of either kind of depth data.
  upload();
  const GLuint word = 0x12345678;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT,
                  &word);
  const GLfloat half = 0.5f;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &half);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const Words words = tex_words();
  EXPECT_EQ(words[0] >> 8, 0x7FFFFFu);  // its stencil index is undefined (garbage in Mesa)
  EXPECT_EQ(words[3], 0x12345678u);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &word);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

TEST_F(PackedDepthStencilTest, GetTexImageFormatsMustMatch) {
  upload();
  std::array<GLfloat, 16> out{};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out.data());
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT, out.data());
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_INT_24_8_EXT, out.data());
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  upload(GL_DEPTH_COMPONENT16);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, out.data());
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glGetTexImage(GL_TEXTURE_2D, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

// The drawable's depth/stencil buffer through the raster renderer (lavapipe).
class PackedDepthStencilFramebufferTest : public PackedDepthStencilTest {
 protected:
  void SetUp() override {
    PackedDepthStencilTest::SetUp();
    glpt::make_current_headless(ctx_, target_);
    // A clear depth whose 24-bit value does not depend on rounding (Mesa truncates clear depths,
    // glpt's raster renderer rounds them: 0.3 is 0x4CCCCC in Mesa, 0x4CCCCD here).
    glClearDepth(1.0);
    glClearStencil(0x5A);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  }
  void TearDown() override {
    ctx_.target = nullptr;
    GlTest::TearDown();
  }
  Words read(GLint x, GLint y) {
    Words out(4, 0xEEEEEEEEu);
    glReadPixels(x, y, 2, 2, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, out.data());
    return out;
  }
  glpt_test::RasterMode raster_mode_;
  glpt::HeadlessTarget target_{32, 32};
};

TEST_F(PackedDepthStencilFramebufferTest, ReadPixelsPacksDepthAboveStencil) {
  EXPECT_EQ(read(0, 0), Words(4, 0xFFFFFF5Au));
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  EXPECT_EQ(read(0, 0)[0], 0x5AFFFFFFu);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8_EXT, 0, 0, 2, 2, 0);
  EXPECT_EQ(tex_words(), Words(4, 0xFFFFFF5Au));
  GLuint word = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT, &word);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8_EXT, &word);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

TEST_F(PackedDepthStencilFramebufferTest, DrawPixelsWritesBothWhateverTheTests) {
  const GLuint image[4] = {0x12345601, 0xABCDEF02, 0x00000103, 0xFFFFFFFF};
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0);
  glColor4f(1, 0, 0, 1);
  glWindowPos2i(4, 4);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  EXPECT_EQ(read(4, 4), Words(image, image + 4));
  GLubyte rgba[4] = {1, 1, 1, 1};
  glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[0], 0);  // no colour written
  // Reading through depth scale and index offset takes Mesa's float path.
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  EXPECT_EQ(read(4, 4), (Words{0x091A2B02, 0x55E6F703, 0x00000004, 0x7FFFFF00}));
  // Drawing ignores both (Mesa uploads the words as they are).
  glWindowPos2i(12, 12);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  EXPECT_EQ(read(12, 12), Words(image, image + 4));
  // The depth and stencil write masks apply.
  glDepthMask(GL_FALSE);
  glStencilMask(0x0F);
  glWindowPos2i(8, 8);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  EXPECT_EQ(read(8, 8), (Words{0xFFFFFF51, 0xFFFFFF52, 0xFFFFFF53, 0xFFFFFF5F}));
  // glCopyPixels(GL_DEPTH_STENCIL) copies both.
  glWindowPos2i(20, 20);
  glCopyPixels(4, 4, 2, 2, GL_DEPTH_STENCIL_EXT);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(read(20, 20), Words(image, image + 4));
}

TEST_F(GlTest, DepthStencilPixelsNeedBothBuffers) {
  glpt::rec::DrawableConfig config;
  config.stencil_bits = 0;
  glpt::HeadlessTarget target(4, 4, config);
  glpt::make_current_headless(ctx_, target);
  GLuint words[4] = {};
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, words);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glDrawPixels(1, 1, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, words);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glCopyPixels(0, 0, 1, 1, GL_DEPTH_STENCIL_EXT);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8_EXT, 0, 0, 2, 2, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 2, 2, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8_EXT, 2, 2, 0, GL_DEPTH_STENCIL_EXT,
               GL_UNSIGNED_INT_24_8_EXT, nullptr);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  ctx_.target = nullptr;
}

}  // namespace
