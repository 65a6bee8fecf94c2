#include "gl_shim/frame/frame_output.hpp"

#include <malloc.h>
#include <unistd.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "common/image_io.hpp"
#include "rt_core/scene/classify.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt {
namespace {

// "static:12,overlay:3": the frame's draws per class (none: "-").
std::string kind_counts(const rt::FrameStats& s) {
  std::string out;
  for (size_t k = 1; k < s.kind_draws.size(); ++k) {
    if (s.kind_draws[k] == 0) continue;
    if (!out.empty()) out += ',';
    out += rt::draw_kind_name(static_cast<rt::DrawKind>(k));
    out += ':' + std::to_string(s.kind_draws[k]);
  }
  return out.empty() ? "-" : out;
}

// The process's resident memory (VmRSS) in KiB, 0 if unknown: GLPT_STATS' rss_kb=, which the
// soak (bench/soak.sh) follows over 10,000 frames.
uint64_t resident_kilobytes() {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  if (statm == nullptr) return 0;
  unsigned long long size_pages = 0, resident_pages = 0;
  const int n = std::fscanf(statm, "%llu %llu", &size_pages, &resident_pages);
  std::fclose(statm);
  if (n != 2) return 0;
  return resident_pages * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE)) / 1024;
}

// The C heap (glibc's malloc, every thread's arena): bytes the program holds and bytes malloc
// keeps free. GLPT_STATS' heap_kb= and heap_free_kb=: with rss_kb they tell memory the process
// uses from memory its allocator keeps (fragmentation) and from memory outside malloc (mapped
// device memory, JIT code). mallinfo2 walks the arenas' free lists: only when stats are on.
struct HeapUse {
  uint64_t in_use_kb = 0, free_kb = 0;
};
HeapUse heap_use() {
  HeapUse h;
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  const struct mallinfo2 m = ::mallinfo2();
  h.in_use_kb = (m.uordblks + m.hblkhd) / 1024;
  h.free_kb = m.fordblks / 1024;
#endif
  return h;
}

}  // namespace

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
  if (const char* file = std::getenv("GLPT_STATS_FILE"); file && *file) {
    s.stats = true;
    s.stats_file = file;
  }
  if (const char* present = std::getenv("GLPT_PRESENT"); present && *present) {
    if (std::strcmp(present, "sync") == 0)
      s.present_later = false;
    else if (std::strcmp(present, "later") != 0)
      std::fprintf(stderr, "glpt: ignoring GLPT_PRESENT=%s (want sync or later)\n", present);
  }
  return s;
}

void report_once_per_process(const std::string& message, const std::string& key) {
  // Process-wide by nature, like the device and the output directory the messages are about.
  static std::mutex mutex;
  static std::set<std::string> said;
  std::lock_guard lock(mutex);
  if (said.insert(key.empty() ? message : key).second)
    std::fprintf(stderr, "%s\n", message.c_str());
}

