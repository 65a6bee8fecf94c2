#include "gl_shim/textures/s3tc.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "gl/gl_enums.h"

namespace glpt::s3tc {
namespace {

using Rgba = std::array<uint8_t, 4>;

bool dxt1(GLenum f) {
  return f == GL_COMPRESSED_RGB_S3TC_DXT1_EXT || f == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
}

uint32_t blocks_across(uint32_t n) { return (n + 3) / 4; }

// 5- and 6-bit channels widened by replicating their high bits (both of Mesa's decoders).
Rgba expand_565(uint32_t c) {
  const uint32_t r = c >> 11, g = (c >> 5) & 63, b = c & 31;
  return {uint8_t(r << 3 | r >> 2), uint8_t(g << 2 | g >> 4), uint8_t(b << 3 | b >> 2), 255};
}

// gallivm's lp_build_lerp23: 8-bit weights 85/256 and 170/256 of the difference, rounded down
// (the CPU decoder divides by 3 instead, which differs by one on many colours).
uint8_t third(int v0, int v1, int weight) { return uint8_t(v0 + ((weight * (v1 - v0)) >> 8)); }

// The four colours of a colour block. DXT1 blocks with c0 <= c1 have three colours and
// transparent black; DXT3 and DXT5 always use four (as both of Mesa's decoders do).
std::array<Rgba, 4> palette(const uint8_t* block, bool three_colour_mode_allowed, bool rgba_dxt1) {
  const uint32_t c0 = uint32_t(block[0] | block[1] << 8), c1 = uint32_t(block[2] | block[3] << 8);
  std::array<Rgba, 4> p{expand_565(c0), expand_565(c1), Rgba{}, Rgba{}};
  if (!three_colour_mode_allowed || c0 > c1) {
    for (int k = 0; k < 3; ++k) {
      p[2][k] = third(p[0][k], p[1][k], 85);
      p[3][k] = third(p[0][k], p[1][k], 170);
    }
    p[2][3] = p[3][3] = 255;
  } else {
    // gallivm averages with pavgb, which rounds halves up (its scalar path would round down,
    // but llvmpipe fetches four texels at a time).
    for (int k = 0; k < 3; ++k) p[2][k] = uint8_t((p[0][k] + p[1][k] + 1) >> 1);
    p[2][3] = 255;
    p[3] = {0, 0, 0, uint8_t(rgba_dxt1 ? 0 : 255)};
  }
  return p;
}

// gallivm's lp_build_lerpdxta: weights 255 * 64 / 7 (or / 5) per step, scaled down by 64, then
// applied to the difference in 8.8 fixed point, rounded down.
uint8_t dxt5_alpha(int a0, int a1, uint32_t code) {
  if (code == 0) return uint8_t(a0);
  if (code == 1) return uint8_t(a1);
  if (a0 > a1) {
    const int weight = ((255 * 64 / 7) * int(code - 1)) >> 6;
    return uint8_t(a0 + (((a1 - a0) * weight) >> 8));
  }
  if (code == 6) return 0;
  if (code == 7) return 255;
  const int weight = ((255 * 64 / 5) * int(code - 1)) >> 6;
  return uint8_t(a0 + (((a1 - a0) * weight) >> 8));
}

uint64_t little_endian(const uint8_t* p, int bytes) {
  uint64_t v = 0;
  for (int k = 0; k < bytes; ++k) v |= uint64_t(p[k]) << (8 * k);
  return v;
}

// Texel (i, j) of a block (i across, j up).
void decode_block(GLenum f, const uint8_t* block, Rgba out[16]) {
  const bool one = dxt1(f);
  const uint8_t* colour = one ? block : block + 8;
  const std::array<Rgba, 4> p = palette(colour, one, f == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT);
  const uint32_t indices = uint32_t(little_endian(colour + 4, 4));
  for (int t = 0; t < 16; ++t) out[t] = p[(indices >> (2 * t)) & 3];
  if (f == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT) {
    for (int t = 0; t < 16; ++t) {
      const uint32_t nibble = (block[t / 2] >> (4 * (t & 1))) & 15;
      out[t][3] = uint8_t(nibble | nibble << 4);
    }
  } else if (f == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT) {
    const uint64_t codes = little_endian(block + 2, 6);
    for (int t = 0; t < 16; ++t)
      out[t][3] = dxt5_alpha(block[0], block[1], uint32_t(codes >> (3 * t)) & 7);
  }
}

// --- encoder -------------------------------------------------------------------------------
//
// Mesa compresses with libtxc_dxtn's encoder (texcompress_s3tc_tmp.h). glpt follows its
// arithmetic step by step so that the blocks come out byte for byte the same (checked against
// OSMesa's glGetCompressedTexImage on random and structured images, docs/extensions.md),
// including its quirks, which are marked where they occur. Texels are indexed [row][column].

using Block = std::array<std::array<Rgba, 4>, 4>;

constexpr int kRedWeight = 4, kGreenWeight = 16, kBlueWeight = 1;  // luminance-like weights
constexpr int kAlphaCut = 127;  // DXT1 RGBA: texels at or below this alpha become transparent

// A colour of 8-bit channels as the 5-6-5 word it would be stored as (low bits dropped).
uint32_t packed(const uint8_t* c) {
  return uint32_t((c[0] & 0xf8) << 8 | (c[1] & 0xfc) << 3 | c[2] >> 3);
}

uint32_t weighted_error(const Rgba& p, const uint8_t* c, int* diff = nullptr) {
  const int dr = int(p[0]) - c[0], dg = int(p[1]) - c[1], db = int(p[2]) - c[2];
  if (diff != nullptr) diff[0] = dr, diff[1] = dg, diff[2] = db;
  return uint32_t(dr * dr * kRedWeight + dg * dg * kGreenWeight + db * db * kBlueWeight);
}

// Refines the two base colours: each moves by the mean signed error of the texels nearest to
// the palette entries it contributes to (weights 3, 2, 1 by the entry's share of it).
void refine_base_colours(const Block& src, int nx, int ny, uint8_t best[2][3]) {
  uint8_t t[2][3];
  const bool keep = packed(best[0]) < packed(best[1]);
  for (int k = 0; k < 3; ++k) t[0][k] = best[keep ? 0 : 1][k], t[1][k] = best[keep ? 1 : 0][k];
  uint8_t cv[4][3];
  for (int k = 0; k < 3; ++k) {
    cv[0][k] = t[0][k], cv[1][k] = t[1][k];
    cv[2][k] = uint8_t((t[0][k] * 2 + t[1][k]) / 3);
    cv[3][k] = uint8_t((t[0][k] + t[1][k] * 2) / 3);
  }
  int error_sum[2][3] = {}, weight_sum[2] = {};
  // Shares of palette entries 0..3 in base colours 0 and 1.
  static constexpr int kShare[4][2] = {{3, 0}, {0, 3}, {2, 1}, {1, 2}};
  int best_diff[3] = {};
  int enc = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      uint32_t best_error = 0xffffffffu;
      for (int c = 0; c < 4; ++c) {
        int diff[3];
        const uint32_t e = weighted_error(src[j][i], cv[c], diff);
        if (e < best_error) best_error = e, enc = c, std::copy(diff, diff + 3, best_diff);
      }
      for (int b = 0; b < 2; ++b) {
        if (kShare[enc][b] == 0) continue;
        for (int k = 0; k < 3; ++k) error_sum[b][k] += kShare[enc][b] * best_diff[k];
        weight_sum[b] += kShare[enc][b];
      }
    }
  }
  for (int b = 0; b < 2; ++b) {
    const int n = weight_sum[b] == 0 ? 1 : weight_sum[b];
    for (int k = 0; k < 3; ++k)
      t[b][k] = uint8_t(std::clamp(t[b][k] + error_sum[b][k] / n, 0, 255));
  }
  // Colours so close that they could pack to the same word are pushed apart.
  if (std::abs(t[0][0] - t[1][0]) < 8 && std::abs(t[0][1] - t[1][1]) < 4 &&
      std::abs(t[0][2] - t[1][2]) < 8) {
    const int dr = std::abs(t[0][0] - t[1][0]), dg = 2 * std::abs(t[0][1] - t[1][1]),
              db = std::abs(t[0][2] - t[1][2]);
    const int dmax = std::max({dr, dg, db});
    if (dmax > 0) {
      const int factor = dmax > 4 ? 2 : dmax > 2 ? 3 : 4;
      const int hi = t[1][1] >= t[0][1] ? 1 : 0, lo = 1 - hi;
      const auto push = [&](uint8_t& v, int by) { v = uint8_t(v + by <= 255 ? v + by : 255); };
      push(t[hi][1], factor * dg);
      // libtxc_dxtn compares the red of one colour with the green of the other here.
      push(t[hi][0] - t[lo][1] > 0 ? t[hi][0] : t[lo][0], factor * dr);
      push(t[hi][2] - t[lo][2] > 0 ? t[hi][2] : t[lo][2], factor * db);
    }
  }
  // libtxc_dxtn's final order test shifts the whole second word right by 3, not its blue only.
  const uint32_t second = uint32_t((t[1][0] & 0xf8) << 8 | (t[1][1] & 0xfc) << 3 | t[1][2]) >> 3;
  const bool in_order = packed(t[0]) < second;
  for (int k = 0; k < 3; ++k)
    best[0][k] = t[in_order ? 0 : 1][k], best[1][k] = t[in_order ? 1 : 0][k];
}

