// Unpacking client images (GL 1.5 3.6.4): layout from the unpack modes, every format and type,
// byte swapping, bitmaps. Expected values are computed by hand from the spec's tables (and Mesa's
// rule for signed types, measured with OSMesa: max(c / (2^(b-1) - 1), -1)).
#include "gl_shim/pixels/pixel_unpack.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_layout.hpp"

namespace glpt {
namespace {

PixelStoreModes modes_with_alignment(int alignment) {
  PixelStoreModes m;
  m.alignment = alignment;
  return m;
}

std::vector<glm::vec4> unpack(const PixelStoreModes& m, int w, int h, GLenum format, GLenum type,
                              const void* data, bool three_d = false, int d = 1) {
  return unpack_color_raw(UnpackSource{m, ImageShape{w, h, d, format, type}, three_d, data});
}

void expect_color(const glm::vec4& got, float r, float g, float b, float a) {
  EXPECT_FLOAT_EQ(got.r, r);
  EXPECT_FLOAT_EQ(got.g, g);
  EXPECT_FLOAT_EQ(got.b, b);
  EXPECT_FLOAT_EQ(got.a, a);
}

TEST(PixelFormats, FormatTypeErrorsFollowGlAndMesa) {
  EXPECT_EQ(check_format_and_type(GL_RGBA, GL_UNSIGNED_BYTE), GLenum{GL_NO_ERROR});
  EXPECT_EQ(check_format_and_type(GL_ABGR_EXT, GL_UNSIGNED_SHORT_4_4_4_4), GLenum{GL_NO_ERROR});
  EXPECT_EQ(check_format_and_type(GL_COLOR_INDEX, GL_BITMAP), GLenum{GL_NO_ERROR});
  EXPECT_EQ(check_format_and_type(GL_STENCIL_INDEX, GL_BITMAP), GLenum{GL_NO_ERROR});
  EXPECT_EQ(check_format_and_type(GL_RGBA, GL_BITMAP), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(check_format_and_type(0x1234, GL_UNSIGNED_BYTE), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(check_format_and_type(GL_RGB, 0x1234), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(check_format_and_type(GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(check_format_and_type(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(check_format_and_type(GL_BGR, GL_UNSIGNED_BYTE_3_3_2), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(check_format_and_type(GL_LUMINANCE, GL_UNSIGNED_BYTE_3_3_2),
            GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(check_format_and_type(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8),
            GLenum{GL_INVALID_OPERATION});
  // Formats of later GL versions (GL_RG 0x8227, GL_RGBA_INTEGER 0x8D99): glpt does not take
  // them, but a packed type that does not fit is GL_INVALID_OPERATION first, as in OSMesa
  // (piglit draw-pixels); a format no GL knows stays GL_INVALID_ENUM.
  EXPECT_EQ(check_format_and_type(0x8227, GL_UNSIGNED_BYTE_3_3_2), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(check_format_and_type(0x8D99, GL_UNSIGNED_SHORT_4_4_4_4), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(check_format_and_type(0x8227, GL_UNSIGNED_BYTE), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(check_format_and_type(0x1234, GL_UNSIGNED_BYTE_3_3_2), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(check_format_and_type(0x8227, GL_BITMAP), GLenum{GL_INVALID_ENUM});
}

TEST(PixelLayout, RowsArePaddedToTheAlignment) {
  // RGB ubyte, 3 pixels: 9 bytes per row, padded to 12 with alignment 4, 16 with 8, 9 with 1.
  const ImageShape shape{3, 2, 1, GL_RGB, GL_UNSIGNED_BYTE};
  EXPECT_EQ(ClientImageLayout(modes_with_alignment(4), shape, false).row_stride(), 12u);
  EXPECT_EQ(ClientImageLayout(modes_with_alignment(8), shape, false).row_stride(), 16u);
  EXPECT_EQ(ClientImageLayout(modes_with_alignment(1), shape, false).row_stride(), 9u);
  EXPECT_EQ(ClientImageLayout(modes_with_alignment(4), shape, false).end_offset(), 12u + 9u);
  // Elements at least as large as the alignment are never padded (s >= a in GL 1.5 3.6.4).
  const ImageShape floats{3, 2, 1, GL_RGB, GL_FLOAT};
  EXPECT_EQ(ClientImageLayout(modes_with_alignment(2), floats, false).row_stride(), 36u);
  EXPECT_EQ(ClientImageLayout(modes_with_alignment(8), floats, false).row_stride(), 40u);
}

TEST(PixelLayout, RowLengthAndSkipsMoveTheFirstGroup) {
  PixelStoreModes m = modes_with_alignment(1);
  m.row_length = 10;
  m.skip_pixels = 2;
  m.skip_rows = 3;
  const ClientImageLayout l(m, ImageShape{4, 2, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT}, false);
  // Groups of 4 bytes, rows of 10 groups = 40 bytes.
  EXPECT_EQ(l.row_stride(), 40u);
  EXPECT_EQ(l.group_offset(0, 0, 0), 3u * 40 + 2 * 4);
  EXPECT_EQ(l.group_offset(3, 1, 0), 4u * 40 + 5 * 4);
}

TEST(PixelLayout, ImageHeightAndSkipImagesApplyOnlyToThreeDimensionalImages) {
  PixelStoreModes m = modes_with_alignment(1);
  m.image_height = 5;
  m.skip_images = 2;
  const ImageShape shape{2, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE};
  const ClientImageLayout three_d(m, shape, true);
  EXPECT_EQ(three_d.group_offset(0, 0, 0), 2u * 5 * 8);
  EXPECT_EQ(three_d.group_offset(1, 2, 1), 3u * 5 * 8 + 2 * 8 + 4);
  const ClientImageLayout two_d(m, shape, false);
  EXPECT_EQ(two_d.group_offset(0, 0, 0), 0u);
}

TEST(PixelLayout, BitmapRowsAreWholeAlignedBytes) {
  PixelStoreModes m = modes_with_alignment(4);
  // 10 bits per row: 2 bytes, padded to 4.
  EXPECT_EQ(
      ClientImageLayout(m, ImageShape{10, 3, 1, GL_COLOR_INDEX, GL_BITMAP}, false).row_stride(),
      4u);
  m.alignment = 1;
  m.skip_pixels = 5;
  const ClientImageLayout l(m, ImageShape{10, 3, 1, GL_COLOR_INDEX, GL_BITMAP}, false);
  EXPECT_EQ(l.row_stride(), 2u);
  EXPECT_EQ(l.group_offset(3, 0, 0), 1u);  // bit 8: second byte
  EXPECT_EQ(l.bit_mask(3), 0x80u);
  EXPECT_EQ(l.bit_mask(0), 0x04u);  // bit 5, most significant first
  m.lsb_first = true;
  EXPECT_EQ(
      ClientImageLayout(m, ImageShape{10, 3, 1, GL_COLOR_INDEX, GL_BITMAP}, false).bit_mask(0),
      0x20u);
}

TEST(PixelUnpack, ComponentOrderOfEveryColourFormat) {
  const PixelStoreModes m = modes_with_alignment(1);
  const uint8_t four[4] = {51, 102, 153, 204};  // 0.2, 0.4, 0.6, 0.8
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, four)[0], 0.2f, 0.4f, 0.6f, 0.8f);
  expect_color(unpack(m, 1, 1, GL_BGRA, GL_UNSIGNED_BYTE, four)[0], 0.6f, 0.4f, 0.2f, 0.8f);
  expect_color(unpack(m, 1, 1, GL_ABGR_EXT, GL_UNSIGNED_BYTE, four)[0], 0.8f, 0.6f, 0.4f, 0.2f);
  expect_color(unpack(m, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, four)[0], 0.2f, 0.4f, 0.6f, 1.0f);
  expect_color(unpack(m, 1, 1, GL_BGR, GL_UNSIGNED_BYTE, four)[0], 0.6f, 0.4f, 0.2f, 1.0f);
  expect_color(unpack(m, 1, 1, GL_RED, GL_UNSIGNED_BYTE, four)[0], 0.2f, 0.0f, 0.0f, 1.0f);
  expect_color(unpack(m, 1, 1, GL_GREEN, GL_UNSIGNED_BYTE, four)[0], 0.0f, 0.2f, 0.0f, 1.0f);
  expect_color(unpack(m, 1, 1, GL_BLUE, GL_UNSIGNED_BYTE, four)[0], 0.0f, 0.0f, 0.2f, 1.0f);
  expect_color(unpack(m, 1, 1, GL_ALPHA, GL_UNSIGNED_BYTE, four)[0], 0.0f, 0.0f, 0.0f, 0.2f);
  // Luminance goes to R, G and B (GL 1.5 3.6.4 "Conversion to RGB").
  expect_color(unpack(m, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, four)[0], 0.2f, 0.2f, 0.2f, 1.0f);
  expect_color(unpack(m, 1, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, four)[0], 0.2f, 0.2f, 0.2f,
               0.4f);
}

TEST(PixelUnpack, EveryComponentTypeConvertsAsMesaDoes) {
  const PixelStoreModes m = modes_with_alignment(1);
  const int8_t bytes[4] = {-128, -127, 63, 127};
  const std::vector<glm::vec4> b = unpack(m, 4, 1, GL_RED, GL_BYTE, bytes);
  EXPECT_FLOAT_EQ(b[0].r, -1.0f);
  EXPECT_FLOAT_EQ(b[1].r, -1.0f);
  EXPECT_FLOAT_EQ(b[2].r, 63.0f / 127.0f);
  EXPECT_FLOAT_EQ(b[3].r, 1.0f);
  const uint16_t ushorts[2] = {0, 32768};
  EXPECT_FLOAT_EQ(unpack(m, 2, 1, GL_RED, GL_UNSIGNED_SHORT, ushorts)[1].r, 32768.0f / 65535.0f);
  const int16_t shorts[2] = {-32768, 16384};
  const std::vector<glm::vec4> s = unpack(m, 2, 1, GL_RED, GL_SHORT, shorts);
  EXPECT_FLOAT_EQ(s[0].r, -1.0f);
  EXPECT_FLOAT_EQ(s[1].r, 16384.0f / 32767.0f);
  const uint32_t uints[2] = {4294967295u, 2147483648u};
  const std::vector<glm::vec4> u = unpack(m, 2, 1, GL_RED, GL_UNSIGNED_INT, uints);
  EXPECT_FLOAT_EQ(u[0].r, 1.0f);
  EXPECT_FLOAT_EQ(u[1].r, 0.5f);
  const int32_t ints[2] = {-2147483647 - 1, 1073741824};
  const std::vector<glm::vec4> i = unpack(m, 2, 1, GL_RED, GL_INT, ints);
  EXPECT_FLOAT_EQ(i[0].r, -1.0f);
  EXPECT_FLOAT_EQ(i[1].r, 0.5f);
  const float floats[2] = {-3.5f, 7.25f};  // floats are taken as they are, unclamped
  const std::vector<glm::vec4> f = unpack(m, 2, 1, GL_RED, GL_FLOAT, floats);
  EXPECT_FLOAT_EQ(f[0].r, -3.5f);
  EXPECT_FLOAT_EQ(f[1].r, 7.25f);
}

TEST(PixelUnpack, EveryPackedTypeUnpacksItsFields) {
  const PixelStoreModes m = modes_with_alignment(1);
  // 0b111'010'01: R = 7/7, G = 2/7, B = 1/3.
  const uint8_t b332 = 0xE9;
  expect_color(unpack(m, 1, 1, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &b332)[0], 1.0f, 2.0f / 7, 1.0f / 3,
               1.0f);
  // 2_3_3_REV, same byte: R = bits 0-2 = 1/7, G = bits 3-5 = 5/7, B = bits 6-7 = 3/3.
  expect_color(unpack(m, 1, 1, GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, &b332)[0], 1.0f / 7, 5.0f / 7,
               1.0f, 1.0f);
  // 5_6_5: R = 31, G = 1, B = 2.
  const uint16_t s565 = uint16_t((31 << 11) | (1 << 5) | 2);
  expect_color(unpack(m, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &s565)[0], 1.0f, 1.0f / 63,
               2.0f / 31, 1.0f);
  expect_color(unpack(m, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, &s565)[0], 2.0f / 31, 1.0f / 63,
               1.0f, 1.0f);
  const uint16_t s4444 = 0x1234;
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, &s4444)[0], 1.0f / 15, 2.0f / 15,
               3.0f / 15, 4.0f / 15);
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, &s4444)[0], 4.0f / 15,
               3.0f / 15, 2.0f / 15, 1.0f / 15);
  // With BGRA the first field is blue (GL 1.5 table 3.13).
  expect_color(unpack(m, 1, 1, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, &s4444)[0], 3.0f / 15, 2.0f / 15,
               1.0f / 15, 4.0f / 15);
  expect_color(unpack(m, 1, 1, GL_ABGR_EXT, GL_UNSIGNED_SHORT_4_4_4_4, &s4444)[0], 4.0f / 15,
               3.0f / 15, 2.0f / 15, 1.0f / 15);
  // 5_5_5_1: R = 3, G = 4, B = 5, A = 1.
  const uint16_t s5551 = uint16_t((3 << 11) | (4 << 6) | (5 << 1) | 1);
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, &s5551)[0], 3.0f / 31, 4.0f / 31,
               5.0f / 31, 1.0f);
  // 1_5_5_5_REV: R = bits 0-4 = 3, G = 5-9 = 4, B = 10-14 = 5, A = bit 15 = 0.
  const uint16_t s1555 = uint16_t(3 | (4 << 5) | (5 << 10));
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_1_5_5_5_REV, &s1555)[0], 3.0f / 31,
               4.0f / 31, 5.0f / 31, 0.0f);
  const uint32_t i8888 = 0x336699CCu;
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, &i8888)[0], 0.2f, 0.4f, 0.6f,
               0.8f);
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, &i8888)[0], 0.8f, 0.6f, 0.4f,
               0.2f);
  // 10_10_10_2: R = 1023, G = 0, B = 511, A = 2.
  const uint32_t i1010102 = (1023u << 22) | (511u << 2) | 2u;
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, &i1010102)[0], 1.0f, 0.0f,
               511.0f / 1023, 2.0f / 3);
  // 2_10_10_10_REV: R = bits 0-9 = 7, G = 10-19 = 8, B = 20-29 = 9, A = 30-31 = 3.
  const uint32_t i2101010 = 7u | (8u << 10) | (9u << 20) | (3u << 30);
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, &i2101010)[0], 7.0f / 1023,
               8.0f / 1023, 9.0f / 1023, 1.0f);
}

