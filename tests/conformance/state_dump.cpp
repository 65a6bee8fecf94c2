#define GL_GLEXT_PROTOTYPES 1
#include "state_dump.hpp"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace glpt::conformance {
namespace {

struct Pname {
  GLenum pname;
  const char* name;
  int count;  // values returned
};

#define P(name, count) \
  Pname { name, #name, count }

// GL 1.5 tables 6.5-6.26 and 6.33: the state a glGet pname returns, except capabilities
// (kCapabilities), per-texture-unit state (kPerUnit*), client texture-coordinate arrays
// (kPerClientUnit*) and the implementation-dependent values (kImplementationPnames).
const Pname kStatePnames[] = {
    // 6.5 current values and associated data
    P(GL_CURRENT_COLOR, 4),
    P(GL_CURRENT_SECONDARY_COLOR, 4),
    P(GL_CURRENT_INDEX, 1),
    P(GL_CURRENT_NORMAL, 3),
    P(GL_CURRENT_FOG_COORDINATE, 1),
    P(GL_CURRENT_RASTER_POSITION, 4),
    P(GL_CURRENT_RASTER_DISTANCE, 1),
    P(GL_CURRENT_RASTER_COLOR, 4),
    P(GL_CURRENT_RASTER_INDEX, 1),
    P(GL_CURRENT_RASTER_POSITION_VALID, 1),
    P(GL_EDGE_FLAG, 1),
    // 6.6-6.8 vertex arrays
    P(GL_CLIENT_ACTIVE_TEXTURE, 1),
    P(GL_VERTEX_ARRAY_SIZE, 1),
    P(GL_VERTEX_ARRAY_TYPE, 1),
    P(GL_VERTEX_ARRAY_STRIDE, 1),
    P(GL_NORMAL_ARRAY_TYPE, 1),
    P(GL_NORMAL_ARRAY_STRIDE, 1),
    P(GL_FOG_COORDINATE_ARRAY_TYPE, 1),
    P(GL_FOG_COORDINATE_ARRAY_STRIDE, 1),
    P(GL_COLOR_ARRAY_SIZE, 1),
    P(GL_COLOR_ARRAY_TYPE, 1),
    P(GL_COLOR_ARRAY_STRIDE, 1),
    P(GL_SECONDARY_COLOR_ARRAY_SIZE, 1),
    P(GL_SECONDARY_COLOR_ARRAY_TYPE, 1),
    P(GL_SECONDARY_COLOR_ARRAY_STRIDE, 1),
    P(GL_INDEX_ARRAY_TYPE, 1),
    P(GL_INDEX_ARRAY_STRIDE, 1),
    P(GL_EDGE_FLAG_ARRAY_STRIDE, 1),
    P(GL_ARRAY_BUFFER_BINDING, 1),
    P(GL_VERTEX_ARRAY_BUFFER_BINDING, 1),
    P(GL_NORMAL_ARRAY_BUFFER_BINDING, 1),
    P(GL_COLOR_ARRAY_BUFFER_BINDING, 1),
    P(GL_INDEX_ARRAY_BUFFER_BINDING, 1),
    P(GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, 1),
    P(GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, 1),
    P(GL_FOG_COORDINATE_ARRAY_BUFFER_BINDING, 1),
    P(GL_ELEMENT_ARRAY_BUFFER_BINDING, 1),
    // 6.9-6.10 transformation state
    P(GL_MODELVIEW_MATRIX, 16),
    P(GL_PROJECTION_MATRIX, 16),
    P(GL_VIEWPORT, 4),
    P(GL_DEPTH_RANGE, 2),
    P(GL_MODELVIEW_STACK_DEPTH, 1),
    P(GL_PROJECTION_STACK_DEPTH, 1),
    P(GL_MATRIX_MODE, 1),
    // 6.11 coloring
    P(GL_FOG_COLOR, 4),
    P(GL_FOG_INDEX, 1),
    P(GL_FOG_DENSITY, 1),
    P(GL_FOG_START, 1),
    P(GL_FOG_END, 1),
    P(GL_FOG_MODE, 1),
    P(GL_FOG_COORDINATE_SOURCE, 1),
    P(GL_SHADE_MODEL, 1),
    // 6.12 lighting (the model; lights and materials are per-object queries below)
    P(GL_COLOR_MATERIAL_PARAMETER, 1),
    P(GL_COLOR_MATERIAL_FACE, 1),
    P(GL_LIGHT_MODEL_AMBIENT, 4),
    P(GL_LIGHT_MODEL_LOCAL_VIEWER, 1),
    P(GL_LIGHT_MODEL_TWO_SIDE, 1),
    P(GL_LIGHT_MODEL_COLOR_CONTROL, 1),
    // 6.14 rasterization
    P(GL_POINT_SIZE, 1),
    P(GL_POINT_SIZE_MIN, 1),
    P(GL_POINT_SIZE_MAX, 1),
    P(GL_POINT_FADE_THRESHOLD_SIZE, 1),
    P(GL_POINT_DISTANCE_ATTENUATION, 3),
    P(GL_POINT_SPRITE_COORD_ORIGIN, 1),
    P(GL_LINE_WIDTH, 1),
    P(GL_LINE_STIPPLE_PATTERN, 1),
    P(GL_LINE_STIPPLE_REPEAT, 1),
    P(GL_CULL_FACE_MODE, 1),
    P(GL_FRONT_FACE, 1),
    P(GL_POLYGON_MODE, 2),
    P(GL_POLYGON_OFFSET_FACTOR, 1),
    P(GL_POLYGON_OFFSET_UNITS, 1),
    // 6.15 multisampling
    P(GL_SAMPLE_COVERAGE_VALUE, 1),
    P(GL_SAMPLE_COVERAGE_INVERT, 1),
    // 6.18 texture environment (unit-independent part)
    P(GL_ACTIVE_TEXTURE, 1),
    // 6.19 pixel operations
    P(GL_SCISSOR_BOX, 4),
    P(GL_ALPHA_TEST_FUNC, 1),
    P(GL_ALPHA_TEST_REF, 1),
    P(GL_STENCIL_FUNC, 1),
    P(GL_STENCIL_VALUE_MASK, 1),
    P(GL_STENCIL_REF, 1),
    P(GL_STENCIL_FAIL, 1),
    P(GL_STENCIL_PASS_DEPTH_FAIL, 1),
    P(GL_STENCIL_PASS_DEPTH_PASS, 1),
    P(GL_ACTIVE_STENCIL_FACE_EXT, 1),  // EXT_stencil_two_side: the face the rows above show
    P(GL_DEPTH_FUNC, 1),
    P(GL_BLEND_SRC_RGB, 1),
    P(GL_BLEND_SRC_ALPHA, 1),
    P(GL_BLEND_DST_RGB, 1),
    P(GL_BLEND_DST_ALPHA, 1),
    P(GL_BLEND_EQUATION, 1),
    P(GL_BLEND_EQUATION_ALPHA_EXT, 1),
    P(GL_BLEND_COLOR, 4),
    P(GL_LOGIC_OP_MODE, 1),
    // 6.20 framebuffer control
    P(GL_DRAW_BUFFER, 1),
    P(GL_INDEX_WRITEMASK, 1),
    P(GL_COLOR_WRITEMASK, 4),
    P(GL_DEPTH_WRITEMASK, 1),
    P(GL_STENCIL_WRITEMASK, 1),
    P(GL_COLOR_CLEAR_VALUE, 4),
    P(GL_INDEX_CLEAR_VALUE, 1),
    P(GL_DEPTH_CLEAR_VALUE, 1),
    P(GL_STENCIL_CLEAR_VALUE, 1),
    P(GL_ACCUM_CLEAR_VALUE, 4),
    // 6.21 pixels
    P(GL_UNPACK_SWAP_BYTES, 1),
    P(GL_UNPACK_LSB_FIRST, 1),
    P(GL_UNPACK_IMAGE_HEIGHT, 1),
    P(GL_UNPACK_SKIP_IMAGES, 1),
    P(GL_UNPACK_ROW_LENGTH, 1),
    P(GL_UNPACK_SKIP_ROWS, 1),
    P(GL_UNPACK_SKIP_PIXELS, 1),
    P(GL_UNPACK_ALIGNMENT, 1),
    P(GL_PACK_SWAP_BYTES, 1),
    P(GL_PACK_LSB_FIRST, 1),
    P(GL_PACK_IMAGE_HEIGHT, 1),
    P(GL_PACK_SKIP_IMAGES, 1),
    P(GL_PACK_ROW_LENGTH, 1),
    P(GL_PACK_SKIP_ROWS, 1),
    P(GL_PACK_SKIP_PIXELS, 1),
    P(GL_PACK_ALIGNMENT, 1),
    P(GL_MAP_COLOR, 1),
    P(GL_MAP_STENCIL, 1),
    P(GL_INDEX_SHIFT, 1),
    P(GL_INDEX_OFFSET, 1),
    P(GL_RED_SCALE, 1),
    P(GL_GREEN_SCALE, 1),
    P(GL_BLUE_SCALE, 1),
    P(GL_ALPHA_SCALE, 1),
    P(GL_DEPTH_SCALE, 1),
    P(GL_RED_BIAS, 1),
    P(GL_GREEN_BIAS, 1),
    P(GL_BLUE_BIAS, 1),
    P(GL_ALPHA_BIAS, 1),
    P(GL_DEPTH_BIAS, 1),
    // 6.22-6.23 imaging subset (an implementation without ARB_imaging answers GL_INVALID_ENUM)
    P(GL_COLOR_TABLE, 1),
    P(GL_POST_CONVOLUTION_COLOR_TABLE, 1),
    P(GL_POST_COLOR_MATRIX_COLOR_TABLE, 1),
    P(GL_CONVOLUTION_1D, 1),
    P(GL_CONVOLUTION_2D, 1),
    P(GL_SEPARABLE_2D, 1),
    P(GL_POST_CONVOLUTION_RED_SCALE, 1),
    P(GL_POST_CONVOLUTION_GREEN_SCALE, 1),
    P(GL_POST_CONVOLUTION_BLUE_SCALE, 1),
    P(GL_POST_CONVOLUTION_ALPHA_SCALE, 1),
    P(GL_POST_CONVOLUTION_RED_BIAS, 1),
    P(GL_POST_CONVOLUTION_GREEN_BIAS, 1),
    P(GL_POST_CONVOLUTION_BLUE_BIAS, 1),
    P(GL_POST_CONVOLUTION_ALPHA_BIAS, 1),
    P(GL_COLOR_MATRIX, 16),
    P(GL_COLOR_MATRIX_STACK_DEPTH, 1),
    P(GL_POST_COLOR_MATRIX_RED_SCALE, 1),
    P(GL_POST_COLOR_MATRIX_GREEN_SCALE, 1),
    P(GL_POST_COLOR_MATRIX_BLUE_SCALE, 1),
    P(GL_POST_COLOR_MATRIX_ALPHA_SCALE, 1),
    P(GL_POST_COLOR_MATRIX_RED_BIAS, 1),
    P(GL_POST_COLOR_MATRIX_GREEN_BIAS, 1),
    P(GL_POST_COLOR_MATRIX_BLUE_BIAS, 1),
    P(GL_POST_COLOR_MATRIX_ALPHA_BIAS, 1),
    P(GL_HISTOGRAM, 1),
    P(GL_MINMAX, 1),
    // 6.24 pixels, continued
    P(GL_ZOOM_X, 1),
    P(GL_ZOOM_Y, 1),
    P(GL_PIXEL_MAP_I_TO_I_SIZE, 1),
    P(GL_PIXEL_MAP_S_TO_S_SIZE, 1),
    P(GL_PIXEL_MAP_I_TO_R_SIZE, 1),
    P(GL_PIXEL_MAP_I_TO_G_SIZE, 1),
    P(GL_PIXEL_MAP_I_TO_B_SIZE, 1),
    P(GL_PIXEL_MAP_I_TO_A_SIZE, 1),
    P(GL_PIXEL_MAP_R_TO_R_SIZE, 1),
    P(GL_PIXEL_MAP_G_TO_G_SIZE, 1),
    P(GL_PIXEL_MAP_B_TO_B_SIZE, 1),
    P(GL_PIXEL_MAP_A_TO_A_SIZE, 1),
    P(GL_READ_BUFFER, 1),
    // 6.25 evaluators
    P(GL_MAP1_GRID_DOMAIN, 2),
    P(GL_MAP2_GRID_DOMAIN, 4),
    P(GL_MAP1_GRID_SEGMENTS, 1),
    P(GL_MAP2_GRID_SEGMENTS, 2),
    // 6.26 hints
    P(GL_PERSPECTIVE_CORRECTION_HINT, 1),
    P(GL_POINT_SMOOTH_HINT, 1),
    P(GL_LINE_SMOOTH_HINT, 1),
    P(GL_POLYGON_SMOOTH_HINT, 1),
    P(GL_FOG_HINT, 1),
    P(GL_GENERATE_MIPMAP_HINT, 1),
    P(GL_TEXTURE_COMPRESSION_HINT, 1),
    // 6.33 miscellaneous
    P(GL_LIST_BASE, 1),
    P(GL_LIST_INDEX, 1),
    P(GL_LIST_MODE, 1),
    P(GL_ATTRIB_STACK_DEPTH, 1),
    P(GL_CLIENT_ATTRIB_STACK_DEPTH, 1),
    P(GL_NAME_STACK_DEPTH, 1),
    P(GL_RENDER_MODE, 1),
    P(GL_SELECTION_BUFFER_SIZE, 1),
    P(GL_FEEDBACK_BUFFER_SIZE, 1),
    P(GL_FEEDBACK_BUFFER_TYPE, 1),
};

// Table 6.5 and 6.16-6.18 state selected by GL_ACTIVE_TEXTURE.
const Pname kPerUnitPnames[] = {
    P(GL_CURRENT_TEXTURE_COORDS, 4), P(GL_CURRENT_RASTER_TEXTURE_COORDS, 4),
    P(GL_TEXTURE_MATRIX, 16),        P(GL_TEXTURE_STACK_DEPTH, 1),
    P(GL_TEXTURE_BINDING_1D, 1),     P(GL_TEXTURE_BINDING_2D, 1),
    P(GL_TEXTURE_BINDING_3D, 1),     P(GL_TEXTURE_BINDING_CUBE_MAP, 1),
};

// Capabilities selected by GL_ACTIVE_TEXTURE.
const Pname kPerUnitCapabilities[] = {
    P(GL_TEXTURE_1D, 1),       P(GL_TEXTURE_2D, 1),    P(GL_TEXTURE_3D, 1),
    P(GL_TEXTURE_CUBE_MAP, 1), P(GL_TEXTURE_GEN_S, 1), P(GL_TEXTURE_GEN_T, 1),
    P(GL_TEXTURE_GEN_R, 1),    P(GL_TEXTURE_GEN_Q, 1),
};

// Table 6.6: texture coordinate arrays, selected by GL_CLIENT_ACTIVE_TEXTURE.
const Pname kPerClientUnitCapabilities[] = {P(GL_TEXTURE_COORD_ARRAY, 1)};
const Pname kPerClientUnitPnames[] = {
    P(GL_TEXTURE_COORD_ARRAY_SIZE, 1),
    P(GL_TEXTURE_COORD_ARRAY_TYPE, 1),
    P(GL_TEXTURE_COORD_ARRAY_STRIDE, 1),
    P(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 1),
};

// Tables 6.27-6.32: implementation-dependent values and pixel depths. Dumped for information,
// not compared: glpt may legitimately choose other limits than Mesa.
const Pname kImplementationPnames[] = {
    P(GL_MAX_LIGHTS, 1),
    P(GL_MAX_CLIP_PLANES, 1),
    P(GL_MAX_COLOR_MATRIX_STACK_DEPTH, 1),
    P(GL_MAX_MODELVIEW_STACK_DEPTH, 1),
    P(GL_MAX_PROJECTION_STACK_DEPTH, 1),
    P(GL_MAX_TEXTURE_STACK_DEPTH, 1),
    P(GL_SUBPIXEL_BITS, 1),
    P(GL_MAX_3D_TEXTURE_SIZE, 1),
    P(GL_MAX_TEXTURE_SIZE, 1),
    P(GL_MAX_TEXTURE_LOD_BIAS, 1),
    P(GL_MAX_CUBE_MAP_TEXTURE_SIZE, 1),
    P(GL_MAX_PIXEL_MAP_TABLE, 1),
    P(GL_MAX_NAME_STACK_DEPTH, 1),
    P(GL_MAX_LIST_NESTING, 1),
    P(GL_MAX_EVAL_ORDER, 1),
    P(GL_MAX_VIEWPORT_DIMS, 2),
    P(GL_MAX_ATTRIB_STACK_DEPTH, 1),
    P(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 1),
    P(GL_AUX_BUFFERS, 1),
    P(GL_RGBA_MODE, 1),
    P(GL_INDEX_MODE, 1),
    P(GL_DOUBLEBUFFER, 1),
    P(GL_STEREO, 1),
    P(GL_ALIASED_POINT_SIZE_RANGE, 2),
    P(GL_SMOOTH_POINT_SIZE_RANGE, 2),
    P(GL_SMOOTH_POINT_SIZE_GRANULARITY, 1),
    P(GL_ALIASED_LINE_WIDTH_RANGE, 2),
    P(GL_SMOOTH_LINE_WIDTH_RANGE, 2),
    P(GL_SMOOTH_LINE_WIDTH_GRANULARITY, 1),
    P(GL_MAX_ELEMENTS_INDICES, 1),
    P(GL_MAX_ELEMENTS_VERTICES, 1),
    P(GL_MAX_TEXTURE_UNITS, 1),
    P(GL_SAMPLE_BUFFERS, 1),
    P(GL_SAMPLES, 1),
    P(GL_NUM_COMPRESSED_TEXTURE_FORMATS, 1),
    P(GL_RED_BITS, 1),
    P(GL_GREEN_BITS, 1),
    P(GL_BLUE_BITS, 1),
    P(GL_ALPHA_BITS, 1),
    P(GL_INDEX_BITS, 1),
    P(GL_DEPTH_BITS, 1),
    P(GL_STENCIL_BITS, 1),
    P(GL_ACCUM_RED_BITS, 1),
    P(GL_ACCUM_GREEN_BITS, 1),
    P(GL_ACCUM_BLUE_BITS, 1),
    P(GL_ACCUM_ALPHA_BITS, 1),
};

// Capabilities (the glEnable/glIsEnabled rows of GL 1.5 tables 6.6-6.25), dumped through
// glIsEnabled and the glGet functions; the per-unit ones are above.
const Pname kCapabilities[] = {
    P(GL_VERTEX_ARRAY, 1),
    P(GL_NORMAL_ARRAY, 1),
    P(GL_FOG_COORDINATE_ARRAY, 1),
    P(GL_COLOR_ARRAY, 1),
    P(GL_SECONDARY_COLOR_ARRAY, 1),
    P(GL_INDEX_ARRAY, 1),
    P(GL_EDGE_FLAG_ARRAY, 1),
    P(GL_NORMALIZE, 1),
    P(GL_RESCALE_NORMAL, 1),
    P(GL_CLIP_PLANE0, 1),
    P(GL_CLIP_PLANE1, 1),
    P(GL_CLIP_PLANE2, 1),
    P(GL_CLIP_PLANE3, 1),
    P(GL_CLIP_PLANE4, 1),
    P(GL_CLIP_PLANE5, 1),
    P(GL_FOG, 1),
    P(GL_COLOR_SUM, 1),
    P(GL_LIGHTING, 1),
    P(GL_COLOR_MATERIAL, 1),
    P(GL_LIGHT0, 1),
    P(GL_LIGHT1, 1),
    P(GL_LIGHT2, 1),
    P(GL_LIGHT3, 1),
    P(GL_LIGHT4, 1),
    P(GL_LIGHT5, 1),
    P(GL_LIGHT6, 1),
    P(GL_LIGHT7, 1),
    P(GL_POINT_SMOOTH, 1),
    P(GL_POINT_SPRITE, 1),
    P(GL_LINE_SMOOTH, 1),
    P(GL_LINE_STIPPLE, 1),
    P(GL_CULL_FACE, 1),
    P(GL_POLYGON_SMOOTH, 1),
    P(GL_POLYGON_OFFSET_POINT, 1),
    P(GL_POLYGON_OFFSET_LINE, 1),
    P(GL_POLYGON_OFFSET_FILL, 1),
    P(GL_POLYGON_STIPPLE, 1),
    P(GL_MULTISAMPLE, 1),
    P(GL_SAMPLE_ALPHA_TO_COVERAGE, 1),
    P(GL_SAMPLE_ALPHA_TO_ONE, 1),
    P(GL_SAMPLE_COVERAGE, 1),
    P(GL_SCISSOR_TEST, 1),
    P(GL_ALPHA_TEST, 1),
    P(GL_STENCIL_TEST, 1),
    P(GL_STENCIL_TEST_TWO_SIDE_EXT, 1),
    P(GL_DEPTH_TEST, 1),
    P(GL_BLEND, 1),
    P(GL_DITHER, 1),
    P(GL_INDEX_LOGIC_OP, 1),
    P(GL_COLOR_LOGIC_OP, 1),
    P(GL_MAP1_VERTEX_3, 1),
    P(GL_MAP1_VERTEX_4, 1),
    P(GL_MAP1_INDEX, 1),
    P(GL_MAP1_COLOR_4, 1),
    P(GL_MAP1_NORMAL, 1),
    P(GL_MAP1_TEXTURE_COORD_1, 1),
    P(GL_MAP1_TEXTURE_COORD_2, 1),
    P(GL_MAP1_TEXTURE_COORD_3, 1),
    P(GL_MAP1_TEXTURE_COORD_4, 1),
    P(GL_MAP2_VERTEX_3, 1),
    P(GL_MAP2_VERTEX_4, 1),
    P(GL_MAP2_INDEX, 1),
    P(GL_MAP2_COLOR_4, 1),
    P(GL_MAP2_NORMAL, 1),
    P(GL_MAP2_TEXTURE_COORD_1, 1),
    P(GL_MAP2_TEXTURE_COORD_2, 1),
    P(GL_MAP2_TEXTURE_COORD_3, 1),
    P(GL_MAP2_TEXTURE_COORD_4, 1),
    P(GL_AUTO_NORMAL, 1),
};

const Pname kLightParams[] = {
    P(GL_AMBIENT, 4),
    P(GL_DIFFUSE, 4),
    P(GL_SPECULAR, 4),
    P(GL_POSITION, 4),
    P(GL_SPOT_DIRECTION, 3),
    P(GL_SPOT_EXPONENT, 1),
    P(GL_SPOT_CUTOFF, 1),
    P(GL_CONSTANT_ATTENUATION, 1),
    P(GL_LINEAR_ATTENUATION, 1),
    P(GL_QUADRATIC_ATTENUATION, 1),
};

const Pname kMaterialParams[] = {
    P(GL_AMBIENT, 4),  P(GL_DIFFUSE, 4),   P(GL_SPECULAR, 4),
    P(GL_EMISSION, 4), P(GL_SHININESS, 1), P(GL_COLOR_INDEXES, 3),
};

const Pname kTexEnvParams[] = {
    P(GL_TEXTURE_ENV_MODE, 1), P(GL_TEXTURE_ENV_COLOR, 4), P(GL_COMBINE_RGB, 1),
    P(GL_COMBINE_ALPHA, 1),    P(GL_SOURCE0_RGB, 1),       P(GL_SOURCE1_RGB, 1),
    P(GL_SOURCE2_RGB, 1),      P(GL_SOURCE0_ALPHA, 1),     P(GL_SOURCE1_ALPHA, 1),
    P(GL_SOURCE2_ALPHA, 1),    P(GL_OPERAND0_RGB, 1),      P(GL_OPERAND1_RGB, 1),
    P(GL_OPERAND2_RGB, 1),     P(GL_OPERAND0_ALPHA, 1),    P(GL_OPERAND1_ALPHA, 1),
    P(GL_OPERAND2_ALPHA, 1),   P(GL_RGB_SCALE, 1),         P(GL_ALPHA_SCALE, 1),
};

const Pname kTexGenParams[] = {
    P(GL_TEXTURE_GEN_MODE, 1),
    P(GL_OBJECT_PLANE, 4),
    P(GL_EYE_PLANE, 4),
};

const Pname kTexGenCoords[] = {P(GL_S, 0), P(GL_T, 0), P(GL_R, 0), P(GL_Q, 0)};

const Pname kTexParams[] = {
    P(GL_TEXTURE_MIN_FILTER, 1),   P(GL_TEXTURE_MAG_FILTER, 1), P(GL_TEXTURE_WRAP_S, 1),
    P(GL_TEXTURE_WRAP_T, 1),       P(GL_TEXTURE_WRAP_R, 1),     P(GL_TEXTURE_BORDER_COLOR, 4),
    P(GL_TEXTURE_PRIORITY, 1),     P(GL_TEXTURE_RESIDENT, 1),   P(GL_TEXTURE_MIN_LOD, 1),
    P(GL_TEXTURE_MAX_LOD, 1),      P(GL_TEXTURE_BASE_LEVEL, 1), P(GL_TEXTURE_MAX_LEVEL, 1),
    P(GL_TEXTURE_LOD_BIAS, 1),     P(GL_DEPTH_TEXTURE_MODE, 1), P(GL_TEXTURE_COMPARE_MODE, 1),
    P(GL_TEXTURE_COMPARE_FUNC, 1), P(GL_GENERATE_MIPMAP, 1),
};

const Pname kTexLevelParams[] = {
    P(GL_TEXTURE_WIDTH, 1),          P(GL_TEXTURE_HEIGHT, 1),          P(GL_TEXTURE_DEPTH, 1),
    P(GL_TEXTURE_BORDER, 1),         P(GL_TEXTURE_INTERNAL_FORMAT, 1), P(GL_TEXTURE_RED_SIZE, 1),
    P(GL_TEXTURE_GREEN_SIZE, 1),     P(GL_TEXTURE_BLUE_SIZE, 1),       P(GL_TEXTURE_ALPHA_SIZE, 1),
    P(GL_TEXTURE_LUMINANCE_SIZE, 1), P(GL_TEXTURE_INTENSITY_SIZE, 1),  P(GL_TEXTURE_DEPTH_SIZE, 1),
    P(GL_TEXTURE_COMPRESSED, 1),
};

// Texture targets and the target their level 0 is queried through.
const Pname kTexTargets[] = {P(GL_TEXTURE_1D, 0), P(GL_TEXTURE_2D, 0), P(GL_TEXTURE_3D, 0),
                             P(GL_TEXTURE_CUBE_MAP, 0)};

#undef P

constexpr int kLights = 8;              // GL 1.5 minimum of GL_MAX_LIGHTS
constexpr int kClipPlanes = 6;          // GL 1.5 minimum of GL_MAX_CLIP_PLANES
constexpr int kTextureUnitsDumped = 4;  // units beyond an implementation's count read as errors

// Builds the JSON text. Keys are the query as written in C ("glGetFloatv(GL_FOG_COLOR)"),
// prefixed with the texture unit for per-unit state ("unit1 glGetFloatv(GL_TEXTURE_MATRIX)").
class JsonObject {
 public:
  void add_raw(const std::string& key, const std::string& value) {
    text_ += text_.empty() ? "\n    " : ",\n    ";
    text_ += quote(key) + ": " + value;
  }
  std::string text() const { return "{" + text_ + "\n  }"; }

  static std::string quote(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
      if (c == '"' || c == '\\') out += '\\';
      out += c;
    }
    return out + "\"";
  }

 private:
  std::string text_;
};

std::string format_float(double v) {
  if (std::isnan(v)) return "\"nan\"";
  if (std::isinf(v)) return v > 0 ? "\"inf\"" : "\"-inf\"";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

template <typename T, typename Format>
std::string json_array(const std::vector<T>& values, Format format) {
  std::string out = "[";
  for (size_t i = 0; i < values.size(); ++i) {
    if (i) out += ", ";
    out += format(values[i]);
  }
  return out + "]";
}

// Runs `query` (which fills `count` values of T into the vector it is given) and records the
// values, or the error it raised. Buffers are over-allocated and pre-filled with a sentinel so
// that an implementation writing more values than the table says cannot corrupt memory.
template <typename T, typename Query, typename Format>
void record(JsonObject& out, const std::string& key, int count, Query query, Format format) {
  std::vector<T> values(static_cast<size_t>(count) + 16, T(0));
  query(values.data());
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    out.add_raw(key, JsonObject::quote(gl_error_name(error)));
    return;
  }
  values.resize(static_cast<size_t>(count));
  out.add_raw(key, json_array(values, format));
}

std::string format_bool(GLboolean b) { return b ? "true" : "false"; }
std::string format_int(GLint i) { return std::to_string(i); }

std::string call(const char* fn, const char* arg) { return std::string(fn) + "(" + arg + ")"; }
std::string call(const char* fn, const char* a, const char* b) {
  return std::string(fn) + "(" + a + ", " + b + ")";
}

// glGetBooleanv, glGetIntegerv and glGetFloatv of each pname.
void dump_pnames(JsonObject& out, const Pname* begin, const Pname* end, const std::string& prefix) {
  for (const Pname* p = begin; p != end; ++p) {
    const GLenum pname = p->pname;
    record<GLboolean>(
        out, prefix + call("glGetBooleanv", p->name), p->count,
        [&](GLboolean* v) { glGetBooleanv(pname, v); }, format_bool);
    record<GLint>(
        out, prefix + call("glGetIntegerv", p->name), p->count,
        [&](GLint* v) { glGetIntegerv(pname, v); }, format_int);
    record<GLfloat>(
        out, prefix + call("glGetFloatv", p->name), p->count,
        [&](GLfloat* v) { glGetFloatv(pname, v); }, format_float);
  }
}

// A two-argument query through its float and integer variants, e.g. glGetLightfv and
// glGetLightiv of (GL_LIGHT0, GL_POSITION): `b.count` values each.
void record_fv_iv(JsonObject& out, const std::string& prefix, const std::string& function,
                  const Pname& a, const Pname& b, void (*fv)(GLenum, GLenum, GLfloat*),
                  void (*iv)(GLenum, GLenum, GLint*)) {
  record<GLfloat>(
      out, prefix + call((function + "fv").c_str(), a.name, b.name), b.count,
      [&](GLfloat* v) { fv(a.pname, b.pname, v); }, format_float);
  record<GLint>(
      out, prefix + call((function + "iv").c_str(), a.name, b.name), b.count,
      [&](GLint* v) { iv(a.pname, b.pname, v); }, format_int);
}

// glIsEnabled of each capability, and the glGet functions too (GL 1.5 6.1.1: a capability is
// also a glGet pname).
void dump_capabilities(JsonObject& out, const Pname* begin, const Pname* end,
                       const std::string& prefix) {
  dump_pnames(out, begin, end, prefix);
  for (const Pname* p = begin; p != end; ++p) {
    const GLenum cap = p->pname;
    record<GLboolean>(
        out, prefix + call("glIsEnabled", p->name), 1,
        [&](GLboolean* v) { v[0] = glIsEnabled(cap); }, format_bool);
  }
}

void dump_lights(JsonObject& out) {
  static const char* const kNames[kLights] = {"GL_LIGHT0", "GL_LIGHT1", "GL_LIGHT2", "GL_LIGHT3",
                                              "GL_LIGHT4", "GL_LIGHT5", "GL_LIGHT6", "GL_LIGHT7"};
  for (int i = 0; i < kLights; ++i) {
    const GLenum light = static_cast<GLenum>(GL_LIGHT0 + i);
    for (const Pname& p : kLightParams) {
      record_fv_iv(out, "", "glGetLight", Pname{light, kNames[i], 0}, p, glGetLightfv,
                   glGetLightiv);
    }
  }
}

void dump_materials(JsonObject& out) {
  const Pname faces[] = {{GL_FRONT, "GL_FRONT", 0}, {GL_BACK, "GL_BACK", 0}};
  for (const Pname& face : faces) {
    for (const Pname& p : kMaterialParams) {
      record_fv_iv(out, "", "glGetMaterial", face, p, glGetMaterialfv, glGetMaterialiv);
    }
  }
}

void dump_clip_planes(JsonObject& out) {
  static const char* const kNames[kClipPlanes] = {"GL_CLIP_PLANE0", "GL_CLIP_PLANE1",
                                                  "GL_CLIP_PLANE2", "GL_CLIP_PLANE3",
                                                  "GL_CLIP_PLANE4", "GL_CLIP_PLANE5"};
  for (int i = 0; i < kClipPlanes; ++i) {
    const GLenum plane = static_cast<GLenum>(GL_CLIP_PLANE0 + i);
    record<GLdouble>(
        out, call("glGetClipPlane", kNames[i]), 4, [&](GLdouble* v) { glGetClipPlane(plane, v); },
        format_float);
  }
}

// The polygon stipple is returned through the pack pixel-store state: read it with the default
// packing (saved and restored around the query) so that a scene's own pack settings cannot make
// it write beyond the 128 bytes.
void dump_polygon_stipple(JsonObject& out) {
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  const bool pushed = glGetError() == GL_NO_ERROR;
  if (pushed) {
    set_default_pack_state();
  }
  std::vector<GLubyte> pattern(128 + 4096, 0);
  glGetPolygonStipple(pattern.data());
  const GLenum error = glGetError();
  if (pushed) glPopClientAttrib();
  glGetError();  // a failed pop is not part of the scene's state
  if (error != GL_NO_ERROR) {
    out.add_raw("glGetPolygonStipple", JsonObject::quote(gl_error_name(error)));
    return;
  }
  std::vector<GLint> values(pattern.begin(), pattern.begin() + 128);
  out.add_raw("glGetPolygonStipple", json_array(values, format_int));
}

// State of texture unit `unit` (already made active): per-unit pnames, environment, coordinate
// generation, and the parameters and level 0 of the texture bound to each target.
void dump_texture_unit(JsonObject& out, const std::string& prefix) {
  dump_pnames(out, std::begin(kPerUnitPnames), std::end(kPerUnitPnames), prefix);
  dump_capabilities(out, std::begin(kPerUnitCapabilities), std::end(kPerUnitCapabilities), prefix);
  const Pname env{GL_TEXTURE_ENV, "GL_TEXTURE_ENV", 0};
  for (const Pname& p : kTexEnvParams) {
    record_fv_iv(out, prefix, "glGetTexEnv", env, p, glGetTexEnvfv, glGetTexEnviv);
  }
  const Pname sprite{GL_POINT_SPRITE, "GL_POINT_SPRITE", 0};
  const Pname coord_replace{GL_COORD_REPLACE, "GL_COORD_REPLACE", 1};
  record_fv_iv(out, prefix, "glGetTexEnv", sprite, coord_replace, glGetTexEnvfv, glGetTexEnviv);
  record<GLfloat>(
      out, prefix + call("glGetTexEnvfv", "GL_TEXTURE_FILTER_CONTROL", "GL_TEXTURE_LOD_BIAS"), 1,
      [&](GLfloat* v) { glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, v); },
      format_float);
  for (const Pname& coord : kTexGenCoords) {
    for (const Pname& p : kTexGenParams) {
      record_fv_iv(out, prefix, "glGetTexGen", coord, p, glGetTexGenfv, glGetTexGeniv);
    }
  }
  for (const Pname& target : kTexTargets) {
    for (const Pname& p : kTexParams) {
      record_fv_iv(out, prefix, "glGetTexParameter", target, p, glGetTexParameterfv,
                   glGetTexParameteriv);
    }
    // A cube map's levels are queried per face; +X stands for the six.
    const bool cube = target.pname == GL_TEXTURE_CUBE_MAP;
    const GLenum level_target = cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X : target.pname;
    const char* level_name = cube ? "GL_TEXTURE_CUBE_MAP_POSITIVE_X" : target.name;
    for (const Pname& p : kTexLevelParams) {
      record<GLint>(
          out, prefix + "glGetTexLevelParameteriv(" + level_name + ", 0, " + p.name + ")", p.count,
          [&](GLint* v) { glGetTexLevelParameteriv(level_target, 0, p.pname, v); }, format_int);
    }
  }
}

