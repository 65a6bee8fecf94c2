// Collects one frame's traced geometry. Consecutive primitives drawn with the same modelview
// are batched into one Geometry (one BLAS), so thousands of tiny glBegin/glEnd blocks or
// display-list calls do not become thousands of acceleration structures.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "gl_shim/geometry/triangulate.hpp"
#include "gl_shim/geometry/vertex_assembly.hpp"
#include "rt_core/frame.hpp"

namespace glpt {

class FrameCapture {
 public:
  // Adds the triangles of one primitive. `flat` copies the provoking vertex's normal and colour
  // to the whole triangle (GL_FLAT). Triangles with a non-finite vertex are dropped.
  void add_primitive(const glm::mat4& modelview, uint64_t modelview_version,
                     const VertexAssembly& primitive, const std::vector<TriangleIndices>& triangles,
                     bool flat);
  // glClear of the colour buffer: what was drawn before can no longer be seen.
  void discard();
  // Closes the open batch; the instances drawn since the last discard().
  const std::vector<rt::Instance>& instances();

  uint64_t triangles_dropped() const { return triangles_dropped_; }

 private:
  void close_batch();
  uint32_t intern_material(const rt::Material& m);

  std::unique_ptr<rt::Geometry> open_;
  glm::mat4 open_modelview_{1.0f};
  uint64_t open_modelview_version_ = 0;
  std::vector<rt::Instance> instances_;
  uint64_t triangles_dropped_ = 0;
};

}  // namespace glpt