TEST(PixelUnpack, SwapBytesReversesEachElement) {
  PixelStoreModes m = modes_with_alignment(1);
  m.swap_bytes = true;
  const uint8_t be_ushort[2] = {0x80, 0x00};  // 0x8000 big-endian
  EXPECT_FLOAT_EQ(unpack(m, 1, 1, GL_RED, GL_UNSIGNED_SHORT, be_ushort)[0].r, 32768.0f / 65535);
  const uint8_t be_uint[4] = {0x80, 0x00, 0x00, 0x00};
  EXPECT_FLOAT_EQ(unpack(m, 1, 1, GL_RED, GL_UNSIGNED_INT, be_uint)[0].r, 0.5f);
  // A packed group is one element: 0x1234 stored big-endian.
  const uint8_t be_4444[2] = {0x12, 0x34};
  expect_color(unpack(m, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, be_4444)[0], 1.0f / 15,
               2.0f / 15, 3.0f / 15, 4.0f / 15);
  // Bytes are not swapped.
  const uint8_t ub[2] = {51, 102};
  EXPECT_FLOAT_EQ(unpack(m, 2, 1, GL_RED, GL_UNSIGNED_BYTE, ub)[1].r, 0.4f);
}

TEST(PixelUnpack, AlignmentRowLengthAndSkipsSelectTheRightTexels) {
  // A 2x2 RGB image at (1, 1) inside a 4-wide client image with alignment 4: rows of 12 bytes.
  PixelStoreModes m = modes_with_alignment(4);
  m.row_length = 4;
  m.skip_pixels = 1;
  m.skip_rows = 1;
  std::vector<uint8_t> data(3 * 12, 0);
  const auto put = [&](int x, int y, uint8_t v) { data[size_t(y * 12 + x * 3)] = v; };
  put(1, 1, 10);
  put(2, 1, 20);
  put(1, 2, 30);
  put(2, 2, 40);
  const std::vector<glm::vec4> px = unpack(m, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, data.data());
  ASSERT_EQ(px.size(), 4u);
  EXPECT_FLOAT_EQ(px[0].r, 10.0f / 255);
  EXPECT_FLOAT_EQ(px[1].r, 20.0f / 255);
  EXPECT_FLOAT_EQ(px[2].r, 30.0f / 255);
  EXPECT_FLOAT_EQ(px[3].r, 40.0f / 255);
}

