// glGetString(GL_EXTENSIONS): the generated list of advertised extensions, changed by
// GLPT_EXTENSION_OVERRIDE as Mesa's MESA_EXTENSION_OVERRIDE changes Mesa's: a space-separated
// list of "+GL_NAME" (advertise an extension glpt does not advertise: one being built, tried by
// piglit before it is complete) and "-GL_NAME" (hide one a program misuses). A name without a
// sign is added. Unknown words are kept as given (the program asks, glpt answers as told).
#pragma once

#include <string>
#include <string_view>

namespace glpt {

// `advertised` (names each followed by a space) with `override` applied; the same form.
std::string apply_extension_override(std::string_view advertised, std::string_view override);

// The process's extension string: the generated list with GLPT_EXTENSION_OVERRIDE applied, read
// once (the environment of the first query).
const char* extensions_string();

}  // namespace glpt
