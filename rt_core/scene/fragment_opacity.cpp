#include "rt_core/scene/fragment_opacity.hpp"

#include <algorithm>
#include <cstring>

namespace glpt::rt {

namespace {

bool image_is_opaque(const rec::TextureImage& image, rec::TexelFormat format) {
  const uint8_t cached = image.alpha_is_one.value.load(std::memory_order_relaxed);
  if (cached != rec::CachedTexelFact::kUnknown) return cached == rec::CachedTexelFact::kTrue;
  bool opaque = true;
  const std::vector<uint8_t>& t = image.texels;
  switch (format) {
    case rec::TexelFormat::kRgba8:
      for (size_t i = 3; i < t.size() && opaque; i += 4) opaque = t[i] == 0xFF;
      break;
    case rec::TexelFormat::kRgba16:
      for (size_t i = 6; i + 1 < t.size() && opaque; i += 8)
        opaque = t[i] == 0xFF && t[i + 1] == 0xFF;
      break;
    case rec::TexelFormat::kRgba32f:
      for (size_t i = 12; i + 4 <= t.size() && opaque; i += 16) {
        float a = 0.0f;
        std::memcpy(&a, &t[i], sizeof a);
        opaque = a >= 1.0f;  // GL clamps a fragment's alpha to 1
      }
      break;
    case rec::TexelFormat::kDepth32f:  // alpha is the depth in some GL_DEPTH_TEXTURE_MODEs
      opaque = false;
      break;
  }
  image.alpha_is_one.value.store(
      opaque ? rec::CachedTexelFact::kTrue : rec::CachedTexelFact::kFalse,
      std::memory_order_relaxed);
  return opaque;
}

bool all_alpha_one(const std::vector<glm::vec4>& colours) {
  for (const glm::vec4& c : colours)
    if (!(c.a >= 1.0f)) return false;
  return true;
}

// The primary colour's alpha (GL 1.5 2.14: lighting gives the diffuse alpha of the lit face's
// material, which GL_COLOR_MATERIAL may track from the vertex colour).
bool primary_alpha_is_one(const rec::VertexData& v, const rec::LightingState& lighting) {
  if (!lighting.enabled) return all_alpha_one(v.color);
  const bool tracks_diffuse =
      lighting.color_material && (lighting.color_material_mode == GL_DIFFUSE ||
                                  lighting.color_material_mode == GL_AMBIENT_AND_DIFFUSE);
  for (int face = 0; face < (lighting.two_side ? 2 : 1); ++face) {
    const uint32_t gl_face = face == 0 ? GL_FRONT : GL_BACK;
    const bool tracked = tracks_diffuse && (lighting.color_material_face == GL_FRONT_AND_BACK ||
                                            lighting.color_material_face == gl_face);
    if (tracked ? !all_alpha_one(v.color) : !(lighting.material[face].diffuse.a >= 1.0f))
      return false;
  }
  return true;
}

bool has_alpha(uint32_t base_format) {
  return base_format == GL_ALPHA || base_format == GL_LUMINANCE_ALPHA || base_format == GL_RGBA ||
         base_format == GL_INTENSITY;
}

// A combine argument's alpha is 1: `previous` (the alpha so far) or the texture's.
bool combine_argument_is_one(uint32_t source, uint32_t operand, bool previous_one, bool primary_one,
                             bool texture_one) {
  if (operand != GL_SRC_ALPHA) return false;  // GL_ONE_MINUS_SRC_ALPHA of 1 is 0
  switch (source) {
    case GL_PREVIOUS:
      return previous_one;
    case GL_PRIMARY_COLOR:
      return primary_one;
    case GL_TEXTURE:
      return texture_one;
    default:
      return false;  // the constant colour, other units (crossbar)
  }
}

}  // namespace

bool blending_keeps_an_opaque_fragment(const rec::FragmentOpsState& ops) {
  if (!ops.blend) return true;
  const auto keeps = [](uint32_t equation, uint32_t source, uint32_t destination,
                        bool saturate_is_one) {
    return (equation == GL_FUNC_ADD || equation == GL_FUNC_SUBTRACT) &&
           (source == GL_ONE || source == GL_SRC_ALPHA ||
            (saturate_is_one && source == GL_SRC_ALPHA_SATURATE)) &&
           (destination == GL_ZERO || destination == GL_ONE_MINUS_SRC_ALPHA);
  };
  return keeps(ops.blend_equation_rgb, ops.blend_src_rgb, ops.blend_dst_rgb, false) &&
         keeps(ops.blend_equation_alpha, ops.blend_src_alpha, ops.blend_dst_alpha, true);
}

bool texels_are_opaque(const rec::TextureObjectSnapshot& texture) {
  const rec::SamplerState& s = texture.sampler;
  for (uint32_t wrap : {s.wrap_s, s.wrap_t, s.wrap_r})
    if ((wrap == GL_CLAMP || wrap == GL_CLAMP_TO_BORDER) && !(s.border_color.a >= 1.0f))
      return false;  // the border's alpha may be filtered in
  const int32_t first = std::max(s.base_level, 0);
  for (const auto& levels : texture.faces)
    for (int32_t level = first; level <= texture.last_level; ++level) {
      if (static_cast<size_t>(level) >= levels.size() || !levels[level]) return false;
      if (!image_is_opaque(*levels[level], texture.texel_format)) return false;
    }
  return !texture.faces.empty();
}

bool fragments_are_opaque(const rec::Draw& draw, const rec::StateSnapshot& state) {
  if (!draw.vertices) return false;
  const bool primary_one = primary_alpha_is_one(*draw.vertices, *state.lighting);
  bool alpha_one = primary_one;
  for (const rec::TextureUnitState& unit : state.texturing->units) {
    if (unit.target == 0 || !unit.texture) continue;
    const rec::TextureObjectSnapshot& texture = *unit.texture;
    const bool texture_one = !has_alpha(texture.base_format) || texels_are_opaque(texture);
    const rec::TexEnv& env = unit.env;
    switch (env.mode) {
      case GL_REPLACE:
        alpha_one = has_alpha(texture.base_format) ? texture_one : alpha_one;
        break;
      case GL_MODULATE:
      case GL_ADD:
        alpha_one = alpha_one && texture_one;
        break;
      case GL_DECAL:
        break;  // the fragment's alpha
      case GL_BLEND:
        alpha_one = alpha_one && !has_alpha(texture.base_format);
        break;
      case GL_COMBINE: {
        const auto arg = [&](int i) {
          return combine_argument_is_one(env.source_alpha[i], env.operand_alpha[i], alpha_one,
                                         primary_one, texture_one);
        };
        if (env.combine_alpha == GL_REPLACE)
          alpha_one = arg(0);
        else if (env.combine_alpha == GL_MODULATE)
          alpha_one = arg(0) && arg(1);
        else
          alpha_one = false;
        break;
      }
      default:
        alpha_one = false;
    }
    if (!alpha_one) return false;
  }
  return alpha_one;
}

bool splits_by_alpha(const rec::Draw& draw, const rec::StateSnapshot& state) {
  const rec::FragmentOpsState& ops = state.raster->ops;
  if (!draw.vertices || ops.color_logic_op || !blending_keeps_an_opaque_fragment(ops) ||
      !ops.depth_test || !ops.depth_write)
    return false;
  if (ops.alpha_test) {
    const bool passes_opaque = (ops.alpha_func == GL_GREATER || ops.alpha_func == GL_GEQUAL ||
                                ops.alpha_func == GL_NOTEQUAL || ops.alpha_func == GL_ALWAYS) &&
                               (ops.alpha_func == GL_ALWAYS || ops.alpha_ref < kOpaqueAlpha);
    if (!passes_opaque) return false;
  }
  return primary_alpha_is_one(*draw.vertices, *state.lighting);
}

}  // namespace glpt::rt
