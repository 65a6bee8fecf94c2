#include "gl_shim/framebuffers/framebuffer_rendering.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/framebuffers/framebuffer_objects.hpp"
#include "gl_shim/pixels/bitmap_cache.hpp"
#include "gl_shim/textures/internal_formats.hpp"
#include "gl_shim/textures/texel_codec.hpp"
#include "gl_shim/textures/texture_object.hpp"

namespace glpt {
namespace {

void swap_bundle(Context& ctx, RecordingBundle& bundle) {
  std::swap(ctx.recorder, bundle.recorder);
  std::swap(ctx.snapshots, bundle.snapshots);
  std::swap(ctx.recording_since, bundle.recording_since);
  std::swap(ctx.drawable, bundle.drawable);
  std::swap(ctx.raster.ops.draw_buffer, bundle.draw_buffer);
  std::swap(ctx.raster.ops.read_buffer, bundle.read_buffer);
  // Draws cached from buffer objects refer to the record they were recorded into.
  ctx.buffer_draws.record_cleared();
}

// The colour attachment `draw_buffer` names (GL_COLOR_ATTACHMENTn), or null.
const Attachment* drawn_attachment(const FramebufferObject& fb, uint32_t draw_buffer) {
  if (draw_buffer < GL_COLOR_ATTACHMENT0_EXT ||
      draw_buffer >= GL_COLOR_ATTACHMENT0_EXT + kMaxColorAttachments)
    return nullptr;
  return &fb.color[draw_buffer - GL_COLOR_ATTACHMENT0_EXT];
}

// The target's buffers for a complete framebuffer object (entered: its draw and read buffers are
// the context's): the attachments' size, depth and stencil as attached.
bool target_config(const Context& ctx, const FramebufferObject& fb, rec::DrawableConfig& config) {
  if (framebuffer_status(fb, ctx.raster.ops.draw_buffer, ctx.raster.ops.read_buffer) !=
      GL_FRAMEBUFFER_COMPLETE_EXT)
    return false;
  uint32_t width = UINT32_MAX, height = UINT32_MAX;
  bool alpha = false, any_color = false;
  auto size_of = [&](const Attachment& a) {
    if (a.type == GL_TEXTURE) {
      const rec::TextureImage* image = attached_image(a);
      if (image == nullptr) return;
      width = std::min(width, image->width);
      height = std::min(height, image->height);
    } else if (a.type == GL_RENDERBUFFER_EXT) {
      width = std::min(width, uint32_t(a.renderbuffer->width));
      height = std::min(height, uint32_t(a.renderbuffer->height));
    }
  };
  for (const Attachment& a : fb.color) {
    size_of(a);
    if (a.type == GL_TEXTURE) {
      const InternalFormatInfo* info = attached_texture_format(a);
      alpha = alpha || (info != nullptr && info->alpha != 0);
      any_color = true;
    } else if (a.type == GL_RENDERBUFFER_EXT) {
      alpha = alpha || a.renderbuffer->bits[3] != 0;
      any_color = true;
    }
  }
  size_of(fb.depth);
  size_of(fb.stencil);
  if (width == UINT32_MAX || height == UINT32_MAX || width == 0 || height == 0) return false;
  config = rec::DrawableConfig{};
  config.width = width;
  config.height = height;
  config.double_buffered = false;
  config.has_alpha = alpha || !any_color;
  config.depth_bits = fb.depth.type != GL_NONE ? 24 : 0;
  config.stencil_bits = fb.stencil.type != GL_NONE ? 8 : 0;
  config.accum_bits = 0;
  config.framebuffer_object = true;
  return true;
}

// The texel at (x, y) of an attachment's image (a 3-D texture's slice `zoffset`), or null where
// the image holds none.
const uint8_t* attached_texel(const rec::TextureImage& image, int zoffset, size_t texel_bytes,
                              uint32_t x, uint32_t y) {
  const size_t i =
      size_t(std::max(zoffset, 0)) * image.width * image.height + size_t{y} * image.width + x;
  return (i + 1) * texel_bytes <= image.texels.size() ? &image.texels[i * texel_bytes] : nullptr;
}

uint64_t content_version(TextureObject& texture) { return texture.snapshot()->content_version; }

// Loads the drawn colour attachment's texture image into the target where the target does not
// hold its current contents.
void load_color(Context& ctx, const FramebufferObject& fb, FramebufferRendering& r) {
  const Attachment* a = drawn_attachment(fb, ctx.raster.ops.draw_buffer);
  if (a == nullptr || a->type != GL_TEXTURE || !r.target) return;
  const uint64_t version = content_version(*a->texture);
  if (r.loaded_texture == a->texture.get() && r.loaded_target == a->texture_target &&
      r.loaded_level == a->level && r.loaded_zoffset == a->zoffset && r.loaded_version == version)
    return;
  const rec::TextureImage* image = attached_image(*a);
  const InternalFormatInfo* info = attached_texture_format(*a);
  if (image == nullptr || info == nullptr || info->is_depth() || !ensure_output(ctx)) return;
  const rec::DrawableConfig config = r.target->config();
  std::vector<uint8_t> rgba(size_t{config.width} * config.height * 4, 0);
  const size_t texel = rec::texel_bytes(info->texel_format());
  for (uint32_t y = 0; y < config.height && y < image->height; ++y)
    for (uint32_t x = 0; x < config.width && x < image->width; ++x) {
      const uint8_t* t = attached_texel(*image, a->zoffset, texel, x, y);
      if (t == nullptr) continue;
      const glm::vec4 c = decode_color_texel(*info, t);
      for (int k = 0; k < 4; ++k)
        rgba[(size_t{y} * config.width + x) * 4 + size_t(k)] =
            uint8_t(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
    }
  std::string error;
  std::lock_guard lock(r.target->mutex());
  if (!ctx.output->renderer().write_color(r.target->buffers(), config, rgba, &error)) {
    if (!error.empty()) std::fprintf(stderr, "%s\n", error.c_str());
    return;
  }
  r.loaded_texture = a->texture.get();
  r.loaded_target = a->texture_target;
  r.loaded_level = a->level;
  r.loaded_zoffset = a->zoffset;
  r.loaded_version = version;
}

// Loads the depth texture attachment's image into the target's depth buffer where the target
// does not hold its current contents (a depth map drawn in an earlier pass and drawn over now).
void load_depth(Context& ctx, const FramebufferObject& fb, FramebufferRendering& r) {
  const Attachment& a = fb.depth;
  if (a.type != GL_TEXTURE || !r.target) return;
  const uint64_t version = content_version(*a.texture);
  if (r.loaded_depth_texture == a.texture.get() && r.loaded_depth_version == version) return;
  const rec::TextureImage* image = attached_image(a);
  const InternalFormatInfo* info = attached_texture_format(a);
  if (image == nullptr || info == nullptr || !info->is_depth() || !ensure_output(ctx)) return;
  const rec::DrawableConfig config = r.target->config();
  std::vector<float> depth(size_t{config.width} * config.height, 1.0f);
  const size_t texel = rec::texel_bytes(info->texel_format());
  for (uint32_t y = 0; y < config.height && y < image->height; ++y)
    for (uint32_t x = 0; x < config.width && x < image->width; ++x)
      if (const uint8_t* t = attached_texel(*image, a.zoffset, texel, x, y))
        depth[size_t{y} * config.width + x] = decode_depth_texel(t);
  std::string error;
  std::lock_guard lock(r.target->mutex());
  if (!ctx.output->renderer().write_depth(r.target->buffers(), config, depth, &error)) {
    if (!error.empty()) std::fprintf(stderr, "%s\n", error.c_str());
    return;
  }
  r.loaded_depth_texture = a.texture.get();
  r.loaded_depth_version = version;
}

}  // namespace

WindowTarget* render_target(Context& ctx) {
  if (!ctx.framebuffers.entered) return ctx.target;
  const FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  return fb != nullptr && fb->rendering ? fb->rendering->target.get() : nullptr;
}

FramebufferRendering& rendering_of(FramebufferObject& fb) {
  if (!fb.rendering) {
    fb.rendering = std::make_shared<FramebufferRendering>();
    fb.rendering->parked.draw_buffer = fb.rendering->parked.read_buffer = GL_COLOR_ATTACHMENT0_EXT;
  }
  return *fb.rendering;
}

FramebufferBuffers buffers_of(const Context& ctx, const FramebufferObject* fb) {
  const FramebufferObject* entered =
      ctx.framebuffers.entered ? ctx.framebuffers.framebuffer.get() : nullptr;
  if (fb == entered) return {ctx.raster.ops.draw_buffer, ctx.raster.ops.read_buffer};
  if (fb != nullptr && !fb->rendering)
    return {GL_COLOR_ATTACHMENT0_EXT, GL_COLOR_ATTACHMENT0_EXT};  // never entered: the defaults
  // An object's own bundle, or the window's, parked in the entered object.
  const RecordingBundle& parked =
      fb != nullptr ? fb->rendering->parked : entered->rendering->parked;
  return {parked.draw_buffer, parked.read_buffer};
}

const rec::DrawableConfig& window_drawable(const Context& ctx) {
  return ctx.framebuffers.entered ? ctx.framebuffers.framebuffer->rendering->parked.drawable
                                  : ctx.drawable;
}

ReadFramebufferScope::ReadFramebufferScope(Context& ctx) : ctx_(ctx) {
  FramebufferBindings& b = ctx.framebuffers;
  if (b.read_framebuffer == b.framebuffer) return;
  leave_framebuffer(ctx);
  draw_ = std::move(b.framebuffer);
  b.framebuffer = b.read_framebuffer;
  enter_framebuffer(ctx);
  swapped_ = true;
}

ReadFramebufferScope::~ReadFramebufferScope() {
  if (!swapped_) return;
  leave_framebuffer(ctx_);
  ctx_.framebuffers.framebuffer = std::move(draw_);
  enter_framebuffer(ctx_);
}

void enter_framebuffer(Context& ctx) {
  FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  if (fb == nullptr || ctx.framebuffers.entered) return;
  flush_bitmap_cache(ctx);
  FramebufferRendering& r = rendering_of(*fb);
  swap_bundle(ctx, r.parked);
  ctx.framebuffers.entered = true;
  rec::DrawableConfig config;
  bool complete = false;
  {
    std::lock_guard lock(ctx.framebuffers.store->mutex);
    complete = target_config(ctx, *fb, config);
  }
  if (!complete) {
    r.target.reset();
    ctx.drawable = rec::DrawableConfig{};
    ctx.drawable.double_buffered = false;
    ctx.drawable.width = ctx.drawable.height = 0;
    return;
  }
  if (!r.target || r.target->config() != config) {
    r.target = std::make_unique<HeadlessTarget>(config.width, config.height, config);
    r.loaded_texture = nullptr;
    r.loaded_depth_texture = nullptr;
  }
  ctx.drawable = config;
  load_color(ctx, *fb, r);
  load_depth(ctx, *fb, r);
}

void leave_framebuffer(Context& ctx) {
  FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  if (fb == nullptr || !ctx.framebuffers.entered || !fb->rendering) return;
  flush_bitmap_cache(ctx);
  FramebufferRendering& r = *fb->rendering;
  if (!r.target) {
    discard_record(ctx);  // an incomplete framebuffer draws nothing
  } else {
    if (!ctx.recorder.empty()) execute_record(ctx);
  }
  if (r.target && r.drawn) {
    r.drawn = false;
    const rec::DrawableConfig config = r.target->config();
    if (const Attachment* a = drawn_attachment(*fb, ctx.raster.ops.draw_buffer);
        a != nullptr && a->type == GL_TEXTURE) {
      write_back_framebuffer_image(ctx, *a->texture, a->texture_target, a->level, a->zoffset,
                                   config.width, config.height, /*depth=*/false);
      r.loaded_texture = a->texture.get();
      r.loaded_target = a->texture_target;
      r.loaded_level = a->level;
      r.loaded_zoffset = a->zoffset;
      r.loaded_version = content_version(*a->texture);
    }
    if (fb->depth.type == GL_TEXTURE) {
      write_back_framebuffer_image(ctx, *fb->depth.texture, fb->depth.texture_target,
                                   fb->depth.level, fb->depth.zoffset, config.width, config.height,
                                   /*depth=*/true);
      r.loaded_depth_texture = fb->depth.texture.get();
      r.loaded_depth_version = content_version(*fb->depth.texture);
    }
  }
  swap_bundle(ctx, r.parked);
  ctx.framebuffers.entered = false;
}

GLenum framebuffer_error(Context& ctx) {
  if (!ctx.framebuffers.entered) return GL_NO_ERROR;
  FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  if (fb == nullptr || !fb->rendering) return GL_NO_ERROR;
  rec::DrawableConfig config;
  bool complete = false;
  {
    std::lock_guard lock(ctx.framebuffers.store->mutex);
    complete = target_config(ctx, *fb, config);
  }
  const HeadlessTarget* target = fb->rendering->target.get();
  if (complete != (target != nullptr) || (complete && target->config() != config))
    refresh_framebuffer(ctx);
  else if (complete && ctx.recorder.empty() && !fb->rendering->drawn) {
    load_color(ctx, *fb, *fb->rendering);  // the attached textures were written meanwhile
    load_depth(ctx, *fb, *fb->rendering);
  }
  return complete ? GLenum{GL_NO_ERROR} : GLenum{GL_INVALID_FRAMEBUFFER_OPERATION_EXT};
}

namespace {

// The components an attachment stores and their bits (0: not stored), luminance and intensity
// counted as red; null attachments store nothing.
struct StoredComponents {
  std::array<int, 4> bits{};  // red (or luminance, intensity), green, blue, alpha
};

std::optional<StoredComponents> stored_components(const Attachment& a) {
  StoredComponents s;
  if (a.type == GL_RENDERBUFFER_EXT) {
    const std::array<GLint, 6>& b = a.renderbuffer->bits;
    s.bits = {b[0], b[1], b[2], b[3]};
    if (s.bits == std::array<int, 4>{}) s.bits[0] = 8;  // luminance and intensity: 8 bits
    return s;
  }
  const InternalFormatInfo* info = a.type == GL_TEXTURE ? attached_texture_format(a) : nullptr;
  if (info == nullptr || info->is_depth()) return std::nullopt;
  s.bits = {std::max({int(info->red), int(info->luminance), int(info->intensity)}), info->green,
            info->blue, info->alpha};
  return s;
}

glm::vec4 stored_view(const StoredComponents& s, glm::vec4 c) {
  auto quantize = [](float v, int bits) {
    const float steps = float((1u << std::min(bits, 24)) - 1u);
    return std::round(std::clamp(v, 0.0f, 1.0f) * steps) / steps;
  };
  return {s.bits[0] != 0 ? quantize(c.r, s.bits[0]) : 0.0f,
          s.bits[1] != 0 ? quantize(c.g, s.bits[1]) : 0.0f,
          s.bits[2] != 0 ? quantize(c.b, s.bits[2]) : 0.0f,
          s.bits[3] != 0 ? quantize(c.a, s.bits[3]) : 1.0f};
}

}  // namespace

void show_stored_components(const Context& ctx, uint32_t read_buffer, FramebufferPixels& out) {
  if (!ctx.framebuffers.entered) return;
  const FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  if (fb == nullptr) return;
  const Attachment* a = drawn_attachment(*fb, read_buffer);
  if (a == nullptr) return;
  const std::optional<StoredComponents> s = stored_components(*a);
  if (!s) return;
  for (glm::vec4& c : out.color) c = stored_view(*s, c);
}

bool read_other_attachment(Context& ctx, uint32_t read_buffer, int32_t x, int32_t y, uint32_t width,
                           uint32_t height, FramebufferPixels& out) {
  if (!ctx.framebuffers.entered || read_buffer == ctx.raster.ops.draw_buffer) return false;
  const FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  if (fb == nullptr) return false;
  const Attachment* a = drawn_attachment(*fb, read_buffer);
  if (a == nullptr || a->type != GL_TEXTURE) return false;  // renderbuffers: only the drawn one
  sync_framebuffer_textures(ctx);                           // the textures hold what was drawn
  const rec::TextureImage* image = attached_image(*a);
  const InternalFormatInfo* info = attached_texture_format(*a);
  const std::optional<StoredComponents> s = stored_components(*a);
  if (image == nullptr || info == nullptr || !s) return false;
  out = FramebufferPixels();
  out.width = width;
  out.height = height;
  out.color.assign(size_t{width} * height, glm::vec4(0.0f));
  const size_t texel = rec::texel_bytes(info->texel_format());
  for (uint32_t row = 0; row < height; ++row)
    for (uint32_t col = 0; col < width; ++col) {
      const int64_t tx = int64_t{x} + col, ty = int64_t{y} + row;
      if (tx < 0 || ty < 0 || tx >= int64_t{image->width} || ty >= int64_t{image->height}) continue;
      const uint8_t* t = attached_texel(*image, a->zoffset, texel, uint32_t(tx), uint32_t(ty));
      if (t == nullptr) continue;
      // Decoded as sampled (luminance replicated), then shown as stored.
      out.color[size_t{row} * width + col] = stored_view(*s, decode_color_texel(*info, t));
    }
  mark_inside_drawable(out, x, y, image->width, image->height);
  return true;
}

void sync_framebuffer_textures(Context& ctx) {
  if (!ctx.framebuffers.entered) return;
  const FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  if (fb == nullptr || !fb->rendering || !fb->rendering->target) return;
  if (!ctx.recorder.empty() || fb->rendering->drawn) refresh_framebuffer(ctx);
}

void refresh_framebuffer(Context& ctx) {
  if (!ctx.framebuffers.entered) return;
  leave_framebuffer(ctx);
  enter_framebuffer(ctx);
}

}  // namespace glpt
