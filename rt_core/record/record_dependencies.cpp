#include "rt_core/record/record_dependencies.hpp"

#include <variant>

#include "gl/gl_enums.h"

namespace glpt::rec {
namespace {

// The colour buffers a draw or read buffer names (GL 1.5 4.2.1); a single-buffered drawable's
// one buffer is its front buffer, which GL_BACK names too (as Mesa draws it).
uint8_t colour_buffers(uint32_t buffer, bool double_buffered) {
  switch (buffer) {
    case GL_FRONT:
    case GL_FRONT_LEFT:
      return kFrontColor;
    case GL_BACK:
    case GL_BACK_LEFT:
      return double_buffered ? kBackColor : kFrontColor;
    case GL_LEFT:
    case GL_FRONT_AND_BACK:
      return double_buffered ? kFrontColor | kBackColor : kFrontColor;
    default:
      // A framebuffer object's colour attachment is its target's one (front) buffer.
      if (buffer >= GL_COLOR_ATTACHMENT0_EXT && buffer <= GL_COLOR_ATTACHMENT15_EXT)
        return kFrontColor;
      return 0;  // GL_NONE, right buffers: nothing
  }
}

bool covers_drawable(const FragmentOpsState& ops, const DrawableConfig& drawable) {
  if (!ops.scissor_test) return true;
  const auto& box = ops.scissor_box;
  return box[0] <= 0 && box[1] <= 0 && int64_t{box[0]} + box[2] >= int64_t{drawable.width} &&
         int64_t{box[1]} + box[3] >= int64_t{drawable.height};
}

// What a fragment-producing command under `ops` reads and changes: the colour buffers it draws
// into (blended or not, it leaves the rest of them as they were), depth when tested (written
// only with depth writes on), stencil when tested (written unless every op keeps it).
void add_fragment_access(const FragmentOpsState& ops, bool double_buffered, uint8_t& reads,
                         uint8_t& writes) {
  const uint8_t colour = colour_buffers(ops.draw_buffer, double_buffered);
  reads |= colour;
  if (ops.color_write[0] || ops.color_write[1] || ops.color_write[2] || ops.color_write[3])
    writes |= colour;
  if (ops.depth_test) {
    reads |= kDepthBuffer;
    if (ops.depth_write) writes |= kDepthBuffer;
  }
  if (ops.stencil_test) {
    reads |= kStencilBuffer;
    if (ops.stencil_write_mask != 0 &&
        (ops.stencil_fail != GL_KEEP || ops.stencil_depth_fail != GL_KEEP ||
         ops.stencil_depth_pass != GL_KEEP))
      writes |= kStencilBuffer;
  }
}

uint8_t pixel_buffer(PixelKind kind, uint32_t colour_buffer, bool double_buffered) {
  switch (kind) {
    case PixelKind::kColor:
      return colour_buffers(colour_buffer, double_buffered);
    case PixelKind::kDepth:
      return kDepthBuffer;
    case PixelKind::kStencil:
      return kStencilBuffer;
  }
  return 0;
}

}  // namespace

RecordAccess record_access(const FrameRecord& record, const DrawableConfig& drawable, bool swaps) {
  const bool doubled = drawable.double_buffered;
  RecordAccess access;
  // Reads of a buffer the record has not overwritten yet depend on what was there before.
  auto read = [&](uint8_t buffers) { access.depends |= buffers & ~access.overwrites; };
  for (const Command& command : record.commands) {
    uint8_t reads = 0, writes = 0;
    if (const auto* clear = std::get_if<Clear>(&command)) {
      const FragmentOpsState& ops = record.states[clear->state].raster->ops;
      const bool whole = covers_drawable(ops, drawable);
      uint8_t cleared = 0;
      if ((clear->mask & GL_COLOR_BUFFER_BIT) != 0 &&
          (ops.color_write[0] || ops.color_write[1] || ops.color_write[2] || ops.color_write[3])) {
        writes |= colour_buffers(ops.draw_buffer, doubled);
        if (ops.color_write[0] && ops.color_write[1] && ops.color_write[2] && ops.color_write[3])
          cleared |= colour_buffers(ops.draw_buffer, doubled);
      }
      if ((clear->mask & GL_DEPTH_BUFFER_BIT) != 0 && ops.depth_write) {
        writes |= kDepthBuffer;
        cleared |= kDepthBuffer;
      }
      if ((clear->mask & GL_STENCIL_BUFFER_BIT) != 0 && (ops.stencil_write_mask & 0xFFu) != 0) {
        writes |= kStencilBuffer;
        if ((ops.stencil_write_mask & 0xFFu) == 0xFFu) cleared |= kStencilBuffer;
      }
      if ((clear->mask & GL_ACCUM_BUFFER_BIT) != 0) {
        writes |= kAccumBuffer;
        cleared |= kAccumBuffer;
      }
      // A partial clear (scissored, or some channels or stencil bits masked) leaves the rest of
      // the buffer as it was: a dependency, unless the buffer was already overwritten whole.
      read(whole ? static_cast<uint8_t>(writes & ~cleared) : writes);
      if (whole) access.overwrites |= cleared;
    } else if (const auto* draw = std::get_if<Draw>(&command)) {
      add_fragment_access(record.states[draw->state].raster->ops, doubled, reads, writes);
    } else if (const auto* bitmap = std::get_if<Bitmap>(&command)) {
      add_fragment_access(record.states[bitmap->state].raster->ops, doubled, reads, writes);
    } else if (const auto* pixels = std::get_if<DrawPixels>(&command)) {
      const FragmentOpsState& ops = record.states[pixels->state].raster->ops;
      add_fragment_access(ops, doubled, reads, writes);
      if (pixels->kind == PixelKind::kStencil) reads |= kStencilBuffer, writes |= kStencilBuffer;
    } else if (const auto* copy = std::get_if<CopyPixels>(&command)) {
      const FragmentOpsState& ops = record.states[copy->state].raster->ops;
      add_fragment_access(ops, doubled, reads, writes);
      reads |= pixel_buffer(copy->kind, ops.read_buffer, doubled);
      if (copy->kind == PixelKind::kStencil) writes |= kStencilBuffer;
    } else if (const auto* accum = std::get_if<Accum>(&command)) {
      const FragmentOpsState& ops = record.states[accum->state].raster->ops;
      reads |= kAccumBuffer;
      writes |= kAccumBuffer;
      if (accum->op == GL_ACCUM || accum->op == GL_LOAD)
        reads |= colour_buffers(ops.read_buffer, doubled);
      if (accum->op == GL_RETURN) {
        reads |= colour_buffers(ops.draw_buffer, doubled);  // scissored, masked: the rest stays
        writes |= colour_buffers(ops.draw_buffer, doubled);
      }
    } else if (const auto* read_back = std::get_if<Read>(&command)) {
      reads |= pixel_buffer(read_back->kind, read_back->buffer, doubled);
    }
    read(reads);
    access.writes |= writes;
  }
  if (swaps && doubled) {
    // The swap copies the back buffer into the front buffer whole.
    access.writes |= kFrontColor;
    access.overwrites |= kFrontColor;
  }
  return access;
}

}  // namespace glpt::rec
