// Renders a synthetic scene (floor, UV spheres, a lamp marker, ~3k triangles) through the public
// API and prints per-stage timings; optionally writes the image as PNG.
//
//   glpt_rt_bench [--size WxH] [--frames N] [--triangles N] [--instances N] [--png out.png]
//                 [--moving]
//
// TraceScene 1 includes the BLAS builds; later frames reuse them (and accumulate unless --moving,
// which changes a transform every frame like an animated GL program). --instances adds N small
// spheres in random order, like a program drawing many objects with separate draw calls.
#include <png.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <string>

#include "rt_core/passes/path_tracer.hpp"

namespace {

using glpt::rt::Geometry;
using glpt::rt::Material;
using glpt::rt::TraceScene;

std::shared_ptr<Geometry> uv_sphere(int slices, int stacks, glm::vec4 color, uint64_t hash) {
  auto geometry = std::make_shared<Geometry>();
  auto point = [&](int i, int j) {
    float theta = float(j) / float(stacks) * 3.14159265f,
          phi = float(i) / float(slices) * 6.2831853f;
    return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                     std::sin(theta) * std::sin(phi));
  };
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      glm::vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
      for (glm::vec3 p : {a, c, b, a, d, c}) {  // counter-clockwise seen from outside
        geometry->positions.push_back(p);
        geometry->normals.push_back(p);
        geometry->colors.push_back(color);
      }
      geometry->material_ids.push_back(0);
      geometry->material_ids.push_back(0);
    }
  }
  Material material;
  material.color_source = glpt::rt::ColorSource::kAmbientAndDiffuse;
  material.specular = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  material.shininess = 32.0f;
  geometry->materials = {material};
  geometry->content_hash = hash;
  return geometry;
}

std::shared_ptr<Geometry> floor_grid(int n, uint64_t hash) {
  auto geometry = std::make_shared<Geometry>();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      float x0 = -1.0f + 2.0f * float(i) / float(n), x1 = -1.0f + 2.0f * float(i + 1) / float(n);
      float z0 = -1.0f + 2.0f * float(j) / float(n), z1 = -1.0f + 2.0f * float(j + 1) / float(n);
      glm::vec4 color =
          (i + j) % 2 ? glm::vec4(0.8f, 0.8f, 0.8f, 1) : glm::vec4(0.3f, 0.3f, 0.6f, 1);
      for (glm::vec3 p : {glm::vec3(x0, 0, z0), glm::vec3(x0, 0, z1), glm::vec3(x1, 0, z1),
                          glm::vec3(x0, 0, z0), glm::vec3(x1, 0, z1), glm::vec3(x1, 0, z0)}) {
        geometry->positions.push_back(p);
        geometry->normals.push_back({0, 1, 0});
        geometry->colors.push_back(color);
      }
      geometry->material_ids.push_back(0);
      geometry->material_ids.push_back(0);
    }
  }
  Material material;
  material.color_source = glpt::rt::ColorSource::kAmbientAndDiffuse;
  geometry->materials = {material};
  geometry->content_hash = hash;
  return geometry;
}

