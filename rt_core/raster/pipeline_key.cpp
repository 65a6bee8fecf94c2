#include "rt_core/raster/pipeline_key.hpp"

#include <algorithm>
#include <cstring>

#include "common/content_hash.hpp"
#include "raster_types.h"
#include "rt_core/raster/sampler_setup.hpp"
#include "rt_core/raster/state_uniforms.hpp"

namespace glpt::rt {
namespace {

uint32_t texgen_code(uint32_t mode) {
  switch (mode) {
    case GL_OBJECT_LINEAR:
      return 1;
    case GL_EYE_LINEAR:
      return 2;
    case GL_SPHERE_MAP:
      return 3;
    case GL_REFLECTION_MAP:
      return 4;
    case GL_NORMAL_MAP:
      return 5;
    default:
      return 0;
  }
}

uint32_t target_code(uint32_t target) {
  switch (target) {
    case GL_TEXTURE_1D:
      return 1;
    case GL_TEXTURE_2D:
    case GL_TEXTURE_RECTANGLE_ARB:  // sampled as 2D with normalized coordinates (GLPT_UNIT_RECT)
      return 2;
    case GL_TEXTURE_3D:
      return 3;
    case GL_TEXTURE_CUBE_MAP:
      return 4;
    default:
      return 0;
  }
}

uint32_t env_code(uint32_t mode) {
  switch (mode) {
    case GL_DECAL:
      return 1;
    case GL_BLEND:
      return 2;
    case GL_REPLACE:
      return 3;
    case GL_ADD:
      return 4;
    case GL_COMBINE:
      return 5;
    default:
      return 0;  // GL_MODULATE
  }
}

uint32_t base_format_code(uint32_t base_format, uint32_t depth_texture_mode) {
  if (base_format == GL_DEPTH_COMPONENT) base_format = depth_texture_mode;
  switch (base_format) {
    case GL_RGB:
      return 1;
    case GL_ALPHA:
      return 2;
    case GL_LUMINANCE:
      return 3;
    case GL_LUMINANCE_ALPHA:
      return 4;
    case GL_INTENSITY:
      return 5;
    default:
      return 0;  // GL_RGBA
  }
}

uint32_t combine_function_code(uint32_t f) {
  switch (f) {
    case GL_REPLACE:
      return GLPT_COMBINE_REPLACE;
    case GL_ADD:
      return GLPT_COMBINE_ADD;
    case GL_ADD_SIGNED:
      return GLPT_COMBINE_ADD_SIGNED;
    case GL_INTERPOLATE:
      return GLPT_COMBINE_INTERPOLATE;
    case GL_SUBTRACT:
      return GLPT_COMBINE_SUBTRACT;
    case GL_DOT3_RGB:
    case GL_DOT3_RGB_EXT:
      return GLPT_COMBINE_DOT3_RGB;
    case GL_DOT3_RGBA:
    case GL_DOT3_RGBA_EXT:
      return GLPT_COMBINE_DOT3_RGBA;
    default:
      return GLPT_COMBINE_MODULATE;
  }
}

uint32_t source_code(uint32_t s) {
  switch (s) {
    case GL_CONSTANT:
      return GLPT_SRC_CONSTANT;
    case GL_PRIMARY_COLOR:
      return GLPT_SRC_PRIMARY;
    case GL_PREVIOUS:
      return GLPT_SRC_PREVIOUS;
    default:
      if (s >= GL_TEXTURE0 && s < GL_TEXTURE0 + rec::kMaxTextureUnits)
        return GLPT_SRC_TEXTURE0 + (s - GL_TEXTURE0);
      return GLPT_SRC_TEXTURE;
  }
}

uint32_t rgb_operand_code(uint32_t op) {
  switch (op) {
    case GL_ONE_MINUS_SRC_COLOR:
      return 1;
    case GL_SRC_ALPHA:
      return 2;
    case GL_ONE_MINUS_SRC_ALPHA:
      return 3;
    default:
      return 0;
  }
}

VkBlendFactor blend_factor(uint32_t f, bool has_alpha) {
  switch (f) {
    case GL_ZERO:
      return VK_BLEND_FACTOR_ZERO;
    case GL_ONE:
      return VK_BLEND_FACTOR_ONE;
    case GL_SRC_COLOR:
      return VK_BLEND_FACTOR_SRC_COLOR;
    case GL_ONE_MINUS_SRC_COLOR:
      return VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR;
    case GL_DST_COLOR:
      return VK_BLEND_FACTOR_DST_COLOR;
    case GL_ONE_MINUS_DST_COLOR:
      return VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR;
    case GL_SRC_ALPHA:
      return VK_BLEND_FACTOR_SRC_ALPHA;
    case GL_ONE_MINUS_SRC_ALPHA:
      return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    // Without an alpha buffer the destination alpha reads as 1 (GL 1.5 4.1.8).
    case GL_DST_ALPHA:
      return has_alpha ? VK_BLEND_FACTOR_DST_ALPHA : VK_BLEND_FACTOR_ONE;
    case GL_ONE_MINUS_DST_ALPHA:
      return has_alpha ? VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA : VK_BLEND_FACTOR_ZERO;
    case GL_CONSTANT_COLOR:
      return VK_BLEND_FACTOR_CONSTANT_COLOR;
    case GL_ONE_MINUS_CONSTANT_COLOR:
      return VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_COLOR;
    case GL_CONSTANT_ALPHA:
      return VK_BLEND_FACTOR_CONSTANT_ALPHA;
    case GL_ONE_MINUS_CONSTANT_ALPHA:
      return VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_ALPHA;
    case GL_SRC_ALPHA_SATURATE:
      return VK_BLEND_FACTOR_SRC_ALPHA_SATURATE;
    default:
      return VK_BLEND_FACTOR_ONE;
  }
}

VkBlendOp blend_op(uint32_t e) {
  switch (e) {
    case GL_FUNC_SUBTRACT:
      return VK_BLEND_OP_SUBTRACT;
    case GL_FUNC_REVERSE_SUBTRACT:
      return VK_BLEND_OP_REVERSE_SUBTRACT;
    case GL_MIN:
      return VK_BLEND_OP_MIN;
    case GL_MAX:
      return VK_BLEND_OP_MAX;
    default:
      return VK_BLEND_OP_ADD;
  }
}

VkStencilOp stencil_op(uint32_t op) {
  switch (op) {
    case GL_ZERO:
      return VK_STENCIL_OP_ZERO;
    case GL_REPLACE:
      return VK_STENCIL_OP_REPLACE;
    case GL_INCR:
      return VK_STENCIL_OP_INCREMENT_AND_CLAMP;
    case GL_DECR:
      return VK_STENCIL_OP_DECREMENT_AND_CLAMP;
    case GL_INVERT:
      return VK_STENCIL_OP_INVERT;
    case GL_INCR_WRAP:
      return VK_STENCIL_OP_INCREMENT_AND_WRAP;
    case GL_DECR_WRAP:
      return VK_STENCIL_OP_DECREMENT_AND_WRAP;
    default:
      return VK_STENCIL_OP_KEEP;
  }
}

// GL_NEVER .. GL_ALWAYS and VK_COMPARE_OP_NEVER .. ALWAYS list the same functions in order.
VkCompareOp compare_op(uint32_t func) {
  return func >= GL_NEVER && func <= GL_ALWAYS ? static_cast<VkCompareOp>(func - GL_NEVER)
                                               : VK_COMPARE_OP_ALWAYS;
}

VkPolygonMode polygon_mode(uint32_t mode) {
  return mode == GL_LINE    ? VK_POLYGON_MODE_LINE
         : mode == GL_POINT ? VK_POLYGON_MODE_POINT
                            : VK_POLYGON_MODE_FILL;
}

VkCullModeFlags cull_mode(uint32_t face) {
  return face == GL_FRONT  ? VK_CULL_MODE_FRONT_BIT
         : face == GL_BACK ? VK_CULL_MODE_BACK_BIT
                           : VK_CULL_MODE_FRONT_AND_BACK;
}

}  // namespace

size_t PipelineKeyHash::operator()(const PipelineKey& key) const {
  ContentHash h;
  h.add_bytes(&key, sizeof key);
  return static_cast<size_t>(h.value());
}

uint32_t varyings_read(const PipelineKey& key) {
  if (key.gbuffer || key.pixels || key.unfilled) return GLPT_VARYINGS_ALL;
  const uint32_t fs = key.constants[GLPT_SC_FS_FLAGS];
  uint32_t varyings = 0;
  if (fs & GLPT_FS_TWO_SIDE) varyings |= GLPT_VARYING_BACK;
  if (fs & GLPT_FS_COLOR_SUM) varyings |= GLPT_VARYING_SECONDARY;
  if (fs & GLPT_FS_POLYGON_STIPPLE) varyings |= GLPT_VARYING_WINDOW_POSITION;
  if ((key.constants[GLPT_SC_FS_ALPHA_FOG] >> 12) & 3u) varyings |= GLPT_VARYING_FOG;
  for (int u = 0; u < GLPT_RASTER_MAX_UNITS; ++u)
    if (key.constants[GLPT_SC_UNIT0 + u] & 7u) varyings |= GLPT_VARYING_TEXCOORDS;
  return varyings;
}

namespace {

// Mesa's float_to_ubyte (u_math.h), which llvmpipe applies to the blend constant of unorm8
// colour buffers: x * 255/256 + 2^15 leaves x * 255 rounded to nearest even in the low byte.
uint32_t blend_constant_unorm8(float x) {
  if (!(x > 0.0f)) return 0;  // NaN too
  if (x >= 1.0f) return 255;
  volatile float scaled = x * (255.0f / 256.0f);  // two roundings, as in Mesa: no fused add
  const float biased = scaled + 32768.0f;
  uint32_t bits;
  std::memcpy(&bits, &biased, sizeof bits);
  return bits & 0xFFu;
}

}  // namespace

glm::uvec4 framebuffer_ops_constants(const PipelineKey& key, const glm::vec4& blend_constant) {
  glm::uvec4 ops(0u);
  ops.x = uint32_t{key.blend_src_rgb} | uint32_t{key.blend_dst_rgb} << 8 |
          uint32_t{key.blend_src_alpha} << 16 | uint32_t{key.blend_dst_alpha} << 24;
  ops.y = uint32_t{key.blend_op_rgb} | uint32_t{key.blend_op_alpha} << 8 |
          uint32_t{key.logic_op} << 16 | (key.logic_op_enable ? 1u << 24 : 0u);
  for (int c = 0; c < 4; ++c) ops.z |= blend_constant_unorm8(blend_constant[c]) << (8 * c);
  return ops;
}

ColorTargets resolve_draw_buffer(uint32_t draw_buffer, bool double_buffered) {
  switch (draw_buffer) {
    case GL_NONE:
      return ColorTargets::kNone;
    case GL_FRONT:
    case GL_FRONT_LEFT:
      return ColorTargets::kFront;
    case GL_BACK:
    case GL_BACK_LEFT:
      // A single-buffered drawable has one buffer; Mesa draws GL_BACK into it too.
      return double_buffered ? ColorTargets::kBack : ColorTargets::kFront;
    // GL 1.5 4.2.1: GL_LEFT names the front left and back left buffers.
    case GL_LEFT:
    case GL_FRONT_AND_BACK:
      return double_buffered ? ColorTargets::kFrontAndBack : ColorTargets::kFront;
    default:
      // A framebuffer object's colour attachments: its target holds the one the draw buffer
      // names, as its single (front) buffer. Right buffers: glpt's drawables are not stereo.
      if (draw_buffer >= GL_COLOR_ATTACHMENT0_EXT && draw_buffer <= GL_COLOR_ATTACHMENT15_EXT)
        return ColorTargets::kFront;
      return ColorTargets::kNone;
  }
}

DrawSetup make_draw_setup(const rec::StateSnapshot& state, const DrawContext& context) {
  DrawSetup setup;
  PipelineKey& key = setup.key;
  uint32_t* sc = key.constants;
  const rec::TransformState& transform = *state.transform;
  const rec::LightingState& lighting = *state.lighting;
  const rec::TexturingState& texturing = *state.texturing;
  const rec::PrimitiveState& prim = state.raster->primitive;
  const rec::FogState& fog = state.raster->fog;
  const rec::FragmentOpsState& ops = state.raster->ops;
  const bool triangles = context.topology == RasterTopology::kTriangles;
  const bool lines =
      context.topology == RasterTopology::kLines || context.topology == RasterTopology::kLineStrip;
  const bool points = context.topology == RasterTopology::kPoints;

  // ---- the polygon mode of this pass (front and back modes may differ: two passes)
  VkCullModeFlags cull = prim.cull_face ? cull_mode(prim.cull_face_mode) : VkCullModeFlags{0};
  uint32_t mode = GL_FILL;
  if (triangles) {
    const bool front_drawn =
        !(cull & VK_CULL_MODE_FRONT_BIT) && context.face_pass != VK_CULL_MODE_FRONT_BIT;
    const bool back_drawn =
        !(cull & VK_CULL_MODE_BACK_BIT) && context.face_pass != VK_CULL_MODE_BACK_BIT;
    if (!front_drawn && !back_drawn) {
      setup.skip = true;
      return setup;
    }
    if (front_drawn && back_drawn && prim.polygon_mode_front != prim.polygon_mode_back) {
      setup.split_faces = true;  // the caller draws each face in its own pass
      return setup;
    }
    mode = front_drawn ? prim.polygon_mode_front : prim.polygon_mode_back;
    cull |= context.face_pass;
  }
  const bool as_lines = lines || (triangles && mode == GL_LINE);

  // ---- vertex stage
  uint32_t vs = 0;
  if (lighting.enabled) {
    vs |= GLPT_VS_LIGHTING;
    if (lighting.two_side) vs |= GLPT_VS_TWO_SIDE;
    if (lighting.local_viewer) vs |= GLPT_VS_LOCAL_VIEWER;
    if (lighting.separate_specular) vs |= GLPT_VS_SEPARATE_SPECULAR;
    sc[GLPT_SC_LIGHT_MASK] = lighting.light_mask | light_kind_bits(lighting);
    if (lighting.color_material) {
      uint32_t cm = 0;
      switch (lighting.color_material_mode) {
        case GL_AMBIENT:
          cm = 1;
          break;
        case GL_DIFFUSE:
          cm = 2;
          break;
        case GL_SPECULAR:
          cm = 4;
          break;
        case GL_EMISSION:
          cm = 5;
          break;
        default:
          cm = 3;
          break;
      }
      if (lighting.color_material_face != GL_BACK) cm |= 8u;
      if (lighting.color_material_face != GL_FRONT) cm |= 16u;
      sc[GLPT_SC_COLOR_MATERIAL] = cm;
    }
  }
  if (transform.normalize) vs |= GLPT_VS_NORMALIZE;
  if (transform.rescale_normal) vs |= GLPT_VS_RESCALE_NORMAL;
  // Point sprites (GL 2.0 3.3.1) apply to every point rasterized: GL_POINTS, and polygons drawn
  // in GL_POINT mode (raster_unfilled.geom), as Mesa draws them.
  const bool sprites = (points || (triangles && mode == GL_POINT)) && prim.point_sprite;
  if (points) {
    vs |= GLPT_VS_POINTS;
    if (prim.point_distance_attenuation != glm::vec3(1.0f, 0.0f, 0.0f))
      vs |= GLPT_VS_POINT_ATTENUATION;
    if (sprites) vs |= GLPT_VS_POINT_SPRITE;
  }
  if (lines) vs |= GLPT_VS_LINES;
  bool needs_eye =
      lighting.enabled || transform.clip_plane_mask != 0 || (vs & GLPT_VS_POINT_ATTENUATION) != 0;
  if (fog.enabled) {
    if (fog.coord_source == GL_FOG_COORDINATE)
      vs |= GLPT_VS_FOG_COORD_SOURCE;
    else
      needs_eye = true;
  }
  uint32_t texcoord_units = 0;
  uint64_t texgen = 0;
  for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
    const rec::TextureUnitState& unit = texturing.units[u];
    if (unit.target == 0 || !unit.texture) continue;
    texcoord_units |= 1u << u;
    for (int c = 0; c < 4; ++c) {
      if (!(unit.texgen_mask & (1u << c))) continue;
      const uint32_t code = texgen_code(unit.texgen[c].mode);
      texgen |= uint64_t{code} << (u * 12 + c * 3);
      if (code >= 2 && code <= 4) needs_eye = true;  // eye linear, sphere and reflection maps
    }
    const rec::TextureObjectSnapshot& tex = *unit.texture;
    const rec::TexEnv& env = unit.env;
    uint32_t config = target_code(unit.target) | (env_code(env.mode) << 3) |
                      (base_format_code(tex.base_format, tex.sampler.depth_texture_mode) << 6);
    // What the shader does beyond a plain lookup (sampler_setup.hpp).
    const SamplerSetup setup = make_sampler_setup(tex, env.lod_bias);
    const ShaderSampling& sampling = setup.shader;
    config |= sampling.clamp_coords * GLPT_UNIT_CLAMP_S;
    if (sampling.clamp_per_filter) config |= GLPT_UNIT_CLAMP_PER_FILTER;
    if (sampling.compare) config |= GLPT_UNIT_COMPARE;
    if (tex.texel_format == rec::TexelFormat::kDepth32f) config |= GLPT_UNIT_DEPTH;
    if (unit.target == GL_TEXTURE_RECTANGLE_ARB) config |= GLPT_UNIT_RECT;
    if (sprites && (prim.point_coord_replace >> u) & 1u) config |= GLPT_UNIT_COORD_REPLACE;
    // Only pipelines that filter anisotropically carry the filter's code.
    if (setup.max_anisotropy > 1.0f) config |= GLPT_UNIT_ANISOTROPIC;
    sc[GLPT_SC_UNIT0 + u] = config;
    if (env.mode == GL_COMBINE) {
      uint32_t combine =
          combine_function_code(env.combine_rgb) | (combine_function_code(env.combine_alpha) << 4);
      uint32_t alpha_operands = 0;
      for (int i = 0; i < 3; ++i) {
        combine |= source_code(env.source_rgb[i]) << (8 + 3 * i);
        combine |= source_code(env.source_alpha[i]) << (17 + 3 * i);
        combine |= rgb_operand_code(env.operand_rgb[i]) << (26 + 2 * i);
        if (env.operand_alpha[i] == GL_ONE_MINUS_SRC_ALPHA) alpha_operands |= 1u << i;
      }
      sc[GLPT_SC_COMBINE0 + u] = combine;
      sc[GLPT_SC_COMBINE_ALPHA_OPERANDS0 + u] = alpha_operands;
    }
  }
  if (needs_eye) vs |= GLPT_VS_NEEDS_EYE;
  sc[GLPT_SC_VS_FLAGS] = vs;
  sc[GLPT_SC_TEXGEN_01] = static_cast<uint32_t>(texgen & 0xFFFFFF);
  sc[GLPT_SC_TEXGEN_23] = static_cast<uint32_t>(texgen >> 24);
  sc[GLPT_SC_TEXCOORD_UNITS] = texcoord_units;
  sc[GLPT_SC_CLIP_PLANES] = transform.clip_plane_mask;

