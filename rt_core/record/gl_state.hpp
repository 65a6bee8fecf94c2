// The GL 1.5 state that decides a draw's pixels, grouped into immutable blocks.
//
// The GL front end (gl_shim) keeps the live state in these same structs; when a draw is recorded,
// every block that differs from the one the previous draw used is copied once into a new
// shared, immutable block (see frame_record.hpp, StateSnapshot). Consumers (raster pipelines, the
// path tracer's scene) read blocks and never see later state changes.
//
// Values are stored as GL defines them (GL enums as uint32_t, colours as floats, matrices
// column-major), already validated by the front end. Initial values are GL's (GL 1.5 spec,
// tables 6.5-6.32). Positions, directions and planes that GL transforms when they are specified
// (light positions, spot directions, eye planes, clip planes) are stored in eye space.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "gl/gl_enums.h"

namespace glpt::rec {

inline constexpr int kMaxLights = 8;
inline constexpr int kMaxTextureUnits = 4;
inline constexpr int kMaxClipPlanes = 6;

// ---- transform (GL 1.5 2.11, 2.12) ------------------------------------------------------------

struct TransformState {
  glm::mat4 modelview{1.0f};
  glm::mat4 projection{1.0f};
  // Derived as Mesa derives them (its matrix analysis decides how products and inverses are
  // computed, and pixel parity depends on the exact floats): projection * modelview, and the
  // inverse of the modelview (whose transpose transforms normals).
  glm::mat4 modelview_projection{1.0f};
  glm::mat4 modelview_inverse{1.0f};
  std::array<int32_t, 4> viewport{0, 0, 0, 0};          // x, y, width, height
  float depth_near = 0.0f, depth_far = 1.0f;            // glDepthRange, clamped to [0,1]
  bool normalize = false;                               // GL_NORMALIZE
  bool rescale_normal = false;                          // GL_RESCALE_NORMAL
  uint8_t clip_plane_mask = 0;                          // bit i: GL_CLIP_PLANEi enabled
  std::array<glm::vec4, kMaxClipPlanes> clip_planes{};  // eye space (transformed at glClipPlane)

  bool operator==(const TransformState&) const = default;
};

// ---- lighting (GL 1.5 2.14) -------------------------------------------------------------------

struct Light {
  glm::vec4 ambient{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 diffuse{0.0f, 0.0f, 0.0f, 1.0f};    // GL_LIGHT0: (1,1,1,1)
  glm::vec4 specular{0.0f, 0.0f, 0.0f, 1.0f};   // GL_LIGHT0: (1,1,1,1)
  glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f};   // eye space; w == 0: directional
  glm::vec3 spot_direction{0.0f, 0.0f, -1.0f};  // eye space
  float spot_exponent = 0.0f;
  float spot_cutoff = 180.0f;  // degrees; 180 = not a spot light
  float constant_attenuation = 1.0f;
  float linear_attenuation = 0.0f;
  float quadratic_attenuation = 0.0f;

  bool operator==(const Light&) const = default;
};

struct Material {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
  glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  glm::vec4 specular{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;

  bool operator==(const Material&) const = default;
};

struct LightingState {
  bool enabled = false;    // GL_LIGHTING
  uint8_t light_mask = 0;  // bit i: GL_LIGHTi enabled
  std::array<Light, kMaxLights> lights = default_lights();
  glm::vec4 model_ambient{0.2f, 0.2f, 0.2f, 1.0f};
  bool two_side = false;
  bool local_viewer = false;
  bool separate_specular = false;  // GL_LIGHT_MODEL_COLOR_CONTROL == GL_SEPARATE_SPECULAR_COLOR
  // [0] front, [1] back: the current material, with every colour GL_COLOR_MATERIAL wrote into it
  // already applied (GL 1.5 2.14.3: the tracked material value follows the current colour).
  std::array<Material, 2> material{};
  // While enabled, the tracked components take each vertex's colour (the raster pipelines and the
  // path tracer substitute the vertex colour, which is exactly what GL does per vertex).
  bool color_material = false;
  uint32_t color_material_face = GL_FRONT_AND_BACK;
  uint32_t color_material_mode = GL_AMBIENT_AND_DIFFUSE;

  bool operator==(const LightingState&) const = default;

  static std::array<Light, kMaxLights> default_lights() {
    std::array<Light, kMaxLights> lights{};
    lights[0].diffuse = glm::vec4(1.0f);
    lights[0].specular = glm::vec4(1.0f);
    return lights;
  }
};

// ---- texturing (GL 1.5 2.11.4 texgen, 3.8 textures, 3.8.13 texture environments) --------------

struct TextureObjectSnapshot;  // texture.hpp: an immutable texture (images + parameters)

struct TexGen {
  uint32_t mode = GL_EYE_LINEAR;
  glm::vec4 object_plane{0.0f};
  glm::vec4 eye_plane{0.0f};  // eye space (transformed by the inverse modelview when set)

