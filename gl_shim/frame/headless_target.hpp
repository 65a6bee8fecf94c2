// A drawable without a window: a fixed-size surface whose presented frames are kept in memory.
// Used by the conformance runner and headless replay (and, later, EGL pbuffers).
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "gl_shim/frame/frame_output.hpp"

namespace glpt {

class Context;

class HeadlessTarget final : public WindowTarget {
 public:
  // `config`: the buffers the surface has (its size is the target's own).
  HeadlessTarget(uint32_t width, uint32_t height, rec::DrawableConfig config = {})
      : width_(width), height_(height), config_(config) {}

  bool query_size(uint32_t* width, uint32_t* height) override {
    *width = width_;
    *height = height_;
    return true;
  }
  void present(const uint8_t* rgba, uint32_t width, uint32_t height) override {
    presented_.assign(rgba, rgba + size_t{width} * height * 4);
    ++presented_frames_;
  }

  rec::DrawableConfig config() const override { return config_; }

  void resize(uint32_t width, uint32_t height) {
    width_ = width;
    height_ = height;
  }
  // The last presented frame: RGBA8, rows bottom to top.
  const std::vector<uint8_t>& presented() const { return presented_; }
  uint64_t presented_frames() const { return presented_frames_; }

 private:
  uint32_t width_, height_;
  rec::DrawableConfig config_;
  std::vector<uint8_t> presented_;
  uint64_t presented_frames_ = 0;
};

// Makes `ctx` current on this thread drawing to `target`, initializing the viewport and scissor
// box to the target's size on the context's first use, as make-current does (GL 1.5 2.11.1).
void make_current_headless(Context& ctx, HeadlessTarget& target);

}  // namespace glpt
