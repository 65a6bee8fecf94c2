#include "rt_core/scene/draw_identity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/content_hash.hpp"
#include "rt_core/scene/light_setup.hpp"

namespace glpt::rt {
namespace {

// Groups larger than this are paired by order only: nearest matching is quadratic.
constexpr size_t kMaxNearestGroup = 64;
// A draw paired by order further than this (relative to its size) from where its partner was is
// re-paired by nearest position.
constexpr float kOrderPairSlack = 0.5f;
// A draw of another geometry is the same object when this close (relative to its size).
constexpr float kSameObjectDistance = 1.0f;

bool affine(const glm::mat4& m) {
  return m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f && m[3][3] == 1.0f;
}

bool invertible(const glm::mat4& m) {
  const glm::mat3 linear(m);
  const float scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
  const float det = glm::determinant(linear);
  return std::isfinite(det) && scale > 0.0f && std::abs(det) > 1e-6f * scale;
}

// Two eye-space motions are the same camera motion: equal rotation/scale to 1e-3 and equal
// translation to 1e-3 of its size.
bool same_motion(const glm::mat4& a, const glm::mat4& b) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (!(std::abs(a[c][r] - b[c][r]) <= 1e-3f)) return false;
  const glm::vec3 ta(a[3]), tb(b[3]);
  const float scale = 1.0f + std::max(glm::length(ta), glm::length(tb));
  return glm::length(ta - tb) <= 1e-3f * scale;
}

bool is_identity(const glm::mat4& m) { return same_motion(m, glm::mat4(1.0f)); }

// Geometry and appearance together: the same mesh drawn in the same way.
uint64_t exact_key(const DrawFingerprint& d) {
  return d.geometry ^ (d.appearance * 0x9E3779B97F4A7C15ull);
}

}  // namespace

DrawFingerprint fingerprint_of(const rec::Draw& draw, const rec::StateSnapshot& state) {
  DrawFingerprint print;
  const rec::VertexData& v = *draw.vertices;
  const rec::VertexKeys& keys = v.keys();
  print.geometry = keys.geometry;
  ContentHash topology;
  const uint32_t counts[5] = {v.mode, static_cast<uint32_t>(v.source), v.vertex_count(),
                              static_cast<uint32_t>(v.indices.size()),
                              static_cast<uint32_t>(v.primitives.size())};
  topology.add_bytes(counts, sizeof counts);
  // The ranges of a few primitives: enough to tell strips of one grid from another's.
  const size_t ranges = std::min<size_t>(v.primitives.size(), 16);
  topology.add_bytes(v.primitives.data(), ranges * sizeof(rec::PrimitiveRange));
  print.topology = topology.value();
  ContentHash appearance;
  for (const rec::TextureUnitState& unit : state.texturing->units) {
    const uint64_t texture = unit.texture ? unit.texture->content_version : 0;
    appearance.add_bytes(&unit.target, sizeof unit.target);
    appearance.add_bytes(&texture, sizeof texture);
  }
  const rec::FragmentOpsState& ops = state.raster->ops;
  const rec::PrimitiveState& primitive = state.raster->primitive;
  const uint32_t flags = (ops.blend ? 1u : 0u) | (state.lighting->enabled ? 2u : 0u) |
                         (primitive.cull_face ? 4u : 0u) | (ops.depth_write ? 8u : 0u) |
                         (ops.color_write[0] ? 16u : 0u) | (ops.stencil_test ? 32u : 0u);
  appearance.add_bytes(&flags, sizeof flags);
  const uint32_t faces[3] = {primitive.cull_face ? primitive.cull_face_mode : 0u,
                             primitive.front_face, ops.depth_func};
  appearance.add_bytes(faces, sizeof faces);
  if (ops.blend) {
    const uint32_t blend[2] = {ops.blend_src_rgb, ops.blend_dst_rgb};
    appearance.add_bytes(blend, sizeof blend);
  }
  if (state.lighting->enabled)
    appearance.add_bytes(&state.lighting->material[0].diffuse,
                         sizeof state.lighting->material[0].diffuse);
  print.appearance = appearance.value();
  ContentHash camera;
  camera.add_bytes(&state.transform->projection, sizeof state.transform->projection);
  camera.add_bytes(&state.transform->viewport, sizeof state.transform->viewport);
  print.camera = camera.value();
  print.modelview = state.transform->modelview;
  print.projection = state.transform->projection;
  print.bounded = keys.bounded();
  if (print.bounded) {
    print.object_min = keys.bounds_min;
    print.object_max = keys.bounds_max;
  }
  return print;
}

