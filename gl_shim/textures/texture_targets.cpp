#include "gl_shim/textures/texture_targets.hpp"

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"

namespace glpt {

std::optional<ImageTarget> image_target(GLenum target, int dims, ProxyTargets proxies) {
  ImageTarget t;
  switch (target) {
    case GL_TEXTURE_1D:
    case GL_PROXY_TEXTURE_1D:
      t = {kSlot1D, 0, target == GL_PROXY_TEXTURE_1D, 1};
      break;
    case GL_TEXTURE_2D:
    case GL_PROXY_TEXTURE_2D:
      t = {kSlot2D, 0, target == GL_PROXY_TEXTURE_2D, 2};
      break;
    case GL_TEXTURE_3D:
    case GL_PROXY_TEXTURE_3D:
      t = {kSlot3D, 0, target == GL_PROXY_TEXTURE_3D, 3};
      break;
    case GL_PROXY_TEXTURE_CUBE_MAP:
      t = {kSlotCube, 0, true, 2};
      break;
    case GL_TEXTURE_RECTANGLE_ARB:
    case GL_PROXY_TEXTURE_RECTANGLE_ARB:
      t = {kSlotRect, 0, target == GL_PROXY_TEXTURE_RECTANGLE_ARB, 2};
      break;
    default:
      if (target < GL_TEXTURE_CUBE_MAP_POSITIVE_X || target > GL_TEXTURE_CUBE_MAP_NEGATIVE_Z)
        return std::nullopt;
      t = {kSlotCube, int(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X), false, 2};
      break;
  }
  if (dims != 0 && t.dims != dims) return std::nullopt;
  if (t.proxy && proxies == ProxyTargets::kRejected) return std::nullopt;
  return t;
}

TextureObject& target_object(Context& ctx, const ImageTarget& target) {
  if (target.proxy) return *ctx.textures.proxies[size_t(target.slot)];
  return ctx.textures.bound(ctx.textures.active_unit(), target.slot);
}

}  // namespace glpt
