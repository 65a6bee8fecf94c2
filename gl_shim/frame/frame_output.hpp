// The consumer side of a context's frames: executes frame records with rt_core's Renderer,
// presents the front buffer to the window, writes it as PNG (GLPT_OUTPUT) and prints statistics
// (GLPT_STATS).
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "common/stopwatch.hpp"
#include "gl_shim/frame/png_streams.hpp"
#include "gl_shim/frame/render_group.hpp"
#include "rt_core/frame_stats.hpp"
#include "rt_core/record/frame_record.hpp"
#include "rt_core/renderer.hpp"

namespace glpt {

// A drawable that frames are shown in (an X window through glpt's own X connection, or a
// headless surface).
class WindowTarget {
 public:
  virtual ~WindowTarget() = default;
  // Current size in pixels; false if the window is gone.
  virtual bool query_size(uint32_t* width, uint32_t* height) = 0;
  // The size frames render at: for a window, the size query_size() last answered until
  // forget_size(), which make-current, glViewport and every swap call. Mesa's software GLX asks
  // the server at the same points (a drawable is re-validated when its stamp changes), not at
  // every glReadPixels or glFinish: a query is a round trip to the X server.
  virtual bool known_size(uint32_t* width, uint32_t* height) { return query_size(width, height); }
  virtual void forget_size() {}
  // The size the program's own connection reported just now (glXSwapBuffers asks there, after
  // the program's requests): the frame ending uses it, and the next forget_size() keeps it.
  virtual void assume_size(uint32_t /*width*/, uint32_t /*height*/) {}
  // `rgba`: width*height RGBA8, rows bottom to top (GL order).
  virtual void present(const uint8_t* rgba, uint32_t width, uint32_t height) = 0;
  // The buffers the drawable has (GLX visual / EGL config); the size is filled in by the caller.
  virtual rec::DrawableConfig config() const { return {}; }
  // Zero-copy presenting: host memory the next frame can be written into directly (the
  // renderer's own submission copies the front buffer there, or, for a frame presented later
  // from a host-readable front image, the presenting thread), shown by present_host_image().
  // nullptr when the target has no such memory (then present() is used).
  virtual const rt::HostImage* host_image(uint32_t /*width*/, uint32_t /*height*/) {
    return nullptr;
  }
  virtual void present_host_image() {}
  // Shows the frame in host_image()'s memory once `ready` (which waits for the renderer to
  // finish it) has returned, on a thread of the target's, so that the program's thread records
  // the next frame meanwhile; host_image() then hands out other memory until this frame is
  // shown. A target without such a thread waits and shows it now.
  virtual void present_host_image_later(std::function<void()> ready) {
    ready();
    present_host_image();
  }
  // Blocks until every frame given to present_host_image_later() is shown (glFinish,
  // glXWaitGL: later X requests of the program see it).
  virtual void wait_presented() {}

  // The drawable's buffers: every context drawing to it draws into and reads these (GLX and EGL
  // let several contexts share a drawable, one after another or on several threads).
  rt::DrawableBuffers& buffers() { return *buffers_; }
  // Held while a context executes on, reads or presents the drawable.
  std::mutex& mutex() { return mutex_; }

 private:
  std::shared_ptr<rt::DrawableBuffers> buffers_ = rt::create_drawable_buffers();
  std::mutex mutex_;
};

struct OutputSettings {
  std::string png_dir;     // GLPT_OUTPUT: write frames as DIR/frame_NNNNNN.png (png_streams.hpp)
  uint32_t png_every = 1;  // GLPT_OUTPUT_EVERY: every Nth frame
  bool stats = false;      // GLPT_STATS=1: one line per frame on stderr
  std::string stats_file;  // GLPT_STATS_FILE=FILE: those lines appended to FILE instead
  // GLPT_PRESENT=later (default): a swapped frame is shown by the window's presenting thread once
  // rendered, while the program records the next (GLX lets a swap complete after it returns;
  // glFinish and glXWaitGL wait for it). sync: the swap returns once the frame is on screen, as
  // Mesa's software GLX does.
  bool present_later = true;
  static OutputSettings from_environment();
};

// Creates settings.png_dir if it is set. If that fails, says so once on stderr and clears
// png_dir: an unwritable GLPT_OUTPUT is reported once, not at every frame, and the program runs
// on without PNGs.
void create_png_directory(OutputSettings& settings);
// Writes frame `frame_index` of `stream` (`rgba`: rows bottom to top, made opaque here, as the
// window shows it) into settings.png_dir under the stream's name for it (frame_NNNNNN.png for
// the first context). A failure is reported on stderr the first time only (*failure_reported).
void write_frame_png(const OutputSettings& settings, PngStream& stream, uint64_t frame_index,
                     uint32_t width, uint32_t height, std::vector<uint8_t>& rgba,
                     bool* failure_reported);

// Prints `message` (one line, on stderr) unless this process printed it already: what every
// context of a program would say alike (no Vulkan device, no ray queries, an unusable
// GLPT_OUTPUT) is said once. `key` (default: the message) names what is reported.
void report_once_per_process(const std::string& message, const std::string& key = {});

class FrameOutput {
 public:
  // A context's output, rendering with its share group's renderer. nullptr and a message if no
  // renderer can be created (e.g. no Vulkan device).
  static std::unique_ptr<FrameOutput> create(RenderGroup& group, std::string* error);

  // Applies `record` to the buffers of `target`, whose configuration is `drawable`. `record_ms`:
  // time spent recording it. `queries`: the samples counted for its occlusion queries
  // (rt::Renderer::execute). False when the render failed (the message went to stderr once).
  bool execute(const rec::FrameRecord& record, WindowTarget& target,
               const rec::DrawableConfig& drawable, double record_ms,
               std::vector<rt::QuerySamples>* queries = nullptr, bool swap = false);
  // End of a frame: a swap (double-buffered) or glFlush/glFinish of a single-buffered drawable.
  // Executes the rest of the frame's record, swaps if asked (all in one submission), shows the
  // front buffer in `target`, writes the PNG and prints the frame's statistics. False when the
  // render failed (nothing was shown; the message went to stderr once).
  bool end_frame(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
                 double record_ms, WindowTarget& target, bool swap,
                 std::vector<rt::QuerySamples>* queries = nullptr);

  rt::Renderer& renderer() { return *renderer_; }
  // What the last completed frame cost (what GLPT_STATS printed for it).
  const rt::FrameStats& last_frame_stats() const { return last_frame_stats_; }
  bool stats_enabled() const { return settings_.stats; }
  const rec::DrawableConfig& drawable() const { return drawable_; }

 private:
  FrameOutput(std::shared_ptr<rt::Renderer> renderer, OutputSettings settings);
  void report_failure(const std::string& error);

  std::shared_ptr<rt::Renderer> renderer_;  // the share group's
  OutputSettings settings_;
  PngStream png_stream_;
  rec::DrawableConfig drawable_{0, 0};
  std::vector<uint8_t> image_;  // the front buffer, for presenting
  rt::FrameStats frame_stats_;  // summed over the records of the frame
  rt::FrameStats last_frame_stats_;
  double record_ms_ = 0;
  uint64_t frame_index_ = 0;
  bool failure_reported_ = false;
  bool png_failure_reported_ = false;
  Stopwatch since_last_frame_;
  struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, FileCloser> stats_out_;  // GLPT_STATS_FILE, opened at first use
  bool stats_file_failed_ = false;
};

}  // namespace glpt
