// glRasterPos* and glWindowPos* (GL 1.5 2.13; GL 1.4 2.13 for WindowPos).
//
// The raster position is computed on the CPU with Mesa's float arithmetic in Mesa's order of
// operations (src/mesa/main/rastpos.c, _mesa_RasterPos), because Mesa does exactly that for
// fixed-function state and its results decide where bitmaps land and what colour they have.
// Mesa's choices that differ from a literal reading of the spec, kept on purpose:
// - an invalid raster position leaves every other raster attribute as it was;
// - without lighting the raster colours are the current colours unclamped (queries show them);
// - the raster distance is the eye-space length sqrt(x^2 + y^2 + z^2) of the undivided eye
//   position (or the current fog coordinate with GL_FOG_COORDINATE);
// - lighting uses the front material only, the current normal as given (never normalized), and
//   the *object-space* vertex for positional lights and the local viewer; lights, the normal and
//   the viewer direction are in eye space or in object space depending on what Mesa calls
//   _NeedEyeCoords (see need_eye_coordinates).
#include "gl_shim/pixels/raster_position.hpp"

#include <algorithm>
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/vertex_shading.hpp"
#include "gl_shim/textures/texture_snapshot.hpp"

namespace glpt {
namespace {

float dot4(const glm::vec4& a, const glm::vec4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}

bool inside_view_volume(const glm::vec4& clip) {
  if (clip.z < -clip.w || clip.z > clip.w) return false;
  return !(clip.x > clip.w || clip.x < -clip.w || clip.y > clip.w || clip.y < -clip.w);
}

// Mesa tests user clip planes in clip space: each eye-space plane times the inverse projection
// (_ClipUserPlane).
bool inside_clip_planes(Context& ctx, const glm::vec4& clip) {
  const uint8_t mask = ctx.transform.clip_plane_mask;
  if (mask == 0) return true;
  const glm::mat4& inverse = ctx.matrices.projection.top_matrix().inverse();
  for (int p = 0; p < rec::kMaxClipPlanes; ++p) {
    if (!(mask & (1u << p))) continue;
    const glm::vec4 plane = transform_row_vector(ctx.transform.clip_planes[p], inverse);
    if (dot4(clip, plane) < 0.0f) return false;
  }
  return true;
}

}  // namespace

void set_raster_position(Context& ctx, const glm::vec4& object) {
  ctx.matrices.validate_for_draw(ctx.transform.clip_plane_mask);  // Mesa's _mesa_update_state
  ctx.flushed_tex_coord = ctx.current.tex_coord;                  // Mesa's FLUSH_CURRENT
  rec::RasterPosition& rp = ctx.raster_position;
  const glm::vec4 eye = transform_point(ctx.matrices.modelview.top(), object);
  const glm::vec4 clip = transform_point(ctx.matrices.projection.top(), eye);
  if (!inside_view_volume(clip) || !inside_clip_planes(ctx, clip)) {
    rp.valid = false;  // Mesa leaves the other raster attributes unchanged
    return;
  }
  const float d = clip.w == 0.0f ? 1.0f : 1.0f / clip.w;
  const glm::vec3 ndc(clip.x * d, clip.y * d, clip.z * d);
  glm::vec3 scale, translate;
  viewport_transform(ctx, scale, translate);
  rp.window = glm::vec4(ndc.x * scale.x + translate.x, ndc.y * scale.y + translate.y,
                        ndc.z * scale.z + translate.z, clip.w);
  rp.distance = ctx.raster.fog.coord_source == GL_FOG_COORDINATE
                    ? ctx.current.fog_coord
                    : std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);

  rec::TexturingState texturing;
  snapshot_texturing(ctx, texturing);
  const bool eye_space = need_eye_coordinates(ctx, texturing);
  const glm::vec3 normal =
      eye_space
          ? transform_normal(ctx.current.normal, ctx.matrices.modelview.top_matrix().inverse())
          : ctx.current.normal;
  if (ctx.lighting.enabled) {
    // Mesa lights the raster position with the front material, at the object-space vertex.
    const LitColors lit =
        light_vertex(ctx, ctx.lighting.material[0], eye_space, glm::vec3(object), normal);
    rp.color = lit.color;
    rp.secondary_color = lit.secondary;
  } else {
    rp.color = ctx.current.color;
    rp.secondary_color = ctx.current.secondary_color;
  }
  for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
    glm::vec4 tc = ctx.current.tex_coord[u];
    const TextureUnit& unit = ctx.textures.units[u];
    if (unit.texgen_mask != 0) tc = generate_tex_coord(unit, object, eye, normal, tc);
    rp.tex_coord[u] = transform_point(ctx.matrices.texture[u].top(), tc);
  }
  rp.valid = true;
  render_mode_raster_position(ctx);  // a hit in selection mode
}

void set_window_position(Context& ctx, float x, float y, float z) {
  ctx.flushed_tex_coord = ctx.current.tex_coord;  // Mesa's FLUSH_CURRENT
  rec::RasterPosition& rp = ctx.raster_position;
  const FramebufferState& fb = ctx.framebuffer;
  // In float, from Mesa's float depth range.
  const float n = static_cast<float>(fb.depth_near), f = static_cast<float>(fb.depth_far);
  const float depth = std::clamp(z, 0.0f, 1.0f) * (f - n) + n;
  rp.window = glm::vec4(x, y, depth, 1.0f);
  rp.valid = true;
  rp.distance = ctx.raster.fog.coord_source == GL_FOG_COORDINATE ? ctx.current.fog_coord : 0.0f;
  rp.color = glm::clamp(ctx.current.color, 0.0f, 1.0f);
  rp.secondary_color = glm::clamp(ctx.current.secondary_color, 0.0f, 1.0f);
  rp.tex_coord = ctx.current.tex_coord;
  render_mode_raster_position(ctx);  // a hit in selection mode (Mesa's too)
}

