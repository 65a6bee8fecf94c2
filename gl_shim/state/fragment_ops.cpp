// Per-fragment operations and buffer controls (GL 1.5 spec 4.1.3-4.1.10, 4.2.2, 4.2.3):
// glAlphaFunc, glStencilFunc/Op/Mask, glBlendFunc/FuncSeparate/Equation/Color, glLogicOp,
// glDepthMask, glColorMask, glIndexMask, glClearIndex, glClearAccum, glSampleCoverage. The live
// state is ctx.raster.ops (rec::FragmentOpsState); colour-index state is kept for queries only.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

// GL clamps these values when they are specified. NaN stays NaN, as in Mesa.
float clamp_to(float v, float lo, float hi) { return v < lo ? lo : (v > hi ? hi : v); }

bool is_comparison(GLenum func) { return func >= GL_NEVER && func <= GL_ALWAYS; }

bool is_stencil_op(GLenum op) {
  switch (op) {
    case GL_KEEP:
    case GL_ZERO:
    case GL_REPLACE:
    case GL_INCR:
    case GL_DECR:
    case GL_INVERT:
    case GL_INCR_WRAP:  // GL 1.4
    case GL_DECR_WRAP:
      return true;
    default:
      return false;
  }
}

// GL 1.5 table 4.2. GL_SRC_ALPHA_SATURATE is a source factor only (Mesa, following later GL
// versions, also accepts it as a destination factor; GL 1.5 names GL_INVALID_ENUM).
bool is_blend_factor(GLenum factor, bool source) {
  switch (factor) {
    case GL_ZERO:
    case GL_ONE:
    case GL_SRC_COLOR:
    case GL_ONE_MINUS_SRC_COLOR:
    case GL_DST_COLOR:
    case GL_ONE_MINUS_DST_COLOR:
    case GL_SRC_ALPHA:
    case GL_ONE_MINUS_SRC_ALPHA:
    case GL_DST_ALPHA:
    case GL_ONE_MINUS_DST_ALPHA:
    case GL_CONSTANT_COLOR:
    case GL_ONE_MINUS_CONSTANT_COLOR:
    case GL_CONSTANT_ALPHA:
    case GL_ONE_MINUS_CONSTANT_ALPHA:
      return true;
    case GL_SRC_ALPHA_SATURATE:
      return source;
    default:
      return false;
  }
}

bool is_blend_equation(GLenum mode) {
  switch (mode) {
    case GL_FUNC_ADD:
    case GL_FUNC_SUBTRACT:
    case GL_FUNC_REVERSE_SUBTRACT:
    case GL_MIN:
    case GL_MAX:
      return true;
    default:
      return false;
  }
}

void blend_func(Context& ctx, GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha) {
  if (!is_blend_factor(src_rgb, true) || !is_blend_factor(dst_rgb, false) ||
      !is_blend_factor(src_alpha, true) || !is_blend_factor(dst_alpha, false))
    return record_error(ctx, GL_INVALID_ENUM);
  rec::FragmentOpsState& ops = ctx.raster.ops;
  ops.blend_src_rgb = src_rgb;
  ops.blend_dst_rgb = dst_rgb;
  ops.blend_src_alpha = src_alpha;
  ops.blend_dst_alpha = dst_alpha;
}

}  // namespace

