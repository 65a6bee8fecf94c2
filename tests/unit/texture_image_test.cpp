// glTexImage*, glTexSubImage*, glGetTexImage, glGetTexLevelParameter, proxies, borders, internal
// formats, mipmap generation. Expected values are Mesa 25's (llvmpipe through OSMesa), measured
// with throwaway programs, or computed by hand from GL 1.5.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gl_shim/textures/texture_snapshot.hpp"
#include "gl_test_context.hpp"

namespace {

constexpr GLenum kTextureStencilSize = 0x88F1;  // GL 3.0

class TexImageTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
  }
  GLint level_parameter(GLenum pname, GLint level = 0, GLenum target = GL_TEXTURE_2D) {
    GLint v = -7;
    glGetTexLevelParameteriv(target, level, pname, &v);
    return v;
  }
  std::vector<GLubyte> rgba_bytes(GLint level, int texels, GLenum target = GL_TEXTURE_2D) {
    std::vector<GLubyte> out(size_t(texels) * 4, 0xEE);
    glGetTexImage(target, level, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    return out;
  }
};

TEST_F(TexImageTest, ComponentSizesAreMesas) {
  struct Case {
    GLint format;
    GLint r, g, b, a, l, i, d, reported;
  };
  const Case cases[] = {
      {3, 8, 8, 8, 0, 0, 0, 0, 3},
      {1, 0, 0, 0, 0, 8, 0, 0, 1},
      {GL_ALPHA4, 0, 0, 0, 8, 0, 0, 0, GL_ALPHA4},
      {GL_LUMINANCE12, 0, 0, 0, 0, 16, 0, 0, GL_LUMINANCE12},
      {GL_LUMINANCE4_ALPHA4, 0, 0, 0, 4, 4, 0, 0, GL_LUMINANCE4_ALPHA4},
      {GL_LUMINANCE6_ALPHA2, 0, 0, 0, 8, 8, 0, 0, GL_LUMINANCE6_ALPHA2},
      {GL_INTENSITY4, 0, 0, 0, 0, 0, 8, 0, GL_INTENSITY4},
      {GL_R3_G3_B2, 3, 3, 2, 0, 0, 0, 0, GL_R3_G3_B2},
      {GL_RGB5, 5, 5, 5, 0, 0, 0, 0, GL_RGB5},
      {GL_RGB10, 10, 10, 10, 0, 0, 0, 0, GL_RGB10},
      {GL_RGB12, 16, 16, 16, 0, 0, 0, 0, GL_RGB12},
      {GL_RGBA2, 4, 4, 4, 4, 0, 0, 0, GL_RGBA2},
      {GL_RGB5_A1, 5, 5, 5, 1, 0, 0, 0, GL_RGB5_A1},
      {GL_RGB10_A2, 10, 10, 10, 2, 0, 0, 0, GL_RGB10_A2},
      {GL_DEPTH_COMPONENT, 0, 0, 0, 0, 0, 0, 24, GL_DEPTH_COMPONENT},
      {GL_DEPTH_COMPONENT16, 0, 0, 0, 0, 0, 0, 16, GL_DEPTH_COMPONENT16},
      // Generic compressed formats Mesa does not compress: stored uncompressed and reported as
      // their base format (GL_COMPRESSED_RGB and RGBA: S3tcGenericFormatsAreDxt1AndDxt5).
      {GL_COMPRESSED_ALPHA, 0, 0, 0, 8, 0, 0, 0, GL_ALPHA},
      {GL_COMPRESSED_INTENSITY, 0, 0, 0, 0, 0, 8, 0, GL_INTENSITY},
      {GL_BGRA, 8, 8, 8, 8, 0, 0, 0, GL_BGRA},  // accepted by Mesa as RGBA8
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.format);
    const GLenum format = c.d != 0 ? GL_DEPTH_COMPONENT : GL_RGBA;
    glTexImage2D(GL_TEXTURE_2D, 0, c.format, 2, 2, 0, format, GL_UNSIGNED_BYTE, nullptr);
    EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
    EXPECT_EQ(level_parameter(GL_TEXTURE_RED_SIZE), c.r);
    EXPECT_EQ(level_parameter(GL_TEXTURE_GREEN_SIZE), c.g);
    EXPECT_EQ(level_parameter(GL_TEXTURE_BLUE_SIZE), c.b);
    EXPECT_EQ(level_parameter(GL_TEXTURE_ALPHA_SIZE), c.a);
    EXPECT_EQ(level_parameter(GL_TEXTURE_LUMINANCE_SIZE), c.l);
    EXPECT_EQ(level_parameter(GL_TEXTURE_INTENSITY_SIZE), c.i);
    EXPECT_EQ(level_parameter(GL_TEXTURE_DEPTH_SIZE), c.d);
    EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT), c.reported);
    EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED), 0);
  }
}

