// Bezier curves and surfaces evaluated with Mesa's arithmetic (src/mesa/math/m_eval.c, Mesa
// 25.0.7), so that evaluated vertices are bit-identical to Mesa's: points by Horner's scheme
// with binomial coefficients built up as Mesa does (multiplied by 1/i from a table of floats),
// surfaces with normals by Mesa's de Casteljau variants, one per combination of small and large
// orders, each rounding in its own order. The parameters are already normalized to [0, 1] over
// the map's domain. `dim` is the number of components per control point (1-4).
#pragma once

#include <cstddef>

namespace glpt::bezier {

// The curve of `order` control points spaced `stride` floats apart, at t: dim values in `out`.
void curve(const float* points, std::size_t stride, unsigned dim, unsigned order, float t,
           float* out);

// The tensor-product surface points[(i * vorder + j) * dim + k] at (u, v).
void surface(const float* points, unsigned dim, unsigned uorder, unsigned vorder, float u, float v,
             float* out);

// The surface point and its (unnormalized) partial derivatives in u and v, as Mesa computes them
// for GL_AUTO_NORMAL. An order of 1 in either direction (where Mesa reads past its control
// points) gives the point by `surface` and zero derivatives.
void surface_with_derivatives(const float* points, unsigned dim, unsigned uorder, unsigned vorder,
                              float u, float v, float* out, float* du, float* dv);

}  // namespace glpt::bezier
