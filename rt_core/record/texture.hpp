// Texture contents as the frame record sees them: immutable snapshots of a GL texture object.
//
// The GL front end owns mutable texture objects; every draw that samples one refers to a
// TextureObjectSnapshot. A snapshot never changes: when the program redefines an image the front
// end makes a new snapshot (copy-on-write of the levels that are still referred to), so a draw
// recorded before a glTexSubImage in the same frame still sees the old texels.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "gl/gl_enums.h"

namespace glpt::rec {

// How texels are stored. Every colour format whose components have at most 8 bits is stored as
// RGBA8 after GL's conversion to its base format (GL 1.5 3.8.1, table 3.15) and quantization to
// the requested component size, laid out so a plain RGBA lookup returns what GL's texture
// environments call the texture colour: L -> (L,L,L,1), A -> (0,0,0,A), LA -> (L,L,L,A),
// I -> (I,I,I,I), RGB -> (R,G,B,1). Which components exist is `base_format`'s business.
enum class TexelFormat : uint8_t {
  kRgba8,    // 4 bytes per texel
  kRgba16,   // 8 bytes per texel, unsigned normalized (internal formats with > 8 bits)
  kRgba32f,  // 16 bytes per texel
  kDepth32f  // 4 bytes per texel: GL_DEPTH_COMPONENT textures (ARB_depth_texture, GL 1.4)
};

constexpr uint32_t texel_bytes(TexelFormat format) {
  switch (format) {
    case TexelFormat::kRgba16:
      return 8;
    case TexelFormat::kRgba32f:
      return 16;
    case TexelFormat::kRgba8:
    case TexelFormat::kDepth32f:
      break;
  }
  return 4;
}

// A fact about an image's texels worked out on first use and kept with it (the image never
// changes); a copy, which may be changed, starts without it.
class CachedTexelFact {
 public:
  enum : uint8_t { kUnknown = 0, kFalse = 1, kTrue = 2 };
  CachedTexelFact() = default;
  CachedTexelFact(const CachedTexelFact&) {}
  CachedTexelFact& operator=(const CachedTexelFact&) {
    value.store(kUnknown, std::memory_order_relaxed);
    return *this;
  }
  mutable std::atomic<uint8_t> value{kUnknown};
};

// One mipmap level of one face. GL texture borders are not stored: Mesa strips them when the
// image is specified (its gallium drivers have no borders), and glpt does the same so both
// sample the same texels.
struct TextureImage {
  uint32_t width = 0, height = 1, depth = 1;
  uint32_t border = 0;           // as specified (for queries); the texels exclude it
  uint32_t internal_format = 0;  // as the program asked (1..4, GL_RGB8, GL_LUMINANCE, ...)
  // The sized format whose component sizes the texels have: Mesa stores some unsized formats
  // with the precision of the data they were given (GL_RGBA from GL_UNSIGNED_SHORT data is
  // GL_RGBA16, GL_RGB from GL_UNSIGNED_SHORT_5_6_5 data is 5-6-5). 0: internal_format itself.
  uint32_t sized_format = 0;
  std::vector<uint8_t> texels;  // width * height * depth * texel_bytes, rows bottom to top
  // S3TC images (EXT_texture_compression_s3tc): the blocks as given or encoded, which
  // glGetCompressedTexImage returns; `texels` holds them decoded (RGBA8). Empty otherwise. The
  // renderer reads only `texels`.
  std::vector<uint8_t> compressed;
  // GL_DEPTH_STENCIL images (EXT_packed_depth_stencil): one stencil index per texel, in the order
  // of `texels`, which hold the depth values. Only glGetTexImage reads them (sampling a
  // depth-stencil texture samples its depth); empty for every other format.
  std::vector<uint8_t> stencil;
  // Whether every texel's alpha is 1 (rt::texels_are_opaque).
  CachedTexelFact alpha_is_one;
};

struct SamplerState {
  uint32_t min_filter = GL_NEAREST_MIPMAP_LINEAR;
  uint32_t mag_filter = GL_LINEAR;
  uint32_t wrap_s = GL_REPEAT, wrap_t = GL_REPEAT, wrap_r = GL_REPEAT;
  glm::vec4 border_color{0.0f};
  float min_lod = -1000.0f, max_lod = 1000.0f;
  int32_t base_level = 0, max_level = 1000;
  float lod_bias = 0.0f;  // GL_TEXTURE_LOD_BIAS of the object (GL 1.4)
  float max_anisotropy = 1.0f;
  uint32_t compare_mode = GL_NONE;  // GL_TEXTURE_COMPARE_MODE (GL 1.4 depth textures)
  uint32_t compare_func = GL_LEQUAL;
  uint32_t depth_texture_mode = GL_LUMINANCE;

  bool operator==(const SamplerState&) const = default;
};

struct TextureObjectSnapshot {
  uint32_t target = GL_TEXTURE_2D;  // GL_TEXTURE_1D, _2D, _3D, _CUBE_MAP
  // Unique for every distinct content of the images (never reused): GPU-side caches key on it,
  // so a texture whose images did not change is uploaded once.
  uint64_t content_version = 0;
  // GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_INTENSITY or
  // GL_DEPTH_COMPONENT: decides what the texture environment takes from the texel.
  uint32_t base_format = GL_RGBA;
  TexelFormat texel_format = TexelFormat::kRgba8;
  // faces[f][level]: one face for 1D/2D/3D, six (+X, -X, +Y, -Y, +Z, -Z) for cube maps.
  // Null or empty levels are undefined.
  std::vector<std::vector<std::shared_ptr<const TextureImage>>> faces;
  SamplerState sampler;
  // Levels base_level..last_level are consistent (GL 1.5 3.8.10). When a draw samples an
  // incomplete texture GL behaves as if texturing were disabled for that unit; the front end
  // resolves that before recording (TextureUnitState::target is 0 then).
  int32_t last_level = 0;
};

}  // namespace glpt::rec
