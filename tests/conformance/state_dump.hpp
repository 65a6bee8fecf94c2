// A JSON dump of the current context's GL 1.5 state, for comparing glpt's state machine with
// Mesa's scene by scene. Every glGet pname of GL 1.5 tables 6.5-6.34 is queried through
// glGetBooleanv, glGetIntegerv and glGetFloatv (so the type conversions of GL 1.5 6.1.2 are
// checked too), plus glIsEnabled of every capability and the per-object queries (lights,
// materials, texture environments, texture coordinate generation, clip planes, texture
// parameters, the polygon stipple). A query that raises an error is recorded as that error's
// name instead of values.
#pragma once

#include <string>

namespace glpt::conformance {

// Returns the dump as a JSON object:
//   {"scene": NAME, "backend": BACKEND, "error_after_scene": "GL_NO_ERROR",
//    "state": {QUERY: [values] or "GL_INVALID_ENUM", ...},
//    "implementation": {...}}
// "state" is what two conforming implementations agree on after the same commands;
// "implementation" holds implementation-dependent values (limits, buffer depths), informational.
// `error_after_scene` is the glGetError value the scene left. The GL error flag must be clear on
// entry; the dump leaves the state as it found it (it restores the active texture units).
std::string dump_gl_state(const std::string& scene, const std::string& backend,
                          unsigned error_after_scene);

// Sets the pixel-pack state glReadPixels and glGetPolygonStipple use to GL's defaults.
void set_default_pack_state();

// "GL_INVALID_ENUM" etc.; a hexadecimal number for anything else.
std::string gl_error_name(unsigned error);

}  // namespace glpt::conformance
