// Pixel transfer operations (GL 1.5 3.6.5) on values already unpacked from client memory or read
// from the framebuffer. The state commands (glPixelTransfer, glPixelMap, glPixelZoom) are in
// pixel_transfer.cpp and keep their state in Context::pixel_transfer.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gl_shim/gl_types.h"
#include "rt_core/record/gl_state.hpp"

namespace glpt {

inline constexpr int kMaxPixelMapTable = 256;  // GL_MAX_PIXEL_MAP_TABLE (Mesa's value)

// RGBA components: scale and bias, the R_TO_R... maps when MAP_COLOR is on, and the final clamp
// to [0, 1].
void transfer_rgba(const rec::PixelTransferState& transfer, std::vector<glm::vec4>& rgba);

// Colour indices: INDEX_SHIFT / INDEX_OFFSET (modulo 2^32, as Mesa's integer arithmetic).
uint32_t shift_and_offset_index(const rec::PixelTransferState& transfer, uint32_t index);

// Colour indices to RGBA in RGBA mode: shift and offset, then the I_TO_R/G/B/A maps (each indexed
// by the index masked with its size - 1). Mesa applies no RGBA scale/bias or colour map to
// colours that started as indices.
std::vector<glm::vec4> transfer_index_to_rgba(const rec::PixelTransferState& transfer,
                                              const std::vector<uint32_t>& indices);

// Stencil indices: shift and offset, then the S_TO_S map when MAP_STENCIL is on.
void transfer_stencil(const rec::PixelTransferState& transfer, std::vector<uint32_t>& stencil);

// Depth: scale and bias, clamped to [0, 1].
void transfer_depth(const rec::PixelTransferState& transfer, std::vector<float>& depth);

// The map of `map` (GL_PIXEL_MAP_I_TO_I ... GL_PIXEL_MAP_A_TO_A), or null for another enum.
const std::vector<float>* pixel_map(const rec::PixelTransferState& transfer, GLenum map);

}  // namespace glpt
