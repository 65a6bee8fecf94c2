#include "rt_core/scene/scene_builder.hpp"

#include <cmath>
#include <cstring>
#include <map>

#include "common/content_hash.hpp"
#include "rt_core/record/decompose.hpp"

namespace glpt::rt {
namespace {

struct Camera {
  glm::mat4 projection;
  std::array<int32_t, 4> viewport;
  bool operator<(const Camera& o) const {
    if (int c = std::memcmp(&viewport, &o.viewport, sizeof viewport)) return c < 0;
    return std::memcmp(&projection, &o.projection, sizeof projection) < 0;
  }
};

Camera camera_of(const rec::StateSnapshot& s) {
  return {s.transform->projection, s.transform->viewport};
}

ColorSource color_source_of(uint32_t mode) {
  switch (mode) {
    case GL_AMBIENT:
      return ColorSource::kAmbient;
    case GL_DIFFUSE:
      return ColorSource::kDiffuse;
    case GL_SPECULAR:
      return ColorSource::kSpecular;
    case GL_EMISSION:
      return ColorSource::kEmission;
    default:
      return ColorSource::kAmbientAndDiffuse;
  }
}

Material material_of(const rec::LightingState& lighting, const rec::Material& front) {
  Material m;
  if (!lighting.enabled) {
    m.lit = false;  // the surface shows its vertex colour
    m.color_source = ColorSource::kAmbientAndDiffuse;
    return m;
  }
  m.ambient = front.ambient;
  m.diffuse = front.diffuse;
  m.specular = front.specular;
  m.emission = front.emission;
  m.shininess = front.shininess;
  if (lighting.color_material && lighting.color_material_face != GL_BACK)
    m.color_source = color_source_of(lighting.color_material_mode);
  return m;
}

Light light_of(const rec::Light& l) {
  Light t;
  t.position = l.position;
  t.ambient = l.ambient;
  t.diffuse = l.diffuse;
  t.specular = l.specular;
  t.spot_direction = l.spot_direction;
  t.spot_exponent = l.spot_exponent;
  t.spot_cutoff = l.spot_cutoff;
  t.constant_attenuation = l.constant_attenuation;
  t.linear_attenuation = l.linear_attenuation;
  t.quadratic_attenuation = l.quadratic_attenuation;
  return t;
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

uint32_t intern(std::vector<Material>& materials, const Material& m) {
  for (size_t i = materials.size(); i-- > 0;)
    if (materials[i] == m) return static_cast<uint32_t>(i);
  materials.push_back(m);
  return static_cast<uint32_t>(materials.size() - 1);
}

// Consecutive traced draws with one modelview become one Geometry (one BLAS).
class Batcher {
 public:
  explicit Batcher(std::vector<Instance>& instances) : instances_(instances) {}

  void add(const rec::Draw& draw, const rec::StateSnapshot& state, rec::Decomposed& scratch) {
    const glm::mat4& modelview = state.transform->modelview;
    if (open_ && std::memcmp(&modelview, &open_modelview_, sizeof modelview) != 0) close();
    if (!open_) {
      open_ = std::make_unique<Geometry>();
      open_modelview_ = modelview;
      hash_ = ContentHash();
    }
    const rec::VertexData& v = *draw.vertices;
    scratch.clear();
    rec::decompose(v, scratch);
    const bool flat = state.raster->primitive.shade_model == GL_FLAT;
    const rec::LightingState& lighting = *state.lighting;
    const uint32_t shared_material =
        v.material.empty() ? intern(open_->materials, material_of(lighting, lighting.material[0]))
                           : 0;
    Geometry& g = *open_;
    const glm::vec3 kDefaultNormal(0, 0, 1);
    const glm::vec4 kDefaultColor(1.0f);
    for (const rec::DecomposedTriangle& t : scratch.triangles) {
      glm::vec3 p[3];
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        const glm::vec4 h = v.position[t.v[k]];
        // A vertex at infinity (w <= 0) or a non-finite one cannot be traced: drop the triangle.
        p[k] = h.w == 1.0f ? glm::vec3(h) : glm::vec3(h) / h.w;
        ok = ok && h.w > 0.0f && finite(p[k]);
      }
      if (!ok) {
        ++dropped_;
        continue;
      }
      const uint32_t provoking = t.v[2];
      for (int k = 0; k < 3; ++k) {
        const uint32_t src = flat ? provoking : t.v[k];
        g.positions.push_back(p[k]);
        g.normals.push_back(rec::attribute_at(v.normal, src, kDefaultNormal));
        g.colors.push_back(rec::attribute_at(v.color, src, kDefaultColor));
      }
      g.material_ids.push_back(
          v.material.empty()
              ? shared_material
              : intern(g.materials, material_of(lighting, v.material[provoking][0])));
    }
    hash_.add_bytes(&v.geometry_key, sizeof v.geometry_key);
    hash_.add_bytes(&v.attribute_key, sizeof v.attribute_key);
    hash_.add_bytes(&flat, sizeof flat);
  }

  void close() {
    if (!open_) return;
    if (!open_->positions.empty()) {
      for (const Material& m : open_->materials) {
        hash_.add_bytes(&m.ambient, sizeof(glm::vec4) * 4);
        hash_.add_bytes(&m.shininess, sizeof m.shininess);
        const uint32_t flags = (m.lit ? 1u : 0u) | (static_cast<uint32_t>(m.color_source) << 1);
        hash_.add_bytes(&flags, sizeof flags);
      }
      open_->content_hash = hash_.value();
      instances_.push_back({std::shared_ptr<const Geometry>(std::move(open_)), open_modelview_});
    }
    open_.reset();
  }

 private:
  std::vector<Instance>& instances_;
  std::unique_ptr<Geometry> open_;
  glm::mat4 open_modelview_{1.0f};
  ContentHash hash_;
  uint64_t dropped_ = 0;
};

}  // namespace

void build_trace_scene(const rec::FrameRecord& record, uint32_t width, uint32_t height,
                       SceneBuild& out) {
  out.scene = TraceScene();
  out.traced.clear();
  out.overlay.clear();
  TraceScene& scene = out.scene;
  scene.width = width;
  scene.height = height;

  // The main camera: the projection and viewport under which the most triangles are drawn.
  std::map<Camera, uint64_t> triangles_per_camera;
  for (const rec::Command& command : record.commands) {
    const auto* draw = std::get_if<rec::Draw>(&command);
    if (draw == nullptr ||
        rec::primitive_class(draw->vertices->mode) != rec::PrimitiveClass::kTriangles)
      continue;
    triangles_per_camera[camera_of(record.states[draw->state])] += draw->vertices->vertex_count();
  }
  const Camera* main_camera = nullptr;
  uint64_t most = 0;
  for (const auto& [camera, count] : triangles_per_camera) {
    if (count > most) {
      most = count;
      main_camera = &camera;
    }
  }
  if (main_camera != nullptr) {
    scene.projection = main_camera->projection;
    scene.viewport = {main_camera->viewport[0], main_camera->viewport[1],
                      static_cast<uint32_t>(std::max(main_camera->viewport[2], 0)),
                      static_cast<uint32_t>(std::max(main_camera->viewport[3], 0))};
  } else {
    scene.viewport = {0, 0, width, height};
  }

  Batcher batcher(scene.instances);
  rec::Decomposed scratch;
  bool lights_taken = false;
  for (size_t i = 0; i < record.commands.size(); ++i) {
    const rec::Command& command = record.commands[i];
    if (const auto* clear = std::get_if<rec::Clear>(&command)) {
      if (clear->mask & GL_COLOR_BUFFER_BIT) scene.clear_color = clear->color;
      continue;
    }
    const auto* draw = std::get_if<rec::Draw>(&command);
    if (draw == nullptr) {
      out.overlay.push_back(i);
      continue;
    }
    const rec::StateSnapshot& state = record.states[draw->state];
    const Camera camera = camera_of(state);
    const bool traced =
        main_camera != nullptr &&
        rec::primitive_class(draw->vertices->mode) == rec::PrimitiveClass::kTriangles &&
        !(camera < *main_camera) && !(*main_camera < camera);
    if (!traced) {
      out.overlay.push_back(i);
      continue;
    }
    out.traced.push_back(i);
    batcher.add(*draw, state, scratch);
    const rec::LightingState& lighting = *state.lighting;
    if (!lights_taken && lighting.enabled) {
      lights_taken = true;
      scene.global_ambient = lighting.model_ambient;
      for (int l = 0; l < rec::kMaxLights; ++l)
        if (lighting.light_mask & (1u << l)) scene.lights.push_back(light_of(lighting.lights[l]));
    }
  }
  batcher.close();
}

}  // namespace glpt::rt
