// The denoiser's list of the tiles with a pixel it filters (shared_types.h,
// GLPT_DN_BINDING_TILES): the trace pass fills it (path_trace.comp), the SVGF passes are
// dispatched over it (svgf_common.h). The includer defines GLPT_TILE_LIST_BINDING, the buffer's
// binding in its set 0.
#ifndef GLPT_SHADERS_SVGF_TILE_LIST_H
#define GLPT_SHADERS_SVGF_TILE_LIST_H

#include "shared_types.h"

layout(std430, set = 0, binding = GLPT_TILE_LIST_BINDING) buffer DenoiseTileList {
  uint tiles_dispatch[GLPT_DN_TILES_HEADER];  // VkDispatchIndirectCommand: x counts the list
  uint tile_words[];                          // a flag per tile, then the list
};

// The tiles (GLPT_IMAGE_TILE_WIDTH x GLPT_IMAGE_TILE_HEIGHT pixels) of an image of `size`
// pixels: across, down, and in all.
uint tiles_across(uvec2 size) {
  return (size.x + GLPT_IMAGE_TILE_WIDTH - 1u) / GLPT_IMAGE_TILE_WIDTH;
}
uint tiles_down(uvec2 size) {
  return (size.y + GLPT_IMAGE_TILE_HEIGHT - 1u) / GLPT_IMAGE_TILE_HEIGHT;
}
uint tile_count(uvec2 size) { return tiles_across(size) * tiles_down(size); }
// The tile of `pixel`, numbered row by row.
uint tile_of(ivec2 pixel, uvec2 size) {
  return uint(pixel.y) / GLPT_IMAGE_TILE_HEIGHT * tiles_across(size) +
         uint(pixel.x) / GLPT_IMAGE_TILE_WIDTH;
}
// The first pixel of tile `tile`.
ivec2 tile_origin(uint tile, uvec2 size) {
  uint across = tiles_across(size);
  return ivec2(uvec2(tile % across, tile / across) *
               uvec2(GLPT_IMAGE_TILE_WIDTH, GLPT_IMAGE_TILE_HEIGHT));
}

#endif  // GLPT_SHADERS_SVGF_TILE_LIST_H
