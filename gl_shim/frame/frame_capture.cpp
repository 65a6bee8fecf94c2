#include "gl_shim/frame/frame_capture.hpp"

#include <cmath>

#include "gl_shim/frame/content_hash.hpp"

namespace glpt {
namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

uint32_t FrameCapture::intern_material(const rt::Material& m) {
  auto& mats = open_->materials;
  // Batches hold few distinct materials; search from the end, where the last one used is.
  for (size_t i = mats.size(); i-- > 0;)
    if (mats[i] == m) return static_cast<uint32_t>(i);
  mats.push_back(m);
  return static_cast<uint32_t>(mats.size() - 1);
}

void FrameCapture::add_primitive(const glm::mat4& modelview, uint64_t modelview_version,
                                 const VertexAssembly& primitive,
                                 const std::vector<TriangleIndices>& triangles, bool flat) {
  if (triangles.empty()) return;
  if (open_ && open_modelview_version_ != modelview_version && open_modelview_ != modelview)
    close_batch();
  if (!open_) {
    open_ = std::make_unique<rt::Geometry>();
    open_modelview_ = modelview;
    open_modelview_version_ = modelview_version;
  }
  // Map the primitive's materials to the batch's.
  uint32_t local_ids[64];
  const size_t n_mats = primitive.materials.size();
  std::vector<uint32_t> many_ids;
  uint32_t* ids = local_ids;
  if (n_mats > 64) {
    many_ids.resize(n_mats);
    ids = many_ids.data();
  }
  for (size_t i = 0; i < n_mats; ++i) ids[i] = intern_material(primitive.materials[i]);

  rt::Geometry& g = *open_;
  const auto& v = primitive.vertices;
  for (const TriangleIndices& t : triangles) {
    const CapturedVertex& pv = v[t.provoking];
    if (!finite(v[t.v[0]].position) || !finite(v[t.v[1]].position) || !finite(v[t.v[2]].position)) {
      ++triangles_dropped_;
      continue;
    }
    for (uint32_t k : t.v) {
      g.positions.push_back(v[k].position);
      g.normals.push_back(flat ? pv.normal : v[k].normal);
      g.colors.push_back(flat ? pv.color : v[k].color);
    }
    g.material_ids.push_back(ids[pv.material]);
  }
}

void FrameCapture::close_batch() {
  if (!open_) return;
  if (open_->positions.empty()) {
    open_.reset();
    return;
  }
  ContentHash h;
  h.add(open_->positions);
  h.add(open_->normals);
  h.add(open_->colors);
  h.add(open_->material_ids);
  for (const rt::Material& m : open_->materials) {
    h.add_bytes(&m.ambient, sizeof(glm::vec4) * 4);
    h.add_bytes(&m.shininess, sizeof m.shininess);
    const uint32_t flags = (m.lit ? 1u : 0u) | (static_cast<uint32_t>(m.color_source) << 1);
    h.add_bytes(&flags, sizeof flags);
  }
  open_->content_hash = h.value();
  instances_.push_back(
      rt::Instance{std::shared_ptr<const rt::Geometry>(std::move(open_)), open_modelview_});
  open_.reset();
}

void FrameCapture::discard() {
  open_.reset();
  instances_.clear();
}

const std::vector<rt::Instance>& FrameCapture::instances() {
  close_batch();
  return instances_;
}

}  // namespace glpt
