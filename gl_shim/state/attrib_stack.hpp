// glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib (GL 1.5 6.1.14, the attribute
// groups of tables 6.5-6.33). A pushed frame keeps copies of the state blocks the groups live in
// (Context::current, raster, lighting, ...); popping writes back only the fields of the groups
// the frame's mask names.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gl_shim/gl_types.h"

namespace glpt {

class Context;

// GL_MAX_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH (Mesa's, the spec's minimum).
inline constexpr size_t kMaxAttribStackDepth = 16;
inline constexpr size_t kMaxClientAttribStackDepth = 16;

struct AttribFrame;        // attrib_stack.cpp
struct ClientAttribFrame;  // attrib_stack.cpp

struct AttribStacks {
  AttribStacks();
  ~AttribStacks();
  AttribStacks(const AttribStacks&) = delete;
  AttribStacks& operator=(const AttribStacks&) = delete;

  std::vector<std::unique_ptr<AttribFrame>> server;
  std::vector<std::unique_ptr<ClientAttribFrame>> client;
};

// glXCopyContext: the attribute groups of `mask` go from `src` to `dst` as a glPushAttrib(mask) on
// `src` popped on `dst` would carry them. False (nothing copied) when either stack is full.
bool copy_attrib_groups(Context& src, Context& dst, GLbitfield mask);

}  // namespace glpt