  // ---- fragment stage
  uint32_t fs = 0;
  if (lighting.enabled && lighting.two_side) fs |= GLPT_FS_TWO_SIDE;
  // GL 1.4 3.9: with lighting the secondary colour is the separate specular (or zero); without,
  // it is the vertex's and only added while GL_COLOR_SUM is enabled.
  if (lighting.enabled ? lighting.separate_specular : ops.color_sum) fs |= GLPT_FS_COLOR_SUM;
  if (triangles && mode == GL_FILL && prim.polygon_stipple) fs |= GLPT_FS_POLYGON_STIPPLE;
  if (sprites && prim.point_sprite_coord_origin == GL_LOWER_LEFT) fs |= GLPT_FS_SPRITE_LOWER_LEFT;
  sc[GLPT_SC_FS_FLAGS] = fs;
  uint32_t alpha_fog = 0;
  if (ops.alpha_test && ops.alpha_func >= GL_NEVER && ops.alpha_func <= GL_ALWAYS)
    alpha_fog |= (ops.alpha_func - GL_NEVER + 1) << 8;
  if (fog.enabled) alpha_fog |= (fog.mode == GL_LINEAR ? 1u : fog.mode == GL_EXP2 ? 3u : 2u) << 12;
  sc[GLPT_SC_FS_ALPHA_FOG] = alpha_fog;
  key.flat = prim.shade_model == GL_FLAT;
  key.clip_variant = transform.clip_plane_mask != 0 || lines;
  // Unfilled polygons become lines or points in the geometry shader, which culls, offsets and
  // honours edge flags itself (Vulkan's polygon mode has no edge flags).
  const bool unfilled = triangles && mode != GL_FILL;
  if (unfilled) {
    key.unfilled = mode == GL_LINE ? 1 : 2;
    key.clip_variant = 1;
    uint32_t u = 0;
    if (prim.front_face == GL_CW) u |= GLPT_UNFILLED_FRONT_CW;
    if (cull & VK_CULL_MODE_FRONT_BIT) u |= GLPT_UNFILLED_CULL_FRONT;
    if (cull & VK_CULL_MODE_BACK_BIT) u |= GLPT_UNFILLED_CULL_BACK;
    if (mode == GL_LINE ? prim.offset_line : prim.offset_point) u |= GLPT_UNFILLED_OFFSET;
    if (prim.shade_model == GL_FLAT) u |= GLPT_UNFILLED_FLAT;
    if (sprites) u |= GLPT_UNFILLED_SPRITE;
    sc[GLPT_SC_UNFILLED] = u;
  }

