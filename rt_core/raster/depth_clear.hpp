// The value glClear writes into a 24-bit depth buffer, as Mesa 25 (llvmpipe) writes it, and the
// float that makes lavapipe write the same value. Measured against OSMesa (conformance scenes
// pixels_depth_clears_read_as_uint and pixels_depth_full_clears_read_as_uint read the cleared
// values back as 32-bit integers):
//
// - Mesa clears a whole depth buffer with util_pack_z: lrint(depth * 0xFFFFFF) in double.
// - A clear the scissor limits (or a depth clear made with a partially masked stencil clear) is
//   a quad (st_cb_clear.c): at the normalized z float(depth * 2 - 1), which the viewport maps to
//   float(z * 0.5f + 0.5f) and llvmpipe's depth stage converts as the float product with
//   16777215, rounded half to even.
#pragma once

#include <cstdint>

namespace glpt::rt {

uint32_t mesa_clear_z24(double depth, bool whole_buffer);

// A depth for vkCmdClearAttachments that lavapipe turns into `z24` (util_pack_z of the float).
float attachment_clear_depth(uint32_t z24);
// A fragment depth (a viewport's depth range) that lavapipe writes as `z24`.
float fragment_depth(uint32_t z24);

}  // namespace glpt::rt
