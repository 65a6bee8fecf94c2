// The path tracer's scene: triangle geometry in object space with per-instance modelviews, GL
// lights, one camera. Derived from the frame record by scene_builder.cpp. Everything is in GL eye
// space: the camera sits at the origin looking down -Z, GL lights are already in eye space, and
// each instance carries the modelview it was drawn with, so a moving camera only changes
// instance transforms and never geometry contents.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

namespace glpt::rt {

// How a material takes the per-vertex colour (GL_COLOR_MATERIAL, or lighting disabled).
enum class ColorSource : uint32_t {
  kNone = 0,               // material values as given
  kAmbientAndDiffuse = 1,  // vertex colour replaces ambient and diffuse
  kDiffuse = 2,
  kAmbient = 3,
  kEmission = 4,
  kSpecular = 5,
};

struct Material {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
  glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  glm::vec4 specular{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;  // GL Blinn-Phong exponent, 0..128
  // false: GL_LIGHTING was disabled; the surface shows its vertex colour as GL would (see
  // docs/architecture.md, "unlit policy").
  bool lit = true;
  ColorSource color_source = ColorSource::kNone;

  bool operator==(const Material&) const = default;
};

// A triangle soup in object space. Triangle t uses vertices 3t, 3t+1, 3t+2. GL_FLAT shading is
// already resolved by the front end (the provoking vertex's normal and colour are copied to all
// three vertices), so the tracer always interpolates.
struct Geometry {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // object space, not necessarily unit length
  std::vector<glm::vec4> colors;   // current colour per vertex (used per Material::color_source)
  std::vector<uint32_t> material_ids;  // one per triangle, index into `materials`
  std::vector<Material> materials;
  // Identity of the content above (positions, normals, colours, materials). Two geometries with
  // the same hash are the same geometry: its acceleration structure is built once and reused.
  uint64_t content_hash = 0;

  size_t triangle_count() const { return positions.size() / 3; }
};

struct Instance {
  std::shared_ptr<const Geometry> geometry;
  glm::mat4 modelview{1.0f};  // object -> eye space at draw time
};

// A GL light in eye space, with its GL parameters (already transformed by the modelview that was
// current when glLight(GL_POSITION / GL_SPOT_DIRECTION) was called, as GL specifies).
struct Light {
  glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f};  // w == 0: directional (towards the light)
  glm::vec4 ambient{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 diffuse{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec4 specular{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec3 spot_direction{0.0f, 0.0f, -1.0f};
  float spot_exponent = 0.0f;
  float spot_cutoff = 180.0f;  // degrees; 180 = not a spot light
  float constant_attenuation = 1.0f;
  float linear_attenuation = 0.0f;
  float quadratic_attenuation = 0.0f;
};

struct Viewport {
  int32_t x = 0, y = 0;
  uint32_t width = 0, height = 0;
};

struct TraceScene {
  uint32_t width = 0, height = 0;  // drawable size in pixels
  Viewport viewport;
  glm::mat4 projection{1.0f};  // eye -> clip, for primary rays
  glm::vec4 clear_color{0.0f, 0.0f, 0.0f, 0.0f};
  glm::vec4 global_ambient{0.2f, 0.2f, 0.2f, 1.0f};  // GL_LIGHT_MODEL_AMBIENT
  std::vector<Light> lights;                         // enabled GL lights only (GL_LIGHTING enabled)
  std::vector<Instance> instances;                   // traced geometry
};

}  // namespace glpt::rt
