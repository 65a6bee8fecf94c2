// A fast 64-bit content hash (not cryptographic): identity of geometry, state and textures across
// frames (acceleration structures, vertex buffers and pipelines are reused by it).
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

namespace glpt {

class ContentHash {
 public:
  void add_bytes(const void* data, size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    size_t i = 0;
    if (size >= 64) {
      // Four independent lanes (xxHash64's round), folded in at the end: the serial mix below
      // has a long dependency chain per word, and a frame's vertex arrays are megabytes.
      uint64_t lanes[4] = {state_ + 0x60ea27eeadc0b5d6ull, state_ ^ 0xc2b2ae3d27d4eb4full,
                           state_ + 0x165667b19e3779f9ull, state_ ^ 0x85ebca77c2b2ae63ull};
      for (; i + 32 <= size; i += 32) {
        for (int k = 0; k < 4; ++k) {
          uint64_t w;
          std::memcpy(&w, p + i + 8 * k, 8);
          lanes[k] = lane_round(lanes[k], w);
        }
      }
      for (uint64_t lane : lanes) mix(lane);
    }
    for (; i + 8 <= size; i += 8) {
      uint64_t w;
      std::memcpy(&w, p + i, 8);
      mix(w);
    }
    uint64_t tail = 0;
    if (size > i) std::memcpy(&tail, p + i, size - i);  // data may be null when size is 0
    mix(tail ^ (uint64_t{size - i} << 56));
  }
  template <typename T>
  void add(const std::vector<T>& v) {
    mix(v.size());
    add_bytes(v.data(), v.size() * sizeof(T));
  }
  uint64_t value() const { return finalize(state_); }

 private:
  static uint64_t lane_round(uint64_t lane, uint64_t w) {
    lane += w * 0xc2b2ae3d27d4eb4full;
    lane = (lane << 31) | (lane >> 33);
    return lane * 0x9e3779b185ebca87ull;
  }
  // splitmix64-style mixing per 8-byte word: fast, and well distributed for float data.
  void mix(uint64_t w) { state_ = finalize(state_ ^ (w + 0x9e3779b97f4a7c15ull + (state_ << 6))); }
  static uint64_t finalize(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  uint64_t state_ = 0x243f6a8885a308d3ull;
};

}  // namespace glpt
