// glClear*, glViewport, glDepthRange, glScissor, glDrawBuffer/glReadBuffer, glPixelStore,
// glFlush, glFinish (GL 1.5 spec 2.11.1, 4.2, 4.3, 5.5); glReadPixels is in
// gl_shim/pixels/read_pixels.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/framebuffer_access.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

}  // namespace

bool read_framebuffer(Context& ctx, rec::PixelKind kind, uint32_t buffer, int32_t x, int32_t y,
                      uint32_t width, uint32_t height, FramebufferPixels& out) {
  out = FramebufferPixels();
  if (kind == rec::PixelKind::kColor &&
      read_other_attachment(ctx, buffer, x, y, width, height, out))
    return true;
  if (!execute_record(ctx) || !ctx.output) {
    // No renderer: the clear colour stands in for the buffers (clear_fallback.hpp).
    uint32_t w = 0, h = 0;
    WindowTarget* target = render_target(ctx);
    if (!ctx.clear_fallback || target == nullptr || !target->query_size(&w, &h)) return false;
    ctx.clear_fallback->read(kind, x, y, width, height, w, h, out);
    return true;
  }
  rt::Renderer& renderer = ctx.output->renderer();
  const rec::DrawableConfig& drawable = ctx.output->drawable();
  WindowTarget& target = *render_target(ctx);
  std::lock_guard lock(target.mutex());
  rt::DrawableBuffers& buffers = target.buffers();
  std::string error;
  const size_t n = size_t{width} * height;
  bool ok = false;
  switch (kind) {
    case rec::PixelKind::kColor: {
      std::vector<uint8_t> rgba;
      ok = renderer.read_color(buffers, buffer, x, y, width, height, rgba, &error);
      if (ok) {
        out.color.resize(n);
        for (size_t i = 0; i < n; ++i)
          out.color[i] =
              glm::vec4(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]) / 255.0f;
      }
      break;
    }
    case rec::PixelKind::kDepth:
      ok = renderer.read_depth(buffers, x, y, width, height, out.depth, &error);
      break;
    case rec::PixelKind::kStencil: {
      std::vector<uint8_t> stencil;
      ok = renderer.read_stencil(buffers, x, y, width, height, stencil, &error);
      if (ok) out.stencil.assign(stencil.begin(), stencil.end());
      break;
    }
  }
  if (!ok) {
    if (!error.empty()) std::fprintf(stderr, "%s\n", error.c_str());
    out = FramebufferPixels();
    return false;
  }
  out.width = width;
  out.height = height;
  mark_inside_drawable(out, x, y, drawable.width, drawable.height);
  if (kind == rec::PixelKind::kColor) show_stored_components(ctx, buffer, out);
  return true;
}

void mark_inside_drawable(FramebufferPixels& out, int32_t x, int32_t y, uint32_t drawable_width,
                          uint32_t drawable_height) {
  out.inside.assign(size_t{out.width} * out.height, 0);
  for (uint32_t j = 0; j < out.height; ++j)
    for (uint32_t i = 0; i < out.width; ++i) {
      const int64_t sx = int64_t{x} + i, sy = int64_t{y} + j;
      out.inside[size_t{j} * out.width + i] =
          sx >= 0 && sy >= 0 && sx < drawable_width && sy < drawable_height ? 1 : 0;
    }
}

