// Lets a header of pure functions compile as GLSL and as C++ (glm), so the tests integrate the
// very sampling and BSDF code the trace pass runs (tests/light_transport). Such headers use only
// what both languages share: glm's GLSL functions, `f`-suffixed float literals, structs, and no
// out/inout parameters.
#ifndef GLPT_SHADERS_TRACE_GLSL_CPP_H
#define GLPT_SHADERS_TRACE_GLSL_CPP_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#define GLPT_FN inline
#define GLPT_CONST inline constexpr
#else
#define GLPT_FN
#define GLPT_CONST const
#endif

#endif  // GLPT_SHADERS_TRACE_GLSL_CPP_H
