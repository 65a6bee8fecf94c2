// Path-traced mode's view of a frame record: which draws are traced (classify_draw), the order in
// which the record's commands run around the trace (the passes), and the tracer's scene
// (TraceScene: triangles for secondary rays, lights and per-state data).
//
// Classification, per draw, until the classification issue lands:
//   traced        triangles (filled on both faces) under the main camera, not blended, no logic
//                 op, writing all colour channels to a colour buffer. Drawn into the G-buffer by
//                 the raster pipelines and lit by the trace pass.
//   sky           would be traced, but is the sky (find_sky): drawn at the far plane
//                 (glDepthRange(1, 1)), or unlit, before every traced draw, around the camera
//                 (its eye-space box holds the eye) and either without depth writes or depth test
//                 (a run of such draws together: a sky box of six faces) or centred on the
//                 camera (within 10 % of its half size). Rays do not hit it (a sky box traced
//                 blocks every shadow and bounce ray); raster mode draws it where it lies.
//   every other   points, lines, unfilled polygons, draws under another projection or viewport
//                 (HUD, 2-D overlays, a second view), blended or logic-op draws (they read the
//                 colour under them), draws with colour writes masked: raster mode draws them.
// The main camera is the projection and viewport under which the most triangles of otherwise
// traceable draws are drawn, preferring perspective projections (the 3-D view) over parallel
// ones (a HUD of many quads must not take the camera from a small 3-D scene).
//
// Passes, in order:
//   1. G-buffer pass (`gbuffer_pass`): the record's commands up to the first traced draw as raster
//      mode draws them (a background drawn first stays behind the scene), then the traced draws
//      into the G-buffer and the clears among them, in record order. It shares the depth/stencil
//      buffer with raster mode, so coverage, depth test, culling, clip planes, polygon offset and
//      projective matrices are GL's.
//   2. Trace pass: lights the G-buffer's pixels into the colour buffers.
//   3. `after_trace`: the remaining commands that are not traced, in record order, by raster mode
//      over the traced image, depth-tested against the G-buffer's depth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "rt_core/record/frame_record.hpp"
#include "rt_core/scene/trace_scene.hpp"

namespace glpt::rt {

enum class DrawClass : uint8_t {
  kTraced,
  kNotTriangles,  // points, lines
  kUnfilled,      // GL_LINE / GL_POINT polygon mode
  kBlended,       // blending or a logic op
  kMaskedColor,   // some colour channel masked, or no colour buffer drawn to
  kOtherCamera,   // another projection or viewport than the main camera's
  kSky,           // the sky around the camera, drawn by raster mode (find_sky)
};

// The class of one draw, given the main camera (`main_projection`, `main_viewport`) and the
// drawable. Draws under the main camera and traceable otherwise are kTraced.
struct MainCamera {
  glm::mat4 projection{1.0f};
  std::array<int32_t, 4> viewport{0, 0, 0, 0};
  bool valid = false;
};
MainCamera find_main_camera(const rec::FrameRecord& record, const rec::DrawableConfig& drawable);
DrawClass classify_draw(const rec::Draw& draw, const rec::StateSnapshot& state,
                        const MainCamera& camera, const rec::DrawableConfig& drawable);

// Turns the classes of the record's sky draws from kTraced into kSky (`classes`: per command,
// as classify_draw gives them).
void find_sky(const rec::FrameRecord& record, std::vector<DrawClass>& classes);

struct SceneBuild {
  TraceScene scene;
  std::vector<DrawClass> classes;    // per command (kNotTriangles for non-draws)
  std::vector<uint8_t> traced;       // per command: 1 for traced draws
  std::vector<size_t> gbuffer_pass;  // commands of pass 1, in record order
  std::vector<size_t> after_trace;   // commands of pass 3, in record order
  bool any_traced = false;
  bool any_sky = false;  // some draw is kSky (the scene's instances include it)
};

// Whether the tracer already holds the acceleration structure and shading data of a geometry
// (its shape and shading hashes): such geometry is not decomposed again (Geometry::resident).
using KnownGeometry = std::function<bool(uint64_t shape_hash, uint64_t shading_hash)>;

struct SceneOptions {
  // A lit scene without any enabled light gets default_light() (GLPT_DEFAULT_LIGHT=1); by
  // default it is lit by GL's ambient and emission alone, as GL lights it.
  bool default_light = false;
  KnownGeometry known_geometry;  // empty: every geometry is decomposed
};

void build_trace_scene(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
                       SceneBuild& out, const SceneOptions& options = {});

// The eye-space viewer of a projection: its centre of projection as a point (w = 1) for
// perspective projections, a unit direction towards the viewer (w = 0) for parallel ones, where
// the sign is GL's lighting convention (+Z, the infinite viewer).
glm::vec4 viewer_of_projection(const glm::mat4& projection);

}  // namespace glpt::rt
