// A GL 1.x scene described once as data, for the CPU reference tracer (reference_tracer.hpp) and
// for glpt (gl_issue.hpp issues the same data as GL calls), so the two can never disagree about
// what the scene is. Usage (see reference_test.cpp for complete tests):
//
//   glpt::reference::Scene scene;
//   scene.size = 32;                                   // size x size window, GL viewport
//   scene.camera = glpt::reference::Camera::frustum(0.577f, 1.0f, 50.0f);
//   scene.lights.push_back(glpt::reference::Light::point({0, 0, -3}, {3, 3, 3}));
//   scene.add_quad({-3, -3, -5}, {3, -3, -5}, {3, 3, -5}, {-3, 3, -5}, material);
//   glpt::reference::Estimate ref = glpt::reference::render(scene, {.samples = 4096});
//   std::vector<uint8_t> gpu = glpt::test::render_headless(
//       scene.size, scene.glpt_settings({{"GLPT_REFERENCE", "1024"}}),
//       [&] { glpt::reference::issue_gl(scene); }, 1, "tag");
//   glpt::reference::compare_means(gpu, 1024, ref, 8)  // distribution_compare.hpp
//
// Every value is stored as the float GL receives (vertices, colours, light parameters): the
// reference computes in double on exactly the program's input, so any difference left is
// glpt's (float arithmetic, sampling, mapping), not a rounding of the scene.
//
// What the description covers: perspective (glFrustum) or parallel (glOrtho) cameras over the
// whole window, lit triangles with per-vertex normals and one GL material per object
// (GL_FRONT_AND_BACK), a translation per object (GL's modelview; consecutive objects with the
// same translation are one glpt instance, which sizes the ambient-occlusion radius), up to 8 GL
// lights in eye space (directional, positional, spot, attenuation), GL's global ambient and
// two-sided lighting. Not covered: textures, colour material, unlit draws, fog, clip planes,
// alpha test, skies.
#pragma once

#include <cstdint>
#include <cstdio>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

namespace glpt::reference {

struct Material {
  glm::vec3 ambient{0.0f};
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
  glm::vec3 emission{0.0f};
  float shininess = 0.0f;
};

// A GL light with its GL parameters, in eye space (issued under an identity modelview).
struct Light {
  glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f};  // w == 0: directional, towards the light
  glm::vec3 ambient{0.0f};
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
  glm::vec3 spot_direction{0.0f, 0.0f, -1.0f};
  float spot_exponent = 0.0f;
  float spot_cutoff = 180.0f;  // degrees; 180: no spot
  float constant_attenuation = 1.0f;
  float linear_attenuation = 0.0f;
  float quadratic_attenuation = 0.0f;

  // A positional light with GL's inverse-square attenuation alone (a physical point or sphere).
  static Light point(glm::vec3 at, glm::vec3 color, float quadratic = 1.0f) {
    Light l;
    l.position = glm::vec4(at, 1.0f);
    l.diffuse = color;
    l.constant_attenuation = 0.0f;
    l.quadratic_attenuation = quadratic;
    return l;
  }
  static Light directional(glm::vec3 towards, glm::vec3 color) {
    Light l;
    l.position = glm::vec4(towards, 0.0f);
    l.diffuse = color;
    return l;
  }
};

struct Vertex {
  glm::vec3 position;  // object space
  glm::vec3 normal;
};

struct Object {
  std::vector<Vertex> vertices;  // three per triangle (GL_TRIANGLES)
  Material material;
  glm::vec3 translation{0.0f};  // modelview = glTranslatef(translation)
};

struct Camera {
  bool perspective = true;
  float left = -1, right = 1, bottom = -1, top = 1, near_plane = 1, far_plane = 50;

  // A symmetric frustum: x and y in [-half, half] * distance.
  static Camera frustum(float half, float near_plane, float far_plane) {
    return {
        true,       -half * near_plane, half * near_plane, -half * near_plane, half * near_plane,
        near_plane, far_plane};
  }
  static Camera ortho(float half, float near_plane, float far_plane) {
    return {false, -half, half, -half, half, near_plane, far_plane};
  }
};

// The trace settings both sides use (glpt gets them as GLPT_* variables: glpt_settings()).
struct Trace {
  int bounces = 1;              // GLPT_BOUNCES
  float light_radius = -1.0f;   // GLPT_LIGHT_RADIUS; < 0: the angular default
  float light_size_deg = 1.0f;  // GLPT_LIGHT_SIZE_DEG
  float ao_radius = 0.0f;       // GLPT_AO_RADIUS; 0: the occluder's own size
  bool ao = true;               // GLPT_AO
  bool shadows = true;          // GLPT_SHADOWS
};

struct Scene {
  int size = 32;
  Camera camera;
  glm::vec3 clear_color{0.0f};
  glm::vec3 global_ambient{0.0f};  // GL_LIGHT_MODEL_AMBIENT (set; GL's default is 0.2)
  bool two_side = false;           // GL_LIGHT_MODEL_TWO_SIDE
  // glDepthFunc(GL_LEQUAL) instead of GL_LESS. The reference has no depth buffer: it sees the
  // closest surface exactly. GL's depth buffer cannot order surfaces whose depths round to the
  // same value, and with GL_LESS drops everything whose depth rounds to 1 (beyond about 3,000
  // units at a near plane of 1e-4); scenes with such far surfaces use GL_LEQUAL and keep them
  // apart from nearer ones.
  bool depth_less_equal = false;
  std::vector<Light> lights;  // at most 8
  std::vector<Object> objects;
  Trace trace;

  // Adds a flat quad p0..p3 (counter-clockwise seen from where its normal points) as two
  // triangles to a new object.
  Object& add_quad(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, const Material& m,
                   glm::vec3 translation = glm::vec3(0.0f)) {
    Object& o = objects.emplace_back();
    o.material = m;
    o.translation = translation;
    append_quad(o, p0, p1, p2, p3);
    return o;
  }
  static void append_quad(Object& o, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
    const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p3 - p0));
    for (const glm::vec3& p : {p0, p1, p2, p0, p2, p3}) o.vertices.push_back({p, n});
  }

  // glpt's GLPT_* settings for this scene's trace settings, followed by `extra`. The denoiser is
  // off: the comparison is of the estimator itself.
  std::vector<std::pair<const char*, std::string>> glpt_settings(
      std::vector<std::pair<const char*, std::string>> extra = {}) const {
    std::vector<std::pair<const char*, std::string>> s = {
        {"GLPT_MODE", "path"},
        {"GLPT_DENOISER", "off"},
        {"GLPT_BOUNCES", std::to_string(trace.bounces)},
        {"GLPT_LIGHT_SIZE_DEG", number(trace.light_size_deg)},
        {"GLPT_AO_RADIUS", number(trace.ao_radius)},
        {"GLPT_AO", trace.ao ? "1" : "0"},
        {"GLPT_SHADOWS", trace.shadows ? "1" : "0"},
        {"GLPT_LIGHT_CHOICE", "contribution"},
        {"GLPT_ENVIRONMENT", "black"},
        {"GLPT_SCALE", "1"}};
    if (trace.light_radius >= 0.0f) s.emplace_back("GLPT_LIGHT_RADIUS", number(trace.light_radius));
    s.insert(s.end(), extra.begin(), extra.end());
    return s;
  }

  // A float as text that reads back as the same float (std::to_string keeps 6 decimals only,
  // which loses the radii of scenes at 1e-6 scale).
  static std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
    return text;
  }
};

}  // namespace glpt::reference
