// glEnable, glDisable, glIsEnabled (GL 1.5 spec 2.x and table 6.x).
#include "gl_shim/state/enable_state.hpp"

#include <algorithm>
#include <array>
#include <iterator>

#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl/gl_enums.h"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

struct Cap {
  GLenum cap;
  bool initially_on;
};

// Every server-side capability of GL 1.5 (plus the ARB/EXT ones glpt accepts), sorted by enum.
constexpr Cap kCapList[] = {
    {GL_POINT_SMOOTH, false},
    {GL_LINE_SMOOTH, false},
    {GL_LINE_STIPPLE, false},
    {GL_POLYGON_SMOOTH, false},
    {GL_POLYGON_STIPPLE, false},
    {GL_CULL_FACE, false},
    {GL_LIGHTING, false},
    {GL_COLOR_MATERIAL, false},
    {GL_FOG, false},
    {GL_DEPTH_TEST, false},
    {GL_STENCIL_TEST, false},
    {GL_NORMALIZE, false},
    {GL_ALPHA_TEST, false},
    {GL_DITHER, true},
    {GL_BLEND, false},
    {GL_INDEX_LOGIC_OP, false},
    {GL_COLOR_LOGIC_OP, false},
    {GL_SCISSOR_TEST, false},
    {GL_TEXTURE_GEN_S, false},
    {GL_TEXTURE_GEN_T, false},
    {GL_TEXTURE_GEN_R, false},
    {GL_TEXTURE_GEN_Q, false},
    {GL_AUTO_NORMAL, false},
    {GL_MAP1_COLOR_4, false},
    {GL_MAP1_INDEX, false},
    {GL_MAP1_NORMAL, false},
    {GL_MAP1_TEXTURE_COORD_1, false},
    {GL_MAP1_TEXTURE_COORD_2, false},
    {GL_MAP1_TEXTURE_COORD_3, false},
    {GL_MAP1_TEXTURE_COORD_4, false},
    {GL_MAP1_VERTEX_3, false},
    {GL_MAP1_VERTEX_4, false},
    {GL_MAP2_COLOR_4, false},
    {GL_MAP2_INDEX, false},
    {GL_MAP2_NORMAL, false},
    {GL_MAP2_TEXTURE_COORD_1, false},
    {GL_MAP2_TEXTURE_COORD_2, false},
    {GL_MAP2_TEXTURE_COORD_3, false},
    {GL_MAP2_TEXTURE_COORD_4, false},
    {GL_MAP2_VERTEX_3, false},
    {GL_MAP2_VERTEX_4, false},
    {GL_TEXTURE_1D, false},
    {GL_TEXTURE_2D, false},
    {GL_POLYGON_OFFSET_POINT, false},
    {GL_POLYGON_OFFSET_LINE, false},
    {GL_CLIP_PLANE0, false},
    {GL_CLIP_PLANE1, false},
    {GL_CLIP_PLANE2, false},
    {GL_CLIP_PLANE3, false},
    {GL_CLIP_PLANE4, false},
    {GL_CLIP_PLANE5, false},
    {GL_LIGHT0, false},
    {GL_LIGHT1, false},
    {GL_LIGHT2, false},
    {GL_LIGHT3, false},
    {GL_LIGHT4, false},
    {GL_LIGHT5, false},
    {GL_LIGHT6, false},
    {GL_LIGHT7, false},
    {GL_CONVOLUTION_1D, false},
    {GL_CONVOLUTION_2D, false},
    {GL_SEPARABLE_2D, false},
    {GL_HISTOGRAM, false},
    {GL_MINMAX, false},
    {GL_POLYGON_OFFSET_FILL, false},
    {GL_RESCALE_NORMAL, false},
    {GL_TEXTURE_3D, false},
    {GL_MULTISAMPLE, true},
    {GL_SAMPLE_ALPHA_TO_COVERAGE, false},
    {GL_SAMPLE_ALPHA_TO_ONE, false},
    {GL_SAMPLE_COVERAGE, false},
    {GL_COLOR_TABLE, false},
    {GL_POST_CONVOLUTION_COLOR_TABLE, false},
    {GL_POST_COLOR_MATRIX_COLOR_TABLE, false},
    {GL_TEXTURE_CUBE_MAP, false},
    {GL_COLOR_SUM, false},
    {GL_TEXTURE_RECTANGLE_ARB, false},
};
constexpr auto kCaps = [] {
  std::array<Cap, std::size(kCapList)> caps{};
  std::copy(std::begin(kCapList), std::end(kCapList), caps.begin());
  std::sort(caps.begin(), caps.end(), [](const Cap& a, const Cap& b) { return a.cap < b.cap; });
  return caps;
}();
static_assert(kCaps.size() <= EnableState::kMaxCaps);

int index_of(GLenum cap) {
  auto it = std::lower_bound(kCaps.begin(), kCaps.end(), cap,
                             [](const Cap& c, GLenum v) { return c.cap < v; });
  return it != kCaps.end() && it->cap == cap ? static_cast<int>(it - kCaps.begin()) : -1;
}

void set_cap(Context& ctx, GLenum cap, bool on) {
  if (!ctx.enables.set(cap, on)) return record_error(ctx, GL_INVALID_ENUM);
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights)
    ctx.lighting.light_enabled[cap - GL_LIGHT0] = on;
  // These change how the next vertices are shaded.
  if (cap == GL_LIGHTING || cap == GL_COLOR_MATERIAL ||
      (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights))
    ++ctx.lighting.material_version;
}

}  // namespace

EnableState::EnableState() {
  for (size_t i = 0; i < kCaps.size(); ++i) bits_[i] = kCaps[i].initially_on;
}

std::optional<bool> EnableState::get(GLenum cap) const {
  const int i = index_of(cap);
  if (i < 0) return std::nullopt;
  return bits_[static_cast<size_t>(i)];
}

bool EnableState::set(GLenum cap, bool on) {
  const int i = index_of(cap);
  if (i < 0) return false;
  bits_[static_cast<size_t>(i)] = on;
  return true;
}

namespace impl {

void glEnable(Context& ctx, GLenum cap) { set_cap(ctx, cap, true); }
void glDisable(Context& ctx, GLenum cap) { set_cap(ctx, cap, false); }
GLboolean glIsEnabled(Context& ctx, GLenum cap) {
  const auto v = ctx.enables.get(cap);
  if (!v) {
    record_error(ctx, GL_INVALID_ENUM);
    return 0;
  }
  return *v ? 1 : 0;
}

}  // namespace impl
}  // namespace glpt