// Chooses the indices for the (quantized) base colours in 4-colour mode and, for DXT1, in
// 3-colour mode, and writes whichever has the smaller error (3-colour mode always when a DXT1
// RGBA block has transparent texels).
void store_colour_block(const Block& src, int nx, int ny, GLenum f, bool has_alpha,
                        uint8_t best[2][3], uint8_t* out) {
  for (int b = 0; b < 2; ++b) best[b][0] &= 0xf8, best[b][1] &= 0xfc, best[b][2] &= 0xf8;
  uint32_t c0 = uint32_t(best[0][0] << 8 | best[0][1] << 3 | best[0][2] >> 3);
  uint32_t c1 = uint32_t(best[1][0] << 8 | best[1][1] << 3 | best[1][2] >> 3);
  int first = 0;
  if (c0 < c1) std::swap(c0, c1), first = 1;
  const uint8_t* b0 = best[first];
  const uint8_t* b1 = best[1 - first];
  uint8_t cv[4][3];
  for (int k = 0; k < 3; ++k) {
    cv[0][k] = b0[k], cv[1][k] = b1[k];
    cv[2][k] = uint8_t((b0[k] * 2 + b1[k]) / 3);
    cv[3][k] = uint8_t((b0[k] + b1[k] * 2) / 3);
  }
  uint32_t error4 = 0, bits4 = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      uint32_t best_error = 0xffffffffu, enc = 0;
      for (uint32_t c = 0; c < 4; ++c) {
        const uint32_t e = weighted_error(src[j][i], cv[c]);
        if (e < best_error) best_error = e, enc = c;
      }
      error4 += best_error;
      bits4 |= enc << (2 * (j * 4 + i));
    }
  }
  uint32_t error3 = 0xffffffffu, bits3 = 0;
  if (dxt1(f)) {
    for (int k = 0; k < 3; ++k) cv[2][k] = uint8_t((b0[k] + b1[k]) / 2);
    error3 = 0;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        uint32_t best_error = 0xffffffffu, enc = 0;
        if (f == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT && src[j][i][3] <= kAlphaCut) {
          enc = 3, best_error = 0;
        } else {
          for (uint32_t c = 0; c < 3; ++c) {
            const uint32_t e = weighted_error(src[j][i], cv[c]);
            // The base colours trade places in 3-colour mode.
            if (e < best_error) best_error = e, enc = c > 1 ? c : c ^ 1;
          }
        }
        error3 += best_error;
        bits3 |= enc << (2 * (j * 4 + i));
      }
    }
  }
  const bool three = error4 > error3 || has_alpha;
  const uint32_t w0 = three ? c1 : c0, w1 = three ? c0 : c1, bits = three ? bits3 : bits4;
  out[0] = uint8_t(w0), out[1] = uint8_t(w0 >> 8), out[2] = uint8_t(w1), out[3] = uint8_t(w1 >> 8);
  for (int k = 0; k < 4; ++k) out[4 + k] = uint8_t(bits >> (8 * k));
}