DrawIdentities::Entry DrawIdentities::entry_of(const DrawFingerprint& print, uint64_t id) const {
  Entry e;
  e.print = print;
  e.id = id;
  e.last_frame = frame_;
  if (print.bounded && affine(print.modelview)) {
    const EyeBounds box =
        EyeBounds::transformed(print.object_min, print.object_max, print.modelview);
    if (!box.empty() && std::isfinite(box.diagonal())) {
      e.eye_centre = 0.5f * (box.min + box.max);
      e.size = box.diagonal();
    }
  }
  return e;
}

glm::mat4 DrawIdentities::camera_motion(uint64_t camera) const {
  auto found = camera_motion_.find(camera);
  return found == camera_motion_.end() ? glm::mat4(1.0f) : found->second;
}

float DrawIdentities::relative_distance(const Entry& before, const Entry& now) const {
  return relative_distance(before, now, camera_motion(now.print.camera));
}

float DrawIdentities::relative_distance(const Entry& before, const Entry& now,
                                        const glm::mat4& motion) const {
  const glm::vec3 expected = glm::vec3(motion * glm::vec4(before.eye_centre, 1.0f));
  const float size = std::max(before.size, now.size);
  const float distance = glm::length(expected - now.eye_centre);
  if (!std::isfinite(distance)) return std::numeric_limits<float>::max();
  if (size <= 0.0f) return distance == 0.0f ? 0.0f : std::numeric_limits<float>::max();
  return distance / size;
}

bool DrawIdentities::same_place(const Entry& before, const Entry& now) const {
  const glm::mat4& a = now.print.modelview;
  const glm::mat4 b = camera_motion(now.print.camera) * before.print.modelview;
  if (!now.print.bounded) return same_motion(a, b);
  // The object's box corners where it is and where it would be had it not moved in the world.
  const float size = std::max(now.size, 1e-20f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec4 p((corner & 1) ? now.print.object_max.x : now.print.object_min.x,
                      (corner & 2) ? now.print.object_max.y : now.print.object_min.y,
                      (corner & 4) ? now.print.object_max.z : now.print.object_min.z, 1.0f);
    const glm::vec4 pa = a * p, pb = b * p;
    const float tolerance = 1e-3f * size + 1e-5f * glm::length(glm::vec3(pa));
    if (!(glm::length(glm::vec3(pa) - glm::vec3(pb)) <= tolerance)) return false;
  }
  return true;
}

void DrawIdentities::estimate_camera_motion(std::span<const DrawFingerprint> draws,
                                            const std::vector<int64_t>& pairs) {
  // Per camera: candidate motions and the votes for each; at most a few kept (a still world under
  // a moving camera has one; a few moving objects add one each).
  struct Candidate {
    glm::mat4 motion;
    uint32_t votes;
  };
  struct View {
    std::vector<Candidate> candidates;
    uint32_t still = 0;
  };
  std::unordered_map<uint64_t, View> views;
  for (size_t i = 0; i < draws.size(); ++i) {
    if (pairs[i] < 0) continue;
    const Entry& earlier = previous_[static_cast<size_t>(pairs[i])];
    if (earlier.print.camera != draws[i].camera) continue;
    const glm::mat4& before = earlier.print.modelview;
    const glm::mat4& now = draws[i].modelview;
    if (!affine(before) || !affine(now) || !invertible(before)) continue;
    // A draw around the eye is the world (a level, a room): it counts twice.
    const EyeBounds box =
        earlier.print.bounded
            ? EyeBounds::transformed(earlier.print.object_min, earlier.print.object_max, before)
            : EyeBounds();
    const bool around_the_eye = !box.empty() && box.contains(glm::vec3(0.0f));
    const uint32_t votes = around_the_eye ? 2 : 1;
    View& view = views[draws[i].camera];
    const glm::mat4 motion = now * glm::inverse(before);
    if (is_identity(motion)) {
      view.still += votes;
      continue;
    }
    auto it = std::find_if(view.candidates.begin(), view.candidates.end(),
                           [&](const Candidate& c) { return same_motion(c.motion, motion); });
    if (it != view.candidates.end())
      it->votes += votes;
    else if (view.candidates.size() < 16)
      view.candidates.push_back({motion, votes});
  }
  camera_motion_.clear();
  for (const auto& [camera, view] : views) {
    uint32_t best = 0;
    glm::mat4 motion(1.0f);
    for (const Candidate& c : view.candidates)
      if (c.votes > best) {
        best = c.votes;
        motion = c.motion;
      }
    // One object alone cannot tell a moving camera from a moving object (a lone object turning
    // in front of a still camera moves), and a still camera wins ties.
    if (best >= 2 && best > view.still) camera_motion_[camera] = motion;
  }
}

