// EXT_framebuffer_object's commands: names, binding, renderbuffer storage, attachments, status
// and queries. Errors and their order are Mesa 25's (src/mesa/main/fbobject.c); completeness is
// EXT_framebuffer_object's, which glpt advertises, where Mesa (which also has
// ARB_framebuffer_object) applies the ARB rules: with EXT, attachments of different sizes or
// colour formats, and a draw or read buffer naming no attachment, make a framebuffer incomplete.
#include <algorithm>
#include <mutex>
#include <optional>
#include <utility>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/framebuffers/framebuffer_objects.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/textures/internal_formats.hpp"
#include "gl_shim/textures/mipmap_generation.hpp"
#include "gl_shim/textures/texture_object.hpp"

namespace glpt {
namespace {

// ARB_framebuffer_object's GL_DEPTH_STENCIL_ATTACHMENT, which Mesa accepts with the EXT commands.
constexpr GLenum kDepthStencilAttachment = 0x821A;

// The base format Mesa gives a renderbuffer's internal format (_mesa_base_fbo_format, desktop
// compatibility context with ARB_framebuffer_object), 0 for formats it rejects.
GLenum renderbuffer_base_format(GLenum internal_format) {
  switch (internal_format) {
    case GL_ALPHA:
    case GL_ALPHA4:
    case GL_ALPHA8:
    case GL_ALPHA12:
    case GL_ALPHA16:
      return GL_ALPHA;
    case GL_LUMINANCE:
    case GL_LUMINANCE4:
    case GL_LUMINANCE8:
    case GL_LUMINANCE12:
    case GL_LUMINANCE16:
      return GL_LUMINANCE;
    case GL_LUMINANCE_ALPHA:
    case GL_LUMINANCE4_ALPHA4:
    case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4:
    case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16:
      return GL_LUMINANCE_ALPHA;
    case GL_INTENSITY:
    case GL_INTENSITY4:
    case GL_INTENSITY8:
    case GL_INTENSITY12:
    case GL_INTENSITY16:
      return GL_INTENSITY;
    case GL_RGB:
    case GL_R3_G3_B2:
    case GL_RGB4:
    case GL_RGB5:
    case GL_RGB8:
    case GL_RGB10:
    case GL_RGB12:
    case GL_RGB16:
      return GL_RGB;
    case GL_RGBA:
    case GL_RGBA2:
    case GL_RGBA4:
    case GL_RGB5_A1:
    case GL_RGBA8:
    case GL_RGB10_A2:
    case GL_RGBA12:
    case GL_RGBA16:
      return GL_RGBA;
    case GL_STENCIL_INDEX:
    case GL_STENCIL_INDEX1_EXT:
    case GL_STENCIL_INDEX4_EXT:
    case GL_STENCIL_INDEX8_EXT:
    case GL_STENCIL_INDEX16_EXT:
      return GL_STENCIL_INDEX;
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
      return GL_DEPTH_COMPONENT;
    case GL_DEPTH_STENCIL_EXT:
    case GL_DEPTH24_STENCIL8_EXT:
      return GL_DEPTH_STENCIL_EXT;
    default:
      return 0;
  }
}

// Bits per component (red, green, blue, alpha, depth, stencil) of the format glpt keeps a
// renderbuffer in: its colour buffers are 8 bits per channel, depth 24 bits, stencil 8 (the
// drawable's formats); components the base format lacks report 0, as Mesa's queries do.
std::array<GLint, 6> renderbuffer_bits(GLenum base) {
  switch (base) {
    case GL_ALPHA:
      return {0, 0, 0, 8, 0, 0};
    case GL_LUMINANCE:
    case GL_INTENSITY:
      return {8, 0, 0, 0, 0, 0};
    case GL_LUMINANCE_ALPHA:
      return {8, 0, 0, 8, 0, 0};
    case GL_RGB:
      return {8, 8, 8, 0, 0, 0};
    case GL_RGBA:
      return {8, 8, 8, 8, 0, 0};
    case GL_STENCIL_INDEX:
      return {0, 0, 0, 0, 0, 8};
    case GL_DEPTH_COMPONENT:
      return {0, 0, 0, 0, 24, 0};
    case GL_DEPTH_STENCIL_EXT:
      return {0, 0, 0, 0, 24, 8};
    default:
      return {};
  }
}

// The framebuffer bound for `target` (null: the window): GL_FRAMEBUFFER_EXT and
// GL_DRAW_FRAMEBUFFER_EXT name the draw framebuffer, GL_READ_FRAMEBUFFER_EXT the read one
// (EXT_framebuffer_blit); false for any other target (GL_INVALID_ENUM, raised here).
bool framebuffer_target(Context& ctx, GLenum target, FramebufferObject** out) {
  switch (target) {
    case GL_FRAMEBUFFER_EXT:
    case GL_DRAW_FRAMEBUFFER_EXT:
      *out = ctx.framebuffers.framebuffer.get();
      return true;
    case GL_READ_FRAMEBUFFER_EXT:
      *out = ctx.framebuffers.read_framebuffer.get();
      return true;
    default:
      record_error(ctx, GL_INVALID_ENUM);
      return false;
  }
}

// Changes the attachments of `fb` under the store's lock. The entered (draw) framebuffer is left
// first, since what was drawn so far belongs to the old attachments, and entered again after (a
// new target size or image); another (a read framebuffer) is judged again when next entered.
template <typename Change>
void change_attachments(Context& ctx, FramebufferObject& fb, Change change) {
  const bool entered = ctx.framebuffers.framebuffer.get() == &fb;
  if (entered) leave_framebuffer(ctx);
  {
    std::lock_guard lock(ctx.framebuffers.store->mutex);
    change();
  }
  if (entered) enter_framebuffer(ctx);
}

// The attachment point `attachment` names, or null (GL_INVALID_OPERATION for a colour attachment
// past the limit, GL_INVALID_ENUM for anything else, raised here). GL_DEPTH_STENCIL_ATTACHMENT
// gives the depth attachment (the caller sets the stencil one as well).
Attachment* attachment_point(Context& ctx, FramebufferObject& fb, GLenum attachment) {
  if (attachment >= GL_COLOR_ATTACHMENT0_EXT && attachment <= GL_COLOR_ATTACHMENT15_EXT) {
    const GLenum index = attachment - GL_COLOR_ATTACHMENT0_EXT;
    if (index < GLenum{kMaxColorAttachments}) return &fb.color[index];
    record_error(ctx, GL_INVALID_OPERATION);
    return nullptr;
  }
  if (attachment == GL_DEPTH_ATTACHMENT_EXT || attachment == kDepthStencilAttachment)
    return &fb.depth;
  if (attachment == GL_STENCIL_ATTACHMENT_EXT) return &fb.stencil;
  record_error(ctx, GL_INVALID_ENUM);
  return nullptr;
}

bool is_cube_face(GLenum target) {
  return target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z;
}

// Mesa's test_attachment_completeness for a colour (0), depth (1) or stencil (2) attachment.
bool attachment_complete(const Attachment& a, int kind) {
  if (a.type == GL_NONE) return true;
  if (a.type == GL_TEXTURE) {
    const rec::TextureImage* image = attached_image(a);
    if (image == nullptr || image->width < 1 || image->height < 1) return false;
    if (a.texture_target == GL_TEXTURE_3D && uint32_t(a.zoffset) >= image->depth) return false;
    const InternalFormatInfo* info = attached_texture_format(a);
    if (info == nullptr) return false;
    if (kind == 0) return !info->is_depth() && info->block_bytes == 0;
    if (kind == 1) return info->is_depth();
    return info->base_format == GL_DEPTH_STENCIL_EXT;  // no stencil-only textures
  }
  const Renderbuffer& rb = *a.renderbuffer;
  if (rb.width < 1 || rb.height < 1) return false;
  const GLenum base = renderbuffer_base_format(rb.internal_format);
  if (kind == 0)
    return base != 0 && base != GL_DEPTH_COMPONENT && base != GL_STENCIL_INDEX &&
           base != GL_DEPTH_STENCIL_EXT;
  if (kind == 1) return base == GL_DEPTH_COMPONENT || base == GL_DEPTH_STENCIL_EXT;
  return base == GL_STENCIL_INDEX || base == GL_DEPTH_STENCIL_EXT;
}

void set_attachment_to_texture(Attachment& a, const std::shared_ptr<TextureObject>& texture,
                               GLenum texture_target, GLint level, GLint zoffset) {
  a = Attachment{};
  if (!texture) return;
  a.type = GL_TEXTURE;
  a.texture = texture;
  a.texture_target = texture_target;
  a.level = level;
  a.zoffset = zoffset;
}

// glFramebufferTexture{1,2,3}DEXT (`dims`), in Mesa's order of checks.
void framebuffer_texture(Context& ctx, int dims, GLenum target, GLenum attachment, GLenum textarget,
                         GLuint texture, GLint level, GLint zoffset) {
  FramebufferObject* fb = nullptr;
  if (!framebuffer_target(ctx, target, &fb)) return;
  std::shared_ptr<TextureObject> object;
  if (texture != 0) {
    {
      TextureStore& store = *ctx.textures.store;
      const std::lock_guard lock(store.mutex);
      const auto it = store.objects.find(texture);
      if (it != store.objects.end()) object = it->second;
    }
    if (!object || object->target() == 0) return record_error(ctx, GL_INVALID_OPERATION);
    bool wrong = false;
    switch (textarget) {
      case GL_TEXTURE_1D:
        wrong = dims != 1;
        break;
      case GL_TEXTURE_2D:
      case GL_TEXTURE_RECTANGLE_ARB:
        wrong = dims != 2;
        break;
      case GL_TEXTURE_3D:
        wrong = dims != 3;
        break;
      case GL_TEXTURE_CUBE_MAP:
        wrong = true;
        break;
      default:
        if (!is_cube_face(textarget)) return record_error(ctx, GL_INVALID_ENUM);
        wrong = dims != 2;
    }
    if (wrong) return record_error(ctx, GL_INVALID_OPERATION);
    const bool consistent = object->target() == GL_TEXTURE_CUBE_MAP ? is_cube_face(textarget)
                                                                    : object->target() == textarget;
    if (!consistent) return record_error(ctx, GL_INVALID_OPERATION);
    if (dims == 3 && (zoffset < 0 || zoffset >= kMax3DTextureSize))
      return record_error(ctx, GL_INVALID_VALUE);
    const int slot =
        texture_slot(is_cube_face(textarget) ? GLenum{GL_TEXTURE_CUBE_MAP} : textarget);
    if (level < 0 || level >= max_texture_levels(slot)) return record_error(ctx, GL_INVALID_VALUE);
  }
  if (fb == nullptr) return record_error(ctx, GL_INVALID_OPERATION);  // the window's
  Attachment* point = attachment_point(ctx, *fb, attachment);
  if (point == nullptr) return;
  change_attachments(ctx, *fb, [&] {
    set_attachment_to_texture(*point, object, textarget, level, dims == 3 ? zoffset : 0);
    if (attachment == kDepthStencilAttachment) fb->stencil = *point;
  });
}

// ARB_framebuffer_object's attachment queries, which Mesa answers through the EXT command too.
constexpr GLenum kAttachmentColorEncoding = 0x8210, kAttachmentComponentType = 0x8211,
                 kAttachmentRedSize = 0x8212, kAttachmentStencilSize = 0x8217;
constexpr GLenum kFramebufferDefault = 0x8218, kUnsignedNormalized = 0x8C17;
// An attachment query's answer when attachment_point has raised the error itself.
constexpr GLenum kErrorRaised = 0xFFFFFFFF;

bool is_size_query(GLenum pname) {
  return pname >= kAttachmentRedSize && pname <= kAttachmentStencilSize;
}

// The window's buffers (GL 3.0 6.1.13 as Mesa answers it for the default framebuffer): an
// existing buffer is GL_FRAMEBUFFER_DEFAULT, one the visual lacks GL_NONE; they have no name,
// level or face (GL_INVALID_ENUM), and sizes only where they exist (GL_INVALID_OPERATION).
GLenum window_attachment_parameter(const Context& ctx, GLenum attachment, GLenum pname,
                                   GLint& value) {
  const rec::DrawableConfig& d = window_drawable(ctx);
  bool exists = false, color = false;
  switch (attachment) {
    case GL_FRONT:
    case GL_FRONT_LEFT:
      exists = color = true;
      break;
    case GL_BACK:
    case GL_BACK_LEFT:
      exists = color = d.double_buffered;
      break;
    case GL_FRONT_RIGHT:
    case GL_BACK_RIGHT:
      break;  // no stereo visuals
    case GL_DEPTH:
      exists = d.depth_bits != 0;
      break;
    case GL_STENCIL:
      exists = d.stencil_bits != 0;
      break;
    default:
      return GL_INVALID_ENUM;
  }
  if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT) {
    value = exists ? GLint(kFramebufferDefault) : GLint(GL_NONE);
    return GL_NO_ERROR;
  }
  if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT) return GL_INVALID_ENUM;
  const bool texture_query = pname == GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT ||
                             pname == GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_EXT ||
                             pname == GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET_EXT;
  if (!texture_query && !is_size_query(pname) && pname != kAttachmentComponentType &&
      pname != kAttachmentColorEncoding)
    return GL_INVALID_ENUM;
  if (!exists) return GL_INVALID_OPERATION;
  if (texture_query) return GL_INVALID_ENUM;
  // The depth and stencil buffers are one packed image when the visual has both (as Mesa's).
  const std::array<GLint, 6> bits = {color ? 8 : 0,
                                     color ? 8 : 0,
                                     color ? 8 : 0,
                                     color && d.has_alpha ? 8 : 0,
                                     color ? 0 : GLint(d.depth_bits),
                                     color ? 0 : GLint(d.stencil_bits)};
  if (is_size_query(pname))
    value = bits[pname - kAttachmentRedSize];
  else if (pname == kAttachmentComponentType)
    value = GLint(kUnsignedNormalized);
  else
    value = GL_LINEAR;  // glpt's window is not sRGB-capable (Mesa's visuals answer GL_SRGB)
  return GL_NO_ERROR;
}

