// A conformance scene: a small, deterministic piece of GL 1.x drawing that both runners (real
// Mesa through OSMesa, and glpt's raster mode) execute from the same object code. Scenes include
// only <GL/gl.h>/<GL/glext.h> and call GL directly; they register themselves with GLPT_SCENE.
#pragma once

#include <string>
#include <vector>

namespace glpt::conformance {

// How close glpt's image must be to Mesa's. The default is the suite's acceptance rule: at least
// 99.5% of the pixels have every channel (R, G, B and A) within 2/255 of Mesa's value.
struct Tolerance {
  int max_channel_diff = 2;     // 0..255
  double min_fraction = 0.995;  // of all pixels, within max_channel_diff on every channel
  // Why a scene needs a tolerance other than the default; required exactly when it is not.
  const char* reason = nullptr;

  bool is_default() const { return max_channel_diff == 2 && min_fraction == 0.995; }
};

// A tolerance other than the default, with the reason it is legitimate (e.g. GL and Vulkan
// rasterize smooth lines differently).
constexpr Tolerance relaxed(double min_fraction, int max_channel_diff, const char* reason) {
  return Tolerance{max_channel_diff, min_fraction, reason};
}

struct Scene {
  const char* name;  // unique; [a-z0-9_]
  const char* file;  // source file, for messages
  int width, height;
  Tolerance tolerance;
  // Draws the scene into the current context's colour buffer (a fresh context of width x height
  // with default GL state, RGBA8 + depth 24 + stencil 8 + accum 16, single-buffered).
  void (*draw)();
};

// Every registered scene, in registration order (by file, then by position in the file).
const std::vector<Scene>& all_scenes();

// Checks the table: unique names made of [a-z0-9_], sizes 16..256, tolerances in range, a reason
// exactly for non-default tolerances. Returns the problems found (empty when the table is valid).
std::vector<std::string> validate_scenes(const std::vector<Scene>& scenes);

// Registers a scene at static-initialization time (see GLPT_SCENE).
struct SceneRegistrar {
  SceneRegistrar(const Scene& scene);
};

}  // namespace glpt::conformance

// Defines and registers a scene with the default tolerance:
//   GLPT_SCENE(lighting_light0_alone, 64, 64) { ...GL calls... }
#define GLPT_SCENE(name, width, height) \
  GLPT_SCENE_TOLERANCE(name, width, height, ::glpt::conformance::Tolerance{})

// The same with a tolerance other than the default, e.g.
//   GLPT_SCENE_TOLERANCE(lines_smooth, 64, 64, glpt::conformance::relaxed(0.97, 8, "why"))
#define GLPT_SCENE_TOLERANCE(name, width, height, tolerance)                                      \
  static void glpt_scene_##name();                                                                \
  static const ::glpt::conformance::SceneRegistrar glpt_scene_registrar_##name{                   \
      ::glpt::conformance::Scene{#name, __FILE__, width, height, tolerance, &glpt_scene_##name}}; \
  static void glpt_scene_##name()
