// glRenderMode, glSelectBuffer, glFeedbackBuffer, glPassThrough and the name stack commands
// (GL 1.5 5.2, 5.3), their state queries, and the feedback and selection buffers themselves.
// Errors and their order are Mesa's (src/mesa/main/feedback.c), measured with OSMesa:
// - glRenderMode leaves the old mode first (writing its last hit record, resetting its count and
//   name stack) and only then checks the new mode: an invalid mode is GL_INVALID_ENUM after the
//   old mode's results are gone, and entering selection or feedback without a buffer is
//   GL_INVALID_OPERATION *and* enters the mode (whose first value then overflows: -1);
// - the name stack commands are ignored outside selection mode (no error);
// - glSelectBuffer accepts a null buffer with a nonzero size (glpt then writes nothing);
//   glFeedbackBuffer rejects it (GL_INVALID_VALUE, and the size becomes 0).
#include <cmath>
#include <cstdint>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/render_modes/render_modes.hpp"
#include "gl_shim/state/query_values.hpp"

namespace glpt {
namespace {

// A hit record's depth: Mesa's (GLuint)((GLfloat)0xffffffff * z). The float product rounds to
// 2^32 for z near 1, and x86-64 converts a float to an unsigned 32-bit integer through a signed
// 64-bit one and keeps the low 32 bits: z = 1 reads 0. Values out of the 64-bit range (and NaN)
// convert to 2^63, whose low bits are 0 too.
GLuint hit_depth(float z) {
  const float scaled = static_cast<float>(0xffffffffu) * z;
  if (!(scaled > -9.2e18f && scaled < 9.2e18f)) return 0;
  return static_cast<GLuint>(static_cast<uint64_t>(static_cast<int64_t>(scaled)));
}

void write_selection_value(SelectionState& s, GLuint value) {
  if (s.count < static_cast<uint64_t>(s.size) && s.buffer != nullptr) s.buffer[s.count] = value;
  ++s.count;
}

// Mesa's update_hit_record: the pending hit, if any, becomes a record with the name stack.
void write_hit_record(SelectionState& s) {
  if (!s.hit) return;
  write_selection_value(s, s.depth);
  write_selection_value(s, hit_depth(s.min_z));
  write_selection_value(s, hit_depth(s.max_z));
  for (uint32_t i = 0; i < s.depth; ++i) write_selection_value(s, s.names[i]);
  s.hit = false;
  s.min_z = 1.0f;
  s.max_z = -1.0f;
  ++s.hits;
}

void reset_name_stack(SelectionState& s) {
  s.depth = 0;
  s.hit = false;
  s.min_z = 1.0f;
  s.max_z = 0.0f;
}

GLint overflowed_or(uint64_t count, GLsizei size, uint64_t result) {
  return count > static_cast<uint64_t>(size) ? -1 : static_cast<GLint>(result);
}

bool selecting(const Context& ctx) { return ctx.render_mode.mode == GL_SELECT; }

}  // namespace

void selection_hit(SelectionState& s, float z) {
  s.hit = true;
  if (z < s.min_z) s.min_z = z;
  if (z > s.max_z) s.max_z = z;
}

void feedback_value(FeedbackState& f, float value) {
  if (f.count < static_cast<uint64_t>(f.size) && f.buffer != nullptr) f.buffer[f.count] = value;
  ++f.count;
}

void feedback_vertex(FeedbackState& f, const glm::vec4& window, const glm::vec4& color,
                     const glm::vec4& tex_coord) {
  feedback_value(f, window.x);
  feedback_value(f, window.y);
  if (f.type == GL_2D) return;
  feedback_value(f, window.z);
  if (f.type == GL_4D_COLOR_TEXTURE) feedback_value(f, window.w);
  if (f.type == GL_3D) return;
  for (int i = 0; i < 4; ++i) feedback_value(f, color[i]);
  if (f.type == GL_3D_COLOR) return;
  for (int i = 0; i < 4; ++i) feedback_value(f, tex_coord[i]);
}

void render_mode_flush_vertices(Context& ctx) {
  ImmediateLayout& layout = ctx.render_mode.immediate;
  if (!layout.vertices_stored) return;  // (Mesa's flush leaves an unused layout as it is)
  layout.edge_flag = false;
  layout.vertices_stored = false;
}

void render_mode_pixel_rectangle(Context& ctx, GLenum token) {
  render_mode_flush_vertices(ctx);
  if (ctx.render_mode.mode != GL_FEEDBACK) return;  // selection: nothing (GL 1.5 5.2)
  ctx.flushed_tex_coord = ctx.current.tex_coord;    // Mesa's FLUSH_CURRENT
  const rec::RasterPosition& rp = ctx.raster_position;
  FeedbackState& f = ctx.render_mode.feedback;
  feedback_value(f, static_cast<float>(token));
  // The raster position as it is: window coordinates and clip w, the raster colour (unclamped
  // when unlit, as Mesa keeps it), unit 0's raster texture coordinates.
  feedback_vertex(f, rp.window, rp.color, rp.tex_coord[0]);
}

void render_mode_raster_position(Context& ctx) {
  render_mode_flush_vertices(ctx);
  if (selecting(ctx)) selection_hit(ctx.render_mode.selection, ctx.raster_position.window.z);
}

bool lookup_render_mode_state(const Context& ctx, GLenum pname, query::Value* out) {
  const RenderModeState& r = ctx.render_mode;
  switch (pname) {
    case GL_RENDER_MODE:
      *out = query::ints({double(r.mode)});
      return true;
    case GL_NAME_STACK_DEPTH:
      *out = query::ints({double(r.selection.depth)});
      return true;
    case GL_MAX_NAME_STACK_DEPTH:
      *out = query::ints({double(kMaxNameStackDepth)});
      return true;
    case GL_SELECTION_BUFFER_SIZE:
      *out = query::ints({double(r.selection.size)});
      return true;
    case GL_FEEDBACK_BUFFER_SIZE:
      *out = query::ints({double(r.feedback.size)});
      return true;
    case GL_FEEDBACK_BUFFER_TYPE:
      *out = query::ints({double(r.feedback.type)});
      return true;
    default:
      return false;
  }
}

namespace impl {

GLint glRenderMode(Context& ctx, GLenum mode) {
  RenderModeState& r = ctx.render_mode;
  GLint result = 0;
  switch (r.mode) {
    case GL_SELECT: {
      SelectionState& s = r.selection;
      write_hit_record(s);
      result = overflowed_or(s.count, s.size, s.hits);
      s.count = 0;
      s.hits = 0;
      reset_name_stack(s);  // the name stack is empty after selection mode
      break;
    }
    case GL_FEEDBACK:
      result = overflowed_or(r.feedback.count, r.feedback.size, r.feedback.count);
      r.feedback.count = 0;
      break;
    default:
      break;
  }
  switch (mode) {
    case GL_RENDER:
      break;
    case GL_SELECT:
      if (r.selection.size == 0) record_error(ctx, GL_INVALID_OPERATION);  // and enters it
      break;
    case GL_FEEDBACK:
      if (r.feedback.size == 0) record_error(ctx, GL_INVALID_OPERATION);  // and enters it
      break;
    default:
      record_error(ctx, GL_INVALID_ENUM);
      return 0;
  }
  if (mode != GL_RENDER) {
    uint32_t width = 0, height = 0;
    if (ctx.target != nullptr && ctx.target->query_size(&width, &height))
      r.drawable_height = static_cast<float>(height);
  }
  r.immediate = ImmediateLayout{};  // Mesa flushes its vertices: the vertex layout starts anew
  r.mode = mode;
  return result;
}

void glSelectBuffer(Context& ctx, GLsizei size, GLuint* buffer) {
  if (size < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (selecting(ctx)) return record_error(ctx, GL_INVALID_OPERATION);
  SelectionState& s = ctx.render_mode.selection;
  s.buffer = buffer;
  s.size = size;
  s.count = 0;
  s.hit = false;
  s.min_z = 1.0f;
  s.max_z = 0.0f;
}

void glFeedbackBuffer(Context& ctx, GLsizei size, GLenum type, GLfloat* buffer) {
  FeedbackState& f = ctx.render_mode.feedback;
  if (ctx.render_mode.mode == GL_FEEDBACK) return record_error(ctx, GL_INVALID_OPERATION);
  if (size < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (buffer == nullptr && size > 0) {
    f.size = 0;  // as Mesa
    return record_error(ctx, GL_INVALID_VALUE);
  }
  if (type != GL_2D && type != GL_3D && type != GL_3D_COLOR && type != GL_3D_COLOR_TEXTURE &&
      type != GL_4D_COLOR_TEXTURE)
    return record_error(ctx, GL_INVALID_ENUM);
  f.type = type;
  f.size = size;
  f.buffer = buffer;
  f.count = 0;
}

void glPassThrough(Context& ctx, GLfloat token) {
  if (ctx.render_mode.mode != GL_FEEDBACK) return;
  render_mode_flush_vertices(ctx);
  FeedbackState& f = ctx.render_mode.feedback;
  feedback_value(f, static_cast<float>(GL_PASS_THROUGH_TOKEN));
  feedback_value(f, token);
}

void glInitNames(Context& ctx) {
  if (!selecting(ctx)) return;
  render_mode_flush_vertices(ctx);
  SelectionState& s = ctx.render_mode.selection;
  write_hit_record(s);
  reset_name_stack(s);
}

void glLoadName(Context& ctx, GLuint name) {
  if (!selecting(ctx)) return;
  render_mode_flush_vertices(ctx);
  SelectionState& s = ctx.render_mode.selection;
  if (s.depth == 0) return record_error(ctx, GL_INVALID_OPERATION);
  write_hit_record(s);
  s.names[s.depth - 1] = name;
}

void glPushName(Context& ctx, GLuint name) {
  if (!selecting(ctx)) return;
  render_mode_flush_vertices(ctx);
  SelectionState& s = ctx.render_mode.selection;
  if (s.depth >= kMaxNameStackDepth) return record_error(ctx, GL_STACK_OVERFLOW);
  write_hit_record(s);
  s.names[s.depth++] = name;
}

void glPopName(Context& ctx) {
  if (!selecting(ctx)) return;
  render_mode_flush_vertices(ctx);
  SelectionState& s = ctx.render_mode.selection;
  if (s.depth == 0) return record_error(ctx, GL_STACK_UNDERFLOW);
  write_hit_record(s);
  --s.depth;
}

}  // namespace impl
}  // namespace glpt