GLenum object_attachment_parameter(Context& ctx, FramebufferObject& fb, GLenum attachment,
                                   GLenum pname, GLint& value) {
  const Attachment* point = attachment_point(ctx, fb, attachment);
  if (point == nullptr) return kErrorRaised;
  std::lock_guard lock(ctx.framebuffers.store->mutex);
  const bool depth_stencil = attachment == kDepthStencilAttachment;
  if (depth_stencil &&
      (fb.depth.renderbuffer != fb.stencil.renderbuffer || fb.depth.texture != fb.stencil.texture))
    return GL_INVALID_OPERATION;
  const Attachment& a = *point;
  switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT:
      value = GLint(a.type);
      return GL_NO_ERROR;
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT:
      value = a.type == GL_TEXTURE            ? GLint(a.texture->name())
              : a.type == GL_RENDERBUFFER_EXT ? GLint(a.renderbuffer->name)
                                              : 0;
      return GL_NO_ERROR;
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT:
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_EXT:
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET_EXT:
      if (a.type == GL_NONE) return GL_INVALID_OPERATION;
      if (a.type != GL_TEXTURE) return GL_INVALID_ENUM;
      value = pname == GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT ? a.level
              : pname == GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_EXT
                  ? (is_cube_face(a.texture_target) ? GLint(a.texture_target) : 0)
                  : (a.texture_target == GL_TEXTURE_3D ? a.zoffset : 0);
      return GL_NO_ERROR;
    default:
      break;
  }
  if (!is_size_query(pname) && pname != kAttachmentComponentType &&
      pname != kAttachmentColorEncoding)
    return GL_INVALID_ENUM;
  if (a.type == GL_NONE) return GL_INVALID_OPERATION;
  if (is_size_query(pname)) {
    value = attachment_bits(a)[pname - kAttachmentRedSize];
  } else if (pname == kAttachmentComponentType) {
    // Depth and stencil of one image have no one component type (GL 3.0 6.1.13).
    if (depth_stencil) return GL_INVALID_OPERATION;
    value = GLint(kUnsignedNormalized);
  } else {
    value = GL_LINEAR;  // glpt has no sRGB formats
  }
  return GL_NO_ERROR;
}

}  // namespace