namespace impl {

void glClearColor(Context& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  ctx.framebuffer.clear_color = {clamp01(r), clamp01(g), clamp01(b), clamp01(a)};
}
void glClearDepth(Context& ctx, GLdouble depth) {
  ctx.framebuffer.clear_depth = std::clamp(depth, 0.0, 1.0);
}
void glClearStencil(Context& ctx, GLint s) { ctx.framebuffer.clear_stencil = s; }

void glClear(Context& ctx, GLbitfield mask) {
  constexpr GLbitfield kValid =
      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
  if (mask & ~kValid) return record_error(ctx, GL_INVALID_VALUE);
  if (const GLenum e = framebuffer_error(ctx); e != GL_NO_ERROR) return record_error(ctx, e);
  if (mask == 0 || ctx.render_mode.mode != GL_RENDER) return;  // (Mesa clears only in GL_RENDER)
  const FramebufferState& fb = ctx.framebuffer;
  rec::Clear clear;
  clear.state = ctx.snapshots.capture(ctx, ctx.recorder.record());
  clear.mask = mask;
  clear.color = fb.clear_color;
  clear.depth = fb.clear_depth;
  clear.stencil = fb.clear_stencil;
  clear.accum = fb.clear_accum;
  ctx.recorder.add(clear);
}

void glViewport(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  constexpr GLsizei kMaxViewport = 16384;  // GL_MAX_VIEWPORT_DIMS
  // Programs answer a resize with glViewport: the window's size is asked again
  // (WindowTarget::known_size), as Mesa re-validates its drawable here.
  if (ctx.target != nullptr) ctx.target->forget_size();
  ctx.framebuffer.viewport_x = x;
  ctx.framebuffer.viewport_y = y;
  ctx.framebuffer.viewport_width = std::min(width, kMaxViewport);
  ctx.framebuffer.viewport_height = std::min(height, kMaxViewport);
  ctx.framebuffer.viewport_initialized = true;
}

// GL clamps the range to [0, 1]; a NaN becomes 0, as Mesa saturates it (checked against OSMesa:
// glDepthRange(NaN, Inf) reads back 0 1), so no NaN reaches the viewport.
static GLdouble saturate_depth(GLdouble v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }

void glDepthRange(Context& ctx, GLdouble n, GLdouble f) {
  ctx.framebuffer.depth_near = saturate_depth(n);
  ctx.framebuffer.depth_far = saturate_depth(f);
}

void glScissor(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  ctx.raster.ops.scissor_box = {x, y, width, height};
}

void glDepthFunc(Context& ctx, GLenum func) {
  if (func < GL_NEVER || func > GL_ALWAYS) return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.ops.depth_func = func;
}

void glCullFace(Context& ctx, GLenum mode) {
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK)
    return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.primitive.cull_face_mode = mode;
}

void glFrontFace(Context& ctx, GLenum mode) {
  if (mode != GL_CW && mode != GL_CCW) return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.primitive.front_face = mode;
}

namespace {
bool valid_color_buffer(GLenum buf) {
  switch (buf) {
    case GL_NONE:
    case GL_FRONT_LEFT:
    case GL_FRONT_RIGHT:
    case GL_BACK_LEFT:
    case GL_BACK_RIGHT:
    case GL_FRONT:
    case GL_BACK:
    case GL_LEFT:
    case GL_RIGHT:
    case GL_FRONT_AND_BACK:
      return true;
    default:
      return false;
  }
}

// glpt's drawables are never stereo: the right buffers do not exist (GL 1.5 4.2.1 and 4.3.2:
// naming only buffers that do not exist is GL_INVALID_OPERATION, as in Mesa).
bool right_buffer_only(GLenum buf) {
  return buf == GL_RIGHT || buf == GL_FRONT_RIGHT || buf == GL_BACK_RIGHT;
}
}  // namespace

namespace {
// A framebuffer object's draw and read buffers name its colour attachments (or GL_NONE); the
// window's buffers are GL_INVALID_OPERATION there, as in Mesa.
bool framebuffer_object_buffer(Context& ctx, GLenum buf) {
  if (buf == GL_NONE ||
      (buf >= GL_COLOR_ATTACHMENT0_EXT && buf < GL_COLOR_ATTACHMENT0_EXT + kMaxColorAttachments))
    return true;
  record_error(ctx, valid_color_buffer(buf) ||
                            (buf >= GL_COLOR_ATTACHMENT0_EXT && buf <= GL_COLOR_ATTACHMENT15_EXT)
                        ? GL_INVALID_OPERATION
                        : GL_INVALID_ENUM);
  return false;
}
}  // namespace

void glDrawBuffer(Context& ctx, GLenum buf) {
  if (ctx.framebuffers.entered) {
    if (!framebuffer_object_buffer(ctx, buf) || buf == ctx.raster.ops.draw_buffer) return;
    // The target holds the drawn attachment's image: the one drawn so far goes back to its
    // texture, the newly named one is loaded.
    leave_framebuffer(ctx);
    ctx.framebuffers.framebuffer->rendering->parked.draw_buffer = buf;
    enter_framebuffer(ctx);
    return;
  }
  if (!valid_color_buffer(buf)) return record_error(ctx, GL_INVALID_ENUM);
  if (right_buffer_only(buf)) return record_error(ctx, GL_INVALID_OPERATION);
  ctx.raster.ops.draw_buffer = buf;
}

