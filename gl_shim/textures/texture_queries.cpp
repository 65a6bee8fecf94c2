// glGet pnames of texturing and the pixel paths (GL 1.5 tables 6.14-6.21, 6.25, 6.28-6.30),
// consulted by queries.cpp's lookup.
#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/pixels/pixel_transfer.hpp"
#include "gl_shim/state/query_values.hpp"

namespace glpt {

bool lookup_texture_and_pixel_state(const Context& ctx, GLenum pname, query::Value* out) {
  using query::boolean;
  using query::floats;
  using query::ints;
  const TextureUnits& tex = ctx.textures;
  const PixelStoreModes& pack = ctx.framebuffer.pack;
  const PixelStoreModes& unpack = ctx.framebuffer.unpack;
  const rec::PixelTransferState& t = ctx.pixel_transfer;
  const auto real = [&](float v) { *out = floats(&v, 1); };
  // Texture bindings of the active unit.
  if (const int slot =
          texture_slot(pname == GL_TEXTURE_BINDING_1D              ? GL_TEXTURE_1D
                       : pname == GL_TEXTURE_BINDING_2D            ? GL_TEXTURE_2D
                       : pname == GL_TEXTURE_BINDING_3D            ? GL_TEXTURE_3D
                       : pname == GL_TEXTURE_BINDING_CUBE_MAP      ? GL_TEXTURE_CUBE_MAP
                       : pname == GL_TEXTURE_BINDING_RECTANGLE_ARB ? GL_TEXTURE_RECTANGLE_ARB
                                                                   : 0);
      slot >= 0) {
    *out = ints({double(tex.bound(tex.active_unit(), slot).name())});
    return true;
  }
  // The pixel map sizes.
  if (pname >= GL_PIXEL_MAP_I_TO_I_SIZE && pname <= GL_PIXEL_MAP_A_TO_A_SIZE) {
    const auto& maps = t.pixel_maps().maps;
    *out = ints({double(maps[pname - GL_PIXEL_MAP_I_TO_I_SIZE].size())});
    return true;
  }
  switch (pname) {
    case GL_ACTIVE_TEXTURE:
      *out = ints({double(GL_TEXTURE0 + tex.active)});
      return true;
    case GL_CLIENT_ACTIVE_TEXTURE:
      *out = ints({double(GL_TEXTURE0 + tex.client_active)});
      return true;
    // Implementation limits.
    case GL_MAX_TEXTURE_SIZE:
    case GL_MAX_CUBE_MAP_TEXTURE_SIZE:
      *out = ints({kMaxTextureSize});
      return true;
    case GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB:
      *out = ints({kMaxRectangleTextureSize});
      return true;
    case GL_MAX_3D_TEXTURE_SIZE:
      *out = ints({kMax3DTextureSize});
      return true;
    case GL_MAX_TEXTURE_UNITS:
    // GL 2.0's per-unit limits are not GL 1.5 state, but state dumpers (apitrace's glretrace
    // -D, which sizes its per-unit loop with them) ask them of every context, and Mesa answers
    // them in a 1.x context too. Without shaders, every unit has coordinates and an image.
    case GL_MAX_TEXTURE_COORDS:
    case GL_MAX_TEXTURE_IMAGE_UNITS:
    case GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS:
      *out = ints({double(rec::kMaxTextureUnits)});
      return true;
    case GL_MAX_TEXTURE_LOD_BIAS:
      real(kMaxTextureLodBias);
      return true;
    // EXT_framebuffer_object's bindings and limits.
    case GL_FRAMEBUFFER_BINDING_EXT:
      *out = ints({double(ctx.framebuffers.framebuffer ? ctx.framebuffers.framebuffer->name : 0)});
      return true;
    case GL_READ_FRAMEBUFFER_BINDING_EXT:
      *out = ints({double(
          ctx.framebuffers.read_framebuffer ? ctx.framebuffers.read_framebuffer->name : 0)});
      return true;
    case GL_RENDERBUFFER_BINDING_EXT:
      *out =
          ints({double(ctx.framebuffers.renderbuffer ? ctx.framebuffers.renderbuffer->name : 0)});
      return true;
    case GL_MAX_RENDERBUFFER_SIZE_EXT:
      *out = ints({kMaxRenderbufferSize});
      return true;
    case GL_MAX_COLOR_ATTACHMENTS_EXT:
      *out = ints({kMaxColorAttachments});
      return true;
    case GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT:
      real(kMaxTextureAnisotropy);
      return true;
    case GL_MAX_PIXEL_MAP_TABLE:
      *out = ints({kMaxPixelMapTable});
      return true;
    // The S3TC formats as Mesa lists them, in its order: desktop GL's list leaves out
    // GL_COMPRESSED_RGBA_S3TC_DXT1_EXT (its 1-bit alpha makes it a poor general choice; Mesa
    // lists it for GLES only). Mesa 25 also lists FXT1 and ETC2 formats, which glpt lacks.
    case GL_NUM_COMPRESSED_TEXTURE_FORMATS:
      *out = ints({3});
      return true;
    case GL_COMPRESSED_TEXTURE_FORMATS:
      *out = ints({GL_COMPRESSED_RGB_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
                   GL_COMPRESSED_RGBA_S3TC_DXT5_EXT});
      return true;
    // Pixel store modes of 3-D images (the others are in queries.cpp).
    case GL_UNPACK_IMAGE_HEIGHT:
      *out = ints({double(unpack.image_height)});
      return true;
    case GL_UNPACK_SKIP_IMAGES:
      *out = ints({double(unpack.skip_images)});
      return true;
    case GL_PACK_IMAGE_HEIGHT:
      *out = ints({double(pack.image_height)});
      return true;
    case GL_PACK_SKIP_IMAGES:
      *out = ints({double(pack.skip_images)});
      return true;
    // Pixel transfer and zoom.
    case GL_MAP_COLOR:
      *out = boolean(t.map_color);
      return true;
    case GL_MAP_STENCIL:
      *out = boolean(t.map_stencil);
      return true;
    case GL_INDEX_SHIFT:
      *out = ints({double(t.index_shift)});
      return true;
    case GL_INDEX_OFFSET:
      *out = ints({double(t.index_offset)});
      return true;
    case GL_RED_SCALE:
      real(t.scale.r);
      return true;
    case GL_GREEN_SCALE:
      real(t.scale.g);
      return true;
    case GL_BLUE_SCALE:
      real(t.scale.b);
      return true;
    case GL_ALPHA_SCALE:
      real(t.scale.a);
      return true;
    case GL_RED_BIAS:
      real(t.bias.r);
      return true;
    case GL_GREEN_BIAS:
      real(t.bias.g);
      return true;
    case GL_BLUE_BIAS:
      real(t.bias.b);
      return true;
    case GL_ALPHA_BIAS:
      real(t.bias.a);
      return true;
    case GL_DEPTH_SCALE:
      real(t.depth_scale);
      return true;
    case GL_DEPTH_BIAS:
      real(t.depth_bias);
      return true;
    case GL_ZOOM_X:
      real(t.zoom_x);
      return true;
    case GL_ZOOM_Y:
      real(t.zoom_y);
      return true;
    default:
      return false;
  }
}

}  // namespace glpt