TEST(PixelUnpack, ThreeDimensionalImagesUseImageHeightAndSkipImages) {
  PixelStoreModes m = modes_with_alignment(1);
  m.image_height = 3;  // images of 3 rows, of which the image uses 1
  m.skip_images = 1;
  const uint8_t data[] = {0, 0, 0, 1, 0, 0, 2, 0, 0};  // one LUMINANCE byte per row
  const std::vector<glm::vec4> px = unpack(m, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, data, true, 2);
  ASSERT_EQ(px.size(), 2u);
  EXPECT_FLOAT_EQ(px[0].r, 1.0f / 255);  // image 1 (after the skipped one) starts at row 3
  EXPECT_FLOAT_EQ(px[1].r, 2.0f / 255);
}

TEST(PixelUnpack, BitmapsHonourLsbFirstAndSkipPixels) {
  PixelStoreModes m = modes_with_alignment(1);
  const uint8_t rows[2] = {0xA0, 0x01};  // row 0: 1010 0000, row 1: 0000 0001
  const std::vector<uint8_t> msb = unpack_bitmap(m, 8, 2, rows);
  const std::vector<uint8_t> expect_msb = {1, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  EXPECT_EQ(msb, expect_msb);
  m.lsb_first = true;
  const std::vector<uint8_t> lsb = unpack_bitmap(m, 8, 2, rows);
  const std::vector<uint8_t> expect_lsb = {0, 0, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_EQ(lsb, expect_lsb);
  m.lsb_first = false;
  m.skip_pixels = 2;  // starts at bit 2 of 0xA0 = 1010 0000
  const std::vector<uint8_t> skipped = unpack_bitmap(m, 3, 1, rows);
  EXPECT_EQ(skipped, (std::vector<uint8_t>{1, 0, 0}));
}

TEST(PixelUnpack, IndicesAreIntegersAsMesaExtractsThem) {
  const PixelStoreModes m = modes_with_alignment(1);
  const float f[3] = {2.9f, 0.0f, 65536.5f};
  const std::vector<uint32_t> fi =
      unpack_indices_raw(UnpackSource{m, ImageShape{3, 1, 1, GL_COLOR_INDEX, GL_FLOAT}, false, f});
  EXPECT_EQ(fi, (std::vector<uint32_t>{2, 0, 65536}));
  const int8_t b[2] = {-1, 5};
  const std::vector<uint32_t> bi =
      unpack_indices_raw(UnpackSource{m, ImageShape{2, 1, 1, GL_STENCIL_INDEX, GL_BYTE}, false, b});
  EXPECT_EQ(bi, (std::vector<uint32_t>{0xFFFFFFFFu, 5}));
}

TEST(PixelUnpack, DepthIntegersAreNormalized) {
  const PixelStoreModes m = modes_with_alignment(1);
  const uint16_t d[2] = {0, 65535};
  const std::vector<float> v = unpack_depth_raw(
      UnpackSource{m, ImageShape{2, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT}, false, d});
  EXPECT_FLOAT_EQ(v[0], 0.0f);
  EXPECT_FLOAT_EQ(v[1], 1.0f);
}

TEST(PixelUnpack, NullDataGivesDefaultsNotACrash) {
  const PixelStoreModes m = modes_with_alignment(4);
  const std::vector<glm::vec4> px = unpack(m, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  ASSERT_EQ(px.size(), 4u);
  expect_color(px[3], 0, 0, 0, 1);
}

}  // namespace
}  // namespace glpt
