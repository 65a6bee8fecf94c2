// Every expression below keeps the operand order and grouping of Mesa's float arithmetic (the
// front end is built without FMA contraction), which decides the last bits of each vertex.
#include "gl_shim/evaluators/bezier.hpp"

#include <algorithm>
#include <array>

#include "gl_shim/evaluators/evaluator_state.hpp"

namespace glpt::bezier {
namespace {

// Mesa multiplies binomial coefficients by 1/i from a table of floats.
float reciprocal(unsigned i) { return 1.0f / static_cast<float>(i); }

// Scratch of Mesa's de Casteljau steps for one component: uorder x vorder values, row i (u) of
// vorder values (Mesa's layout; the steps work in place, so the layout is part of the result).
class Scratch {
 public:
  explicit Scratch(unsigned vorder) : vorder_(vorder) {}
  float& operator()(unsigned i, unsigned j) { return values_[i * vorder_ + j]; }

 private:
  unsigned vorder_;
  std::array<float, kMaxEvalOrder * kMaxEvalOrder> values_{};
};

}  // namespace

void curve(const float* cp, std::size_t stride, unsigned dim, unsigned order, float t, float* out) {
  if (order < 2) {  // a constant curve
    for (unsigned k = 0; k < dim; ++k) out[k] = cp[k];
    return;
  }
  // ((C(n,0) s b0 + C(n,1) t b1) s + C(n,2) t^2 b2) s + ..., s = 1 - t
  const float s = 1.0f - t;
  float coefficient = static_cast<float>(order - 1);
  for (unsigned k = 0; k < dim; ++k) out[k] = s * cp[k] + coefficient * t * cp[stride + k];
  float t_power = t * t;
  for (unsigned i = 2; i < order; ++i, t_power *= t) {
    coefficient *= static_cast<float>(order - i);
    coefficient *= reciprocal(i);
    const float* p = cp + i * stride;
    for (unsigned k = 0; k < dim; ++k) out[k] = s * out[k] + coefficient * t_power * p[k];
  }
}

void surface(const float* cn, unsigned dim, unsigned uorder, unsigned vorder, float u, float v,
             float* out) {
  const std::size_t row = std::size_t{vorder} * dim;  // from one u index to the next
  std::array<float, kMaxEvalOrder * 4> control{};     // the control polygon of one curve
  if (vorder > uorder) {
    if (uorder < 2) return curve(cn, dim, dim, vorder, v, out);
    // The curves in u through each column j give the control polygon of the curve in v.
    for (unsigned j = 0; j < vorder; ++j)
      curve(cn + j * dim, row, dim, uorder, u, &control[j * dim]);
    curve(control.data(), dim, dim, vorder, v, out);
  } else {
    if (vorder < 2) return curve(cn, dim, dim, uorder, u, out);
    for (unsigned i = 0; i < uorder; ++i)
      curve(cn + i * row, dim, dim, vorder, v, &control[i * dim]);
    curve(control.data(), dim, dim, uorder, u, out);
  }
}

void surface_with_derivatives(const float* cn, unsigned dim, unsigned uorder, unsigned vorder,
                              float u, float v, float* out, float* du, float* dv) {
  if (uorder < 2 || vorder < 2) {
    surface(cn, dim, uorder, vorder, u, v, out);
    for (unsigned k = 0; k < dim; ++k) du[k] = dv[k] = 0.0f;
    return;
  }
  const float us = 1.0f - u, vs = 1.0f - v;
  const unsigned min_order = std::min(uorder, vorder);
  Scratch d(vorder);
  for (unsigned k = 0; k < dim; ++k) {
    auto p = [&](unsigned i, unsigned j) { return cn[(i * vorder + j) * dim + k]; };
    if (min_order < 3 && uorder == vorder) {  // bilinear
      du[k] = vs * (p(1, 0) - p(0, 0)) + v * (p(1, 1) - p(0, 1));
      dv[k] = us * (p(0, 1) - p(0, 0)) + u * (p(1, 1) - p(1, 0));
      out[k] = us * (vs * p(0, 0) + v * p(0, 1)) + u * (vs * p(1, 0) + v * p(1, 1));
      continue;
    }
    if (min_order < 3 && min_order == uorder) {  // linear in u, de Casteljau in v
      d(1, 0) = p(1, 0) - p(0, 0);
      d(0, 0) = us * p(0, 0) + u * p(1, 0);
      for (unsigned j = 0; j + 1 < vorder; ++j) {
        d(1, j + 1) = p(1, j + 1) - p(0, j + 1);
        d(1, j) = vs * d(1, j) + v * d(1, j + 1);
        d(0, j + 1) = us * p(0, j + 1) + u * p(1, j + 1);
        d(0, j) = vs * d(0, j) + v * d(0, j + 1);
      }
      for (unsigned h = min_order; h + 1 < vorder; ++h) {
        for (unsigned j = 0; j < vorder - h; ++j) {
          d(1, j) = vs * d(1, j) + v * d(1, j + 1);
          d(0, j) = vs * d(0, j) + v * d(0, j + 1);
        }
      }
      dv[k] = d(0, 1) - d(0, 0);
      du[k] = vs * d(1, 0) + v * d(1, 1);
      out[k] = vs * d(0, 0) + v * d(0, 1);
      continue;
    }
    if (min_order < 3) {  // linear in v, de Casteljau in u
      d(0, 1) = p(0, 1) - p(0, 0);
      d(0, 0) = vs * p(0, 0) + v * p(0, 1);
      for (unsigned i = 0; i + 1 < uorder; ++i) {
        d(i + 1, 1) = p(i + 1, 1) - p(i + 1, 0);
        d(i, 1) = us * d(i, 1) + u * d(i + 1, 1);
        d(i + 1, 0) = vs * p(i + 1, 0) + v * p(i + 1, 1);
        d(i, 0) = us * d(i, 0) + u * d(i + 1, 0);
      }
      for (unsigned h = min_order; h + 1 < uorder; ++h) {
        for (unsigned i = 0; i < uorder - h; ++i) {
          d(i, 1) = us * d(i, 1) + u * d(i + 1, 1);
          d(i, 0) = us * d(i, 0) + u * d(i + 1, 0);
        }
      }
      du[k] = d(1, 0) - d(0, 0);
      dv[k] = us * d(0, 1) + u * d(1, 1);
      out[k] = us * d(0, 0) + u * d(1, 0);
      continue;
    }
    // Both orders >= 3: bilinear steps while both directions have steps left.
    for (unsigned i = 0; i + 1 < uorder; ++i) {
      d(i, 0) = us * p(i, 0) + u * p(i + 1, 0);
      for (unsigned j = 0; j + 1 < vorder; ++j) {
        d(i, j + 1) = us * p(i, j + 1) + u * p(i + 1, j + 1);
        d(i, j) = vs * d(i, j) + v * d(i, j + 1);
      }
    }
    for (unsigned h = 2; h + 1 < min_order; ++h) {
      for (unsigned i = 0; i < uorder - h; ++i) {
        d(i, 0) = us * d(i, 0) + u * d(i + 1, 0);
        for (unsigned j = 0; j < vorder - h; ++j) {
          d(i, j + 1) = us * d(i, j + 1) + u * d(i + 1, j + 1);
          d(i, j) = vs * d(i, j) + v * d(i, j + 1);
        }
      }
    }
    if (uorder == vorder) {  // the last bilinear step
      du[k] = vs * (d(1, 0) - d(0, 0)) + v * (d(1, 1) - d(0, 1));
      dv[k] = us * (d(0, 1) - d(0, 0)) + u * (d(1, 1) - d(1, 0));
      out[k] = us * (vs * d(0, 0) + v * d(0, 1)) + u * (vs * d(1, 0) + v * d(1, 1));
    } else if (min_order == uorder) {
      // The last step in u, keeping the u difference in row 2; then linear steps in v.
      d(2, 0) = d(1, 0) - d(0, 0);
      d(0, 0) = us * d(0, 0) + u * d(1, 0);
      for (unsigned j = 0; j + 1 < vorder; ++j) {
        d(2, j + 1) = d(1, j + 1) - d(0, j + 1);
        d(2, j) = vs * d(2, j) + v * d(2, j + 1);
        d(0, j + 1) = us * d(0, j + 1) + u * d(1, j + 1);
        d(0, j) = vs * d(0, j) + v * d(0, j + 1);
      }
      for (unsigned h = min_order; h + 1 < vorder; ++h) {
        for (unsigned j = 0; j < vorder - h; ++j) {
          d(2, j) = vs * d(2, j) + v * d(2, j + 1);
          d(0, j) = vs * d(0, j) + v * d(0, j + 1);
        }
      }
      dv[k] = d(0, 1) - d(0, 0);
      du[k] = vs * d(2, 0) + v * d(2, 1);
      out[k] = vs * d(0, 0) + v * d(0, 1);
    } else {
      // The last step in v, keeping the v difference in column 2; then linear steps in u.
      d(0, 2) = d(0, 1) - d(0, 0);
      d(0, 0) = vs * d(0, 0) + v * d(0, 1);
      for (unsigned i = 0; i + 1 < uorder; ++i) {
        d(i + 1, 2) = d(i + 1, 1) - d(i + 1, 0);
        d(i, 2) = us * d(i, 2) + u * d(i + 1, 2);
        d(i + 1, 0) = vs * d(i + 1, 0) + v * d(i + 1, 1);
        d(i, 0) = us * d(i, 0) + u * d(i + 1, 0);
      }
      for (unsigned h = min_order; h + 1 < uorder; ++h) {
        for (unsigned i = 0; i < uorder - h; ++i) {
          d(i, 2) = us * d(i, 2) + u * d(i + 1, 2);
          d(i, 0) = us * d(i, 0) + u * d(i + 1, 0);
        }
      }
      du[k] = d(1, 0) - d(0, 0);
      dv[k] = us * d(0, 2) + u * d(1, 2);
      out[k] = us * d(0, 0) + u * d(1, 0);
    }
  }
}

}  // namespace glpt::bezier
