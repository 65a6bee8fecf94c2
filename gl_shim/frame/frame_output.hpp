// The end of a frame: render the captured frame with rt_core, then present it to the window,
// write it as PNG (GLPT_OUTPUT) and print its statistics (GLPT_STATS).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/stopwatch.hpp"
#include "rt_core/frame.hpp"
#include "rt_core/renderer.hpp"

namespace glpt {

// A window that frames are shown in (an X window through glpt's own X connection).
class WindowTarget {
 public:
  virtual ~WindowTarget() = default;
  // Current size in pixels; false if the window is gone.
  virtual bool query_size(uint32_t* width, uint32_t* height) = 0;
  // `rgba`: width*height RGBA8, rows bottom to top (GL order).
  virtual void present(const uint8_t* rgba, uint32_t width, uint32_t height) = 0;
};

struct OutputSettings {
  std::string png_dir;     // GLPT_OUTPUT: write frames as DIR/frame_NNNNNN.png
  uint32_t png_every = 1;  // GLPT_OUTPUT_EVERY: every Nth frame
  bool stats = false;      // GLPT_STATS=1: one line per frame on stderr
  static OutputSettings from_environment();
};

class FrameOutput {
 public:
  // nullptr and a message if no renderer can be created (e.g. no Vulkan ray query).
  static std::unique_ptr<FrameOutput> create(std::string* error);

  // Renders `frame`; the result is image(). `capture_ms`: time spent turning GL calls into it.
  bool render(const rt::Frame& frame, double capture_ms);
  // A swap: show the last image in `target` (may be null), write the PNG, print stats.
  void swap(WindowTarget* target);

  const std::vector<uint8_t>& image() const { return image_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  FrameOutput(std::unique_ptr<rt::Renderer> renderer, OutputSettings settings);

  std::unique_ptr<rt::Renderer> renderer_;
  OutputSettings settings_;
  std::vector<uint8_t> image_;
  std::vector<uint8_t> png_scratch_;
  uint32_t width_ = 0, height_ = 0;
  rt::FrameStats last_stats_;
  double last_capture_ms_ = 0;
  uint64_t frame_index_ = 0;
  bool render_failure_reported_ = false;
  Stopwatch since_last_swap_;
};

}  // namespace glpt
