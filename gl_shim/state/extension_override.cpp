#include "gl_shim/state/extension_override.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "gl_shim/dispatch.hpp"

namespace glpt {
namespace {

std::vector<std::string> words(std::string_view text) {
  std::vector<std::string> out;
  std::istringstream in{std::string(text)};
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace

std::string apply_extension_override(std::string_view advertised, std::string_view override) {
  std::vector<std::string> names = words(advertised);
  for (const std::string& word : words(override)) {
    const bool remove = word[0] == '-';
    const std::string name = word[0] == '-' || word[0] == '+' ? word.substr(1) : word;
    if (name.empty()) continue;
    const auto at = std::find(names.begin(), names.end(), name);
    if (remove && at != names.end()) names.erase(at);
    if (!remove && at == names.end()) names.push_back(name);
  }
  std::string out;
  for (const std::string& name : names) out += name + ' ';  // Mesa's form: a space after each
  return out;
}

const char* extensions_string() {
  // Immutable once made (the first query's environment), like the generated list it extends.
  static const std::string s = [] {
    const char* override = std::getenv("GLPT_EXTENSION_OVERRIDE");
    return override != nullptr && *override != '\0'
               ? apply_extension_override(gl_extensions_string(), override)
               : std::string(gl_extensions_string());
  }();
  return s.c_str();
}

}  // namespace glpt
