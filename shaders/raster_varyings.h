// The varyings from raster_ff.vert to raster_ff.frag (and through the geometry shaders).
//
// Lavapipe compiles each stage on its own, with no varying linking: an output that is declared
// is stored for every vertex, carried through clipping and primitive setup and interpolated for
// every fragment even where the specialization constants leave it unread. That doubled the cost
// of small triangles against Mesa's fixed-function shaders, which declare only what they use. So
// the shaders are built in variants: GLPT_VARYINGS (GLPT_VARYING_* bits, raster_types.h) names the
// varyings declared as interface variables; the others are private globals that the variant's
// pipelines never read (RasterPipelines picks a variant whose bits cover the key's needs). The
// front colour and the state index (raster_types.h GLPT_RASTER_VARYING_STATE) are always
// declared. The including shader defines GLPT_VARYING_OUT (out or in) and
// GLPT_COLOR_VARYING_OUT (with its colour interpolation qualifier).
#ifndef GLPT_VARYINGS
#define GLPT_VARYINGS GLPT_VARYINGS_ALL
#endif

layout(location = 0) GLPT_COLOR_VARYING_OUT vec4 v_front_color;
#if defined(GLPT_VARYINGS_INTO_FRAGMENT) && GLPT_GBUFFER  // after raster_gbuffer.geom
layout(location = GLPT_GBUFFER_VARYING_STATE) flat GLPT_VARYING_OUT uint v_state;
#else
layout(location = GLPT_RASTER_VARYING_STATE) flat GLPT_VARYING_OUT uint v_state;
#endif
#if (GLPT_VARYINGS & GLPT_VARYING_BACK) != 0
layout(location = 1) GLPT_COLOR_VARYING_OUT vec4 v_back_color;
#else
vec4 v_back_color;
#endif
#if (GLPT_VARYINGS & GLPT_VARYING_SECONDARY) != 0
layout(location = 2) GLPT_COLOR_VARYING_OUT vec4 v_front_secondary;
#else
vec4 v_front_secondary;
#endif
#if (GLPT_VARYINGS & (GLPT_VARYING_BACK | GLPT_VARYING_SECONDARY)) == \
    (GLPT_VARYING_BACK | GLPT_VARYING_SECONDARY)
layout(location = 3) GLPT_COLOR_VARYING_OUT vec4 v_back_secondary;
#else
vec4 v_back_secondary;
#endif
#if (GLPT_VARYINGS & GLPT_VARYING_TEXCOORDS) != 0
layout(location = 4) GLPT_VARYING_OUT vec4 v_texcoord[GLPT_RASTER_MAX_UNITS];
#else
vec4 v_texcoord[GLPT_RASTER_MAX_UNITS];
#endif
#if (GLPT_VARYINGS & GLPT_VARYING_FOG) != 0
layout(location = 8) GLPT_VARYING_OUT float v_fog;
#else
float v_fog;
#endif