  bool operator==(const TexGen&) const = default;
};

struct TexEnv {
  uint32_t mode = GL_MODULATE;
  glm::vec4 color{0.0f};
  // GL_COMBINE (GL 1.3 3.8.13, table 3.24)
  uint32_t combine_rgb = GL_MODULATE;
  uint32_t combine_alpha = GL_MODULATE;
  std::array<uint32_t, 3> source_rgb{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<uint32_t, 3> source_alpha{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<uint32_t, 3> operand_rgb{GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  std::array<uint32_t, 3> operand_alpha{GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgb_scale = 1.0f;
  float alpha_scale = 1.0f;
  float lod_bias = 0.0f;  // GL_TEXTURE_FILTER_CONTROL / GL_TEXTURE_LOD_BIAS (GL 1.4)

  bool operator==(const TexEnv&) const = default;
};

struct TextureUnitState {
  // The target GL samples on this unit: the highest-priority enabled target that has a complete
  // texture bound (cube map > 3D > 2D > 1D, GL 1.5 3.8.15), or 0 when texturing is off.
  uint32_t target = 0;
  // What is bound to `target` (null when target == 0). Keeps the texture's content alive and
  // unchanged for as long as the record refers to it.
  std::shared_ptr<const TextureObjectSnapshot> texture;
  TexEnv env;
  uint8_t texgen_mask = 0;                          // bits 0..3: GL_TEXTURE_GEN_S, T, R, Q enabled
  std::array<TexGen, 4> texgen = default_texgen();  // s, t, r, q
  glm::mat4 matrix{1.0f};                           // GL_TEXTURE matrix

  bool operator==(const TextureUnitState&) const = default;

  static std::array<TexGen, 4> default_texgen() {
    std::array<TexGen, 4> g{};
    g[0].object_plane = g[0].eye_plane = glm::vec4(1, 0, 0, 0);
    g[1].object_plane = g[1].eye_plane = glm::vec4(0, 1, 0, 0);
    return g;
  }
};

struct TexturingState {
  std::array<TextureUnitState, kMaxTextureUnits> units{};

  bool operator==(const TexturingState&) const = default;
};

// ---- rasterization, fog and per-fragment operations (GL 1.5 3.3-3.6, 3.10, 4.1, 4.2) ----------

struct PrimitiveState {
  uint32_t shade_model = GL_SMOOTH;
  bool cull_face = false;
  uint32_t cull_face_mode = GL_BACK;
  uint32_t front_face = GL_CCW;
  uint32_t polygon_mode_front = GL_FILL;
  uint32_t polygon_mode_back = GL_FILL;
  bool offset_fill = false, offset_line = false, offset_point = false;
  float offset_factor = 0.0f, offset_units = 0.0f;
  bool polygon_smooth = false;
  bool polygon_stipple = false;
  // Row r (bottom row first) of the 32x32 pattern; bit 31 - c is column c (glPolygonStipple as
  // unpacked with GL_UNPACK_LSB_FIRST false).
  std::array<uint32_t, 32> stipple_pattern = all_ones();
  float line_width = 1.0f;
  bool line_smooth = false;
  bool line_stipple = false;
  int32_t line_stipple_factor = 1;
  uint16_t line_stipple_pattern = 0xFFFF;
  float point_size = 1.0f;
  bool point_smooth = false;
  // GL 1.4 point parameters
  float point_size_min = 0.0f;
  float point_size_max = 1.0e30f;  // clamped to the implementation's range when used
  float point_fade_threshold = 1.0f;
  glm::vec3 point_distance_attenuation{1.0f, 0.0f, 0.0f};
  // ARB_point_sprite (GL 2.0 3.3.1): points drawn as textured squares. Bit u: unit u's texture
  // coordinates are replaced by the sprite's (glTexEnv(GL_POINT_SPRITE, GL_COORD_REPLACE)); like
  // Mesa this is point state (GL_POINT_BIT), not texture environment. GL_UPPER_LEFT or
  // GL_LOWER_LEFT: where t = 0 lies (GL 2.0's glPointParameter(GL_POINT_SPRITE_COORD_ORIGIN)).
  bool point_sprite = false;
  uint8_t point_coord_replace = 0;
  uint32_t point_sprite_coord_origin = GL_UPPER_LEFT;

  bool operator==(const PrimitiveState&) const = default;

  static std::array<uint32_t, 32> all_ones() {
    std::array<uint32_t, 32> p{};
    p.fill(0xFFFFFFFFu);
    return p;
  }
};

struct FogState {
  bool enabled = false;
  uint32_t mode = GL_EXP;
  float density = 1.0f, start = 0.0f, end = 1.0f;
  glm::vec4 color{0.0f};
  uint32_t coord_source = GL_FRAGMENT_DEPTH;  // or GL_FOG_COORDINATE

  bool operator==(const FogState&) const = default;
};

// One face's stencil test and operations (EXT_stencil_two_side's back face).
struct StencilFaceState {
  uint32_t func = GL_ALWAYS;
  int32_t ref = 0;
  uint32_t value_mask = 0xFFu;
  uint32_t fail = GL_KEEP, depth_fail = GL_KEEP, depth_pass = GL_KEEP;
  uint32_t write_mask = 0xFFu;

  bool operator==(const StencilFaceState&) const = default;
};

struct FragmentOpsState {
  bool color_sum = false;  // GL_COLOR_SUM: add the secondary colour while lighting is off
  bool scissor_test = false;
  std::array<int32_t, 4> scissor_box{0, 0, 0, 0};  // x, y, width, height
  bool alpha_test = false;
  uint32_t alpha_func = GL_ALWAYS;
  float alpha_ref = 0.0f;  // clamped to [0,1]
  bool stencil_test = false;
  uint32_t stencil_func = GL_ALWAYS;
  int32_t stencil_ref = 0;
  uint32_t stencil_value_mask = 0xFFFFFFFFu;
  uint32_t stencil_fail = GL_KEEP, stencil_depth_fail = GL_KEEP, stencil_depth_pass = GL_KEEP;
  uint32_t stencil_write_mask = 0xFFFFFFFFu;
  // EXT_stencil_two_side: while stencil_two_side is enabled, back-facing polygons are tested and
  // counted with back_stencil instead of the fields above. stencil_back_selected
  // (GL_ACTIVE_STENCIL_FACE_EXT is GL_BACK) only routes glStencilFunc/Op/Mask to back_stencil;
  // with GL_FRONT selected they set the fields above (Mesa's faces 0 and 2).
  bool stencil_two_side = false;
  bool stencil_back_selected = false;
  StencilFaceState back_stencil;
  bool depth_test = false;
  uint32_t depth_func = GL_LESS;
  bool depth_write = true;
  bool blend = false;
  uint32_t blend_src_rgb = GL_ONE, blend_dst_rgb = GL_ZERO;
  uint32_t blend_src_alpha = GL_ONE, blend_dst_alpha = GL_ZERO;
  uint32_t blend_equation_rgb = GL_FUNC_ADD, blend_equation_alpha = GL_FUNC_ADD;
  glm::vec4 blend_color{0.0f};
  bool color_logic_op = false;
  uint32_t logic_op = GL_COPY;
  std::array<bool, 4> color_write{true, true, true, true};
  bool dither = true;
  uint32_t draw_buffer = GL_BACK;  // resolved against the drawable when executed
  uint32_t read_buffer = GL_BACK;  // source of glCopyPixels and glAccum

  StencilFaceState front_stencil() const {
    return {stencil_func,       stencil_ref,        stencil_value_mask, stencil_fail,
            stencil_depth_fail, stencil_depth_pass, stencil_write_mask};
  }
  // The state back-facing polygons use.
  StencilFaceState back_face_stencil() const {
    return stencil_two_side ? back_stencil : front_stencil();
  }

  bool operator==(const FragmentOpsState&) const = default;
};

// Everything between the vertex stage and the framebuffer: one block because these change
// together rarely and are small.
struct RasterState {
  PrimitiveState primitive;
  FogState fog;
  FragmentOpsState ops;

  bool operator==(const RasterState&) const = default;
};

// ---- pixel transfer (GL 1.5 3.6.3, 3.6.5): glDrawPixels/glCopyPixels/glTexImage conversions ----

// glPixelMap tables (GL 1.5 3.6.3, table 3.3). Immutable once shared: glPixelMap makes a new one.
struct PixelMaps {
  // Indexed by map - GL_PIXEL_MAP_I_TO_I: I_TO_I, S_TO_S, I_TO_R, I_TO_G, I_TO_B, I_TO_A, R_TO_R,
  // G_TO_G, B_TO_B, A_TO_A. Every map has at least one entry (initially the single value 0).
  // Colour maps (x_TO_R/G/B/A) hold values in [0, 1]; index maps hold indices.
  static constexpr int kCount = 10;
  std::array<std::vector<float>, kCount> maps = initial_maps();

  bool operator==(const PixelMaps&) const = default;

  static std::array<std::vector<float>, kCount> initial_maps() {
    std::array<std::vector<float>, kCount> m;
    m.fill(std::vector<float>{0.0f});
    return m;
  }
  static const PixelMaps& initial() {
    static const PixelMaps maps;  // immutable
    return maps;
  }
};

struct PixelTransferState {
  bool map_color = false, map_stencil = false;
  int32_t index_shift = 0, index_offset = 0;
  glm::vec4 scale{1.0f}, bias{0.0f};  // RGBA
  float depth_scale = 1.0f, depth_bias = 0.0f;
  float zoom_x = 1.0f, zoom_y = 1.0f;     // glPixelZoom
  std::shared_ptr<const PixelMaps> maps;  // null: GL's initial maps

  const PixelMaps& pixel_maps() const { return maps ? *maps : PixelMaps::initial(); }
  bool operator==(const PixelTransferState&) const = default;
};

}  // namespace glpt::rec
