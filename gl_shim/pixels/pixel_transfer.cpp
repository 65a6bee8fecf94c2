// Pixel transfer operations and their state commands: glPixelTransfer{i,f}, glPixelMap{fv,uiv,usv},
// glGetPixelMap{fv,uiv,usv}, glPixelZoom (GL 1.5 3.6.3, 3.6.5, 3.6.4 "Zoom", 6.1.3).
#include "gl_shim/pixels/pixel_transfer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

int map_slot(GLenum map) {
  if (map < GL_PIXEL_MAP_I_TO_I || map > GL_PIXEL_MAP_A_TO_A) return -1;
  return int(map - GL_PIXEL_MAP_I_TO_I);
}
bool is_index_map(GLenum map) { return map == GL_PIXEL_MAP_I_TO_I || map == GL_PIXEL_MAP_S_TO_S; }
// Maps indexed by a colour or stencil index, whose size GL requires to be a power of two.
bool is_indexed_by_index(GLenum map) { return map <= GL_PIXEL_MAP_I_TO_A; }

// The map's entry for a component in [0, 1] (round to nearest even, as Mesa's _mesa_map_rgba).
float lookup_color(const std::vector<float>& map, float c) {
  const float scaled = std::clamp(c, 0.0f, 1.0f) * float(map.size() - 1);
  return map[size_t(std::lrint(scaled))];
}

float lookup_index(const std::vector<float>& map, uint32_t index) {
  return map[index & uint32_t(map.size() - 1)];
}

// Stores a map given as floats (already converted from the command's type): colour maps clamp
// to [0, 1]; S_TO_S rounds to integers; I_TO_I keeps the values (Mesa's store_pixelmap).
void store_map(Context& ctx, GLenum map, GLsizei size, const float* values) {
  const int slot = map_slot(map);
  if (slot < 0) return record_error(ctx, GL_INVALID_ENUM);
  if (size < 1 || size > kMaxPixelMapTable) return record_error(ctx, GL_INVALID_VALUE);
  // GL 1.5 3.6.3 requires powers of two for every map indexed by an index, I_TO_I included
  // (Mesa forgets I_TO_I).
  if (is_indexed_by_index(map) && !std::has_single_bit(uint32_t(size)))
    return record_error(ctx, GL_INVALID_VALUE);
  if (values == nullptr) return;
  std::vector<float> table(values, values + size);
  for (float& v : table) {
    if (map == GL_PIXEL_MAP_S_TO_S)
      v = std::round(v);
    else if (!is_index_map(map))
      v = std::clamp(v, 0.0f, 1.0f);
  }
  auto maps = std::make_shared<rec::PixelMaps>(ctx.pixel_transfer.pixel_maps());
  maps->maps[size_t(slot)] = std::move(table);
  ctx.pixel_transfer.maps = std::move(maps);
}

template <typename T, typename Convert>
void store_map_from(Context& ctx, GLenum map, GLsizei size, const T* values, Convert convert) {
  if (values == nullptr || size < 1 || size > kMaxPixelMapTable)
    return store_map(ctx, map, size, nullptr);
  float converted[kMaxPixelMapTable];
  for (GLsizei i = 0; i < size; ++i) converted[i] = convert(values[i]);
  store_map(ctx, map, size, converted);
}

// The map for glGetPixelMap, or null (GL_INVALID_ENUM recorded).
const std::vector<float>* map_to_get(Context& ctx, GLenum map) {
  const std::vector<float>* m = pixel_map(ctx.pixel_transfer, map);
  if (m == nullptr) record_error(ctx, GL_INVALID_ENUM);
  return m;
}

// Index maps returned as integers: truncated and clamped to the type's range (Mesa's usv rule;
// Mesa's uiv returns colour-converted values for I_TO_I and raw float bits for S_TO_S, which is
// a bug glpt does not copy).
template <typename T>
T index_as(float v) {
  const double max = double(std::numeric_limits<T>::max());
  return T(std::clamp(std::trunc(double(v)), 0.0, max));
}

}  // namespace

void transfer_rgba(const rec::PixelTransferState& t, std::vector<glm::vec4>& rgba) {
  const bool scale_bias = t.scale != glm::vec4(1.0f) || t.bias != glm::vec4(0.0f);
  const rec::PixelMaps& maps = t.pixel_maps();
  const int first_color_map = GL_PIXEL_MAP_R_TO_R - GL_PIXEL_MAP_I_TO_I;
  for (glm::vec4& px : rgba) {
    if (scale_bias) px = px * t.scale + t.bias;
    if (t.map_color) {
      for (int c = 0; c < 4; ++c)
        px[c] = lookup_color(maps.maps[size_t(first_color_map + c)], px[c]);
    }
    px = glm::clamp(px, 0.0f, 1.0f);
  }
}

uint32_t shift_and_offset_index(const rec::PixelTransferState& t, uint32_t index) {
  const int32_t shift = t.index_shift;
  if (shift >= 32 || shift <= -32) {
    index = 0;
  } else if (shift > 0) {
    index <<= shift;
  } else if (shift < 0) {
    index >>= -shift;
  }
  return index + uint32_t(t.index_offset);
}

std::vector<glm::vec4> transfer_index_to_rgba(const rec::PixelTransferState& t,
                                              const std::vector<uint32_t>& indices) {
  const rec::PixelMaps& maps = t.pixel_maps();
  const int first = GL_PIXEL_MAP_I_TO_R - GL_PIXEL_MAP_I_TO_I;
  std::vector<glm::vec4> rgba(indices.size());
  for (size_t i = 0; i < indices.size(); ++i) {
    const uint32_t index = shift_and_offset_index(t, indices[i]);
    for (int c = 0; c < 4; ++c)
      rgba[i][c] = std::clamp(lookup_index(maps.maps[size_t(first + c)], index), 0.0f, 1.0f);
  }
  return rgba;
}