namespace impl {

void glAlphaFunc(Context& ctx, GLenum func, GLfloat ref) {
  if (!is_comparison(func)) return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.ops.alpha_func = func;
  ctx.raster.ops.alpha_ref = clamp_to(ref, 0.0f, 1.0f);
}

// The reference value is stored as given; GL clamps it to [0, 2^s - 1] (s: the stencil buffer's
// bits) when it is used and when it is queried.
// With EXT_stencil_two_side's back face selected, glStencilFunc/Op/Mask set the back face's state
// only; otherwise the front face's (which back faces also use while two-sided stencil is off).
void glStencilFunc(Context& ctx, GLenum func, GLint ref, GLuint mask) {
  if (!is_comparison(func)) return record_error(ctx, GL_INVALID_ENUM);
  rec::FragmentOpsState& ops = ctx.raster.ops;
  if (ops.stencil_back_selected) {
    ops.back_stencil.func = func;
    ops.back_stencil.ref = ref;
    ops.back_stencil.value_mask = mask;
    return;
  }
  ops.stencil_func = func;
  ops.stencil_ref = ref;
  ops.stencil_value_mask = mask;
}

void glStencilOp(Context& ctx, GLenum fail, GLenum zfail, GLenum zpass) {
  if (!is_stencil_op(fail) || !is_stencil_op(zfail) || !is_stencil_op(zpass))
    return record_error(ctx, GL_INVALID_ENUM);
  rec::FragmentOpsState& ops = ctx.raster.ops;
  if (ops.stencil_back_selected) {
    ops.back_stencil.fail = fail;
    ops.back_stencil.depth_fail = zfail;
    ops.back_stencil.depth_pass = zpass;
    return;
  }
  ops.stencil_fail = fail;
  ops.stencil_depth_fail = zfail;
  ops.stencil_depth_pass = zpass;
}

void glStencilMask(Context& ctx, GLuint mask) {
  rec::FragmentOpsState& ops = ctx.raster.ops;
  (ops.stencil_back_selected ? ops.back_stencil.write_mask : ops.stencil_write_mask) = mask;
}

// EXT_stencil_two_side: which face glStencilFunc/Op/Mask set and stencil queries report.
void glActiveStencilFaceEXT(Context& ctx, GLenum face) {
  if (face != GL_FRONT && face != GL_BACK) return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.ops.stencil_back_selected = face == GL_BACK;
}

void glBlendFunc(Context& ctx, GLenum sfactor, GLenum dfactor) {
  blend_func(ctx, sfactor, dfactor, sfactor, dfactor);
}

void glBlendFuncSeparate(Context& ctx, GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha,
                         GLenum dst_alpha) {
  blend_func(ctx, src_rgb, dst_rgb, src_alpha, dst_alpha);
}

void glBlendEquation(Context& ctx, GLenum mode) {
  if (!is_blend_equation(mode)) return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.ops.blend_equation_rgb = mode;
  ctx.raster.ops.blend_equation_alpha = mode;
}

// EXT_blend_equation_separate (GL 2.0's glBlendEquationSeparate): both modes are checked before
// either is set, as Mesa does.
void glBlendEquationSeparate(Context& ctx, GLenum mode_rgb, GLenum mode_alpha) {
  if (!is_blend_equation(mode_rgb) || !is_blend_equation(mode_alpha))
    return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.ops.blend_equation_rgb = mode_rgb;
  ctx.raster.ops.blend_equation_alpha = mode_alpha;
}

void glBlendColor(Context& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  ctx.raster.ops.blend_color = {clamp_to(r, 0.0f, 1.0f), clamp_to(g, 0.0f, 1.0f),
                                clamp_to(b, 0.0f, 1.0f), clamp_to(a, 0.0f, 1.0f)};
}

void glLogicOp(Context& ctx, GLenum opcode) {
  if (opcode < GL_CLEAR || opcode > GL_SET) return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.ops.logic_op = opcode;
}

void glDepthMask(Context& ctx, GLboolean flag) { ctx.raster.ops.depth_write = flag != 0; }

void glColorMask(Context& ctx, GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  ctx.raster.ops.color_write = {r != 0, g != 0, b != 0, a != 0};
}

void glIndexMask(Context& ctx, GLuint mask) { ctx.color_index.write_mask = mask; }

// Mesa stores the clear index as an integer, truncating.
void glClearIndex(Context& ctx, GLfloat c) {
  constexpr float kIntLimit = 2147483520.0f;  // the largest float below 2^31
  ctx.color_index.clear_index =
      std::isnan(c) ? 0 : static_cast<GLint>(clamp_to(c, -kIntLimit, kIntLimit));
}

void glClearAccum(Context& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  ctx.framebuffer.clear_accum = {clamp_to(r, -1.0f, 1.0f), clamp_to(g, -1.0f, 1.0f),
                                 clamp_to(b, -1.0f, 1.0f), clamp_to(a, -1.0f, 1.0f)};
}

void glSampleCoverage(Context& ctx, GLfloat value, GLboolean invert) {
  ctx.framebuffer.sample_coverage_value = clamp_to(value, 0.0f, 1.0f);
  ctx.framebuffer.sample_coverage_invert = invert != 0;
}

}  // namespace impl
}  // namespace glpt
