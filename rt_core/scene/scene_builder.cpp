#include "rt_core/scene/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <span>

#include "common/content_hash.hpp"
#include "rt_core/raster/pipeline_key.hpp"
#include "rt_core/record/decompose.hpp"
#include "rt_core/record/texgen.hpp"
#include "rt_core/scene/fragment_opacity.hpp"
#include "rt_core/scene/light_setup.hpp"

namespace glpt::rt {
namespace {

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

// The material of one face (`back`: the back face's, with two-sided lighting).
Material material_of(const rec::LightingState& lighting, const rec::Material& face, bool back) {
  Material m;
  if (!lighting.enabled) {
    m.lit = false;  // the surface shows its vertex colour
    m.color_source = ColorSource::kAmbientAndDiffuse;
    return m;
  }
  m.ambient = face.ambient;
  m.diffuse = face.diffuse;
  m.specular = face.specular;
  m.emission = face.emission;
  m.shininess = face.shininess;
  const uint32_t tracked = back ? GL_FRONT : GL_BACK;  // the face colour material leaves alone
  if (lighting.color_material && lighting.color_material_face != tracked)
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

// Two lighting states light surfaces the same way (ignoring materials, which are per triangle):
// a batch of draws shares the lights of its instance.
bool same_light_set(const rec::LightingState& a, const rec::LightingState& b) {
  if (&a == &b) return true;
  if (a.enabled != b.enabled || a.light_mask != b.light_mask ||
      a.model_ambient != b.model_ambient || a.two_side != b.two_side ||
      a.local_viewer != b.local_viewer || a.separate_specular != b.separate_specular)
    return false;
  for (int l = 0; l < rec::kMaxLights; ++l)
    if ((a.light_mask & (1u << l)) && !(a.lights[l] == b.lights[l])) return false;
  return true;
}

// Whether a surface of this lighting state can reflect specularly: a specular colour on either
// face, or GL_COLOR_MATERIAL replacing it with the current colour.
bool reflects_specularly(const rec::LightingState& lighting) {
  if (lighting.color_material && lighting.color_material_mode == GL_SPECULAR) return true;
  for (const rec::Material& material : lighting.material)
    if (material.specular.r > 0.0f || material.specular.g > 0.0f || material.specular.b > 0.0f)
      return true;
  return false;
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

// What rays see of a draw besides its triangles: its texture units, alpha test, clip planes.
TracedSurface surface_texture_of(const rec::StateSnapshot& state) {
  TracedSurface surface;
  for (size_t u = 0; u < TracedSurface::kUnits; ++u) {
    const rec::TextureUnitState& unit = state.texturing->units[u];
    // A depth texture with comparison on is a shadow map of a multipass technique: what it
    // holds is the comparison's answer for the camera's pixels, meaningless at a bounce hit.
    if (unit.target != 0 && unit.texture && unit.texture->sampler.compare_mode == GL_NONE) {
      surface.units[u].texture = unit.texture;
      surface.units[u].env_mode = unit.env.mode;
      surface.units[u].lod_bias = unit.env.lod_bias;
    }
  }
  const rec::FragmentOpsState& ops = state.raster->ops;
  if (ops.alpha_test && ops.alpha_func != GL_ALWAYS) {
    surface.alpha_func = ops.alpha_func;
    surface.alpha_ref = ops.alpha_ref;
  }
  const rec::TransformState& transform = *state.transform;
  for (size_t i = 0; i < transform.clip_planes.size() && i < TracedSurface::kMaxClipPlanes; ++i)
    if ((transform.clip_plane_mask >> i) & 1u)
      surface.clip_planes[surface.clip_plane_count++] = transform.clip_planes[i];
  return surface;
}

// The side of a draw's triangles GL culls, in the coordinates its triangles are traced in
// (object space, or eye space for a projective modelview, whose vertices are transformed on the
// CPU): GL decides front and back by the winding in window coordinates (GL 1.5 2.6.1.1), which
// a mirroring modelview or projection reverses, and culls GL_BACK (or GL_FRONT) faces of the
// glFrontFace convention. `projection_mirrored`: projection_mirrors of the draw's projection.
TracedSurface::CulledSide culled_side_of(const rec::StateSnapshot& state, bool projective,
                                         bool projection_mirrored) {
  using Side = TracedSurface::CulledSide;
  const rec::PrimitiveState& primitive = state.raster->primitive;
  if (!primitive.cull_face || primitive.cull_face_mode == GL_FRONT_AND_BACK) return Side::kNone;
  // Culled: the faces counter-clockwise in the window under glFrontFace(GL_CW) and GL_BACK.
  const bool culled_window_ccw =
      (primitive.front_face == GL_CW) != (primitive.cull_face_mode == GL_FRONT);
  const rec::TransformState& transform = *state.transform;
  bool culled_ccw = culled_window_ccw != projection_mirrored;
  if (!projective) {
    const double det = glm::determinant(glm::dmat3(glm::mat3(transform.modelview)));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return Side::kNone;  // flat: no sides
    culled_ccw = culled_ccw != (det < 0.0);
  }
  return culled_ccw ? Side::kCounterClockwise : Side::kClockwise;
}

// Vertex `src`'s eye-space normal as GL's texture generation uses it (GL 1.5 2.11.3): the
// inverse transpose of the modelview, then GL_RESCALE_NORMAL's factor or GL_NORMALIZE.
glm::vec3 eye_normal_of(const rec::VertexData& v, uint32_t src,
                        const rec::TransformState& transform) {
  const glm::mat4& inverse = transform.modelview_inverse;
  glm::vec3 n = glm::transpose(glm::mat3(inverse)) *
                rec::attribute_at(v.normal, src, glm::vec3(0.0f, 0.0f, 1.0f));
  if (transform.rescale_normal) {
    const float row = std::sqrt(inverse[0][2] * inverse[0][2] + inverse[1][2] * inverse[1][2] +
                                inverse[2][2] * inverse[2][2]);
    if (row > 0.0f) n /= row;
  }
  if (transform.normalize) {
    const float length = glm::length(n);
    if (length > 0.0f) n /= length;
  }
  return n;
}

// Unit `u`'s coordinates of vertex `src` as GL computes them per vertex (GL 1.5 2.11.4): texgen
// (object- and eye-linear, and sphere, reflection and normal maps, whose eye-space vectors are
// the camera's, so they are known here, once per vertex, as GL computes them), then the texture
// matrix. A bounce hit interpolates them as GL's rasterizer does.
glm::vec4 texcoord_of(const rec::VertexData& v, uint32_t src, size_t u,
                      const rec::TextureUnitState& unit, const rec::TransformState& transform) {
  glm::vec4 tc = rec::attribute_at(v.tex_coord[u], src, glm::vec4(0, 0, 0, 1));
  if (unit.texgen_mask != 0) {
    const glm::vec4 object = v.position[src];
    tc =
        rec::generate_tex_coord(unit.texgen_mask, unit.texgen, object, transform.modelview * object,
                                eye_normal_of(v, src, transform), tc);
  }
  return unit.matrix * tc;
}

// The parts of a draw's lighting state that make its materials (material_of), hashed: with the
// vertex data's attribute key (which covers per-vertex materials) this identifies a geometry's
// shading without decomposing it.
void add_material_state(ContentHash& hash, const rec::LightingState& lighting,
                        bool per_vertex_materials) {
  const uint32_t flags = (lighting.enabled ? 1u : 0u) | (lighting.color_material ? 2u : 0u) |
                         (lighting.two_side ? 4u : 0u);
  hash.add_bytes(&flags, sizeof flags);
  if (!lighting.enabled) return;
  hash.add_bytes(&lighting.color_material_face, sizeof lighting.color_material_face);
  hash.add_bytes(&lighting.color_material_mode, sizeof lighting.color_material_mode);
  if (per_vertex_materials) return;
  for (const rec::Material& m : lighting.material) {
    hash.add_bytes(&m.ambient, sizeof m.ambient);
    hash.add_bytes(&m.diffuse, sizeof m.diffuse);
    hash.add_bytes(&m.specular, sizeof m.specular);
    hash.add_bytes(&m.emission, sizeof m.emission);
    hash.add_bytes(&m.shininess, sizeof m.shininess);
  }
}

// Consecutive traced draws with one modelview and one light set become one Geometry (one BLAS).
// Draws under a projective modelview are transformed to eye space here and batched under the
// identity. A batch's identity (shape and shading hashes) comes from its draws' content keys
// alone; only a batch the tracer does not already hold (`known`) is decomposed into triangles,
// so unchanged geometry is not decomposed, copied or hashed again frame after frame.
//
// A modulating later pass over the same triangles (a lightmap, a detail texture: FoldedPass) is
// folded into the draw for the rays: its unit-0 texture becomes a further texture unit of the
// surface (after the draw's own, GL_MODULATE), with the pass's coordinates, so a bounce sees the
// lightmapped surface as the same lightmap through ARB_multitexture would show it. The pass
// itself is still drawn by raster mode over the traced pixels (what the camera sees is GL's).
struct FoldedPass {
  const rec::Draw* draw = nullptr;
  const rec::StateSnapshot* state = nullptr;
};

class Batcher {
 public:
  Batcher(std::vector<Instance>& instances, const KnownGeometry& known, rec::Decomposed& scratch)
      : instances_(instances), known_(known), scratch_(scratch) {}

  // `id`: the draw's stable identity (0: none).
  // `opaque_part`: rays see only its opaque fragments (DrawClass::kSplitByAlpha).
  void add(const rec::Draw& draw, const rec::StateSnapshot& state, uint64_t id, bool sky = false,
           std::span<const FoldedPass> passes = {}, bool opaque_part = false) {
    const rec::TransformState& transform = *state.transform;
    const bool projective = is_projective_modelview(transform.modelview);
    const glm::mat4 modelview = projective ? glm::mat4(1.0f) : transform.modelview;
    const rec::PrimitiveState& primitive = state.raster->primitive;
    // Culling both faces draws no polygon: nothing for rays either.
    if (primitive.cull_face && primitive.cull_face_mode == GL_FRONT_AND_BACK) return;
    TracedSurface surface = surface_texture_of(state);
    if (primitive.cull_face)
      surface.culled_side =
          culled_side_of(state, projective, projection_mirrored(transform.projection));
    if (opaque_part) {
      // The draw's own alpha test, if any, passes every opaque fragment (splits_by_alpha).
      surface.alpha_func = GL_GEQUAL;
      surface.alpha_ref = kOpaqueAlpha;
    }
    std::array<FoldedPass, TracedSurface::kUnits> folded{};
    fold(draw, passes, surface, folded);
    if (open_ && (std::memcmp(&modelview, &open_modelview_, sizeof modelview) != 0 ||
                  !same_light_set(*state.lighting, *open_lighting_) ||
                  !(surface == open_surface_) || sky != open_sky_))
      close();
    if (!open_) {
      open_ = true;
      open_sky_ = sky;
      open_modelview_ = modelview;
      open_surface_ = surface;
      open_lighting_ = state.lighting;
      open_state_ = draw.state;
      shape_ = ContentHash();
      shading_ = ContentHash();
      lineage_ = ContentHash();
      untracked_ = false;
      draws_.clear();
    }
    lineage_.add_bytes(&id, sizeof id);
    untracked_ = untracked_ || id == 0;
    const rec::VertexData& v = *draw.vertices;
    const bool flat = state.raster->primitive.shade_model == GL_FLAT;
    const rec::VertexKeys& keys = v.keys();
    for (size_t u = 0; u < TracedSurface::kUnits; ++u) {
      if (!folded[u].draw) continue;
      // The folded coordinates: the pass's vertices and unit-0 state.
      const rec::TextureUnitState& unit = folded[u].state->texturing->units[0];
      const uint64_t attributes = folded[u].draw->vertices->keys().attributes;
      shading_.add_bytes(&u, sizeof u);
      shading_.add_bytes(&attributes, sizeof attributes);
      shading_.add_bytes(&unit.texgen_mask, sizeof unit.texgen_mask);
      shading_.add_bytes(&unit.matrix, sizeof unit.matrix);
      if (unit.texgen_mask != 0) shading_.add_bytes(&unit.texgen, sizeof unit.texgen);
    }
    shape_.add_bytes(&keys.geometry, sizeof keys.geometry);
    shading_.add_bytes(&keys.attributes, sizeof keys.attributes);
    shading_.add_bytes(&flat, sizeof flat);
    add_material_state(shading_, *state.lighting, !v.material.empty());
    for (size_t u = 0; u < TracedSurface::kUnits; ++u) {
      if (!surface.units[u].texture) continue;
      // The texture coordinates: what makes them besides the vertex data.
      const rec::TextureUnitState& unit = state.texturing->units[u];
      shading_.add_bytes(&u, sizeof u);
      shading_.add_bytes(&unit.texgen_mask, sizeof unit.texgen_mask);
      shading_.add_bytes(&unit.matrix, sizeof unit.matrix);
      if (unit.texgen_mask != 0) {
        shading_.add_bytes(&unit.texgen, sizeof unit.texgen);
        shading_.add_bytes(&transform.modelview, sizeof transform.modelview);
        const uint8_t normals[2] = {transform.normalize, transform.rescale_normal};
        shading_.add_bytes(normals, sizeof normals);
      }
    }
    if (projective) {
      shape_.add_bytes(&transform.modelview, sizeof transform.modelview);
      shading_.add_bytes(&transform.modelview, sizeof transform.modelview);
    }
    draws_.push_back({&draw, &state, folded});
  }

  void close() {
    if (!open_) return;
    open_ = false;
    auto geometry = std::make_shared<Geometry>();
    geometry->shape_hash = shape_.value();
    geometry->shading_hash = shading_.value();
    geometry->lineage = untracked_ ? 0 : lineage_.value();
    if (known_ && known_(geometry->shape_hash, geometry->shading_hash)) {
      geometry->resident = true;
    } else {
      for (const OpenDraw& d : draws_) append_triangles(d, *geometry);
      if (geometry->positions.empty()) return;
    }
    std::vector<uint32_t> states;
    for (const OpenDraw& d : draws_) states.push_back(d.draw->state);
    std::sort(states.begin(), states.end());
    states.erase(std::unique(states.begin(), states.end()), states.end());
    instances_.push_back({std::move(geometry), open_modelview_, open_state_, open_surface_,
                          open_sky_, std::move(states)});
    open_lighting_.reset();
    open_surface_ = TracedSurface();
  }

 private:
  // projection_mirrors, remembered for the last projection asked about: a frame's draws share a
  // few projections, and each answer costs a 4x4 inverse (235 ns measured, against the 16-float
  // compare here).
  bool projection_mirrored(const glm::mat4& projection) {
    if (!mirror_known_ || std::memcmp(&projection, &mirror_projection_, sizeof projection) != 0) {
      mirror_projection_ = projection;
      mirror_ = projection_mirrors(projection);
      mirror_known_ = true;
    }
    return mirror_;
  }

  // Folds `passes` into the surface's free texture units after its last used one.
  static void fold(const rec::Draw& draw, std::span<const FoldedPass> passes,
                   TracedSurface& surface, std::array<FoldedPass, TracedSurface::kUnits>& folded) {
    size_t next = 0;
    for (size_t u = 0; u < TracedSurface::kUnits; ++u)
      if (surface.units[u].texture) next = u + 1;
    for (const FoldedPass& pass : passes) {
      if (next >= TracedSurface::kUnits) break;
      const rec::TextureUnitState& unit = pass.state->texturing->units[0];
      if (unit.target == 0 || !unit.texture || unit.texture->sampler.compare_mode != GL_NONE ||
          pass.draw->vertices->vertex_count() != draw.vertices->vertex_count())
        continue;
      surface.units[next].texture = unit.texture;
      surface.units[next].env_mode = GL_MODULATE;
      surface.units[next].lod_bias = unit.env.lod_bias;
      folded[next++] = pass;
    }
  }

  struct OpenDraw {
    const rec::Draw* draw;
    const rec::StateSnapshot* state;
    std::array<FoldedPass, TracedSurface::kUnits> folded;
  };

  void append_triangles(const OpenDraw& open, Geometry& g) {
    const rec::Draw& draw = *open.draw;
    const rec::StateSnapshot& state = *open.state;
    const rec::TransformState& transform = *state.transform;
    const bool projective = is_projective_modelview(transform.modelview);
    const rec::VertexData& v = *draw.vertices;
    scratch_.clear();
    rec::decompose(v, scratch_);
    const bool flat = state.raster->primitive.shade_model == GL_FLAT;
    const rec::LightingState& lighting = *state.lighting;
    // Two-sided lighting gives faces seen from behind the back material (GL 1.5 2.14.1).
    const bool two_side = lighting.enabled && lighting.two_side;
    auto material_pair = [&](const std::array<rec::Material, 2>& pair) {
      Material front = material_of(lighting, pair[0], false);
      if (two_side) front.back = intern(g.materials, material_of(lighting, pair[1], true));
      return intern(g.materials, front);
    };
    const uint32_t shared_material = v.material.empty() ? material_pair(lighting.material) : 0;
    const TracedSurface surface = surface_texture_of(state);
    // GL's normal transform (the inverse transpose of the modelview) for eye-space normals.
    const glm::mat3 normal_matrix = glm::transpose(glm::mat3(transform.modelview_inverse));
    const glm::vec3 kDefaultNormal(0, 0, 1);
    const glm::vec4 kDefaultColor(1.0f);
    for (const rec::DecomposedTriangle& t : scratch_.triangles) {
      glm::vec3 p[3];
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        glm::vec4 h = v.position[t.v[k]];
        if (projective) h = transform.modelview * h;
        // A vertex at infinity (w <= 0) or a non-finite one cannot be traced: drop the triangle.
        p[k] = h.w == 1.0f ? glm::vec3(h) : glm::vec3(h) / h.w;
        ok = ok && h.w > 0.0f && finite(p[k]);
      }
      if (!ok) continue;
      const uint32_t provoking = t.v[2];
      for (int k = 0; k < 3; ++k) {
        const uint32_t src = flat ? provoking : t.v[k];
        const glm::vec3 normal = rec::attribute_at(v.normal, src, kDefaultNormal);
        g.positions.push_back(p[k]);
        g.normals.push_back(projective ? normal_matrix * normal : normal);
        g.colors.push_back(rec::attribute_at(v.color, src, kDefaultColor));
        // Texture coordinates are not flat-shaded: they follow each vertex.
        for (size_t u = 0; u < TracedSurface::kUnits; ++u) {
          if (const FoldedPass& pass = open.folded[u]; pass.draw)
            g.texcoords[u].push_back(texcoord_of(*pass.draw->vertices, t.v[k], 0,
                                                 pass.state->texturing->units[0],
                                                 *pass.state->transform));
          else if (surface.units[u].texture)
            g.texcoords[u].push_back(
                texcoord_of(v, t.v[k], u, state.texturing->units[u], transform));
        }
      }
      g.material_ids.push_back(v.material.empty() ? shared_material
                                                  : material_pair(v.material[provoking]));
    }
  }

  std::vector<Instance>& instances_;
  const KnownGeometry& known_;
  rec::Decomposed& scratch_;
  bool open_ = false;
  bool open_sky_ = false;
  std::vector<OpenDraw> draws_;
  glm::mat4 open_modelview_{1.0f};
  std::shared_ptr<const rec::LightingState> open_lighting_;
  TracedSurface open_surface_;
  uint32_t open_state_ = 0;
  ContentHash shape_, shading_, lineage_;
  bool untracked_ = false;  // a draw of the open batch has no identity
  glm::mat4 mirror_projection_{1.0f};
  bool mirror_ = false, mirror_known_ = false;
};

uint32_t fog_mode_of(const rec::FogState& fog) {
  if (!fog.enabled) return 0;
  return fog.mode == GL_LINEAR ? 1u : fog.mode == GL_EXP2 ? 3u : 2u;
}

uint32_t targets_of(const rec::FragmentOpsState& ops, const rec::DrawableConfig& drawable) {
  switch (resolve_draw_buffer(ops.draw_buffer, drawable.double_buffered)) {
    case ColorTargets::kFront:
      return 1;
    case ColorTargets::kBack:
      return 2;
    case ColorTargets::kFrontAndBack:
      return 3;
    default:
      return 0;
  }
}

// The index of `light` in `lights`, appended if new.
uint32_t light_index(std::vector<Light>& lights, const Light& light) {
  for (size_t i = 0; i < lights.size(); ++i)
    if (lights[i] == light) return static_cast<uint32_t>(i);
  lights.push_back(light);
  return static_cast<uint32_t>(lights.size() - 1);
}

// The denoiser's history of a state (TraceState::history_id and the previous transforms) from
// its first traced draw's identity (null: none).
void set_history(const rec::StateSnapshot& state, const DrawIdentity* identity, TraceState& t) {
  const rec::TransformState& transform = *state.transform;
  t.viewport = transform.viewport;
  // Ids fold to 32 bits; 1 is a traced state without identity (no history across frames), so a
  // folded id is at least 2.
  t.history_id = 1;
  if (identity == nullptr || identity->id == 0) return;
  t.history_id = static_cast<uint32_t>(identity->id ^ (identity->id >> 32));
  if (t.history_id < 2) t.history_id += 2;
  if (!identity->has_previous) return;
  const glm::dmat4 current(transform.modelview);
  const double det = glm::determinant(current);
  if (!std::isfinite(det) || std::abs(det) < 1e-12) return;
  const glm::mat4 to_previous(glm::dmat4(identity->previous_modelview) * glm::inverse(current));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(to_previous[c][r])) return;
  t.has_previous = true;
  t.to_previous_eye = to_previous;
  t.previous_projection = identity->previous_projection;
}

}  // namespace

bool projection_mirrors(const glm::mat4& projection) {
  // A small triangle at the centre of the view volume, counter-clockwise as seen from the
  // viewer; mirrored when its window coordinates run clockwise.
  const glm::dmat4 p(projection);
  const double det = glm::determinant(p);
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
  glm::dvec4 centre = glm::inverse(p) * glm::dvec4(0.0, 0.0, 0.0, 1.0);
  if (!(std::abs(centre.w) > 0.0)) return false;
  const glm::dvec3 c = glm::dvec3(centre) / centre.w;
  const glm::dvec4 viewer(viewer_of_projection(projection));
  glm::dvec3 towards = viewer.w != 0.0 ? glm::dvec3(viewer) - c : glm::dvec3(viewer);
  const double distance = glm::length(towards);
  if (!(distance > 0.0) || !std::isfinite(distance)) return false;
  towards /= distance;
  const glm::dvec3 helper = std::abs(towards.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, towards));
  const glm::dvec3 v = glm::cross(towards, u);  // u x v = towards
  const double size = 1e-3 * std::max(distance, glm::length(c));
  glm::dvec2 window[3];
  const glm::dvec3 corners[3] = {c, c + size * u, c + size * v};
  for (int k = 0; k < 3; ++k) {
    const glm::dvec4 clip = p * glm::dvec4(corners[k], 1.0);
    if (!(clip.w > 0.0)) return false;
    window[k] = glm::dvec2(clip) / clip.w;
  }
  const glm::dvec2 a = window[1] - window[0], b = window[2] - window[0];
  return a.x * b.y - a.y * b.x < 0.0;
}

