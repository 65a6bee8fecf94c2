// GL 1.x shapes shared by tests that reach GL through different declarations: the conformance
// scenes (the system's <GL/gl.h>, run on Mesa and on glpt) and the in-process tests
// (gl_shim/gl_entry_decls.h). Header-only: include it after either; call with a current context.
#pragma once

#include <cmath>
#include <numbers>

namespace glpt::test_shapes {

// A sphere of `radius` around (cx, cy, cz) as quad strips with unit normals, each vertex computed
// in double and rounded to float only once by glVertex3d: at 1e5 from the origin the float
// vertices are 1/128 apart, which is the point of the extremes scenes that use it.
inline void sphere_around(double cx, double cy, double cz, double radius, int slices, int stacks) {
  constexpr double pi = std::numbers::pi;
  for (int i = 0; i < stacks; ++i) {
    const double p0 = pi * i / stacks - pi / 2, p1 = pi * (i + 1) / stacks - pi / 2;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const double a = 2 * pi * j / slices;
      for (const double p : {p1, p0}) {
        const double nx = std::cos(p) * std::cos(a), ny = std::cos(p) * std::sin(a),
                     nz = std::sin(p);
        glNormal3d(nx, ny, nz);
        glVertex3d(cx + radius * nx, cy + radius * ny, cz + radius * nz);
      }
    }
    glEnd();
  }
}

}  // namespace glpt::test_shapes