TEST_F(TexImageTest, TexelsAreQuantizedToTheFormatsBitsAsMesaDoes) {
  std::vector<GLubyte> ramp(256 * 4);
  for (int i = 0; i < 256; ++i) ramp[size_t(i) * 4] = ramp[size_t(i) * 4 + 3] = GLubyte(i);
  std::vector<GLfloat> back(256 * 4);
  // RGB5: round(i * 31 / 255), read back as q / 31.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5, 256, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp.data());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, back.data());
  for (int i = 0; i < 256; ++i) {
    const float q = std::floor(i * 31.0f / 255.0f + 0.5f);
    ASSERT_FLOAT_EQ(back[size_t(i) * 4], q / 31.0f) << i;
    ASSERT_FLOAT_EQ(back[size_t(i) * 4 + 3], 1.0f) << i;  // RGB: alpha is 1
  }
  // RGB10 from bytes: Mesa widens 8 -> 10 bits by replication, (i << 2) | (i >> 6).
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB10, 256, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp.data());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, back.data());
  for (int i = 0; i < 256; ++i)
    ASSERT_NEAR(back[size_t(i) * 4] * 1023.0f, float((i << 2) | (i >> 6)), 1e-3f) << i;
  // ... but from floats it rounds: 43/255 -> round(172.5...) = 173.
  const GLfloat f43[4] = {43.0f / 255.0f, 0, 0, 1};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB10, 1, 1, 0, GL_RGBA, GL_FLOAT, f43);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, back.data());
  EXPECT_NEAR(back[0] * 1023.0f, 173.0f, 1e-3f);
  // RGB5_A1: alpha is one bit.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5_A1, 256, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp.data());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, back.data());
  EXPECT_FLOAT_EQ(back[127 * 4 + 3], 0.0f);
  EXPECT_FLOAT_EQ(back[128 * 4 + 3], 1.0f);
}

TEST_F(TexImageTest, UnsignedClientIntegersConvertLikeMesasIntegerPath) {
  // Measured with OSMesa: fields narrower than the texture are widened by bit replication (a
  // 5-bit 7 becomes 57, not round(7 * 255 / 31) = 58), wider ones rounded.
  const GLushort s565 = GLushort((13 << 11) | (41 << 5) | 7);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &s565);
  EXPECT_EQ(rgba_bytes(0, 1), (std::vector<GLubyte>{107, 166, 57, 255}));
  const GLuint i1010102 = (1000u << 22) | (3u << 12) | (513u << 2) | 1u;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, &i1010102);
  EXPECT_EQ(rgba_bytes(0, 1), (std::vector<GLubyte>{249, 1, 128, 85}));
  const GLubyte b332 = 0xE9;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &b332);
  EXPECT_EQ(rgba_bytes(0, 1), (std::vector<GLubyte>{255, 73, 85, 255}));
  const GLushort s4444 = 0x1234;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, &s4444);
  EXPECT_EQ(rgba_bytes(0, 1), (std::vector<GLubyte>{17, 34, 51, 68}));
  // Signed bytes go through float: 63/127 * 255 = 126.5 -> 126, 64 -> 128.5 -> 129.
  const GLbyte b[4] = {63, 64, -5, 127};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_BYTE, b);
  EXPECT_EQ(rgba_bytes(0, 1), (std::vector<GLubyte>{126, 129, 0, 255}));
  // Luminance data has alpha 1: an ALPHA texture made from it is opaque.
  const GLubyte l = 77;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &l);
  EXPECT_EQ(rgba_bytes(0, 1), (std::vector<GLubyte>{0, 0, 0, 255}));
  // Narrow formats read back as bytes give the replicated values (Mesa: 0 99 132 247 for RGB5,
  // 0 109 146 255 for R3_G3_B2).
  const GLubyte r[16] = {4, 0, 0, 0, 100, 0, 0, 0, 133, 0, 0, 0, 250, 0, 0, 0};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5, 4, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, r);
  std::vector<GLubyte> back = rgba_bytes(0, 4);
  EXPECT_EQ((std::vector<int>{back[0], back[4], back[8], back[12]}),
            (std::vector<int>{0, 99, 132, 247}));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R3_G3_B2, 4, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, r);
  back = rgba_bytes(0, 4);
  EXPECT_EQ((std::vector<int>{back[0], back[4], back[8], back[12]}),
            (std::vector<int>{0, 109, 146, 255}));
  // A 5-bit 7 read as a byte is 57 as well.
  const GLushort s7 = 7;  // B = 7 in 5_6_5
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5, 1, 1, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &s7);
  EXPECT_EQ(rgba_bytes(0, 1)[2], 57);
}

