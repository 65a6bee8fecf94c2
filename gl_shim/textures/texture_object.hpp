// GL texture objects (GL 1.5 3.8.12) as the front end keeps them: mutable, shared by the contexts
// of a share group, handing out immutable rec::TextureObjectSnapshot s to the frame record.
//
// Images are held by shared_ptr and shared with the snapshots that refer to them; an image still
// referred to by a snapshot is copied before it is changed (copy-on-write), so the record never
// sees later changes. The snapshot is cached until the object changes, which makes taking it at
// every draw cheap.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "gl_shim/gl_types.h"
#include "rt_core/record/texture.hpp"

namespace glpt {

// Binding points of a texture unit. Their priority when several are enabled (GL 1.5 3.8.15,
// ARB_texture_rectangle) is kSlotsByPriority's order, not this one: the rectangle slot came last.
enum TextureSlot : int {
  kSlot1D = 0,
  kSlot2D = 1,
  kSlot3D = 2,
  kSlotCube = 3,
  kSlotRect = 4,  // GL_TEXTURE_RECTANGLE_ARB
  kSlotCount = 5
};
// Highest priority first: cube map, 3D, rectangle, 2D, 1D (ARB_texture_rectangle; Mesa's
// gl_texture_index order).
inline constexpr TextureSlot kSlotsByPriority[kSlotCount] = {kSlotCube, kSlot3D, kSlotRect, kSlot2D,
                                                             kSlot1D};

// GL_TEXTURE_1D/2D/3D/CUBE_MAP/RECTANGLE_ARB -> slot, -1 for anything else.
int texture_slot(GLenum target);
GLenum slot_target(int slot);

// Implementation limits (glpt keeps texels in host memory; Mesa's llvmpipe allows 16384).
inline constexpr int kMaxTextureSize = 4096;   // GL_MAX_TEXTURE_SIZE, _CUBE_MAP_TEXTURE_SIZE
inline constexpr int kMax3DTextureSize = 256;  // GL_MAX_3D_TEXTURE_SIZE
inline constexpr int kMaxTextureLevels = 13;   // log2(4096) + 1
inline constexpr int kMax3DTextureLevels = 9;  // log2(256) + 1
// GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB: the 2D limit, as in Mesa (llvmpipe: 16384 for both).
inline constexpr int kMaxRectangleTextureSize = kMaxTextureSize;
inline constexpr float kMaxTextureLodBias = 16.0f;     // GL_MAX_TEXTURE_LOD_BIAS (Mesa)
inline constexpr float kMaxTextureAnisotropy = 16.0f;  // GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT

int max_texture_levels(int slot);

class TextureObject {
 public:
  TextureObject(GLuint name, GLenum target) : name_(name) { set_target(target); }

  GLuint name() const { return name_; }
  // The target of its first binding; 0 while the name was only generated.
  GLenum target() const { return target_; }
  // Also sets the target's initial parameters (rectangle textures: CLAMP_TO_EDGE, LINEAR).
  void set_target(GLenum target);
  int faces() const { return target_ == GL_TEXTURE_CUBE_MAP ? 6 : 1; }

  // --- parameters (glTexParameter): change through edit_sampler() so the snapshot is renewed.
  const rec::SamplerState& sampler() const { return sampler_; }
  rec::SamplerState& edit_sampler();
  bool generate_mipmap = false;  // GL_GENERATE_MIPMAP (does not change what is sampled)
  float priority = 1.0f;         // GL_TEXTURE_PRIORITY

  // --- images --------------------------------------------------------------------------------
  // Null when undefined.
  const rec::TextureImage* image(int face, int level) const;
  // Defines (or, with null, undefines) an image.
  void set_image(int face, int level, std::shared_ptr<rec::TextureImage> image);
  // The image for in-place changes (glTexSubImage, mipmap generation): copied first if a
  // snapshot still refers to it. Null when undefined.
  rec::TextureImage* image_for_update(int face, int level);

  // --- derived state, cached ----------------------------------------------------------------
  // GL 1.5 3.8.10: complete (with its current filters; cube maps: cube complete).
  bool complete();
  // The highest level such that base_level..last are a consistent mipmap chain on every face
  // (base_level - 1 when the base level is not usable).
  int last_consistent_level();
  // The immutable snapshot of the current state; the same pointer until the object changes.
  std::shared_ptr<const rec::TextureObjectSnapshot> snapshot();

 private:
  void images_changed();
  void analyze();

  GLuint name_;
  GLenum target_;
  rec::SamplerState sampler_;
  std::array<std::vector<std::shared_ptr<rec::TextureImage>>, 6> images_;

  // Caches, renewed on change. Contexts of a share group may draw with one texture from several
  // threads at once, so the caches are guarded.
  std::mutex cache_mutex_;
  bool analyzed_ = false;
  bool complete_ = false;
  int last_level_ = -1;
  bool content_changed_ = true;  // images changed since the last snapshot
  uint64_t content_version_ = 0;
  int versioned_base_ = 0, versioned_max_ = 0;  // base/max level when the version was taken
  std::shared_ptr<const rec::TextureObjectSnapshot> snapshot_;
};

// The texture objects of a share group (GLX share_list), like DisplayListStore for lists.
// Contexts of one share group may run on several threads (a loader thread uploading textures
// while another draws is common): the name table is guarded by `mutex`.
struct TextureStore {
  TextureStore();
  std::mutex mutex;
  // Named objects; generated names map to an object whose target is 0 until first bound.
  std::unordered_map<GLuint, std::shared_ptr<TextureObject>> objects;
  // Texture 0 of each target. Mesa keeps them in the share group's state too.
  std::array<std::shared_ptr<TextureObject>, kSlotCount> defaults;
  GLuint next_name = 1;  // where glGenTextures starts looking for unused names
};

// A new value for rec::TextureObjectSnapshot::content_version, never handed out before in this
// process (GPU caches are per device, and the device is shared by every share group).
uint64_t next_texture_content_version();

}  // namespace glpt
