#include "rt_core/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <variant>

#include "rt_core/passes/gbuffer.hpp"
#include "rt_core/passes/path_tracer.hpp"
#include "rt_core/raster/raster_renderer.hpp"
#include "rt_core/scene/classify.hpp"
#include "rt_core/scene/classify_debug.hpp"
#include "rt_core/scene/classify_log.hpp"
#include "rt_core/scene/frame_signature.hpp"
#include "rt_core/scene/scene_builder.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {
namespace {

// Runs `body`, turning any exception into false + message (nothing may escape this API).
template <typename Body>
bool guarded(const char* what, std::string* error, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    if (error != nullptr) *error = std::string("glpt: ") + what + ": " + e.what();
  } catch (...) {
    if (error != nullptr) *error = std::string("glpt: ") + what + ": unknown error";
  }
  return false;
}

}  // namespace

class Renderer::Impl {
 public:
  Impl(RenderSettings settings, std::shared_ptr<VulkanDevice> device,
       std::unique_ptr<PathTracer> tracer)
      : settings_(settings),
        device_(device),
        raster_(std::move(device)),
        tracer_(std::move(tracer)) {
    if (!settings_.classify_log.empty()) {
      std::string error;
      log_ = std::make_unique<ClassifyLog>(settings_.classify_log, &error);
      if (!log_->is_open()) {
        std::fprintf(stderr, "glpt: %s\n", error.c_str());  // drawing goes on without it
        log_.reset();
      }
    }
  }

  RenderMode mode() const { return settings_.mode; }
  const std::string& device_name() const { return device_->name(); }
  RasterRenderer& raster() { return raster_; }
  VulkanDevice& device() const { return *device_; }
  void start_independent_frame(uint64_t frame_index, uint32_t history_window) {
    if (tracer_) tracer_->start_independent_frame(frame_index, history_window);
  }

  // Throws on failure (Renderer::execute turns that into false + message).
  bool execute(const rec::FrameRecord& record, DrawableBuffers& buffers,
               const rec::DrawableConfig& drawable, FrameStats& stats, const FrameEnd* end,
               std::vector<QuerySamples>* queries) {
    stats = FrameStats();
    // Submissions of a frame do not wait for each other (each pass's host work overlaps the
    // device work of the one before); the frame waits once, here at its end, also when it fails
    // half-way, so nothing pending outlives the call that submitted it.
    struct FrameEndWait {
      VulkanDevice& device;
      bool submitted_only;  // FrameEnd::present_later: the caller waits before presenting
      ~FrameEndWait() {
        if (submitted_only) return;
        try {
          device.wait_all();
        } catch (...) {  // a lost device: the next submission reports it
        }
      }
    };
    const uint64_t waits_before = device_->host_waits();
    classified_ = false;
    if (!drawable.framebuffer_object && (log_ || settings_.classify_debug ||
                                         (settings_.mode == RenderMode::kPathTraced && tracer_))) {
      const auto start = std::chrono::steady_clock::now();
      classify_frame(record, drawable, &identities_of(buffers), classification_);
      stats.classify_ms +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      classified_ = true;
      if (log_) log_->write(classification_);
      for (const CommandLabel& label : classification_.labels)
        if (label.kind != DrawKind::kNone) ++stats.kind_draws[static_cast<size_t>(label.kind)];
    }
    if (end != nullptr) {  // the frame ends with this record: what follows is the next frame
      identities_of(buffers).end_frame();
      if (log_) log_->end_frame();
    }
    // Only raster mode's frames return before they complete: the path tracer's passes keep
    // history and acceleration structures that the next frame rewrites.
    FrameEnd end_now;
    if (end != nullptr && end->present_later &&
        (settings_.mode != RenderMode::kRaster || drawable.framebuffer_object)) {
      end_now = *end;
      end_now.present_later = false;
      end = &end_now;
    }
    {
      const FrameEndWait frame_end{*device_, end != nullptr && end->present_later};
      if (classified_ && settings_.classify_debug) {
        tint_by_class(record, classification_, debug_record_);
        run_frame(debug_record_, buffers, drawable, stats, end, queries);
      } else {
        run_frame(record, buffers, drawable, stats, end, queries);
      }
    }
    stats.host_waits = static_cast<uint32_t>(device_->host_waits() - waits_before);
    raster_.end_frame(stats);
    if (tracer_) tracer_->finish_frame(stats);
    return true;
  }