  // ---- fixed function
  key.topology = static_cast<uint8_t>(context.topology);
  key.polygon_mode = static_cast<uint8_t>(unfilled ? VK_POLYGON_MODE_FILL : polygon_mode(mode));
  key.line_mode =
      static_cast<uint8_t>(prim.line_smooth ? VK_LINE_RASTERIZATION_MODE_RECTANGULAR_SMOOTH_EXT
                                            : VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT);
  key.line_stipple = as_lines && prim.line_stipple;
  key.logic_op_enable = ops.color_logic_op;
  key.logic_op = static_cast<uint8_t>(ops.logic_op >= GL_CLEAR && ops.logic_op <= GL_SET
                                          ? ops.logic_op - GL_CLEAR
                                          : uint32_t{VK_LOGIC_OP_COPY});
  key.blend = ops.blend && !ops.color_logic_op;
  if (key.blend) {
    key.blend_src_rgb =
        static_cast<uint8_t>(blend_factor(ops.blend_src_rgb, context.drawable_has_alpha));
    key.blend_dst_rgb =
        static_cast<uint8_t>(blend_factor(ops.blend_dst_rgb, context.drawable_has_alpha));
    key.blend_src_alpha =
        static_cast<uint8_t>(blend_factor(ops.blend_src_alpha, context.drawable_has_alpha));
    key.blend_dst_alpha =
        static_cast<uint8_t>(blend_factor(ops.blend_dst_alpha, context.drawable_has_alpha));
    key.blend_op_rgb = static_cast<uint8_t>(blend_op(ops.blend_equation_rgb));
    key.blend_op_alpha = static_cast<uint8_t>(blend_op(ops.blend_equation_alpha));
  }
  uint8_t mask = 0;
  if (ops.color_write[0]) mask |= VK_COLOR_COMPONENT_R_BIT;
  if (ops.color_write[1]) mask |= VK_COLOR_COMPONENT_G_BIT;
  if (ops.color_write[2]) mask |= VK_COLOR_COMPONENT_B_BIT;
  // A drawable without alpha keeps alpha 1 (never written), so DST_ALPHA reads 1 everywhere.
  if (ops.color_write[3] && context.drawable_has_alpha) mask |= VK_COLOR_COMPONENT_A_BIT;
  key.color_write_mask = context.targets == ColorTargets::kNone ? 0 : mask;
  key.attachments = context.targets == ColorTargets::kFrontAndBack ? 2 : 1;

