// Renders a synthetic scene (floor, UV spheres, a lamp marker, ~3k triangles) as frame records
// through the public API (Renderer, path-traced mode unless GLPT_MODE says otherwise) and prints
// per-stage timings; optionally writes the last image as PNG.
//
//   glpt_rt_bench [--size WxH] [--frames N] [--triangles N] [--instances N] [--png out.png]
//                 [--moving]
//
// Frame 1 includes the BLAS builds and pipeline compiles; later frames reuse them (and accumulate
// unless --moving, which changes a transform every frame like an animated GL program).
// --instances adds N small spheres in random order, like a program drawing many objects with
// separate draw calls. The source only uses the frame-record API, so it builds against older
// glpt versions too (docs/performance.md compares the primary-ray tracer with the G-buffer one).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <string>

#include "common/image_io.hpp"
#include "record_builder.hpp"
#include "rt_core/renderer.hpp"

namespace {

using glpt::rt::test::RecordBuilder;

struct Mesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec4> colors;  // empty: one colour for the draw
};

Mesh uv_sphere(int slices, int stacks) {
  Mesh mesh;
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
        mesh.positions.push_back(p);
        mesh.normals.push_back(p);
      }
    }
  }
  return mesh;
}

Mesh floor_grid(int n) {
  Mesh mesh;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      float x0 = -1.0f + 2.0f * float(i) / float(n), x1 = -1.0f + 2.0f * float(i + 1) / float(n);
      float z0 = -1.0f + 2.0f * float(j) / float(n), z1 = -1.0f + 2.0f * float(j + 1) / float(n);
      glm::vec4 color =
          (i + j) % 2 ? glm::vec4(0.8f, 0.8f, 0.8f, 1) : glm::vec4(0.3f, 0.3f, 0.6f, 1);
      for (glm::vec3 p : {glm::vec3(x0, 0, z0), glm::vec3(x0, 0, z1), glm::vec3(x1, 0, z1),
                          glm::vec3(x0, 0, z0), glm::vec3(x1, 0, z1), glm::vec3(x1, 0, z0)}) {
        mesh.positions.push_back(p);
        mesh.normals.push_back({0, 1, 0});
        mesh.colors.push_back(color);
      }
    }
  }
  return mesh;
}

