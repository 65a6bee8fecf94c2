// Pixel rectangles (glBitmap, glDrawPixels, glCopyPixels: GL 1.5 3.6.4, 3.7, 4.3.3) and the
// accumulation buffer (glAccum, 4.2.4) in raster mode.
//
// A pixel rectangle is drawn the way Mesa's state tracker draws it (st_cb_bitmap.c,
// st_cb_drawpixels.c): one quad over the zoomed image's window rectangle, through the same
// fixed-function pipelines as primitives, with a fragment shader variant (raster_ff.frag,
// GLPT_PIXELS) that takes each fragment's colour from the image (bitmaps: keeps the fragments
// whose bit is set; depth images: takes the depth), so texturing, fog, the alpha, stencil and
// depth tests, blending, logic op and masks apply as for any fragment. What the fragments carry
// besides the image follows Mesa rather than a literal reading of the spec:
// - the fog coordinate is 0 (Mesa's pass-through vertex shader writes none);
// - bitmaps have the raster's secondary colour (colour images with GL_COLOR_SUM on are not
//   reproduced: see record_pixels);
// - depth images (and depth copies) take the raster colour with no texturing, fog or colour sum;
// - stencil images and copies only write stencil (scissor and stencil write mask apply), drawn
//   here as one masked pass per bit instead of a stencil export;
// - glCopyPixels(GL_COLOR) that Mesa does with a blit (no zoom, no fragment operation that
//   changes the result, see blit_region) copies the pixels, ignoring the colour write mask.
// Texture coordinates are Mesa's: the current ones the front end records, untransformed (bitmaps
// under a texture matrix or texgen, whose coordinates Mesa takes from its bitmap quad, are
// counted in FrameStats::inexpressible).
//
// glAccum runs on the CPU (accumulation.hpp), as in Mesa: the commands before it are executed
// first (raster_renderer.cpp splits the submission), colour is read back and written back.
#include <array>
#include <cmath>
#include <optional>

#include "raster_types.h"
#include "rt_core/raster/pixel_quad.hpp"
#include "rt_core/raster/raster_recording.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

// The state snapshot of a pixel rectangle; nullopt for other commands.
std::optional<rec::StateId> pixel_state_id(const rec::Command& command) {
  if (const auto* b = std::get_if<rec::Bitmap>(&command)) return b->state;
  if (const auto* d = std::get_if<rec::DrawPixels>(&command)) return d->state;
  if (const auto* c = std::get_if<rec::CopyPixels>(&command)) return c->state;
  return std::nullopt;
}

const rec::StateSnapshot* state_of(const rec::FrameRecord& record, const rec::Command& command) {
  const std::optional<rec::StateId> id = pixel_state_id(command);
  return id && *id < record.states.size() ? &record.states[*id] : nullptr;
}

// What a pixel rectangle draws: its image's size, where group (0, 0) lands, the zoom, and how
// its words hold a pixel.
struct PixelImage {
  const rec::RasterPosition* raster = nullptr;
  rec::PixelKind kind = rec::PixelKind::kColor;
  uint32_t width = 0, height = 0;
  glm::vec2 origin{0.0f}, zoom{1.0f};
  uint32_t format = GLPT_PIXELS_RGBA32F;
  bool bitmap = false, copy = false;
};

// Images (glDrawPixels) and copies (glCopyPixels) of colour, depth or stencil.
template <typename Command>
PixelImage describe_image(const Command& c, const rec::StateSnapshot& state,
                          const std::array<uint32_t, 3>& formats) {
  PixelImage p;
  p.raster = &c.raster;
  p.kind = c.kind;
  p.width = c.width;
  p.height = c.height;
  p.origin = glm::vec2(c.raster.window);
  p.zoom = glm::vec2(state.pixel_transfer->zoom_x, state.pixel_transfer->zoom_y);
  p.format = formats[static_cast<size_t>(c.kind)];
  return p;
}

