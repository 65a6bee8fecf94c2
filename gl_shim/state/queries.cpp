// glGetError, glGetString, glGet{Boolean,Integer,Float,Double}v (GL 1.5 spec 6.1).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/extension_override.hpp"
#include "gl_shim/state/query_values.hpp"

namespace glpt {
namespace {

using query::boolean;
using query::floats;
using query::ints;
using query::Kind;
using query::Value;

// GL_CURRENT_RASTER_SECONDARY_COLOR is not in the GL 1.5 registry selection; Mesa answers it.
constexpr GLenum kCurrentRasterSecondaryColor = 0x845F;

bool lookup(const Context& ctx, GLenum pname, Value* out) {
  const auto& fb = ctx.framebuffer;
  const auto& m = ctx.matrices;
  switch (pname) {
    case GL_VIEWPORT:
      *out = ints({double(fb.viewport_x), double(fb.viewport_y), double(fb.viewport_width),
                   double(fb.viewport_height)});
      return true;
    case GL_MAX_VIEWPORT_DIMS:
      *out = ints({16384, 16384});
      return true;
    case GL_MATRIX_MODE:
      *out = ints({double(m.mode)});
      return true;
    case GL_MODELVIEW_MATRIX:
      *out = floats(&m.modelview.top()[0][0], 16);
      return true;
    case GL_PROJECTION_MATRIX:
      *out = floats(&m.projection.top()[0][0], 16);
      return true;
    case GL_TEXTURE_MATRIX:
      *out = floats(&m.texture[ctx.textures.active].top()[0][0], 16);
      return true;
    case GL_MODELVIEW_STACK_DEPTH:
      *out = ints({double(m.modelview.depth())});
      return true;
    case GL_PROJECTION_STACK_DEPTH:
      *out = ints({double(m.projection.depth())});
      return true;
    case GL_TEXTURE_STACK_DEPTH:
      *out = ints({double(m.texture[ctx.textures.active].depth())});
      return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH:
      *out = ints({double(m.modelview.max_depth())});
      return true;
    case GL_MAX_PROJECTION_STACK_DEPTH:
      *out = ints({double(m.projection.max_depth())});
      return true;
    case GL_MAX_TEXTURE_STACK_DEPTH:
      *out = ints({double(m.texture[0].max_depth())});
      return true;
    case GL_MAX_LIGHTS:
      *out = ints({rec::kMaxLights});
      return true;
    case GL_MAX_CLIP_PLANES:
      *out = ints({6});
      return true;
    case GL_MAX_LIST_NESTING:
      *out = ints({DisplayListState::kMaxNesting});
      return true;
    case GL_MAX_ATTRIB_STACK_DEPTH:
      *out = ints({double(kMaxAttribStackDepth)});
      return true;
    case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH:
      *out = ints({double(kMaxClientAttribStackDepth)});
      return true;
    case GL_MAX_EVAL_ORDER:
      *out = ints({30});
      return true;
    // Mesa's recommended maximums (glpt draws any count up to kMaxArrayDrawVertices).
    case GL_MAX_ELEMENTS_VERTICES:
    case GL_MAX_ELEMENTS_INDICES:
      *out = ints({3000});
      return true;
    case GL_SUBPIXEL_BITS:
      *out = ints({8});  // Mesa llvmpipe's
      return true;
    case GL_AUX_BUFFERS:
      *out = ints({0});
      return true;
    case GL_LIST_BASE:
      *out = ints({double(ctx.lists.list_base)});
      return true;
    case GL_LIST_INDEX:
      *out = ints({double(ctx.lists.compiling_name)});
      return true;
    case GL_LIST_MODE:
      *out = ints({double(ctx.lists.compiling_mode)});
      return true;
    case GL_COLOR_CLEAR_VALUE:
      *out = floats(&fb.clear_color.x, 4, Kind::kColor);
      return true;
    case GL_DEPTH_CLEAR_VALUE:
      // Kept as the double glClearDepth took, as Mesa keeps it: integer queries map the double
      // (conformance scene pixels_depth_clears_read_as_uint).
      out->kind = Kind::kColor;
      out->count = 1;
      out->v[0] = fb.clear_depth;
      return true;
    case GL_STENCIL_CLEAR_VALUE:
      *out = ints({double(fb.clear_stencil)});
      return true;
    case GL_DEPTH_RANGE: {
      float d[2] = {float(fb.depth_near), float(fb.depth_far)};
      *out = floats(d, 2, Kind::kColor);
      return true;
    }
    case GL_DEPTH_FUNC:
      *out = ints({double(ctx.raster.ops.depth_func)});
      return true;
    case GL_CULL_FACE_MODE:
      *out = ints({double(ctx.raster.primitive.cull_face_mode)});
      return true;
    case GL_FRONT_FACE:
      *out = ints({double(ctx.raster.primitive.front_face)});
      return true;
    case GL_DRAW_BUFFER:
      *out = ints({double(ctx.raster.ops.draw_buffer)});
      return true;
    case GL_READ_BUFFER:
      // The read framebuffer's (EXT_framebuffer_blit), usually the draw framebuffer.
      *out = ints({double(buffers_of(ctx, ctx.framebuffers.read_framebuffer.get()).read_buffer)});
      return true;
    case GL_SCISSOR_BOX:
      *out = ints({double(ctx.raster.ops.scissor_box[0]), double(ctx.raster.ops.scissor_box[1]),
                   double(ctx.raster.ops.scissor_box[2]), double(ctx.raster.ops.scissor_box[3])});
      return true;
    case GL_PACK_ALIGNMENT:
      *out = ints({double(fb.pack.alignment)});
      return true;
    case GL_UNPACK_ALIGNMENT:
      *out = ints({double(fb.unpack.alignment)});
      return true;
    case GL_PACK_ROW_LENGTH:
      *out = ints({double(fb.pack.row_length)});
      return true;
    case GL_UNPACK_ROW_LENGTH:
      *out = ints({double(fb.unpack.row_length)});
      return true;
    case GL_PACK_SKIP_ROWS:
      *out = ints({double(fb.pack.skip_rows)});
      return true;
    case GL_UNPACK_SKIP_ROWS:
      *out = ints({double(fb.unpack.skip_rows)});
      return true;
    case GL_PACK_SKIP_PIXELS:
      *out = ints({double(fb.pack.skip_pixels)});
      return true;
    case GL_UNPACK_SKIP_PIXELS:
      *out = ints({double(fb.unpack.skip_pixels)});
      return true;
    case GL_PACK_SWAP_BYTES:
      *out = boolean(fb.pack.swap_bytes);
      return true;
    case GL_UNPACK_SWAP_BYTES:
      *out = boolean(fb.unpack.swap_bytes);
      return true;
    case GL_PACK_LSB_FIRST:
      *out = boolean(fb.pack.lsb_first);
      return true;
    case GL_UNPACK_LSB_FIRST:
      *out = boolean(fb.unpack.lsb_first);
      return true;
    case GL_CURRENT_COLOR:
      *out = floats(&ctx.current.color.x, 4, Kind::kColor);
      return true;
    case GL_CURRENT_NORMAL:
      *out = floats(&ctx.current.normal.x, 3, Kind::kColor);
      return true;
    case GL_CURRENT_TEXTURE_COORDS:
      *out = floats(&ctx.current.tex_coord[ctx.textures.active].x, 4);
      return true;
    case GL_SHADE_MODEL:
      *out = ints({double(ctx.raster.primitive.shade_model)});
      return true;
    case GL_LIGHT_MODEL_AMBIENT:
      *out = floats(&ctx.lighting.model_ambient.x, 4, Kind::kColor);
      return true;
    case GL_LIGHT_MODEL_TWO_SIDE:
      *out = boolean(ctx.lighting.two_side);
      return true;
    case GL_LIGHT_MODEL_LOCAL_VIEWER:
      *out = boolean(ctx.lighting.local_viewer);
      return true;
    case GL_COLOR_MATERIAL_FACE:
      *out = ints({double(ctx.lighting.color_material_face)});
      return true;
    case GL_COLOR_MATERIAL_PARAMETER:
      *out = ints({double(ctx.lighting.color_material_mode)});
      return true;
    // The drawable's buffers (its GLX visual / EGL config): RGBA8 colour.
    case GL_RED_BITS:
    case GL_GREEN_BITS:
    case GL_BLUE_BITS:
      *out = ints({8});
      return true;
    case GL_ALPHA_BITS:
      *out = ints({ctx.drawable.has_alpha ? 8.0 : 0.0});
      return true;
    case GL_DEPTH_BITS:
      *out = ints({double(ctx.drawable.depth_bits)});
      return true;
    case GL_STENCIL_BITS:
      *out = ints({double(ctx.drawable.stencil_bits)});
      return true;
    case GL_ACCUM_RED_BITS:
    case GL_ACCUM_GREEN_BITS:
    case GL_ACCUM_BLUE_BITS:
    case GL_ACCUM_ALPHA_BITS:
      *out = ints({double(ctx.drawable.accum_bits)});
      return true;
    case GL_INDEX_BITS:
      *out = ints({0});
      return true;
    case GL_DOUBLEBUFFER:
      *out = boolean(ctx.drawable.double_buffered);
      return true;
    case GL_RGBA_MODE:
      *out = boolean(true);
      return true;
    case GL_INDEX_MODE:
    case GL_STEREO:
      *out = boolean(false);
      return true;

    // ---- the raster position (GL 1.5 2.13, table 6.9; gl_shim/pixels/) ----
    // Colours convert as colours; the index is Mesa's 1 in RGBA mode.
    case GL_CURRENT_RASTER_POSITION:
      *out = floats(&ctx.raster_position.window.x, 4);
      return true;
    case GL_CURRENT_RASTER_POSITION_VALID:
      *out = boolean(ctx.raster_position.valid);
      return true;
    case GL_CURRENT_RASTER_DISTANCE:
      *out = floats(&ctx.raster_position.distance, 1);
      return true;
    case GL_CURRENT_RASTER_COLOR:
      *out = floats(&ctx.raster_position.color.x, 4, Kind::kColor);
      return true;
    case kCurrentRasterSecondaryColor:
      *out = floats(&ctx.raster_position.secondary_color.x, 4, Kind::kColor);
      return true;
    case GL_CURRENT_RASTER_TEXTURE_COORDS:
      *out = floats(&ctx.raster_position.tex_coord[ctx.textures.active].x, 4);
      return true;
    case GL_CURRENT_RASTER_INDEX:
      *out = ints({1});
      return true;
    default:
      break;
  }
  if (lookup_fixed_function_state(ctx, pname, out)) return true;
  if (lookup_array_state(ctx, pname, out)) return true;
  if (lookup_texture_and_pixel_state(ctx, pname, out)) return true;
  if (lookup_render_mode_state(ctx, pname, out)) return true;
  if (lookup_evaluator_state(ctx, pname, out)) return true;
  if (auto on = capability_enabled(const_cast<Context&>(ctx), pname)) {
    *out = boolean(*on);
    return true;
  }
  return false;
}

template <typename T>
void get(Context& ctx, GLenum pname, T* out) {
  Value v;
  if (!lookup(ctx, pname, &v)) return record_error(ctx, GL_INVALID_ENUM);
  if (out == nullptr) return;
  for (int i = 0; i < v.count; ++i) {
    const double d = v.v[i];
    if constexpr (std::is_same_v<T, GLboolean>) {
      out[i] = d != 0.0 ? 1 : 0;
    } else if constexpr (std::is_same_v<T, GLint>) {
      out[i] = v.kind == Kind::kColor ? query::color_to_int(d) : query::round_to_int(d);
    } else {
      out[i] = static_cast<T>(d);
    }
  }
}

}  // namespace

namespace impl {

GLenum glGetError(Context& ctx) {
  const GLenum e = ctx.error;
  ctx.error = GL_NO_ERROR;
  return e;
}

const GLubyte* glGetString(Context& ctx, GLenum name) {
  const char* s = nullptr;
  switch (name) {
    case GL_VENDOR:
      s = "glpt";
      break;
    case GL_RENDERER:
      s = "glpt path tracer (Vulkan ray query)";
      break;
    case GL_VERSION:
      s = "1.5 glpt " GLPT_VERSION_STRING;
      break;
    case GL_EXTENSIONS:
      s = extensions_string();
      break;
    default:
      record_error(ctx, GL_INVALID_ENUM);
      return nullptr;
  }
  return reinterpret_cast<const GLubyte*>(s);
}

void glGetBooleanv(Context& ctx, GLenum pname, GLboolean* data) { get(ctx, pname, data); }
void glGetIntegerv(Context& ctx, GLenum pname, GLint* data) { get(ctx, pname, data); }
void glGetFloatv(Context& ctx, GLenum pname, GLfloat* data) { get(ctx, pname, data); }
void glGetDoublev(Context& ctx, GLenum pname, GLdouble* data) { get(ctx, pname, data); }

}  // namespace impl
}  // namespace glpt
