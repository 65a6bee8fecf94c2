// glBegin/glEnd and the current vertex attributes (GL 1.5 spec 2.6, 2.7).
#include <cmath>

#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/geometry/attributes.hpp"
#include "gl_shim/geometry/triangulate.hpp"
#include "gl/gl_enums.h"
#include "gl_shim/gl_impl_decls.hpp"

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
  if (!ctx.enables.is(GL_LIGHTING)) {
    // Lighting off: GL shows the vertex colour. Fixed values for the rest keep all unlit
    // geometry on one material.
    rt::Material m;
    m.lit = false;
    m.color_source = rt::ColorSource::kAmbientAndDiffuse;
    return m;
  }
  rt::Material m = ctx.lighting.front;
  m.lit = true;
  if (ctx.enables.is(GL_COLOR_MATERIAL) && ctx.lighting.color_material_face != GL_BACK)
    m.color_source = color_source_of(ctx.lighting.color_material_mode);
  return m;
}

// The camera and lights of the frame, as the last draw saw them. Only redone when lighting or
// projection state changed since the last draw: frames of thousands of tiny primitives would
// otherwise copy the light list per primitive.
void snapshot_lighting(Context& ctx) {
  const std::pair<uint64_t, uint64_t> version{ctx.lighting.material_version,
                                              ctx.matrices.projection_version};
  if (ctx.pending_snapshot_version == version) return;
  ctx.pending_snapshot_version = version;
  rt::Frame& f = ctx.pending;
  f.projection = ctx.matrices.projection.top();
  if (!ctx.enables.is(GL_LIGHTING)) return;
  f.global_ambient = ctx.lighting.model_ambient;
  f.lights.clear();
  for (int i = 0; i < kMaxLights; ++i)
    if (ctx.lighting.light_enabled[i]) f.lights.push_back(ctx.lighting.lights[i]);
}

}  // namespace

void attribute_vertex(Context& ctx, glm::vec4 p) {
  VertexAssembly& a = ctx.assembly;
  if (!a.inside) return;  // a vertex outside glBegin/glEnd has no effect
  if (a.vertices.size() >= kMaxVerticesPerPrimitive) {
    if (a.dropped_vertices++ == 0) record_error(ctx, GL_OUT_OF_MEMORY);
    return;
  }
  if (a.material_version_seen != ctx.lighting.material_version || a.materials.empty()) {
    a.materials.push_back(effective_material(ctx));
    a.material_version_seen = ctx.lighting.material_version;
  }
  // Homogeneous vertices become object-space points; w == 0 (a point at infinity) cannot be
  // traced and yields non-finite coordinates, which the capture drops.
  const glm::vec3 pos = p.w == 1.0f ? glm::vec3(p) : glm::vec3(p) / p.w;
  a.vertices.push_back(CapturedVertex{pos, ctx.current.normal, ctx.current.color,
                                      static_cast<uint32_t>(a.materials.size() - 1)});
}

void attribute_normal(Context& ctx, glm::vec3 n) { ctx.current.normal = n; }

void attribute_color(Context& ctx, glm::vec4 c) { ctx.current.color = c; }

void attribute_tex_coord(Context& ctx, glm::vec4 t) { ctx.current.tex_coord[0] = t; }

void attribute_multi_tex_coord(Context& ctx, GLenum unit, glm::vec4 t) {
  if (unit < GL_TEXTURE0 || unit >= GL_TEXTURE0 + kMaxTextureUnits)
    return record_error(ctx, GL_INVALID_ENUM);
  ctx.current.tex_coord[unit - GL_TEXTURE0] = t;
}

namespace impl {

void glBegin(Context& ctx, GLenum mode) {
  if (!is_valid_primitive_mode(mode)) return record_error(ctx, GL_INVALID_ENUM);
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
                            triangles, ctx.lighting.shade_model == GL_FLAT);
  snapshot_lighting(ctx);
  ctx.frame_dirty = true;
}

}  // namespace impl
}  // namespace glpt