 private:
  // Identities follow the draws of one drawable (another window's draws are other objects).
  // A few drawables are tracked; the least recently drawn to is forgotten first.
  DrawIdentities& identities_of(const DrawableBuffers& buffers) {
    ++identity_clock_;
    for (TrackedDrawable& t : identities_)
      if (t.buffers == &buffers) {
        t.last_used = identity_clock_;
        return t.identities;
      }
    if (identities_.size() >= kTrackedDrawables)
      identities_.erase(std::min_element(identities_.begin(), identities_.end(),
                                         [](const TrackedDrawable& a, const TrackedDrawable& b) {
                                           return a.last_used < b.last_used;
                                         }));
    // Each drawable's ids in a range of 2^40 of their own (a trillion draws each).
    const uint64_t first_id = (identity_ranges_++ << 40) + 1;
    identities_.push_back({&buffers, identity_clock_, DrawIdentities({}, first_id)});
    return identities_.back().identities;
  }

  // The draws of each class in scene_ (built from `record`) and its instances.
  void count_classes(const rec::FrameRecord& record, FrameStats& stats) const {
    for (size_t i = 0; i < record.commands.size() && i < scene_.classes.size(); ++i) {
      if (!std::holds_alternative<rec::Draw>(record.commands[i])) continue;
      const DrawClass cls = scene_.classes[i];
      if (cls == DrawClass::kShadow) continue;  // not drawn (kind_draws counts them)
      ++(cls == DrawClass::kTraced || cls == DrawClass::kViewmodel ||
                 cls == DrawClass::kSplitByAlpha
             ? stats.traced_draws
         : cls == DrawClass::kSky ? stats.sky_draws
                                  : stats.raster_draws);
    }
    stats.instances = static_cast<uint32_t>(scene_.scene.instances.size());
  }

