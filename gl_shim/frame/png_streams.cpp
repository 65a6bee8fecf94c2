#include "gl_shim/frame/png_streams.hpp"

#include <cinttypes>
#include <cstdio>
#include <mutex>
#include <vector>

namespace glpt {
namespace {

// Process-wide by nature, like the directory: which streams are held, and where each one's
// numbering goes on.
struct Streams {
  std::mutex mutex;
  std::vector<bool> held;
  std::vector<uint64_t> next_frame;
};

// Never destroyed: contexts may be destroyed during exit (a library destructor, an atexit
// handler), after function-local statics are gone.
Streams& streams() {
  static Streams* const s = new Streams;
  return *s;
}

}  // namespace

PngStream::PngStream() {
  Streams& s = streams();
  std::lock_guard lock(s.mutex);
  size_t slot = 0;
  while (slot < s.held.size() && s.held[slot]) ++slot;
  if (slot == s.held.size()) {
    s.held.push_back(false);
    s.next_frame.push_back(0);
  }
  s.held[slot] = true;
  slot_ = static_cast<unsigned>(slot);
  first_ = s.next_frame[slot];
}

PngStream::~PngStream() {
  Streams& s = streams();
  std::lock_guard lock(s.mutex);
  s.held[slot_] = false;
  s.next_frame[slot_] = first_ + frames_;
}

std::string PngStream::file_name(uint64_t frame) {
  if (frame + 1 > frames_) frames_ = frame + 1;
  char name[64];
  if (slot_ == 0)
    std::snprintf(name, sizeof name, "frame_%06" PRIu64 ".png", first_ + frame);
  else
    std::snprintf(name, sizeof name, "ctx%u_frame_%06" PRIu64 ".png", slot_ + 1, first_ + frame);
  return name;
}

}  // namespace glpt