namespace impl {

// Every variant converts to float first, as Mesa does.
void glRasterPos2d(Context& ctx, GLdouble x, GLdouble y) {
  set_raster_position(ctx, {float(x), float(y), 0.0f, 1.0f});
}
void glRasterPos2f(Context& ctx, GLfloat x, GLfloat y) {
  set_raster_position(ctx, {x, y, 0.0f, 1.0f});
}
void glRasterPos2i(Context& ctx, GLint x, GLint y) {
  set_raster_position(ctx, {float(x), float(y), 0.0f, 1.0f});
}
void glRasterPos2s(Context& ctx, GLshort x, GLshort y) {
  set_raster_position(ctx, {float(x), float(y), 0.0f, 1.0f});
}
void glRasterPos3d(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  set_raster_position(ctx, {float(x), float(y), float(z), 1.0f});
}
void glRasterPos3f(Context& ctx, GLfloat x, GLfloat y, GLfloat z) {
  set_raster_position(ctx, {x, y, z, 1.0f});
}
void glRasterPos3i(Context& ctx, GLint x, GLint y, GLint z) {
  set_raster_position(ctx, {float(x), float(y), float(z), 1.0f});
}
void glRasterPos3s(Context& ctx, GLshort x, GLshort y, GLshort z) {
  set_raster_position(ctx, {float(x), float(y), float(z), 1.0f});
}
void glRasterPos4d(Context& ctx, GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  set_raster_position(ctx, {float(x), float(y), float(z), float(w)});
}
void glRasterPos4f(Context& ctx, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  set_raster_position(ctx, {x, y, z, w});
}
void glRasterPos4i(Context& ctx, GLint x, GLint y, GLint z, GLint w) {
  set_raster_position(ctx, {float(x), float(y), float(z), float(w)});
}
void glRasterPos4s(Context& ctx, GLshort x, GLshort y, GLshort z, GLshort w) {
  set_raster_position(ctx, {float(x), float(y), float(z), float(w)});
}
// The vector forms ignore a null pointer, as the generated attribute families do.
void glRasterPos2dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glRasterPos2d(ctx, v[0], v[1]);
}
void glRasterPos2fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glRasterPos2f(ctx, v[0], v[1]);
}
void glRasterPos2iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glRasterPos2i(ctx, v[0], v[1]);
}
void glRasterPos2sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glRasterPos2s(ctx, v[0], v[1]);
}
void glRasterPos3dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glRasterPos3d(ctx, v[0], v[1], v[2]);
}
void glRasterPos3fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glRasterPos3f(ctx, v[0], v[1], v[2]);
}
void glRasterPos3iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glRasterPos3i(ctx, v[0], v[1], v[2]);
}
void glRasterPos3sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glRasterPos3s(ctx, v[0], v[1], v[2]);
}
void glRasterPos4dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glRasterPos4d(ctx, v[0], v[1], v[2], v[3]);
}
void glRasterPos4fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glRasterPos4f(ctx, v[0], v[1], v[2], v[3]);
}
void glRasterPos4iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glRasterPos4i(ctx, v[0], v[1], v[2], v[3]);
}
void glRasterPos4sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glRasterPos4s(ctx, v[0], v[1], v[2], v[3]);
}

void glWindowPos2d(Context& ctx, GLdouble x, GLdouble y) {
  set_window_position(ctx, float(x), float(y), 0.0f);
}
void glWindowPos2f(Context& ctx, GLfloat x, GLfloat y) { set_window_position(ctx, x, y, 0.0f); }
void glWindowPos2i(Context& ctx, GLint x, GLint y) {
  set_window_position(ctx, float(x), float(y), 0.0f);
}
void glWindowPos2s(Context& ctx, GLshort x, GLshort y) {
  set_window_position(ctx, float(x), float(y), 0.0f);
}
void glWindowPos3d(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  set_window_position(ctx, float(x), float(y), float(z));
}
void glWindowPos3f(Context& ctx, GLfloat x, GLfloat y, GLfloat z) {
  set_window_position(ctx, x, y, z);
}
void glWindowPos3i(Context& ctx, GLint x, GLint y, GLint z) {
  set_window_position(ctx, float(x), float(y), float(z));
}
void glWindowPos3s(Context& ctx, GLshort x, GLshort y, GLshort z) {
  set_window_position(ctx, float(x), float(y), float(z));
}
void glWindowPos2dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glWindowPos2d(ctx, v[0], v[1]);
}
void glWindowPos2fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glWindowPos2f(ctx, v[0], v[1]);
}
void glWindowPos2iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glWindowPos2i(ctx, v[0], v[1]);
}
void glWindowPos2sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glWindowPos2s(ctx, v[0], v[1]);
}
void glWindowPos3dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glWindowPos3d(ctx, v[0], v[1], v[2]);
}
void glWindowPos3fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glWindowPos3f(ctx, v[0], v[1], v[2]);
}
void glWindowPos3iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glWindowPos3i(ctx, v[0], v[1], v[2]);
}
void glWindowPos3sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glWindowPos3s(ctx, v[0], v[1], v[2]);
}

}  // namespace impl
}  // namespace glpt