PixelImage describe(const rec::Command& command, const rec::StateSnapshot& state) {
  if (const auto* d = std::get_if<rec::DrawPixels>(&command))
    return describe_image(*d, state,
                          {GLPT_PIXELS_RGBA32F, GLPT_PIXELS_DEPTH32F, GLPT_PIXELS_VALUE32});
  if (const auto* c = std::get_if<rec::CopyPixels>(&command)) {
    PixelImage p =
        describe_image(*c, state, {GLPT_PIXELS_RGBA8, GLPT_PIXELS_DEPTH24, GLPT_PIXELS_VALUE8});
    p.copy = true;
    return p;
  }
  PixelImage p;
  if (const auto* b = std::get_if<rec::Bitmap>(&command)) {
    p.raster = &b->raster;
    p.width = b->width;
    p.height = b->height;
    p.origin = b->origin;  // bitmaps are never zoomed
    p.format = GLPT_PIXELS_VALUE32;
    p.bitmap = true;
  }
  return p;
}

bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// GL_COLOR copies with a pixel transfer that Mesa calls _ImageTransferState.
bool has_color_transfer(const rec::PixelTransferState& t) {
  return t.scale != glm::vec4(1.0f) || t.bias != glm::vec4(0.0f) || t.map_color ||
         t.index_shift != 0 || t.index_offset != 0;
}

VkRect2D intersect(const VkRect2D& a, const VkRect2D& b) {
  const int64_t x0 = std::max(a.offset.x, b.offset.x), y0 = std::max(a.offset.y, b.offset.y);
  const int64_t x1 =
      std::min(int64_t{a.offset.x} + a.extent.width, int64_t{b.offset.x} + b.extent.width);
  const int64_t y1 =
      std::min(int64_t{a.offset.y} + a.extent.height, int64_t{b.offset.y} + b.extent.height);
  return {{int32_t(x0), int32_t(y0)},
          {uint32_t(std::max<int64_t>(0, x1 - x0)), uint32_t(std::max<int64_t>(0, y1 - y0))}};
}

bool overlap(const VkRect2D& a, const VkRect2D& b) {
  return a.offset.x < b.offset.x + int32_t(b.extent.width) &&
         b.offset.x < a.offset.x + int32_t(a.extent.width) &&
         a.offset.y < b.offset.y + int32_t(b.extent.height) &&
         b.offset.y < a.offset.y + int32_t(a.extent.height);
}

bool front_buffer(uint32_t buffer, bool double_buffered) {
  return buffer == GL_FRONT || buffer == GL_FRONT_LEFT || buffer == GL_LEFT || !double_buffered;
}

// Mesa's blit_copy_pixels: a glCopyPixels(GL_COLOR) without zoom whose fragment operations
// cannot change the copied values is a plain copy of the source rectangle, clipped to the
// drawable, then of its destination clipped to the drawable and the scissor box. Mesa takes this
// path only when source and destination are different buffers or do not overlap.
struct Blit {
  VkRect2D source, destination;
};
std::optional<Blit> blit_region(const rec::CopyPixels& copy, const rec::StateSnapshot& state,
                                const rec::DrawableConfig& drawable, ColorTargets targets) {
  const rec::PixelTransferState& t = *state.pixel_transfer;
  const rec::FragmentOpsState& ops = state.raster->ops;
  // Depth and stencil copies never blit on llvmpipe: Mesa requires the destination format to be
  // a render target, which depth/stencil formats are not.
  if (copy.kind != rec::PixelKind::kColor) return std::nullopt;
  const bool keeps_values =
      t.zoom_x == 1.0f && t.zoom_y == 1.0f && !has_color_transfer(t) && !ops.blend &&
      !ops.alpha_test && (!ops.color_logic_op || ops.logic_op == GL_COPY) &&
      (!ops.depth_test || (ops.depth_func == GL_ALWAYS && !ops.depth_write)) &&
      !state.raster->fog.enabled &&
      (!ops.stencil_test || (ops.stencil_fail == GL_KEEP && ops.stencil_depth_fail == GL_KEEP &&
                             ops.stencil_depth_pass == GL_KEEP)) &&
      (targets == ColorTargets::kFront || targets == ColorTargets::kBack);
  if (!keeps_values) return std::nullopt;
  // _mesa_clip_readpixels, then _mesa_clip_drawpixels (which includes the scissor box).
  const VkRect2D read = intersect_with_framebuffer(copy.x, copy.y, int32_t(copy.width),
                                                   int32_t(copy.height), drawable);
  const int32_t dx = int32_t(copy.raster.window.x) - copy.x;
  const int32_t dy = int32_t(copy.raster.window.y) - copy.y;
  const VkRect2D destination =
      intersect({{read.offset.x + dx, read.offset.y + dy}, read.extent}, scissor_of(ops, drawable));
  Blit blit{{{destination.offset.x - dx, destination.offset.y - dy}, destination.extent},
            destination};
  if (destination.extent.width == 0 || destination.extent.height == 0) return blit;
  const bool same_buffer =
      front_buffer(ops.read_buffer, drawable.double_buffered) == (targets == ColorTargets::kFront);
  if (same_buffer && overlap(blit.source, blit.destination)) return std::nullopt;
  return blit;
}