  // One frame's passes, submitted in order; execute waits for them.
  void run_frame(const rec::FrameRecord& record, DrawableBuffers& buffers,
                 const rec::DrawableConfig& drawable, FrameStats& stats, const FrameEnd* end,
                 std::vector<QuerySamples>* queries) {
    // Draws into a framebuffer object make a texture the traced scene may sample: rasterized
    // as raster mode draws them, never traced, classified or made the main camera.
    if (settings_.mode == RenderMode::kRaster || !tracer_ || drawable.framebuffer_object) {
      raster_.execute(record, buffers, drawable, stats, nullptr, end, nullptr, queries);
      return;
    }
    // Path-traced mode (docs/architecture.md): the traced draws are rasterized into the
    // G-buffer in record order (after what precedes them), the trace pass lights the G-buffer into
    // the colour buffers, then the other draws are rasterized over the result.
    SceneOptions scene_options;
    scene_options.default_light = settings_.default_light;
    scene_options.classification = classified_ ? &classification_ : nullptr;
    scene_options.known_geometry = [this](uint64_t shape, uint64_t shading) {
      return tracer_->holds_geometry(shape, shading);
    };
    build_trace_scene(record, drawable, scene_, scene_options);
    count_classes(record, stats);
    if (!scene_.any_traced || drawable.width == 0 || drawable.height == 0) {
      // Nothing traced (e.g. the rest of a frame after a glReadPixels): raster mode. The
      // accumulation stays valid for the next frame with the same signature.
      raster_.execute(record, buffers, drawable, stats, nullptr, end, nullptr, queries);
      return;
    }
    try {
      glm::vec2 jitter =
          tracer_->begin_frame(FrameSignature(record, scene_.gbuffer_pass, drawable));
      gbuffer_.ensure(raster_.device(), drawable.width, drawable.height);
      // GLPT_REFERENCE repeats the G-buffer pass and the trace with new jitter until the frame
      // has the reference's samples; occlusion queries count the last pass only.
      for (bool last = false; !last;) {
        glm::vec2 next_jitter;
        FrameStats traced;
        const GBufferTargets targets = gbuffer_.targets(&scene_.traced, jitter);
        // Occlusion queries count the traced draws' samples here, where they are rasterized with
        // their own pipelines' coverage, depth and stencil tests (only their outputs differ), and
        // the other draws' in pass 3.
        const std::vector<QuerySamples> counted_before =
            queries != nullptr ? *queries : std::vector<QuerySamples>();
        raster_.execute(record, buffers, drawable, stats, &scene_.gbuffer_pass, nullptr, &targets,
                        queries, &scene_.split_by_alpha);
        // The colour buffers exist once the raster renderer has drawn into them.
        const TraceTargets trace_targets{
            &gbuffer_, &raster_.textures(), raster_.color_image(true).view(),
            raster_.color_image(!drawable.double_buffered).view(), &buffers};
        tracer_->trace(scene_.scene, trace_targets, traced);
        last = !tracer_->next_reference_pass(&next_jitter);
        if (!last && queries != nullptr) *queries = counted_before;  // the last pass counts
        jitter = next_jitter;
        // Every reference pass traces the same triangles: count them once.
        stats.triangles = 0;
        stats += traced;
      }
    } catch (...) {
      tracer_->forget_previous_frame();  // nothing about this frame's accumulation holds
      throw;
    }
    raster_.execute(record, buffers, drawable, stats, &scene_.after_trace, end, nullptr, queries,
                    &scene_.split_by_alpha);
  }

 public:
  // Every public method holds it: contexts of one share group may be current on several threads.
  std::mutex mutex;

 private:
  RenderSettings settings_;
  std::shared_ptr<VulkanDevice> device_;
  RasterRenderer raster_;
  std::unique_ptr<PathTracer> tracer_;  // null in raster mode or without ray queries
  SceneBuild scene_;
  GBuffer gbuffer_;
  struct TrackedDrawable {
    const DrawableBuffers* buffers;
    uint64_t last_used;
    DrawIdentities identities;
  };
  static constexpr size_t kTrackedDrawables = 8;
  std::vector<TrackedDrawable> identities_;
  uint64_t identity_clock_ = 0;
  uint64_t identity_ranges_ = 0;  // id ranges given to drawables so far
  FrameClassification classification_;
  bool classified_ = false;           // classification_ is this record's
  std::unique_ptr<ClassifyLog> log_;  // GLPT_CLASSIFY_LOG; null: off
  rec::FrameRecord debug_record_;     // GLPT_CLASSIFY_DEBUG: the record tinted by class
};

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

std::unique_ptr<Renderer> Renderer::create(const RenderSettings& settings, std::string* error,
                                           std::string* notice) {
  std::unique_ptr<Renderer> renderer;
  guarded("cannot create the Vulkan renderer", error, [&] {
    DeviceOptions options = DeviceOptions::from_environment(settings.validation);
    options.timestamps = settings.device_timing;
    std::shared_ptr<VulkanDevice> device = VulkanDevice::shared(options);
    RenderSettings effective = settings;
    std::unique_ptr<PathTracer> tracer;
    if (settings.mode == RenderMode::kPathTraced) {
      if (device->has_ray_query()) {
        tracer = PathTracer::create(device, settings, error);
        if (!tracer) return false;
      } else {
        // No ray queries: GL still draws, through raster mode, and says so once.
        effective.mode = RenderMode::kRaster;
        if (notice != nullptr)
          *notice = "glpt: " + device->name() + " has no ray queries (lacks " +
                    device->ray_query_missing() + "): drawing in raster mode. " +
                    vulkan_install_hint() + " (" + kDoctorHint + ")";
      }
    }
    renderer.reset(new Renderer(std::make_unique<Impl>(effective, device, std::move(tracer))));
    return true;
  });
  return renderer;
}