std::array<GLint, 6> attachment_bits(const Attachment& a) {
  if (a.type == GL_RENDERBUFFER_EXT) return a.renderbuffer->bits;
  const InternalFormatInfo* info = a.type == GL_TEXTURE ? attached_texture_format(a) : nullptr;
  if (info == nullptr) return {};
  return {info->red, info->green, info->blue, info->alpha, info->depth, info->stencil};
}

const rec::TextureImage* attached_image(const Attachment& a) {
  if (a.type != GL_TEXTURE || !a.texture) return nullptr;
  const int face =
      is_cube_face(a.texture_target) ? int(a.texture_target - GL_TEXTURE_CUBE_MAP_POSITIVE_X) : 0;
  return a.texture->image(face, a.level);
}

const InternalFormatInfo* attached_texture_format(const Attachment& a) {
  const rec::TextureImage* image = attached_image(a);
  return image ? stored_format_info(image->internal_format, image->sized_format) : nullptr;
}

GLenum framebuffer_status(const FramebufferObject& fb, uint32_t draw_buffer, uint32_t read_buffer) {
  // Depth, stencil, then the colour attachments, as Mesa walks them.
  if (!attachment_complete(fb.depth, 1) || !attachment_complete(fb.stencil, 2))
    return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT;
  bool any = fb.depth.type != GL_NONE || fb.stencil.type != GL_NONE;
  for (const Attachment& a : fb.color) {
    if (!attachment_complete(a, 0)) return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT;
    any = any || a.type != GL_NONE;
  }
  if (!any) return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT;
  // EXT_framebuffer_object's rules, which ARB_framebuffer_object (not advertised) relaxed and
  // Mesa therefore does not apply: one size for every image, one internal format for the colour
  // images, and an image at the attachments the draw and read buffers name.
  std::optional<std::pair<uint32_t, uint32_t>> size;
  std::optional<GLint> color_format;
  auto image_size = [](const Attachment& a) -> std::pair<uint32_t, uint32_t> {
    if (a.type == GL_RENDERBUFFER_EXT)
      return {uint32_t(a.renderbuffer->width), uint32_t(a.renderbuffer->height)};
    const rec::TextureImage* image = attached_image(a);
    return {image->width, image->height};  // complete: the image exists
  };
  bool same_size = true, same_format = true;
  auto visit = [&](const Attachment& a, bool color) {
    if (a.type == GL_NONE) return;
    const auto s = image_size(a);
    if (size && *size != s) same_size = false;
    size = s;
    if (!color) return;
    const GLint format = a.type == GL_RENDERBUFFER_EXT ? GLint(a.renderbuffer->internal_format)
                                                       : GLint(attached_image(a)->internal_format);
    if (color_format && *color_format != format) same_format = false;
    color_format = format;
  };
  for (const Attachment& a : fb.color) visit(a, true);
  visit(fb.depth, false);
  visit(fb.stencil, false);
  if (!same_size) return GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT;
  if (!same_format) return GL_FRAMEBUFFER_INCOMPLETE_FORMATS_EXT;
  auto names_nothing = [&](uint32_t buffer) {
    if (buffer < GL_COLOR_ATTACHMENT0_EXT ||
        buffer >= GL_COLOR_ATTACHMENT0_EXT + kMaxColorAttachments)
      return false;
    return fb.color[buffer - GL_COLOR_ATTACHMENT0_EXT].type == GL_NONE;
  };
  if (draw_buffer != GL_NONE && names_nothing(draw_buffer))
    return GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER_EXT;
  if (read_buffer != GL_NONE && names_nothing(read_buffer))
    return GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER_EXT;
  // What gallium (llvmpipe) supports: depth and stencil in one image.
  const Attachment& d = fb.depth;
  const Attachment& s = fb.stencil;
  if (d.type != GL_NONE && s.type != GL_NONE) {
    if (d.type != s.type) return GL_FRAMEBUFFER_UNSUPPORTED_EXT;
    if (d.type == GL_RENDERBUFFER_EXT && d.renderbuffer != s.renderbuffer)
      return GL_FRAMEBUFFER_UNSUPPORTED_EXT;
    if (d.type == GL_TEXTURE && d.texture != s.texture) return GL_FRAMEBUFFER_UNSUPPORTED_EXT;
  }
  return GL_FRAMEBUFFER_COMPLETE_EXT;
}