constexpr VkPipelineStageFlags kAttachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags kAttachmentAccess =
    VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stage, VkAccessFlags src_access,
                    VkPipelineStageFlags dst_stage, VkAccessFlags dst_access) {
  auto barrier = make_info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

uint32_t float_bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

}  // namespace

size_t RasterRenderer::begin_pixel_commands(const rec::FrameRecord& record,
                                            const std::vector<size_t>& commands) {
  pixel_words_.clear();
  size_t count = 0;
  for (size_t i : commands)
    if (state_of(record, record.commands[i]) != nullptr) ++count;
  return count;
}

bool RasterRenderer::prepare_pixels(Recording& r, size_t index, Arena& arena,
                                    std::vector<gpu::RasterState>& states, size_t& next_state) {
  const rec::Command& command = r.record->commands[index];
  const rec::StateSnapshot* state = state_of(*r.record, command);
  if (state == nullptr) return false;
  const size_t state_index = next_state++;
  const PixelImage image = describe(command, *state);
  PixelPlan& plan = r.pixels[index];
  plan = PixelPlan();
  if (image.width == 0 || image.height == 0 || !finite(image.origin) || !finite(image.zoom) ||
      !image.raster->valid)
    return true;

  // ---- the image's words
  plan.first_word = static_cast<uint32_t>(pixel_words_.size());
  glm::uvec4 stored(0, 0, image.width, image.height);
  if (const auto* b = std::get_if<rec::Bitmap>(&command)) {
    if (b->bits.size() != size_t{b->width} * b->height) return true;
    pixel_words_.insert(pixel_words_.end(), b->bits.begin(), b->bits.end());
  } else if (const auto* d = std::get_if<rec::DrawPixels>(&command)) {
    const size_t n = size_t{d->width} * d->height;
    if (d->kind == rec::PixelKind::kColor) {
      if (d->color.size() != n) return true;
      for (const glm::vec4& c : d->color)
        for (int k = 0; k < 4; ++k) pixel_words_.push_back(float_bits(c[k]));
    } else if (d->kind == rec::PixelKind::kDepth) {
      if (d->depth.size() != n) return true;
      for (float z : d->depth) pixel_words_.push_back(float_bits(z));
    } else {
      if (d->stencil.size() != n) return true;
      pixel_words_.insert(pixel_words_.end(), d->stencil.begin(), d->stencil.end());
    }
  } else if (const auto* c = std::get_if<rec::CopyPixels>(&command)) {
    const ColorTargets targets =
        resolve_draw_buffer(state->raster->ops.draw_buffer, buffers_->config.double_buffered);
    // Mesa never blits while an occlusion query is active: the copy's fragments count.
    const std::optional<Blit> blit = queries_.query_of(index) == 0
                                         ? blit_region(*c, *state, buffers_->config, targets)
                                         : std::nullopt;
    if (blit) {
      plan.prepared = true;
      plan.blit = true;
      plan.blit_source = blit->source;
      plan.blit_destination = blit->destination;
      return true;
    }
    // The source as far as it lies in the drawable; the rest of the image reads as zero.
    const VkRect2D inside = intersect_with_framebuffer(c->x, c->y, int32_t(c->width),
                                                       int32_t(c->height), buffers_->config);
    stored = glm::uvec4(uint32_t(inside.offset.x - c->x), uint32_t(inside.offset.y - c->y),
                        inside.extent.width, inside.extent.height);
    const size_t texels = size_t{inside.extent.width} * inside.extent.height;
    pixel_words_.resize(pixel_words_.size() +
                        (c->kind == rec::PixelKind::kStencil ? (texels + 3) / 4 : texels));
  }

  // ---- its state entry: the snapshot's, with the image and a window-to-clip mapping
  gpu::RasterState& s = states[state_index];
  s = states[*pixel_state_id(command)];
  s.mvp = glm::mat4(1.0f);
  s.modelview = glm::mat4(1.0f);
  for (glm::mat4& m : s.texture_matrix) m = glm::mat4(1.0f);  // raster coordinates are final
  s.pixel_image = glm::uvec4(image.format, plan.first_word, image.width, image.height);
  const glm::vec2 p0 = image.origin;
  const glm::vec2 p1 =
      image.origin + glm::vec2(float(image.width), float(image.height)) * image.zoom;
  if (image.bitmap) {
    // Bitmaps: integer corners, no zoom; every fragment centre is inside its group.
    s.pixel_table = glm::uvec4(0xFFFFFFFFu, uint32_t(int32_t(p0.x)), uint32_t(int32_t(p0.y)), 0);
  } else {
    // Which group each window column and row of the quad takes, per triangle of Mesa's quad.
    const PixelQuad mesa =
        mesa_pixel_quad(p0, p1, buffers_->config.width, buffers_->config.height, image.copy);
    const glm::vec2 low = glm::min(p0, p1), high = glm::max(p0, p1);
    const int32_t x0 = std::clamp(int32_t(std::floor(low.x)), 0, int32_t(buffers_->config.width));
    const int32_t x1 = std::clamp(int32_t(std::ceil(high.x)), 0, int32_t(buffers_->config.width));
    const int32_t y0 = std::clamp(int32_t(std::floor(low.y)), 0, int32_t(buffers_->config.height));
    const int32_t y1 = std::clamp(int32_t(std::ceil(high.y)), 0, int32_t(buffers_->config.height));
    s.pixel_table = glm::uvec4(uint32_t(pixel_words_.size()), uint32_t(x0), uint32_t(y0),
                               uint32_t(std::max(x1 - x0, 0)));
    for (int32_t x = x0; x < x1; ++x)
      pixel_words_.push_back(uint32_t(mesa_pixel_column(mesa, 0, x, image.width)) |
                             uint32_t(mesa_pixel_column(mesa, 1, x, image.width)) << 16);
    for (int32_t y = y0; y < y1; ++y)
      pixel_words_.push_back(uint32_t(mesa_pixel_row(mesa, 0, y, image.height, image.copy)) |
                             uint32_t(mesa_pixel_row(mesa, 1, y, image.height, image.copy)) << 16);
    s.pixel_diagonal = mesa.diagonal;
  }
  s.pixel_stored = stored;
  const rec::PixelTransferState& transfer = *state->pixel_transfer;
  const bool copied_color = image.copy && image.kind == rec::PixelKind::kColor;
  s.pixel_scale = copied_color ? transfer.scale : glm::vec4(1.0f);
  s.pixel_bias = copied_color ? transfer.bias : glm::vec4(0.0f);
  plan.state = static_cast<uint32_t>(state_index);

  // ---- its quad: the zoomed image's window rectangle in clip space, as Mesa computes it
  // (draw_textured_quad), at the raster position's depth; constant attributes
  const float w = float(buffers_->config.width), h = float(buffers_->config.height);
  const float z = image.raster->window.z * 2.0f - 1.0f;
  const float x0 = p0.x / w * 2.0f - 1.0f, x1 = p1.x / w * 2.0f - 1.0f;
  const float y0 = p0.y / h * 2.0f - 1.0f, y1 = p1.y / h * 2.0f - 1.0f;
  // Mesa's fan: the diagonal from (x0, y1) to (x1, y0) (pixel_quad.hpp assigns fragments to the
  // triangles the same way).
  const glm::vec4 corners[] = {
      {x0, y1, z, 1.0f}, {x1, y1, z, 1.0f}, {x1, y0, z, 1.0f}, {x0, y0, z, 1.0f}};
  const uint32_t indices[] = {0, 1, 2, 0, 2, 3};
  // Colour, secondary colour, fog coordinate.
  const glm::vec4 constants[] = {image.raster->color,
                                 image.bitmap ? image.raster->secondary_color : glm::vec4(0.0f),
                                 glm::vec4(0.0f)};
  DrawGeometry& g = plan.quad;
  const VkDeviceSize at = arena.add(constants, 3);
  g.offsets.fill(at);
  g.strides.fill(0);
  g.offsets[GLPT_RASTER_ATTR_POSITION] = arena.add(corners, 4);
  g.strides[GLPT_RASTER_ATTR_POSITION] = sizeof(glm::vec4);
  g.offsets[GLPT_RASTER_ATTR_COLOR] = at;
  g.offsets[GLPT_RASTER_ATTR_SECONDARY] = at + 16;
  g.offsets[GLPT_RASTER_ATTR_FOG] = at + 32;
  for (int u = 0; u < rec::kMaxTextureUnits; ++u)
    g.offsets[GLPT_RASTER_ATTR_TEXCOORD0 + u] = arena.add(&image.raster->tex_coord[u], 1);
  g.index_offset = arena.add(indices, 6);
  g.index_count = 6;
  plan.prepared = true;
  return true;
}

