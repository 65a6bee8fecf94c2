// glEnable/glDisable/glIsEnabled (GL 1.5 spec tables 6.x, "Enable" column). Most capabilities are
// fields of the state blocks (Context::lighting, raster, transform, textures); EnableState holds
// only those without one (evaluator maps, imaging, multisample, ...).
#pragma once

#include <bitset>
#include <optional>

#include "gl_shim/gl_types.h"

namespace glpt {

class Context;

class EnableState {
 public:
  static constexpr size_t kMaxCaps = 96;
  EnableState();
  // std::nullopt for an enum that is not a capability (the caller reports GL_INVALID_ENUM).
  std::optional<bool> get(GLenum cap) const;
  bool set(GLenum cap, bool on);  // false if not a capability
  bool is(GLenum cap) const { return get(cap).value_or(false); }

 private:
  std::bitset<kMaxCaps> bits_;
};

// The value of any capability, wherever it lives; std::nullopt for an enum that is not one.
std::optional<bool> capability_enabled(Context& ctx, GLenum cap);

}  // namespace glpt