// libtxc_dxtn's encodedxtcolorblockfaster: the base colours start as the texels of the least and
// greatest weighted length (transparent DXT1 RGBA texels left out), then are refined.
void encode_colour_block(const Block& src, int nx, int ny, GLenum f, uint8_t* out) {
  const auto length = [](const Rgba& p) {
    return uint32_t(p[0] * p[0] * kRedWeight + p[1] * p[1] * kGreenWeight +
                    p[2] * p[2] * kBlueWeight);
  };
  uint32_t low = length(src[0][0]), high = low;
  const Rgba* lo = &src[0][0];
  const Rgba* hi = &src[0][0];
  bool has_alpha = false;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (f == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT && src[j][i][3] <= kAlphaCut) {
        has_alpha = true;
        continue;
      }
      const uint32_t l = length(src[j][i]);
      if (l > high) {
        high = l, hi = &src[j][i];
      } else if (l < low) {
        low = l, lo = &src[j][i];
      }
    }
  }
  uint8_t best[2][3] = {{(*lo)[0], (*lo)[1], (*lo)[2]}, {(*hi)[0], (*hi)[1], (*hi)[2]}};
  refine_base_colours(src, nx, ny, best);
  store_colour_block(src, nx, ny, f, has_alpha, best, out);
}

// A DXT5 alpha block: libtxc_dxtn tries the 8-alpha mode between the extremes (0 and 255
// included), the 6-alpha mode between the extremes of the other values, and a 6-alpha mode with
// adjusted end points, and keeps the one of least squared error.
void encode_dxt5_alpha(const Block& src, int nx, int ny, uint8_t* out) {
  int base[2] = {255, 0};  // least and greatest alpha other than 0 and 255
  bool has_min = false, has_max = false;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = src[j][i][3];
      if (a == 0) {
        has_min = true;
      } else if (a == 255) {
        has_max = true;
      } else {
        base[1] = std::max(base[1], a);
        base[0] = std::min(base[0], a);
      }
    }
  }
  std::memset(out, 0, 8);
  if (base[0] > base[1] && !(has_min && has_max)) {
    out[0] = src[0][0][3];  // one value: every code 0 (libtxc_dxtn leaves the second byte)
    return;
  }
  const auto write = [&](int a0, int a1, const uint8_t codes[16]) {
    out[0] = uint8_t(a0), out[1] = uint8_t(a1);
    uint64_t bits = 0;
    for (int t = 0; t < 16; ++t) bits |= uint64_t(codes[t] & 7) << (3 * t);
    for (int k = 0; k < 6; ++k) out[2 + k] = uint8_t(bits >> (8 * k));
  };
  uint8_t enc1[16] = {}, enc2[16] = {}, enc3[16] = {};
  uint32_t error1 = 0, error2 = 0xffffffffu, error3 = 0xffffffffu;
  const auto sq = [](int d) { return uint32_t(int16_t(d) * int16_t(d)); };
  // 8-alpha mode between use[0] (least) and use[1] (greatest).
  const int use[2] = {has_min ? 0 : base[0], has_max ? 255 : base[1]};
  uint8_t cut[7];
  for (int k = 0; k < 7; ++k)
    cut[k] = uint8_t((use[0] * (2 * k + 1) + use[1] * (14 - (2 * k + 1))) / 14);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = src[j][i][3];
      int k = 0;
      while (k < 7 && a <= cut[k]) ++k;
      // Interval k of the cuts: code 0 (greatest), 2..7 (interpolated), 1 (least).
      static constexpr uint8_t kCode[8] = {0, 2, 3, 4, 5, 6, 7, 1};
      const int value = k == 0 ? use[1] : k == 7 ? use[0] : (use[1] * (7 - k) + use[0] * k) / 7;
      enc1[4 * j + i] = kCode[k];
      error1 += sq(a - value);
    }
  }
  // 6-alpha mode between lo and hi; 0 and 255 exact. `at_ends`: also snap values below lo / 2
  // and above (255 + hi) / 2 to them.
  const auto six_alpha = [&](int lo, int hi, bool at_ends, uint8_t codes[16]) {
    int cuts[5];
    for (int k = 0; k < 5; ++k)
      cuts[k] = uint8_t((lo * (10 - (2 * k + 1)) + hi * (2 * k + 1)) / 10);
    uint32_t error = 0;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const int a = src[j][i][3];
        int code, d;
        if (at_ends ? a <= lo / 2 : a == 0) {
          code = 6, d = a;
        } else if (at_ends ? a > (255 + hi) / 2 : a == 255) {
          code = 7, d = 255 - a;
        } else {
          int k = 0;
          while (k < 5 && a > cuts[k]) ++k;
          // Interval k: code 0 (lo), 2..5 (interpolated), 1 (hi).
          static constexpr int kCode[6] = {0, 2, 3, 4, 5, 1};
          code = kCode[k];
          d = a - (k == 0 ? lo : k == 5 ? hi : (lo * (5 - k) + hi * k) / 5);
        }
        if (!at_ends && (a == 0 || a == 255)) d = 0;
        codes[4 * j + i] = uint8_t(code);
        error += sq(d);
      }
    }
    return error;
  };
  int test[2] = {0, 0};
  if (error1 >= 32) {
    error2 = six_alpha(base[0], base[1], false, enc2);
    if (error2 > 96 && error1 > 96) {
      // End points near 0 and 255 are left to codes 6 and 7; the others move by the mean
      // distance of the values between them to their nearest interpolated value.
      test[0] = 0xff, test[1] = 0;
      const int margin = (base[1] - base[0]) / 28;
      for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
          const int a = src[j][i][3];
          if (a > test[1] && a < 255 - margin) test[1] = a;
          if (a < test[0] && a > margin) test[0] = a;
        }
      }
      if (test[1] <= test[0]) test[0] = 1, test[1] = 254;
      int cuts[5];
      for (int k = 0; k < 5; ++k)
        cuts[k] = uint8_t((test[0] * (10 - (2 * k + 1)) + test[1] * (2 * k + 1)) / 10);
      int16_t drift_low = 0, drift_high = 0;
      uint8_t n_low = 0, n_high = 0;
      for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
          const int a = src[j][i][3];
          if (a <= test[0] / 2 || a > (255 + test[1]) / 2) continue;
          int k = 0;
          while (k < 5 && a > cuts[k]) ++k;
          if (k == 0) {
            drift_low = int16_t(drift_low + (a - test[0])), ++n_low;
          } else if (k == 5) {
            drift_high = int16_t(drift_high + (a - test[1])), ++n_high;
          } else {
            const int d = a - (test[0] * (5 - k) + test[1] * k) / 5;
            drift_low = int16_t(drift_low + d), drift_high = int16_t(drift_high + d);
            ++n_low, ++n_high;
          }
        }
      }
      if (n_low == 0) n_low = 1;
      if (n_high == 0) n_high = 1;
      test[0] = std::max(0, test[0] + drift_low / n_low);
      test[1] = std::min(255, test[1] + drift_high / n_high);
      error3 = six_alpha(test[0], test[1], true, enc3);
    }
  }
  if (error1 <= error2 && error1 <= error3)
    write(use[1], use[0], enc1);
  else if (error2 <= error3)
    write(base[0], base[1], enc2);
  else
    write(uint8_t(test[0]), uint8_t(test[1]), enc3);
}