namespace {

// Every attachment of the bound draw and read framebuffers that `holds_image` accepts becomes
// GL_NONE: a deleted image is detached from the bound framebuffers only (EXT_framebuffer_object
// 4.4.2.2, 4.4.2.3). The caller holds the store's mutex.
template <typename HoldsImage>
void detach_from_bound_framebuffers(Context& ctx, HoldsImage holds_image) {
  auto detach = [&](Attachment& a) {
    if (holds_image(a)) a = Attachment{};
  };
  for (FramebufferObject* fb :
       {ctx.framebuffers.framebuffer.get(), ctx.framebuffers.read_framebuffer.get()}) {
    if (fb == nullptr) continue;
    for (Attachment& a : fb->color) detach(a);
    detach(fb->depth);
    detach(fb->stencil);
  }
}

}  // namespace

void detach_deleted_texture(Context& ctx, const TextureObject& texture) {
  std::lock_guard lock(ctx.framebuffers.store->mutex);
  detach_from_bound_framebuffers(ctx,
                                 [&](const Attachment& a) { return a.texture.get() == &texture; });
}

namespace impl {

// ---- renderbuffers ------------------------------------------------------------------------------

GLboolean glIsRenderbuffer(Context& ctx, GLuint renderbuffer) {
  FramebufferStore& store = *ctx.framebuffers.store;
  std::lock_guard lock(store.mutex);
  const auto it = store.renderbuffers.find(renderbuffer);
  return it != store.renderbuffers.end() && it->second ? GL_TRUE : GL_FALSE;
}

void glBindRenderbufferEXT(Context& ctx, GLenum target, GLuint renderbuffer) {
  if (target != GL_RENDERBUFFER_EXT) return record_error(ctx, GL_INVALID_ENUM);
  if (renderbuffer == 0) {
    ctx.framebuffers.renderbuffer.reset();
    return;
  }
  FramebufferStore& store = *ctx.framebuffers.store;
  std::lock_guard lock(store.mutex);
  std::shared_ptr<Renderbuffer>& object = store.renderbuffers[renderbuffer];
  if (!object) object = std::make_shared<Renderbuffer>(renderbuffer);
  ctx.framebuffers.renderbuffer = object;
}

void glDeleteRenderbuffers(Context& ctx, GLsizei n, const GLuint* renderbuffers) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (renderbuffers == nullptr) return;
  FramebufferStore& store = *ctx.framebuffers.store;
  std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    const auto it = store.renderbuffers.find(renderbuffers[i]);
    if (renderbuffers[i] == 0 || it == store.renderbuffers.end()) continue;
    const std::shared_ptr<Renderbuffer> object = it->second;
    if (object) {
      if (ctx.framebuffers.renderbuffer == object) ctx.framebuffers.renderbuffer.reset();
      detach_from_bound_framebuffers(
          ctx, [&](const Attachment& a) { return a.renderbuffer == object; });
    }
    store.renderbuffers.erase(it);
  }
}

