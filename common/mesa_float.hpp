// Mesa's float-to-byte conversion, where glpt must round exactly as Mesa does.
#pragma once

#include <cstdint>
#include <cstring>

namespace glpt {

// Mesa's float_to_ubyte (src/util/u_math.h): [0, 1] to a byte, rounding to nearest (ties to
// even) through a float magic-number addition; NaN and negative values are 0.
inline uint8_t mesa_float_to_ubyte(float f) {
  if (!(f > 0.0f)) return 0;
  if (f >= 1.0f) return 255;
  const float t = f * (255.0f / 256.0f) + 32768.0f;
  uint32_t bits;
  std::memcpy(&bits, &t, sizeof bits);
  return static_cast<uint8_t>(bits);
}

}  // namespace glpt
