#include "rt_core/raster/accumulation.hpp"

#include <cmath>
#include <cstring>

namespace glpt::rt {
namespace {

// C's (GLshort) of a float as GCC compiles it on x86-64: truncated to a 32-bit integer
// (cvttss2si gives INT32_MIN when out of range), then the low 16 bits.
int16_t to_short(float f) {
  int32_t i = INT32_MIN;
  if (f > -2147483648.0f && f < 2147483648.0f) i = static_cast<int32_t>(f);
  return static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(i) & 0xFFFFu));
}

// A 16-bit sum as C computes it (int arithmetic), stored back into a GLshort (wraps).
int16_t wrap(int32_t v) { return static_cast<int16_t>(static_cast<uint16_t>(v & 0xFFFF)); }

// Mesa's FLOAT_TO_SHORT: ((GLint)(65535.0F * X) - 1) / 2, integer division toward zero.
int16_t float_to_short(float x) {
  const float scaled = 65535.0f * x;
  const int32_t i =
      scaled > -2147483648.0f && scaled < 2147483648.0f ? static_cast<int32_t>(scaled) : INT32_MIN;
  return wrap((i - 1) / 2);
}

// Mesa's ubyte_to_float.
float ubyte_to_float(uint8_t b) { return static_cast<float>(b) * (1.0f / 255.0f); }

}  // namespace

void AccumulationBuffer::resize(uint32_t width, uint32_t height) {
  width_ = width;
  height_ = height;
  values_.assign(size_t{width} * height * 4, 0);
}

template <typename F>
void AccumulationBuffer::for_each_pixel(const PixelRect& rect, F&& f) {
  for (uint32_t j = 0; j < rect.height; ++j) {
    int16_t* row = &values_[((size_t(rect.y) + j) * width_ + size_t(rect.x)) * 4];
    for (uint32_t i = 0; i < rect.width; ++i) f(row + size_t{i} * 4, size_t{j} * rect.width + i);
  }
}

void AccumulationBuffer::clear(const PixelRect& rect, const glm::vec4& value) {
  const int16_t v[4] = {float_to_short(value.r), float_to_short(value.g), float_to_short(value.b),
                        float_to_short(value.a)};
  for_each_pixel(rect, [&](int16_t* p, size_t) { std::memcpy(p, v, sizeof v); });
}

void AccumulationBuffer::add(const PixelRect& rect, float value) {
  const int16_t increment = to_short(value * 32767.0f);
  for_each_pixel(rect, [&](int16_t* p, size_t) {
    for (int c = 0; c < 4; ++c) p[c] = wrap(int32_t{p[c]} + increment);
  });
}

void AccumulationBuffer::multiply(const PixelRect& rect, float value) {
  for_each_pixel(rect, [&](int16_t* p, size_t) {
    for (int c = 0; c < 4; ++c) p[c] = to_short(static_cast<float>(p[c]) * value);
  });
}

void AccumulationBuffer::accumulate(const PixelRect& rect, const std::vector<uint8_t>& rgba,
                                    float value, bool load) {
  const float scale = value * 32767.0f;
  for_each_pixel(rect, [&](int16_t* p, size_t k) {
    for (int c = 0; c < 4; ++c) {
      const int16_t v = to_short(ubyte_to_float(rgba[k * 4 + c]) * scale);
      p[c] = load ? v : wrap(int32_t{p[c]} + v);
    }
  });
}

void AccumulationBuffer::return_to(const PixelRect& rect, float value,
                                   const std::array<bool, 4>& write_mask,
                                   std::vector<uint8_t>& rgba) const {
  const float scale = value / 32767.0f;
  for (uint32_t j = 0; j < rect.height; ++j) {
    const int16_t* row = &values_[((size_t(rect.y) + j) * width_ + size_t(rect.x)) * 4];
    for (uint32_t i = 0; i < rect.width; ++i) {
      uint8_t* out = &rgba[(size_t{j} * rect.width + i) * 4];
      for (int c = 0; c < 4; ++c) {
        // Masked components keep the colour buffer's value (through float and back, as Mesa).
        const float f =
            write_mask[c] ? static_cast<float>(row[i * 4 + c]) * scale : ubyte_to_float(out[c]);
        out[c] = mesa_float_to_ubyte(f);
      }
    }
  }
}

}  // namespace glpt::rt
