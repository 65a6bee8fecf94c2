// The attribute stacks. Where Mesa (25.0.7, checked with OSMesa) and GL 1.5 differ on what a pop
// restores, and the spec is clear, the spec is followed; where Mesa's behaviour comes from what
// it counts as a change to a group, it is reproduced:
//   - Mesa restores a group only if a command changed it since the push, and glMaterial and
//     GL_COLOR_MATERIAL's tracking do not count as changes to the lighting group. So popping
//     GL_LIGHTING_BIT restores the material only when some other lighting state changed too
//     (then all of it, the material included); otherwise the material keeps its current value.
//     glpt decides "changed" by comparing the group with the pushed copy, the material aside.
//   - Popping GL_CURRENT_BIT restores the current colour without re-applying colour material.
//   - Group restores that Mesa performs through its API functions keep their side effects: a clip
//     plane being enabled, or a changed transform group, analyses the projection matrix; a
//     changed lighting group analyses the modelview; GL_COLOR_MATERIAL being enabled applies the
//     current colour (before a restored lighting group overwrites the material).
//   - Mesa does not restore GL_FOG_COORD_SRC with GL_FOG_BIT, nor GL_COLOR_SUM with GL_FOG_BIT or
//     GL_ENABLE_BIT; GL 1.5 table 6.10 puts both in the fog group (and GL_COLOR_SUM in the enable
//     group), and glpt restores them.
#include "gl_shim/state/attrib_stack.hpp"

#include <algorithm>
#include <array>
#include <iterator>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

// Server capabilities of the enable group that are not per texture unit (GL 1.5 tables 6.5-6.27,
// "enable" in the attribute column), plus those glpt keeps for the imaging subset.
constexpr GLenum kEnableCaps[] = {
    GL_ALPHA_TEST,
    GL_AUTO_NORMAL,
    GL_BLEND,
    GL_CLIP_PLANE0,
    GL_CLIP_PLANE1,
    GL_CLIP_PLANE2,
    GL_CLIP_PLANE3,
    GL_CLIP_PLANE4,
    GL_CLIP_PLANE5,
    GL_COLOR_MATERIAL,
    GL_CULL_FACE,
    GL_DEPTH_TEST,
    GL_DITHER,
    GL_FOG,
    GL_LIGHT0,
    GL_LIGHT1,
    GL_LIGHT2,
    GL_LIGHT3,
    GL_LIGHT4,
    GL_LIGHT5,
    GL_LIGHT6,
    GL_LIGHT7,
    GL_LIGHTING,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_INDEX_LOGIC_OP,
    GL_COLOR_LOGIC_OP,
    GL_MAP1_COLOR_4,
    GL_MAP1_INDEX,
    GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4,
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
    GL_MAP2_COLOR_4,
    GL_MAP2_INDEX,
    GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1,
    GL_MAP2_TEXTURE_COORD_2,
    GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4,
    GL_NORMALIZE,
    GL_POINT_SMOOTH,
    GL_POINT_SPRITE,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE,
    GL_RESCALE_NORMAL,
    GL_SCISSOR_TEST,
    GL_STENCIL_TEST,
    GL_STENCIL_TEST_TWO_SIDE_EXT,
    GL_MULTISAMPLE,
    GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE,
    GL_SAMPLE_COVERAGE,
    GL_COLOR_SUM,
    GL_CONVOLUTION_1D,
    GL_CONVOLUTION_2D,
    GL_SEPARABLE_2D,
    GL_HISTOGRAM,
    GL_MINMAX,
    GL_COLOR_TABLE,
    GL_POST_CONVOLUTION_COLOR_TABLE,
    GL_POST_COLOR_MATRIX_COLOR_TABLE,
};
// Per texture unit: the targets and coordinate generation (tables 6.15, 6.17).
constexpr GLenum kUnitEnableCaps[] = {GL_TEXTURE_1D,
                                      GL_TEXTURE_2D,
                                      GL_TEXTURE_3D,
                                      GL_TEXTURE_CUBE_MAP,
                                      GL_TEXTURE_RECTANGLE_ARB,
                                      GL_TEXTURE_GEN_S,
                                      GL_TEXTURE_GEN_T,
                                      GL_TEXTURE_GEN_R,
                                      GL_TEXTURE_GEN_Q};
