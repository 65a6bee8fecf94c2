// What the generated entry points (gen/gen_gl_api.py) need from the hand-written front end.
#pragma once

#include <cstddef>

#include "gl_shim/gl_commands.hpp"
#include "gl_shim/gl_types.h"

namespace glpt {

class Context;

// Sets the GL error flag if it is clear (GL keeps the first error until glGetError).
void record_error(Context& ctx, GLenum error);
// An exception reached an exported entry point (allocation failure): GL_OUT_OF_MEMORY on the
// current context, as GL 1.5 2.5 allows for any command, instead of unwinding into the program.
void exception_at_entry_point() noexcept;

// A command without an implementation: GL_INVALID_OPERATION the first time, and counted always.
void unimplemented(Context& ctx, CommandId id);

// A command that GL compiles into display lists but that glpt cannot record yet (image data,
// client arrays): counted like an unimplemented command, and not recorded.
void not_compilable(Context& ctx, CommandId id);

// Element count of a pname-dependent parameter array (glLightfv, glMaterialfv, glFogfv, ...);
// 0 for an enum that is not a valid pname of that command.
uint32_t pname_value_count(CommandId id, GLenum pname);

// Array lengths given by a GLsizei parameter: negative counts record nothing (the command
// itself reports GL_INVALID_VALUE when executed), absurd ones are clamped.
inline uint32_t clamp_count(GLsizei n) {
  constexpr GLsizei kMax = 1 << 24;
  return n <= 0 ? 0u : static_cast<uint32_t>(n > kMax ? kMax : n);
}

// Bytes of glCallLists' name array: n names of `type` (0 for an invalid type).
uint32_t call_lists_bytes(GLsizei n, GLenum type);

using GlProc = void (*)();
struct GlProcEntry {
  const char* name;
  GlProc entry;
  bool implemented;
};
// Every exported GL command, sorted by name (generated).
const GlProcEntry* gl_proc_table(size_t* count);

// glGetString(GL_EXTENSIONS) (generated from gen_gl_api.py's ADVERTISED_GL_EXTENSIONS) and the
// commands those extensions add, every one of which must be implemented.
const char* gl_extensions_string();
const char* const* advertised_extension_commands(size_t* count);

// The exported entry point for `name` if glpt implements it, else nullptr.
GlProc lookup_gl_proc(const char* name);

}  // namespace glpt
