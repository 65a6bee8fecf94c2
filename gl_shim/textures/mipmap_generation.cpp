#include "gl_shim/textures/mipmap_generation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include "gl_shim/textures/internal_formats.hpp"
#include "gl_shim/textures/s3tc.hpp"
#include "gl_shim/textures/texel_codec.hpp"
#include "gl_shim/textures/texture_object.hpp"

namespace glpt {
namespace {

// Where destination texel i samples a source row of `src` texels: between texels i0 and i1,
// with weight w / 256 on i1.
struct Tap {
  uint32_t i0 = 0, i1 = 0;
  int32_t w = 0;
};

std::vector<Tap> taps(uint32_t src, uint32_t dst) {
  std::vector<Tap> t(dst);
  for (uint32_t i = 0; i < dst; ++i) {
    const double u = (double(i) + 0.5) * double(src) / double(dst) - 0.5;
    const double fl = std::floor(u);
    const int64_t i0 = int64_t(fl);
    t[i].w = int32_t((u - fl) * 256.0);  // truncated to 8 fractional bits
    t[i].i0 = uint32_t(std::clamp<int64_t>(i0, 0, src - 1));
    t[i].i1 = uint32_t(std::clamp<int64_t>(i0 + 1, 0, src - 1));
  }
  return t;
}

// llvmpipe's fixed-point lerp: halves round up.
int32_t lerp(int32_t a, int32_t b, int32_t w) { return a + (((b - a) * w + 128) >> 8); }
float lerp(float a, float b, int32_t w) { return a + (b - a) * (float(w) / 256.0f); }

// Channel values of one texel, and their storage.
struct Channels {
  int count = 4;
  int32_t v[4] = {};
  float depth = 0.0f;
};

Channels load(const rec::TextureImage& img, rec::TexelFormat format, size_t index) {
  Channels c;
  const uint8_t* p = img.texels.data() + index * rec::texel_bytes(format);
  switch (format) {
    case rec::TexelFormat::kRgba8:
      for (int k = 0; k < 4; ++k) c.v[k] = p[k];
      break;
    case rec::TexelFormat::kRgba16:
      for (int k = 0; k < 4; ++k) {
        uint16_t h;
        std::memcpy(&h, p + 2 * k, 2);
        c.v[k] = h;
      }
      break;
    default:
      std::memcpy(&c.depth, p, 4);
      break;
  }
  return c;
}

Channels lerp(const Channels& a, const Channels& b, int32_t w) {
  Channels r;
  for (int k = 0; k < 4; ++k) r.v[k] = lerp(a.v[k], b.v[k], w);
  r.depth = lerp(a.depth, b.depth, w);
  return r;
}

void store(const InternalFormatInfo& info, rec::TexelFormat format, const Channels& c, uint8_t* p) {
  switch (format) {
    case rec::TexelFormat::kRgba8:
    case rec::TexelFormat::kRgba16: {
      const uint32_t storage_bits = format == rec::TexelFormat::kRgba8 ? 8 : 16;
      for (int k = 0; k < 4; ++k) {
        // Written back in the format's precision, as the blit into the texture does.
        const uint32_t bits = info.channel_bits(k) != 0 ? info.channel_bits(k) : storage_bits;
        const uint32_t q = narrow_from_storage(uint32_t(c.v[k]), bits, storage_bits);
        const uint32_t stored = widen_to_storage(q, bits, storage_bits);
        if (storage_bits == 8) {
          p[k] = uint8_t(stored);
        } else {
          const uint16_t h = uint16_t(stored);
          std::memcpy(p + 2 * k, &h, 2);
        }
      }
      break;
    }
    default: {
      const float d = c.depth;
      encode_depth_texels(info, &d, 1, p);
      break;
    }
  }
}

std::shared_ptr<rec::TextureImage> downsample(const rec::TextureImage& src,
                                              const InternalFormatInfo& info) {
  const rec::TexelFormat format = info.texel_format();
  auto dst = std::make_shared<rec::TextureImage>();
  dst->width = std::max(1u, src.width / 2);
  dst->height = std::max(1u, src.height / 2);
  dst->depth = std::max(1u, src.depth / 2);
  dst->border = src.border;
  dst->internal_format = src.internal_format;
  dst->sized_format = src.sized_format;
  const uint32_t texel = rec::texel_bytes(format);
  dst->texels.resize(size_t(dst->width) * dst->height * dst->depth * texel);
  const std::vector<Tap> tx = taps(src.width, dst->width);
  const std::vector<Tap> ty = taps(src.height, dst->height);
  const std::vector<Tap> tz = taps(src.depth, dst->depth);
  const auto at = [&](uint32_t x, uint32_t y, uint32_t z) {
    return load(src, format, (size_t(z) * src.height + y) * src.width + x);
  };
  uint8_t* out = dst->texels.data();
  for (const Tap& z : tz) {
    for (const Tap& y : ty) {
      for (const Tap& x : tx) {
        // x first, then y, then z, as the sampler filters.
        const Channels c = lerp(lerp(lerp(at(x.i0, y.i0, z.i0), at(x.i1, y.i0, z.i0), x.w),
                                     lerp(at(x.i0, y.i1, z.i0), at(x.i1, y.i1, z.i0), x.w), y.w),
                                lerp(lerp(at(x.i0, y.i0, z.i1), at(x.i1, y.i0, z.i1), x.w),
                                     lerp(at(x.i0, y.i1, z.i1), at(x.i1, y.i1, z.i1), x.w), y.w),
                                z.w);
        store(info, format, c, out);
        out += texel;
      }
    }
  }
  return dst;
}

// Mesa generates the levels of a compressed texture in software (util_gen_mipmap cannot render
// into a compressed format; generate_mipmap_compressed): the base level decoded (as llvmpipe
// decodes it: measured, the CPU decoder's rounding gives other blocks), each level a 2x2 box of
// the uncompressed level before it, truncated (_mesa_generate_mipmap_level's do_row; an odd last
// row or column is dropped), then compressed by its encoder. The texels sampled are those blocks
// decoded.
void generate_s3tc_mipmaps(TextureObject& object, int face, const rec::TextureImage& base,
                           int base_level, int top) {
  const GLenum f = GLenum(base.internal_format);
  const uint32_t border = base.border, internal_format = base.internal_format;
  uint32_t w = base.width, h = base.height;
  std::vector<uint8_t> src = base.texels;
  for (int level = base_level + 1; level <= top; ++level) {
    if (w == 1 && h == 1) break;
    const uint32_t dw = std::max(1u, w / 2), dh = std::max(1u, h / 2);
    const uint32_t col_step = w == dw ? 1 : 2, k0 = w == dw ? 0 : 1;
    const bool two_rows = h > 1 && h > dh;
    std::vector<uint8_t> dst(size_t(dw) * dh * 4);
    for (uint32_t y = 0; y < dh; ++y) {
      const uint8_t* a = src.data() + size_t(y) * (two_rows ? 2 : 1) * w * 4;
      const uint8_t* b = two_rows ? a + size_t(w) * 4 : a;
      for (uint32_t x = 0; x < dw; ++x) {
        const size_t j = size_t(x) * col_step * 4, k = j + k0 * 4;
        for (int c = 0; c < 4; ++c)
          dst[(size_t(y) * dw + x) * 4 + c] =
              uint8_t((a[j + c] + a[k + c] + b[j + c] + b[k + c]) / 4);
      }
    }
    auto img = std::make_shared<rec::TextureImage>();
    img->width = dw, img->height = dh, img->depth = 1;
    img->border = border, img->internal_format = internal_format;
    img->compressed.assign(s3tc::image_bytes(f, dw, dh, 1), 0);
    s3tc::encode_image(f, dst.data(), dw, dh, 1, img->compressed.data());
    img->texels.assign(dst.size(), 0);
    s3tc::decode_image(f, img->compressed.data(), dw, dh, 1, img->texels.data());
    object.set_image(face, level, std::move(img));
    src = std::move(dst);
    w = dw, h = dh;
  }
}

}  // namespace

void generate_mipmaps(TextureObject& object, int face) {
  const int base = object.sampler().base_level;
  const rec::TextureImage* base_image = object.image(face, base);
  if (base_image == nullptr || base_image->texels.empty()) return;
  const InternalFormatInfo* info =
      stored_format_info(base_image->internal_format, base_image->sized_format);
  if (info == nullptr) return;
  const int top =
      std::min(object.sampler().max_level, max_texture_levels(texture_slot(object.target())) - 1);
  if (info->block_bytes != 0 && base_image->depth == 1 && !base_image->compressed.empty())
    return generate_s3tc_mipmaps(object, face, *base_image, base, top);
  // Each level is held by the object while the next is computed from it (set_image only
  // replaces levels above it).
  const rec::TextureImage* previous = base_image;
  for (int level = base + 1; level <= top; ++level) {
    if (previous->width == 1 && previous->height == 1 && previous->depth == 1) break;
    std::shared_ptr<rec::TextureImage> next = downsample(*previous, *info);
    if (info->block_bytes != 0) {
      // 3-D S3TC images (Mesa's path for them is not modelled): filtered as uncompressed 3-D
      // images are, then compressed, so that their levels keep blocks like every S3TC image.
      const GLenum f = GLenum(next->internal_format);
      next->compressed.assign(s3tc::image_bytes(f, next->width, next->height, next->depth), 0);
      s3tc::encode_image(f, next->texels.data(), next->width, next->height, next->depth,
                         next->compressed.data());
      s3tc::decode_image(f, next->compressed.data(), next->width, next->height, next->depth,
                         next->texels.data());
    }
    previous = next.get();
    object.set_image(face, level, std::move(next));
  }
}

}  // namespace glpt
