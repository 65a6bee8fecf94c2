// Element counts of pname-dependent array parameters, for recording them into display lists.
#include "gl_shim/dispatch.hpp"
#include "gl/gl_enums.h"

namespace glpt {

uint32_t pname_value_count(CommandId, GLenum pname) {
  // The pname alone decides the count across all families that use COMPSIZE(pname); an enum
  // that is not valid for the command still gets its (harmless) count and the command itself
  // reports GL_INVALID_ENUM when the list is executed.
  switch (pname) {
    // 4 values
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR:
    case GL_POSITION:
    case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE:
    case GL_LIGHT_MODEL_AMBIENT:
    case GL_FOG_COLOR:
    case GL_TEXTURE_ENV_COLOR:
    case GL_TEXTURE_BORDER_COLOR:
    case GL_OBJECT_PLANE:
    case GL_EYE_PLANE:
      return 4;
    case GL_SPOT_DIRECTION:
    case GL_COLOR_INDEXES:
    case GL_POINT_DISTANCE_ATTENUATION:
      return 3;
    default:
      return 1;
  }
}

}  // namespace glpt