void create_png_directory(OutputSettings& settings) {
  if (settings.png_dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(settings.png_dir, ec);
  if (!ec) return;
  report_once_per_process("glpt: cannot create GLPT_OUTPUT directory " + settings.png_dir + ": " +
                          ec.message() + "; writing no PNGs");
  settings.png_dir.clear();
}

void write_frame_png(const OutputSettings& settings, PngStream& stream, uint64_t frame_index,
                     uint32_t width, uint32_t height, std::vector<uint8_t>& rgba,
                     bool* failure_reported) {
  const std::string name = stream.file_name(frame_index);
  // The PNG shows what the window shows: opaque. (glReadPixels still returns GL's alpha.)
  for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  std::string error;
  if (!write_png_rgba8(settings.png_dir + "/" + name, width, height, rgba.data(), true, &error) &&
      !*failure_reported) {
    // Once per context here, once per process for the directory (every context fails alike).
    report_once_per_process("glpt: GLPT_OUTPUT: " + error + " (reported once)",
                            "png " + settings.png_dir);
    *failure_reported = true;
  }
}

std::unique_ptr<FrameOutput> FrameOutput::create(RenderGroup& group, std::string* error) {
  std::string notice;
  std::shared_ptr<rt::Renderer> renderer = group.renderer(error, &notice);
  if (!renderer) return nullptr;
  if (!notice.empty()) report_once_per_process(notice);
  OutputSettings settings = OutputSettings::from_environment();
  create_png_directory(settings);
  return std::unique_ptr<FrameOutput>(new FrameOutput(std::move(renderer), std::move(settings)));
}

namespace {

// The frame's rows (bottom to top, `pitch` bytes apart) into the image, top to bottom.
void copy_rows_flipped(const uint8_t* rows, size_t pitch, const rt::HostImage& image) {
  const size_t row_bytes = size_t{image.width} * 4;
  for (uint32_t y = 0; y < image.height; ++y)
    std::memcpy(image.pixels + size_t{image.height - 1 - y} * row_bytes, rows + y * pitch,
                row_bytes);
}

// Reverses the order of the image's rows in place.
void flip_rows(const rt::HostImage& image) {
  const size_t row_bytes = size_t{image.width} * 4;
  std::vector<uint8_t> row(row_bytes);
  for (uint32_t top = 0, bottom = image.height - 1; top < bottom; ++top, --bottom) {
    uint8_t* a = image.pixels + top * row_bytes;
    uint8_t* b = image.pixels + bottom * row_bytes;
    std::memcpy(row.data(), a, row_bytes);
    std::memcpy(a, b, row_bytes);
    std::memcpy(b, row.data(), row_bytes);
  }
}

}  // namespace

FrameOutput::FrameOutput(std::shared_ptr<rt::Renderer> renderer, OutputSettings settings)
    : renderer_(std::move(renderer)), settings_(std::move(settings)) {}

void FrameOutput::report_failure(const std::string& error) {
  if (!failure_reported_) std::fprintf(stderr, "%s\n", error.c_str());
  failure_reported_ = true;
}

bool FrameOutput::execute(const rec::FrameRecord& record, WindowTarget& target,
                          const rec::DrawableConfig& drawable, double record_ms,
                          std::vector<rt::QuerySamples>* queries, bool swap) {
  std::string error;
  rt::FrameStats stats;
  drawable_ = drawable;
  record_ms_ += record_ms;
  std::lock_guard lock(target.mutex());
  // A swap without an image: a frame glpt-replay skipped, rendered because a later one builds
  // on it (deferred_frames.hpp).
  const rt::FrameEnd end{true, nullptr, nullptr};
  if (!renderer_->execute(record, target.buffers(), drawable, stats, &error, swap ? &end : nullptr,
                          queries)) {
    report_failure(error);
    return false;
  }
  frame_stats_ += stats;
  return true;
}

bool FrameOutput::end_frame(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
                            double record_ms, WindowTarget& target, bool swap,
                            std::vector<rt::QuerySamples>* queries) {
  const double frame_ms = since_last_frame_.elapsed_ms();
  const Stopwatch wall_timer;  // what the frame's end costs the program: render and present
  std::string error;
  rt::FrameStats stats;
  drawable_ = drawable;
  record_ms_ += record_ms;
  // With host memory from the window (X shared memory), the frame goes there inside the
  // renderer's submission and presenting is one request; the RGBA copy is only made for PNGs.
  const uint32_t width = drawable_.width, height = drawable_.height;
  // The drawable is held from the execute to the present: another context drawing to it (on
  // another thread) must not change its buffers or the window's memory in between.
  std::unique_lock lock(target.mutex());
  const rt::HostImage* host = target.host_image(width, height);
  const bool want_png = !settings_.png_dir.empty() && frame_index_ % settings_.png_every == 0;
  // Into the window's memory: shown by the target's thread once rendered, while the program
  // goes on (a PNG of the frame needs its pixels here, so that frame waits).
  const bool later =
      swap && drawable.double_buffered && host != nullptr && !want_png && settings_.present_later;
  rt::FrameEnd::FrontPixels front;
  rt::FrameEnd end{swap, host == nullptr || want_png ? &image_ : nullptr, host, later, later};
  if (later) end.front_pixels = &front;
  image_.clear();
  const bool ok =
      renderer_->execute(record, target.buffers(), drawable, stats, &error, &end, queries);
  if (!ok) report_failure(error);
  frame_stats_ += stats;
  const Stopwatch present_timer;
  const bool have_image =
      ok && width > 0 && height > 0 && image_.size() == size_t{width} * height * 4;
  if (ok && host != nullptr && later) {
    std::shared_ptr<const rt::Renderer> renderer = renderer_;
    const uint64_t ticket = renderer_->frame_ticket();
    // The rows arrive bottom to top (FrameEnd::present_bottom_up); X's run top to bottom. The
    // flip runs on the presenting thread, beside the program's: from the front image itself where
    // the renderer left it there (FrameEnd::front_pixels; the token held until then keeps the
    // image from being drawn into or replaced), else in the window's memory.
    const rt::HostImage image = *host;
    target.present_host_image_later([renderer, ticket, image, front]() mutable {
      renderer->wait_for_frame(ticket);
      if (image.pixels != nullptr && front.rows != nullptr)
        copy_rows_flipped(front.rows, front.row_pitch, image);
      else if (image.pixels != nullptr)
        flip_rows(image);
      front.reading.reset();
    });
  } else if (ok && host != nullptr)
    target.present_host_image();
  else if (have_image)
    target.present(image_.data(), width, height);
  lock.unlock();
  const double present_ms = present_timer.elapsed_ms();

  if (have_image && !settings_.png_dir.empty() && frame_index_ % settings_.png_every == 0)
    write_frame_png(settings_, png_stream_, frame_index_, width, height, image_,
                    &png_failure_reported_);
  if (settings_.stats) {
    const rt::FrameStats& s = frame_stats_;
    const double trace_s = s.trace_ms / 1000.0;
    if (!settings_.stats_file.empty() && !stats_out_ && !stats_file_failed_) {
      stats_out_.reset(std::fopen(settings_.stats_file.c_str(), "a"));
      if (!stats_out_) {
        stats_file_failed_ = true;
        std::fprintf(stderr, "glpt: GLPT_STATS_FILE: cannot open %s: writing to stderr\n",
                     settings_.stats_file.c_str());
      }
    }
    std::FILE* out = stats_out_ ? stats_out_.get() : stderr;
    const HeapUse heap = heap_use();
    std::fprintf(
        out,
        "glpt: frame=%" PRIu64
        " size=%ux%u frame_ms=%.2f capture_ms=%.2f upload_ms=%.2f raster_ms=%.2f "
        "blas_ms=%.2f tlas_ms=%.2f trace_ms=%.2f readback_ms=%.2f present_ms=%.2f "
        "total_ms=%.2f draws=%u merged_draws=%u resident_draws=%u pipelines_created=%u "
        "inexpressible=%u upside_down_runs=%u "
        "triangles=%" PRIu64 " rays=%" PRIu64
        " mrays_per_s=%.3f blas_builds=%u blas_refits=%u blas_reused=%u spp=%u non_finite=%" PRIu64
        " non_finite_prims=%" PRIu64
        " non_finite_draws=%u emitters=%u host_waits=%u wall_ms=%.2f traced_draws=%u sky_draws=%u"
        " raster_draws=%u instances=%u tlas_builds=%u tlas_updates=%u upload_bytes=%" PRIu64
        " classify_ms=%.3f denoise_ms=%.2f composite_ms=%.2f taa_ms=%.2f denoised=%u "
        "denoised_tiles=%u"
        " vk_objects=%" PRId64 " rss_kb=%" PRIu64 " heap_kb=%" PRIu64 " heap_free_kb=%" PRIu64
        " classes=%s vk_by_kind=%s\n",
        frame_index_, width, height, frame_ms, record_ms_, s.upload_ms, s.raster_ms, s.blas_ms,
        s.tlas_ms, s.trace_ms, s.readback_ms, present_ms,
        record_ms_ + s.upload_ms + s.raster_ms + s.blas_ms + s.tlas_ms + s.trace_ms + s.denoise_ms +
            s.composite_ms + s.taa_ms + s.readback_ms + present_ms,
        s.draws, s.merged_draws, s.resident_draws, s.pipelines_created, s.inexpressible,
        s.upside_down_runs, s.triangles, s.rays, trace_s > 0 ? s.rays / trace_s / 1e6 : 0.0,
        s.blas_builds, s.blas_refits, s.blas_reused, s.accumulated_samples, s.non_finite_samples,
        s.non_finite_primitives, s.non_finite_draws, s.emitters, s.host_waits,
        wall_timer.elapsed_ms(), s.traced_draws, s.sky_draws, s.raster_draws, s.instances,
        s.tlas_builds, s.tlas_updates, s.upload_bytes, s.classify_ms, s.denoise_ms, s.composite_ms,
        s.taa_ms, s.denoised, s.denoised_tiles,
        rt::vk::live_object_count().load(std::memory_order_relaxed), resident_kilobytes(),
        heap.in_use_kb, heap.free_kb, kind_counts(s).c_str(),
        rt::vk::live_object_counts_text().c_str());
    if (stats_out_) std::fflush(stats_out_.get());
  }
  last_frame_stats_ = frame_stats_;
  frame_stats_ = rt::FrameStats();
  record_ms_ = 0;
  ++frame_index_;
  since_last_frame_.restart();
  return ok;
}

}  // namespace glpt
