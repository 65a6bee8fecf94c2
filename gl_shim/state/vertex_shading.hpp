// The fixed-function per-vertex computations the front end does on the CPU, with Mesa's float
// arithmetic in Mesa's order of operations: lighting (GL 1.5 2.14.1), texture coordinate
// generation (2.11.4) and the viewport transform (2.11.1). Mesa computes the raster position
// this way in C (src/mesa/main/rastpos.c); glRasterPos (pixels/raster_position.cpp) and the
// feedback render mode (render_modes/primitive_pipeline.cpp) share it.
#pragma once

#include <glm/glm.hpp>

#include "rt_core/record/gl_state.hpp"
#include "rt_core/record/mesa_vector.hpp"

namespace glpt {

class Context;
struct TextureUnit;

// TRANSFORM_NORMAL: the row vector n times the upper 3x3 of m (with m the inverse modelview this
// is the inverse transpose applied to n).
glm::vec3 transform_normal(const glm::vec3& n, const glm::mat4& m);

// NORMALIZE_3FV (rt_core/record/mesa_vector.hpp).
using rec::normalize3;

// Mesa's ctx->_NeedEyeCoords: whether lighting and texture generation run in eye space (else
// lights are moved into object space, which Mesa does while the modelview preserves lengths).
// `texturing`: the units that are enabled (their texgen counts).
bool need_eye_coordinates(const Context& ctx, const rec::TexturingState& texturing);

struct LitColors {
  glm::vec4 color{0.0f};      // primary: ambient + diffuse (+ specular), alpha the diffuse's
  glm::vec4 secondary{0.0f};  // separate specular (GL_SEPARATE_SPECULAR_COLOR), alpha 1
};

// The lighting equation for one vertex with `material`, both colours clamped to [0, 1]. `eye`
// (need_eye_coordinates) says which space `vertex` and `normal` are in: eye space, or object
// space (lights are then moved into object space by the inverse modelview).
LitColors light_vertex(Context& ctx, const rec::Material& material, bool eye,
                       const glm::vec3& vertex, const glm::vec3& normal);

// compute_texgen: the coordinates of one unit after texture generation (only the coordinates
// whose generation is enabled change). `eye`: the eye-space vertex; `normal` the eye-space
// normal.
glm::vec4 generate_tex_coord(const TextureUnit& unit, const glm::vec4& object, const glm::vec4& eye,
                             const glm::vec3& normal, glm::vec4 tc);

// Mesa's _mesa_get_viewport_xform: window = ndc * scale + translate.
void viewport_transform(const Context& ctx, glm::vec3& scale, glm::vec3& translate);

}  // namespace glpt