TEST_F(TexImageTest, StorageLayoutExpandsTheBaseFormat) {
  const GLubyte c[4] = {100, 50, 30, 200};
  const auto texel_of = [&](GLint internal) {
    glTexImage2D(GL_TEXTURE_2D, 0, internal, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glpt::rec::TexturingState s;
    glpt::snapshot_texturing(ctx_, s);
    const auto& img = *s.units[0].texture->faces[0][0];
    return std::vector<int>(img.texels.begin(), img.texels.end());
  };
  EXPECT_EQ(texel_of(GL_RGBA), (std::vector<int>{100, 50, 30, 200}));
  EXPECT_EQ(texel_of(GL_RGB), (std::vector<int>{100, 50, 30, 255}));
  EXPECT_EQ(texel_of(GL_LUMINANCE), (std::vector<int>{100, 100, 100, 255}));
  EXPECT_EQ(texel_of(GL_LUMINANCE_ALPHA), (std::vector<int>{100, 100, 100, 200}));
  EXPECT_EQ(texel_of(GL_INTENSITY), (std::vector<int>{100, 100, 100, 100}));
  EXPECT_EQ(texel_of(GL_ALPHA), (std::vector<int>{0, 0, 0, 200}));
  // RGB5: 100 -> round(12.16) = 12 -> (12 << 3) | (12 >> 2) = 99.
  EXPECT_EQ(texel_of(GL_RGB5)[0], 99);
}

TEST_F(TexImageTest, GetTexImagePlacesBaseComponentsAsMesa) {
  const GLubyte c[4] = {100, 50, 30, 200};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  EXPECT_EQ(rgba_bytes(0, 1), (std::vector<GLubyte>{100, 0, 0, 200}));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_INTENSITY, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  EXPECT_EQ(rgba_bytes(0, 1), (std::vector<GLubyte>{100, 0, 0, 255}));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  GLubyte l[2] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, l);
  EXPECT_EQ(l[0], 100);  // luminance of a texture is R, not R + G + B
  EXPECT_EQ(l[1], 200);
  GLubyte abgr[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_ABGR_EXT, GL_UNSIGNED_BYTE, abgr);
  EXPECT_EQ(std::vector<GLubyte>(abgr, abgr + 4), (std::vector<GLubyte>{200, 30, 50, 100}));
  // No pixel transfer on the way out (Mesa).
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  EXPECT_EQ(rgba_bytes(0, 1)[0], 100);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(TexImageTest, PixelTransferAppliesOnTheWayIn) {
  const GLubyte c[4] = {200, 0, 0, 255};
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  EXPECT_EQ(rgba_bytes(0, 1)[0], 100);
}

TEST_F(TexImageTest, ColorIndexImagesGoThroughTheIndexMaps) {
  // Mesa: I_TO_R = {0.25, 0.75}, I_TO_A = {0.5}, RED_SCALE ignored for indices.
  const GLfloat r[2] = {0.25f, 0.75f};
  const GLfloat a[1] = {0.5f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, r);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 1, a);
  glPixelTransferf(GL_RED_SCALE, 2.0f);
  const GLubyte idx[4] = {0, 1, 2, 3};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 1, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
  EXPECT_EQ(rgba_bytes(0, 4),
            (std::vector<GLubyte>{64, 0, 0, 128, 191, 0, 0, 128, 64, 0, 0, 128, 191, 0, 0, 128}));
  glPixelTransferi(GL_INDEX_SHIFT, 1);  // every index becomes even: 0.25 everywhere
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 1, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
  EXPECT_EQ(rgba_bytes(0, 4)[12], 64);
  // Bitmaps are colour indices too.
  const GLubyte bits = 0x40;  // 0100...
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_COLOR_INDEX, GL_BITMAP, &bits);
  EXPECT_EQ(rgba_bytes(0, 2)[4], 191);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(TexImageTest, ErrorsMatchMesa) {
  const GLubyte t[64] = {};
  const auto expect = [&](GLenum error, const char* what) {
    EXPECT_EQ(glGetError(), error) << what;
  };
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 6, 2, GL_RGBA, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_VALUE, "border 2");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_VALUE, "width below twice the border");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  expect(GL_NO_ERROR, "non-power-of-two (Mesa accepts)");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  expect(GL_NO_ERROR, "0x0");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_VALUE, "negative width");
  glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_VALUE, "level -1");
  glTexImage2D(GL_TEXTURE_2D, glpt::kMaxTextureLevels, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               t);
  expect(GL_INVALID_VALUE, "level too high");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, glpt::kMaxTextureSize + 1, 1, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, nullptr);
  expect(GL_INVALID_VALUE, "too wide");
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, glpt::kMaxTextureSize, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  expect(GL_INVALID_VALUE, "too wide for level 1");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_BITMAP, t);
  expect(GL_INVALID_ENUM, "bitmap with RGBA");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_OPERATION, "stencil data");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, t);
  expect(GL_INVALID_OPERATION, "depth data into a colour texture");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 1, 1, 0, GL_RGBA, GL_FLOAT, t);
  expect(GL_INVALID_OPERATION, "colour data into a depth texture");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, t);
  expect(GL_INVALID_OPERATION, "packed type of another size");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 0, 0x1234, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_ENUM, "bad format");
  glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_VALUE, "bad internal format");
  glTexImage2D(GL_TEXTURE_2D, 0, 5, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_VALUE, "internal format 5");
  glTexImage2D(GL_TEXTURE_3D, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_ENUM, "3D target to glTexImage2D");
  glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_ENUM, "the cube map itself");
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGB, 2, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_VALUE, "non-square cube face");
  glTexImage1D(GL_TEXTURE_2D, 0, GL_RGB, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
  expect(GL_INVALID_ENUM, "2D target to glTexImage1D");
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, glpt::kMax3DTextureSize + 1, 1, 1, 0, GL_RGB,
               GL_UNSIGNED_BYTE, nullptr);
  expect(GL_INVALID_VALUE, "3D too large");
  glBegin(GL_TRIANGLES);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
  glEnd();
  expect(GL_INVALID_OPERATION, "inside glBegin/glEnd");
}

