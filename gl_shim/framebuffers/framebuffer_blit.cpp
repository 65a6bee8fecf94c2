// glBlitFramebufferEXT (EXT_framebuffer_blit): a rectangle of the read framebuffer copied, scaled
// and mirrored, into the draw framebuffer, past every fragment operation but the scissor test
// (GL 3.0 4.3.3). Validation and its order are Mesa 25's (src/mesa/main/blit.c).
//
// glpt reads the source as glReadPixels of the read framebuffer would (read_framebuffer: what the
// read buffer stores), samples it on the CPU at each destination pixel's centre mapped into the
// source rectangle (nearest: the texel that holds it; linear: the four around it, weighted,
// clamped to the read buffer's edge; a sample on a texel edge goes as in Mesa, see AxisSpan) and
// writes the result into the draw framebuffer's buffers (rt::Renderer::write_pixels) once what was
// drawn before is rendered. Destination pixels whose sample falls outside the read buffer are left
// as they are, as Mesa clips the rectangles
// (_mesa_clip_blit); GL leaves them undefined.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/framebuffer_access.hpp"
#include "gl_shim/framebuffers/framebuffer_objects.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/pixels/bitmap_cache.hpp"
#include "gl_shim/state/out_of_memory.hpp"

namespace glpt {
namespace {

constexpr GLbitfield kBlitBuffers =
    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;

// The depth and stencil bits of the image at a framebuffer's depth or stencil attachment point,
// as Mesa compares them (the window's is one packed image of the visual's depth and stencil).
struct DepthStencilImage {
  bool exists = false;
  int depth_bits = 0, stencil_bits = 0;
};

DepthStencilImage depth_stencil_image(const Context& ctx, const FramebufferObject* fb,
                                      bool depth_point) {
  if (fb == nullptr) {
    const rec::DrawableConfig& d = window_drawable(ctx);
    const bool exists = depth_point ? d.depth_bits != 0 : d.stencil_bits != 0;
    if (!exists) return {};
    return {true, int(d.depth_bits), int(d.stencil_bits)};
  }
  const Attachment& a = depth_point ? fb->depth : fb->stencil;
  if (a.type == GL_NONE) return {};
  const std::array<GLint, 6> bits = attachment_bits(a);
  return {true, bits[4], bits[5]};
}

// Mesa's validate_stencil_buffer (`depth_point` false) and validate_depth_buffer: where `mask`
// asks for `bit` and both framebuffers have an image at that point, its bits must match (and the
// other component's too where both images have it): false (GL_INVALID_OPERATION) otherwise; where
// either has none, `bit` is silently dropped from `mask`.
bool depth_stencil_compatible(const Context& ctx, const FramebufferObject* read_fb,
                              const FramebufferObject* draw_fb, bool depth_point, GLbitfield bit,
                              GLbitfield& mask) {
  if (!(mask & bit)) return true;
  const DepthStencilImage r = depth_stencil_image(ctx, read_fb, depth_point);
  const DepthStencilImage d = depth_stencil_image(ctx, draw_fb, depth_point);
  if (!r.exists || !d.exists) {
    mask &= ~bit;
    return true;
  }
  const int r_own = depth_point ? r.depth_bits : r.stencil_bits;
  const int d_own = depth_point ? d.depth_bits : d.stencil_bits;
  const int r_other = depth_point ? r.stencil_bits : r.depth_bits;
  const int d_other = depth_point ? d.stencil_bits : d.depth_bits;
  return r_own == d_own && !(r_other > 0 && d_other > 0 && r_other != d_other);
}

// The read framebuffer's read buffer names an image (an attachment of an object, or a window
// colour buffer).
bool reads_color(const FramebufferObject* fb, uint32_t read_buffer) {
  if (read_buffer == GL_NONE) return false;
  if (fb == nullptr) return true;
  const uint32_t i = read_buffer - GL_COLOR_ATTACHMENT0_EXT;
  return i < uint32_t(kMaxColorAttachments) && fb->color[i].type != GL_NONE;
}

// One axis of the blit: the destination pixels [lo, hi) whose sample lies in the read buffer,
// and for each the source texels it takes (nearest: `first`; linear: `first` and `second`, the
// latter weighted by `weight`). Source texels used: [source_lo, source_hi).
struct BlitAxis {
  int lo = 0, hi = 0;
  std::vector<int> first, second;
  std::vector<float> weight;
  int source_lo = INT_MAX, source_hi = INT_MIN;
};

// Where one axis's rectangles are, and whether the framebuffer on each side is stored top row
// first (a window system's, in Mesa: _mesa_fb_orientation), which decides which texel a sample
// exactly on a texel edge takes (the lower one in the stored order: measured against OSMesa,
// whose window is such a framebuffer, a 2:1 minification of the window takes its even rows and
// of an object's texture its odd ones). `source_size` and `destination_size` are the buffers'.
struct AxisSpan {
  int64_t src0, src1, dst0, dst1;
  int64_t source_size, destination_size;
  bool source_top_first = false, destination_top_first = false;
};

BlitAxis blit_axis(AxisSpan a, int64_t bound_lo, int64_t bound_hi, bool linear) {
  BlitAxis out;
  const int64_t lo = std::max(std::min(a.dst0, a.dst1), bound_lo);
  const int64_t hi = std::min(std::max(a.dst0, a.dst1), bound_hi);
  // In the stored order, as Mesa's do_blit_framebuffer hands the rectangles to gallium.
  if (a.source_top_first) {
    a.src0 = a.source_size - a.src0;
    a.src1 = a.source_size - a.src1;
  }
  if (a.destination_top_first) {
    a.dst0 = a.destination_size - a.dst0;
    a.dst1 = a.destination_size - a.dst1;
  }
  if (a.src0 > a.src1 && a.dst0 > a.dst1) {
    std::swap(a.src0, a.src1);
    std::swap(a.dst0, a.dst1);
  }
  const double scale = double(a.src1 - a.src0) / double(a.dst1 - a.dst0);
  const int64_t last = a.source_size - 1;
  auto stored = [&](int64_t texel) {
    return int(a.source_top_first ? last - texel : texel);  // back to rows bottom to top
  };
  bool any = false;
  for (int64_t d = lo; d < hi; ++d) {
    const int64_t stored_d = a.destination_top_first ? a.destination_size - 1 - d : d;
    // The destination pixel's centre in the source (the mapping may mirror).
    const double s = double(a.src0) + (double(stored_d) + 0.5 - double(a.dst0)) * scale;
    if (!(s >= 0.0 && s < double(a.source_size))) continue;
    if (!any) out.lo = int(d);
    any = true;
    out.hi = int(d) + 1;
    int i0 = 0, i1 = 0;
    if (!linear) {
      i0 = i1 = stored(int64_t(std::floor(s)));
    } else {
      const double t = s - 0.5, below = std::floor(t);
      i0 = stored(std::clamp<int64_t>(int64_t(below), 0, last));
      i1 = stored(std::clamp<int64_t>(int64_t(below) + 1, 0, last));
      out.second.push_back(i1);
      out.weight.push_back(float(t - below));
    }
    out.first.push_back(i0);
    out.source_lo = std::min({out.source_lo, i0, i1});
    out.source_hi = std::max({out.source_hi, i0 + 1, i1 + 1});
  }
  if (!any) out.lo = out.hi = 0;
  return out;
}

// What the read framebuffer holds over the source rectangle the axes use.
struct BlitSource {
  int x = 0, y = 0, width = 0, height = 0;
  FramebufferPixels color, depth, stencil;
};

bool read_source(Context& ctx, GLbitfield mask, BlitSource& source) {
  const uint32_t w = uint32_t(source.width), h = uint32_t(source.height);
  const uint32_t buffer = ctx.raster.ops.read_buffer;
  if ((mask & GL_COLOR_BUFFER_BIT) && !read_framebuffer(ctx, rec::PixelKind::kColor, buffer,
                                                        source.x, source.y, w, h, source.color))
    return false;
  if ((mask & GL_DEPTH_BUFFER_BIT) && !read_framebuffer(ctx, rec::PixelKind::kDepth, buffer,
                                                        source.x, source.y, w, h, source.depth))
    return false;
  return !(mask & GL_STENCIL_BUFFER_BIT) ||
         read_framebuffer(ctx, rec::PixelKind::kStencil, buffer, source.x, source.y, w, h,
                          source.stencil);
}

uint8_t to_unorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// The destination rectangle's pixels from the source.
void sample(const BlitSource& source, const BlitAxis& ax, const BlitAxis& ay, bool linear,
            rt::PixelWrite& out) {
  const size_t w = size_t(ax.hi - ax.lo), h = size_t(ay.hi - ay.lo);
  const size_t stride = size_t(source.width);
  auto at = [&](int x, int y) { return size_t(y - source.y) * stride + size_t(x - source.x); };
  if (!source.color.color.empty()) out.rgba.resize(w * h * 4);
  if (!source.depth.depth.empty()) out.depth.resize(w * h);
  if (!source.stencil.stencil.empty()) out.stencil.resize(w * h);
  for (size_t j = 0; j < h; ++j)
    for (size_t i = 0; i < w; ++i) {
      const size_t o = j * w + i;
      const int x0 = ax.first[i], y0 = ay.first[j];
      if (!out.rgba.empty()) {
        glm::vec4 c = source.color.color[at(x0, y0)];
        if (linear) {
          const int x1 = ax.second[i], y1 = ay.second[j];
          const float fx = ax.weight[i], fy = ay.weight[j];
          const std::vector<glm::vec4>& s = source.color.color;
          c = glm::mix(glm::mix(s[at(x0, y0)], s[at(x1, y0)], fx),
                       glm::mix(s[at(x0, y1)], s[at(x1, y1)], fx), fy);
        }
        for (int k = 0; k < 4; ++k) out.rgba[o * 4 + size_t(k)] = to_unorm8(c[k]);
      }
      // Depth and stencil are always nearest (GL_LINEAR is an error for them).
      if (!out.depth.empty()) out.depth[o] = source.depth.depth[at(x0, y0)];
      if (!out.stencil.empty()) out.stencil[o] = uint8_t(source.stencil.stencil[at(x0, y0)]);
    }
}

}  // namespace

namespace impl {

void glBlitFramebuffer(Context& ctx, GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1,
                       GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask,
                       GLenum filter) {
  flush_bitmap_cache(ctx);  // as Mesa's do_blit_framebuffer
  FramebufferBindings& b = ctx.framebuffers;
  const FramebufferObject* read_fb = b.read_framebuffer.get();
  const FramebufferObject* draw_fb = b.framebuffer.get();
  bool complete = framebuffer_error(ctx) == GL_NO_ERROR;  // the draw framebuffer (entered)
  if (read_fb != nullptr && read_fb != draw_fb) {
    const FramebufferBuffers buffers = buffers_of(ctx, read_fb);
    std::lock_guard lock(b.store->mutex);
    complete = complete && framebuffer_status(*read_fb, buffers.draw_buffer, buffers.read_buffer) ==
                               GL_FRAMEBUFFER_COMPLETE_EXT;
  }
  if (!complete) return record_error(ctx, GL_INVALID_FRAMEBUFFER_OPERATION_EXT);
  if (filter != GL_NEAREST && filter != GL_LINEAR) return record_error(ctx, GL_INVALID_ENUM);
  if (mask & ~kBlitBuffers) return record_error(ctx, GL_INVALID_VALUE);
  if ((mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT)) && filter != GL_NEAREST)
    return record_error(ctx, GL_INVALID_OPERATION);
  // A buffer that does not exist in both framebuffers is silently not copied
  // (EXT_framebuffer_blit); depth and stencil images must match in bits (Mesa's
  // validate_depth_buffer / validate_stencil_buffer). glpt's colour formats are all normalized
  // fixed point: any colour pair is compatible.
  const uint32_t draw_buffer = ctx.raster.ops.draw_buffer;
  if ((mask & GL_COLOR_BUFFER_BIT) &&
      (!reads_color(read_fb, buffers_of(ctx, read_fb).read_buffer) || draw_buffer == GL_NONE))
    mask &= ~GLbitfield{GL_COLOR_BUFFER_BIT};
  if (!depth_stencil_compatible(ctx, read_fb, draw_fb, false, GL_STENCIL_BUFFER_BIT, mask) ||
      !depth_stencil_compatible(ctx, read_fb, draw_fb, true, GL_DEPTH_BUFFER_BIT, mask))
    return record_error(ctx, GL_INVALID_OPERATION);
  if (mask == 0 || srcX0 == srcX1 || srcY0 == srcY1 || dstX0 == dstX1 || dstY0 == dstY1) return;
  if (!ensure_output(ctx)) return;  // no renderer: the buffers hold only the clear colour

