// Blending and the colour logic op done in the fragment shader (raster_ff.frag built with
// GLPT_FRAMEBUFFER_OPS 1), reading the colour buffer as an input attachment: one shader variant
// for every blend state. llvmpipe compiles blending into each fragment shader variant, so with
// Vulkan's blend state every new combination of factors and equations costs a variant compile
// (or a load from Mesa's shader cache); here they are push constants
// (RasterPushConstants.framebuffer_ops, rt_core/raster/raster_pipelines.cpp).
//
// The arithmetic is llvmpipe's for unorm8 colour buffers (lp_bld_blend_aos.c, lp_bld_blend.c,
// lp_bld_arit.c), so pixels equal Mesa's: the fragment colour converted to 8 bits as gallivm
// converts floats to unorm8, each product a*b/255 rounded as lp_build_mul_norm rounds it
// (Blinn's (t + (t >> 8) + 128) >> 8, exact), sums and differences saturated, GL_MIN and GL_MAX
// of the unweighted colours, the logic op on the 8-bit values.
#ifndef GLPT_RASTER_FRAMEBUFFER_OPS_H
#define GLPT_RASTER_FRAMEBUFFER_OPS_H

// lp_build_clamped_float_to_unsigned_norm: x * 255/256 + 2^15 leaves x * 255 rounded to
// nearest even in the low 8 bits of the mantissa (two roundings: `precise` keeps them apart).
uvec4 unorm8_of(vec4 x) {
  precise vec4 scaled = clamp(x, 0.0, 1.0) * (255.0 / 256.0);
  precise vec4 biased = scaled + 32768.0;
  return floatBitsToUint(biased) & 0xFFu;
}

uvec4 mul_unorm8(uvec4 a, uvec4 b) {
  uvec4 t = a * b;
  return (t + (t >> 8u) + 128u) >> 8u;
}

// One VkBlendFactor's value for the colour channels (rgb) and the alpha channel: s the source,
// d the destination, c the constant colour. GL_DST_ALPHA of a drawable without alpha has become
// ONE on the host (pipeline_key.cpp); its buffer's alpha holds 255, so SRC_ALPHA_SATURATE
// gives 0 there, as llvmpipe's does without destination alpha.
uvec4 blend_factor(uint factor, uvec4 s, uvec4 d, uvec4 c) {
  uvec4 v;
  switch (factor >> 1u) {  // pairs: the factor and its complement (VkBlendFactor 2..13)
    case 1u:
      v = s;
      break;
    case 2u:
      v = d;
      break;
    case 3u:
      v = uvec4(s.a);
      break;
    case 4u:
      v = uvec4(d.a);
      break;
    case 5u:
      v = c;
      break;
    case 6u:
      v = uvec4(c.a);
      break;
    default:
      v = uvec4(0u);  // ZERO (and ONE below), SRC_ALPHA_SATURATE
      break;
  }
  if (factor == 14u) return uvec4(uvec3(min(s.a, 255u - d.a)), 255u);  // SRC_ALPHA_SATURATE
  return (factor & 1u) != 0u ? 255u - v : v;  // ONE = 255 - ZERO, and every ONE_MINUS_*
}

// VkBlendOp 0..4 of the weighted source a and destination b, or of the unweighted ones.
uvec4 blend_equation(uint op, uvec4 a, uvec4 b, uvec4 s, uvec4 d) {
  switch (op) {
    case 1u:
      return uvec4(max(ivec4(a) - ivec4(b), 0));  // SUBTRACT
    case 2u:
      return uvec4(max(ivec4(b) - ivec4(a), 0));  // REVERSE_SUBTRACT
    case 3u:
      return min(s, d);  // MIN
    case 4u:
      return max(s, d);  // MAX
    default:
      return min(a + b, 255u);  // ADD
  }
}

// VkLogicOp 0..15 on 8-bit values.
uvec4 logic_op(uint op, uvec4 s, uvec4 d) {
  uvec4 r;
  // One line per operation: the table it is.
  // clang-format off
  switch (op) {
    case 0u: r = uvec4(0u); break;
    case 1u: r = s & d; break;
    case 2u: r = s & ~d; break;
    case 3u: r = s; break;
    case 4u: r = ~s & d; break;
    case 5u: r = d; break;
    case 6u: r = s ^ d; break;
    case 7u: r = s | d; break;
    case 8u: r = ~(s | d); break;
    case 9u: r = ~(s ^ d); break;
    case 10u: r = ~d; break;
    case 11u: r = s | ~d; break;
    case 12u: r = ~s; break;
    case 13u: r = ~s | d; break;
    case 14u: r = ~(s & d); break;
    default: r = uvec4(255u); break;
  }
  // clang-format on
  return r & 0xFFu;
}

// The colour written for a fragment of colour `color` over the buffer's `destination`.
// ops: x the four VkBlendFactors (rgb source, rgb destination, alpha source, alpha destination,
// a byte each from the lowest), y the VkBlendOps (rgb, alpha) in bytes 0 and 1, the VkLogicOp
// in byte 2 and in bit 24 whether the logic op replaces blending, z the constant colour as
// unorm8 (r in the lowest byte).
vec4 framebuffer_ops(vec4 color, vec4 destination, uvec4 ops) {
  uvec4 s = unorm8_of(color);
  uvec4 d = uvec4(round(clamp(destination, 0.0, 1.0) * 255.0));
  uvec4 result;
  if ((ops.y & (1u << 24u)) != 0u) {
    result = logic_op((ops.y >> 16u) & 0xFFu, s, d);
  } else {
    uvec4 c = (uvec4(ops.z) >> uvec4(0u, 8u, 16u, 24u)) & 0xFFu;
    uvec4 rgb_source = blend_factor(ops.x & 0xFFu, s, d, c);
    uvec4 rgb_destination = blend_factor((ops.x >> 8u) & 0xFFu, s, d, c);
    uvec4 alpha_source = blend_factor((ops.x >> 16u) & 0xFFu, s, d, c);
    uvec4 alpha_destination = blend_factor(ops.x >> 24u, s, d, c);
    uvec4 source_weight = uvec4(rgb_source.rgb, alpha_source.a);
    uvec4 destination_weight = uvec4(rgb_destination.rgb, alpha_destination.a);
    uvec4 a = mul_unorm8(s, source_weight), b = mul_unorm8(d, destination_weight);
    result.rgb = blend_equation(ops.y & 0xFFu, a, b, s, d).rgb;
    result.a = blend_equation((ops.y >> 8u) & 0xFFu, a, b, s, d).a;
  }
  return vec4(result) / 255.0;
}

#endif
