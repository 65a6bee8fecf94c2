#include "rt_core/raster/sampler_setup.hpp"

#include <algorithm>
#include <cmath>

namespace glpt::rt {
namespace {

bool is_linear(uint32_t filter) {
  return filter == GL_LINEAR || filter == GL_LINEAR_MIPMAP_NEAREST ||
         filter == GL_LINEAR_MIPMAP_LINEAR;
}

// st/mesa's gl_filter_to_mip_filter: 0 none, 1 nearest, 2 linear.
uint32_t mip_filter_of(uint32_t min_filter) {
  switch (min_filter) {
    case GL_NEAREST_MIPMAP_NEAREST:
    case GL_LINEAR_MIPMAP_NEAREST:
      return 1;
    case GL_NEAREST_MIPMAP_LINEAR:
    case GL_LINEAR_MIPMAP_LINEAR:
      return 2;
    default:
      return 0;
  }
}

VkSamplerAddressMode address_mode(uint32_t wrap, bool any_linear) {
  switch (wrap) {
    case GL_CLAMP_TO_EDGE:
      return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case GL_MIRRORED_REPEAT:
      return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case GL_CLAMP_TO_BORDER:
      return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    case GL_CLAMP:
      // gallivm's lp_build_sample_wrap_nearest treats PIPE_TEX_WRAP_CLAMP as CLAMP_TO_EDGE; its
      // linear filtering clamps the scaled coordinate to [0, size] and takes the border beyond.
      return any_linear ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER
                        : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    default:
      return VK_SAMPLER_ADDRESS_MODE_REPEAT;
  }
}

}  // namespace

float quantize_lod_bias(float bias) {
  return std::round(std::clamp(bias, -16.0f, 16.0f) * 256.0f) / 256.0f;
}

glm::vec4 border_color_of(glm::vec4 b, uint32_t base_format, rec::TexelFormat texel_format) {
  glm::vec4 c = b;
  switch (base_format) {
    case GL_RGB:
      c = {b.r, b.g, b.b, 1.0f};
      break;
    case GL_ALPHA:
      c = {0.0f, 0.0f, 0.0f, b.a};
      break;
    case GL_LUMINANCE:
      c = {b.r, b.r, b.r, 1.0f};
      break;
    case GL_LUMINANCE_ALPHA:
      c = {b.r, b.r, b.r, b.a};
      break;
    case GL_INTENSITY:
      c = {b.r, b.r, b.r, b.r};
      break;
    default:  // GL_RGBA, GL_DEPTH_COMPONENT
      break;
  }
  // Every format glpt stores except float texels is normalized: gallivm clamps the border to
  // [0, 1] for those (a NaN becomes 0).
  if (texel_format != rec::TexelFormat::kRgba32f)
    for (int i = 0; i < 4; ++i) c[i] = std::isnan(c[i]) ? 0.0f : std::clamp(c[i], 0.0f, 1.0f);
  return c;
}

SamplerSetup make_sampler_setup(const rec::TextureObjectSnapshot& t, float unit_lod_bias) {
  const rec::SamplerState& s = t.sampler;
  SamplerSetup out;
  ShaderSampling& sh = out.shader;
  sh.min_linear = is_linear(s.min_filter);
  sh.mag_linear = s.mag_filter == GL_LINEAR;
  sh.mip_filter = mip_filter_of(s.min_filter);
  const bool any_linear = sh.min_linear || sh.mag_linear;
  out.mag_filter = sh.mag_linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  out.min_filter = sh.min_linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  out.mipmap_mode =
      sh.mip_filter == 2 ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;

  const uint32_t wraps[3] = {s.wrap_s, s.wrap_t, s.wrap_r};
  const bool cube = t.target == GL_TEXTURE_CUBE_MAP;
  for (int i = 0; i < 3; ++i) {
    // gallivm samples cube maps with CLAMP_TO_EDGE whatever the wrap modes say.
    out.address[i] =
        cube ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : address_mode(wraps[i], any_linear);
    if (!cube && wraps[i] == GL_CLAMP && any_linear) sh.clamp_coords |= 1u << i;
  }
  sh.clamp_per_filter = sh.clamp_coords != 0 && sh.min_linear != sh.mag_linear;

  // Depth comparison (st_convert_sampler: only for GL_DEPTH_COMPONENT textures).
  if (s.compare_mode == GL_COMPARE_R_TO_TEXTURE && t.base_format == GL_DEPTH_COMPONENT) {
    sh.compare = true;
    sh.compare_func = s.compare_func;
  }

  // Level of detail as st/mesa hands it to gallivm: min_lod = max(GL_TEXTURE_MIN_LOD, 0),
  // max_lod = GL_TEXTURE_MAX_LOD, lod_bias = the object's plus the unit's bias, each quantized
  // (texparam.c, texenv.c). lavapipe builds the same gallivm sampler state from these.
  const float bias = quantize_lod_bias(s.lod_bias) + quantize_lod_bias(unit_lod_bias);
  const float min_lod = std::max(s.min_lod, 0.0f);
  // The lod matters only with mipmapping or with two different filters; otherwise the sampler
  // keeps the default lods (fewer sampler variants).
  const bool lod_matters = sh.mip_filter != 0 || sh.min_linear != sh.mag_linear;
  // Vulkan limits the bias to maxSamplerLodBias (16 on lavapipe); Mesa's sum of two quantized
  // biases can reach 32, which no lod range needs.
  if (lod_matters) out.lod_bias = std::clamp(bias, -16.0f, 16.0f);
  if (sh.mip_filter != 0) {
    out.min_lod = min_lod;
    // gallivm clamps to min_lod last, so a maximum below the minimum reads as the minimum;
    // Vulkan wants maxLod >= minLod.
    out.max_lod = std::max(s.max_lod, min_lod);
  } else if (lod_matters) {
    // No mipmapping, but the lod still chooses between the two filters (lod > 0: minified).
    // Vulkan has no "no mipmapping" mode: a nearest mip filter with the lod kept below 0.5
    // samples the base level, and lod > 0 still decides exactly when gallivm's would.
    out.min_lod = std::min(min_lod, 0.25f);
    out.max_lod = std::clamp(s.max_lod, out.min_lod, 0.25f);
  }
  out.border = border_color_of(s.border_color, t.base_format, t.texel_format);
  const float anisotropy = std::floor(s.max_anisotropy);
  if (anisotropy > 1.0f) out.max_anisotropy = anisotropy;
  return out;
}

void pack_texture_unit(const rec::TextureUnitState& unit, int u, gpu::RasterState& out) {
  if (unit.target == 0 || !unit.texture) return;
  const rec::TextureObjectSnapshot& t = *unit.texture;
  const SamplerSetup setup = make_sampler_setup(t, unit.env.lod_bias);
  const ShaderSampling& sh = setup.shader;
  const int32_t base = std::clamp(t.sampler.base_level, 0, std::max(t.last_level, 0));
  if (!t.faces.empty() && static_cast<size_t>(base) < t.faces[0].size() && t.faces[0][base]) {
    const rec::TextureImage& image = *t.faces[0][base];
    out.tex_size[u] = glm::vec4(image.width, image.height, image.depth,
                                static_cast<float>(std::max(t.last_level - base + 1, 1)));
  }
  // gallivm's lod state from st/mesa's sampler (lp_sampler_static_sampler_state).
  const float bias = quantize_lod_bias(t.sampler.lod_bias) + quantize_lod_bias(unit.env.lod_bias);
  const float min_lod = std::max(t.sampler.min_lod, 0.0f), max_lod = t.sampler.max_lod;
  out.tex_lod[u] = glm::vec4(bias, min_lod, max_lod, setup.max_anisotropy);
  out.tex_border[u] = setup.border;
  uint32_t flags = 0;
  if (sh.min_linear) flags |= GLPT_TEX_MIN_LINEAR;
  if (sh.mag_linear) flags |= GLPT_TEX_MAG_LINEAR;
  if (sh.mip_filter == 1) flags |= GLPT_TEX_MIP_NEAREST;
  if (sh.mip_filter == 2) flags |= GLPT_TEX_MIP_LINEAR;
  if (bias != 0.0f) flags |= GLPT_TEX_LOD_BIAS;
  if (sh.mip_filter != 0 || sh.min_linear != sh.mag_linear) {
    if (min_lod == max_lod) {
      flags |= GLPT_TEX_MIN_MAX_LOD_EQUAL;
    } else {
      if (min_lod > 0.0f) flags |= GLPT_TEX_APPLY_MIN_LOD;
      if (max_lod < 15.0f) flags |= GLPT_TEX_APPLY_MAX_LOD;  // PIPE_MAX_TEXTURE_LEVELS - 1
    }
  }
  const auto wrap_code = [&](uint32_t wrap) -> uint32_t {
    if (t.target == GL_TEXTURE_CUBE_MAP) return GLPT_WRAP_CLAMP_TO_EDGE;
    switch (wrap) {
      case GL_CLAMP:
        return GLPT_WRAP_CLAMP;
      case GL_CLAMP_TO_EDGE:
        return GLPT_WRAP_CLAMP_TO_EDGE;
      case GL_CLAMP_TO_BORDER:
        return GLPT_WRAP_CLAMP_TO_BORDER;
      case GL_MIRRORED_REPEAT:
        return GLPT_WRAP_MIRRORED_REPEAT;
      default:
        return GLPT_WRAP_REPEAT;
    }
  };
  out.tex_mode[u] = glm::uvec4(wrap_code(t.sampler.wrap_s) | wrap_code(t.sampler.wrap_t) << 4 |
                                   wrap_code(t.sampler.wrap_r) << 8,
                               flags, sh.compare_func - GL_NEVER, 0);
}

}  // namespace glpt::rt