  // ---- dynamic state
  DynamicDrawState& d = setup.dynamic;
  d.cull = triangles && !unfilled ? cull : VkCullModeFlags{0};
  // Vulkan's signed area has the opposite sign of GL's for the same coordinates, and glpt's
  // framebuffer coordinates are GL's window coordinates (row 0 is GL's bottom row): GL's
  // counter-clockwise is Vulkan's clockwise.
  d.front_face =
      prim.front_face == GL_CW ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
  d.depth_test = ops.depth_test;
  d.depth_write = ops.depth_test && ops.depth_write;
  d.depth_compare = compare_op(ops.depth_func);
  d.stencil_test = ops.stencil_test && context.stencil_bits > 0;
  d.stencil_fail = stencil_op(ops.stencil_fail);
  d.stencil_depth_fail = stencil_op(ops.stencil_depth_fail);
  d.stencil_pass = stencil_op(ops.stencil_depth_pass);
  d.stencil_compare = compare_op(ops.stencil_func);
  const uint32_t stencil_max = (1u << std::min(context.stencil_bits, 8u)) - 1;
  d.stencil_compare_mask = ops.stencil_value_mask & stencil_max;
  d.stencil_write_mask = ops.stencil_write_mask & stencil_max;
  d.stencil_reference = static_cast<uint32_t>(
      std::clamp<int32_t>(ops.stencil_ref, 0, static_cast<int32_t>(stencil_max)));
  // Only polygons have a back face (points, lines and pixel rectangles are front-facing in GL as
  // in Vulkan). Unfilled polygons are expanded into their edges by the geometry stage, whose
  // triangles do not keep the polygon's facing: they use the front face's state.
  if (ops.stencil_two_side && triangles && !unfilled) {
    const rec::StencilFaceState& back = ops.back_stencil;
    d.separate_back_stencil = true;
    d.back_stencil.fail = stencil_op(back.fail);
    d.back_stencil.depth_fail = stencil_op(back.depth_fail);
    d.back_stencil.pass = stencil_op(back.depth_pass);
    d.back_stencil.compare = compare_op(back.func);
    d.back_stencil.compare_mask = back.value_mask & stencil_max;
    d.back_stencil.write_mask = back.write_mask & stencil_max;
    d.back_stencil.reference =
        static_cast<uint32_t>(std::clamp<int32_t>(back.ref, 0, static_cast<int32_t>(stencil_max)));
  }
  if (triangles && !unfilled) {
    d.depth_bias = mode == GL_FILL   ? prim.offset_fill
                   : mode == GL_LINE ? prim.offset_line
                                     : prim.offset_point;
    d.depth_bias_constant = prim.offset_units;
    d.depth_bias_slope = prim.offset_factor;
  }
  d.line_width = std::clamp(prim.line_width, 1.0f, 255.0f);
  d.line_stipple_factor = static_cast<uint32_t>(std::clamp(prim.line_stipple_factor, 1, 256));
  d.line_stipple_pattern = prim.line_stipple_pattern;
  d.blend_constant = ops.blend_color;

  // What raster mode does not reproduce exactly yet.
  // (Polygons are smoothed by the rule of the mode they are rasterized in: GL 1.5 3.5.6.)
  const bool as_points = points || (triangles && mode == GL_POINT);
  const bool filled = triangles && mode == GL_FILL;
  // (Sprites are squares: GL_POINT_SMOOTH does not apply to them, GL 2.0 3.3.1.)
  if ((as_points && prim.point_smooth && !sprites) || (filled && prim.polygon_smooth) ||
      (as_lines && prim.line_smooth))
    setup.approximated = true;
  return setup;
}

}  // namespace glpt::rt
