// How many bytes GL reads for an image in client memory (GL 1.5 3.6.4 "unpacking"), so a trace's
// blob that is shorter than that can be padded rather than read past its end.
#pragma once

#include <cstdint>
#include <optional>

#include "gl_shim/gl_types.h"

namespace glpt::replay {

struct UnpackModes {
  int64_t row_length = 0, skip_rows = 0, skip_pixels = 0, alignment = 4, image_height = 0,
          skip_images = 0;
};

// An upper bound of the bytes a width x height (x depth) image of `format` and `type` occupies
// under `modes` (skips included); nullopt for a format or type GL 1.5 does not know, or a
// negative size.
std::optional<uint64_t> image_bytes(int64_t width, int64_t height, int64_t depth, GLenum format,
                                    GLenum type, bool three_d, const UnpackModes& modes);

}  // namespace glpt::replay