void glGenRenderbuffers(Context& ctx, GLsizei n, GLuint* renderbuffers) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (renderbuffers == nullptr) return;
  FramebufferStore& store = *ctx.framebuffers.store;
  std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    GLuint name = store.next_renderbuffer_name;
    while (name == 0 || store.renderbuffers.count(name) != 0) ++name;
    store.next_renderbuffer_name = name + 1;
    store.renderbuffers.emplace(name, nullptr);  // reserved until bound
    renderbuffers[i] = name;
  }
}

void glRenderbufferStorage(Context& ctx, GLenum target, GLenum internalformat, GLsizei width,
                           GLsizei height) {
  if (target != GL_RENDERBUFFER_EXT) return record_error(ctx, GL_INVALID_ENUM);
  Renderbuffer* rb = ctx.framebuffers.renderbuffer.get();
  if (rb == nullptr) return record_error(ctx, GL_INVALID_OPERATION);
  const GLenum base = renderbuffer_base_format(internalformat);
  if (base == 0) return record_error(ctx, GL_INVALID_ENUM);
  if (width < 0 || width > kMaxRenderbufferSize || height < 0 || height > kMaxRenderbufferSize)
    return record_error(ctx, GL_INVALID_VALUE);
  leave_framebuffer(ctx);  // the bound framebuffer object may hold it: a new target size
  {
    std::lock_guard lock(ctx.framebuffers.store->mutex);
    rb->internal_format = internalformat;
    rb->width = width;
    rb->height = height;
    rb->bits = renderbuffer_bits(base);
    // The sizes Mesa stores the format in where its texture table has it (GL_RGBA4: 4 bits;
    // GL_DEPTH_COMPONENT16: 16), which reads of the renderbuffer are quantized to.
    if (const InternalFormatInfo* info = internal_format_info(GLint(internalformat));
        info != nullptr && base != GL_STENCIL_INDEX)
      rb->bits = {info->red,   info->green, info->blue,
                  info->alpha, info->depth, base == GL_DEPTH_STENCIL_EXT ? GLint(8) : GLint(0)};
  }
  enter_framebuffer(ctx);
}