void encode_block(GLenum f, const Block& src, int nx, int ny, uint8_t* out) {
  if (dxt1(f)) return encode_colour_block(src, nx, ny, f, out);
  if (f == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT) {
    // Alpha truncated to its high four bits.
    std::memset(out, 0, 8);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        out[(4 * j + i) / 2] |= uint8_t((src[j][i][3] >> 4) << (4 * (i & 1)));
  } else {
    encode_dxt5_alpha(src, nx, ny, out);
  }
  encode_colour_block(src, nx, ny, f, out + 8);
}

}  // namespace

uint32_t block_bytes(GLenum f) {
  switch (f) {
    case GL_COMPRESSED_RGB_S3TC_DXT1_EXT:
    case GL_COMPRESSED_RGBA_S3TC_DXT1_EXT:
      return 8;
    case GL_COMPRESSED_RGBA_S3TC_DXT3_EXT:
    case GL_COMPRESSED_RGBA_S3TC_DXT5_EXT:
      return 16;
    default:
      return 0;
  }
}

size_t image_bytes(GLenum f, uint32_t w, uint32_t h, uint32_t d) {
  return size_t(blocks_across(w)) * blocks_across(h) * d * block_bytes(f);
}

void decode_image(GLenum f, const uint8_t* blocks, uint32_t w, uint32_t h, uint32_t d,
                  uint8_t* rgba8) {
  const uint32_t bw = blocks_across(w), bh = blocks_across(h), bytes = block_bytes(f);
  Rgba texels[16];
  for (uint32_t z = 0; z < d; ++z) {
    for (uint32_t by = 0; by < bh; ++by) {
      for (uint32_t bx = 0; bx < bw; ++bx) {
        decode_block(f, blocks + ((size_t(z) * bh + by) * bw + bx) * bytes, texels);
        for (uint32_t j = 0; j < 4 && by * 4 + j < h; ++j)
          for (uint32_t i = 0; i < 4 && bx * 4 + i < w; ++i)
            std::memcpy(rgba8 + ((size_t(z) * h + by * 4 + j) * w + bx * 4 + i) * 4,
                        texels[j * 4 + i].data(), 4);
      }
    }
  }
}

void encode_image(GLenum f, const uint8_t* rgba8, uint32_t w, uint32_t h, uint32_t d,
                  uint8_t* blocks) {
  const uint32_t bw = blocks_across(w), bh = blocks_across(h), bytes = block_bytes(f);
  for (uint32_t z = 0; z < d; ++z) {
    for (uint32_t by = 0; by < bh; ++by) {
      for (uint32_t bx = 0; bx < bw; ++bx) {
        // Edge blocks: only the texels inside the image take part.
        const int nx = int(std::min(4u, w - bx * 4)), ny = int(std::min(4u, h - by * 4));
        Block src{};
        for (int j = 0; j < ny; ++j)
          for (int i = 0; i < nx; ++i)
            std::memcpy(src[j][i].data(),
                        rgba8 + ((size_t(z) * h + by * 4 + j) * w + bx * 4 + i) * 4, 4);
        encode_block(f, src, nx, ny, blocks + ((size_t(z) * bh + by) * bw + bx) * bytes);
      }
    }
  }
}

}  // namespace glpt::s3tc
