#include "gl_shim/context.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "common/stopwatch.hpp"
#include "gl/gl_enums.h"
#include "gl_shim/frame/headless_target.hpp"

namespace glpt {
namespace {

// The one piece of global mutable state glpt has: GL's current context, per thread.
thread_local Context* t_current = nullptr;

}  // namespace

Context::Context(const Context* shared)
    : unimplemented_calls(static_cast<size_t>(CommandId::kCount), 0),
      unimplemented_reported(static_cast<size_t>(CommandId::kCount), false) {
  if (shared != nullptr) {
    lists.store = shared->lists.store;
    textures.store = shared->textures.store;
  }
}

Context::~Context() {
  if (t_current == this) t_current = nullptr;
  if (std::getenv("GLPT_STATS") == nullptr) return;
  uint64_t total = 0;
  for (size_t i = 0; i < unimplemented_calls.size(); ++i) {
    if (unimplemented_calls[i] == 0) continue;
    total += unimplemented_calls[i];
    std::fprintf(stderr, "glpt: unimplemented %s called %llu times\n",
                 command_name(static_cast<CommandId>(i)),
                 static_cast<unsigned long long>(unimplemented_calls[i]));
  }
  if (total > 0 || not_compilable_calls > 0)
    std::fprintf(
        stderr,
        "glpt: %llu calls to unimplemented commands, %llu commands not compiled into lists\n",
        static_cast<unsigned long long>(total),
        static_cast<unsigned long long>(not_compilable_calls));
}

bool Context::list_executes_while_compiling() const {
  return lists.compiling_mode == GL_COMPILE_AND_EXECUTE;
}

Context* current_context() { return t_current; }
void set_current_context(Context* ctx) { t_current = ctx; }

void bind_target_and_make_current(Context& ctx, WindowTarget* target) {
  ctx.target = target;
  set_current_context(&ctx);
  uint32_t w = 0, h = 0;
  if (ctx.framebuffer.viewport_initialized || target == nullptr || !target->query_size(&w, &h))
    return;
  FramebufferState& fb = ctx.framebuffer;
  fb.viewport_width = static_cast<GLsizei>(w);
  fb.viewport_height = static_cast<GLsizei>(h);
  ctx.raster.ops.scissor_box = {0, 0, static_cast<int32_t>(w), static_cast<int32_t>(h)};
  fb.viewport_initialized = true;
}

void make_current_headless(Context& ctx, HeadlessTarget& target) {
  bind_target_and_make_current(ctx, &target);
}

bool render_pending_frame(Context& ctx) {
  if (ctx.target == nullptr || ctx.renderer_unavailable) return false;
  if (!ctx.frame_dirty && ctx.output) return true;
  const Stopwatch capture_timer;
  if (!ctx.output) {
    std::string error;
    ctx.output = FrameOutput::create(&error);
    if (!ctx.output) {
      // Reported once per context (make-current does not retry it); the program keeps
      // running, showing nothing.
      std::fprintf(stderr, "%s\n", error.c_str());  // the message names glpt itself
      ctx.renderer_unavailable = true;
      return false;
    }
  }
  uint32_t width = 0, height = 0;
  if (!ctx.target->query_size(&width, &height) || width == 0 || height == 0) return false;
  rt::Frame& frame = ctx.pending;
  frame.width = width;
  frame.height = height;
  frame.viewport = {ctx.framebuffer.viewport_x, ctx.framebuffer.viewport_y,
                    static_cast<uint32_t>(std::max(ctx.framebuffer.viewport_width, 0)),
                    static_cast<uint32_t>(std::max(ctx.framebuffer.viewport_height, 0))};
  frame.instances = ctx.capture.instances();
  const double capture_ms = capture_timer.elapsed_ms();
  const bool ok = ctx.output->render(frame, capture_ms);
  ctx.frame_dirty = false;
  return ok;
}

}  // namespace glpt
