// The targets image commands name (GL 1.5 3.8.1-3.8.2, 3.8.11, 6.1.3): which texture object,
// which cube face, and whether it is a proxy.
#pragma once

#include <optional>

#include "gl_shim/gl_types.h"
#include "gl_shim/textures/texture_object.hpp"

namespace glpt {

class Context;

struct ImageTarget {
  int slot = kSlot2D;  // TextureSlot
  int face = 0;        // 0..5 for the cube faces (+X, -X, +Y, -Y, +Z, -Z), else 0
  bool proxy = false;
  int dims = 2;  // 1, 2 or 3
};

enum class ProxyTargets : bool { kRejected, kAccepted };

// `dims`: the command's dimensionality (1, 2, 3), or 0 for any (glGetTexLevelParameter).
// std::nullopt for targets the command does not accept (the caller reports GL_INVALID_ENUM).
std::optional<ImageTarget> image_target(GLenum target, int dims, ProxyTargets proxies);

// The object the target refers to in `ctx`: the proxy, or what the active unit has bound.
TextureObject& target_object(Context& ctx, const ImageTarget& target);

}  // namespace glpt
