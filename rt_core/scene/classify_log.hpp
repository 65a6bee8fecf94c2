// GLPT_CLASSIFY_LOG=FILE: one JSON object per line for every classified draw of every frame, in
// GL order: {"frame": F, "class": "static", "calls": K, "id": I}. `frame` counts from 0 and ends
// at each swap; `calls` is how many of the program's drawing commands the entry covers (each
// glBegin/glEnd pair, glDrawArrays, glDrawElements, glDrawRangeElements, glRect, glBitmap,
// glDrawPixels counts one, also when executed from a display list); `id` the draw's stable
// identity (draw_identity.hpp). The file is appended to, each record's lines in one write.
#pragma once

#include <cstdint>
#include <string>

#include "rt_core/record/frame_record.hpp"
#include "rt_core/scene/classify.hpp"

namespace glpt::rt {

class ClassifyLog {
 public:
  // An unopenable path gives a log that writes nothing (`error` says why).
  ClassifyLog(const std::string& path, std::string* error);
  ~ClassifyLog();
  ClassifyLog(const ClassifyLog&) = delete;
  ClassifyLog& operator=(const ClassifyLog&) = delete;

  bool is_open() const { return fd_ >= 0; }
  // Writes the labels of one record of the current frame.
  void write(const FrameClassification& classification);
  // The current frame ended (a swap): the next record belongs to the next frame.
  void end_frame();

 private:
  int fd_ = -1;  // owned
  uint64_t frame_ = 0;
  std::string text_;  // one record's lines
};

}  // namespace glpt::rt
