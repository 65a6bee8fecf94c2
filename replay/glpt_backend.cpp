// Backend "glpt": glpt's GL front end linked into the replayer (the static library the unit
// tests use), drawing to HeadlessTargets. Entry points are found in the front end's own
// generated name table, so no second libGL is loaded.
#include <map>

#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "replay/backend.hpp"

namespace glpt::replay {
namespace {

class GlptBackend final : public Backend {
 public:
  GlptBackend() {
    size_t count = 0;
    const GlProcEntry* table = gl_proc_table(&count);
    for (size_t i = 0; i < count; ++i) procs_[table[i].name] = table[i].entry;
  }
  ~GlptBackend() override {
    set_current_context(nullptr);
    contexts_.clear();
  }

  const char* name() const override { return "glpt"; }

  GlProc resolve(const char* name) override {
    // Every exported command, implemented or not: calling an unimplemented one is how glpt
    // counts it.
    const auto it = procs_.find(name);
    return it != procs_.end() ? reinterpret_cast<GlProc>(it->second) : nullptr;
  }

  ContextHandle create_context(ContextHandle share, std::string* error) override {
    const Context* shared = static_cast<const Context*>(share);
    auto context = std::make_unique<Context>(shared);
    // The renderer now rather than at the first frame: a missing Vulkan device is a clear error
    // at the start, and frames can be seeded before they render.
    context->output = FrameOutput::create(*context->render_group, error);
    if (!context->output) return nullptr;
    context->replayed = true;
    Context* handle = context.get();
    contexts_.push_back(std::move(context));
    return handle;
  }

  void destroy_context(ContextHandle handle) override {
    for (auto it = contexts_.begin(); it != contexts_.end(); ++it) {
      if (it->get() != handle) continue;
      add_unimplemented(**it);
      if (current_context() == it->get()) set_current_context(nullptr);
      contexts_.erase(it);
      return;
    }
  }

  bool make_current(ContextHandle handle, uint64_t surface, uint32_t width, uint32_t height,
                    bool double_buffered, std::string* /*error*/) override {
    // The context losing its current status is flushed, as GLX and EGL do.
    if (Context* old = current_context(); old != nullptr && old != handle)
      flush_before_release(*old);
    if (handle == nullptr) {
      set_current_context(nullptr);
      return true;
    }
    std::unique_ptr<HeadlessTarget>& target = surfaces_[surface];
    if (!target) {
      rec::DrawableConfig config;
      config.double_buffered = double_buffered;
      target = std::make_unique<HeadlessTarget>(width, height, config);
    }
    bind_target_and_make_current(*static_cast<Context*>(handle), target.get());
    return true;
  }

  bool current_size(uint32_t* width, uint32_t* height) override {
    const Context* ctx = current_context();
    return ctx != nullptr && ctx->target != nullptr && ctx->target->query_size(width, height);
  }

  void resize_current(uint32_t width, uint32_t height) override {
    Context* ctx = current_context();
    if (ctx == nullptr || ctx->target == nullptr) return;
    for (auto& [id, target] : surfaces_)
      if (target.get() == ctx->target) target->resize(width, height);
  }

  void begin_frame(uint64_t frame_index, bool render) override {
    Context* ctx = current_context();
    if (ctx == nullptr) return;
    // Skipped frames are held unrendered (gl_shim/frame/deferred_frames.hpp) from their start:
    // their glFinish, glReadPixels and frame end render nothing unless a later frame needs it.
    ctx->render_frame_ends = render;
    ctx->replay_frame = frame_index;
    ctx->replay_history_window = history_window_;
  }

  void set_history_window(uint32_t frames) override { history_window_ = frames; }

  bool end_frame(bool swap, GlProc flush, bool render, FrameImage* image,
                 std::string* /*error*/) override {
    Context* ctx = current_context();
    if (ctx == nullptr || ctx->target == nullptr) return true;
    HeadlessTarget* target = nullptr;
    for (auto& [id, surface] : surfaces_)
      if (surface.get() == ctx->target) target = surface.get();
    const uint64_t presented = target ? target->presented_frames() : 0;
    ctx->render_frame_ends = render;
    if (swap)
      glpt::end_frame(*ctx, /*swap=*/true);
    else if (flush != nullptr)
      flush();
    if (render && target != nullptr && target->presented_frames() != presented && image) {
      ctx->target->query_size(&image->width, &image->height);
      image->rgba = target->presented();
      if (image->rgba.size() != size_t{image->width} * image->height * 4) image->rgba.clear();
      for (size_t i = 3; i < image->rgba.size(); i += 4) image->rgba[i] = 255;
      if (ctx->output) {
        const rt::FrameStats& s = ctx->output->last_frame_stats();
        last_render_ms_ = s.upload_ms + s.raster_ms + s.blas_ms + s.tlas_ms + s.trace_ms +
                          s.denoise_ms + s.composite_ms + s.taa_ms + s.readback_ms;
      }
    }
    return true;
  }

  std::vector<std::pair<std::string, uint64_t>> unimplemented_calls() const override {
    std::map<std::string, uint64_t> calls = unimplemented_;
    for (const auto& context : contexts_) count_unimplemented(*context, calls);
    return {calls.begin(), calls.end()};
  }

  double last_render_ms() const override { return last_render_ms_; }

 private:
  static void count_unimplemented(const Context& ctx, std::map<std::string, uint64_t>& calls) {
    for (size_t i = 0; i < ctx.unimplemented_calls.size(); ++i)
      if (ctx.unimplemented_calls[i] != 0)
        calls[command_name(static_cast<CommandId>(i))] += ctx.unimplemented_calls[i];
  }
  void add_unimplemented(const Context& ctx) { count_unimplemented(ctx, unimplemented_); }

  std::map<std::string, GlProc, std::less<>> procs_;
  std::vector<std::unique_ptr<Context>> contexts_;
  std::map<uint64_t, std::unique_ptr<HeadlessTarget>> surfaces_;
  std::map<std::string, uint64_t> unimplemented_;
  double last_render_ms_ = 0;
  uint32_t history_window_ = 1;
};

}  // namespace

std::unique_ptr<Backend> create_glpt_backend(std::string* /*error*/) {
  return std::make_unique<GlptBackend>();
}

}  // namespace glpt::replay
