// The accumulation buffer (GL 1.5 4.2.4) kept the way Mesa 25 keeps it, so glAccum gives Mesa's
// pixels: signed 16-bit components (MESA_FORMAT_RGBA_SNORM16) updated on the CPU with Mesa's C
// arithmetic (src/mesa/main/accum.c): float products truncated toward zero, 16-bit sums that
// wrap, colours read as byte * (1 / 255) and written back with Mesa's float_to_ubyte.
//
// Raster mode executes glAccum here (Mesa does it in software too): the colour buffer rectangle
// is read back, combined, and for GL_RETURN written back.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "common/mesa_float.hpp"

namespace glpt::rt {

// A rectangle of the drawable in window coordinates, already clipped to it.
struct PixelRect {
  int32_t x = 0, y = 0;
  uint32_t width = 0, height = 0;
  size_t pixels() const { return size_t{width} * height; }
};

class AccumulationBuffer {
 public:
  // A new buffer of width x height, all zero (GL leaves it undefined; Mesa's starts zeroed).
  void resize(uint32_t width, uint32_t height);
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

  // glClear(GL_ACCUM_BUFFER_BIT): each component of `value` (in [-1, 1]) as Mesa's FLOAT_TO_SHORT.
  void clear(const PixelRect& rect, const glm::vec4& value);
  // GL_ADD: every component += (short)(value * 32767).
  void add(const PixelRect& rect, float value);
  // GL_MULT: every component = (short)(component * value).
  void multiply(const PixelRect& rect, float value);
  // GL_ACCUM (load false) adds, GL_LOAD (load true) replaces with, (short)(colour * value *
  // 32767) per component. `rgba`: the rectangle of the read buffer, RGBA8, rows bottom to top.
  void accumulate(const PixelRect& rect, const std::vector<uint8_t>& rgba, float value, bool load);
  // GL_RETURN: the rectangle of a colour buffer (`rgba`, RGBA8, its current contents) becomes
  // component * value / 32767 where `write_mask` allows it.
  void return_to(const PixelRect& rect, float value, const std::array<bool, 4>& write_mask,
                 std::vector<uint8_t>& rgba) const;

  // One component of pixel (x, y); for tests.
  int16_t at(uint32_t x, uint32_t y, int component) const {
    return values_[(size_t{y} * width_ + x) * 4 + static_cast<size_t>(component)];
  }

 private:
  template <typename F>
  void for_each_pixel(const PixelRect& rect, F&& f);

  uint32_t width_ = 0, height_ = 0;
  std::vector<int16_t> values_;  // RGBA per pixel, rows bottom to top
};

using glpt::mesa_float_to_ubyte;  // common/mesa_float.hpp

}  // namespace glpt::rt
