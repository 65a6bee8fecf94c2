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

// Mesa's de Casteljau variants where one order is the smaller and its last step is linear:
// that step (between `a` and `b`, two rows of control points or of scratch values, with weights
// s_linear, t_linear), the difference along it kept in scratch row `diff`, then the remaining
// steps along the other direction (s, t) from step `first_h` on. `cell(row, n)` is the scratch
// value of that row at index n of the other direction. Returns the point and the derivatives
// along the linear direction and along the other.
template <typename Cell, typename RowA, typename RowB>
void linear_then_de_casteljau(Cell cell, RowA a, RowB b, unsigned diff, unsigned first_h,
                              unsigned order, float s_linear, float t_linear, float s, float t,
                              float& out, float& d_linear, float& d_other) {
  cell(diff, 0) = b(0) - a(0);
  cell(0, 0) = s_linear * a(0) + t_linear * b(0);
  for (unsigned n = 0; n + 1 < order; ++n) {
    cell(diff, n + 1) = b(n + 1) - a(n + 1);
    cell(diff, n) = s * cell(diff, n) + t * cell(diff, n + 1);
    cell(0, n + 1) = s_linear * a(n + 1) + t_linear * b(n + 1);
    cell(0, n) = s * cell(0, n) + t * cell(0, n + 1);
  }
  for (unsigned h = first_h; h + 1 < order; ++h) {
    for (unsigned n = 0; n < order - h; ++n) {
      cell(diff, n) = s * cell(diff, n) + t * cell(diff, n + 1);
      cell(0, n) = s * cell(0, n) + t * cell(0, n + 1);
    }
  }
  d_other = cell(0, 1) - cell(0, 0);
  d_linear = s * cell(diff, 0) + t * cell(diff, 1);
  out = s * cell(0, 0) + t * cell(0, 1);
}

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
    // The last bilinear step, on 2 x 2 values c(i, j).
    auto bilinear = [&](auto c) {
      du[k] = vs * (c(1, 0) - c(0, 0)) + v * (c(1, 1) - c(0, 1));
      dv[k] = us * (c(0, 1) - c(0, 0)) + u * (c(1, 1) - c(1, 0));
      out[k] = us * (vs * c(0, 0) + v * c(0, 1)) + u * (vs * c(1, 0) + v * c(1, 1));
    };
    if (min_order < 3 && uorder == vorder) {
      bilinear(p);
      continue;
    }
    // Rows of u (index i) and columns of v (index j) of the control net and of the scratch.
    auto u_rows = [&](unsigned r, unsigned j) -> float& { return d(r, j); };
    auto v_columns = [&](unsigned c, unsigned i) -> float& { return d(i, c); };
    if (min_order < 3 && min_order == uorder) {  // linear in u, de Casteljau in v
      linear_then_de_casteljau(
          u_rows, [&](unsigned j) { return p(0, j); }, [&](unsigned j) { return p(1, j); }, 1,
          min_order, vorder, us, u, vs, v, out[k], du[k], dv[k]);
      continue;
    }
    if (min_order < 3) {  // linear in v, de Casteljau in u
      linear_then_de_casteljau(
          v_columns, [&](unsigned i) { return p(i, 0); }, [&](unsigned i) { return p(i, 1); }, 1,
          min_order, uorder, vs, v, us, u, out[k], dv[k], du[k]);
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
    if (uorder == vorder) {
      bilinear([&](unsigned i, unsigned j) { return d(i, j); });
    } else if (min_order == uorder) {  // the last step in u, then linear steps in v
      linear_then_de_casteljau(
          u_rows, [&](unsigned j) { return d(0, j); }, [&](unsigned j) { return d(1, j); }, 2,
          min_order, vorder, us, u, vs, v, out[k], du[k], dv[k]);
    } else {  // the last step in v, then linear steps in u
      linear_then_de_casteljau(
          v_columns, [&](unsigned i) { return d(i, 0); }, [&](unsigned i) { return d(i, 1); }, 2,
          min_order, uorder, vs, v, us, u, out[k], dv[k], du[k]);
    }
  }
}

}  // namespace glpt::bezier