TEST_F(TexImageTest, BordersAreReportedButNotStored) {
  std::vector<GLubyte> img(6 * 6 * 4);
  for (size_t i = 0; i < img.size(); ++i) img[i] = GLubyte(i);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH), 6);
  EXPECT_EQ(level_parameter(GL_TEXTURE_HEIGHT), 6);
  EXPECT_EQ(level_parameter(GL_TEXTURE_BORDER), 1);
  EXPECT_EQ(level_parameter(GL_TEXTURE_DEPTH), 1);
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glpt::rec::TexturingState s;
  glpt::snapshot_texturing(ctx_, s);
  ASSERT_NE(s.units[0].texture, nullptr);
  const auto& stored = *s.units[0].texture->faces[0][0];
  EXPECT_EQ(stored.width, 4u);
  EXPECT_EQ(stored.height, 4u);
  EXPECT_EQ(stored.border, 1u);
  // The first stored texel is (1, 1) of the specified image: byte (1 * 6 + 1) * 4 = 28.
  EXPECT_EQ(stored.texels[0], 28);
  // glGetTexImage writes the 6x6 image GL reports; the border repeats the edge texels.
  const std::vector<GLubyte> back = rgba_bytes(0, 36);
  EXPECT_EQ(back[(1 * 6 + 1) * 4], 28);
  EXPECT_EQ(back[0], 28);
  EXPECT_EQ(back[(5 * 6 + 5) * 4], img[(4 * 6 + 4) * 4]);
  // Sub-images may reach into the border; what falls on it is dropped.
  const GLubyte one[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, one);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(rgba_bytes(0, 36)[0], 5);  // the interior texel (0,0) got the second texel
  glTexSubImage2D(GL_TEXTURE_2D, 0, -2, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, one);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
}

TEST_F(TexImageTest, UnpackModesSelectTheImage) {
  // A 2x2 image at (1, 2) of a 4-wide client image, rows aligned to 4 with 3-byte texels.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 4);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  std::vector<GLubyte> client(4 * 12, 0);
  client[2 * 12 + 3] = 11;
  client[2 * 12 + 6] = 22;
  client[3 * 12 + 3] = 33;
  client[3 * 12 + 6] = 44;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, client.data());
  const std::vector<GLubyte> back = rgba_bytes(0, 4);
  EXPECT_EQ(back[0], 11);
  EXPECT_EQ(back[4], 22);
  EXPECT_EQ(back[8], 33);
  EXPECT_EQ(back[12], 44);
}

TEST_F(TexImageTest, ThreeDimensionalImagesAndPackModes) {
  const GLubyte lum[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE, 2, 2, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  EXPECT_EQ(level_parameter(GL_TEXTURE_DEPTH, 0, GL_TEXTURE_3D), 2);
  // Read back the second image only, placed after one skipped image of 3 rows.
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 3);
  GLubyte out[2 * 3 * 2 + 4] = {};
  glGetTexImage(GL_TEXTURE_3D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 1);
  EXPECT_EQ(out[3], 4);
  EXPECT_EQ(out[6], 5);  // image 1 starts at row 3
  EXPECT_EQ(out[9], 8);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 1, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[9], 1);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(TexImageTest, SubImageErrorsMatchMesa) {
  const GLubyte t[64] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});  // undefined level
  glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glTexSubImage2D(GL_TEXTURE_2D, 0, 5, 5, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});  // offsets checked even when empty
  glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 0, 0, 0, 2, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glCopyTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 0, 0, 1, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

TEST_F(TexImageTest, GetTexImageErrors) {
  const GLubyte t[4] = {};
  GLubyte out[64];
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_BITMAP, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  // GL 1.5 6.1.4 says GL_INVALID_ENUM; Mesa (ARB_texture_stencil8) reads the stencil indices of
  // depth-stencil textures and reports GL_INVALID_OPERATION for the others (OSMesa).
  glGetTexImage(GL_TEXTURE_2D, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glGetTexImage(GL_TEXTURE_2D, -1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glGetTexImage(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetTexImage(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  out[0] = 77;
  glGetTexImage(GL_TEXTURE_2D, 5, GL_RGBA, GL_UNSIGNED_BYTE, out);  // undefined: nothing
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(out[0], 77);
}

TEST_F(TexImageTest, ProxiesReportWhatWouldFitWithoutErrors) {
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB, glpt::kMaxTextureSize * 2, 1, 0, GL_RGB,
               GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 0, GL_PROXY_TEXTURE_2D), 0);
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT, 0, GL_PROXY_TEXTURE_2D), GL_RGBA);  // Mesa
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB5, 64, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 0, GL_PROXY_TEXTURE_2D), 64);
  EXPECT_EQ(level_parameter(GL_TEXTURE_HEIGHT, 0, GL_PROXY_TEXTURE_2D), 32);
  EXPECT_EQ(level_parameter(GL_TEXTURE_RED_SIZE, 0, GL_PROXY_TEXTURE_2D), 5);
  // Argument errors are still errors and leave the proxy alone.
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB, -1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, 0x1234, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 0, GL_PROXY_TEXTURE_2D), 64);
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGB, 8, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});  // non-square: unsupported, not an error
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 0, GL_PROXY_TEXTURE_CUBE_MAP), 0);
  // The real texture is untouched.
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH), 0);
}

TEST_F(TexImageTest, LevelParameterQueriesOfUndefinedImagesAndErrors) {
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 3), 0);
  // Mesa (and GL 3+) answer GL_RGBA; GL 1.5's table 6.17 said 1.
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT, 3), GL_RGBA);
  const GLubyte t[4] = {};
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(level_parameter(GL_TEXTURE_HEIGHT, 0, GL_TEXTURE_1D), 1);
  EXPECT_EQ(level_parameter(GL_TEXTURE_DEPTH, 0, GL_TEXTURE_1D), 1);
  EXPECT_EQ(level_parameter(GL_TEXTURE_HEIGHT, 1, GL_TEXTURE_1D), 0);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLint v;
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glGetTexLevelParameteriv(GL_TEXTURE_2D, glpt::kMaxTextureLevels, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  GLfloat f = 0;
  glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &f);
  EXPECT_FLOAT_EQ(f, 1.0f);
}