constexpr size_t kCapCount = std::size(kEnableCaps);
constexpr size_t kUnitCapCount = std::size(kUnitEnableCaps);

constexpr GLenum kEvalCaps[] = {
    GL_AUTO_NORMAL,          GL_MAP1_COLOR_4,         GL_MAP1_INDEX,
    GL_MAP1_NORMAL,          GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3, GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,        GL_MAP2_COLOR_4,         GL_MAP2_INDEX,
    GL_MAP2_NORMAL,          GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2,
    GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4, GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4};
// Capabilities of other groups that glpt keeps outside their group's blocks.
constexpr GLenum kColorBufferCaps[] = {GL_INDEX_LOGIC_OP};
constexpr GLenum kMultisampleCaps[] = {GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE,
                                       GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE};

}  // namespace

// The state a glPushAttrib saved: copies of the blocks its groups live in.
// A texture object's state of the texture group (GL 1.5 table 6.16: its parameters).
struct TextureParams {
  GLuint name = 0;
  rec::SamplerState sampler;
  bool generate_mipmap = false;
  float priority = 1.0f;
};

struct AttribFrame {
  GLbitfield mask = 0;
  CurrentAttributes current;
  rec::RasterPosition raster_position;  // GL_CURRENT_BIT includes it (GL 1.5 table 6.5)
  rec::RasterState raster;
  rec::LightingState lighting;
  TransformControls transform;
  GLenum matrix_mode = GL_MODELVIEW;
  FramebufferState framebuffer;
  rec::PixelTransferState pixel_transfer;
  ColorIndexState color_index;
  TextureUnits textures;
  // The objects bound to each unit's targets, and texture 0 of each target (Mesa saves these
  // separately: they are shared by every unit that has nothing bound).
  std::array<std::array<TextureParams, kSlotCount>, rec::kMaxTextureUnits> bound_textures;
  std::array<TextureParams, kSlotCount> default_textures;
  HintState hints;
  GLuint list_base = 0;
  EvaluatorGrid eval_grid;  // GL_EVAL_BIT (the maps themselves are in no group)
  std::array<bool, kCapCount> caps{};
  std::array<std::array<bool, kUnitCapCount>, rec::kMaxTextureUnits> unit_caps{};
};

struct ClientAttribFrame {
  GLbitfield mask = 0;
  PixelStoreModes pack, unpack;
  VertexArrays arrays;
  uint32_t client_active_texture = 0;
};

AttribStacks::AttribStacks() = default;
AttribStacks::~AttribStacks() = default;

