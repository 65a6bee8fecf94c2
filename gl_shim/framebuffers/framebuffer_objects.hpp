// EXT_framebuffer_object's objects as the front end keeps them: renderbuffers (an image format
// and size) and framebuffer objects (colour attachments, a depth and a stencil attachment, each a
// texture image or a renderbuffer, and their own draw and read buffer). Both are shared by the
// contexts of a share group, as Mesa keeps them (EXT_framebuffer_object: "framebuffer and
// renderbuffer objects are shared"), guarded by the store's mutex.
//
// Names: glGen* reserves a name; the object is created when the name is first bound (as Mesa's
// placeholder objects: glIs* answers false until then), and binding a name never generated
// creates it too (EXT_framebuffer_object allows it; GL 3.0's names do not).
// docs/framebuffer-objects-plan.md says how drawing into them is to be rendered.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <unordered_map>

#include "gl/gl_enums.h"
#include "gl_shim/gl_types.h"

namespace glpt {

class Context;
class TextureObject;
struct InternalFormatInfo;
namespace rec {
struct TextureImage;
}
struct FramebufferRendering;  // framebuffer_rendering.hpp

// Mesa's limits on llvmpipe (GL_MAX_COLOR_ATTACHMENTS_EXT, GL_MAX_RENDERBUFFER_SIZE_EXT), the
// latter capped at glpt's texture size limit.
inline constexpr int kMaxColorAttachments = 8;
inline constexpr int kMaxRenderbufferSize = 4096;

struct Renderbuffer {
  explicit Renderbuffer(GLuint name) : name(name) {}
  GLuint name;
  GLenum internal_format = GL_RGBA;  // as given to glRenderbufferStorageEXT (GL_RGBA before)
  GLsizei width = 0, height = 0;
  // Bits per component of the format glpt stores it in: red, green, blue, alpha, depth, stencil.
  std::array<GLint, 6> bits{};
};

// What an attachment point holds (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT).
struct Attachment {
  GLenum type = GL_NONE;  // GL_NONE, GL_TEXTURE or GL_RENDERBUFFER_EXT
  std::shared_ptr<TextureObject> texture;
  std::shared_ptr<Renderbuffer> renderbuffer;
  GLenum texture_target = 0;  // GL_TEXTURE_1D/2D/3D/RECTANGLE_ARB or a cube map face
  GLint level = 0;
  GLint zoffset = 0;
};

struct FramebufferObject {
  explicit FramebufferObject(GLuint name) : name(name) {}
  GLuint name;
  std::array<Attachment, kMaxColorAttachments> color;
  Attachment depth, stencil;
  // What drawing into it needs (its record and target), created when first bound.
  std::shared_ptr<FramebufferRendering> rendering;
};

struct FramebufferStore {
  std::mutex mutex;
  // Reserved names map to null until first bound.
  std::unordered_map<GLuint, std::shared_ptr<FramebufferObject>> framebuffers;
  std::unordered_map<GLuint, std::shared_ptr<Renderbuffer>> renderbuffers;
  // Where glGen* starts looking for unused names (as glGenTextures: after the last one given).
  GLuint next_framebuffer_name = 1, next_renderbuffer_name = 1;
};

// What a context has bound: EXT_framebuffer_blit's draw and read framebuffers
// (GL_FRAMEBUFFER_EXT binds both) and the renderbuffer.
struct FramebufferBindings {
  std::shared_ptr<FramebufferStore> store = std::make_shared<FramebufferStore>();
  std::shared_ptr<FramebufferObject> framebuffer;  // the draw framebuffer; null: the window
  // What reads (glReadPixels, glCopyTex*Image, glCopyPixels, glBlitFramebufferEXT) take their
  // source from; null: the window. Usually the same object as `framebuffer`.
  std::shared_ptr<FramebufferObject> read_framebuffer;
  std::shared_ptr<Renderbuffer> renderbuffer;
  // The bound object's recording bundle is the context's (framebuffer_rendering.hpp): between
  // enter_framebuffer and leave_framebuffer.
  bool entered = false;
};

// An attachment's texture image (its cube face and level), null when it holds none or the level
// is undefined; and the format its texels are stored in.
const rec::TextureImage* attached_image(const Attachment& attachment);
const InternalFormatInfo* attached_texture_format(const Attachment& attachment);
// Bits of red, green, blue, alpha, depth and stencil an attachment stores (0 where it holds no
// such component; luminance and intensity count as none, as Mesa answers).
std::array<GLint, 6> attachment_bits(const Attachment& attachment);

// GL_FRAMEBUFFER_COMPLETE_EXT or the first reason a framebuffer object with these draw and read
// buffers is incomplete (EXT_framebuffer_object 4.4.4.2); the window is always complete.
GLenum framebuffer_status(const FramebufferObject& framebuffer, uint32_t draw_buffer,
                          uint32_t read_buffer);

// A texture is being deleted: the bound framebuffer objects' attachments of it become GL_NONE
// (EXT_framebuffer_object 4.4.2.3: only the bound framebuffers are affected, the draw and the
// read one with EXT_framebuffer_blit).
void detach_deleted_texture(Context& ctx, const TextureObject& texture);

}  // namespace glpt
