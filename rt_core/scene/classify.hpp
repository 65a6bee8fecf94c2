// What every draw of a frame is, from GL state alone (docs/classification.md): nothing is tagged
// by hand. Two answers per command:
//   DrawKind   what the draw is (static, moving, deforming, blended, particles, multipass, decal,
//              overlay, sky, shadow, viewmodel; lines and hidden for what the taxonomy leaves
//              out), with its stable identity (draw_identity.hpp): GLPT_CLASSIFY_LOG writes it.
//   DrawClass  how path-traced mode draws it: traced (G-buffer and rays), sky (drawn by raster
//              mode, seen by rays that miss), dropped (fake shadows: the tracer's shadows are
//              real), or drawn by raster mode around the trace (everything else).
// The same classification runs in raster mode when GLPT_CLASSIFY_LOG asks for it.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "rt_core/frame_stats.hpp"
#include "rt_core/record/frame_record.hpp"
#include "rt_core/scene/draw_identity.hpp"

namespace glpt::rt {

enum class DrawClass : uint8_t {
  kTraced,
  kNotTriangles,  // points, lines
  kUnfilled,      // GL_LINE / GL_POINT polygon mode
  kBlended,       // blending or a logic op
  kMaskedColor,   // some colour channel masked, or no colour buffer drawn to
  kOtherCamera,   // another 3-D projection or viewport than the main camera's (a second view)
  kSky,           // the sky around the camera, drawn by raster mode (find_sky)
  kOverlay,       // 2-D: parallel projections, or the depth test off after the world
  kShadow,        // a fake shadow: not drawn in path-traced mode
  kViewmodel,     // first-person geometry in its own depth range or projection: traced (into the
                  // G-buffer, lit by rays) but not in the TLAS, so it casts no shadow on the world
  // A blended draw of a solid object with see-through texels (fragment_opacity.hpp,
  // splits_by_alpha): traced where its fragments are opaque (alpha 1: the G-buffer and the
  // TLAS), drawn blended over the trace where they are not
  kSplitByAlpha,
};

enum class DrawKind : uint8_t {
  kNone,  // not a drawing command
  kStatic,
  kMoving,
  kDeforming,
  kBlended,
  kParticles,
  kMultipass,
  kDecal,
  kOverlay,
  kSky,
  kShadow,
  kViewmodel,
  kLines,   // points, lines and unfilled polygons that are none of the above
  kHidden,  // draws that write no colour and are no shadow volume (depth or stencil passes)
};
inline constexpr size_t kDrawKindCount = 14;
static_assert(kDrawKindCount == std::tuple_size_v<decltype(FrameStats::kind_draws)>);
const char* draw_kind_name(DrawKind kind);

struct CommandLabel {
  DrawKind kind = DrawKind::kNone;
  uint32_t calls = 0;  // the program's drawing commands it covers (glBegin/glEnd pairs, ...)
  uint64_t id = 0;     // stable identity of the draw (pixel commands: of their kind and place)
  // A modulating multipass draw (a lightmap, a detail texture) over the very triangles of an
  // earlier traced draw: that draw's command + 1 (0: none). Path-traced mode folds its texture
  // into that surface as a further texture unit for the rays (scene_builder.cpp).
  uint32_t folds_onto = 0;
};

// The main camera: the 3-D view path-traced mode traces.
struct MainCamera {
  glm::mat4 projection{1.0f};
  std::array<int32_t, 4> viewport{0, 0, 0, 0};
  float depth_near = 0.0f, depth_far = 1.0f;
  bool valid = false;
};

struct FrameClassification {
  MainCamera camera;
  std::vector<DrawClass> classes;        // per command (kNotTriangles for non-draws)
  std::vector<CommandLabel> labels;      // per command
  std::vector<DrawIdentity> identities;  // per fingerprinted command (see identity_of)
  std::vector<int32_t> identity_of;      // per command: its index in identities, -1: none
  std::vector<DrawFingerprint> prints;   // scratch
};

// GL's perspective projections have a last row other than (0, 0, 0, 1).
bool is_perspective_projection(const glm::mat4& projection);
// A modelview whose bottom row is not (0, 0, 0, 1) (planar shadow matrices): an affine TLAS
// instance transform cannot hold it.
bool is_projective_modelview(const glm::mat4& modelview);

// The main camera: among perspective projections (with their viewports) of otherwise traceable
// draws, those with at least a fifth of the most triangles any of them has are candidates, and
// the first drawn wins (the world comes before a view model or a menu's 3-D model, which may have
// more triangles; a sky of a dozen is no candidate). Parallel projections only when no
// perspective one draws.
MainCamera find_main_camera(const rec::FrameRecord& record, const rec::DrawableConfig& drawable);

// How path-traced mode draws one draw, before the sky and the frame-level rules.
DrawClass classify_draw(const rec::Draw& draw, const rec::StateSnapshot& state,
                        const MainCamera& camera, const rec::DrawableConfig& drawable);

// Turns the classes of the record's sky draws into kSky (`classes`: per command, as
// classify_draw gives them): traced draws, and draws of another camera whose view is the main
// camera's but for its near and far planes (a sky drawn under a projection reaching farther).
void find_sky(const rec::FrameRecord& record, const MainCamera& camera,
              std::vector<DrawClass>& classes);

// Classifies every command of `record`. `identities` (may be null: every draw new, ids 0)
// matches draws against the previous frame's and is updated.
void classify_frame(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
                    DrawIdentities* identities, FrameClassification& out);

}  // namespace glpt::rt
