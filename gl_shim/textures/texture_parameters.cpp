// glTexParameter{i,f}{,v}, glGetTexParameter{iv,fv}, glGetTexLevelParameter{iv,fv}
// (GL 1.5 3.8.4, 3.8.8, 6.1.3; GL 1.4 depth textures and LOD bias; SGIS_generate_mipmap;
// EXT_texture_filter_anisotropic).
#include <algorithm>
#include <array>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/query_values.hpp"
#include "gl_shim/state/value_conversions.hpp"
#include "gl_shim/textures/internal_formats.hpp"
#include "gl_shim/textures/s3tc.hpp"
#include "gl_shim/textures/texture_targets.hpp"

namespace glpt {
namespace {

// ARB_texture_rectangle: rectangle textures take no mipmap filter and no repeating wrap mode
// (GL_INVALID_ENUM, as in Mesa).
bool valid_min_filter(GLenum f, bool rectangle) {
  switch (f) {
    case GL_NEAREST:
    case GL_LINEAR:
      return true;
    case GL_NEAREST_MIPMAP_NEAREST:
    case GL_LINEAR_MIPMAP_NEAREST:
    case GL_NEAREST_MIPMAP_LINEAR:
    case GL_LINEAR_MIPMAP_LINEAR:
      return !rectangle;
    default:
      return false;
  }
}

bool valid_wrap(GLenum w, bool rectangle) {
  switch (w) {
    case GL_CLAMP:
    case GL_CLAMP_TO_EDGE:
    case GL_CLAMP_TO_BORDER:  // GL 1.3
      return true;
    case GL_REPEAT:
    case GL_MIRRORED_REPEAT:  // GL 1.4
      return !rectangle;
    default:
      return false;
  }
}

bool valid_compare_func(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

// The object glTexParameter / glGetTexParameter address: proxies and cube faces are not targets.
TextureObject* parameter_object(Context& ctx, GLenum target) {
  const int slot = texture_slot(target);
  if (slot < 0) {
    record_error(ctx, GL_INVALID_ENUM);
    return nullptr;
  }
  return &ctx.textures.bound(ctx.textures.active_unit(), slot);
}

void tex_parameter(Context& ctx, GLenum target, GLenum pname, const ParamValues& p, bool vector) {
  TextureObject* object = parameter_object(ctx, target);
  if (object == nullptr) return;
  const rec::SamplerState& s = object->sampler();
  // Validates, then writes through edit_sampler() only when the value changes, so that redundant
  // glTexParameter calls keep the snapshot (and the record's state) the same.
  const auto set_enum = [&](uint32_t rec::SamplerState::*field, bool valid) {
    if (!valid) return record_error(ctx, GL_INVALID_ENUM);
    const uint32_t v = uint32_t(p.as_int_rounded(0));
    if (s.*field != v) object->edit_sampler().*field = v;
  };
  const auto set_float = [&](float rec::SamplerState::*field, float v) {
    if (s.*field != v) object->edit_sampler().*field = v;
  };
  const bool rectangle = target == GL_TEXTURE_RECTANGLE_ARB;
  // Rectangle textures have level 0 only: Mesa answers another base level (negative ones too)
  // with GL_INVALID_OPERATION and another maximum level with GL_INVALID_VALUE (measured).
  const auto set_level = [&](int32_t rec::SamplerState::*field, GLenum rectangle_error) {
    const GLint v = p.as_int_rounded(0);
    if (rectangle && v != 0) return record_error(ctx, rectangle_error);
    if (v < 0) return record_error(ctx, GL_INVALID_VALUE);
    if (s.*field != v) object->edit_sampler().*field = v;
  };
  const GLenum e = GLenum(p.as_int_rounded(0));
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      return set_enum(&rec::SamplerState::min_filter, valid_min_filter(e, rectangle));
    case GL_TEXTURE_MAG_FILTER:
      return set_enum(&rec::SamplerState::mag_filter, e == GL_NEAREST || e == GL_LINEAR);
    case GL_TEXTURE_WRAP_S:
      return set_enum(&rec::SamplerState::wrap_s, valid_wrap(e, rectangle));
    case GL_TEXTURE_WRAP_T:
      return set_enum(&rec::SamplerState::wrap_t, valid_wrap(e, rectangle));
    case GL_TEXTURE_WRAP_R:
      return set_enum(&rec::SamplerState::wrap_r, valid_wrap(e, rectangle));
    case GL_TEXTURE_BORDER_COLOR: {
      if (!vector) return record_error(ctx, GL_INVALID_ENUM);
      glm::vec4 c;
      for (int k = 0; k < 4; ++k) c[k] = std::clamp(p.as_color(k), 0.0f, 1.0f);
      if (s.border_color != c) object->edit_sampler().border_color = c;
      return;
    }
    case GL_TEXTURE_PRIORITY:
      // Integers are taken as they are (not as colours), as Mesa does.
      object->priority = std::clamp(p.as_float(0), 0.0f, 1.0f);
      return;
    case GL_TEXTURE_MIN_LOD:
      return set_float(&rec::SamplerState::min_lod, p.as_float(0));
    case GL_TEXTURE_MAX_LOD:
      return set_float(&rec::SamplerState::max_lod, p.as_float(0));
    case GL_TEXTURE_LOD_BIAS:
      return set_float(&rec::SamplerState::lod_bias, p.as_float(0));
    case GL_TEXTURE_BASE_LEVEL:
      return set_level(&rec::SamplerState::base_level, GL_INVALID_OPERATION);
    case GL_TEXTURE_MAX_LEVEL:
      return set_level(&rec::SamplerState::max_level, GL_INVALID_VALUE);
    case GL_TEXTURE_MAX_ANISOTROPY_EXT: {
      const float a = p.as_float(0);
      if (!(a >= 1.0f)) return record_error(ctx, GL_INVALID_VALUE);
      return set_float(&rec::SamplerState::max_anisotropy, std::min(a, kMaxTextureAnisotropy));
    }
    case GL_DEPTH_TEXTURE_MODE:
      return set_enum(&rec::SamplerState::depth_texture_mode,
                      e == GL_LUMINANCE || e == GL_INTENSITY || e == GL_ALPHA);
    case GL_TEXTURE_COMPARE_MODE:
      return set_enum(&rec::SamplerState::compare_mode,
                      e == GL_NONE || e == GL_COMPARE_R_TO_TEXTURE);
    case GL_TEXTURE_COMPARE_FUNC:  // all eight functions since GL 1.5 (EXT_shadow_funcs)
      return set_enum(&rec::SamplerState::compare_func, valid_compare_func(e));
    case GL_GENERATE_MIPMAP:
      object->generate_mipmap = p.as_float(0) != 0.0f;
      return;
    default:  // GL_TEXTURE_RESIDENT is only a query
      record_error(ctx, GL_INVALID_ENUM);
  }
}

// The value(s) of a glGetTexParameter query and how they convert to integers.
enum class ValueKind { kInteger, kFloat, kColor };
struct ParamValue {
  ValueKind kind = ValueKind::kInteger;
  int count = 1;
  std::array<double, 4> v{};
};

bool tex_parameter_value(Context& ctx, GLenum target, GLenum pname, ParamValue& out) {
  TextureObject* object = parameter_object(ctx, target);
  if (object == nullptr) return false;
  const rec::SamplerState& s = object->sampler();
  const auto integer = [&](double v) { out = {ValueKind::kInteger, 1, {v}}; };
  const auto real = [&](float v) { out = {ValueKind::kFloat, 1, {v}}; };
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      integer(s.min_filter);
      return true;
    case GL_TEXTURE_MAG_FILTER:
      integer(s.mag_filter);
      return true;
    case GL_TEXTURE_WRAP_S:
      integer(s.wrap_s);
      return true;
    case GL_TEXTURE_WRAP_T:
      integer(s.wrap_t);
      return true;
    case GL_TEXTURE_WRAP_R:
      integer(s.wrap_r);
      return true;
    case GL_TEXTURE_BORDER_COLOR:
      out = {ValueKind::kColor,
             4,
             {s.border_color.r, s.border_color.g, s.border_color.b, s.border_color.a}};
      return true;
    case GL_TEXTURE_PRIORITY:
      out = {ValueKind::kColor, 1, {object->priority}};
      return true;
    case GL_TEXTURE_RESIDENT:
      integer(1);  // every texture is resident
      return true;
    case GL_TEXTURE_MIN_LOD:
      real(s.min_lod);
      return true;
    case GL_TEXTURE_MAX_LOD:
      real(s.max_lod);
      return true;
    case GL_TEXTURE_LOD_BIAS:
      real(s.lod_bias);
      return true;
    case GL_TEXTURE_BASE_LEVEL:
      integer(s.base_level);
      return true;
    case GL_TEXTURE_MAX_LEVEL:
      integer(s.max_level);
      return true;
    case GL_TEXTURE_MAX_ANISOTROPY_EXT:
      real(s.max_anisotropy);
      return true;
    case GL_DEPTH_TEXTURE_MODE:
      integer(s.depth_texture_mode);
      return true;
    case GL_TEXTURE_COMPARE_MODE:
      integer(s.compare_mode);
      return true;
    case GL_TEXTURE_COMPARE_FUNC:
      integer(s.compare_func);
      return true;
    case GL_GENERATE_MIPMAP:
      integer(object->generate_mipmap ? 1 : 0);
      return true;
    default:
      record_error(ctx, GL_INVALID_ENUM);
      return false;
  }
}

// glGetTexLevelParameter: one integer.
bool tex_level_parameter_value(Context& ctx, GLenum target, GLint level, GLenum pname, GLint& out) {
  const std::optional<ImageTarget> t = image_target(target, 0, ProxyTargets::kAccepted);
  if (!t) {
    record_error(ctx, GL_INVALID_ENUM);
    return false;
  }
  if (level < 0 || level >= max_texture_levels(t->slot)) {
    record_error(ctx, GL_INVALID_VALUE);
    return false;
  }
  const rec::TextureImage* img = target_object(ctx, *t).image(t->face, level);
  // Sizes are those of the format the texels are stored in; the internal format is reported as
  // requested.
  const InternalFormatInfo* info =
      img != nullptr ? stored_format_info(img->internal_format, img->sized_format) : nullptr;
  const InternalFormatInfo* requested =
      img != nullptr ? internal_format_info(GLint(img->internal_format)) : nullptr;
  const auto size = [&](uint32_t stored, bool bordered) {
    if (img == nullptr) return GLint(0);
    // Reported with the border, as specified (the stored texels have it stripped).
    return GLint(stored + (bordered ? 2 * img->border : 0));
  };
  switch (pname) {
    case GL_TEXTURE_WIDTH:
      out = size(img ? img->width : 0, true);
      return true;
    case GL_TEXTURE_HEIGHT:
      out = size(img ? img->height : 0, t->dims >= 2);
      return true;
    case GL_TEXTURE_DEPTH:
      out = size(img ? img->depth : 0, t->dims == 3);
      return true;
    case GL_TEXTURE_BORDER:
      out = img ? GLint(img->border) : 0;
      return true;
    case GL_TEXTURE_INTERNAL_FORMAT:  // == GL_TEXTURE_COMPONENTS
      // An undefined image (or a proxy GL could not create) answers GL_RGBA, as Mesa and GL 3+
      // do; GL 1.5's table 6.17 says 1 (no program can tell the difference in what it draws).
      out = requested ? requested->reported : GL_RGBA;
      return true;
    case GL_TEXTURE_RED_SIZE:
      out = info ? info->red : 0;
      return true;
    case GL_TEXTURE_GREEN_SIZE:
      out = info ? info->green : 0;
      return true;
    case GL_TEXTURE_BLUE_SIZE:
      out = info ? info->blue : 0;
      return true;
    case GL_TEXTURE_ALPHA_SIZE:
      out = info ? info->alpha : 0;
      return true;
    case GL_TEXTURE_LUMINANCE_SIZE:
      out = info ? info->luminance : 0;
      return true;
    case GL_TEXTURE_INTENSITY_SIZE:
      out = info ? info->intensity : 0;
      return true;
    case GL_TEXTURE_DEPTH_SIZE:
      out = info ? info->depth : 0;
      return true;
    case GL_TEXTURE_STENCIL_SIZE_EXT:  // EXT_packed_depth_stencil
      out = info ? info->stencil : 0;
      return true;
    case GL_TEXTURE_COMPRESSED:
      // S3TC images, proxies included; the generic compressed formats are stored uncompressed.
      out = requested != nullptr && requested->block_bytes != 0 ? 1 : 0;
      return true;
    case GL_TEXTURE_COMPRESSED_IMAGE_SIZE:
      // Mesa answers only for a compressed image that is not a proxy; anything else (an
      // undefined image too) is GL_INVALID_OPERATION.
      if (requested == nullptr || requested->block_bytes == 0 || t->proxy) {
        record_error(ctx, GL_INVALID_OPERATION);
        return false;
      }
      out = GLint(
          s3tc::image_bytes(GLenum(img->internal_format), img->width, img->height, img->depth));
      return true;
    default:
      record_error(ctx, GL_INVALID_ENUM);
      return false;
  }
}

}  // namespace

