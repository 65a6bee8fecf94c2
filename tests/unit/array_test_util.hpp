// Helpers of the vertex-array, buffer-object and display-list-array tests: the draws the frame
// record holds.
#pragma once

#include <variant>
#include <vector>

#include "gl_test_context.hpp"

inline std::vector<glpt::rec::Draw> recorded_draws(glpt::Context& ctx) {
  ctx.recorder.seal();
  std::vector<glpt::rec::Draw> out;
  for (const auto& c : ctx.recorder.record().commands)
    if (const auto* d = std::get_if<glpt::rec::Draw>(&c)) out.push_back(*d);
  return out;
}

inline GLint get_integer(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

// The value of attribute `values` at vertex `i` (the record keeps one value for all vertices when
// it did not change).
template <typename T>
T at(const std::vector<T>& values, uint32_t i) {
  return values.size() == 1 ? values[0] : values.at(i);
}