// EXT_texture_compression_s3tc. Expected texels, bytes and errors are OSMesa 25.0.7's.
constexpr GLenum kDxt1Rgb = GL_COMPRESSED_RGB_S3TC_DXT1_EXT;
constexpr GLenum kDxt1Rgba = GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
constexpr GLenum kDxt3 = GL_COMPRESSED_RGBA_S3TC_DXT3_EXT;
constexpr GLenum kDxt5 = GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;

// Red (0xF800) and blue (0x001F) end points; texel t takes index t % 4.
constexpr GLubyte kFourColours[8] = {0x00, 0xF8, 0x1F, 0x00, 0xE4, 0xE4, 0xE4, 0xE4};
constexpr GLubyte kThreeColours[8] = {0x1F, 0x00, 0x00, 0xF8, 0xE4, 0xE4, 0xE4, 0xE4};

std::vector<GLubyte> first_texels(const std::vector<GLubyte>& rgba, int n) {
  return {rgba.begin(), rgba.begin() + 4 * n};
}

TEST_F(TexImageTest, S3tcDecodesAsLlvmpipe) {
  // The 1/3 and 2/3 colours round as gallivm's 85/256 and 170/256 weights do (Mesa's CPU decoder
  // would give 85 and 170 blue), DXT1's 3-colour midpoint rounds up (128, not 127).
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 4, 4, 0, 8, kFourColours);
  EXPECT_EQ(
      first_texels(rgba_bytes(0, 16), 4),
      (std::vector<GLubyte>{255, 0, 0, 255, 0, 0, 255, 255, 170, 0, 84, 255, 85, 0, 169, 255}));
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 4, 4, 0, 8, kThreeColours);
  EXPECT_EQ(first_texels(rgba_bytes(0, 16), 4),
            (std::vector<GLubyte>{0, 0, 255, 255, 255, 0, 0, 255, 128, 0, 128, 255, 0, 0, 0, 255}));
  // Only DXT1 RGBA makes index 3 of a 3-colour block transparent.
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgba, 4, 4, 0, 8, kThreeColours);
  EXPECT_EQ(first_texels(rgba_bytes(0, 16), 4),
            (std::vector<GLubyte>{0, 0, 255, 255, 255, 0, 0, 255, 128, 0, 128, 255, 0, 0, 0, 0}));
  // DXT5: texel t has alpha code t % 8. 8-alpha mode (255 > 0), then 6-alpha mode (0 <= 255).
  GLubyte dxt5[16] = {255, 0};
  uint64_t codes = 0;
  for (int t = 0; t < 16; ++t) codes |= uint64_t(t % 8) << (3 * t);
  for (int k = 0; k < 6; ++k) dxt5[2 + k] = GLubyte(codes >> (8 * k));
  std::copy(kFourColours, kFourColours + 8, dxt5 + 8);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt5, 4, 4, 0, 16, dxt5);
  std::vector<GLubyte> alphas;
  for (int t = 0; t < 8; ++t) alphas.push_back(rgba_bytes(0, 16)[size_t(4 * t + 3)]);
  EXPECT_EQ(alphas, (std::vector<GLubyte>{255, 0, 219, 183, 146, 110, 73, 37}));
  std::swap(dxt5[0], dxt5[1]);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt5, 4, 4, 0, 16, dxt5);
  alphas.clear();
  for (int t = 0; t < 8; ++t) alphas.push_back(rgba_bytes(0, 16)[size_t(4 * t + 3)]);
  EXPECT_EQ(alphas, (std::vector<GLubyte>{0, 255, 50, 101, 152, 203, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(TexImageTest, S3tcImagesKeepTheirBlocksAndAnswerQueriesAsMesa) {
  std::vector<GLubyte> data(64);
  for (size_t k = 0; k < data.size(); ++k) data[k] = GLubyte(k * 37 + 11);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt3, 13, 7, 0, 128, nullptr);  // sized: 4x2 blocks
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 13, 7, 0, 64, data.data());
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT), GLint(kDxt1Rgb));
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED), 1);
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED_IMAGE_SIZE), 64);
  EXPECT_EQ(level_parameter(GL_TEXTURE_RED_SIZE), 4);
  EXPECT_EQ(level_parameter(GL_TEXTURE_ALPHA_SIZE), 0);
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH), 13);
  std::vector<GLubyte> back(64, 0xEE);
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, back.data());
  EXPECT_EQ(back, data);
  // A sub-image reaching the right edge (one texel wide) replaces the last column of blocks.
  const GLubyte column[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 12, 0, 1, 7, kDxt1Rgb, 16, column);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, back.data());
  std::copy(column, column + 8, data.begin() + 24);
  std::copy(column + 8, column + 16, data.begin() + 56);
  EXPECT_EQ(back, data);
  // The generic formats stay uncompressed; a proxy of an S3TC format is compressed but has no
  // image size.
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GLint(kDxt5), 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED, 0, GL_PROXY_TEXTURE_2D), 1);
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT, 0, GL_PROXY_TEXTURE_2D), GLint(kDxt5));
  level_parameter(GL_TEXTURE_COMPRESSED_IMAGE_SIZE, 0, GL_PROXY_TEXTURE_2D);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  level_parameter(GL_TEXTURE_COMPRESSED_IMAGE_SIZE, 1);  // undefined image
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

