// The FLIP error map as a picture: each error value in [0, 1] through a colour map.
#pragma once

#include <cstdint>
#include <vector>

#include "flip.hpp"

namespace glpt::diff {

// The colour of one error value: black (0) through purple, red and orange to pale yellow (1),
// brightness rising monotonically so the map also reads in greyscale. Values outside [0, 1]
// are clamped.
void heatmap_color(float error, uint8_t rgb[3]);

// `result`'s error map as 8-bit RGBA (opaque), rows top first, ready for write_png_rgba8.
std::vector<uint8_t> heatmap_rgba8(const FlipResult& result);

}  // namespace glpt::diff