  // The destination bounds: the draw framebuffer, cut by the scissor box where it is enabled.
  const rec::DrawableConfig draw_config = current_drawable(ctx);
  int64_t x_lo = 0, y_lo = 0, x_hi = draw_config.width, y_hi = draw_config.height;
  if (ctx.raster.ops.scissor_test) {
    const std::array<int32_t, 4>& s = ctx.raster.ops.scissor_box;
    x_lo = std::max<int64_t>(x_lo, s[0]);
    y_lo = std::max<int64_t>(y_lo, s[1]);
    x_hi = std::min<int64_t>(x_hi, int64_t{s[0]} + s[2]);
    y_hi = std::min<int64_t>(y_hi, int64_t{s[1]} + s[3]);
  }
  if (x_lo >= x_hi || y_lo >= y_hi) return;
  const bool linear = filter == GL_LINEAR;

  rt::PixelWrite write;
  or_out_of_memory(ctx, [&] {
    BlitAxis ax, ay;
    BlitSource source;
    {
      const ReadFramebufferScope read(ctx);
      const rec::DrawableConfig read_config = current_drawable(ctx);
      ax = blit_axis({srcX0, srcX1, dstX0, dstX1, read_config.width, draw_config.width}, x_lo, x_hi,
                     linear);
      ay = blit_axis({srcY0, srcY1, dstY0, dstY1, read_config.height, draw_config.height,
                      read_fb == nullptr, draw_fb == nullptr},
                     y_lo, y_hi, linear);
      if (ax.lo == ax.hi || ay.lo == ay.hi) return;
      source.x = ax.source_lo;
      source.y = ay.source_lo;
      source.width = ax.source_hi - ax.source_lo;
      source.height = ay.source_hi - ay.source_lo;
      if (!read_source(ctx, mask, source)) return;
    }
    write.x = ax.lo;
    write.y = ay.lo;
    write.width = uint32_t(ax.hi - ax.lo);
    write.height = uint32_t(ay.hi - ay.lo);
    write.draw_buffer = draw_buffer;
    sample(source, ax, ay, linear, write);
  });
  if (write.width == 0 || write.height == 0) return;
  // What was drawn before the blit lands first; the blit's pixels are written over it.
  if (!execute_record(ctx) || !ctx.output) return;
  WindowTarget* target = render_target(ctx);
  if (target == nullptr) return;
  std::string error;
  bool ok = false;
  {
    std::lock_guard lock(target->mutex());
    ok = ctx.output->renderer().write_pixels(target->buffers(), current_drawable(ctx), write,
                                             &error);
  }
  if (!ok) {
    if (!error.empty()) std::fprintf(stderr, "%s\n", error.c_str());
    return record_error(ctx, GL_OUT_OF_MEMORY);
  }
  // A framebuffer object's textures take what the blit wrote when it is left.
  if (b.entered) b.framebuffer->rendering->drawn = true;
}

}  // namespace impl
}  // namespace glpt
