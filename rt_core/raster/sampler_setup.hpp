// How raster mode samples one GL texture as llvmpipe does: the Vulkan sampler (lavapipe shares
// llvmpipe's sampler code, gallivm, so a sampler in the same state samples the same texels) and
// what the fragment shader must do itself where GL state has no Vulkan equivalent. Everything
// here reproduces Mesa 25.0.7's st/mesa (st_atom_sampler.c, texparam.c) and gallivm
// (lp_bld_sample*.c) decisions; the comments name the Mesa code each rule comes from.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/glm.hpp>

#include "raster_types.h"
#include "rt_core/record/gl_state.hpp"
#include "rt_core/record/texture.hpp"

namespace glpt::rt {

// What the fragment shader does for a unit beyond a plain lookup (bits of the unit's
// specialization constant, raster_types.h GLPT_UNIT_*).
struct ShaderSampling {
  // GL_CLAMP (GL 1.5 3.8.7) on s, t, r (bits 0-2) where the lookup is linear: the shader clamps
  // the coordinate to [0, 1] and the sampler blends in the border (CLAMP_TO_BORDER), which is
  // gallivm's PIPE_TEX_WRAP_CLAMP for linear filtering exactly. Nearest filtering of GL_CLAMP is
  // gallivm's CLAMP_TO_EDGE and needs nothing in the shader.
  uint32_t clamp_coords = 0;
  // The minification and magnification filters differ in kind (one NEAREST, one LINEAR) while
  // GL_CLAMP is clamped in the shader: the shader decides per quad which filter applies and
  // clamps the nearest pixels short of the border.
  bool clamp_per_filter = false;
  bool min_linear = false, mag_linear = false;  // the image filters (for clamp_per_filter)
  // Depth comparison (GL_ARB_shadow, GL 1.4): done in the shader from the stored depths.
  bool compare = false;
  uint32_t compare_func = GL_LEQUAL;
  uint32_t mip_filter = 0;  // 0 none, 1 nearest, 2 linear (for the shader's own lookups)

  bool operator==(const ShaderSampling&) const = default;
};

struct SamplerSetup {
  VkFilter mag_filter = VK_FILTER_NEAREST, min_filter = VK_FILTER_NEAREST;
  VkSamplerMipmapMode mipmap_mode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  VkSamplerAddressMode address[3] = {VK_SAMPLER_ADDRESS_MODE_REPEAT, VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                     VK_SAMPLER_ADDRESS_MODE_REPEAT};
  float min_lod = 0.0f, max_lod = 0.0f, lod_bias = 0.0f;
  // EXT_texture_filter_anisotropic: above 1, the most texels gallivm's anisotropic filter takes
  // along the axis of anisotropy; st/mesa passes the whole part of GL_TEXTURE_MAX_ANISOTROPY_EXT
  // (st_convert_sampler), so 1.9 filters isotropically. 0: off.
  float max_anisotropy = 0.0f;
  // The border colour as the sampler returns it: in the texel layout of rec::TexelFormat
  // (st_translate_color's per-base-format mapping) and clamped to the format's range.
  glm::vec4 border{0.0f};
  ShaderSampling shader;

  bool operator==(const SamplerSetup&) const = default;
};

// Mesa's util_quantize_lod_bias: clamped to [-16, 16], rounded to 1/256.
float quantize_lod_bias(float bias);

// The border colour a texture of `base_format` samples: st_translate_color (GL_RGB: alpha 1,
// GL_ALPHA: colour 0, GL_LUMINANCE: (r, r, r, 1), GL_LUMINANCE_ALPHA: (r, r, r, a),
// GL_INTENSITY: (r, r, r, r)), then gallivm's clamp of the border to the range of a normalized
// format (lp_build_clamp_border_color).
glm::vec4 border_color_of(glm::vec4 border, uint32_t base_format, rec::TexelFormat texel_format);

// The sampler and shader handling of `texture` on a unit whose GL_TEXTURE_LOD_BIAS is
// `unit_lod_bias`.
SamplerSetup make_sampler_setup(const rec::TextureObjectSnapshot& texture, float unit_lod_bias);

// The per-unit data of RasterState the shader's own lookups read (tex_size, tex_lod, tex_border,
// tex_mode) for `unit` (a texture on it) as unit `u`.
void pack_texture_unit(const rec::TextureUnitState& unit, int u, gpu::RasterState& out);

}  // namespace glpt::rt