bool write_png(const char* path, const std::vector<uint8_t>& rgba, uint32_t width,
               uint32_t height) {
  FILE* file = std::fopen(path, "wb");
  if (file == nullptr) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (uint32_t row = 0; row < height; ++row) {  // rgba is bottom-to-top, PNG top-to-bottom
    png_write_row(png, &rgba[size_t{height - 1 - row} * width * 4]);
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  uint32_t width = 300, height = 300;
  int frames = 5, target_triangles = 3000;
  const char* png_path = nullptr;
  bool moving = false;
  int extra_instances = 0;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--size" && i + 1 < argc) {
      std::sscanf(argv[++i], "%ux%u", &width, &height);
    } else if (arg == "--frames" && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else if (arg == "--triangles" && i + 1 < argc) {
      target_triangles = std::atoi(argv[++i]);
    } else if (arg == "--png" && i + 1 < argc) {
      png_path = argv[++i];
    } else if (arg == "--instances" && i + 1 < argc) {
      extra_instances = std::atoi(argv[++i]);
    } else if (arg == "--moving") {
      moving = true;
    } else {
      std::fprintf(stderr,
                   "usage: %s [--size WxH] [--frames N] [--triangles N] [--instances N] [--png "
                   "out.png] [--moving]\n",
                   argv[0]);
      return 2;
    }
  }

  std::string error;
  auto renderer =
      glpt::rt::PathTracer::create(glpt::rt::RenderSettings::from_environment(), &error);
  if (!renderer) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }

  // Budget: a floor grid (~1/4) and three spheres sharing one geometry, plus a lamp marker.
  int grid = std::max(2, int(std::sqrt(target_triangles / 8)));
  int sphere_slices = std::max(6, int(std::sqrt(target_triangles * 3 / 4 / 3 / 2 * 2)));
  auto floor = floor_grid(grid, 1);
  auto sphere = uv_sphere(sphere_slices, sphere_slices / 2, glm::vec4(0.9f, 0.3f, 0.2f, 1), 2);
  auto lamp = uv_sphere(8, 4, glm::vec4(1), 3);
  auto small_sphere = uv_sphere(8, 4, glm::vec4(0.2f, 0.8f, 0.3f, 1), 4);
  std::const_pointer_cast<Geometry>(lamp)->materials[0].lit = false;

  TraceScene frame;
  frame.width = width;
  frame.height = height;
  frame.viewport = {0, 0, width, height};
  frame.projection =
      glm::perspective(glm::radians(50.0f), float(width) / float(height), 0.1f, 100.0f);
  frame.clear_color = glm::vec4(0.1f, 0.1f, 0.15f, 1.0f);
  const glm::mat4 view =
      glm::lookAt(glm::vec3(0, 2.5f, 6), glm::vec3(0, 0.5f, 0), glm::vec3(0, 1, 0));
  glpt::rt::Light sun;
  sun.position = glm::vec4(glm::normalize(glm::mat3(view) * glm::vec3(-1, 2, 1)), 0.0f);
  sun.diffuse = glm::vec4(0.7f);
  glpt::rt::Light bulb;
  const glm::vec3 bulb_position(1.5f, 2.0f, 1.0f);
  bulb.position = view * glm::vec4(bulb_position, 1.0f);
  bulb.diffuse = glm::vec4(0.6f, 0.5f, 0.3f, 1.0f);
  bulb.linear_attenuation = 0.2f;
  frame.lights = {sun, bulb};

  uint64_t triangles = 0;
  for (int f = 0; f < frames; ++f) {
    const float angle = moving ? 0.1f * float(f) : 0.0f;
    frame.instances.clear();
    frame.instances.push_back({floor, view * glm::scale(glm::mat4(1), glm::vec3(4, 1, 4))});
    for (int s = 0; s < 3; ++s) {
      glm::mat4 model =
          glm::rotate(glm::mat4(1), angle, glm::vec3(0, 1, 0)) *
          glm::translate(glm::mat4(1), glm::vec3(-2.0f + 2.0f * float(s), 0.8f, -0.5f * float(s))) *
          glm::scale(glm::mat4(1), glm::vec3(0.8f));
      frame.instances.push_back({sphere, view * model});
    }
    std::mt19937 random(5);  // same positions every frame
    std::uniform_real_distribution<float> coordinate(-3.5f, 3.5f);
    for (int k = 0; k < extra_instances; ++k) {
      glm::vec3 position(coordinate(random), 0.1f + 0.1f * (coordinate(random) + 3.5f),
                         coordinate(random));
      frame.instances.push_back({small_sphere, view * glm::translate(glm::mat4(1), position) *
                                                   glm::scale(glm::mat4(1), glm::vec3(0.1f))});
    }
    frame.instances.push_back({lamp, view * glm::translate(glm::mat4(1), bulb_position) *
                                         glm::scale(glm::mat4(1), glm::vec3(0.1f))});

    std::vector<uint8_t> rgba;
    glpt::rt::FrameStats stats;
    const auto start = std::chrono::steady_clock::now();
    if (!renderer->render(frame, rgba, stats, &error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    const double total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    triangles = stats.triangles;
    std::printf(
        "frame %d %ux%u: total %.1f ms | upload %.2f blas %.2f tlas %.2f trace %.1f readback %.2f "
        "ms"
        " | blas builds %u reused %u | %llu tris | %.3f Mrays (%.2f Mrays/s) | spp %u\n",
        f, width, height, total_ms, stats.upload_ms, stats.blas_ms, stats.tlas_ms, stats.trace_ms,
        stats.readback_ms, stats.blas_builds, stats.blas_reused,
        (unsigned long long)stats.triangles, double(stats.rays) / 1e6,
        stats.trace_ms > 0 ? double(stats.rays) / 1e3 / stats.trace_ms : 0.0,
        stats.accumulated_samples);
    if (png_path != nullptr && f == frames - 1 && !write_png(png_path, rgba, width, height)) {
      std::fprintf(stderr, "cannot write %s\n", png_path);
      return 1;
    }
  }
  std::printf("device: %s, %llu triangles\n", renderer->device_name().c_str(),
              (unsigned long long)triangles);
  return 0;
}
