#version 460
// Tonemap pass: accumulated radiance -> RGBA8, the way GL writes a fixed-function colour to an
// 8-bit framebuffer (clamp to [0,1], round). Alpha is 1 where geometry was traced and the clear
// alpha elsewhere (fractional on anti-aliased silhouettes); pixels outside the viewport and pixels
// no sample hit get the clear colour exactly.
#extension GL_GOOGLE_include_directive : require

#include "shared_types.h"

layout(local_size_x = GLPT_TILE_SIZE, local_size_y = GLPT_TILE_SIZE) in;

layout(std430, set = 0, binding = GLPT_TM_BINDING_ACCUMULATION) readonly buffer Accumulation {
  vec4 accumulation[];
};
layout(std430, set = 0, binding = GLPT_TM_BINDING_OUTPUT) writeonly buffer Output {
  uint rgba8[];
};
layout(std140, set = 0, binding = GLPT_TM_BINDING_FRAME) uniform FrameBlock {
  FrameUniforms frame;
};

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= frame.image.x || pixel.y >= frame.image.y) return;
  uint pixel_index = pixel.y * frame.image.x + pixel.x;
  ivec2 in_viewport = ivec2(pixel) - frame.viewport.xy;
  bool inside = all(greaterThanEqual(in_viewport, ivec2(0))) &&
                all(lessThan(in_viewport, frame.viewport.zw));
  uint total_samples = frame.sampling.w;
  vec4 color = frame.clear_color;
  if (inside && total_samples > 0u) {
    vec4 sum = accumulation[pixel_index];
    if (sum.a > 0.0) {  // some sample hit geometry (otherwise keep the clear colour bit-exact)
      float inverse_count = 1.0 / float(total_samples);
      float coverage = sum.a * inverse_count;
      color = vec4(sum.rgb * inverse_count, mix(frame.clear_color.a, 1.0, coverage));
    }
  }
  rgba8[pixel_index] = packUnorm4x8(clamp(color, 0.0, 1.0));
}