void DrawIdentities::forget_all() noexcept {
  previous_.clear();
  previous_taken_.clear();
  previous_by_geometry_.clear();
  previous_by_exact_.clear();
  previous_by_look_.clear();
  current_.clear();
  lost_.clear();
  lost_by_geometry_.clear();
  lost_by_look_.clear();
  camera_motion_.clear();
}

// An allocation failing half-way would leave the indices pointing past the vectors they index:
// forgetting everything is the consistent state to fall back to.
void DrawIdentities::match(std::span<const DrawFingerprint> draws, std::vector<DrawIdentity>& out) {
  try {
    match_unguarded(draws, out);
  } catch (...) {
    forget_all();
    throw;
  }
}

void DrawIdentities::end_frame() {
  try {
    end_frame_unguarded();
  } catch (...) {
    forget_all();
    ++frame_;
    throw;
  }
}

void DrawIdentities::match_unguarded(std::span<const DrawFingerprint> draws,
                                     std::vector<DrawIdentity>& out) {
  out.assign(draws.size(), DrawIdentity());
  std::vector<Entry> now;
  now.reserve(draws.size());
  for (const DrawFingerprint& print : draws) now.push_back(entry_of(print, 0));

  // 1. Same geometry, by order among the draws of that geometry and appearance, then of that
  // geometry.
  std::vector<int64_t> pairs(draws.size(), -1);
  std::unordered_map<uint64_t, std::vector<size_t>> groups;  // this record's draws by geometry
  for (size_t i = 0; i < draws.size(); ++i) groups[draws[i].geometry].push_back(i);
  auto pair_by = [&](const std::unordered_map<uint64_t, std::vector<size_t>>& index, auto key_of) {
    std::unordered_map<uint64_t, size_t> next_of_key;
    for (size_t i = 0; i < draws.size(); ++i) {
      if (pairs[i] >= 0) continue;
      const uint64_t key = key_of(draws[i]);
      auto found = index.find(key);
      if (found == index.end()) continue;
      size_t& next = next_of_key[key];
      while (next < found->second.size() && previous_taken_[found->second[next]]) ++next;
      if (next < found->second.size()) {
        pairs[i] = static_cast<int64_t>(found->second[next]);
        previous_taken_[found->second[next]] = 1;
        ++next;
      }
    }
  };
  pair_by(previous_by_exact_, exact_key);
  pair_by(previous_by_geometry_, [](const DrawFingerprint& d) { return d.geometry; });
  estimate_camera_motion(draws, pairs);

  // Identical meshes drawn in another order: re-pair a group by nearest position where pairing by
  // order put a draw far from its partner.
  for (auto& [geometry, members] : groups) {
    if (members.size() < 2 || members.size() > kMaxNearestGroup) continue;
    bool far = false;
    for (size_t i : members)
      if (pairs[i] >= 0 &&
          relative_distance(previous_[static_cast<size_t>(pairs[i])], now[i]) > kOrderPairSlack)
        far = true;
    if (!far) continue;
    std::vector<size_t> partners;
    for (size_t i : members)
      if (pairs[i] >= 0) {
        partners.push_back(static_cast<size_t>(pairs[i]));
        pairs[i] = -1;
      }
    struct Option {
      float distance;
      size_t member, partner;
    };
    std::vector<Option> options;
    for (size_t i : members)
      for (size_t p : partners) options.push_back({relative_distance(previous_[p], now[i]), i, p});
    std::stable_sort(options.begin(), options.end(),
                     [](const Option& a, const Option& b) { return a.distance < b.distance; });
    std::vector<uint8_t> partner_used(previous_.size(), 0);
    for (const Option& o : options) {
      if (pairs[o.member] >= 0 || partner_used[o.partner]) continue;
      pairs[o.member] = static_cast<int64_t>(o.partner);
      partner_used[o.partner] = 1;
    }
  }
  for (size_t i = 0; i < draws.size(); ++i) {
    if (pairs[i] < 0) continue;
    const Entry& before = previous_[static_cast<size_t>(pairs[i])];
    out[i] = {before.id, same_place(before, now[i]) ? DrawMotion::kStatic : DrawMotion::kMoving,
              true, before.print.modelview, before.print.projection};
  }

  // 2. Same topology and appearance, new positions: the nearest within its size.
  for (size_t i = 0; i < draws.size(); ++i) {
    if (out[i].id != 0) continue;
    auto found = previous_by_look_.find(draws[i].topology ^ draws[i].appearance);
    if (found == previous_by_look_.end()) continue;
    float best = kSameObjectDistance;
    int64_t partner = -1;
    size_t looked = 0;
    for (size_t p : found->second) {
      if (previous_taken_[p] || previous_[p].print.geometry == draws[i].geometry) continue;
      if (++looked > kMaxNearestGroup) break;
      const float d = relative_distance(previous_[p], now[i]);
      if (d <= best) {
        best = d;
        partner = static_cast<int64_t>(p);
      }
    }
    if (partner < 0) continue;
    previous_taken_[static_cast<size_t>(partner)] = 1;
    const Entry& before = previous_[static_cast<size_t>(partner)];
    out[i] = {before.id, DrawMotion::kDeforming, true, before.print.modelview,
              before.print.projection};
  }

  // 3. Draws seen before the last frame: by geometry (the nearest), else by look within their
  // size. The camera may have moved any way since: positions are compared in eye space.
  for (size_t i = 0; i < draws.size(); ++i) {
    if (out[i].id != 0) continue;
    int64_t found = -1;
    float best = std::numeric_limits<float>::max();
    auto consider = [&](const std::unordered_map<uint64_t, std::vector<size_t>>& index,
                        uint64_t key, float limit) {
      auto candidates = index.find(key);
      if (candidates == index.end()) return;
      size_t looked = 0;
      for (size_t l : candidates->second) {
        if (lost_[l].id == 0) continue;
        if (++looked > kMaxNearestGroup) break;
        const float d = relative_distance(lost_[l], now[i], glm::mat4(1.0f));
        if (d <= limit && d < best) {
          best = d;
          found = static_cast<int64_t>(l);
        }
      }
    };
    consider(lost_by_geometry_, draws[i].geometry, std::numeric_limits<float>::max());
    if (found < 0)
      consider(lost_by_look_, draws[i].topology ^ draws[i].appearance, kSameObjectDistance);
    if (found < 0) continue;
    out[i].id = lost_[static_cast<size_t>(found)].id;
    lost_[static_cast<size_t>(found)].id = 0;  // taken: erased at end_frame
  }

  // 4. New ids.
  for (size_t i = 0; i < draws.size(); ++i) {
    if (out[i].id == 0) out[i].id = next_id_++;
    now[i].id = out[i].id;
    current_.push_back(std::move(now[i]));
  }
}

