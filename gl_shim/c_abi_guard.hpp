// No C++ exception crosses glpt's C ABI. The generated gl* entry points catch at their boundary
// (gen/gen_gl_api.py: GL_OUT_OF_MEMORY); the hand-written GLX and EGL entry points run their
// bodies through guard_c_abi, which turns an exception (std::bad_alloc from a container or a
// string, in practice) into the API's own failure: the report (EGL_BAD_ALLOC, a BadAlloc X
// error) and the function's failure value (EGL_NO_CONTEXT, EGL_FALSE, NULL, None, ...).
#pragma once

#include <utility>

namespace glpt {

// Returns body(), or `failure` after calling report() if body throws. report() may throw too
// (it may itself need memory): that is swallowed, the failure value still returned.
template <typename Result, typename Report, typename Body>
Result guard_c_abi(Result failure, Report&& report, Body&& body) noexcept {
  try {
    return std::forward<Body>(body)();
  } catch (...) {
    try {
      report();
    } catch (...) {
    }
    return failure;
  }
}

// The same for a function without a result.
template <typename Report, typename Body>
void guard_c_abi_void(Report&& report, Body&& body) noexcept {
  try {
    std::forward<Body>(body)();
  } catch (...) {
    try {
      report();
    } catch (...) {
    }
  }
}

}  // namespace glpt
