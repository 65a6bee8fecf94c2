// glpt-replay --window: shows the replayed frames in a GLFW window through a Vulkan swapchain of
// its own (no GL context: the frames come from the backend as images). Keys: space pauses and
// resumes, n or Right steps one frame while paused, q or Escape quits.
#pragma once

#include <memory>
#include <string>

#include "replay/backend.hpp"

namespace glpt::replay {

class WindowView {
 public:
  // nullptr + message without a display or a Vulkan device that can present to it.
  static std::unique_ptr<WindowView> create(std::string* error);
  ~WindowView();
  WindowView(const WindowView&) = delete;
  WindowView& operator=(const WindowView&) = delete;

  // Shows frame `frame` (the window takes the size of the first frame) and handles input;
  // while paused it waits for a step, a resume or quitting. False once the user quit; false +
  // message on a failure.
  bool show(const FrameImage& image, uint64_t frame, std::string* error);
  bool quit_requested() const;
  // Start paused (--paused): the first frame waits for a key.
  void pause();

 private:
  class Impl;
  explicit WindowView(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace glpt::replay
