#include <cstdio>
#include <set>

#include "scene.hpp"

namespace glpt::conformance {
namespace {

// The table is filled only during static initialization (one registrar per scene, before main)
// and read-only afterwards, like GoogleTest's test registry. A function-local static avoids the
// static-initialization-order problem between translation units.
std::vector<Scene>& registry() {
  static std::vector<Scene> scenes;
  return scenes;
}

bool valid_name(const std::string& name) {
  if (name.empty()) return false;
  for (const char c : name) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  }
  return true;
}

}  // namespace

SceneRegistrar::SceneRegistrar(const Scene& scene) { registry().push_back(scene); }

const std::vector<Scene>& all_scenes() { return registry(); }

std::vector<std::string> validate_scenes(const std::vector<Scene>& scenes) {
  std::vector<std::string> problems;
  std::set<std::string> names;
  for (const Scene& s : scenes) {
    const std::string where = std::string(s.file) + ": scene '" + s.name + "': ";
    if (!valid_name(s.name)) problems.push_back(where + "name must be [a-z0-9_]+");
    if (!names.insert(s.name).second) problems.push_back(where + "name registered twice");
    if (s.width < 16 || s.width > 256 || s.height < 16 || s.height > 256)
      problems.push_back(where + "size must be 16..256 on each side");
    const Tolerance& t = s.tolerance;
    if (t.max_channel_diff < 0 || t.max_channel_diff > 255 || !(t.min_fraction > 0.0) ||
        t.min_fraction > 1.0)
      problems.push_back(where + "tolerance out of range");
    const bool has_reason = t.reason != nullptr && t.reason[0] != '\0';
    if (!t.is_default() && !has_reason)
      problems.push_back(where + "a tolerance other than the default needs a reason");
    if (t.is_default() && has_reason)
      problems.push_back(where + "a reason is given but the tolerance is the default");
    if (s.draw == nullptr) problems.push_back(where + "no draw function");
  }
  return problems;
}

}  // namespace glpt::conformance
