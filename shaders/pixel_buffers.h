// Per-pixel data in buffers reached by device address (shared_types.h: the denoiser's buffers,
// the radiance channels, the composite's accumulation, the anti-aliasing history): texels of 16
// bytes in layers of one texel per pixel, layer-major, rows bottom to top as GL's window rows.
// Buffers, not storage images: lavapipe calls a function for every image access and stores an
// image texel lane by lane, while a buffer texel is one gather or scatter (docs/denoiser.md,
// "Cost"). The including pass enables GL_EXT_buffer_reference and
// GL_EXT_buffer_reference_uvec2. A buffer has no border: p must lie inside the image.
#ifndef GLPT_SHADERS_PIXEL_BUFFERS_H
#define GLPT_SHADERS_PIXEL_BUFFERS_H
layout(buffer_reference, std430, buffer_reference_align = 16) buffer PixelTexels {
  vec4 texels[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer PixelUintTexels {
  uvec4 texels[];
};
// The texel of pixel p in layer `layer` of a `size` image's buffer.
uint layer_texel(uvec2 size, uint layer, ivec2 p) {
  return layer * size.x * size.y + uint(p.y) * size.x + uint(p.x);
}
vec4 load_texel(uvec2 address, uvec2 size, uint layer, ivec2 p) {
  return PixelTexels(address).texels[layer_texel(size, layer, p)];
}
void store_texel(uvec2 address, uvec2 size, uint layer, ivec2 p, vec4 value) {
  PixelTexels(address).texels[layer_texel(size, layer, p)] = value;
}
// The trace pass's radiance channels (shared_types.h, "radiance channels"): layer c is channel c.
// Written by path_trace.comp, read by the denoiser's temporal pass and the composite pass.
vec4 load_channel(uvec2 address, uvec2 size, uint c, ivec2 p) {
  return load_texel(address, size, c, p);
}
#endif  // GLPT_SHADERS_PIXEL_BUFFERS_H
