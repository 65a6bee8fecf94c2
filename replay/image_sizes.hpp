// How many bytes GL reads for an image in client memory (GL 1.5 3.6.4 "unpacking"), so a trace's
// blob that is shorter than that can be padded rather than read past its end. The arithmetic is
// the front end's own (gl_shim/pixels/pixel_layout.hpp): the spec's, whichever backend replays.
#pragma once

#include <cstdint>
#include <optional>

#include "gl_shim/gl_types.h"
#include "gl_shim/state/framebuffer_state.hpp"

namespace glpt::replay {

// The bytes a width x height (x depth) image of `format` and `type` spans under the unpack
// `modes` (skips included); 0 for an empty image; nullopt for a format/type combination GL
// rejects (it then reads nothing) or an image too large to address.
std::optional<uint64_t> image_bytes(int64_t width, int64_t height, int64_t depth, GLenum format,
                                    GLenum type, bool three_d, const PixelStoreModes& modes);

}  // namespace glpt::replay
