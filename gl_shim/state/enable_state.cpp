// glEnable, glDisable, glIsEnabled (GL 1.5 spec 2.x and table 6.x).
#include "gl_shim/state/enable_state.hpp"

#include <algorithm>
#include <array>
#include <iterator>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/lighting.hpp"

namespace glpt {
namespace {

struct Cap {
  GLenum cap;
  bool initially_on;
};

// Server-side capabilities of GL 1.5 (plus the ARB/EXT ones glpt accepts) that have no field in
// the state blocks (see flag_field/flag_bit below); sorted by enum at compile time. The imaging
// subset's capabilities (colour tables, convolution, histogram, minmax) are not among them: Mesa
// does not expose ARB_imaging and answers GL_INVALID_ENUM for them, as glpt does.
constexpr Cap kCapList[] = {
    {GL_INDEX_LOGIC_OP, false},       {GL_AUTO_NORMAL, false},
    {GL_MAP1_COLOR_4, false},         {GL_MAP1_INDEX, false},
    {GL_MAP1_NORMAL, false},          {GL_MAP1_TEXTURE_COORD_1, false},
    {GL_MAP1_TEXTURE_COORD_2, false}, {GL_MAP1_TEXTURE_COORD_3, false},
    {GL_MAP1_TEXTURE_COORD_4, false}, {GL_MAP1_VERTEX_3, false},
    {GL_MAP1_VERTEX_4, false},        {GL_MAP2_COLOR_4, false},
    {GL_MAP2_INDEX, false},           {GL_MAP2_NORMAL, false},
    {GL_MAP2_TEXTURE_COORD_1, false}, {GL_MAP2_TEXTURE_COORD_2, false},
    {GL_MAP2_TEXTURE_COORD_3, false}, {GL_MAP2_TEXTURE_COORD_4, false},
    {GL_MAP2_VERTEX_3, false},        {GL_MAP2_VERTEX_4, false},
    {GL_MULTISAMPLE, true},           {GL_SAMPLE_ALPHA_TO_COVERAGE, false},
    {GL_SAMPLE_ALPHA_TO_ONE, false},  {GL_SAMPLE_COVERAGE, false},
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

// Capabilities whose value lives in the state blocks (ctx.lighting, ctx.raster, ...): the single
// source of truth for both glEnable and glIsEnabled. Bit-field capabilities (lights, clip planes,
// texture targets and texgen of the active unit) are handled by `flag_bit`.
bool* flag_field(Context& ctx, GLenum cap) {
  rec::PrimitiveState& p = ctx.raster.primitive;
  rec::FragmentOpsState& f = ctx.raster.ops;
  switch (cap) {
    case GL_LIGHTING:
      return &ctx.lighting.enabled;
    case GL_COLOR_MATERIAL:
      return &ctx.lighting.color_material;
    case GL_NORMALIZE:
      return &ctx.transform.normalize;
    case GL_RESCALE_NORMAL:
      return &ctx.transform.rescale_normal;
    case GL_CULL_FACE:
      return &p.cull_face;
    case GL_POLYGON_OFFSET_FILL:
      return &p.offset_fill;
    case GL_POLYGON_OFFSET_LINE:
      return &p.offset_line;
    case GL_POLYGON_OFFSET_POINT:
      return &p.offset_point;
    case GL_POLYGON_SMOOTH:
      return &p.polygon_smooth;
    case GL_POLYGON_STIPPLE:
      return &p.polygon_stipple;
    case GL_LINE_SMOOTH:
      return &p.line_smooth;
    case GL_LINE_STIPPLE:
      return &p.line_stipple;
    case GL_POINT_SMOOTH:
      return &p.point_smooth;
    case GL_POINT_SPRITE:
      return &p.point_sprite;
    case GL_FOG:
      return &ctx.raster.fog.enabled;
    case GL_COLOR_SUM:
      return &f.color_sum;
    case GL_SCISSOR_TEST:
      return &f.scissor_test;
    case GL_ALPHA_TEST:
      return &f.alpha_test;
    case GL_STENCIL_TEST:
      return &f.stencil_test;
    case GL_STENCIL_TEST_TWO_SIDE_EXT:
      return &f.stencil_two_side;
    case GL_DEPTH_TEST:
      return &f.depth_test;
    case GL_BLEND:
      return &f.blend;
    case GL_COLOR_LOGIC_OP:
      return &f.color_logic_op;
    case GL_DITHER:
      return &f.dither;
    default:
      return nullptr;
  }
}

struct BitField {
  uint8_t* bits = nullptr;
  uint8_t mask = 0;
};

BitField flag_bit(Context& ctx, GLenum cap) {
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + rec::kMaxLights)
    return {&ctx.lighting.light_mask, static_cast<uint8_t>(1u << (cap - GL_LIGHT0))};
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + rec::kMaxClipPlanes)
    return {&ctx.transform.clip_plane_mask, static_cast<uint8_t>(1u << (cap - GL_CLIP_PLANE0))};
  TextureUnit& unit = ctx.textures.active_unit();
  switch (cap) {
    case GL_TEXTURE_1D:
      return {&unit.enabled_targets, kTarget1D};
    case GL_TEXTURE_2D:
      return {&unit.enabled_targets, kTarget2D};
    case GL_TEXTURE_3D:
      return {&unit.enabled_targets, kTarget3D};
    case GL_TEXTURE_CUBE_MAP:
      return {&unit.enabled_targets, kTargetCubeMap};
    case GL_TEXTURE_RECTANGLE_ARB:
      return {&unit.enabled_targets, kTargetRect};
    case GL_TEXTURE_GEN_S:
      return {&unit.texgen_mask, 1};
    case GL_TEXTURE_GEN_T:
      return {&unit.texgen_mask, 2};
    case GL_TEXTURE_GEN_R:
      return {&unit.texgen_mask, 4};
    case GL_TEXTURE_GEN_Q:
      return {&unit.texgen_mask, 8};
    default:
      return {};
  }
}

void set_cap(Context& ctx, GLenum cap, bool on) {
  // Client-state capabilities through glEnable: Mesa accepts them (as glEnableClientState).
  if (ClientArray* array = client_state_array(ctx.arrays, cap, ctx.textures.client_active)) {
    array->enabled = on;
    return;
  }
  if (bool* field = flag_field(ctx, cap)) {
    *field = on;
  } else if (BitField b = flag_bit(ctx, cap); b.bits != nullptr) {
    // Enabling a clip plane makes Mesa derive its clip-space equation, which analyses the
    // projection matrix (and so decides how later products with it are computed).
    const bool enabling_clip_plane =
        on && !(*b.bits & b.mask) && b.bits == &ctx.transform.clip_plane_mask;
    *b.bits = on ? (*b.bits | b.mask) : (*b.bits & ~b.mask);
    if (enabling_clip_plane) ctx.matrices.projection.top_matrix().analyse();
  } else if (!ctx.enables.set(cap, on)) {
    return record_error(ctx, GL_INVALID_ENUM);
  }
  // Enabling colour material applies the current colour at once (GL 1.5 2.14.3).
  if (cap == GL_COLOR_MATERIAL && on) apply_color_material(ctx);
}

}  // namespace

std::optional<bool> capability_enabled(Context& ctx, GLenum cap) {
  if (bool* field = flag_field(ctx, cap)) return *field;
  if (BitField b = flag_bit(ctx, cap); b.bits != nullptr) return (*b.bits & b.mask) != 0;
  if (const ClientArray* array = client_state_array(ctx.arrays, cap, ctx.textures.client_active))
    return array->enabled;
  return ctx.enables.get(cap);
}

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
  const auto v = capability_enabled(ctx, cap);
  if (!v) {
    record_error(ctx, GL_INVALID_ENUM);
    return 0;
  }
  return *v ? 1 : 0;
}

}  // namespace impl
}  // namespace glpt