void glGetRenderbufferParameteriv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  if (target != GL_RENDERBUFFER_EXT) return record_error(ctx, GL_INVALID_ENUM);
  const Renderbuffer* rb = ctx.framebuffers.renderbuffer.get();
  if (rb == nullptr) return record_error(ctx, GL_INVALID_OPERATION);
  std::lock_guard lock(ctx.framebuffers.store->mutex);
  GLint value = 0;
  switch (pname) {
    case GL_RENDERBUFFER_WIDTH_EXT:
      value = rb->width;
      break;
    case GL_RENDERBUFFER_HEIGHT_EXT:
      value = rb->height;
      break;
    case GL_RENDERBUFFER_INTERNAL_FORMAT_EXT:
      value = GLint(rb->internal_format);
      break;
    case GL_RENDERBUFFER_RED_SIZE_EXT:
      value = rb->bits[0];
      break;
    case GL_RENDERBUFFER_GREEN_SIZE_EXT:
      value = rb->bits[1];
      break;
    case GL_RENDERBUFFER_BLUE_SIZE_EXT:
      value = rb->bits[2];
      break;
    case GL_RENDERBUFFER_ALPHA_SIZE_EXT:
      value = rb->bits[3];
      break;
    case GL_RENDERBUFFER_DEPTH_SIZE_EXT:
      value = rb->bits[4];
      break;
    case GL_RENDERBUFFER_STENCIL_SIZE_EXT:
      value = rb->bits[5];
      break;
    default:
      return record_error(ctx, GL_INVALID_ENUM);
  }
  if (params != nullptr) *params = value;
}