TEST_F(TexImageTest, S3tcEncodesUncompressedDataAsMesa) {
  // An 8x4 image: two blocks each, compressed by Mesa's encoder (libtxc_dxtn).
  std::vector<GLubyte> image(8 * 4 * 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      GLubyte* p = &image[size_t(y * 8 + x) * 4];
      p[0] = GLubyte(x * 30 + y * 5), p[1] = GLubyte(200 - x * 20),
      p[2] = GLubyte((x * y * 17) & 255);
      p[3] = GLubyte(x < 4 ? y * 80 : (x * 37) & 255);
    }
  }
  const std::vector<std::vector<GLubyte>> expected = {
      {0x67, 0x5c, 0x42, 0x0e, 0x2d, 0x2d, 0x2d, 0x2d, 0x44, 0xc2, 0x9a, 0x8b, 0x0b, 0x2f, 0xbd,
       0x05},
      {0x40, 0x0e, 0x6a, 0x64, 0xff, 0xff, 0x68, 0x68, 0x9a, 0x8b, 0x44, 0xc2, 0xda, 0xe8, 0xe8,
       0xd0},
      {0x00, 0x00, 0x55, 0x55, 0xaa, 0xaa, 0xff, 0xff, 0x67, 0x5c, 0x42,
       0x0e, 0x2d, 0x2d, 0x2d, 0x2d, 0xb9, 0x0d, 0xb9, 0x0d, 0xb9, 0x0d,
       0xb9, 0x0d, 0x44, 0xc2, 0x9a, 0x8b, 0x0b, 0x2f, 0xbd, 0x05},
      {0x58, 0xf8, 0xb6, 0x0d, 0x00, 0xdb, 0x96, 0x24, 0x67, 0x5c, 0x42,
       0x0e, 0x2d, 0x2d, 0x2d, 0x2d, 0x98, 0xe2, 0x58, 0x8c, 0xc5, 0x58,
       0x8c, 0xc5, 0x44, 0xc2, 0x9a, 0x8b, 0x0b, 0x2f, 0xbd, 0x05},
  };
  const GLenum formats[4] = {kDxt1Rgb, kDxt1Rgba, kDxt3, kDxt5};
  for (int i = 0; i < 4; ++i) {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(formats[i]), 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.data());
    std::vector<GLubyte> back(expected[size_t(i)].size(), 0xEE);
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, back.data());
    EXPECT_EQ(back, expected[size_t(i)]) << "format " << std::hex << formats[i];
  }
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(TexImageTest, S3tcErrorsAreMesas) {
  std::vector<GLubyte> data(512, 0x55), out(512);
  const auto error = [] { return glGetError(); };
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 8, 8, 0, 31, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});  // imageSize
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 8, 8, 1, 32, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});  // border
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 8, 8, 0, 32, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});  // generic format
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, 256, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glCompressedTexImage1D(GL_TEXTURE_1D, 0, kDxt1Rgb, 8, 0, 16, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});  // no 1-D S3TC images
  glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP, 0, kDxt1Rgb, 8, 8, 0, 32, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, kDxt1Rgb, 8, 4, 0, 16, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glCompressedTexImage3D(GL_TEXTURE_3D, 0, kDxt1Rgb, 8, 8, 4, 0, 32, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});  // 3-D is allowed, 4 slices are 128 bytes
  glCompressedTexImage3D(GL_TEXTURE_3D, 0, kDxt1Rgb, 8, 8, 4, 0, 128, data.data());
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glTexImage1D(GL_TEXTURE_1D, 0, GLint(kDxt1Rgb), 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});

  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 8, 8, 0, 32, data.data());
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, kDxt1Rgb, 8, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});  // not on a block edge
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 4, kDxt1Rgb, 8, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});  // partial block inside the image
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 4, kDxt1Rgb, 16, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});  // beyond the image
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 4, 4, kDxt1Rgb, 7, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});  // imageSize
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 4, 4, kDxt1Rgba, 8, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});  // another format
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 4, 4, GL_COMPRESSED_RGB, 8, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 4, 4, kDxt1Rgb, 8, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});  // undefined level
  glCompressedTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 4, 4, kDxt1Rgb, 8, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glGetCompressedTexImage(GL_TEXTURE_2D, 1, out.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});  // undefined image
  glGetCompressedTexImage(GL_PROXY_TEXTURE_2D, 0, out.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});

  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, kDxt1Rgb, 8, data.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});  // not a compressed image
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, out.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED), 0);
}

