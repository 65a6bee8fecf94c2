// GLPT_CLASSIFY_LOG=FILE: one JSON object per line for every classified draw of every frame, in
// GL order: {"frame": F, "class": "static", "calls": K, "id": I}. `frame` counts from 0 and ends
// at each swap; `calls` is how many of the program's drawing commands the entry covers (each
// glBegin/glEnd pair, glDrawArrays, glDrawElements, glDrawRangeElements, glRect, glBitmap,
// glDrawPixels counts one, also when executed from a display list); `id` the draw's stable
// identity (draw_identity.hpp). The file is appended to, and flushed at each frame's end.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "rt_core/record/frame_record.hpp"
#include "rt_core/scene/classify.hpp"

namespace glpt::rt {

class ClassifyLog {
 public:
  // An unopenable path gives a log that writes nothing (`error` says why).
  ClassifyLog(const std::string& path, std::string* error);

  bool is_open() const { return file_ != nullptr; }
  // Writes the labels of one record of the current frame.
  void write(const FrameClassification& classification);
  // The current frame ended (a swap): the next record belongs to the next frame.
  void end_frame();

 private:
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Closer> file_;
  uint64_t frame_ = 0;
};

}  // namespace glpt::rt