void dump_texture_units(JsonObject& out) {
  GLint active = GL_TEXTURE0, client_active = GL_TEXTURE0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &client_active);
  glGetError();  // the plain pnames above already recorded any error of these two
  for (int unit = 0; unit < kTextureUnitsDumped; ++unit) {
    const std::string prefix = "unit" + std::to_string(unit) + " ";
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
      out.add_raw(prefix + "glActiveTexture", JsonObject::quote(gl_error_name(error)));
    } else {
      dump_texture_unit(out, prefix);
    }
    glClientActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    error = glGetError();
    if (error != GL_NO_ERROR) {
      out.add_raw(prefix + "glClientActiveTexture", JsonObject::quote(gl_error_name(error)));
    } else {
      dump_pnames(out, std::begin(kPerClientUnitPnames), std::end(kPerClientUnitPnames), prefix);
      dump_capabilities(out, std::begin(kPerClientUnitCapabilities),
                        std::end(kPerClientUnitCapabilities), prefix);
    }
  }
  glActiveTexture(static_cast<GLenum>(active));
  glClientActiveTexture(static_cast<GLenum>(client_active));
  glGetError();
}

}  // namespace

void set_default_pack_state() {
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

std::string gl_error_name(unsigned error) {
  switch (error) {
    case GL_NO_ERROR:
      return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW:
      return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW:
      return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_TABLE_TOO_LARGE:
      return "GL_TABLE_TOO_LARGE";
    default: {
      char buf[16];
      std::snprintf(buf, sizeof buf, "0x%04x", error);
      return buf;
    }
  }
}

std::string dump_gl_state(const std::string& scene, const std::string& backend,
                          unsigned error_after_scene) {
  JsonObject state, implementation;
  dump_pnames(state, std::begin(kStatePnames), std::end(kStatePnames), "");
  dump_capabilities(state, std::begin(kCapabilities), std::end(kCapabilities), "");
  dump_lights(state);
  dump_materials(state);
  dump_clip_planes(state);
  dump_polygon_stipple(state);
  dump_texture_units(state);
  dump_pnames(implementation, std::begin(kImplementationPnames), std::end(kImplementationPnames),
              "");
  return "{\n  \"scene\": " + JsonObject::quote(scene) +
         ",\n  \"backend\": " + JsonObject::quote(backend) +
         ",\n  \"error_after_scene\": " + JsonObject::quote(gl_error_name(error_after_scene)) +
         ",\n  \"state\": " + state.text() + ",\n  \"implementation\": " + implementation.text() +
         "\n}\n";
}

}  // namespace glpt::conformance