TEST_F(TexImageTest, S3tcCopiesAndGeneratedLevelsAreCompressed) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, kDxt5, 0, 0, 5, 3, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED_IMAGE_SIZE), 32);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, kDxt5, 0, 0, 5, 3, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});  // no borders
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const std::vector<GLubyte> data(32, 0x3C);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 8, 8, 0, 32, data.data());
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT, 1), GLint(kDxt1Rgb));
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED_IMAGE_SIZE, 1), 8);
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 3), 1);
  // 3-D images of block slices generate compressed levels too (Mesa: level 1 of 8x8x4 DXT1 is
  // 4x4x2, 16 bytes).
  glBindTexture(GL_TEXTURE_3D, 1);
  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
  const std::vector<GLubyte> slices(128, 0x3C);
  glCompressedTexImage3D(GL_TEXTURE_3D, 0, kDxt1Rgb, 8, 8, 4, 0, 128, slices.data());
  EXPECT_EQ(level_parameter(GL_TEXTURE_DEPTH, 1, GL_TEXTURE_3D), 2);
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED_IMAGE_SIZE, 1, GL_TEXTURE_3D), 16);
  std::vector<GLubyte> level1(16, 0xEE);
  glGetCompressedTexImage(GL_TEXTURE_3D, 1, level1.data());
  EXPECT_NE(level1, std::vector<GLubyte>(16, 0xEE));  // blocks were written
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

// Mesa 25.0.7 (OSMesa, llvmpipe) stores GL_COMPRESSED_RGB and GL_COMPRESSED_RGBA as DXT1 and
// DXT5 on every target but 1-D, also from the framebuffer, for proxies and with a border.
TEST_F(TexImageTest, S3tcGenericFormatsAreDxt1AndDxt5) {
  std::vector<GLubyte> image(13 * 7 * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = GLubyte(i * 37);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 13, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.data());
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT), GLint(kDxt1Rgb));
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED), 1);
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED_IMAGE_SIZE), 64);
  EXPECT_EQ(level_parameter(GL_TEXTURE_RED_SIZE), 4);
  // The texels are the encoder's: the same as the image compressed as DXT1 explicitly.
  std::vector<GLubyte> generic(image.size()), explicit_dxt1(image.size());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, generic.data());
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(kDxt1Rgb), 13, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.data());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, explicit_dxt1.data());
  EXPECT_EQ(generic, explicit_dxt1);
  EXPECT_NE(generic, image);  // lossy
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 6, 5, 1, GL_RGBA, GL_UNSIGNED_BYTE,
               image.data());
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT), GLint(kDxt5));
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED_IMAGE_SIZE), 16);  // the 4x3 inside
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT, 0, GL_PROXY_TEXTURE_2D), GLint(kDxt5));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 0, 0, 8, 8, 0);
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT), GLint(kDxt5));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});  // not on block edges, as Mesa
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 1);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_COMPRESSED_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.data());
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT, 0, GL_TEXTURE_RECTANGLE_ARB), GLint(kDxt5));
  glBindTexture(GL_TEXTURE_1D, 2);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_COMPRESSED_RGBA, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  EXPECT_EQ(level_parameter(GL_TEXTURE_INTERNAL_FORMAT, 0, GL_TEXTURE_1D), GL_RGBA);
  EXPECT_EQ(level_parameter(GL_TEXTURE_COMPRESSED, 0, GL_TEXTURE_1D), 0);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(TexImageTest, DepthTexturesQuantizeToTheirBits) {
  const GLfloat d[2] = {0.3f, 1.5f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  GLfloat back[2] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  // Mesa's _mesa_unpack_depth_span truncates: 0.3f * 65535.0f = 19660.5 -> 19660 (OSMesa:
  // 0.299992383).
  EXPECT_FLOAT_EQ(back[0], 19660.0f / 65535.0f);
  EXPECT_FLOAT_EQ(back[1], 1.0f);  // clamped
  GLuint ui[2] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, ui);
  EXPECT_EQ(ui[1], 4294967295u);  // Mesa: D24 level 0 read as uint
  GLubyte c[8];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

// GL_TEXTURE_STENCIL_SIZE (GL 3.0, EXT_packed_depth_stencil) is answered as Mesa does in a
// compatibility context: 0 for every format glpt has, with or without an image, no error.
TEST_F(TexImageTest, StencilSizeIsZero) {
  EXPECT_EQ(level_parameter(kTextureStencilSize), 0);
  const GLubyte t[16] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(level_parameter(kTextureStencilSize), 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 2, 0, GL_DEPTH_COMPONENT,
               GL_UNSIGNED_BYTE, t);
  EXPECT_EQ(level_parameter(kTextureStencilSize), 0);
  EXPECT_EQ(level_parameter(kTextureStencilSize, 0, GL_PROXY_TEXTURE_2D), 0);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

// Integer depth data as Mesa stores it (values read back as floats from OSMesa): the texture's own
// integer width is copied, 32-bit to 16-bit shifts right by 16, 16-bit to 32-bit replicates, and
// everything else goes through floats, truncated.
TEST_F(TexImageTest, IntegerDepthDataIsStoredAsMesaDoes) {
  const GLushort us[4] = {0x1234, 0x8000, 0xffff, 0x0001};
  const GLuint ui[4] = {0x12345678u, 0x80000000u, 0xffffffffu, 0x0001ffffu};
  const GLubyte ub[4] = {0x12, 0x80, 0xff, 0x01};
  struct Case {
    GLenum format, type;
    const void* data;
    float expected[4];
  };
  const Case cases[] = {
      {GL_DEPTH_COMPONENT16,
       GL_UNSIGNED_SHORT,
       us,
       {0.0711070448f, 0.500007629f, 1.0f, 1.52590219e-05f}},
      {GL_DEPTH_COMPONENT16,
       GL_UNSIGNED_INT,
       ui,
       {0.0711070448f, 0.500007629f, 1.0f, 1.52590219e-05f}},
      {GL_DEPTH_COMPONENT16,
       GL_UNSIGNED_BYTE,
       ub,
       {0.0705882385f, 0.501960754f, 1.0f, 0.00392156839f}},
      {GL_DEPTH_COMPONENT24,
       GL_UNSIGNED_SHORT,
       us,
       {0.0711070374f, 0.500007629f, 1.0f, 1.52587909e-05f}},
      {GL_DEPTH_COMPONENT24,
       GL_UNSIGNED_INT,
       ui,
       {0.0711110905f, 0.49999997f, 1.0f, 3.04579753e-05f}},
      {GL_DEPTH_COMPONENT24,
       GL_UNSIGNED_BYTE,
       ub,
       {0.0705882385f, 0.501960814f, 1.0f, 0.00392156886f}},
      {GL_DEPTH_COMPONENT32,
       GL_UNSIGNED_SHORT,
       us,
       {0.0711070448f, 0.500007629f, 1.0f, 1.52590219e-05f}},
      {GL_DEPTH_COMPONENT32, GL_UNSIGNED_INT, ui, {0.0711111128f, 0.5f, 1.0f, 3.05173453e-05f}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << std::hex << c.format << " " << c.type);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(c.format), 4, 1, 0, GL_DEPTH_COMPONENT, c.type, c.data);
    GLfloat back[4] = {};
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
    for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(back[i], c.expected[i]) << i;
  }
}

// ---- GL_GENERATE_MIPMAP -------------------------------------------------------------------

TEST_F(TexImageTest, GeneratedMipmapsMatchMesasBoxFilterRounding) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  // 2x2 -> 1x1 as Mesa's llvmpipe computes it (measured): pairs averaged as (a + b + 1) / 2,
  // along x, then y.
  const int cases[][5] = {{0, 1, 0, 0, 1},          {1, 1, 0, 0, 1},       {3, 0, 0, 0, 1},
                          {255, 0, 0, 0, 64},       {255, 255, 0, 0, 128}, {1, 2, 3, 4, 3},
                          {5, 5, 5, 6, 6},          {10, 11, 12, 13, 12},  {7, 0, 0, 0, 2},
                          {254, 255, 255, 255, 255}};
  for (const auto& c : cases) {
    GLubyte t[16];
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) t[i * 4 + k] = GLubyte(c[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    EXPECT_EQ(rgba_bytes(1, 1)[0], c[4]) << c[0] << " " << c[1] << " " << c[2] << " " << c[3];
  }
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 1), 1);
}

