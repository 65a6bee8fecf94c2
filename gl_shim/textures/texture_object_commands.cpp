// glGenTextures, glDeleteTextures, glBindTexture, glIsTexture, glAreTexturesResident,
// glPrioritizeTextures (GL 1.5 3.8.12); the EXT_texture_object names share these (gen_gl_api.py).
#include <algorithm>
#include <mutex>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt::impl {

void glGenTextures(Context& ctx, GLsizei n, GLuint* textures) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (textures == nullptr) return;
  TextureStore& store = *ctx.textures.store;
  const std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    GLuint name = store.next_name;
    while (name == 0 || store.objects.count(name) != 0) ++name;
    store.next_name = name + 1;
    // The object exists from now on (Mesa creates it here), but it has no target and is not a
    // texture for glIsTexture until it is first bound.
    store.objects.emplace(name, std::make_shared<TextureObject>(name, 0));
    textures[i] = name;
  }
}

void glDeleteTextures(Context& ctx, GLsizei n, const GLuint* textures) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (textures == nullptr) return;
  TextureStore& store = *ctx.textures.store;
  const std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    const auto it = store.objects.find(textures[i]);
    if (textures[i] == 0 || it == store.objects.end()) continue;  // silently ignored
    // Bindings of this context revert to texture 0 (GL 1.5 3.8.12); other contexts of the share
    // group keep the object alive until they unbind it.
    for (TextureUnit& unit : ctx.textures.units) {
      for (std::shared_ptr<TextureObject>& bound : unit.bound) {
        if (bound == it->second) bound.reset();
      }
    }
    // And from the bound framebuffer object's attachments (EXT_framebuffer_object 4.4.2.3).
    if (it->second) detach_deleted_texture(ctx, *it->second);
    store.objects.erase(it);
  }
}

void glBindTexture(Context& ctx, GLenum target, GLuint texture) {
  const int slot = texture_slot(target);
  if (slot < 0) return record_error(ctx, GL_INVALID_ENUM);
  TextureUnit& unit = ctx.textures.active_unit();
  if (texture == 0) {
    unit.bound[size_t(slot)].reset();
    return;
  }
  TextureStore& store = *ctx.textures.store;
  const std::lock_guard lock(store.mutex);
  std::shared_ptr<TextureObject>& object = store.objects[texture];
  if (!object) object = std::make_shared<TextureObject>(texture, target);  // an unused name
  if (object->target() == 0) object->set_target(target);
  if (object->target() != target) return record_error(ctx, GL_INVALID_OPERATION);
  unit.bound[size_t(slot)] = object;
}

GLboolean glIsTexture(Context& ctx, GLuint texture) {
  TextureStore& store = *ctx.textures.store;
  const std::lock_guard lock(store.mutex);
  const auto it = store.objects.find(texture);
  return texture != 0 && it != store.objects.end() && it->second->target() != 0 ? 1 : 0;
}

GLboolean glAreTexturesResident(Context& ctx, GLsizei n, const GLuint* textures,
                                GLboolean* residences) {
  if (n < 0) {
    record_error(ctx, GL_INVALID_VALUE);
    return 0;
  }
  if (textures == nullptr) return 0;
  TextureStore& store = *ctx.textures.store;
  const std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    if (textures[i] == 0 || store.objects.count(textures[i]) == 0) {
      record_error(ctx, GL_INVALID_VALUE);
      return 0;
    }
  }
  // Every texture is resident: TRUE, and `residences` is left unchanged (GL 1.5 3.8.12).
  (void)residences;
  return 1;
}

void glPrioritizeTextures(Context& ctx, GLsizei n, const GLuint* textures,
                          const GLfloat* priorities) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (textures == nullptr || priorities == nullptr) return;
  TextureStore& store = *ctx.textures.store;
  const std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    if (textures[i] == 0) continue;  // GL ignores texture 0
    const auto it = store.objects.find(textures[i]);
    if (it != store.objects.end()) it->second->priority = std::clamp(priorities[i], 0.0f, 1.0f);
  }
}

}  // namespace glpt::impl
