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
// own vertices (back to back in the record's vertex streams, vertex_streams.hpp). Only draws the
// streams take are merged, filled triangles only: the unfilled polygons' edge masks are found per
// draw, points and lines keep their stipple and strips. The G-buffer pass draws every command
// on its own (each keeps its identity for the tracer).
#pragma once

#include <cstdint>
#include <vector>

#include "rt_core/raster/raster_recording.hpp"
#include "rt_core/record/decompose.hpp"

namespace glpt::rt {

// Whether `draw` may share one Vulkan draw with neighbours of the same state; `streamed`: the
// record's vertex streams take its vertices (VertexStreams::takes).
bool mergeable_draw(const rec::FrameRecord& record, const rec::Draw& draw, bool streamed);

// The filled triangles of `v` in Mesa's order (decompose.hpp), as vertex numbers plus `base`,
// appended to `out`; triangles with a non-finite vertex are left out. Returns how many were.
uint64_t append_filled_triangles(const rec::VertexData& v, const rec::AssemblyState& assembly,
                                 uint32_t base, rec::Decomposed& scratch,
                                 std::vector<uint32_t>& out);

}  // namespace glpt::rt
