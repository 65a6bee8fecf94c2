// PNG input and output for glpt: 8-bit RGBA images in, 8-bit RGBA images out.
//
// Used inside libGL.so.1 and by the test tools, so the API never throws (allocation failure
// aside) and keeps no global state: every call is independent and thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace glpt {

// An 8-bit RGBA image, rows stored top row first, 4 bytes per pixel, no padding.
struct ImageRGBA8 {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> pixels;  // width * height * 4 bytes, top row first
};

// Writes `rgba` (w * h * 4 bytes, tightly packed) as an 8-bit RGBA PNG at `path`.
// bottom_up == true: row 0 of `rgba` is the bottom row of the image (as glReadPixels returns
// it); the PNG is upright either way. The file is written to a temporary name in the same
// directory and renamed into place, so a reader never sees a partly written PNG.
// Fast zlib settings are used: this runs once per frame inside libGL.
// Returns false and sets *error (if non-null) on failure; `path` is then left untouched.
bool write_png_rgba8(const std::string& path, uint32_t w, uint32_t h, const uint8_t* rgba,
                     bool bottom_up, std::string* error);

// Reads any PNG (any colour type and bit depth, with or without palette or transparency) and
// converts it to 8-bit RGBA. 16-bit channels without gamma information are scaled to 8 bits
// directly. Returns false and sets *error (if non-null) on failure; *out is then unspecified.
bool read_png_rgba8(const std::string& path, ImageRGBA8* out, std::string* error);

}  // namespace glpt