void DrawIdentities::end_frame_unguarded() {
  // Last frame's draws not seen in this one are lost (kept a while: culled objects come back).
  for (size_t p = 0; p < previous_.size(); ++p)
    if (!previous_taken_[p]) lost_.push_back(std::move(previous_[p]));
  std::erase_if(lost_, [&](const Entry& e) {
    return e.id == 0 || frame_ - e.last_frame > limits_.lost_frames;
  });
  if (lost_.size() > limits_.max_lost) {
    // Least recently seen first out.
    std::stable_sort(lost_.begin(), lost_.end(),
                     [](const Entry& a, const Entry& b) { return a.last_frame > b.last_frame; });
    lost_.resize(limits_.max_lost);
  }
  previous_ = std::move(current_);
  current_.clear();
  previous_taken_.assign(previous_.size(), 0);
  previous_by_geometry_.clear();
  previous_by_exact_.clear();
  previous_by_look_.clear();
  for (size_t p = 0; p < previous_.size(); ++p) {
    previous_by_geometry_[previous_[p].print.geometry].push_back(p);
    previous_by_exact_[exact_key(previous_[p].print)].push_back(p);
    previous_by_look_[previous_[p].print.topology ^ previous_[p].print.appearance].push_back(p);
  }
  lost_by_geometry_.clear();
  lost_by_look_.clear();
  for (size_t l = 0; l < lost_.size(); ++l) {
    lost_by_geometry_[lost_[l].print.geometry].push_back(l);
    lost_by_look_[lost_[l].print.topology ^ lost_[l].print.appearance].push_back(l);
  }
  ++frame_;
}

}  // namespace glpt::rt