void RasterRenderer::upload_pixels() {
  const VkDeviceSize bytes = std::max<size_t>(pixel_words_.size(), 4) * sizeof(uint32_t);
  ensure_capacity(*device_, pixels_, bytes,
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  pixels_.write(pixel_words_.data(), pixel_words_.size() * sizeof(uint32_t));
}

void RasterRenderer::record_pixels(Recording& r, size_t index) {
  const PixelPlan& plan = r.pixels[index];
  if (!plan.prepared) return;
  const rec::Command& command = r.record->commands[index];
  const rec::StateSnapshot& state = *state_of(*r.record, command);
  const PixelImage image = describe(command, state);
  const rec::FragmentOpsState& ops = state.raster->ops;
  const ColorTargets targets =
      resolve_draw_buffer(ops.draw_buffer, buffers_->config.double_buffered);
  const GpuImage& read_color = front_buffer(ops.read_buffer, buffers_->config.double_buffered)
                                   ? buffers_->front
                                   : buffers_->back;
  const VkImageAspectFlags aspect = image.kind == rec::PixelKind::kColor ? VK_IMAGE_ASPECT_COLOR_BIT
                                    : image.kind == rec::PixelKind::kDepth
                                        ? VK_IMAGE_ASPECT_DEPTH_BIT
                                        : VK_IMAGE_ASPECT_STENCIL_BIT;
  const GpuImage& source =
      image.kind == rec::PixelKind::kColor ? read_color : buffers_->depth_stencil;

  // ---- glCopyPixels: the source first (a plain copy when Mesa blits)
  if (image.copy) {
    end_rendering(r);
    memory_barrier(r.cmd, kAttachmentStages, kAttachmentAccess, VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
    if (plan.blit) {
      if (plan.blit_destination.extent.width == 0 || plan.blit_destination.extent.height == 0)
        return;
      const GpuImage& destination = image.kind != rec::PixelKind::kColor ? buffers_->depth_stencil
                                    : targets == ColorTargets::kFront    ? buffers_->front
                                                                         : buffers_->back;
      if ((image.kind == rec::PixelKind::kDepth && buffers_->config.depth_bits == 0) ||
          (image.kind == rec::PixelKind::kStencil && buffers_->config.stencil_bits == 0))
        return;
      VkImageCopy region{};
      region.srcSubresource = {aspect, 0, 0, 1};
      region.dstSubresource = region.srcSubresource;
      region.srcOffset = {plan.blit_source.offset.x, plan.blit_source.offset.y, 0};
      region.dstOffset = {plan.blit_destination.offset.x, plan.blit_destination.offset.y, 0};
      region.extent = {plan.blit_destination.extent.width, plan.blit_destination.extent.height, 1};
      vkCmdCopyImage(r.cmd, source.handle(), VK_IMAGE_LAYOUT_GENERAL, destination.handle(),
                     VK_IMAGE_LAYOUT_GENERAL, 1, &region);
      memory_barrier(r.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                     kAttachmentStages, kAttachmentAccess);
      return;
    }
    const auto& copy = std::get<rec::CopyPixels>(command);
    const VkRect2D inside = intersect_with_framebuffer(copy.x, copy.y, int32_t(copy.width),
                                                       int32_t(copy.height), buffers_->config);
    if (inside.extent.width > 0 && inside.extent.height > 0) {
      VkBufferImageCopy region{};
      region.bufferOffset = VkDeviceSize{plan.first_word} * sizeof(uint32_t);
      region.imageSubresource = {aspect, 0, 0, 1};
      region.imageOffset = {inside.offset.x, inside.offset.y, 0};
      region.imageExtent = {inside.extent.width, inside.extent.height, 1};
      vkCmdCopyImageToBuffer(r.cmd, source.handle(), VK_IMAGE_LAYOUT_GENERAL, pixels_.handle(), 1,
                             &region);
    }
    memory_barrier(r.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | kAttachmentStages,
                   VK_ACCESS_SHADER_READ_BIT | kAttachmentAccess);
  }

  const VkViewport viewport{
      0.0f, 0.0f, float(buffers_->config.width), float(buffers_->config.height), 0.0f, 1.0f};
  const VkRect2D scissor = scissor_of(ops, buffers_->config);
  if (scissor.extent.width == 0 || scissor.extent.height == 0) return;
  auto draw_quad = [&](uint32_t keep) {
    push_constants(
        r, gpu::RasterPushConstants{glm::uvec4(0, 0, keep, 0), glm::uvec4(0u), glm::uvec4(0u)});
    queries_.before_draw(r.cmd, r.counting);
    draw_geometry(r, plan.quad, plan.state);
  };

  // ---- stencil images: only the stencil buffer, under the scissor and the stencil write mask
  // (GL 1.5 4.3.1): every written bit cleared, then set again bit by bit where the image has it
  if (image.kind == rec::PixelKind::kStencil) {
    const uint32_t stencil_max = (1u << std::min(buffers_->config.stencil_bits, 8u)) - 1;
    const uint32_t write_mask = ops.stencil_write_mask & stencil_max;
    // Mesa draws the quad (its fragments count in an occlusion query) even when it writes nothing.
    if ((buffers_->config.stencil_bits == 0 || write_mask == 0) && r.counting == 0) return;
    PipelineKey key;
    key.topology = static_cast<uint8_t>(RasterTopology::kTriangles);
    key.polygon_mode = VK_POLYGON_MODE_FILL;
    key.line_mode = VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT;
    key.logic_op = VK_LOGIC_OP_COPY;
    key.attachments = 1;
    key.pixels = 1;
    begin_rendering(r, ColorTargets::kNone);
    bind(r, key, nullptr);
    DynamicDrawState d;
    d.stencil_test = true;
    d.stencil_fail = d.stencil_depth_fail = d.stencil_pass = VK_STENCIL_OP_REPLACE;
    d.stencil_compare = VK_COMPARE_OP_ALWAYS;
    d.stencil_compare_mask = 0xFF;
    d.stencil_write_mask = write_mask;
    d.stencil_reference = 0;
    set_dynamic_state(r, d, viewport, scissor);
    draw_quad(GLPT_PIXELS_KEEP_ALL);  // every fragment of Mesa's one quad: the pass that counts
    queries_.stop(r.cmd);
    r.counting = 0;
    d.stencil_reference = 0xFF;
    for (uint32_t bit = 0; bit < 8; ++bit) {
      if (!(write_mask & (1u << bit))) continue;
      d.stencil_write_mask = 1u << bit;
      set_dynamic_state(r, d, viewport, scissor);
      draw_quad(GLPT_PIXELS_KEEP_BIT | bit);
    }
    return;
  }

  // ---- colour and depth images, bitmaps: fragments through the fixed-function pipeline. The
  // state as pixel rectangles see it: no lighting, texgen, clip planes, culling, polygon modes,
  // stipple or offset; depth images without texturing, fog and colour sum (Mesa's z program).
  const bool depth_image = image.kind == rec::PixelKind::kDepth;
  auto transform = std::make_shared<rec::TransformState>(*state.transform);
  transform->clip_plane_mask = 0;
  transform->normalize = transform->rescale_normal = false;
  auto texturing = std::make_shared<rec::TexturingState>(*state.texturing);
  // The command carries Mesa's texture coordinates (the current ones, see the front end): no
  // texgen or texture matrix applies. Bitmaps under a texture matrix or texgen get the
  // coordinates of Mesa's bitmap quad instead, which are not reproduced.
  bool unreproduced_coords = false;
  for (rec::TextureUnitState& unit : texturing->units) {
    if (image.bitmap && unit.target != 0 &&
        (unit.texgen_mask != 0 || unit.matrix != glm::mat4(1.0f)))
      unreproduced_coords = true;
    unit.texgen_mask = 0;
    unit.matrix = glm::mat4(1.0f);
    if (depth_image) unit = rec::TextureUnitState{};
  }
  auto raster = std::make_shared<rec::RasterState>(*state.raster);
  raster->primitive = rec::PrimitiveState{};
  if (depth_image) raster->fog.enabled = false;
  const rec::StateSnapshot pixel_state{transform, std::make_shared<rec::LightingState>(), texturing,
                                       raster, state.pixel_transfer};
  DrawContext context;
  context.topology = RasterTopology::kTriangles;
  context.targets = targets;
  context.drawable_has_alpha = buffers_->config.has_alpha;
  context.stencil_bits = buffers_->config.stencil_bits;
  DrawSetup setup = make_draw_setup(pixel_state, context);
  // Not reproduced: the texture coordinates of bitmaps under a texture matrix or texgen; Mesa's
  // colour images with GL_COLOR_SUM on (their colour becomes unrelated
  // to the image: the fragment program reads inputs the pass-through shader lacks); the colour
  // maps of copies (the record does not carry the maps yet); and, for zoomed images that cross
  // the window's edge, the groups of fragments on group edges (Mesa clips the quad first).
  const rec::LightingState& lighting = *state.lighting;
  const bool color_sum = lighting.enabled ? lighting.separate_specular : ops.color_sum;
  const glm::vec2 corner = image.origin + glm::vec2(image.width, image.height) * image.zoom;
  const bool clipped = std::min(image.origin.x, corner.x) < 0.0f ||
                       std::min(image.origin.y, corner.y) < 0.0f ||
                       std::max(image.origin.x, corner.x) > float(buffers_->config.width) ||
                       std::max(image.origin.y, corner.y) > float(buffers_->config.height);
  const bool whole_zoom = image.zoom == glm::round(image.zoom);
  if (setup.approximated || unreproduced_coords || (color_sum && !image.bitmap && !depth_image) ||
      (image.copy && state.pixel_transfer->map_color) || (clipped && !whole_zoom))
    ++r.stats->inexpressible;
  PipelineKey& key = setup.key;
  key.constants[GLPT_SC_VS_FLAGS] = GLPT_VS_FOG_COORD_SOURCE;  // the fog coordinate is 0
  uint32_t fs = key.constants[GLPT_SC_FS_FLAGS] & ~GLPT_FS_COLOR_SUM;
  if (image.bitmap && color_sum) fs |= GLPT_FS_COLOR_SUM;
  key.constants[GLPT_SC_FS_FLAGS] = fs;
  key.pixels = depth_image ? 2 : 1;
  DynamicDrawState d = setup.dynamic;
  d.cull = VK_CULL_MODE_NONE;
  d.depth_bias = false;
  if (buffers_->config.depth_bits == 0) d.depth_test = d.depth_write = false;
  begin_rendering(r, targets);
  bind(r, key, &pixel_state);
  set_dynamic_state(r, d, viewport, scissor);
  draw_quad(image.bitmap ? GLPT_PIXELS_KEEP_NONZERO : GLPT_PIXELS_KEEP_ALL);
}

bool RasterRenderer::accumulation_touches_color(const rec::Accum& accum) {
  return accum.op == GL_ACCUM || accum.op == GL_LOAD || accum.op == GL_RETURN;
}

void RasterRenderer::clear_accum(const rec::FrameRecord& record, const rec::Clear& clear) {
  if (buffers_->accum.width() == 0 || clear.state >= record.states.size()) return;
  const VkRect2D rect = scissor_of(record.states[clear.state].raster->ops, buffers_->config);
  buffers_->accum.clear({rect.offset.x, rect.offset.y, rect.extent.width, rect.extent.height},
                        clear.accum);
}

void RasterRenderer::execute_accum(const rec::FrameRecord& record, const rec::Accum& accum) {
  if (buffers_->accum.width() == 0 || accum.state >= record.states.size()) return;
  const rec::FragmentOpsState& ops = record.states[accum.state].raster->ops;
  const VkRect2D scissor = scissor_of(ops, buffers_->config);
  const PixelRect rect{scissor.offset.x, scissor.offset.y, scissor.extent.width,
                       scissor.extent.height};
  if (rect.pixels() == 0) return;
  std::vector<uint8_t> rgba;
  // Mesa skips the operations that would not change the buffer.
  switch (accum.op) {
    case GL_ADD:
      if (accum.value != 0.0f) buffers_->accum.add(rect, accum.value);
      return;
    case GL_MULT:
      if (accum.value != 1.0f) buffers_->accum.multiply(rect, accum.value);
      return;
    case GL_ACCUM:
    case GL_LOAD:
      if (accum.op == GL_ACCUM && accum.value == 0.0f) return;
      read_current_color(ops.read_buffer, rect.x, rect.y, rect.width, rect.height, rgba);
      buffers_->accum.accumulate(rect, rgba, accum.value, accum.op == GL_LOAD);
      return;
    case GL_RETURN:
      break;
    default:
      return;
  }
  const ColorTargets targets =
      resolve_draw_buffer(ops.draw_buffer, buffers_->config.double_buffered);
  std::array<bool, 4> mask = ops.color_write;
  mask[3] = mask[3] && buffers_->config.has_alpha;  // a drawable without alpha keeps alpha 1
  for (const GpuImage* image : {&buffers_->front, &buffers_->back}) {
    const bool front = image == &buffers_->front;
    if (!(targets == ColorTargets::kFrontAndBack || (front && targets == ColorTargets::kFront) ||
          (!front && targets == ColorTargets::kBack)))
      continue;
    read_image(*image, VK_IMAGE_ASPECT_COLOR_BIT, 4, rect.x, rect.y, rect.width, rect.height, rgba);
    swap_red_and_blue(rgba.data(), rect.pixels());  // BGRA8 buffers
    buffers_->accum.return_to(rect, accum.value, mask, rgba);
    write_image(*image, {{rect.x, rect.y}, {rect.width, rect.height}}, rgba);
  }
}

}  // namespace glpt::rt
