#include "gl_shim/textures/texture_object.hpp"

#include <algorithm>
#include <atomic>

#include "gl/gl_enums.h"
#include "gl_shim/textures/internal_formats.hpp"

namespace glpt {

int texture_slot(GLenum target) {
  switch (target) {
    case GL_TEXTURE_1D:
      return kSlot1D;
    case GL_TEXTURE_2D:
      return kSlot2D;
    case GL_TEXTURE_3D:
      return kSlot3D;
    case GL_TEXTURE_CUBE_MAP:
      return kSlotCube;
    case GL_TEXTURE_RECTANGLE_ARB:
      return kSlotRect;
    default:
      return -1;
  }
}

GLenum slot_target(int slot) {
  constexpr GLenum kTargets[kSlotCount] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D,
                                           GL_TEXTURE_CUBE_MAP, GL_TEXTURE_RECTANGLE_ARB};
  return kTargets[slot];
}

int max_texture_levels(int slot) {
  // Rectangle textures have level 0 only (ARB_texture_rectangle: other levels are
  // GL_INVALID_VALUE).
  return slot == kSlot3D ? kMax3DTextureLevels : slot == kSlotRect ? 1 : kMaxTextureLevels;
}

uint64_t next_texture_content_version() {
  // The one process-wide counter of the front end: an id allocator, not GL state. Versions must
  // be unique across share groups because rt_core's texture caches live with the (one) device.
  static std::atomic<uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}

void TextureObject::set_target(GLenum target) {
  target_ = target;
  if (target == GL_TEXTURE_RECTANGLE_ARB) {
    // ARB_texture_rectangle's initial state (Mesa's _mesa_initialize_texture_object): no
    // repeating wrap modes and no mipmaps on rectangle textures.
    sampler_.wrap_s = sampler_.wrap_t = sampler_.wrap_r = GL_CLAMP_TO_EDGE;
    sampler_.min_filter = GL_LINEAR;
  }
}

rec::SamplerState& TextureObject::edit_sampler() {
  // Filters decide completeness and base/max level the usable chain: recompute both.
  const std::lock_guard lock(cache_mutex_);
  analyzed_ = false;
  snapshot_.reset();
  return sampler_;
}

const rec::TextureImage* TextureObject::image(int face, int level) const {
  const auto& levels = images_[size_t(face)];
  return level >= 0 && size_t(level) < levels.size() ? levels[size_t(level)].get() : nullptr;
}

void TextureObject::set_image(int face, int level, std::shared_ptr<rec::TextureImage> image) {
  auto& levels = images_[size_t(face)];
  if (size_t(level) >= levels.size()) levels.resize(size_t(level) + 1);
  levels[size_t(level)] = std::move(image);
  images_changed();
}

rec::TextureImage* TextureObject::image_for_update(int face, int level) {
  auto& levels = images_[size_t(face)];
  if (level < 0 || size_t(level) >= levels.size() || !levels[size_t(level)]) return nullptr;
  images_changed();  // drops the cached snapshot's reference first
  std::shared_ptr<rec::TextureImage>& image = levels[size_t(level)];
  if (image.use_count() > 1) image = std::make_shared<rec::TextureImage>(*image);
  return image.get();
}

void TextureObject::images_changed() {
  const std::lock_guard lock(cache_mutex_);
  content_changed_ = true;
  analyzed_ = false;
  snapshot_.reset();
}

void TextureObject::analyze() {
  if (analyzed_) return;
  analyzed_ = true;
  complete_ = false;
  const int base = sampler_.base_level;
  const int max = sampler_.max_level;
  last_level_ = base - 1;
  if (target_ == 0 || base > max || base >= max_texture_levels(texture_slot(target_))) return;
  const rec::TextureImage* first = image(0, base);
  if (first == nullptr || first->width == 0 || first->height == 0 || first->depth == 0) return;
  // Cube maps: every face's base image square and alike (GL 1.5 3.8.10 "cube complete").
  for (int f = 0; f < faces(); ++f) {
    const rec::TextureImage* img = image(f, base);
    if (img == nullptr || img->width != first->width || img->height != first->height ||
        img->depth != first->depth || img->internal_format != first->internal_format ||
        img->sized_format != first->sized_format)
      return;
    if (target_ == GL_TEXTURE_CUBE_MAP && img->width != img->height) return;
  }
  last_level_ = base;
  // The levels GL's mipmap chain has: down to 1x1x1, but not beyond max_level.
  const uint32_t largest = std::max({first->width, first->height, first->depth});
  int chain_end = base;
  for (uint32_t size = largest; size > 1; size >>= 1) ++chain_end;
  chain_end = std::min({chain_end, max, max_texture_levels(texture_slot(target_)) - 1});
  for (int level = base + 1; level <= chain_end; ++level) {
    const int shift = level - base;
    bool consistent = true;
    for (int f = 0; f < faces() && consistent; ++f) {
      const rec::TextureImage* img = image(f, level);
      consistent = img != nullptr && img->internal_format == first->internal_format &&
                   img->sized_format == first->sized_format &&
                   img->width == std::max(1u, first->width >> shift) &&
                   img->height == std::max(1u, first->height >> shift) &&
                   img->depth == std::max(1u, first->depth >> shift);
    }
    if (!consistent) break;
    last_level_ = level;
  }
  const bool mipmapped = sampler_.min_filter != GL_NEAREST && sampler_.min_filter != GL_LINEAR;
  complete_ = !mipmapped || last_level_ == chain_end;
}

bool TextureObject::complete() {
  const std::lock_guard lock(cache_mutex_);
  analyze();
  return complete_;
}

int TextureObject::last_consistent_level() {
  const std::lock_guard lock(cache_mutex_);
  analyze();
  return last_level_;
}

std::shared_ptr<const rec::TextureObjectSnapshot> TextureObject::snapshot() {
  const std::lock_guard lock(cache_mutex_);
  if (snapshot_) return snapshot_;
  analyze();
  auto s = std::make_shared<rec::TextureObjectSnapshot>();
  s->target = target_;
  // The texels the snapshot exposes are the images and the base..max range.
  if (content_changed_ || content_version_ == 0 || versioned_base_ != sampler_.base_level ||
      versioned_max_ != sampler_.max_level) {
    content_version_ = next_texture_content_version();
    content_changed_ = false;
    versioned_base_ = sampler_.base_level;
    versioned_max_ = sampler_.max_level;
  }
  s->content_version = content_version_;
  if (const rec::TextureImage* base = image(0, std::max(sampler_.base_level, 0))) {
    if (const InternalFormatInfo* info =
            stored_format_info(base->internal_format, base->sized_format)) {
      // Depth-stencil textures sample as depth textures (EXT_packed_depth_stencil).
      s->base_format = info->is_depth() ? GLenum(GL_DEPTH_COMPONENT) : info->base_format;
      s->texel_format = info->texel_format();
    }
  }
  s->faces.resize(size_t(faces()));
  for (int f = 0; f < faces(); ++f) {
    s->faces[size_t(f)].assign(images_[size_t(f)].begin(), images_[size_t(f)].end());
  }
  s->sampler = sampler_;
  s->last_level = last_level_;
  snapshot_ = std::move(s);
  return snapshot_;
}

TextureStore::TextureStore() {
  for (int s = 0; s < kSlotCount; ++s)
    defaults[size_t(s)] = std::make_shared<TextureObject>(0, slot_target(s));
}

}  // namespace glpt
