#include "gl_shim/frame/frame_output.hpp"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "common/image_io.hpp"

namespace glpt {
namespace {}  // namespace

OutputSettings OutputSettings::from_environment() {
  OutputSettings s;
  if (const char* dir = std::getenv("GLPT_OUTPUT"); dir && *dir) s.png_dir = dir;
  if (const char* every = std::getenv("GLPT_OUTPUT_EVERY"); every && *every) {
    char* end = nullptr;
    const long n = std::strtol(every, &end, 10);
    if (*end == '\0' && n >= 1 && n <= 1000000)
      s.png_every = static_cast<uint32_t>(n);
    else
      std::fprintf(stderr, "glpt: ignoring GLPT_OUTPUT_EVERY=%s (want a whole number >= 1)\n",
                   every);
  }
  if (const char* stats = std::getenv("GLPT_STATS"); stats && *stats && *stats != '0')
    s.stats = true;
  return s;
}

std::unique_ptr<FrameOutput> FrameOutput::create(std::string* error) {
  auto renderer = rt::Renderer::create(rt::RenderSettings::from_environment(), error);
  if (!renderer) return nullptr;
  OutputSettings settings = OutputSettings::from_environment();
  if (!settings.png_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(settings.png_dir, ec);
    if (ec)
      std::fprintf(stderr, "glpt: cannot create GLPT_OUTPUT directory %s: %s\n",
                   settings.png_dir.c_str(), ec.message().c_str());
  }
  return std::unique_ptr<FrameOutput>(new FrameOutput(std::move(renderer), std::move(settings)));
}

FrameOutput::FrameOutput(std::unique_ptr<rt::Renderer> renderer, OutputSettings settings)
    : renderer_(std::move(renderer)), settings_(std::move(settings)) {}

bool FrameOutput::render(const rt::Frame& frame, double capture_ms) {
  std::string error;
  last_stats_ = {};
  last_capture_ms_ = capture_ms;
  if (!renderer_->render(frame, image_, last_stats_, &error)) {
    if (!render_failure_reported_) std::fprintf(stderr, "%s\n", error.c_str());
    render_failure_reported_ = true;
    return false;
  }
  width_ = frame.width;
  height_ = frame.height;
  return true;
}

void FrameOutput::swap(WindowTarget* target) {
  const Stopwatch present_timer;
  const double frame_ms = since_last_swap_.elapsed_ms();
  if (target && width_ > 0 && height_ > 0) target->present(image_.data(), width_, height_);
  const double present_ms = present_timer.elapsed_ms();

  if (!settings_.png_dir.empty() && frame_index_ % settings_.png_every == 0 && width_ > 0) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%06" PRIu64 ".png", frame_index_);
    // The PNG shows what the window shows: opaque. (glReadPixels still returns GL's alpha.)
    png_scratch_ = image_;
    for (size_t i = 3; i < png_scratch_.size(); i += 4) png_scratch_[i] = 255;
    std::string error;
    if (!write_png_rgba8(settings_.png_dir + "/" + name, width_, height_, png_scratch_.data(), true,
                         &error))
      std::fprintf(stderr, "glpt: %s\n", error.c_str());
  }
  if (settings_.stats) {
    const rt::FrameStats& s = last_stats_;
    const double trace_s = s.trace_ms / 1000.0;
    std::fprintf(stderr,
                 "glpt: frame=%" PRIu64
                 " size=%ux%u frame_ms=%.2f capture_ms=%.2f upload_ms=%.2f "
                 "blas_ms=%.2f tlas_ms=%.2f trace_ms=%.2f readback_ms=%.2f present_ms=%.2f "
                 "total_ms=%.2f triangles=%" PRIu64 " rays=%" PRIu64
                 " mrays_per_s=%.3f "
                 "blas_builds=%u blas_reused=%u spp=%u\n",
                 frame_index_, width_, height_, frame_ms, last_capture_ms_, s.upload_ms, s.blas_ms,
                 s.tlas_ms, s.trace_ms, s.readback_ms, present_ms,
                 last_capture_ms_ + s.upload_ms + s.blas_ms + s.tlas_ms + s.trace_ms +
                     s.readback_ms + present_ms,
                 s.triangles, s.rays, trace_s > 0 ? s.rays / trace_s / 1e6 : 0.0, s.blas_builds,
                 s.blas_reused, s.accumulated_samples);
  }
  ++frame_index_;
  since_last_swap_.restart();
}

}  // namespace glpt
