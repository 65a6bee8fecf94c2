// GLPT_OUTPUT's file names when several contexts of a process write PNGs into one directory.
//
// Each context (its FrameOutput, or its ClearFallback) holds a PngStream. The streams alive at
// one time have distinct names: the first frame_NNNNNN.png, the K-th ctxK_frame_NNNNNN.png.
// A stream given back (its context destroyed) is taken by the next context with its numbering
// continued, so a program that replaces its context (a mode change) writes frame_NNNNNN.png on
// after the last one instead of over the first ones.
#pragma once

#include <cstdint>
#include <string>

namespace glpt {

class PngStream {
 public:
  PngStream();   // takes the lowest stream no live context holds
  ~PngStream();  // gives it back, numbered on from the frames counted
  PngStream(const PngStream&) = delete;
  PngStream& operator=(const PngStream&) = delete;

  // The name (no directory) of the file of this stream's frame `frame` (0: its first frame
  // here); frames up to `frame` count as this holder's.
  std::string file_name(uint64_t frame);
  // 1 for frame_NNNNNN.png, K for ctxK_frame_NNNNNN.png.
  unsigned number() const { return slot_ + 1; }

 private:
  unsigned slot_ = 0;
  uint64_t first_ = 0;   // the stream's number of this holder's frame 0
  uint64_t frames_ = 0;  // frames counted by this holder
};

}  // namespace glpt