void glReadBuffer(Context& ctx, GLenum buf) {
  const ReadFramebufferScope read(ctx);  // the read framebuffer's read buffer
  if (ctx.framebuffers.entered) {
    // Reads come from the target, which holds the drawn attachment.
    if (framebuffer_object_buffer(ctx, buf)) ctx.raster.ops.read_buffer = buf;
    return;
  }
  if (!valid_color_buffer(buf) || buf == GL_NONE || buf == GL_FRONT_AND_BACK)
    return record_error(ctx, GL_INVALID_ENUM);
  if (right_buffer_only(buf)) return record_error(ctx, GL_INVALID_OPERATION);
  ctx.raster.ops.read_buffer = buf;
}

void glPixelStorei(Context& ctx, GLenum pname, GLint param) {
  FramebufferState& fb = ctx.framebuffer;
  const bool pack = pname >= GL_PACK_SWAP_BYTES && pname <= GL_PACK_ALIGNMENT;
  PixelStoreModes& m =
      pack || pname == GL_PACK_SKIP_IMAGES || pname == GL_PACK_IMAGE_HEIGHT ? fb.pack : fb.unpack;
  switch (pname) {
    case GL_PACK_SWAP_BYTES:
    case GL_UNPACK_SWAP_BYTES:
      m.swap_bytes = param != 0;
      return;
    case GL_PACK_LSB_FIRST:
    case GL_UNPACK_LSB_FIRST:
      m.lsb_first = param != 0;
      return;
    case GL_PACK_ALIGNMENT:
    case GL_UNPACK_ALIGNMENT:
      if (param != 1 && param != 2 && param != 4 && param != 8)
        return record_error(ctx, GL_INVALID_VALUE);
      m.alignment = param;
      return;
    default:
      break;
  }
  if (param < 0) return record_error(ctx, GL_INVALID_VALUE);
  switch (pname) {
    case GL_PACK_ROW_LENGTH:
    case GL_UNPACK_ROW_LENGTH:
      m.row_length = param;
      return;
    case GL_PACK_SKIP_ROWS:
    case GL_UNPACK_SKIP_ROWS:
      m.skip_rows = param;
      return;
    case GL_PACK_SKIP_PIXELS:
    case GL_UNPACK_SKIP_PIXELS:
      m.skip_pixels = param;
      return;
    case GL_PACK_IMAGE_HEIGHT:
    case GL_UNPACK_IMAGE_HEIGHT:
      m.image_height = param;
      return;
    case GL_PACK_SKIP_IMAGES:
    case GL_UNPACK_SKIP_IMAGES:
      m.skip_images = param;
      return;
    default:
      record_error(ctx, GL_INVALID_ENUM);
  }
}

void glPixelStoref(Context& ctx, GLenum pname, GLfloat param) {
  if (!std::isfinite(param)) return record_error(ctx, GL_INVALID_VALUE);
  glPixelStorei(ctx, pname, static_cast<GLint>(std::lround(param)));
}

namespace {

// glFlush/glFinish end a frame when what was drawn goes to the front buffer (a single-buffered
// drawable, or glDrawBuffer(GL_FRONT)): the window shows the front buffer, and this is the only
// point where a program drawing there says its image is complete.
bool draws_to_front(const Context& ctx) {
  if (ctx.framebuffers.entered) return false;  // a framebuffer object's drawing ends no frame
  const uint32_t b = ctx.raster.ops.draw_buffer;
  return !ctx.drawable.double_buffered || b == GL_FRONT || b == GL_FRONT_LEFT || b == GL_LEFT ||
         b == GL_FRONT_AND_BACK;
}

}  // namespace

void glFlush(Context& ctx) {
  flush_bitmap_cache(ctx);  // as Mesa's glFlush does
  if (draws_to_front(ctx)) end_frame(ctx, /*swap=*/false);
}

void glFinish(Context& ctx) {
  // Finishing means the recorded commands are executed, and a swapped frame still being shown
  // by the window's presenting thread is on screen (later X requests of the program see it).
  if (draws_to_front(ctx))
    end_frame(ctx, /*swap=*/false);
  else if (!ctx.replayed)  // a replay (glpt-replay) has nothing to wait for
    execute_record(ctx);
  if (ctx.target != nullptr) ctx.target->wait_presented();
}

}  // namespace impl
}  // namespace glpt
