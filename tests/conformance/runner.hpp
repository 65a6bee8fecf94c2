// The command line shared by both conformance runners (glpt_conformance_mesa and
// glpt_conformance_glpt). A runner supplies a Backend that creates a fresh GL context per scene;
// everything else (scene selection, reading the image back, the state dump, files) is common.
#pragma once

#include <string>

namespace glpt::conformance {

class Backend {
 public:
  virtual ~Backend() = default;
  // "mesa" or "glpt": recorded in the state dump.
  virtual const char* name() const = 0;
  // Creates a context with default state drawing to a width x height RGBA8 colour buffer with
  // 24-bit depth, 8-bit stencil and 16-bit accumulation, and makes it current. Returns false with
  // *error set when that is impossible.
  virtual bool begin_scene(int width, int height, std::string* error) = 0;
  // Releases the current context (each scene starts from a new one: no state leaks between
  // scenes in a run of several).
  virtual void end_scene() = 0;
};

// Parses the command line and runs it; returns the process exit status (0 ok, 1 a scene could
// not run, 2 usage).
int run_main(int argc, char** argv, Backend& backend);

}  // namespace glpt::conformance