// ---- framebuffers -------------------------------------------------------------------------------

GLboolean glIsFramebuffer(Context& ctx, GLuint framebuffer) {
  FramebufferStore& store = *ctx.framebuffers.store;
  std::lock_guard lock(store.mutex);
  const auto it = store.framebuffers.find(framebuffer);
  return framebuffer != 0 && it != store.framebuffers.end() && it->second ? GL_TRUE : GL_FALSE;
}

void glBindFramebufferEXT(Context& ctx, GLenum target, GLuint framebuffer) {
  const bool draw = target == GL_FRAMEBUFFER_EXT || target == GL_DRAW_FRAMEBUFFER_EXT;
  const bool read = target == GL_FRAMEBUFFER_EXT || target == GL_READ_FRAMEBUFFER_EXT;
  if (!draw && !read) return record_error(ctx, GL_INVALID_ENUM);
  std::shared_ptr<FramebufferObject> object;
  if (framebuffer != 0) {
    FramebufferStore& store = *ctx.framebuffers.store;
    std::lock_guard lock(store.mutex);
    std::shared_ptr<FramebufferObject>& named = store.framebuffers[framebuffer];
    if (!named) named = std::make_shared<FramebufferObject>(framebuffer);
    object = named;
  }
  if (read) ctx.framebuffers.read_framebuffer = object;
  if (!draw || object == ctx.framebuffers.framebuffer) return;
  leave_framebuffer(ctx);  // what was drawn into the last one goes to its textures
  ctx.framebuffers.framebuffer = std::move(object);
  enter_framebuffer(ctx);
}

void glDeleteFramebuffers(Context& ctx, GLsizei n, const GLuint* framebuffers) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (framebuffers == nullptr) return;
  FramebufferStore& store = *ctx.framebuffers.store;
  for (GLsizei i = 0; i < n; ++i) {
    std::shared_ptr<FramebufferObject> object;
    {
      std::lock_guard lock(store.mutex);
      const auto it = store.framebuffers.find(framebuffers[i]);
      if (framebuffers[i] == 0 || it == store.framebuffers.end()) continue;
      object = it->second;
      store.framebuffers.erase(it);
    }
    if (object && ctx.framebuffers.read_framebuffer == object)
      ctx.framebuffers.read_framebuffer.reset();  // the window again
    if (object && ctx.framebuffers.framebuffer == object) {
      leave_framebuffer(ctx);
      ctx.framebuffers.framebuffer.reset();
    }
  }
}

void glGenFramebuffers(Context& ctx, GLsizei n, GLuint* framebuffers) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (framebuffers == nullptr) return;
  FramebufferStore& store = *ctx.framebuffers.store;
  std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    GLuint name = store.next_framebuffer_name;
    while (name == 0 || store.framebuffers.count(name) != 0) ++name;
    store.next_framebuffer_name = name + 1;
    store.framebuffers.emplace(name, nullptr);  // reserved until bound
    framebuffers[i] = name;
  }
}

GLenum glCheckFramebufferStatus(Context& ctx, GLenum target) {
  FramebufferObject* fb = nullptr;
  if (!framebuffer_target(ctx, target, &fb)) return 0;
  if (fb == nullptr) return GL_FRAMEBUFFER_COMPLETE_EXT;  // the window
  const FramebufferBuffers buffers = buffers_of(ctx, fb);
  std::lock_guard lock(ctx.framebuffers.store->mutex);
  return framebuffer_status(*fb, buffers.draw_buffer, buffers.read_buffer);
}

