// Draws rasterized in Mesa's orientation.
//
// Mesa renders window-system buffers (windows, pixmaps, pbuffers, OSMesa's) upside down: its row
// 0 is GL's top row, and llvmpipe flips its edge rule to keep GL's ties (bottom_edge_rule).
// glpt renders them upright (shared/reference/raster-parity.md): Vulkan's top-left rule then
// gives GL's ties exactly, but the interpolated values differ from llvmpipe's in their last bit,
// because llvmpipe evaluates each plane from the other end of the buffer. That last bit decides
// one thing visibly: which of two equally long derivatives the anisotropic filter spreads its
// lookups along, for a texture minified equally in both directions (trigger-rally's HUD text:
// 2 % of its pixels, up to 42 levels apart). So a draw that filters anisotropically and cannot
// tie with Vulkan's rule in a way that matters (filled triangles; no depth or stencil test, whose
// buffer stays upright; no polygon stipple, which reads window positions) is rasterized into a
// copy of its colour buffer with the rows reversed, through a viewport and scissor flipped the
// same way, and copied back after the run of such draws. Interpolation is then llvmpipe's to the
// bit; what still differs are horizontal edges through pixel centres, which Vulkan's top-left
// rule gives the other triangle (rare in 2-D text, whose quads lie on pixel edges). Cost: two
// copies of the colour buffer per run (and two waits in lavapipe), only in frames with such draws.
#include <vector>

#include "raster_types.h"
#include "rt_core/raster/raster_recording.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {

bool RasterRenderer::draws_in_mesa_orientation(const PipelineKey& key, const DynamicDrawState& d,
                                               ColorTargets targets) const {
  // Mesa renders framebuffer objects upright, as glpt does.
  if (buffers_->config.framebuffer_object) return false;
  if (key.gbuffer != 0 || key.pixels != 0 || key.unfilled != 0 ||
      key.topology != static_cast<uint8_t>(RasterTopology::kTriangles))
    return false;
  if (d.depth_test || d.stencil_test) return false;
  if (targets != ColorTargets::kBack && targets != ColorTargets::kFront) return false;
  if ((key.constants[GLPT_SC_FS_FLAGS] & GLPT_FS_POLYGON_STIPPLE) != 0) return false;
  for (int u = 0; u < GLPT_RASTER_MAX_UNITS; ++u)
    if ((key.constants[GLPT_SC_UNIT0 + u] & GLPT_UNIT_ANISOTROPIC) != 0) return true;
  return false;
}

namespace {

// Copies `source` into `destination` (same size) with the rows in reverse order: exact, one
// region per row.
void copy_rows_reversed(VkCommandBuffer cmd, const GpuImage& source, const GpuImage& destination,
                        uint32_t width, uint32_t height) {
  auto before = make_info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  before.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  before.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                           VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
  std::vector<VkImageCopy> rows(height);
  for (uint32_t y = 0; y < height; ++y) {
    VkImageCopy& row = rows[y];
    row.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    row.dstSubresource = row.srcSubresource;
    row.srcOffset = {0, static_cast<int32_t>(y), 0};
    row.dstOffset = {0, static_cast<int32_t>(height - 1 - y), 0};
    row.extent = {width, 1, 1};
  }
  vkCmdCopyImage(cmd, source.handle(), VK_IMAGE_LAYOUT_GENERAL, destination.handle(),
                 VK_IMAGE_LAYOUT_GENERAL, height, rows.data());
  auto after = make_info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  after.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                        VK_ACCESS_INPUT_ATTACHMENT_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                        VK_ACCESS_TRANSFER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                           VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       0, 1, &after, 0, nullptr, 0, nullptr);
}

}  // namespace

void RasterRenderer::use_mesa_orientation(Recording& r, ColorTargets target) {
  if (r.mesa_target == target) return;  // every draw asks: most change nothing
  if (target != ColorTargets::kNone && mesa_image_ &&
      (mesa_image_.info().extent.width != buffers_->config.width ||
       mesa_image_.info().extent.height != buffers_->config.height)) {
    target = ColorTargets::kNone;  // cannot happen (execute() sized it): drawn upright
    if (r.mesa_target == target) return;
  }
  end_rendering(r);
  const uint32_t width = buffers_->config.width, height = buffers_->config.height;
  const auto buffer = [&](ColorTargets t) -> const GpuImage& {
    return t == ColorTargets::kFront ? buffers_->front : buffers_->back;
  };
  if (r.mesa_target != ColorTargets::kNone)
    copy_rows_reversed(r.cmd, mesa_image_, buffer(r.mesa_target), width, height);
  r.mesa_target = target;
  // The viewport, scissor and front face are set again, flipped or not.
  r.dynamic_valid = false;
  if (target == ColorTargets::kNone) return;
  ++r.stats->upside_down_runs;
  // (execute() drops one of another size before it records: nothing may wait here.)
  if (!mesa_image_) {
    GpuImageInfo info;
    info.format = kColorFormat;
    info.extent = {width, height, 1};
    info.usage = kColorUsage;
    mesa_image_ = GpuImage::create(*device_, info);
    mesa_image_.initial_barrier(r.cmd);
  }
  copy_rows_reversed(r.cmd, buffer(target), mesa_image_, width, height);
}

VkImageView RasterRenderer::color_view(const Recording& r, ColorTargets target) const {
  if (target == r.mesa_target) return mesa_image_.view();
  return target == ColorTargets::kFront ? buffers_->front.view() : buffers_->back.view();
}

}  // namespace glpt::rt
