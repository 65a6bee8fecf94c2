// GL_GENERATE_MIPMAP (SGIS_generate_mipmap, GL 1.4 3.8.8): the levels above the base level are
// recomputed whenever the base level changes.
#pragma once

namespace glpt {

class TextureObject;

// Replaces levels base_level + 1 .. min(max_level, the 1x1x1 level) of `face` with images derived
// from the base level, the way Mesa 25 on llvmpipe does it: each level is sampled from the one
// before at its texel centres with bilinear (3-D: trilinear) filtering, clamped to the edge, with
// weights in 1/256 steps and results rounded up at one half, in the stored precision. For
// power-of-two sizes that is a 2x2(x2) box filter averaging pairs as (a + b + 1) / 2 per axis.
void generate_mipmaps(TextureObject& object, int face);

}  // namespace glpt