void glFramebufferTexture1D(Context& ctx, GLenum target, GLenum attachment, GLenum textarget,
                            GLuint texture, GLint level) {
  framebuffer_texture(ctx, 1, target, attachment, textarget, texture, level, 0);
}

void glFramebufferTexture2D(Context& ctx, GLenum target, GLenum attachment, GLenum textarget,
                            GLuint texture, GLint level) {
  framebuffer_texture(ctx, 2, target, attachment, textarget, texture, level, 0);
}

void glFramebufferTexture3D(Context& ctx, GLenum target, GLenum attachment, GLenum textarget,
                            GLuint texture, GLint level, GLint zoffset) {
  framebuffer_texture(ctx, 3, target, attachment, textarget, texture, level, zoffset);
}

void glFramebufferRenderbuffer(Context& ctx, GLenum target, GLenum attachment,
                               GLenum renderbuffertarget, GLuint renderbuffer) {
  FramebufferObject* fb = nullptr;
  if (!framebuffer_target(ctx, target, &fb)) return;
  if (renderbuffertarget != GL_RENDERBUFFER_EXT) return record_error(ctx, GL_INVALID_ENUM);
  std::shared_ptr<Renderbuffer> rb;
  if (renderbuffer != 0) {
    FramebufferStore& store = *ctx.framebuffers.store;
    std::lock_guard lock(store.mutex);
    const auto it = store.renderbuffers.find(renderbuffer);
    if (it != store.renderbuffers.end()) rb = it->second;
    // A name never bound is no renderbuffer (Mesa: _mesa_lookup_renderbuffer_err).
    if (!rb) return record_error(ctx, GL_INVALID_OPERATION);
  }
  if (fb == nullptr) return record_error(ctx, GL_INVALID_OPERATION);  // the window's
  Attachment* point = attachment_point(ctx, *fb, attachment);
  if (point == nullptr) return;
  if (attachment == kDepthStencilAttachment && rb && rb->width > 0 &&
      renderbuffer_base_format(rb->internal_format) != GL_DEPTH_STENCIL_EXT)
    return record_error(ctx, GL_INVALID_OPERATION);
  change_attachments(ctx, *fb, [&] {
    *point = Attachment{};
    if (rb) {
      point->type = GL_RENDERBUFFER_EXT;
      point->renderbuffer = rb;
    }
    if (attachment == kDepthStencilAttachment) fb->stencil = *point;
  });
}

void glGetFramebufferAttachmentParameteriv(Context& ctx, GLenum target, GLenum attachment,
                                           GLenum pname, GLint* params) {
  FramebufferObject* fb = nullptr;
  if (!framebuffer_target(ctx, target, &fb)) return;
  GLint value = 0;
  const GLenum error = fb == nullptr
                           ? window_attachment_parameter(ctx, attachment, pname, value)
                           : object_attachment_parameter(ctx, *fb, attachment, pname, value);
  if (error == kErrorRaised) return;
  if (error != GL_NO_ERROR) return record_error(ctx, error);
  if (params != nullptr) *params = value;
}

void glGenerateMipmap(Context& ctx, GLenum target) {
  if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && target != GL_TEXTURE_3D &&
      target != GL_TEXTURE_CUBE_MAP)
    return record_error(ctx, GL_INVALID_ENUM);
  sync_framebuffer_textures(ctx);  // level 0 may hold what the bound object drew
  TextureUnit& unit = ctx.textures.active_unit();
  TextureObject& object = ctx.textures.bound(unit, texture_slot(target));
  // Cube maps need all six base images alike (GL 3.0 4.4.4.3: GL_INVALID_OPERATION otherwise).
  if (target == GL_TEXTURE_CUBE_MAP) {
    const int base = int(object.sampler().base_level);
    const rec::TextureImage* first = object.image(0, base);
    for (int face = 0; face < 6; ++face) {
      const rec::TextureImage* image = object.image(face, base);
      if (first == nullptr || image == nullptr || image->width != first->width ||
          image->height != first->height || image->internal_format != first->internal_format)
        return record_error(ctx, GL_INVALID_OPERATION);
    }
  }
  for (int face = 0; face < object.faces(); ++face) generate_mipmaps(object, face);
}

}  // namespace impl
}  // namespace glpt