void transfer_stencil(const rec::PixelTransferState& t, std::vector<uint32_t>& stencil) {
  const std::vector<float>& map = t.pixel_maps().maps[GL_PIXEL_MAP_S_TO_S - GL_PIXEL_MAP_I_TO_I];
  for (uint32_t& s : stencil) {
    s = shift_and_offset_index(t, s);
    if (t.map_stencil) s = uint32_t(int64_t(lookup_index(map, s)));
  }
}

void transfer_depth(const rec::PixelTransferState& t, std::vector<float>& depth) {
  for (float& d : depth) d = std::clamp(d * t.depth_scale + t.depth_bias, 0.0f, 1.0f);
}

const std::vector<float>* pixel_map(const rec::PixelTransferState& t, GLenum map) {
  const int slot = map_slot(map);
  return slot < 0 ? nullptr : &t.pixel_maps().maps[size_t(slot)];
}

namespace impl {

void glPixelTransferf(Context& ctx, GLenum pname, GLfloat param) {
  rec::PixelTransferState& t = ctx.pixel_transfer;
  switch (pname) {
    case GL_MAP_COLOR:
      t.map_color = param != 0.0f;
      return;
    case GL_MAP_STENCIL:
      t.map_stencil = param != 0.0f;
      return;
    // Integer state set from a float: truncated, as Mesa does.
    case GL_INDEX_SHIFT:
      t.index_shift = std::isfinite(param) ? int32_t(std::clamp(param, -2.0e9f, 2.0e9f)) : 0;
      return;
    case GL_INDEX_OFFSET:
      t.index_offset = std::isfinite(param) ? int32_t(std::clamp(param, -2.0e9f, 2.0e9f)) : 0;
      return;
    case GL_RED_SCALE:
      t.scale.r = param;
      return;
    case GL_GREEN_SCALE:
      t.scale.g = param;
      return;
    case GL_BLUE_SCALE:
      t.scale.b = param;
      return;
    case GL_ALPHA_SCALE:
      t.scale.a = param;
      return;
    case GL_RED_BIAS:
      t.bias.r = param;
      return;
    case GL_GREEN_BIAS:
      t.bias.g = param;
      return;
    case GL_BLUE_BIAS:
      t.bias.b = param;
      return;
    case GL_ALPHA_BIAS:
      t.bias.a = param;
      return;
    case GL_DEPTH_SCALE:
      t.depth_scale = param;
      return;
    case GL_DEPTH_BIAS:
      t.depth_bias = param;
      return;
    default:  // the ARB_imaging pnames too: glpt has no imaging subset (nor has Mesa)
      record_error(ctx, GL_INVALID_ENUM);
  }
}

void glPixelTransferi(Context& ctx, GLenum pname, GLint param) {
  if (pname == GL_INDEX_SHIFT || pname == GL_INDEX_OFFSET) {
    // Exact for every int (a float would round large offsets).
    if (pname == GL_INDEX_SHIFT)
      ctx.pixel_transfer.index_shift = param;
    else
      ctx.pixel_transfer.index_offset = param;
    return;
  }
  glPixelTransferf(ctx, pname, static_cast<GLfloat>(param));
}

void glPixelZoom(Context& ctx, GLfloat xfactor, GLfloat yfactor) {
  ctx.pixel_transfer.zoom_x = xfactor;
  ctx.pixel_transfer.zoom_y = yfactor;
}

void glPixelMapfv(Context& ctx, GLenum map, GLsizei mapsize, const GLfloat* values) {
  store_map(ctx, map, mapsize, values);
}

void glPixelMapuiv(Context& ctx, GLenum map, GLsizei mapsize, const GLuint* values) {
  const bool index = is_index_map(map);
  store_map_from(ctx, map, mapsize, values,
                 [index](GLuint v) { return index ? float(v) : float(double(v) / 4294967295.0); });
}

void glPixelMapusv(Context& ctx, GLenum map, GLsizei mapsize, const GLushort* values) {
  const bool index = is_index_map(map);
  store_map_from(ctx, map, mapsize, values,
                 [index](GLushort v) { return index ? float(v) : float(v) / 65535.0f; });
}

void glGetPixelMapfv(Context& ctx, GLenum map, GLfloat* values) {
  const std::vector<float>* m = map_to_get(ctx, map);
  if (m == nullptr || values == nullptr) return;
  std::copy(m->begin(), m->end(), values);
}

void glGetPixelMapuiv(Context& ctx, GLenum map, GLuint* values) {
  const std::vector<float>* m = map_to_get(ctx, map);
  if (m == nullptr || values == nullptr) return;
  for (size_t i = 0; i < m->size(); ++i) {
    // Colour maps: [0,1] -> [0, 2^32-1], truncated (Mesa's FLOAT_TO_UINT).
    values[i] =
        is_index_map(map) ? index_as<GLuint>((*m)[i]) : GLuint(double((*m)[i]) * 4294967295.0);
  }
}

void glGetPixelMapusv(Context& ctx, GLenum map, GLushort* values) {
  const std::vector<float>* m = map_to_get(ctx, map);
  if (m == nullptr || values == nullptr) return;
  for (size_t i = 0; i < m->size(); ++i) {
    // Colour maps: [0,1] -> [0, 65535], rounded (Mesa's FLOAT_TO_USHORT).
    values[i] =
        is_index_map(map) ? index_as<GLushort>((*m)[i]) : GLushort(std::lround((*m)[i] * 65535.0f));
  }
}

}  // namespace impl
}  // namespace glpt
