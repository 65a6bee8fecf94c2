// EXT_texture_compression_s3tc: the four DXT formats' blocks, decoded as Mesa 25's llvmpipe
// decodes them, and encoded as Mesa encodes the images it is given uncompressed.
//
// Decoding follows what real Mesa renders and what its glGetTexImage returns (both go through
// gallivm's S3TC fetch, lp_bld_format_s3tc.c, which rounds differently from the CPU decoder in
// texcompress_s3tc_tmp.h): the 1/3 and 2/3 colours are c0 + (85 * (c1 - c0) >> 8) and
// c0 + (170 * (c1 - c0) >> 8), DXT1's 3-colour midpoint rounds up, DXT5's interpolated alphas
// take gallivm's fixed-point weights. Measured against OSMesa 25.0.7 on random blocks of every
// format: identical texels (docs/extensions.md).
#pragma once

#include <cstddef>
#include <cstdint>

#include "gl_shim/gl_types.h"

namespace glpt::s3tc {

// Bytes of one 4x4 block: 8 for DXT1 (RGB and RGBA), 16 for DXT3 and DXT5, 0 for any other
// internal format.
uint32_t block_bytes(GLenum internal_format);
inline bool is_s3tc(GLenum internal_format) { return block_bytes(internal_format) != 0; }

// Bytes of a w x h x d image (d slices of blocks; partial blocks at the edges count whole).
size_t image_bytes(GLenum internal_format, uint32_t w, uint32_t h, uint32_t d);

// RGBA8 texels (rows bottom to top, as GL and the blocks order them) of a w x h x d image from
// its blocks.
void decode_image(GLenum internal_format, const uint8_t* blocks, uint32_t w, uint32_t h, uint32_t d,
                  uint8_t* rgba8);

// The blocks of a w x h x d image from RGBA8 texels (DXT1 RGB ignores alpha), as Mesa's encoder
// (libtxc_dxtn, texcompress_s3tc_tmp.h) writes them. Edge blocks encode only the texels inside
// the image; their other indices are 0 (Mesa's are whatever its scratch memory held).
void encode_image(GLenum internal_format, const uint8_t* rgba8, uint32_t w, uint32_t h, uint32_t d,
                  uint8_t* blocks);

}  // namespace glpt::s3tc
