// Allocation failure inside a GL command is GL_OUT_OF_MEMORY (GL 1.5 2.5), never an exception
// across the C ABI.
#pragma once

#include <new>

#include "gl/gl_enums.h"
#include "gl_shim/dispatch.hpp"

namespace glpt {

template <typename F>
void or_out_of_memory(Context& ctx, F&& f) {
  try {
    f();
  } catch (const std::bad_alloc&) {
    record_error(ctx, GL_OUT_OF_MEMORY);
  }
}

}  // namespace glpt