namespace impl {

void glTexParameterf(Context& ctx, GLenum target, GLenum pname, GLfloat param) {
  tex_parameter(ctx, target, pname, ParamValues{&param, nullptr}, false);
}
void glTexParameteri(Context& ctx, GLenum target, GLenum pname, GLint param) {
  tex_parameter(ctx, target, pname, ParamValues{nullptr, &param}, false);
}
void glTexParameterfv(Context& ctx, GLenum target, GLenum pname, const GLfloat* params) {
  if (params == nullptr) return;
  tex_parameter(ctx, target, pname, ParamValues{params, nullptr}, true);
}
void glTexParameteriv(Context& ctx, GLenum target, GLenum pname, const GLint* params) {
  if (params == nullptr) return;
  tex_parameter(ctx, target, pname, ParamValues{nullptr, params}, true);
}

void glGetTexParameterfv(Context& ctx, GLenum target, GLenum pname, GLfloat* params) {
  ParamValue v;
  if (!tex_parameter_value(ctx, target, pname, v) || params == nullptr) return;
  for (int k = 0; k < v.count; ++k) params[k] = GLfloat(v.v[size_t(k)]);
}

void glGetTexParameteriv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  ParamValue v;
  if (!tex_parameter_value(ctx, target, pname, v) || params == nullptr) return;
  for (int k = 0; k < v.count; ++k) {
    switch (v.kind) {
      case ValueKind::kInteger:
        params[k] = GLint(v.v[size_t(k)]);
        break;
      case ValueKind::kFloat:
        params[k] = query::round_to_int(float(v.v[size_t(k)]));
        break;
      case ValueKind::kColor:
        params[k] = query::color_to_int(float(v.v[size_t(k)]));
        break;
    }
  }
}

void glGetTexLevelParameteriv(Context& ctx, GLenum target, GLint level, GLenum pname,
                              GLint* params) {
  GLint v = 0;
  if (tex_level_parameter_value(ctx, target, level, pname, v) && params != nullptr) *params = v;
}

void glGetTexLevelParameterfv(Context& ctx, GLenum target, GLint level, GLenum pname,
                              GLfloat* params) {
  GLint v = 0;
  if (tex_level_parameter_value(ctx, target, level, pname, v) && params != nullptr)
    *params = GLfloat(v);
}

}  // namespace impl
}  // namespace glpt
