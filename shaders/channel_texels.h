// The trace pass's radiance channels (shared_types.h, "radiance channels"): one buffer reached by
// device address, a vec4 layer per channel, layer-major. Written by path_trace.comp, read by the
// denoiser's temporal pass and the composite pass. The including pass enables
// GL_EXT_buffer_reference and GL_EXT_buffer_reference_uvec2; pixels must lie inside the image
// (a buffer has no border).
#ifndef GLPT_SHADERS_CHANNEL_TEXELS_H
#define GLPT_SHADERS_CHANNEL_TEXELS_H
layout(buffer_reference, std430, buffer_reference_align = 16) buffer ChannelTexels {
  vec4 texels[];
};
// Channel c of pixel p of a `size` image, in the channels at `address`.
uint channel_texel(uvec2 size, uint c, ivec2 p) {
  return c * size.x * size.y + uint(p.y) * size.x + uint(p.x);
}
vec4 load_channel(uvec2 address, uvec2 size, uint c, ivec2 p) {
  return ChannelTexels(address).texels[channel_texel(size, c, p)];
}
void store_channel(uvec2 address, uvec2 size, uint c, ivec2 p, vec4 value) {
  ChannelTexels(address).texels[channel_texel(size, c, p)] = value;
}
#endif  // GLPT_SHADERS_CHANNEL_TEXELS_H
