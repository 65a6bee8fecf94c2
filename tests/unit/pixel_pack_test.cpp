// Packing values into client memory (GL 1.5 4.3.2) and the pixel transfer operations (3.6.5).
// Rounding is Mesa's (measured with OSMesa: nearest even of c * (2^b - 1) in float arithmetic,
// signed types c * (2^(b-1) - 1)); luminance is R + G + B for glReadPixels, R for glGetTexImage.
#include "gl_shim/pixels/pixel_pack.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/pixels/pixel_transfer.hpp"
#include "gl_shim/pixels/pixel_unpack.hpp"

namespace glpt {
namespace {

PixelStoreModes packed_tight() {
  PixelStoreModes m;
  m.alignment = 1;
  return m;
}

template <typename T, size_t N>
void pack(const PixelStoreModes& m, int w, int h, GLenum format, GLenum type,
          const std::vector<glm::vec4>& rgba, T (&out)[N],
          LuminanceFrom lum = LuminanceFrom::kSumRgb) {
  pack_color(PackTarget{m, ImageShape{w, h, 1, format, type}, false, out, nullptr}, rgba, lum);
}

TEST(PixelPack, UnsignedTypesRoundToNearestEven) {
  const PixelStoreModes m = packed_tight();
  // 0.5/255 -> 0 and 2.5/255 -> 2 (ties to even), 1.5/255 -> 2, 1 -> 255.
  const std::vector<glm::vec4> v = {{0.5f / 255, 1.5f / 255, 2.5f / 255, 1.0f}};
  uint8_t ub[4];
  pack(m, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, v, ub);
  EXPECT_EQ(ub[0], 0);
  EXPECT_EQ(ub[1], 2);
  EXPECT_EQ(ub[2], 2);
  EXPECT_EQ(ub[3], 255);
  uint16_t us[4];
  pack(m, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT, {{0.25f, 0.5f, 0.0f, 1.0f}}, us);
  EXPECT_EQ(us[0], 16384);  // 16383.75
  EXPECT_EQ(us[1], 32768);  // 32767.5 -> even
  EXPECT_EQ(us[3], 65535);
  uint32_t ui[4];
  pack(m, 1, 1, GL_RGBA, GL_UNSIGNED_INT, {{0.25f, 0.5f, 0.0f, 1.0f}}, ui);
  EXPECT_EQ(ui[0], 1073741824u);
  EXPECT_EQ(ui[1], 2147483648u);
  EXPECT_EQ(ui[3], 4294967295u);  // Mesa overflows to 0 here; glpt saturates
}

TEST(PixelPack, SignedTypesUseTheMagnitudeRange) {
  const PixelStoreModes m = packed_tight();
  int8_t b[4];
  pack(m, 1, 1, GL_RGBA, GL_BYTE, {{0.25f, 0.75f, 0.0f, 1.0f}}, b);
  EXPECT_EQ(b[0], 32);  // 31.75
  EXPECT_EQ(b[1], 95);  // 95.25
  EXPECT_EQ(b[3], 127);
  int16_t s[4];
  pack(m, 1, 1, GL_RGBA, GL_SHORT, {{0.25f, 0.75f, 0.0f, 1.0f}}, s);
  EXPECT_EQ(s[0], 8192);
  EXPECT_EQ(s[1], 24575);
  EXPECT_EQ(s[3], 32767);
  int32_t i[4];
  pack(m, 1, 1, GL_RGBA, GL_INT, {{0.25f, 0.5f, 0.0f, 1.0f}}, i);
  EXPECT_EQ(i[0], 536870912);
  EXPECT_EQ(i[1], 1073741824);
  EXPECT_EQ(i[3], 2147483647);  // Mesa overflows to INT_MIN here; glpt saturates
  float f[4];
  pack(m, 1, 1, GL_RGBA, GL_FLOAT, {{0.25f, 0.5f, 0.0f, 1.0f}}, f);
  EXPECT_FLOAT_EQ(f[0], 0.25f);
}

TEST(PixelPack, LuminanceIsTheSumForReadPixelsAndRedForGetTexImage) {
  const PixelStoreModes m = packed_tight();
  const std::vector<glm::vec4> c = {{100 / 255.0f, 50 / 255.0f, 30 / 255.0f, 200 / 255.0f}};
  uint8_t la[2];
  pack(m, 1, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, c, la, LuminanceFrom::kSumRgb);
  EXPECT_EQ(la[0], 180);  // Mesa: 100 + 50 + 30
  EXPECT_EQ(la[1], 200);
  pack(m, 1, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, c, la, LuminanceFrom::kRed);
  EXPECT_EQ(la[0], 100);
  // The sum saturates at 1 (Mesa: 200 + 150 + 30 -> 255, float 1.0).
  const std::vector<glm::vec4> bright = {{200 / 255.0f, 150 / 255.0f, 30 / 255.0f, 1.0f}};
  float lf[1];
  pack(m, 1, 1, GL_LUMINANCE, GL_FLOAT, bright, lf);
  EXPECT_FLOAT_EQ(lf[0], 1.0f);
}

TEST(PixelPack, FormatsPlaceComponentsInTheirOrder) {
  const PixelStoreModes m = packed_tight();
  const std::vector<glm::vec4> c = {{0.2f, 0.4f, 0.6f, 0.8f}};
  uint8_t out[4] = {9, 9, 9, 9};
  pack(m, 1, 1, GL_BGRA, GL_UNSIGNED_BYTE, c, out);
  EXPECT_EQ(std::vector<int>(out, out + 4), (std::vector<int>{153, 102, 51, 204}));
  pack(m, 1, 1, GL_ABGR_EXT, GL_UNSIGNED_BYTE, c, out);
  EXPECT_EQ(std::vector<int>(out, out + 4), (std::vector<int>{204, 153, 102, 51}));
  uint8_t one[4] = {9, 9, 9, 9};
  pack(m, 1, 1, GL_GREEN, GL_UNSIGNED_BYTE, c, one);
  EXPECT_EQ(one[0], 102);
  EXPECT_EQ(one[1], 9);  // nothing else written
}

TEST(PixelPack, PackedTypesRoundEachField) {
  const PixelStoreModes m = packed_tight();
  // R = 1 -> 31, G = 0.5 -> 31.5 -> 32 (even), B = 0.1 -> 3.1 -> 3.
  uint16_t s565[1];
  pack(m, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, {{1.0f, 0.5f, 0.1f, 1.0f}}, s565);
  EXPECT_EQ(s565[0], (31 << 11) | (32 << 5) | 3);
  uint16_t s1555[1];
  pack(m, 1, 1, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, {{1.0f, 0.0f, 0.5f, 1.0f}}, s1555);
  // BGRA: first field (bits 0-4) is B = 15.5 -> 16, second G = 0, third R = 31, A = 1.
  EXPECT_EQ(s1555[0], 16 | (0 << 5) | (31 << 10) | (1 << 15));
  uint32_t i2101010[1];
  pack(m, 1, 1, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, {{1.0f, 0.0f, 0.0f, 1.0f / 3}}, i2101010);
  EXPECT_EQ(i2101010[0], 1023u | (1u << 30));
  uint8_t b332[1];
  pack(m, 1, 1, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, {{1.0f, 0.0f, 1.0f, 1.0f}}, b332);
  EXPECT_EQ(b332[0], 0xE3);
}

TEST(PixelPack, SwapBytesAlignmentAndSkipsPlaceTheGroups) {
  PixelStoreModes m;
  m.alignment = 4;
  m.swap_bytes = true;
  m.skip_pixels = 1;
  m.skip_rows = 1;
  // 1 x 2 image of ushort luminance, rows of 2 groups -> 4 bytes (aligned), after one row.
  m.row_length = 2;
  uint8_t out[12];
  std::memset(out, 0xEE, sizeof out);
  pack(m, 1, 2, GL_LUMINANCE, GL_UNSIGNED_SHORT, {{1.0f, 0, 0, 1}, {0.5f, 0, 0, 1}}, out,
       LuminanceFrom::kRed);
  // Row y starts at (1 + y) * 4, pixel at +2; big-endian values.
  EXPECT_EQ(out[6], 0xFF);
  EXPECT_EQ(out[7], 0xFF);
  EXPECT_EQ(out[10], 0x80);  // 32768 (32767.5 -> even)
  EXPECT_EQ(out[11], 0x00);
  EXPECT_EQ(out[0], 0xEE);
  EXPECT_EQ(out[8], 0xEE);
}

TEST(PixelPack, UnwrittenGroupsAreLeftAlone) {
  const PixelStoreModes m = packed_tight();
  uint8_t out[2] = {7, 7};
  const uint8_t written[2] = {0, 1};
  pack_color(PackTarget{m, ImageShape{2, 1, 1, GL_RED, GL_UNSIGNED_BYTE}, false, out, written},
             {{1, 0, 0, 1}, {1, 0, 0, 1}}, LuminanceFrom::kSumRgb);
  EXPECT_EQ(out[0], 7);
  EXPECT_EQ(out[1], 255);
}

TEST(PixelPack, IndicesAreMaskedToTheType) {
  const PixelStoreModes m = packed_tight();
  const std::vector<uint32_t> v = {0x1FF, 0x1FF};
  uint8_t ub[2];
  pack_indices(PackTarget{m, ImageShape{2, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE}, false, ub},
               v);
  EXPECT_EQ(ub[0], 0xFF);
  int8_t b[2];
  pack_indices(PackTarget{m, ImageShape{2, 1, 1, GL_STENCIL_INDEX, GL_BYTE}, false, b}, v);
  EXPECT_EQ(b[0], 0x7F);
  float f[1];
  pack_indices(PackTarget{m, ImageShape{1, 1, 1, GL_STENCIL_INDEX, GL_FLOAT}, false, f}, {300});
  EXPECT_FLOAT_EQ(f[0], 300.0f);
}

TEST(PixelPack, BitmapsRoundTripWithLsbFirst) {
  PixelStoreModes m = packed_tight();
  m.lsb_first = true;
  const std::vector<uint8_t> bits = {1, 0, 0, 0, 0, 0, 0, 1, 1, 1};
  uint8_t out[4] = {0, 0, 0, 0};
  pack_bitmap(m, 10, 1, bits, out);
  EXPECT_EQ(out[0], 0x81);
  EXPECT_EQ(out[1], 0x03);
  EXPECT_EQ(unpack_bitmap(m, 10, 1, out), bits);
}

TEST(PixelPack, DepthTypes) {
  const PixelStoreModes m = packed_tight();
  uint16_t us[2];
  pack_depth(PackTarget{m, ImageShape{2, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT}, false, us},
             {0.5f, 1.0f});
  EXPECT_EQ(us[0], 32768);
  EXPECT_EQ(us[1], 65535);
  uint32_t ui[1];
  pack_depth(PackTarget{m, ImageShape{1, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT}, false, ui},
             {1.0f});
  EXPECT_EQ(ui[0], 4294967295u);
}

// ---- pixel transfer ------------------------------------------------------------------------

TEST(PixelTransfer, ScaleBiasThenClamp) {
  rec::PixelTransferState t;
  t.scale = glm::vec4(2.0f, 1.0f, 1.0f, 0.5f);
  t.bias = glm::vec4(0.0f, -0.5f, 0.25f, 0.0f);
  std::vector<glm::vec4> c = {{0.25f, 0.25f, 0.5f, 1.0f}, {0.75f, 1.0f, 1.0f, 0.0f}};
  transfer_rgba(t, c);
  EXPECT_FLOAT_EQ(c[0].r, 0.5f);
  EXPECT_FLOAT_EQ(c[0].g, 0.0f);  // -0.25 clamped
  EXPECT_FLOAT_EQ(c[0].b, 0.75f);
  EXPECT_FLOAT_EQ(c[0].a, 0.5f);
  EXPECT_FLOAT_EQ(c[1].r, 1.0f);  // 1.5 clamped
}

TEST(PixelTransfer, ColorMapsIndexByRoundedComponentTimesSizeMinusOne) {
  rec::PixelTransferState t;
  t.map_color = true;
  auto maps = std::make_shared<rec::PixelMaps>();
  maps->maps[GL_PIXEL_MAP_R_TO_R - GL_PIXEL_MAP_I_TO_I] = {0.0f, 0.2f, 1.0f};
  t.maps = maps;
  // Mesa: 63/255*2 = 0.49 -> 0; 64/255*2 = 0.502 -> 1; 0.25*2 = 0.5 -> 0 (even); 0.75 -> 2.
  std::vector<glm::vec4> c = {
      {63 / 255.0f, 0, 0, 1}, {64 / 255.0f, 0, 0, 1}, {0.25f, 0, 0, 1}, {0.75f, 0, 0, 1}};
  transfer_rgba(t, c);
  EXPECT_FLOAT_EQ(c[0].r, 0.0f);
  EXPECT_FLOAT_EQ(c[1].r, 0.2f);
  EXPECT_FLOAT_EQ(c[2].r, 0.0f);
  EXPECT_FLOAT_EQ(c[3].r, 1.0f);
  EXPECT_FLOAT_EQ(c[0].a, 0.0f);  // A_TO_A is still the initial single 0
}

TEST(PixelTransfer, IndicesShiftOffsetAndLookUpWithoutRgbaScale) {
  rec::PixelTransferState t;
  t.scale.r = 2.0f;  // not applied to colours that started as indices (Mesa)
  t.index_shift = 1;
  t.index_offset = 1;
  auto maps = std::make_shared<rec::PixelMaps>();
  maps->maps[GL_PIXEL_MAP_I_TO_R - GL_PIXEL_MAP_I_TO_I] = {0.25f, 0.75f, 0.5f, 1.0f};
  t.maps = maps;
  // (i << 1) + 1 masked with 3: 0 -> 1, 1 -> 3, 2 -> 5 & 3 = 1.
  const std::vector<glm::vec4> c = transfer_index_to_rgba(t, {0, 1, 2});
  EXPECT_FLOAT_EQ(c[0].r, 0.75f);
  EXPECT_FLOAT_EQ(c[1].r, 1.0f);
  EXPECT_FLOAT_EQ(c[2].r, 0.75f);
  EXPECT_FLOAT_EQ(c[0].g, 0.0f);
  t.index_shift = -1;
  t.index_offset = 0;
  EXPECT_EQ(shift_and_offset_index(t, 7), 3u);
}

TEST(PixelTransfer, StencilAndDepth) {
  rec::PixelTransferState t;
  t.index_offset = 2;
  t.map_stencil = true;
  auto maps = std::make_shared<rec::PixelMaps>();
  maps->maps[GL_PIXEL_MAP_S_TO_S - GL_PIXEL_MAP_I_TO_I] = {10, 11, 12, 13};
  t.maps = maps;
  std::vector<uint32_t> s = {0, 3};
  transfer_stencil(t, s);
  EXPECT_EQ(s, (std::vector<uint32_t>{12, 11}));  // (0+2)&3 = 2, (3+2)&3 = 1
  t.depth_scale = 0.5f;
  t.depth_bias = 0.75f;
  std::vector<float> d = {0.0f, 1.0f};
  transfer_depth(t, d);
  EXPECT_FLOAT_EQ(d[0], 0.75f);
  EXPECT_FLOAT_EQ(d[1], 1.0f);  // 1.25 clamped
}

}  // namespace
}  // namespace glpt
