// The packed key of a raster pipeline, derived from a state snapshot (cf. gl4es fpe_state_t,
// Mesa's ffvertex_prog / texenvprogram keys): the shader variant as specialization constants and
// the fixed-function state Vulkan bakes into a pipeline. Everything else (viewport, scissor,
// depth and stencil tests, culling, depth bias, line width and stipple, blend constant) is
// dynamic state set per draw, so unrelated state changes never compile a pipeline.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "rt_core/record/frame_record.hpp"

namespace glpt::rt {

enum class RasterTopology : uint8_t { kPoints, kLines, kLineStrip, kTriangles };

// Which colour attachments a draw writes: GL's draw buffer resolved against the drawable.
// kGBuffer: path-traced mode's G-buffer attachments (gbuffer_targets.hpp) instead of colour.
enum class ColorTargets : uint8_t { kNone, kFront, kBack, kFrontAndBack, kGBuffer };

struct PipelineKey {
  // Specialization constants, indexed by constant_id (GLPT_SC_* in raster_types.h).
  static constexpr int kConstants = 24;
  uint32_t constants[kConstants];
  uint8_t clip_variant;  // the vertex shader with gl_ClipDistance
  uint8_t flat;          // the fragment shader with flat colours
  uint8_t topology;      // RasterTopology
  uint8_t polygon_mode;  // VkPolygonMode
  uint8_t line_mode;     // VkLineRasterizationModeEXT
  uint8_t line_stipple;
  uint8_t blend;
  uint8_t blend_src_rgb, blend_dst_rgb, blend_src_alpha, blend_dst_alpha;  // VkBlendFactor
  uint8_t blend_op_rgb, blend_op_alpha;                                    // VkBlendOp
  uint8_t logic_op_enable, logic_op;                                       // VkLogicOp
  uint8_t color_write_mask;                                                // VkColorComponentFlags
  uint8_t attachments;  // colour attachments the pipeline renders to (1 or 2)
  uint8_t unfilled;     // polygon mode through the geometry shader: 0 no, 1 lines, 2 points
  uint8_t pixels;       // pixel rectangles: the GLPT_PIXELS fragment shader (1, or 2 with depth)
  uint8_t gbuffer;      // path-traced mode's G-buffer pass: G-buffer shaders and attachments
  // Blending or the logic op in the fragment shader (raster_framebuffer_ops.h); the blend and
  // logic-op fields above then go to push constants (framebuffer_ops_constants()).
  uint8_t framebuffer_ops;
  // Explicit, so that copies keep it zero: keys compare and hash as bytes (implicit padding
  // would carry whatever a copy leaves there, and equal states would miss their pipeline).
  uint8_t padding[3];

  PipelineKey() { std::memset(this, 0, sizeof *this); }
  bool operator==(const PipelineKey& o) const { return std::memcmp(this, &o, sizeof *this) == 0; }
};
static_assert(sizeof(PipelineKey) % 4 == 0);
static_assert(std::has_unique_object_representations_v<PipelineKey>, "no implicit padding");

struct PipelineKeyHash {
  size_t operator()(const PipelineKey& key) const;
};

// One face's stencil state, as Vulkan takes it.
struct StencilFaceOps {
  VkStencilOp fail = VK_STENCIL_OP_KEEP, depth_fail = VK_STENCIL_OP_KEEP, pass = VK_STENCIL_OP_KEEP;
  VkCompareOp compare = VK_COMPARE_OP_ALWAYS;
  uint32_t compare_mask = 0xFF, write_mask = 0xFF, reference = 0;

  bool operator==(const StencilFaceOps&) const = default;
};

// Per-draw state that is dynamic in every pipeline.
struct DynamicDrawState {
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  VkFrontFace front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  bool depth_test = false, depth_write = false;
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
  bool stencil_test = false;
  VkStencilOp stencil_fail = VK_STENCIL_OP_KEEP, stencil_depth_fail = VK_STENCIL_OP_KEEP,
              stencil_pass = VK_STENCIL_OP_KEEP;
  VkCompareOp stencil_compare = VK_COMPARE_OP_ALWAYS;
  uint32_t stencil_compare_mask = 0xFF, stencil_write_mask = 0xFF, stencil_reference = 0;
  // EXT_stencil_two_side: back-facing polygons use back_stencil; otherwise both faces use the
  // fields above.
  bool separate_back_stencil = false;
  StencilFaceOps back_stencil;

  StencilFaceOps front_stencil() const {
    return {stencil_fail,         stencil_depth_fail, stencil_pass,     stencil_compare,
            stencil_compare_mask, stencil_write_mask, stencil_reference};
  }
  bool depth_bias = false;
  float depth_bias_constant = 0.0f, depth_bias_slope = 0.0f;
  float line_width = 1.0f;
  uint32_t line_stipple_factor = 1;
  uint16_t line_stipple_pattern = 0xFFFF;
  glm::vec4 blend_constant{0.0f};
};

// What a draw needs beyond the snapshot: its primitive class and the drawable.
struct DrawContext {
  RasterTopology topology = RasterTopology::kTriangles;
  ColorTargets targets = ColorTargets::kBack;
  bool drawable_has_alpha = true;
  uint32_t stencil_bits = 8;
  // For triangles drawn in two passes (front and back faces with different polygon modes): the
  // face this pass draws (VK_CULL_MODE_BACK_BIT: front faces only, FRONT_BIT: back faces only).
  VkCullModeFlags face_pass = VK_CULL_MODE_NONE;
};

struct DrawSetup {
  PipelineKey key;
  DynamicDrawState dynamic;
  bool skip = false;  // nothing can be drawn (e.g. both faces culled)
  // Front and back faces have different polygon modes: draw twice, once per face (face_pass).
  bool split_faces = false;
  bool approximated = false;  // a state raster mode cannot express exactly yet (counted)
};

DrawSetup make_draw_setup(const rec::StateSnapshot& state, const DrawContext& context);

// The varyings (GLPT_VARYING_* bits of raster_types.h) the pipeline's fragment stage reads beyond
// the front colour: its shaders must declare them (raster_varyings.h). The G-buffer pass, pixel
// rectangles and unfilled polygons (geometry shaders) take them all.
uint32_t varyings_read(const PipelineKey& key);

// RasterPushConstants.framebuffer_ops of a key's blend and logic-op state and the blend
// constant (raster_framebuffer_ops.h has the layout).
glm::uvec4 framebuffer_ops_constants(const PipelineKey& key, const glm::vec4& blend_constant);

// The GL draw buffer of a state resolved against the drawable.
ColorTargets resolve_draw_buffer(uint32_t draw_buffer, bool double_buffered);

}  // namespace glpt::rt