RenderMode Renderer::mode() const { return impl_->mode(); }
const std::string& Renderer::device_name() const { return impl_->device_name(); }

bool Renderer::execute(const rec::FrameRecord& record, DrawableBuffers& buffers,
                       const rec::DrawableConfig& drawable, FrameStats& stats, std::string* error,
                       const FrameEnd* end, std::vector<QuerySamples>* queries) {
  if (queries != nullptr) queries->clear();
  std::lock_guard lock(impl_->mutex);
  return guarded("render failed", error,
                 [&] { return impl_->execute(record, buffers, drawable, stats, end, queries); });
}

uint64_t Renderer::frame_ticket() const { return impl_->device().last_ticket(); }

void Renderer::wait_for_frame(uint64_t ticket) const {
  try {
    impl_->device().wait(ticket);
  } catch (...) {  // a lost device: the next execute reports it
  }
}

bool Renderer::read_color(DrawableBuffers& buffers, uint32_t buffer, int32_t x, int32_t y,
                          uint32_t width, uint32_t height, std::vector<uint8_t>& rgba,
                          std::string* error) {
  std::lock_guard lock(impl_->mutex);
  return guarded("read failed", error, [&] {
    return impl_->raster().read_color(buffers, buffer, x, y, width, height, rgba);
  });
}

bool Renderer::write_color(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                           const std::vector<uint8_t>& rgba, std::string* error) {
  std::lock_guard lock(impl_->mutex);
  return guarded("write failed", error, [&] {
    impl_->raster().write_front_color(buffers, drawable, rgba);
    return true;
  });
}

bool Renderer::write_depth(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                           const std::vector<float>& depth, std::string* error) {
  std::lock_guard lock(impl_->mutex);
  return guarded("write failed", error, [&] {
    impl_->raster().write_depth(buffers, drawable, depth);
    return true;
  });
}

bool Renderer::write_pixels(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                            const PixelWrite& pixels, std::string* error) {
  std::lock_guard lock(impl_->mutex);
  return guarded("write failed", error, [&] {
    impl_->raster().write_pixels(buffers, drawable, pixels);
    return true;
  });
}

bool Renderer::read_depth(DrawableBuffers& buffers, int32_t x, int32_t y, uint32_t width,
                          uint32_t height, std::vector<float>& depth, std::string* error) {
  std::lock_guard lock(impl_->mutex);
  return guarded("read failed", error,
                 [&] { return impl_->raster().read_depth(buffers, x, y, width, height, depth); });
}

bool Renderer::read_stencil(DrawableBuffers& buffers, int32_t x, int32_t y, uint32_t width,
                            uint32_t height, std::vector<uint8_t>& stencil, std::string* error) {
  std::lock_guard lock(impl_->mutex);
  return guarded("read failed", error, [&] {
    return impl_->raster().read_stencil(buffers, x, y, width, height, stencil);
  });
}

bool Renderer::swap_buffers(DrawableBuffers& buffers, std::string* error) {
  std::lock_guard lock(impl_->mutex);
  return guarded("swap failed", error, [&] {
    impl_->raster().swap_buffers(buffers);
    return true;
  });
}

void Renderer::start_independent_frame(uint64_t frame_index, uint32_t history_window) {
  std::lock_guard lock(impl_->mutex);
  impl_->start_independent_frame(frame_index, history_window);
}

uint64_t new_host_image_generation() {
  static std::atomic<uint64_t> next{1};  // an id allocator, process-wide like the device
  return next.fetch_add(1, std::memory_order_relaxed);
}

std::shared_ptr<DrawableBuffers> create_drawable_buffers() {
  return std::make_shared<DrawableBuffers>();
}

}  // namespace glpt::rt