glm::vec4 viewer_of_projection(const glm::mat4& projection) {
  // The centre of projection is the eye-space point every clip x, y and w vanish at: the
  // generalized cross product of the projection's rows 0, 1 and 3.
  auto row = [&](int r) {
    return glm::dvec4(projection[0][r], projection[1][r], projection[2][r], projection[3][r]);
  };
  const glm::dvec4 a = row(0), b = row(1), c = row(3);
  auto det3 = [](glm::dvec3 x, glm::dvec3 y, glm::dvec3 z) {
    return glm::dot(x, glm::cross(y, z));
  };
  auto drop = [](const glm::dvec4& v, int i) {
    glm::dvec3 out;
    for (int k = 0, j = 0; k < 4; ++k)
      if (k != i) out[j++] = v[k];
    return out;
  };
  glm::dvec4 centre;
  for (int i = 0; i < 4; ++i)
    centre[i] = ((i % 2) ? -1.0 : 1.0) * det3(drop(a, i), drop(b, i), drop(c, i));
  const double length = glm::length(glm::dvec3(centre));
  if (!std::isfinite(length) || !std::isfinite(centre.w) || (length == 0.0 && centre.w == 0.0))
    return glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);  // degenerate: GL's infinite viewer
  if (std::abs(centre.w) > 1e-6 * length) return glm::vec4(glm::dvec3(centre) / centre.w, 1.0);
  glm::dvec3 direction = glm::dvec3(centre) / length;
  if (direction.z < 0.0 || (direction.z == 0.0 && direction.y < 0.0)) direction = -direction;
  return glm::vec4(glm::vec3(direction), 0.0f);
}

