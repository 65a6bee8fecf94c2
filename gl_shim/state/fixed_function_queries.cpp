// glGet* answers for the fixed-function state this area owns: rasterization (points, lines,
// polygons), fog, per-fragment operations and buffer masks, current attributes beyond colour,
// normal and texture coordinates, transposed matrices, and the implementation limits of these
// groups (GL 1.5 spec tables 6.5-6.34). queries.cpp consults lookup_fixed_function_state for
// every pname it does not answer itself.
#include <algorithm>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/state/implementation_limits.hpp"
#include "gl_shim/state/query_values.hpp"

namespace glpt {
namespace {

using query::Kind;
using query::Value;

Value enums(std::initializer_list<uint32_t> l) {
  Value r;
  r.kind = Kind::kInt;
  for (uint32_t e : l) r.v[r.count++] = e;
  return r;
}

Value number(double v, Kind kind = Kind::kFloat) {
  Value r;
  r.kind = kind;
  r.count = 1;
  r.v[0] = v;
  return r;
}

Value vec(const float* p, int n, Kind kind = Kind::kFloat) { return query::floats(p, n, kind); }

Value transposed(const glm::mat4& m) {
  Value r;
  r.kind = Kind::kFloat;
  r.count = 16;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) r.v[row * 4 + col] = m[col][row];
  return r;
}

// Rasterization of points, lines and polygons (tables 6.12-6.14) and their limits (6.29).
bool lookup_primitive(const rec::PrimitiveState& p, GLenum pname, Value* out) {
  switch (pname) {
    case GL_POINT_SIZE:
      *out = number(p.point_size);
      return true;
    case GL_POINT_SIZE_MIN:
      *out = number(p.point_size_min);
      return true;
    case GL_POINT_SIZE_MAX:
      *out = number(p.point_size_max);
      return true;
    case GL_POINT_FADE_THRESHOLD_SIZE:
      *out = number(p.point_fade_threshold);
      return true;
    case GL_POINT_DISTANCE_ATTENUATION:
      *out = vec(&p.point_distance_attenuation.x, 3);
      return true;
    case GL_POINT_SPRITE_COORD_ORIGIN:
      *out = query::ints({double(p.point_sprite_coord_origin)});
      return true;
    case GL_LINE_WIDTH:
      *out = number(p.line_width);
      return true;
    case GL_LINE_STIPPLE_PATTERN:
      *out = number(p.line_stipple_pattern, Kind::kInt);
      return true;
    case GL_LINE_STIPPLE_REPEAT:
      *out = number(p.line_stipple_factor, Kind::kInt);
      return true;
    case GL_POLYGON_MODE:
      *out = enums({p.polygon_mode_front, p.polygon_mode_back});
      return true;
    case GL_POLYGON_OFFSET_FACTOR:
      *out = number(p.offset_factor);
      return true;
    case GL_POLYGON_OFFSET_UNITS:
      *out = number(p.offset_units);
      return true;
    case GL_ALIASED_POINT_SIZE_RANGE:
      *out = vec(kAliasedPointSizeRange, 2);
      return true;
    case GL_SMOOTH_POINT_SIZE_RANGE:  // == GL_POINT_SIZE_RANGE
      *out = vec(kSmoothPointSizeRange, 2);
      return true;
    case GL_POINT_SIZE_GRANULARITY:  // == GL_SMOOTH_POINT_SIZE_GRANULARITY
      *out = number(kPointSizeGranularity);
      return true;
    case GL_ALIASED_LINE_WIDTH_RANGE:
      *out = vec(kAliasedLineWidthRange, 2);
      return true;
    case GL_SMOOTH_LINE_WIDTH_RANGE:  // == GL_LINE_WIDTH_RANGE
      *out = vec(kSmoothLineWidthRange, 2);
      return true;
    case GL_SMOOTH_LINE_WIDTH_GRANULARITY:  // == GL_LINE_WIDTH_GRANULARITY
      *out = number(kLineWidthGranularity);
      return true;
    default:
      return false;
  }
}

// Fog (table 6.10).
bool lookup_fog(const Context& ctx, GLenum pname, Value* out) {
  const rec::FogState& f = ctx.raster.fog;
  switch (pname) {
    case GL_FOG_MODE:
      *out = enums({f.mode});
      return true;
    case GL_FOG_DENSITY:
      *out = number(f.density);
      return true;
    case GL_FOG_START:
      *out = number(f.start);
      return true;
    case GL_FOG_END:
      *out = number(f.end);
      return true;
    case GL_FOG_COLOR:
      *out = vec(&f.color.x, 4, Kind::kColor);
      return true;
    case GL_FOG_INDEX:
      *out = number(ctx.color_index.fog_index);
      return true;
    case GL_FOG_COORDINATE_SOURCE:
      *out = enums({f.coord_source});
      return true;
    default:
      return false;
  }
}

// Per-fragment operations and framebuffer control (tables 6.19-6.21).
bool lookup_fragment_ops(const Context& ctx, GLenum pname, Value* out) {
  const rec::FragmentOpsState& o = ctx.raster.ops;
  const rec::StencilFaceState stencil =
      o.stencil_back_selected ? o.back_stencil : o.front_stencil();
  switch (pname) {
    case GL_ALPHA_TEST_FUNC:
      *out = enums({o.alpha_func});
      return true;
    case GL_ALPHA_TEST_REF:  // an alpha value: integers get the colour mapping
      *out = number(o.alpha_ref, Kind::kColor);
      return true;
    case GL_STENCIL_FUNC:  // of the face EXT_stencil_two_side selects, as in Mesa
      *out = enums({stencil.func});
      return true;
    case GL_STENCIL_REF:  // clamped to the stencil buffer's range when queried, as in Mesa
      *out = number(std::clamp(stencil.ref, 0, (1 << kStencilBits) - 1), Kind::kInt);
      return true;
    case GL_STENCIL_VALUE_MASK:  // unsigned: integer queries saturate at 2^31 - 1
      *out = number(stencil.value_mask, Kind::kInt);
      return true;
    case GL_STENCIL_WRITEMASK:
      *out = number(stencil.write_mask, Kind::kInt);
      return true;
    case GL_STENCIL_FAIL:
      *out = enums({stencil.fail});
      return true;
    case GL_STENCIL_PASS_DEPTH_FAIL:
      *out = enums({stencil.depth_fail});
      return true;
    case GL_STENCIL_PASS_DEPTH_PASS:
      *out = enums({stencil.depth_pass});
      return true;
    case GL_ACTIVE_STENCIL_FACE_EXT:
      *out = enums({o.stencil_back_selected ? GLenum{GL_BACK} : GLenum{GL_FRONT}});
      return true;
    case GL_BLEND_SRC:
    case GL_BLEND_SRC_RGB:
      *out = enums({o.blend_src_rgb});
      return true;
    case GL_BLEND_DST:
    case GL_BLEND_DST_RGB:
      *out = enums({o.blend_dst_rgb});
      return true;
    case GL_BLEND_SRC_ALPHA:
      *out = enums({o.blend_src_alpha});
      return true;
    case GL_BLEND_DST_ALPHA:
      *out = enums({o.blend_dst_alpha});
      return true;
    case GL_BLEND_EQUATION:  // also EXT_blend_equation_separate's GL_BLEND_EQUATION_RGB_EXT
      *out = enums({o.blend_equation_rgb});
      return true;
    case GL_BLEND_EQUATION_ALPHA_EXT:
      *out = enums({o.blend_equation_alpha});
      return true;
    case GL_BLEND_COLOR:
      *out = vec(&o.blend_color.x, 4, Kind::kColor);
      return true;
    case GL_LOGIC_OP_MODE:
      *out = enums({o.logic_op});
      return true;
    case GL_DEPTH_WRITEMASK:
      *out = query::boolean(o.depth_write);
      return true;
    case GL_COLOR_WRITEMASK: {
      Value r;
      r.kind = Kind::kBool;
      r.count = 4;
      for (int i = 0; i < 4; ++i) r.v[i] = o.color_write[i] ? 1 : 0;
      *out = r;
      return true;
    }
    case GL_ACCUM_CLEAR_VALUE:
      *out = vec(&ctx.framebuffer.clear_accum.x, 4, Kind::kColor);
      return true;
    case GL_INDEX_WRITEMASK:  // Mesa reports the mask as a signed integer (all ones: -1)
      *out = number(static_cast<GLint>(ctx.color_index.write_mask), Kind::kInt);
      return true;
    case GL_INDEX_CLEAR_VALUE:
      *out = number(ctx.color_index.clear_index, Kind::kInt);
      return true;
    case GL_SAMPLE_COVERAGE_VALUE:
      *out = number(ctx.framebuffer.sample_coverage_value);
      return true;
    case GL_SAMPLE_COVERAGE_INVERT:
      *out = query::boolean(ctx.framebuffer.sample_coverage_invert);
      return true;
    case GL_SAMPLE_BUFFERS:  // no multisample buffers (as an OSMesa or default GLX drawable)
    case GL_SAMPLES:
      *out = number(0, Kind::kInt);
      return true;
    default:
      return false;
  }
}

// Current values beyond colour, normal and texture coordinates (table 6.5), the lighting model's
// colour control (6.11), the transposed matrices (6.7) and the clip plane limit (6.29).
bool lookup_current_and_transform(const Context& ctx, GLenum pname, Value* out) {
  const CurrentAttributes& c = ctx.current;
  switch (pname) {
    case GL_CURRENT_SECONDARY_COLOR:
      *out = vec(&c.secondary_color.x, 4, Kind::kColor);
      return true;
    case GL_CURRENT_FOG_COORD:  // == GL_CURRENT_FOG_COORDINATE
      *out = number(c.fog_coord);
      return true;
    case GL_CURRENT_INDEX:
      *out = number(c.index);
      return true;
    case GL_EDGE_FLAG:
      *out = query::boolean(c.edge_flag);
      return true;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      *out = enums({ctx.lighting.separate_specular ? GLenum{GL_SEPARATE_SPECULAR_COLOR}
                                                   : GLenum{GL_SINGLE_COLOR}});
      return true;
    case GL_TRANSPOSE_MODELVIEW_MATRIX:
      *out = transposed(ctx.matrices.modelview.top());
      return true;
    case GL_TRANSPOSE_PROJECTION_MATRIX:
      *out = transposed(ctx.matrices.projection.top());
      return true;
    case GL_TRANSPOSE_TEXTURE_MATRIX:
      *out = transposed(ctx.matrices.texture[ctx.textures.active].top());
      return true;
    default:
      return false;
  }
}

}  // namespace

bool lookup_fixed_function_state(const Context& ctx, GLenum pname, Value* out) {
  return lookup_primitive(ctx.raster.primitive, pname, out) || lookup_fog(ctx, pname, out) ||
         lookup_fragment_ops(ctx, pname, out) || lookup_current_and_transform(ctx, pname, out);
}

}  // namespace glpt
