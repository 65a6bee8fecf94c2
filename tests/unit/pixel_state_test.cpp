// glPixelTransfer, glPixelMap, glGetPixelMap, glPixelZoom, glPolygonStipple and their queries and
// errors, through the entry points. Expected values measured with Mesa 25 (OSMesa) where GL 1.5
// leaves room.
#include <vector>

#include "gl_test_context.hpp"

namespace {

TEST_F(GlTest, PixelTransferStateRoundTripsThroughGlGet) {
  glPixelTransferf(GL_RED_SCALE, 2.6f);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferi(GL_INDEX_SHIFT, -3);
  glPixelTransferf(GL_INDEX_OFFSET, 2.7f);  // integer state: truncated, as Mesa does
  glPixelTransferf(GL_MAP_COLOR, 0.4f);     // any non-zero value is true
  glPixelZoom(-2.0f, 3.0f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLfloat f = 0;
  glGetFloatv(GL_RED_SCALE, &f);
  EXPECT_FLOAT_EQ(f, 2.6f);
  GLint i = 0;
  glGetIntegerv(GL_RED_SCALE, &i);
  EXPECT_EQ(i, 3);  // rounded
  glGetFloatv(GL_GREEN_BIAS, &f);
  EXPECT_FLOAT_EQ(f, 0.25f);
  glGetFloatv(GL_DEPTH_SCALE, &f);
  EXPECT_FLOAT_EQ(f, 0.5f);
  glGetIntegerv(GL_INDEX_SHIFT, &i);
  EXPECT_EQ(i, -3);
  glGetIntegerv(GL_INDEX_OFFSET, &i);
  EXPECT_EQ(i, 2);
  GLboolean b = 0;
  glGetBooleanv(GL_MAP_COLOR, &b);
  EXPECT_EQ(b, 1);
  glGetBooleanv(GL_MAP_STENCIL, &b);
  EXPECT_EQ(b, 0);
  glGetFloatv(GL_ZOOM_X, &f);
  EXPECT_FLOAT_EQ(f, -2.0f);
  glGetFloatv(GL_ZOOM_Y, &f);
  EXPECT_FLOAT_EQ(f, 3.0f);
  EXPECT_FLOAT_EQ(ctx_.pixel_transfer.scale.r, 2.6f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, PixelTransferRejectsUnknownAndImagingNames) {
  glPixelTransferf(GL_POST_CONVOLUTION_RED_SCALE, 2.0f);  // no imaging subset (nor in Mesa)
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glPixelTransferi(0x1234, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
}

TEST_F(GlTest, PixelMapsStoreAndConvertLikeMesa) {
  const GLfloat color[4] = {-0.5f, 0.25f, 1.5f, 1.0f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 3, color);  // colour maps need no power of two
  const GLfloat index[4] = {-0.5f, 0.25f, 1.5f, 2.6f};
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 4, index);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 4, index);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &size);
  EXPECT_EQ(size, 3);
  glGetIntegerv(GL_PIXEL_MAP_A_TO_A_SIZE, &size);
  EXPECT_EQ(size, 1);
  GLfloat f[4] = {};
  glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, f);
  EXPECT_FLOAT_EQ(f[0], 0.0f);  // colour maps are clamped to [0,1]
  EXPECT_FLOAT_EQ(f[1], 0.25f);
  EXPECT_FLOAT_EQ(f[2], 1.0f);
  glGetPixelMapfv(GL_PIXEL_MAP_S_TO_S, f);  // S_TO_S rounds (Mesa: -1, 0, 2, 3)
  EXPECT_EQ(std::vector<float>(f, f + 4), (std::vector<float>{-1, 0, 2, 3}));
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, f);  // I_TO_I keeps its values
  EXPECT_FLOAT_EQ(f[3], 2.6f);
  GLuint ui[3] = {};
  glGetPixelMapuiv(GL_PIXEL_MAP_R_TO_R, ui);  // Mesa: 0, 1073741823, 4294967295
  EXPECT_EQ(ui[0], 0u);
  EXPECT_EQ(ui[1], 1073741823u);
  EXPECT_EQ(ui[2], 4294967295u);
  GLushort us[4] = {};
  glGetPixelMapusv(GL_PIXEL_MAP_R_TO_R, us);  // Mesa: 0, 16384, 65535
  EXPECT_EQ(us[1], 16384);
  EXPECT_EQ(us[2], 65535);
  glGetPixelMapusv(GL_PIXEL_MAP_I_TO_I, us);  // Mesa: 0, 0, 1, 2
  EXPECT_EQ(std::vector<int>(us, us + 4), (std::vector<int>{0, 0, 1, 2}));
}