namespace {

bool cap_enabled(Context& ctx, GLenum cap) { return capability_enabled(ctx, cap).value_or(false); }

void set_cap(Context& ctx, GLenum cap, bool on) {
  if (cap_enabled(ctx, cap) == on) return;
  if (on)
    impl::glEnable(ctx, cap);
  else
    impl::glDisable(ctx, cap);
}

TextureParams params_of(const TextureObject& t) {
  return {t.name(), t.sampler(), t.generate_mipmap, t.priority};
}

void apply_params(TextureObject& t, const TextureParams& p) {
  if (!(t.sampler() == p.sampler)) t.edit_sampler() = p.sampler;
  t.generate_mipmap = p.generate_mipmap;
  t.priority = p.priority;
}

void save_textures(const Context& ctx, AttribFrame& f) {
  const TextureUnits& t = ctx.textures;
  for (int s = 0; s < kSlotCount; ++s)
    f.default_textures[size_t(s)] = params_of(*t.store->defaults[size_t(s)]);
  for (size_t u = 0; u < t.units.size(); ++u)
    for (int s = 0; s < kSlotCount; ++s)
      f.bound_textures[u][size_t(s)] = params_of(t.bound(t.units[u], s));
}

void save_enables(Context& ctx, AttribFrame& f) {
  for (size_t i = 0; i < kCapCount; ++i) f.caps[i] = cap_enabled(ctx, kEnableCaps[i]);
  const uint32_t active = ctx.textures.active;
  for (uint32_t u = 0; u < rec::kMaxTextureUnits; ++u) {
    ctx.textures.active = u;
    for (size_t i = 0; i < kUnitCapCount; ++i)
      f.unit_caps[u][i] = cap_enabled(ctx, kUnitEnableCaps[i]);
  }
  ctx.textures.active = active;
}

// Restores the capabilities `caps` names from the frame, through glEnable/glDisable (Mesa's
// way: the side effects of enabling follow), only where they differ.
template <size_t N>
void restore_caps(Context& ctx, const AttribFrame& f, const GLenum (&caps)[N]) {
  for (GLenum cap : caps) {
    for (size_t i = 0; i < kCapCount; ++i)
      if (kEnableCaps[i] == cap) set_cap(ctx, cap, f.caps[i]);
  }
}

void restore_enables(Context& ctx, const AttribFrame& f) {
  for (size_t i = 0; i < kCapCount; ++i) set_cap(ctx, kEnableCaps[i], f.caps[i]);
  const uint32_t active = ctx.textures.active;
  for (uint32_t u = 0; u < rec::kMaxTextureUnits; ++u) {
    ctx.textures.active = u;
    for (size_t i = 0; i < kUnitCapCount; ++i) set_cap(ctx, kUnitEnableCaps[i], f.unit_caps[u][i]);
  }
  ctx.textures.active = active;
}

// The lighting group without the material (see the file comment).
bool lighting_changed(const Context& ctx, const AttribFrame& f) {
  rec::LightingState now = ctx.lighting;
  now.material = f.lighting.material;
  return !(now == f.lighting) || ctx.raster.primitive.shade_model != f.raster.primitive.shade_model;
}

bool transform_changed(const Context& ctx, const AttribFrame& f) {
  const TransformControls& t = ctx.transform;
  return ctx.matrices.mode != f.matrix_mode || t.normalize != f.transform.normalize ||
         t.rescale_normal != f.transform.rescale_normal ||
         t.clip_plane_mask != f.transform.clip_plane_mask ||
         t.clip_planes != f.transform.clip_planes;
}

void restore_color_buffer(Context& ctx, const AttribFrame& f) {
  rec::FragmentOpsState& o = ctx.raster.ops;
  const rec::FragmentOpsState& s = f.raster.ops;
  o.alpha_test = s.alpha_test;
  o.alpha_func = s.alpha_func;
  o.alpha_ref = s.alpha_ref;
  o.blend = s.blend;
  o.blend_src_rgb = s.blend_src_rgb;
  o.blend_dst_rgb = s.blend_dst_rgb;
  o.blend_src_alpha = s.blend_src_alpha;
  o.blend_dst_alpha = s.blend_dst_alpha;
  o.blend_equation_rgb = s.blend_equation_rgb;
  o.blend_equation_alpha = s.blend_equation_alpha;
  o.blend_color = s.blend_color;
  o.dither = s.dither;
  o.color_logic_op = s.color_logic_op;
  o.logic_op = s.logic_op;
  o.color_write = s.color_write;
  o.draw_buffer = s.draw_buffer;
  restore_caps(ctx, f, kColorBufferCaps);
  ctx.color_index.write_mask = f.color_index.write_mask;
  ctx.color_index.clear_index = f.color_index.clear_index;
  ctx.framebuffer.clear_color = f.framebuffer.clear_color;
}

void restore_depth_buffer(Context& ctx, const AttribFrame& f) {
  ctx.raster.ops.depth_test = f.raster.ops.depth_test;
  ctx.raster.ops.depth_func = f.raster.ops.depth_func;
  ctx.raster.ops.depth_write = f.raster.ops.depth_write;
  ctx.framebuffer.clear_depth = f.framebuffer.clear_depth;
}

void restore_stencil_buffer(Context& ctx, const AttribFrame& f) {
  rec::FragmentOpsState& o = ctx.raster.ops;
  const rec::FragmentOpsState& s = f.raster.ops;
  o.stencil_test = s.stencil_test;
  o.stencil_func = s.stencil_func;
  o.stencil_ref = s.stencil_ref;
  o.stencil_value_mask = s.stencil_value_mask;
  o.stencil_fail = s.stencil_fail;
  o.stencil_depth_fail = s.stencil_depth_fail;
  o.stencil_depth_pass = s.stencil_depth_pass;
  o.stencil_write_mask = s.stencil_write_mask;
  // EXT_stencil_two_side keeps its enable, the face selector and the back face in this group
  // too, as Mesa does.
  o.stencil_two_side = s.stencil_two_side;
  o.stencil_back_selected = s.stencil_back_selected;
  o.back_stencil = s.back_stencil;
  ctx.framebuffer.clear_stencil = f.framebuffer.clear_stencil;
}

void restore_fog(Context& ctx, const AttribFrame& f) {
  ctx.raster.fog = f.raster.fog;
  ctx.color_index.fog_index = f.color_index.fog_index;
  ctx.raster.ops.color_sum = f.raster.ops.color_sum;
}

void restore_lighting(Context& ctx, const AttribFrame& f, bool changed) {
  if (!changed) return;
  // Mesa analyses the modelview before restoring the lights.
  ctx.matrices.modelview.top_matrix().analyse();
  ctx.lighting = f.lighting;
  std::copy(&f.color_index.material_indexes[0][0], &f.color_index.material_indexes[0][0] + 6,
            &ctx.color_index.material_indexes[0][0]);
  ctx.raster.primitive.shade_model = f.raster.primitive.shade_model;
}

void restore_point(Context& ctx, const AttribFrame& f) {
  rec::PrimitiveState& p = ctx.raster.primitive;
  const rec::PrimitiveState& s = f.raster.primitive;
  p.point_size = s.point_size;
  p.point_smooth = s.point_smooth;
  p.point_size_min = s.point_size_min;
  p.point_size_max = s.point_size_max;
  p.point_fade_threshold = s.point_fade_threshold;
  p.point_distance_attenuation = s.point_distance_attenuation;
  p.point_sprite = s.point_sprite;
  p.point_coord_replace = s.point_coord_replace;
  p.point_sprite_coord_origin = s.point_sprite_coord_origin;
}

void restore_line(Context& ctx, const AttribFrame& f) {
  rec::PrimitiveState& p = ctx.raster.primitive;
  const rec::PrimitiveState& s = f.raster.primitive;
  p.line_width = s.line_width;
  p.line_smooth = s.line_smooth;
  p.line_stipple = s.line_stipple;
  p.line_stipple_factor = s.line_stipple_factor;
  p.line_stipple_pattern = s.line_stipple_pattern;
}

void restore_polygon(Context& ctx, const AttribFrame& f) {
  rec::PrimitiveState& p = ctx.raster.primitive;
  const rec::PrimitiveState& s = f.raster.primitive;
  p.cull_face = s.cull_face;
  p.cull_face_mode = s.cull_face_mode;
  p.front_face = s.front_face;
  p.polygon_mode_front = s.polygon_mode_front;
  p.polygon_mode_back = s.polygon_mode_back;
  p.offset_fill = s.offset_fill;
  p.offset_line = s.offset_line;
  p.offset_point = s.offset_point;
  p.offset_factor = s.offset_factor;
  p.offset_units = s.offset_units;
  p.polygon_smooth = s.polygon_smooth;
  p.polygon_stipple = s.polygon_stipple;
}

// Pixel transfer and zoom, and the read buffer (table 6.22; pixel maps are in no group).
void restore_pixel_mode(Context& ctx, const AttribFrame& f) {
  const std::shared_ptr<const rec::PixelMaps> maps = ctx.pixel_transfer.maps;
  ctx.pixel_transfer = f.pixel_transfer;
  ctx.pixel_transfer.maps = maps;
  ctx.raster.ops.read_buffer = f.raster.ops.read_buffer;
}

void restore_transform(Context& ctx, const AttribFrame& f, bool changed) {
  if (!changed) return;
  ctx.matrices.mode = f.matrix_mode;
  // Mesa analyses the projection here, and again (a no-op then) for each plane it enables.
  ctx.matrices.projection.top_matrix().analyse();
  ctx.transform = f.transform;
}

// As Mesa does it: the units' state, then each binding by name (a texture deleted meanwhile is
// bound again as a new object, as glBindTexture would), then the saved parameters into the
// objects now bound and into the default textures.
void restore_texture(Context& ctx, const AttribFrame& f) {
  TextureUnits& t = ctx.textures;
  for (size_t u = 0; u < t.units.size(); ++u) {
    const auto bound = t.units[u].bound;
    t.units[u] = f.textures.units[u];
    t.units[u].bound = bound;
  }
  for (uint32_t u = 0; u < t.units.size(); ++u) {
    t.active = u;
    for (int s = 0; s < kSlotCount; ++s) {
      const TextureParams& saved = f.bound_textures[u][size_t(s)];
      if (t.bound(t.units[u], s).name() != saved.name)
        impl::glBindTexture(ctx, slot_target(s), saved.name);
      TextureObject& now = t.bound(t.units[u], s);
      if (now.name() != 0 && now.name() == saved.name) apply_params(now, saved);
    }
  }
  for (int s = 0; s < kSlotCount; ++s)
    apply_params(*t.store->defaults[size_t(s)], f.default_textures[size_t(s)]);
  t.active = f.textures.active;
}

void restore_viewport(Context& ctx, const AttribFrame& f) {
  FramebufferState& fb = ctx.framebuffer;
  fb.viewport_x = f.framebuffer.viewport_x;
  fb.viewport_y = f.framebuffer.viewport_y;
  fb.viewport_width = f.framebuffer.viewport_width;
  fb.viewport_height = f.framebuffer.viewport_height;
  fb.depth_near = f.framebuffer.depth_near;
  fb.depth_far = f.framebuffer.depth_far;
}

void restore_multisample(Context& ctx, const AttribFrame& f) {
  restore_caps(ctx, f, kMultisampleCaps);
  ctx.framebuffer.sample_coverage_value = f.framebuffer.sample_coverage_value;
  ctx.framebuffer.sample_coverage_invert = f.framebuffer.sample_coverage_invert;
}

void restore_scissor(Context& ctx, const AttribFrame& f) {
  ctx.raster.ops.scissor_test = f.raster.ops.scissor_test;
  ctx.raster.ops.scissor_box = f.raster.ops.scissor_box;
}

}  // namespace

