#include "gl_shim/dispatch.hpp"

#include <cstdio>
#include <cstring>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"

namespace glpt {

void record_error(Context& ctx, GLenum error) {
  ++ctx.errors_recorded;
  if (ctx.error == GL_NO_ERROR) ctx.error = error;
}

void unimplemented(Context& ctx, CommandId id) {
  const auto i = static_cast<size_t>(id);
  ++ctx.unimplemented_calls[i];
  if (!ctx.unimplemented_reported[i]) {
    ctx.unimplemented_reported[i] = true;
    record_error(ctx, GL_INVALID_OPERATION);
    if (std::getenv("GLPT_QUIET") == nullptr)
      std::fprintf(stderr, "glpt: %s is not implemented yet (GL_INVALID_OPERATION, counted)\n",
                   command_name(id));
  }
}

void not_compilable(Context& ctx, CommandId id) {
  ++ctx.not_compilable_calls;
  unimplemented(ctx, id);
}

GlProc lookup_gl_proc(const char* name) {
  if (name == nullptr) return nullptr;
  size_t count = 0;
  const GlProcEntry* table = gl_proc_table(&count);
  size_t lo = 0, hi = count;
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    const int c = std::strcmp(table[mid].name, name);
    if (c == 0) return table[mid].implemented ? table[mid].entry : nullptr;
    if (c < 0)
      lo = mid + 1;
    else
      hi = mid;
  }
  return nullptr;
}

}  // namespace glpt
