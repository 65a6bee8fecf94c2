// Evaluator state (GL 1.5 5.1, table 6.25): the eighteen maps with their control points, and the
// grids of glMapGrid. Not part of a draw's snapshot: evaluators only generate vertices, which
// enter the frame record like any glVertex (evaluator_commands.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "gl_shim/gl_types.h"

namespace glpt {

// GL_MAX_EVAL_ORDER (Mesa's MAX_EVAL_ORDER).
inline constexpr int kMaxEvalOrder = 30;

// A one-dimensional map (glMap1). `du` is Mesa's 1 / (u2 - u1), computed by glMap1 (0 until
// then: the initial maps have order 1, whose value does not depend on u).
struct EvaluatorMap1 {
  int order = 1;
  float u1 = 0.0f, u2 = 1.0f, du = 0.0f;
  // order * components values, packed. Empty only where Mesa keeps no points (see glMap2).
  std::vector<float> points;
};

// A two-dimensional map (glMap2): points[(i * vorder + j) * components + k] for u index i and v
// index j.
struct EvaluatorMap2 {
  int uorder = 1, vorder = 1;
  float u1 = 0.0f, u2 = 1.0f, du = 0.0f;
  float v1 = 0.0f, v2 = 1.0f, dv = 0.0f;
  std::vector<float> points;
};

// glMapGrid1/glMapGrid2 (part of GL_EVAL_BIT). The steps are what glMapGrid computed, as Mesa
// keeps them: glEvalMesh uses them, glEvalPoint recomputes its own. Mesa starts them at 0 (its
// context is zero-initialized and only glMapGrid sets them), so glEvalMesh on the initial grid
// puts every point at u1 (measured with OSMesa).
struct EvaluatorGrid {
  int un1 = 1;
  float u1_1 = 0.0f, u2_1 = 1.0f, du1 = 0.0f;
  int un2 = 1, vn2 = 1;
  float u1_2 = 0.0f, u2_2 = 1.0f, du2 = 0.0f;
  float v1_2 = 0.0f, v2_2 = 1.0f, dv2 = 0.0f;
  bool operator==(const EvaluatorGrid&) const = default;
};

// The map targets in GL_MAP1_COLOR_4 .. GL_MAP1_VERTEX_4 order (GL_MAP2_* likewise).
inline constexpr int kEvaluatorTargets = 9;

struct EvaluatorState {
  EvaluatorState();
  std::array<EvaluatorMap1, kEvaluatorTargets> map1;
  std::array<EvaluatorMap2, kEvaluatorTargets> map2;
  EvaluatorGrid grid;
};

// What a map target names: its dimension (1 or 2), slot and components per control point (GL
// 1.5 table 5.1). std::nullopt for any other enum.
struct EvaluatorTarget {
  int dimension;
  int slot;  // target - GL_MAP1_COLOR_4 (or GL_MAP2_COLOR_4)
  int components;
};
std::optional<EvaluatorTarget> evaluator_target(GLenum target);

}  // namespace glpt
