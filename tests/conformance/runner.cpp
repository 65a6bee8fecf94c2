#define GL_GLEXT_PROTOTYPES 1
#include "runner.hpp"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "image_io.hpp"
#include "scene.hpp"
#include "state_dump.hpp"

namespace glpt::conformance {
namespace {

const char kUsage[] =
    "usage: %s [--list] [--all] [--scene NAME]... [--out DIR]\n"
    "  --list        print every scene: name, width, height, max channel difference, minimum\n"
    "                fraction of pixels within it, and the reason for a non-default tolerance\n"
    "                (tab-separated)\n"
    "  --scene NAME  run this scene (repeatable)\n"
    "  --all         run every scene\n"
    "  --out DIR     write DIR/NAME.png (the colour buffer after the scene) and\n"
    "                DIR/NAME.state.json (the GL state after it); default: current directory\n";

// The first error the scene left, then the flag cleared: GL may keep several error flags
// (GL 1.5 2.5), and the state dump needs them all clear to attribute its own errors.
GLenum take_scene_error() {
  const GLenum first = glGetError();
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }
  return first;
}

// Puts back the default pixel-pack and pixel-transfer state so that glReadPixels returns the
// colour buffer unchanged whatever the scene left (GL 1.5 4.3.2 applies the pixel transfer
// operations to ReadPixels). Runs after the state dump, so the dump shows the scene's values.
void reset_read_state() {
  set_default_pack_state();
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  const GLenum scales[] = {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE};
  const GLenum biases[] = {GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS};
  for (const GLenum s : scales) glPixelTransferf(s, 1.0f);
  for (const GLenum b : biases) glPixelTransferf(b, 0.0f);
}

bool write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << text;
  return static_cast<bool>(file);
}

// Runs one scene in a fresh context and writes its image and state dump.
bool run_scene(Backend& backend, const Scene& scene, const std::filesystem::path& out_dir) {
  std::string error;
  if (!backend.begin_scene(scene.width, scene.height, &error)) {
    std::fprintf(stderr, "%s: %s: cannot create a context: %s\n", backend.name(), scene.name,
                 error.c_str());
    return false;
  }
  take_scene_error();  // context creation must not leak errors into the scene's
  scene.draw();
  const GLenum scene_error = take_scene_error();
  glFinish();
  take_scene_error();  // glFinish raises nothing; keep the dump's start clean regardless
  const std::string state = dump_gl_state(scene.name, backend.name(), scene_error);

  reset_read_state();
  take_scene_error();  // an implementation without pixel transfer: not the read's error
  std::vector<uint8_t> pixels(static_cast<size_t>(scene.width) * scene.height * 4, 0);
  glReadPixels(0, 0, scene.width, scene.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  const GLenum read_error = glGetError();
  backend.end_scene();

  bool ok = true;
  if (read_error != GL_NO_ERROR) {
    std::fprintf(stderr, "%s: %s: glReadPixels raised %s\n", backend.name(), scene.name,
                 gl_error_name(read_error).c_str());
    ok = false;
  }
  const std::filesystem::path png = out_dir / (std::string(scene.name) + ".png");
  if (!write_png_rgba8(png.string(), static_cast<uint32_t>(scene.width),
                       static_cast<uint32_t>(scene.height), pixels.data(), true, &error)) {
    std::fprintf(stderr, "%s: %s: %s\n", backend.name(), scene.name, error.c_str());
    ok = false;
  }
  const std::filesystem::path json = out_dir / (std::string(scene.name) + ".state.json");
  if (!write_text(json, state)) {
    std::fprintf(stderr, "%s: %s: cannot write %s\n", backend.name(), scene.name,
                 json.string().c_str());
    ok = false;
  }
  return ok;
}

void list_scenes(const std::vector<Scene>& scenes) {
  for (const Scene& s : scenes) {
    std::printf("%s\t%d\t%d\t%d\t%.6g\t%s\n", s.name, s.width, s.height,
                s.tolerance.max_channel_diff, s.tolerance.min_fraction,
                s.tolerance.reason ? s.tolerance.reason : "");
  }
}

}  // namespace

int run_main(int argc, char** argv, Backend& backend) {
  const std::vector<Scene>& scenes = all_scenes();
  const std::vector<std::string> problems = validate_scenes(scenes);
  if (!problems.empty()) {
    for (const std::string& p : problems) std::fprintf(stderr, "%s\n", p.c_str());
    return 2;
  }
  std::map<std::string, const Scene*> by_name;
  for (const Scene& s : scenes) by_name[s.name] = &s;

  bool list = false, all = false;
  std::vector<const Scene*> selected;
  std::filesystem::path out_dir = ".";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--list") {
      list = true;
    } else if (arg == "--all") {
      all = true;
    } else if ((arg == "--scene" || arg == "--out") && i + 1 < argc) {
      const std::string value = argv[++i];
      if (arg == "--out") {
        out_dir = value;
        continue;
      }
      const auto it = by_name.find(value);
      if (it == by_name.end()) {
        std::fprintf(stderr, "%s: no scene named '%s' (see --list)\n", argv[0], value.c_str());
        return 2;
      }
      selected.push_back(it->second);
    } else {
      std::fprintf(stderr, kUsage, argv[0]);
      return 2;
    }
  }
  if (list) {
    list_scenes(scenes);
    return 0;
  }
  if (all) {
    selected.clear();
    for (const Scene& s : scenes) selected.push_back(&s);
  }
  if (selected.empty()) {
    std::fprintf(stderr, kUsage, argv[0]);
    return 2;
  }
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "%s: cannot create %s: %s\n", argv[0], out_dir.string().c_str(),
                 ec.message().c_str());
    return 1;
  }
  int status = 0;
  for (const Scene* s : selected) {
    if (!run_scene(backend, *s, out_dir)) status = 1;
  }
  return status;
}

}  // namespace glpt::conformance
