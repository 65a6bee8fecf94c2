#include "scene_runner.hpp"

#include <GL/gl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include "image_io.hpp"

namespace glpt::pixel_ops {
namespace {

constexpr int kMaxChannelDiff = 2;
constexpr double kMinFraction = 0.995;

bool render(Backend& backend, const Scene& scene, const std::string& dir) {
  std::string error;
  if (!backend.begin_scene(scene.width, scene.height, &error)) {
    std::fprintf(stderr, "%s: %s\n", scene.name, error.c_str());
    return false;
  }
  scene.draw();
  glFinish();
  std::vector<uint8_t> rgba(size_t(scene.width) * scene.height * 4, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, scene.width, scene.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  const GLenum gl_error = glGetError();
  backend.end_scene();
  if (gl_error != GL_NO_ERROR) {
    std::fprintf(stderr, "%s: GL error 0x%x\n", scene.name, gl_error);
    return false;
  }
  const std::string base = dir + "/" + scene.name;
  std::ofstream(base + ".rgba", std::ios::binary)
      .write(reinterpret_cast<const char*>(rgba.data()), std::streamsize(rgba.size()));
  write_png_rgba8(base + ".png", uint32_t(scene.width), uint32_t(scene.height), rgba.data(), true,
                  nullptr);
  return true;
}

std::vector<uint8_t> load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool compare(const Scene& scene, const std::string& mesa_dir, const std::string& glpt_dir) {
  const std::vector<uint8_t> a = load(mesa_dir + "/" + scene.name + ".rgba");
  const std::vector<uint8_t> b = load(glpt_dir + "/" + scene.name + ".rgba");
  const size_t pixels = size_t(scene.width) * scene.height;
  if (a.size() != pixels * 4 || b.size() != pixels * 4) {
    std::printf("%-40s MISSING\n", scene.name);
    return false;
  }
  size_t within = 0, exact = 0;
  int worst = 0;
  std::vector<uint8_t> diff(pixels * 4, 255);
  for (size_t i = 0; i < pixels; ++i) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[i * 4 + c]) - int(b[i * 4 + c])));
    worst = std::max(worst, d);
    if (d <= kMaxChannelDiff) ++within;
    if (d == 0) ++exact;
    if (d > kMaxChannelDiff) diff[i * 4 + 1] = diff[i * 4 + 2] = 0;  // red where off
  }
  const double fraction = double(within) / double(pixels);
  const bool ok = fraction >= kMinFraction;
  std::printf("%-40s %s within 2/255: %.4f  exact: %.4f  worst: %d\n", scene.name,
              ok ? "ok  " : "FAIL", fraction, double(exact) / double(pixels), worst);
  if (!ok)
    write_png_rgba8(glpt_dir + "/" + scene.name + ".diff.png", uint32_t(scene.width),
                    uint32_t(scene.height), diff.data(), true, nullptr);
  return ok;
}

}  // namespace

int run_main(int argc, char** argv, Backend& backend) {
  if (argc == 4 && std::strcmp(argv[1], "--compare") == 0) {
    bool ok = true;
    for (const Scene& scene : scenes()) ok = compare(scene, argv[2], argv[3]) && ok;
    return ok ? 0 : 1;
  }
  if ((argc == 3 || argc == 5) && std::strcmp(argv[1], "--out") == 0) {
    const char* only = argc == 5 && std::strcmp(argv[3], "--scene") == 0 ? argv[4] : nullptr;
    bool ok = true;
    for (const Scene& scene : scenes())
      if (only == nullptr || std::strcmp(only, scene.name) == 0)
        ok = render(backend, scene, argv[2]) && ok;
    return ok ? 0 : 1;
  }
  std::fprintf(stderr, "usage: %s --out DIR [--scene NAME] | --compare MESA_DIR GLPT_DIR\n",
               argv[0]);
  return 2;
}

}  // namespace glpt::pixel_ops
