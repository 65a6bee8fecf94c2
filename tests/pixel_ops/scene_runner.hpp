// Pixel rectangle and accumulation scenes (glRasterPos, glWindowPos, glBitmap, glDrawPixels,
// glCopyPixels, glAccum) rendered by real Mesa (OSMesa) and by glpt's raster mode, compared pixel
// by pixel: at least 99.5% of each scene's pixels must have every channel within 2/255 of Mesa's.
//
// Both runners execute the same scene code (scenes.cpp, plain GL 1.5 calls); the GL entry points
// resolve to libOSMesa in one and to glpt's front end in the other. Each writes one raw RGBA8
// file per scene (rows bottom to top, as glReadPixels returns them); either runner compares two
// output directories.
//
// This is a stand-in for the conformance suite (tests/conformance, branch `conformance`): once
// that is in main, these scenes belong there.
#pragma once

#include <string>
#include <vector>

namespace glpt::pixel_ops {

struct Scene {
  const char* name;
  int width, height;
  void (*draw)();
};

// Every scene, in a fixed order.
const std::vector<Scene>& scenes();

// What a runner provides: a fresh context of width x height with default GL state (RGBA8, depth
// 24, stencil 8, accumulation 16), current until end_scene.
class Backend {
 public:
  virtual ~Backend() = default;
  virtual bool begin_scene(int width, int height, std::string* error) = 0;
  virtual void end_scene() = 0;
};

// runner --out DIR [--scene NAME]: renders the scenes into DIR/NAME.rgba (and DIR/NAME.png).
// runner --compare MESA_DIR GLPT_DIR: compares every scene; exit status 1 if one is off.
int run_main(int argc, char** argv, Backend& backend);

}  // namespace glpt::pixel_ops
