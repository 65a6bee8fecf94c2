// glBegin/glEnd and the current vertex attributes (GL 1.5 spec 2.6, 2.7).
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/geometry/attributes.hpp"
#include "gl_shim/geometry/triangulate.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/lighting.hpp"

namespace glpt {
namespace {

// One glBegin/glEnd may not grow without bound: past this many vertices the rest are dropped
// and GL_OUT_OF_MEMORY is recorded (the spec's answer when an implementation runs out).
constexpr size_t kMaxVerticesPerPrimitive = size_t{1} << 24;

rt::ColorSource color_source_of(GLenum mode) {
  switch (mode) {
    case GL_AMBIENT:
      return rt::ColorSource::kAmbient;
    case GL_DIFFUSE:
      return rt::ColorSource::kDiffuse;
    case GL_SPECULAR:
      return rt::ColorSource::kSpecular;
    case GL_EMISSION:
      return rt::ColorSource::kEmission;
    default:
      return rt::ColorSource::kAmbientAndDiffuse;
  }
}

// The material a vertex is shaded with, resolved from the lighting state.
rt::Material effective_material(const Context& ctx) {
  if (!ctx.lighting.enabled) {
    // Lighting off: GL shows the vertex colour. Fixed values for the rest keep all unlit
    // geometry on one material.
    rt::Material m;
    m.lit = false;
    m.color_source = rt::ColorSource::kAmbientAndDiffuse;
    return m;
  }
  const rec::Material& front = ctx.lighting.material[0];
  rt::Material m;
  m.ambient = front.ambient;
  m.diffuse = front.diffuse;
  m.specular = front.specular;
  m.emission = front.emission;
  m.shininess = front.shininess;
  m.lit = true;
  if (ctx.lighting.color_material && ctx.lighting.color_material_face != GL_BACK)
    m.color_source = color_source_of(ctx.lighting.color_material_mode);
  return m;
}

// The camera and lights of the frame, as the last draw saw them. Only redone when lighting or
// projection state changed since the last draw: frames of thousands of tiny primitives would
// otherwise copy the light list per primitive.
void snapshot_lighting(Context& ctx) {
  rt::Frame& f = ctx.pending;
  f.projection = ctx.matrices.projection.top();
  if (!ctx.lighting.enabled) return;
  f.global_ambient = ctx.lighting.model_ambient;
  f.lights.clear();
  for (int i = 0; i < rec::kMaxLights; ++i) {
    if (!(ctx.lighting.light_mask & (1u << i))) continue;
    const rec::Light& l = ctx.lighting.lights[i];
    rt::Light t;
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
    f.lights.push_back(t);
  }
}

}  // namespace

void attribute_vertex(Context& ctx, glm::vec4 p) {
  VertexAssembly& a = ctx.assembly;
  if (!a.inside) return;  // a vertex outside glBegin/glEnd has no effect
  if (a.vertices.size() >= kMaxVerticesPerPrimitive) {
    if (a.dropped_vertices++ == 0) record_error(ctx, GL_OUT_OF_MEMORY);
    return;
  }
  const rt::Material material = effective_material(ctx);
  if (a.materials.empty() || !(a.materials.back() == material)) a.materials.push_back(material);
  // Homogeneous vertices become object-space points; w == 0 (a point at infinity) cannot be
  // traced and yields non-finite coordinates, which the capture drops.
  const glm::vec3 pos = p.w == 1.0f ? glm::vec3(p) : glm::vec3(p) / p.w;
  a.vertices.push_back(CapturedVertex{pos, ctx.current.normal, ctx.current.color,
                                      static_cast<uint32_t>(a.materials.size() - 1)});
}

void attribute_normal(Context& ctx, glm::vec3 n) { ctx.current.normal = n; }

void attribute_color(Context& ctx, glm::vec4 c) {
  ctx.current.color = c;
  apply_color_material(ctx);
}

void attribute_tex_coord(Context& ctx, glm::vec4 t) { ctx.current.tex_coord[0] = t; }

void attribute_multi_tex_coord(Context& ctx, GLenum unit, glm::vec4 t) {
  if (unit < GL_TEXTURE0 || unit >= GL_TEXTURE0 + rec::kMaxTextureUnits)
    return record_error(ctx, GL_INVALID_ENUM);
  ctx.current.tex_coord[unit - GL_TEXTURE0] = t;
}

namespace impl {

void glBegin(Context& ctx, GLenum mode) {
  if (!is_valid_primitive_mode(mode)) return record_error(ctx, GL_INVALID_ENUM);
  // A draw: Mesa validates its derived state here (matrix analysis decides later arithmetic).
  ctx.matrices.validate_for_draw(ctx.transform.clip_plane_mask);
  ctx.assembly.begin(mode);
}

void glEnd(Context& ctx) {
  VertexAssembly& a = ctx.assembly;
  if (!a.inside) return record_error(ctx, GL_INVALID_OPERATION);
  a.inside = false;
  std::vector<TriangleIndices>& triangles = a.triangles;
  triangles.clear();
  triangulate(a.mode, static_cast<uint32_t>(a.vertices.size()), triangles);
  if (triangles.empty()) return;
  ctx.capture.add_primitive(ctx.matrices.modelview.top(), ctx.matrices.modelview_version, a,
                            triangles, ctx.raster.primitive.shade_model == GL_FLAT);
  snapshot_lighting(ctx);
  ctx.frame_dirty = true;
}

}  // namespace impl
}  // namespace glpt
