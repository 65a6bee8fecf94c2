#include "gl_shim/context.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "gl/gl_enums.h"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/frame/heap_tuning.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt {

constinit thread_local Context* t_current_context = nullptr;

Context::Context(const Context* shared)
    : unimplemented_calls(static_cast<size_t>(CommandId::kCount), 0),
      unimplemented_reported(static_cast<size_t>(CommandId::kCount), false) {
  if (shared != nullptr) {
    lists.store = shared->lists.store;
    buffers = shared->buffers;
    textures.store = shared->textures.store;
    framebuffers.store = shared->framebuffers.store;
    render_group = shared->render_group;
  }
}

Context::~Context() {
  if (t_current_context == this) t_current_context = nullptr;
  // Destroyed from an exit handler: the renderer's Vulkan objects are left to the process's end
  // (destroying pipelines frees JIT code through LLVM, which may be torn down already).
  if (output && rt::process_exiting()) static_cast<void>(output.release());
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

void set_current_context(Context* ctx) { t_current_context = ctx; }

void flush_before_release(Context& ctx) {
  // Frames the context swapped on the drawable it leaves are on screen before it draws
  // elsewhere, as with Mesa's synchronous swap (a program reading its windows after switching
  // contexts or windows sees them).
  if (ctx.target != nullptr) ctx.target->wait_presented();
  if (ctx.framebuffers.entered) {  // the object's drawing to its textures, then the window's
    leave_framebuffer(ctx);
    flush_before_release(ctx);
    enter_framebuffer(ctx);
    return;
  }
  if (ctx.target == nullptr) return;
  if (!ctx.render_frame_ends) {
    // glpt-replay's skipped frames: what this context holds and has recorded was drawn on this
    // drawable, and a later frame may build on it: it is rendered there before the context
    // leaves it (nothing is shown).
    if (ctx.skipped_frames.held() > 0 || !ctx.recorder.empty()) execute_record(ctx);
    return;
  }
  flush_bitmap_cache(ctx);
  if (ctx.recorder.empty()) return;  // (a front-buffer frame would otherwise present again)
  impl::glFinish(ctx);
}

void bind_target_and_make_current(Context& ctx, WindowTarget* target) {
  if (ctx.target != nullptr && ctx.target != target) flush_before_release(ctx);
  ctx.target = target;
  set_current_context(&ctx);
  if (target != nullptr) target->forget_size();  // (WindowTarget::known_size)
  uint32_t w = 0, h = 0;
  if (ctx.framebuffer.viewport_initialized || target == nullptr || !target->query_size(&w, &h))
    return;
  FramebufferState& fb = ctx.framebuffer;
  fb.viewport_width = static_cast<GLsizei>(w);
  fb.viewport_height = static_cast<GLsizei>(h);
  ctx.raster.ops.scissor_box = {0, 0, static_cast<int32_t>(w), static_cast<int32_t>(h)};
  fb.viewport_initialized = true;
  // GL 1.5 4.2.1, 4.3.2: the initial draw and read buffers are the back buffer when there is one,
  // else the front.
  ctx.drawable = target->config();
  const uint32_t buffer = ctx.drawable.double_buffered ? GL_BACK : GL_FRONT;
  ctx.raster.ops.draw_buffer = ctx.raster.ops.read_buffer = buffer;
}

void make_current_headless(Context& ctx, HeadlessTarget& target) {
  bind_target_and_make_current(ctx, &target);
}

namespace {

// A frame that is never swapped or read (a single-buffered program that never flushes) is
// executed once its record holds this many bytes of vertices.
constexpr size_t kMaxRecordVertexBytes = size_t{256} << 20;
// Likewise once its draws sample this many bytes of distinct texture contents: a program that
// replaces its texture at every draw would otherwise hold them all until the swap (Mesa draws at
// once and frees each texture with its object).
constexpr size_t kMaxRecordTextureBytes = size_t{256} << 20;

}  // namespace

bool ensure_output(Context& ctx) {
  if (render_target(ctx) == nullptr || ctx.renderer_unavailable) return false;
  if (ctx.output) return true;
  std::string error;
  ctx.output = FrameOutput::create(*ctx.render_group, &error);
  if (!ctx.output) {
    // Not retried by this context, and said once per process; the program keeps running, its
    // GL state answering, its frames showing the clear colour.
    report_once_per_process(error + "; frames show only the clear colour");
    ctx.renderer_unavailable = true;
    ctx.clear_fallback = std::make_unique<ClearFallback>();
    return false;
  }
  tune_heap_for_rendering();  // the process renders from now on (heap_tuning.hpp)
  return true;
}

rec::DrawableConfig current_drawable(Context& ctx) {
  WindowTarget* target = render_target(ctx);
  rec::DrawableConfig drawable = target->config();
  if (!target->known_size(&drawable.width, &drawable.height)) drawable.width = drawable.height = 0;
  return drawable;
}

namespace {

void start_new_record(Context& ctx) {
  ctx.recorder.clear();
  ctx.buffer_draws.record_cleared();
  ctx.recorder.record().query_at_start = ctx.queries.active_id();
  ctx.snapshots.record_cleared();
  ctx.recording_since.restart();
  // A frame ended between glBegin and glEnd (a swap there, as a replayed or careless program
  // may do): the open primitive's state id named the old record, so it is captured again into
  // the new one (state cannot change inside glBegin/glEnd but for the current attributes).
  if (ctx.assembly.inside) ctx.assembly.state = ctx.snapshots.capture(ctx, ctx.recorder.record());
}

// Renders a record of glpt-replay's skipped frames (DeferredFrames) on the current drawable;
// needs ensure_output.
DeferredFrames::Execute render_held(Context& ctx) {
  return [&ctx](const rec::FrameRecord& record, bool swap, uint64_t frame) {
    // Rendered as a whole replay renders that frame: from the same start, seeded by its index.
    ctx.output->renderer().start_independent_frame(frame, ctx.replay_history_window);
    std::vector<rt::QuerySamples> samples;
    const bool ok =
        ctx.output->execute(record, *ctx.target, current_drawable(ctx), 0.0, &samples, swap);
    count_query_samples(ctx.queries, samples);
    return ok;
  };
}

// The sealed record is about to be rendered: glpt-replay's held frames go first where it builds
// on them, and then this frame starts (or goes on) from the start a whole replay gives it. The
// frame starts here, when its first record renders, not when it begins: held frames before it
// must render on the history of the frames before them.
void render_held_before(Context& ctx, const rec::DrawableConfig& drawable, bool swap) {
  // Held frames are the window's: a framebuffer object's record does not build on them.
  if (ctx.framebuffers.entered) return;
  ctx.skipped_frames.before_render(ctx.recorder.record(), drawable, swap, render_held(ctx));
  if (ctx.replayed)
    ctx.output->renderer().start_independent_frame(ctx.replay_frame, ctx.replay_history_window);
}

}  // namespace

bool execute_record(Context& ctx) {
  if (rt::process_exiting()) {
    // Released or destroyed from an exit handler: nothing rendered now can be seen, and the
    // driver's compiler may already be torn down (rt::process_exiting).
    discard_record(ctx);
    return false;
  }
  if (!ensure_output(ctx)) {
    if (ctx.clear_fallback && ctx.target) {  // the record is consumed all the same
      ctx.recorder.seal();
      ctx.clear_fallback->consume(ctx.recorder.record());
      start_new_record(ctx);
    }
    return false;
  }
  const rec::DrawableConfig drawable = current_drawable(ctx);
  ctx.recorder.seal();
  render_held_before(ctx, drawable, /*swap=*/false);
  bool ok = true;
  std::vector<rt::QuerySamples> samples;
  if (ctx.framebuffers.entered && !ctx.recorder.empty())
    ctx.framebuffers.framebuffer->rendering->drawn = true;  // its textures take the result
  if (!ctx.recorder.empty() || drawable != ctx.output->drawable())
    ok = ctx.output->execute(ctx.recorder.record(), *render_target(ctx), drawable,
                             ctx.recording_since.elapsed_ms(), &samples);
  // A render that failed (device memory, a lost device) loses the commands' effect: GL's
  // error for "not enough memory left to execute the command" (GL 1.5 2.5), not silence.
  if (!ok) record_error(ctx, GL_OUT_OF_MEMORY);
  start_new_record(ctx);
  count_query_samples(ctx.queries, samples);
  return ok;
}

void discard_record(Context& ctx) {
  ctx.recorder.seal();
  start_new_record(ctx);
}

void note_frame_content(Context& ctx) {
  if (ctx.recorder.vertex_bytes() > kMaxRecordVertexBytes ||
      ctx.snapshots.texture_bytes() > kMaxRecordTextureBytes)
    execute_record(ctx);
}

namespace {

void end_window_frame(Context& ctx, bool swap);

}  // namespace

void end_frame(Context& ctx, bool swap) {
  // A swap (or a flush of the front buffer) while a framebuffer object is bound ends the window's
  // frame: what was drawn into the object goes to its textures first.
  if (ctx.framebuffers.entered) {
    leave_framebuffer(ctx);
    end_window_frame(ctx, swap);
    enter_framebuffer(ctx);
    return;
  }
  end_window_frame(ctx, swap);
}

namespace {

void end_window_frame(Context& ctx, bool swap) {
  // A swap sees the window's size now, and the next frame asks again (WindowTarget::known_size).
  if (ctx.target != nullptr) ctx.target->forget_size();
  struct ForgetAfter {
    WindowTarget* target;
    ~ForgetAfter() {
      if (target != nullptr) target->forget_size();
    }
  } forget_after{ctx.target};
  if (!ctx.render_frame_ends) {
    ctx.recorder.seal();
    if (ensure_output(ctx)) {
      const size_t bytes = ctx.recorder.vertex_bytes();
      ctx.skipped_frames.skip(std::move(ctx.recorder.record()), current_drawable(ctx), swap,
                              ctx.replay_frame, bytes, render_held(ctx));
    }
    start_new_record(ctx);
    return;
  }
  if (!ensure_output(ctx)) {
    if (ctx.clear_fallback && ctx.target) {
      ctx.recorder.seal();
      const rec::DrawableConfig drawable = current_drawable(ctx);
      std::lock_guard lock(ctx.target->mutex());  // presenting, as FrameOutput::end_frame does
      ctx.clear_fallback->end_frame(ctx.recorder.record(), drawable.width, drawable.height,
                                    ctx.target);
      start_new_record(ctx);
    }
    return;
  }
  ctx.recorder.seal();
  const rec::DrawableConfig drawable = current_drawable(ctx);
  render_held_before(ctx, drawable, swap);
  std::vector<rt::QuerySamples> samples;
  if (!ctx.output->end_frame(ctx.recorder.record(), drawable, ctx.recording_since.elapsed_ms(),
                             *ctx.target, swap, &samples))
    record_error(ctx, GL_OUT_OF_MEMORY);  // as in execute_record
  // Running totals, so a program killed mid-run (as screensavers are) still leaves them.
  if (ctx.output->stats_enabled()) {
    uint64_t unimplemented = 0;
    for (uint64_t n : ctx.unimplemented_calls) unimplemented += n;
    std::fprintf(stderr, "glpt: totals gl_errors=%llu unimplemented_calls=%llu\n",
                 static_cast<unsigned long long>(ctx.errors_recorded),
                 static_cast<unsigned long long>(unimplemented));
  }
  start_new_record(ctx);
  count_query_samples(ctx.queries, samples);
}

}  // namespace

}  // namespace glpt