namespace impl {

void glPushAttrib(Context& ctx, GLbitfield mask) {
  auto& stack = ctx.attrib_stacks.server;
  if (stack.size() >= kMaxAttribStackDepth) return record_error(ctx, GL_STACK_OVERFLOW);
  auto f = std::make_unique<AttribFrame>();
  f->mask = mask;
  f->current = ctx.current;
  f->raster_position = ctx.raster_position;
  f->raster = ctx.raster;
  f->lighting = ctx.lighting;
  f->transform = ctx.transform;
  f->matrix_mode = ctx.matrices.mode;
  f->framebuffer = ctx.framebuffer;
  f->pixel_transfer = ctx.pixel_transfer;
  f->color_index = ctx.color_index;
  f->textures = ctx.textures;
  save_textures(ctx, *f);
  f->hints = ctx.hints;
  f->list_base = ctx.lists.list_base;
  f->eval_grid = ctx.evaluators.grid;
  save_enables(ctx, *f);
  stack.push_back(std::move(f));
}

// Groups are restored in Mesa's order (which decides the order of side effects).
void glPopAttrib(Context& ctx) {
  auto& stack = ctx.attrib_stacks.server;
  if (stack.empty()) return record_error(ctx, GL_STACK_UNDERFLOW);
  const std::unique_ptr<AttribFrame> frame = std::move(stack.back());
  stack.pop_back();
  const AttribFrame& f = *frame;
  const GLbitfield mask = f.mask;
  const bool lighting = (mask & GL_LIGHTING_BIT) && lighting_changed(ctx, f);
  const bool transform = (mask & GL_TRANSFORM_BIT) && transform_changed(ctx, f);
  if (mask & GL_ACCUM_BUFFER_BIT) ctx.framebuffer.clear_accum = f.framebuffer.clear_accum;
  if (mask & GL_COLOR_BUFFER_BIT) restore_color_buffer(ctx, f);
  if (mask & GL_CURRENT_BIT) {
    ctx.current = f.current;
    ctx.raster_position = f.raster_position;
  }
  if (mask & GL_DEPTH_BUFFER_BIT) restore_depth_buffer(ctx, f);
  if (mask & GL_ENABLE_BIT) restore_enables(ctx, f);
  if (mask & GL_EVAL_BIT) {
    restore_caps(ctx, f, kEvalCaps);
    ctx.evaluators.grid = f.eval_grid;
  }
  if (mask & GL_FOG_BIT) restore_fog(ctx, f);
  if (mask & GL_HINT_BIT) ctx.hints = f.hints;
  if (mask & GL_LIGHTING_BIT) restore_lighting(ctx, f, lighting);
  if (mask & GL_LINE_BIT) restore_line(ctx, f);
  if (mask & GL_LIST_BIT) ctx.lists.list_base = f.list_base;
  if (mask & GL_PIXEL_MODE_BIT) restore_pixel_mode(ctx, f);
  if (mask & GL_POINT_BIT) restore_point(ctx, f);
  if (mask & GL_POLYGON_BIT) restore_polygon(ctx, f);
  if (mask & GL_POLYGON_STIPPLE_BIT)
    ctx.raster.primitive.stipple_pattern = f.raster.primitive.stipple_pattern;
  if (mask & GL_SCISSOR_BIT) restore_scissor(ctx, f);
  if (mask & GL_STENCIL_BUFFER_BIT) restore_stencil_buffer(ctx, f);
  if (mask & GL_TRANSFORM_BIT) restore_transform(ctx, f, transform);
  if (mask & GL_TEXTURE_BIT) restore_texture(ctx, f);
  if (mask & GL_VIEWPORT_BIT) restore_viewport(ctx, f);
  if (mask & GL_MULTISAMPLE_BIT) restore_multisample(ctx, f);
}

void glPushClientAttrib(Context& ctx, GLbitfield mask) {
  auto& stack = ctx.attrib_stacks.client;
  if (stack.size() >= kMaxClientAttribStackDepth) return record_error(ctx, GL_STACK_OVERFLOW);
  auto f = std::make_unique<ClientAttribFrame>();
  f->mask = mask;
  f->pack = ctx.framebuffer.pack;
  f->unpack = ctx.framebuffer.unpack;
  // The pushed arrays hold their buffer objects: a buffer deleted meanwhile comes back with them
  // (its name is no longer a buffer for glIsBuffer).
  f->arrays = ctx.arrays;
  f->client_active_texture = ctx.textures.client_active;
  stack.push_back(std::move(f));
}

void glPopClientAttrib(Context& ctx) {
  auto& stack = ctx.attrib_stacks.client;
  if (stack.empty()) return record_error(ctx, GL_STACK_UNDERFLOW);
  const std::unique_ptr<ClientAttribFrame> f = std::move(stack.back());
  stack.pop_back();
  if (f->mask & GL_CLIENT_PIXEL_STORE_BIT) {
    ctx.framebuffer.pack = f->pack;
    ctx.framebuffer.unpack = f->unpack;
  }
  if (f->mask & GL_CLIENT_VERTEX_ARRAY_BIT) {
    ctx.arrays = std::move(f->arrays);
    ctx.textures.client_active = f->client_active_texture;
  }
}

}  // namespace impl
}  // namespace glpt

namespace glpt {

bool copy_attrib_groups(Context& src, Context& dst, GLbitfield mask) {
  auto& from = src.attrib_stacks.server;
  auto& to = dst.attrib_stacks.server;
  if (from.size() >= kMaxAttribStackDepth || to.size() >= kMaxAttribStackDepth) return false;
  impl::glPushAttrib(src, mask);
  to.push_back(std::move(from.back()));
  from.pop_back();
  impl::glPopAttrib(dst);
  return true;
}

}  // namespace glpt
