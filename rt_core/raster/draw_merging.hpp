// Consecutive draws under one state drawn as one Vulkan draw.
//
// glxgears' gears are display lists of six glBegin/glEnd blocks, five of them under one state
// (flat-shaded quad strips and quads). Mesa's display-list compiler keeps a list's blocks in one
// vertex buffer and hands them to the driver in one call; glpt drew each block with its own
// vertex-buffer bindings and vkCmdDrawIndexed, about 12 us of CPU each (lavapipe records every
// command as a heap entry and validates vertex state again per draw: bench/many_draws).
//
// Merging changes no pixel: every draw is decomposed on its own into Mesa's triangles in Mesa's
// order (decompose.hpp), and the merged index list draws them in the same order, each with its
// own vertices. Only what the shaders index per draw rules a draw out: per-vertex materials
// (RasterPushConstants::materials) and the edge masks of unfilled polygons; points and lines
// (stipple and strips) and geometry big enough to stay resident (ResidentGeometry) are drawn as
// they are. The G-buffer pass keeps one draw per command (the geometry shader's ids).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "rt_core/raster/raster_recording.hpp"
#include "rt_core/record/decompose.hpp"

namespace glpt::rt {

// Whether `draw` may share one Vulkan draw with neighbours of the same state.
bool mergeable_draw(const rec::FrameRecord& record, const rec::Draw& draw);

// The filled triangles of `v` in Mesa's order (decompose.hpp), as vertex numbers plus `base`,
// appended to `out`; triangles with a non-finite vertex are left out. Returns how many were.
uint64_t append_filled_triangles(const rec::VertexData& v, const rec::AssemblyState& assembly,
                                 uint32_t base, rec::Decomposed& scratch,
                                 std::vector<uint32_t>& out);

// Lays the vertex attributes of `draws` out back to back in `arena` and says where they are: an
// attribute every draw lacks reads the default at `default_offset + default_at`, one value the
// draws all share is stored once, anything else is one value per vertex (a draw's single value
// or default repeated over its vertices). `offsets` and `strides` per attribute location.
void merge_attributes(std::span<const rec::VertexData* const> draws, Arena& arena,
                      const uint8_t* defaults, VkDeviceSize default_offset,
                      std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT>& offsets,
                      std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT>& strides);

}  // namespace glpt::rt