void draw(RecordBuilder& b, const Mesh& mesh, glm::vec4 color) {
  auto v = std::make_shared<glpt::rec::VertexData>();
  v->mode = GL_TRIANGLES;
  for (const glm::vec3& p : mesh.positions) v->position.push_back(glm::vec4(p, 1.0f));
  v->normal = mesh.normals;
  if (mesh.colors.empty())
    v->color = {color};
  else
    v->color = mesh.colors;
  v->primitives.push_back({0, static_cast<uint32_t>(mesh.positions.size())});
  b.draw(std::move(v));
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
  auto renderer = glpt::rt::Renderer::create(glpt::rt::RenderSettings::from_environment(), &error);
  if (!renderer) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const std::shared_ptr<glpt::rt::DrawableBuffers> buffers = glpt::rt::create_drawable_buffers();

  // Budget: a floor grid (~1/4) and three spheres sharing one geometry, plus a lamp marker.
  const int grid = std::max(2, int(std::sqrt(target_triangles / 8)));
  const int sphere_slices = std::max(6, int(std::sqrt(target_triangles * 3 / 4 / 3 / 2 * 2)));
  const Mesh floor = floor_grid(grid);
  const Mesh sphere = uv_sphere(sphere_slices, sphere_slices / 2);
  const Mesh small_sphere = uv_sphere(8, 4);

  const glm::mat4 view =
      glm::lookAt(glm::vec3(0, 2.5f, 6), glm::vec3(0, 0.5f, 0), glm::vec3(0, 1, 0));
  const glm::vec3 bulb_position(1.5f, 2.0f, 1.0f);
  uint64_t triangles = 0;
  std::vector<uint8_t> rgba;
  for (int f = 0; f < frames; ++f) {
    const float angle = moving ? 0.1f * float(f) : 0.0f;
    RecordBuilder b(width, height);
    b.drawable.double_buffered = false;
    b.transform.projection =
        glm::perspective(glm::radians(50.0f), float(width) / float(height), 0.1f, 100.0f);
    b.raster.ops.depth_test = true;
    b.clear(glm::vec4(0.1f, 0.1f, 0.15f, 1.0f));
    // GL_LIGHT0: a directional sun; GL_LIGHT1: a bulb with linear attenuation. Eye space.
    b.lighting.enabled = true;
    b.lighting.light_mask = 3;
    b.lighting.lights[0].position =
        glm::vec4(glm::normalize(glm::mat3(view) * glm::vec3(-1, 2, 1)), 0.0f);
    b.lighting.lights[0].diffuse = glm::vec4(0.7f);
    b.lighting.lights[1].position = view * glm::vec4(bulb_position, 1.0f);
    b.lighting.lights[1].diffuse = glm::vec4(0.6f, 0.5f, 0.3f, 1.0f);
    b.lighting.lights[1].specular = glm::vec4(1.0f);
    b.lighting.lights[1].linear_attenuation = 0.2f;
    b.lighting.color_material = true;  // GL_AMBIENT_AND_DIFFUSE

    b.transform.modelview = view * glm::scale(glm::mat4(1), glm::vec3(4, 1, 4));
    draw(b, floor, glm::vec4(1));
    b.lighting.material[0].specular = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    b.lighting.material[0].shininess = 32.0f;
    for (int s = 0; s < 3; ++s) {
      const glm::mat4 model =
          glm::rotate(glm::mat4(1), angle, glm::vec3(0, 1, 0)) *
          glm::translate(glm::mat4(1), glm::vec3(-2.0f + 2.0f * float(s), 0.8f, -0.5f * float(s))) *
          glm::scale(glm::mat4(1), glm::vec3(0.8f));
      b.transform.modelview = view * model;
      draw(b, sphere, glm::vec4(0.9f, 0.3f, 0.2f, 1));
    }
    std::mt19937 random(5);  // same positions every frame
    std::uniform_real_distribution<float> coordinate(-3.5f, 3.5f);
    for (int k = 0; k < extra_instances; ++k) {
      glm::vec3 position(coordinate(random), 0.1f + 0.1f * (coordinate(random) + 3.5f),
                         coordinate(random));
      b.transform.modelview =
          view * glm::translate(glm::mat4(1), position) * glm::scale(glm::mat4(1), glm::vec3(0.1f));
      draw(b, small_sphere, glm::vec4(0.2f, 0.8f, 0.3f, 1));
    }
    // The lamp marker: a small unlit sphere around the bulb.
    b.lighting.enabled = false;
    b.transform.modelview = view * glm::translate(glm::mat4(1), bulb_position) *
                            glm::scale(glm::mat4(1), glm::vec3(0.1f));
    draw(b, small_sphere, glm::vec4(1));

    glpt::rt::FrameStats stats;
    const auto start = std::chrono::steady_clock::now();
    if (!renderer->execute(b.record, *buffers, b.drawable, stats, &error) ||
        !renderer->read_color(*buffers, GL_FRONT, 0, 0, width, height, rgba, &error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    const double total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    triangles = stats.triangles;
    std::printf(
        "frame %d %ux%u: total %.1f ms | upload %.2f raster %.2f blas %.2f tlas %.2f trace %.1f "
        "ms | blas builds %u reused %u | %llu tris | %.3f Mrays (%.2f Mrays/s) | spp %u\n",
        f, width, height, total_ms, stats.upload_ms, stats.raster_ms, stats.blas_ms, stats.tlas_ms,
        stats.trace_ms, stats.blas_builds, stats.blas_reused, (unsigned long long)stats.triangles,
        double(stats.rays) / 1e6,
        stats.trace_ms > 0 ? double(stats.rays) / 1e3 / stats.trace_ms : 0.0,
        stats.accumulated_samples);
  }
  if (png_path != nullptr && !rgba.empty() &&
      !glpt::write_png_rgba8(png_path, width, height, rgba.data(), true, &error)) {
    std::fprintf(stderr, "cannot write %s: %s\n", png_path, error.c_str());
    return 1;
  }
  std::printf("device: %s, %llu triangles\n", renderer->device_name().c_str(),
              (unsigned long long)triangles);
  return 0;
}