TEST_F(TexImageTest, NonPowerOfTwoMipmapsSampleBilinearlyLikeMesa) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const int v[5] = {0, 50, 100, 200, 255};
  GLubyte t[20];
  for (int i = 0; i < 5; ++i)
    for (int k = 0; k < 4; ++k) t[i * 4 + k] = GLubyte(v[i]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 5, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  const std::vector<GLubyte> l1 = rgba_bytes(1, 2);
  EXPECT_EQ(l1[0], 38);                 // Mesa
  EXPECT_EQ(l1[4], 214);                // Mesa
  EXPECT_EQ(rgba_bytes(2, 1)[0], 126);  // Mesa
  const GLubyte three[12] = {0, 0, 0, 0, 90, 90, 90, 90, 255, 255, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 3, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, three);
  EXPECT_EQ(rgba_bytes(1, 1)[0], 90);  // Mesa: the middle texel
}

TEST_F(TexImageTest, GeneratedMipmapsOfOtherFormatsAndTargets) {
  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
  GLubyte v[8 * 4];
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 16; ++i) v[z * 16 + i] = z ? 200 : 0;
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, v);
  EXPECT_EQ(rgba_bytes(1, 1, GL_TEXTURE_3D)[0], 100);  // Mesa: filtered along z too

  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const GLubyte white_corner[16] = {255, 255, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, white_corner);
  GLfloat f[4];
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_FLOAT, f);
  EXPECT_FLOAT_EQ(f[0], 8.0f / 31.0f);  // Mesa
  const GLushort l16[4] = {65535, 0, 0, 0};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE16, 2, 2, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT, l16);
  GLushort l[1];
  glGetTexImage(GL_TEXTURE_2D, 1, GL_LUMINANCE, GL_UNSIGNED_SHORT, l);
  EXPECT_EQ(l[0], 16384);  // Mesa
  const GLfloat depth[4] = {1, 0, 0, 0};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
               depth);
  glGetTexImage(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT, GL_FLOAT, f);
  EXPECT_FLOAT_EQ(f[0], 0.25f);  // Mesa
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(TexImageTest, MipmapsAreRegeneratedOnlyWhenTheBaseLevelChanges) {
  const GLubyte black[16] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 1), 0);  // GENERATE_MIPMAP was off
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  EXPECT_EQ(level_parameter(GL_TEXTURE_WIDTH, 1), 0);  // setting it generates nothing yet
  const GLubyte white[4] = {255, 255, 255, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  EXPECT_EQ(rgba_bytes(1, 1)[0], 64);
  // A change to another level does not regenerate.
  glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, black);
  EXPECT_EQ(rgba_bytes(1, 1)[0], 0);
  // The base level is the one GL_TEXTURE_BASE_LEVEL names.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
  EXPECT_EQ(rgba_bytes(1, 1)[0], 0);
}

}  // namespace
