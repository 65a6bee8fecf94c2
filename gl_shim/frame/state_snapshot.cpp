#include "gl_shim/frame/state_snapshot.hpp"

#include <algorithm>

#include "gl_shim/context.hpp"
#include "gl_shim/textures/texture_snapshot.hpp"

namespace glpt {
namespace {

void build_transform(Context& ctx, rec::TransformState& t) {
  t.modelview = ctx.matrices.modelview.top();
  t.projection = ctx.matrices.projection.top();
  t.modelview_projection = ctx.matrices.model_projection();
  t.modelview_inverse = ctx.matrices.modelview.top_matrix().inverse();
  const FramebufferState& fb = ctx.framebuffer;
  t.viewport = {fb.viewport_x, fb.viewport_y, fb.viewport_width, fb.viewport_height};
  t.depth_near = static_cast<float>(fb.depth_near);
  t.depth_far = static_cast<float>(fb.depth_far);
  t.normalize = ctx.transform.normalize;
  t.rescale_normal = ctx.transform.rescale_normal;
  t.clip_plane_mask = ctx.transform.clip_plane_mask;
  t.clip_planes = ctx.transform.clip_planes;
}

// Replaces `block` with a copy of `value` unless it already holds an equal value. Returns whether
// it was replaced.
template <typename T>
bool refresh(std::shared_ptr<const T>& block, const T& value) {
  if (block && *block == value) return false;
  block = std::make_shared<const T>(value);
  return true;
}

}  // namespace

void StateSnapshotter::count_textures(const rec::TexturingState& texturing) {
  for (const rec::TextureUnitState& unit : texturing.units) {
    if (unit.target == 0 || !unit.texture) continue;
    if (!texture_versions_.insert(unit.texture->content_version).second) continue;
    for (const auto& face : unit.texture->faces)
      for (const auto& level : face)
        if (level) texture_bytes_ += level->texels.size();
  }
}

rec::StateId StateSnapshotter::capture(Context& ctx, rec::FrameRecord& record) {
  build_transform(ctx, transform_scratch_);
  snapshot_texturing(ctx, texturing_scratch_);
  bool changed = refresh(transform_, transform_scratch_);
  changed |= refresh(lighting_, ctx.lighting);
  // The first snapshot of a record counts its textures even when the block is the previous
  // record's.
  if (refresh(texturing_, texturing_scratch_) || !last_id_) {
    changed = true;
    count_textures(*texturing_);
  }
  changed |= refresh(raster_, ctx.raster);
  changed |= refresh(pixel_transfer_, ctx.pixel_transfer);
  if (!changed && last_id_) return *last_id_;
  record.states.push_back({transform_, lighting_, texturing_, raster_, pixel_transfer_});
  last_id_ = static_cast<rec::StateId>(record.states.size() - 1);
  return *last_id_;
}

}  // namespace glpt