TEST_F(GlTest, PixelMapIntegerFormsConvertColoursAndKeepIndices) {
  const GLuint ui[4] = {0, 1, 2147483648u, 4294967295u};
  glPixelMapuiv(GL_PIXEL_MAP_G_TO_G, 4, ui);
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 4, ui);
  GLfloat f[4];
  glGetPixelMapfv(GL_PIXEL_MAP_G_TO_G, f);
  EXPECT_FLOAT_EQ(f[2], 0.5f);
  EXPECT_FLOAT_EQ(f[3], 1.0f);
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, f);
  EXPECT_FLOAT_EQ(f[1], 1.0f);
  EXPECT_FLOAT_EQ(f[3], 4294967295.0f);
  const GLushort us[2] = {32768, 65535};
  glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 2, us);
  glGetPixelMapfv(GL_PIXEL_MAP_B_TO_B, f);
  EXPECT_FLOAT_EQ(f[0], 32768.0f / 65535.0f);
  EXPECT_FLOAT_EQ(f[1], 1.0f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, PixelMapErrors) {
  const GLfloat v[300] = {};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, v);  // index maps need a power of two
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 6, v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 3, v);  // GL 1.5 3.6.3 (Mesa forgets this one)
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, v);  // > GL_MAX_PIXEL_MAP_TABLE
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glPixelMapfv(GL_PIXEL_MAP_I_TO_I_SIZE, 1, v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  GLfloat out[1];
  glGetPixelMapfv(0x1234, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, nullptr);  // nothing to read: no change, no crash
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLint max = 0;
  glGetIntegerv(GL_MAX_PIXEL_MAP_TABLE, &max);
  EXPECT_EQ(max, 256);
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &size);
  EXPECT_EQ(size, 1);  // every rejected call left the map alone
}

TEST_F(GlTest, PolygonStippleUnpacksWithTheUnpackModes) {
  GLubyte pattern[32 * 4];
  for (int r = 0; r < 32; ++r) {
    pattern[r * 4 + 0] = GLubyte(r);
    pattern[r * 4 + 1] = 0x80;
    pattern[r * 4 + 2] = 0x00;
    pattern[r * 4 + 3] = 0x01;
  }
  glPolygonStipple(pattern);
  // Row r, bit 31 - c is column c: byte 0 holds columns 0..7 most significant first.
  EXPECT_EQ(ctx_.raster.primitive.stipple_pattern[5], (5u << 24) | 0x00800001u);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPolygonStipple(pattern);
  // LSB first: byte 0x01 (columns 24..31) puts its bit at column 24; 0x80 at column 15.
  EXPECT_EQ(ctx_.raster.primitive.stipple_pattern[0], (1u << (31 - 15)) | (1u << (31 - 24)));
  GLubyte back[32 * 4] = {};
  glGetPolygonStipple(back);  // packed with the pack modes (MSB first)
  EXPECT_EQ(back[1], 0x01);
  EXPECT_EQ(back[3], 0x80);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
  glGetPolygonStipple(back);
  EXPECT_EQ(back[1], 0x80);
  EXPECT_EQ(back[3], 0x01);
  glPolygonStipple(nullptr);
  glGetPolygonStipple(nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, PolygonStippleHonoursSkipsAndRowLength) {
  GLubyte image[40 * 8] = {};
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 64);  // 8 bytes per row
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 8);  // starts at byte 1
  image[2 * 8 + 1] = 0xC0;                  // first stipple row, columns 0 and 1
  glPolygonStipple(image);
  EXPECT_EQ(ctx_.raster.primitive.stipple_pattern[0], 0xC0000000u);
  EXPECT_EQ(ctx_.raster.primitive.stipple_pattern[1], 0u);
}

TEST_F(GlTest, ThreeDimensionalPixelStoreModesAreQueryable) {
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 7);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 2);
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 5);
  glPixelStorei(GL_PACK_SKIP_IMAGES, 1);
  GLint v = 0;
  glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, &v);
  EXPECT_EQ(v, 7);
  glGetIntegerv(GL_UNPACK_SKIP_IMAGES, &v);
  EXPECT_EQ(v, 2);
  glGetIntegerv(GL_PACK_IMAGE_HEIGHT, &v);
  EXPECT_EQ(v, 5);
  glGetIntegerv(GL_PACK_SKIP_IMAGES, &v);
  EXPECT_EQ(v, 1);
}

TEST_F(GlTest, ReadPixelsValidatesBeforeReading) {
  GLubyte out[4];
  glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glReadPixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BITMAP, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glReadPixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, out);  // RGBA contexts only
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_BITMAP, out);  // valid, nothing bound to read
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

}  // namespace
