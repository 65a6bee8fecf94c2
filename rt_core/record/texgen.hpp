// GL's texture coordinate generation (GL 1.5 2.11.4) for one unit and one vertex, as Mesa computes
// it (compute_texgen in src/mesa/tnl/t_vb_texgen.c and its scalar twin): shared by the front
// end's CPU paths (raster position, feedback and selection) and by the tracer, which needs the
// coordinates of traced vertices where rays hit them.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "rt_core/record/gl_state.hpp"

namespace glpt::rec {

// The coordinates `tc` after generating those `mask` enables (bit c: coordinate c) with
// `texgen`'s modes: object- and eye-linear, sphere map (s and t), reflection and normal maps
// (s, t and r). `object`: the object-space vertex; `eye`: the eye-space vertex; `normal`: the
// eye-space normal (after GL_NORMALIZE or GL_RESCALE_NORMAL, as lighting uses it).
glm::vec4 generate_tex_coord(uint8_t mask, const std::array<TexGen, 4>& texgen,
                             const glm::vec4& object, const glm::vec4& eye, const glm::vec3& normal,
                             glm::vec4 tc);

}  // namespace glpt::rec
