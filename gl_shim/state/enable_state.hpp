// glEnable/glDisable/glIsEnabled capabilities (GL 1.5 spec table 6.x, "Enable" column).
#pragma once

#include <bitset>
#include <optional>

#include "gl_shim/gl_types.h"

namespace glpt {

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

}  // namespace glpt