void build_trace_scene(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
                       SceneBuild& out, const SceneOptions& options) {
  out.scene = TraceScene();
  FrameClassification own;
  const FrameClassification* classification = options.classification;
  if (classification == nullptr) {
    classify_frame(record, drawable, nullptr, own);
    classification = &own;
  }
  out.classes = classification->classes;
  out.traced.assign(record.commands.size(), 0);
  out.split_by_alpha.assign(record.commands.size(), 0);
  out.gbuffer_pass.clear();
  out.after_trace.clear();
  out.any_traced = false;
  out.any_sky = false;
  TraceScene& scene = out.scene;
  scene.width = drawable.width;
  scene.height = drawable.height;
  scene.states.resize(record.states.size());

  const MainCamera& camera = classification->camera;
  scene.camera_projection = camera.projection;
  scene.camera_viewport = camera.viewport;
  scene.camera_valid = camera.valid;
  if (camera.valid && is_perspective_projection(camera.projection) && camera.viewport[3] > 0 &&
      camera.projection[1][1] != 0.0f)
    scene.pixel_spread =
        std::abs(2.0f / (camera.projection[1][1] * static_cast<float>(camera.viewport[3])));
  else if (camera.valid && camera.viewport[3] > 0 && camera.projection[1][1] != 0.0f)
    scene.pixel_size_parallel =
        std::abs(2.0f / (camera.projection[1][1] * static_cast<float>(camera.viewport[3])));
  // Modulating passes folded into the traced draws they redraw (classify.hpp, folds_onto).
  std::vector<std::vector<size_t>> passes_onto(record.commands.size());
  for (size_t i = 0; i < classification->labels.size() && i < record.commands.size(); ++i)
    if (const uint32_t onto = classification->labels[i].folds_onto;
        onto != 0 && onto - 1 < record.commands.size())
      passes_onto[onto - 1].push_back(i);
  std::vector<FoldedPass> folded;
  auto identity_id = [&](size_t command) -> uint64_t {
    const int32_t k =
        command < classification->identity_of.size() ? classification->identity_of[command] : -1;
    return k >= 0 ? classification->identities[static_cast<size_t>(k)].id : 0;
  };
  rec::Decomposed scratch;
  Batcher batcher(scene.instances, options.known_geometry, scratch);
  std::vector<uint8_t> state_used(record.states.size(), 0);
  for (size_t i = 0; i < record.commands.size(); ++i) {
    const rec::Command& command = record.commands[i];
    const auto* draw = std::get_if<rec::Draw>(&command);
    if (const auto* clear = std::get_if<rec::Clear>(&command);
        clear != nullptr && !out.any_traced && (clear->mask & GL_COLOR_BUFFER_BIT) != 0)
      scene.clear_color = clear->color;
    if (draw != nullptr && out.classes[i] == DrawClass::kSky) {
      // Drawn by raster mode where GL draws it, and held for the rays that miss the world.
      out.any_sky = true;
      state_used[draw->state] = 1;
      batcher.add(*draw, record.states[draw->state], identity_id(i), /*sky=*/true);
    }
    // Fake shadows are not drawn: the tracer's shadows are real.
    if (draw != nullptr && out.classes[i] == DrawClass::kShadow) continue;
    const bool viewmodel = out.classes[i] == DrawClass::kViewmodel;
    const bool split = out.classes[i] == DrawClass::kSplitByAlpha;
    if (draw == nullptr || (out.classes[i] != DrawClass::kTraced && !viewmodel && !split)) {
      // Clears act on the G-buffer in its pass; everything else before the first traced draw is
      // drawn first, the rest after the trace.
      if (!out.any_traced || std::holds_alternative<rec::Clear>(command))
        out.gbuffer_pass.push_back(i);
      else
        out.after_trace.push_back(i);
      continue;
    }
    const rec::StateSnapshot& state = record.states[draw->state];
    if (!out.any_traced) scene.default_targets = targets_of(state.raster->ops, drawable);
    out.any_traced = true;
    out.traced[i] = 1;
    out.gbuffer_pass.push_back(i);
    // Its opaque fragments go into the G-buffer, the others are blended over the trace.
    if (split) {
      out.split_by_alpha[i] = 1;
      out.after_trace.push_back(i);
    }
    state_used[draw->state] = 1;
    if (scene.states[draw->state].history_id == 0) {
      const int32_t k =
          i < classification->identity_of.size() ? classification->identity_of[i] : -1;
      set_history(state, k >= 0 ? &classification->identities[static_cast<size_t>(k)] : nullptr,
                  scene.states[draw->state]);
    }
    // A view model is drawn into the G-buffer in its own depth range and projection and lit by
    // rays, but is no geometry for them: it casts no shadow on the world (nor on itself).
    if (viewmodel) continue;
    folded.clear();
    for (size_t pass : passes_onto[i]) {
      const rec::Draw& pass_draw = std::get<rec::Draw>(record.commands[pass]);
      folded.push_back({&pass_draw, &record.states[pass_draw.state]});
    }
    batcher.add(*draw, state, identity_id(i), /*sky=*/false, folded, /*opaque_part=*/split);
  }
  batcher.close();
  // Clears after the last traced draw clear for the draws after them alone, which raster mode
  // draws after the trace: they go there, in record order. In the G-buffer pass a depth clear
  // would come before every such draw (xscreensaver glplanet clears depth between its alpha
  // mask and its night pass, whose sphere then failed the depth test against the mask's), and a
  // colour clear would erase a traced surface GL shows until then.
  if (out.any_traced) {
    size_t last_traced = 0;
    for (size_t i = 0; i < out.traced.size(); ++i)
      if (out.traced[i]) last_traced = i;
    std::vector<size_t> trailing;
    std::erase_if(out.gbuffer_pass, [&](size_t i) {
      const bool moves = i > last_traced && std::holds_alternative<rec::Clear>(record.commands[i]);
      if (moves) trailing.push_back(i);
      return moves;
    });
    if (!trailing.empty()) {
      std::vector<size_t> merged;
      merged.reserve(out.after_trace.size() + trailing.size());
      std::merge(out.after_trace.begin(), out.after_trace.end(), trailing.begin(), trailing.end(),
                 std::back_inserter(merged));
      out.after_trace = std::move(merged);
    }
  }

  // Per-state lighting. Lights are shared between states that have the same light (each light
  // gets one shadow bit for lamp markers, light_setup.hpp). Unlit states have no GL lights; where
  // bounce rays hit their surfaces these are lit by the first lit state's lights.
  int first_lit = -1;
  bool any_light = false;
  for (size_t s = 0; s < record.states.size(); ++s) {
    if (!state_used[s]) continue;
    const rec::StateSnapshot& state = record.states[s];
    const rec::LightingState& lighting = *state.lighting;
    TraceState& t = scene.states[s];
    t.viewer = viewer_of_projection(state.transform->projection);
    t.targets = targets_of(state.raster->ops, drawable);
    const rec::FogState& fog = state.raster->fog;
    t.fog_mode = fog_mode_of(fog);
    t.fog_color = fog.color;
    const float range = fog.end - fog.start;
    t.fog_params = glm::vec4(fog.density, fog.start, fog.end, range != 0.0f ? 1.0f / range : 1.0f);
    if (!lighting.enabled) continue;
    t.local_viewer = lighting.local_viewer;
    t.two_side = lighting.two_side;
    t.separate_specular = lighting.separate_specular;
    t.specular_material = reflects_specularly(lighting);
    if (first_lit < 0) first_lit = static_cast<int>(s);
    t.global_ambient = lighting.model_ambient;
    for (int l = 0; l < rec::kMaxLights; ++l) {
      if (!(lighting.light_mask & (1u << l))) continue;
      t.lights.push_back(light_index(scene.lights, light_of(lighting.lights[l])));
      any_light = true;
    }
  }
  // A lit scene without any enabled light gets the default light only when asked for.
  if (options.default_light && first_lit >= 0 && !any_light) {
    scene.lights.push_back(default_light());
    for (size_t s = 0; s < record.states.size(); ++s)
      if (state_used[s] && record.states[s].lighting->enabled) scene.states[s].lights = {0};
  }
  if (first_lit >= 0) {
    for (size_t s = 0; s < record.states.size(); ++s) {
      if (!state_used[s] || record.states[s].lighting->enabled) continue;
      scene.states[s].lights = scene.states[first_lit].lights;
      scene.states[s].global_ambient = scene.states[first_lit].global_ambient;
    }
  }
}

}  // namespace glpt::rt
