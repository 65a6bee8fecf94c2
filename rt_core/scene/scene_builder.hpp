// Path-traced mode's view of a frame record: the order in
// which the record's commands run around the trace (the passes), and the tracer's scene
// (TraceScene: triangles for secondary rays, lights and per-state data).
//
// Which draws are traced comes from classify.hpp (classify_frame; docs/classification.md): traced
// draws are drawn into the G-buffer and lit by the trace pass, sky draws are held for the rays
// that miss, fake shadows are not drawn, everything else is drawn by raster mode.
//
// Passes, in order:
//   1. G-buffer pass (`gbuffer_pass`): the record's commands up to the first traced draw as raster
//      mode draws them (a background drawn first stays behind the scene), then the traced draws
//      into the G-buffer and the clears among them, in record order. It shares the depth/stencil
//      buffer with raster mode, so coverage, depth test, culling, clip planes, polygon offset and
//      projective matrices are GL's.
//   2. Trace pass: lights the G-buffer's pixels into the colour buffers.
//   3. `after_trace`: the remaining commands that are not traced, and the clears after the last
//      traced draw, in record order, by raster mode over the traced image, depth-tested against
//      the G-buffer's depth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "rt_core/record/frame_record.hpp"
#include "rt_core/scene/classify.hpp"
#include "rt_core/scene/trace_scene.hpp"

namespace glpt::rt {

struct SceneBuild {
  TraceScene scene;
  std::vector<DrawClass> classes;  // per command (kNotTriangles for non-draws)
  std::vector<uint8_t> traced;     // per command: 1 for traced draws
  // Per command: 1 for draws split by alpha (DrawClass::kSplitByAlpha), which are in both passes:
  // their opaque fragments in the G-buffer pass, the others in `after_trace`.
  std::vector<uint8_t> split_by_alpha;
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
  // The frame's classification (classify_frame, with identities); null: classified here without.
  const FrameClassification* classification = nullptr;
};

void build_trace_scene(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
                       SceneBuild& out, const SceneOptions& options = {});

// The eye-space viewer of a projection: its centre of projection as a point (w = 1) for
// perspective projections, a unit direction towards the viewer (w = 0) for parallel ones, where
// the sign is GL's lighting convention (+Z, the infinite viewer).
glm::vec4 viewer_of_projection(const glm::mat4& projection);

// Whether `projection` mirrors what it shows (a glOrtho or glFrustum with right < left, or
// top < bottom): a triangle counter-clockwise as seen from its viewer (viewer_of_projection)
// runs clockwise in window coordinates, so GL calls its other face the front. False for a
// degenerate projection.
bool projection_mirrors(const glm::mat4& projection);

}  // namespace glpt::rt
