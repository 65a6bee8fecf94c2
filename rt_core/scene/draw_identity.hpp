// Identity of draws across frames: every draw of a frame is matched to one of the previous
// frame's and keeps that draw's id, so what the renderer derives from a draw (its class, its
// acceleration structure, its history) follows the object, not its position in the record.
//
// A draw is matched, in this order, to the previous frame's draw
//   1. with the same geometry (VertexKeys::geometry: positions and topology), first by order among
//      the draws of that geometry and appearance (two passes over one mesh stay apart), then of
//      that geometry, and, where that pairs draws far apart (identical meshes drawn
//      in another order), by nearest position;
//   2. else of the same topology and appearance (a mesh whose vertices moved: deforming), the
//      nearest one within its own size;
//   3. else a draw seen in an earlier frame but not the last (culled for a while and back), by
//      geometry, else by topology and appearance within its size;
//   4. else it gets a new id.
// Positions are compared in the world, not in eye space: the camera's motion since the last
// frame (camera_motion, per view: projection and viewport) is estimated first, as the eye-space
// motion most matched draws share (a camera folded into the modelview moves every static object
// the same way), so a static world under a moving camera stays static and a lone object turning
// in front of a still camera moves. A draw around the eye (its box holds it: a level, a room)
// is the world and counts twice, so a world drawn as one draw still shows the camera's motion.
// Distances are relative to the object's size, never a fixed number of units.
//
// Bounded: the previous frame's draws, plus at most Limits::max_lost draws not seen since for at
// most Limits::lost_frames frames (least recently seen dropped first).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <unordered_map>
#include <vector>

#include "rt_core/record/frame_record.hpp"

namespace glpt::rt {

// What a draw is relative to the previous frame.
enum class DrawMotion : uint8_t {
  kNew,        // no match in the previous frame (first frame, or back after being culled)
  kStatic,     // same geometry, same place in the world
  kMoving,     // same geometry, another transform relative to the world
  kDeforming,  // same topology and appearance, new vertex positions
};

// What identity matching knows of a draw.
struct DrawFingerprint {
  uint64_t geometry = 0;    // VertexKeys::geometry
  uint64_t topology = 0;    // primitive mode, source, vertex, index and primitive counts
  uint64_t appearance = 0;  // textures bound, blending, lighting and material, faces drawn
  uint64_t camera = 0;      // projection and viewport: each view has its own camera motion
  glm::mat4 modelview{1.0f};
  glm::mat4 projection{1.0f};  // where the draw's pixels were (the denoiser's reprojection)
  glm::vec3 object_min{0.0f}, object_max{0.0f};  // object-space box (bounded only)
  bool bounded = false;
};
DrawFingerprint fingerprint_of(const rec::Draw& draw, const rec::StateSnapshot& state);

struct DrawIdentity {
  uint64_t id = 0;  // stable while the draw exists; ids are never reused
  DrawMotion motion = DrawMotion::kNew;
  // Matched to a draw of the previous frame (kStatic, kMoving, kDeforming): its transforms, from
  // which the denoiser finds where this draw's surfaces were on screen.
  bool has_previous = false;
  glm::mat4 previous_modelview{1.0f};
  glm::mat4 previous_projection{1.0f};
};

class DrawIdentities {
 public:
  struct Limits {
    uint64_t lost_frames = 600;  // a draw not seen for longer gets a new id when it comes back
    size_t max_lost = 65536;
  };
  DrawIdentities() = default;
  explicit DrawIdentities(const Limits& limits) : limits_(limits) {}
  // Ids start at `first_id`: the renderer gives each drawable's identities a range of their own,
  // so what is keyed by id across drawables (BLAS lineages) never confuses two windows' draws.
  DrawIdentities(const Limits& limits, uint64_t first_id) : limits_(limits), next_id_(first_id) {}

  // Matches the draws of one record (`draws`, in GL order) against the previous frame's. A frame
  // may come in several records (a glReadPixels in the middle): they all match against the frame
  // before until end_frame().
  void match(std::span<const DrawFingerprint> draws, std::vector<DrawIdentity>& out);
  // The draws matched since the last call become the previous frame.
  void end_frame();
  // Both give the basic guarantee: when they throw (std::bad_alloc), every draw tracked so far is
  // forgotten (the next frame's draws get new ids), ids already given are never given again.

  // The eye-space motion of the world under `camera` (DrawFingerprint::camera) from the previous
  // frame to this one (identity: the camera did not move), as estimated by the last match.
  glm::mat4 camera_motion(uint64_t camera) const;
  size_t tracked() const { return previous_.size() + current_.size() + lost_.size(); }

 private:
  struct Entry {
    DrawFingerprint print;
    uint64_t id = 0;
    uint64_t last_frame = 0;
    glm::vec3 eye_centre{0.0f};
    float size = 0.0f;  // eye-space box diagonal
  };
  Entry entry_of(const DrawFingerprint& print, uint64_t id) const;
  void estimate_camera_motion(std::span<const DrawFingerprint> draws,
                              const std::vector<int64_t>& pairs);
  // How far `now` is from where `before` would be had it not moved in the world, relative to
  // their size.
  float relative_distance(const Entry& before, const Entry& now) const;
  float relative_distance(const Entry& before, const Entry& now, const glm::mat4& motion) const;
  bool same_place(const Entry& before, const Entry& now) const;
  void match_unguarded(std::span<const DrawFingerprint> draws, std::vector<DrawIdentity>& out);
  void end_frame_unguarded();
  void forget_all() noexcept;

  Limits limits_;
  std::vector<Entry> previous_;
  std::vector<uint8_t> previous_taken_;
  std::unordered_map<uint64_t, std::vector<size_t>> previous_by_geometry_;
  std::unordered_map<uint64_t, std::vector<size_t>> previous_by_exact_;  // geometry + appearance
  std::unordered_map<uint64_t, std::vector<size_t>> previous_by_look_;   // topology ^ appearance
  std::vector<Entry> current_;
  std::vector<Entry> lost_;
  std::unordered_map<uint64_t, std::vector<size_t>> lost_by_geometry_, lost_by_look_;
  uint64_t next_id_ = 1;
  uint64_t frame_ = 0;
  std::unordered_map<uint64_t, glm::mat4> camera_motion_;  // per camera; absent: identity
};

}  // namespace glpt::rt
