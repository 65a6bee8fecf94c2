// glHint targets (GL 1.5 5.6, table 6.27: the "hint" attribute group). glpt renders the same
// whatever the hints say; they are kept for glGet and glPushAttrib(GL_HINT_BIT).
#pragma once

#include <cstdint>

#include "gl_shim/gl_types.h"

namespace glpt {

struct HintState {
  static constexpr GLenum kDontCare = 0x1100;  // GL_DONT_CARE
  GLenum perspective_correction = kDontCare;
  GLenum point_smooth = kDontCare;
  GLenum line_smooth = kDontCare;
  GLenum polygon_smooth = kDontCare;
  GLenum fog = kDontCare;
  GLenum texture_compression = kDontCare;
  GLenum generate_mipmap = kDontCare;

  // The field a target names; null for an enum that is not a hint target.
  GLenum* target(GLenum hint_target);
  const GLenum* target(GLenum hint_target) const {
    return const_cast<HintState*>(this)->target(hint_target);
  }
  bool operator==(const HintState&) const = default;
};

}  // namespace glpt
