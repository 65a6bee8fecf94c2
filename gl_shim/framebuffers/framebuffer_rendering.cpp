#include "gl_shim/framebuffers/framebuffer_rendering.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
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

// The target's buffers for a complete framebuffer object: the smallest attachment's size (Mesa's
// rule with ARB_framebuffer_object), depth and stencil as attached.
bool target_config(const FramebufferObject& fb, rec::DrawableConfig& config) {
  if (framebuffer_status(fb) != GL_FRAMEBUFFER_COMPLETE_EXT) return false;
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

uint64_t content_version(TextureObject& texture) { return texture.snapshot()->content_version; }

// Loads the drawn colour attachment's texture image into the target where the target does not
// hold its current contents.
void load_color(Context& ctx, const FramebufferObject& fb, FramebufferRendering& r) {
  const Attachment* a = drawn_attachment(fb, ctx.raster.ops.draw_buffer);
  if (a == nullptr || a->type != GL_TEXTURE || !r.target) return;
  const uint64_t version = content_version(*a->texture);
  if (r.loaded_texture == a->texture.get() && r.loaded_target == a->texture_target &&
      r.loaded_level == a->level && r.loaded_version == version)
    return;
  const rec::TextureImage* image = attached_image(*a);
  const InternalFormatInfo* info = attached_texture_format(*a);
  if (image == nullptr || info == nullptr || info->is_depth() || !ensure_output(ctx)) return;
  const rec::DrawableConfig config = r.target->config();
  std::vector<uint8_t> rgba(size_t{config.width} * config.height * 4, 0);
  const size_t texel = rec::texel_bytes(info->texel_format());
  for (uint32_t y = 0; y < config.height && y < image->height; ++y)
    for (uint32_t x = 0; x < config.width && x < image->width; ++x) {
      const size_t i = size_t{y} * image->width + x;
      if ((i + 1) * texel > image->texels.size()) continue;
      const glm::vec4 c = decode_color_texel(*info, &image->texels[i * texel]);
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
  r.loaded_version = version;
}

}  // namespace

WindowTarget* render_target(Context& ctx) {
  if (!ctx.framebuffers.entered) return ctx.target;
  const FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  return fb != nullptr && fb->rendering ? fb->rendering->target.get() : nullptr;
}

void enter_framebuffer(Context& ctx) {
  FramebufferObject* fb = ctx.framebuffers.framebuffer.get();
  if (fb == nullptr || ctx.framebuffers.entered) return;
  flush_bitmap_cache(ctx);
  if (!fb->rendering) {
    fb->rendering = std::make_shared<FramebufferRendering>();
    fb->rendering->parked.draw_buffer = fb->rendering->parked.read_buffer =
        GL_COLOR_ATTACHMENT0_EXT;
  }
  FramebufferRendering& r = *fb->rendering;
  swap_bundle(ctx, r.parked);
  ctx.framebuffers.entered = true;
  rec::DrawableConfig config;
  bool complete = false;
  {
    std::lock_guard lock(ctx.framebuffers.store->mutex);
    complete = target_config(*fb, config);
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
  }
  ctx.drawable = config;
  load_color(ctx, *fb, r);
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
      write_back_framebuffer_image(ctx, *a->texture, a->texture_target, a->level, config.width,
                                   config.height, /*depth=*/false);
      r.loaded_texture = a->texture.get();
      r.loaded_target = a->texture_target;
      r.loaded_level = a->level;
      r.loaded_version = content_version(*a->texture);
    }
    if (fb->depth.type == GL_TEXTURE)
      write_back_framebuffer_image(ctx, *fb->depth.texture, fb->depth.texture_target,
                                   fb->depth.level, config.width, config.height, /*depth=*/true);
  }
  swap_bundle(ctx, r.parked);
  ctx.framebuffers.entered = false;
}

void refresh_framebuffer(Context& ctx) {
  if (!ctx.framebuffers.entered) return;
  leave_framebuffer(ctx);
  enter_framebuffer(ctx);
}

}  // namespace glpt
