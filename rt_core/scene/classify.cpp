#include "rt_core/scene/classify.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "common/content_hash.hpp"
#include "rt_core/raster/pipeline_key.hpp"
#include "rt_core/record/decompose.hpp"
#include "rt_core/scene/fragment_opacity.hpp"
#include "rt_core/scene/light_setup.hpp"

namespace glpt::rt {
namespace {

// A camera: where a draw lands on screen. Ordered by raw bits (exact comparison).
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

bool same_camera(const Camera& a, const Camera& b) { return !(a < b) && !(b < a); }

// The same view as the main camera's: the same viewport, and a projection equal but for the
// row that maps depth (its near and far planes), to within float rounding of the same frustum
// computed for another near plane.
bool same_view_but_depth(const Camera& a, const MainCamera& main) {
  if (!main.valid || a.viewport != main.viewport) return false;
  for (int column = 0; column < 4; ++column)
    for (int row : {0, 1, 3}) {
      const float x = a.projection[column][row], y = main.projection[column][row];
      if (!(std::abs(x - y) <= 1e-5f * std::max(std::abs(x), std::abs(y)))) return false;
    }
  return true;
}

bool same_matrix(const glm::mat4& a, const glm::mat4& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Whether a draw's fragments mix with what is under them. Programs often leave GL_BLEND on and
// draw their opaque world with GL_ONE, GL_ZERO (colour and alpha, GL_FUNC_ADD or
// GL_FUNC_SUBTRACT), or a colour logic op of GL_COPY: that writes the fragment as it is.
bool mixes_with_destination(const rec::FragmentOpsState& ops) {
  const auto replaces = [](uint32_t equation, uint32_t source, uint32_t destination) {
    return (equation == GL_FUNC_ADD || equation == GL_FUNC_SUBTRACT) && source == GL_ONE &&
           destination == GL_ZERO;
  };
  if (ops.color_logic_op) return ops.logic_op != GL_COPY;
  return ops.blend &&
         !(replaces(ops.blend_equation_rgb, ops.blend_src_rgb, ops.blend_dst_rgb) &&
           replaces(ops.blend_equation_alpha, ops.blend_src_alpha, ops.blend_dst_alpha));
}

// Whether a draw shows what is under it: it mixes with the destination, and not merely through
// blending of fragments that are all opaque (fragment_opacity.hpp).
bool blends_visibly(const rec::Draw& draw, const rec::StateSnapshot& state) {
  const rec::FragmentOpsState& ops = state.raster->ops;
  if (!mixes_with_destination(ops)) return false;
  if (ops.color_logic_op) return true;
  return !(blending_keeps_an_opaque_fragment(ops) && fragments_are_opaque(draw, state));
}

bool writes_all_channels(const rec::FragmentOpsState& ops) {
  return ops.color_write[0] && ops.color_write[1] && ops.color_write[2] && ops.color_write[3];
}

// Everything about a draw that makes it traceable except its camera.
DrawClass classify_ignoring_camera(const rec::Draw& draw, const rec::StateSnapshot& state,
                                   const rec::DrawableConfig& drawable) {
  if (!draw.vertices ||
      rec::primitive_class(draw.vertices->mode) != rec::PrimitiveClass::kTriangles)
    return DrawClass::kNotTriangles;
  const rec::PrimitiveState& primitive = state.raster->primitive;
  if (primitive.polygon_mode_front != GL_FILL || primitive.polygon_mode_back != GL_FILL)
    return DrawClass::kUnfilled;
  const rec::FragmentOpsState& ops = state.raster->ops;
  if (blends_visibly(draw, state)) return DrawClass::kBlended;
  if (!writes_all_channels(ops) ||
      resolve_draw_buffer(ops.draw_buffer, drawable.double_buffered) == ColorTargets::kNone)
    return DrawClass::kMaskedColor;
  return DrawClass::kTraced;
}

// A draw's eye-space box: its vertex data's object-space box under the modelview. False when it
// has no bounds or the modelview is projective.
bool eye_bounds_of(const rec::Draw& draw, const rec::StateSnapshot& state, EyeBounds& bounds) {
  const rec::VertexKeys& keys = draw.vertices->keys();
  if (!keys.bounded() || is_projective_modelview(state.transform->modelview)) return false;
  bounds = EyeBounds::transformed(keys.bounds_min, keys.bounds_max, state.transform->modelview);
  return !bounds.empty() && std::isfinite(bounds.diagonal());
}

bool holds_the_eye(const EyeBounds& b) {
  return b.min.x < 0.0f && b.min.y < 0.0f && b.min.z < 0.0f && b.max.x > 0.0f && b.max.y > 0.0f &&
         b.max.z > 0.0f;
}

// A box around the eye whose centre is within 10 % of its half size of the eye on every axis:
// what drawing a box with the camera's translation removed makes.
bool centred_on_the_eye(const EyeBounds& b) {
  const glm::vec3 centre = 0.5f * (b.min + b.max), half = 0.5f * (b.max - b.min);
  return holds_the_eye(b) && glm::all(glm::lessThanEqual(glm::abs(centre), 0.1f * half));
}

bool encloses(const EyeBounds& outer, const EyeBounds& inner) {
  return inner.empty() || (glm::all(glm::lessThanEqual(outer.min, inner.min)) &&
                           glm::all(glm::greaterThanEqual(outer.max, inner.max)));
}

bool writes_color(const rec::FragmentOpsState& ops, const rec::DrawableConfig& drawable) {
  const bool any_channel =
      ops.color_write[0] || ops.color_write[1] || ops.color_write[2] || ops.color_write[3];
  return any_channel &&
         resolve_draw_buffer(ops.draw_buffer, drawable.double_buffered) != ColorTargets::kNone;
}

bool counts_stencil(uint32_t op) {
  return op == GL_INCR || op == GL_DECR || op == GL_INCR_WRAP || op == GL_DECR_WRAP ||
         op == GL_INVERT;
}

// A shadow volume pass: no colour written, the stencil counting where the volume's faces pass
// or fail the depth test (with EXT_stencil_two_side, front and back faces in one pass).
bool is_shadow_volume(const rec::FragmentOpsState& ops, const rec::DrawableConfig& drawable) {
  if (writes_color(ops, drawable) || !ops.stencil_test) return false;
  const rec::StencilFaceState back = ops.back_face_stencil();
  return counts_stencil(ops.stencil_depth_pass) || counts_stencil(ops.stencil_depth_fail) ||
         counts_stencil(back.depth_pass) || counts_stencil(back.depth_fail);
}

// A modelview that flattens geometry onto a plane: the planar shadow matrix, singular (for a
// point light it is projective, for a directional one affine; either way it maps space onto
// the plane, so its determinant vanishes).
bool is_flattening(const glm::mat4& modelview) {
  float scale = 1.0f;
  for (int c = 0; c < 4; ++c) scale *= glm::length(modelview[c]);
  const float det = glm::determinant(modelview);
  return std::isfinite(det) && scale > 0.0f && std::abs(det) <= 1e-4f * scale;
}

// Blending that multiplies what is there (lightmaps, detail textures) or adds to it (light
// passes).
bool modulates_or_adds(const rec::FragmentOpsState& ops) {
  const uint32_t s = ops.blend_src_rgb, d = ops.blend_dst_rgb;
  const bool modulate = (s == GL_DST_COLOR && (d == GL_ZERO || d == GL_SRC_COLOR)) ||
                        (s == GL_ZERO && (d == GL_SRC_COLOR || d == GL_SRC_ALPHA));
  const bool add = d == GL_ONE && (s == GL_ONE || s == GL_SRC_ALPHA || s == GL_DST_COLOR);
  return ops.blend && ops.blend_equation_rgb == GL_FUNC_ADD && (modulate || add);
}

// The faces of a draw as vertex numbers (at most `limit`): quads and triangles, and one face per
// primitive for strips, fans and polygons (a particle drawn as one strip each).
struct Faces {
  std::vector<std::array<uint32_t, 3>> faces;
  uint32_t total = 0;
};
Faces faces_of(const rec::VertexData& v, size_t limit) {
  Faces out;
  auto vertex = [&](uint32_t element) {
    return v.indices.empty() ? element : (element < v.indices.size() ? v.indices[element] : 0u);
  };
  const uint32_t per = v.mode == GL_QUADS ? 4 : v.mode == GL_TRIANGLES ? 3 : 0;
  for (const rec::PrimitiveRange& range : v.primitives) {
    if (per == 0) {
      if (range.count < 3) continue;
      ++out.total;
      if (out.faces.size() < limit)
        out.faces.push_back(
            {vertex(range.first), vertex(range.first + 1), vertex(range.first + 2)});
      continue;
    }
    for (uint32_t f = 0; f + per <= range.count; f += per) {
      ++out.total;
      if (out.faces.size() < limit)
        out.faces.push_back(
            {vertex(range.first + f), vertex(range.first + f + 1), vertex(range.first + f + 2)});
    }
  }
  return out;
}

// Every sampled face of the draw is small (at most a tenth of its distance to the eye) and faces
// the camera (its plane parallel to the view plane, or facing the eye).
bool small_and_facing(const rec::VertexData& v, const glm::mat4& modelview, const Faces& faces) {
  if (faces.faces.empty()) return false;
  for (const auto& face : faces.faces) {
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) {
      if (face[k] >= v.position.size()) return false;
      const glm::vec4 h = modelview * v.position[face[k]];
      if (!(h.w > 0.0f)) return false;
      p[k] = glm::vec3(h) / h.w;
    }
    const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const float area = glm::length(n);
    const glm::vec3 centre = (p[0] + p[1] + p[2]) / 3.0f;
    const float distance = glm::length(centre);
    const float size =
        std::max({glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
    if (!(area > 0.0f) || !(distance > 0.0f) || size > 0.1f * distance) return false;
    const bool parallel = std::abs(n.z) >= 0.9f * area;
    const bool towards_eye = std::abs(glm::dot(n, centre)) >= 0.9f * area * distance;
    if (!parallel && !towards_eye) return false;
  }
  return true;
}

// All vertices of the draw (at most 64 looked at) lie in one plane.
bool is_planar(const rec::VertexData& v) {
  const size_t n = std::min<size_t>(v.position.size(), 64);
  if (n < 3) return false;
  glm::vec3 p[64];
  for (size_t i = 0; i < n; ++i) {
    const glm::vec4 h = v.position[i];
    if (!(h.w != 0.0f)) return false;
    p[i] = glm::vec3(h) / h.w;
  }
  glm::vec3 normal(0.0f);
  float extent = 0.0f;
  for (size_t i = 1; i < n; ++i) extent = std::max(extent, glm::length(p[i] - p[0]));
  for (size_t i = 1; i + 1 < n && glm::length(normal) <= 1e-6f * extent * extent; ++i)
    normal = glm::cross(p[i] - p[0], p[i + 1] - p[0]);
  const float length = glm::length(normal);
  if (!(length > 0.0f) || !std::isfinite(length)) return false;
  normal /= length;
  for (size_t i = 0; i < n; ++i)
    if (!(std::abs(glm::dot(p[i] - p[0], normal)) <= 1e-3f * extent)) return false;
  return true;
}

// Whether the draw redraws vertices of a surface drawn before it in the frame (under the same
// modelview): its first, middle and last vertices are among the earlier draw's.
bool redraws_a_surface(const rec::VertexData& v, const glm::mat4& modelview,
                       const std::vector<const rec::Draw*>& surfaces,
                       const rec::FrameRecord& record) {
  if (v.position.empty()) return false;
  const glm::vec4 samples[3] = {v.position.front(), v.position[v.position.size() / 2],
                                v.position.back()};
  size_t looked = 0;
  for (auto it = surfaces.rbegin(); it != surfaces.rend() && looked < 256; ++it, ++looked) {
    const rec::Draw& earlier = **it;
    if (!same_matrix(record.states[earlier.state].transform->modelview, modelview)) continue;
    const std::vector<glm::vec4>& positions = earlier.vertices->position;
    bool all = true;
    for (const glm::vec4& s : samples)
      if (std::find(positions.begin(), positions.end(), s) == positions.end()) {
        all = false;
        break;
      }
    if (all) return true;
  }
  return false;
}

// Blending that multiplies what is there by the incoming colour (a lightmap, a detail texture).
bool modulates(const rec::FragmentOpsState& ops) {
  return ops.blend && ops.blend_equation_rgb == GL_FUNC_ADD &&
         ((ops.blend_src_rgb == GL_DST_COLOR && ops.blend_dst_rgb == GL_ZERO) ||
          (ops.blend_src_rgb == GL_ZERO && ops.blend_dst_rgb == GL_SRC_COLOR));
}

// The traced draw a later pass redraws triangle for triangle: the same geometry (positions and
// topology) under the same modelview, drawn earlier in the frame; its command + 1, or 0.
uint32_t traced_surface_under(const rec::Draw& pass, const std::vector<size_t>& surface_commands,
                              const rec::FrameRecord& record,
                              const std::vector<DrawClass>& classes) {
  const uint64_t geometry = pass.vertices->keys().geometry;
  const glm::mat4& modelview = record.states[pass.state].transform->modelview;
  size_t looked = 0;
  for (auto it = surface_commands.rbegin(); it != surface_commands.rend() && looked < 256;
       ++it, ++looked) {
    if (classes[*it] != DrawClass::kTraced) continue;
    const rec::Draw& earlier = std::get<rec::Draw>(record.commands[*it]);
    if (earlier.vertices->keys().geometry == geometry &&
        same_matrix(record.states[earlier.state].transform->modelview, modelview))
      return static_cast<uint32_t>(*it + 1);
  }
  return 0;
}

// Whether the draw lies on a surface drawn before it in the frame: all its vertices (at most 16
// looked at) in the plane of one of the earlier draw's faces (at most 256 looked at), in eye
// space. What makes a small quad a decal rather than a pane of glass.
bool lies_on_a_surface(const rec::VertexData& v, const glm::mat4& modelview,
                       const std::vector<const rec::Draw*>& surfaces,
                       const rec::FrameRecord& record) {
  const size_t n = std::min<size_t>(v.position.size(), 16);
  if (n < 3 || is_projective_modelview(modelview)) return false;
  glm::vec3 p[16];
  EyeBounds box;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec4 h = modelview * v.position[i];
    if (!(h.w != 0.0f)) return false;
    p[i] = glm::vec3(h) / h.w;
    box.extend(p[i]);
  }
  const float size = std::max(box.diagonal(), 1e-20f);
  size_t looked = 0;
  for (auto it = surfaces.rbegin(); it != surfaces.rend() && looked < 64; ++it, ++looked) {
    const rec::Draw& earlier = **it;
    const glm::mat4& earlier_modelview = record.states[earlier.state].transform->modelview;
    if (is_projective_modelview(earlier_modelview)) continue;
    const rec::VertexData& e = *earlier.vertices;
    for (const auto& face : faces_of(e, 256).faces) {
      if (face[0] >= e.position.size() || face[1] >= e.position.size() ||
          face[2] >= e.position.size())
        continue;
      glm::vec3 q[3];
      for (int k = 0; k < 3; ++k) {
        const glm::vec4 h = earlier_modelview * e.position[face[k]];
        q[k] = glm::vec3(h) / h.w;
      }
      glm::vec3 normal = glm::cross(q[1] - q[0], q[2] - q[0]);
      const float length = glm::length(normal);
      if (!(length > 0.0f) || !std::isfinite(length)) continue;
      normal /= length;
      bool on = true;
      for (size_t i = 0; i < n && on; ++i)
        on = std::abs(glm::dot(p[i] - q[0], normal)) <= 1e-3f * size;
      if (on) return true;
    }
  }
  return false;
}

// Pixel commands' fingerprints: their size and kind as geometry, their window position as
// bounds (under the identity).
DrawFingerprint pixel_fingerprint(uint32_t kind, const rec::RasterPosition& raster, uint32_t width,
                                  uint32_t height) {
  DrawFingerprint print;
  ContentHash hash;
  const uint32_t key[3] = {kind, width, height};
  hash.add_bytes(key, sizeof key);
  print.geometry = print.topology = hash.value();
  print.bounded = true;
  print.object_min = glm::vec3(raster.window.x, raster.window.y, 0.0f);
  print.object_max =
      print.object_min + glm::vec3(float(std::max(width, 1u)), float(std::max(height, 1u)), 1.0f);
  return print;
}

}  // namespace

bool is_perspective_projection(const glm::mat4& projection) {
  return projection[0][3] != 0.0f || projection[1][3] != 0.0f || projection[2][3] != 0.0f ||
         projection[3][3] != 1.0f;
}

bool is_projective_modelview(const glm::mat4& modelview) {
  return modelview[0][3] != 0.0f || modelview[1][3] != 0.0f || modelview[2][3] != 0.0f ||
         modelview[3][3] != 1.0f;
}

const char* draw_kind_name(DrawKind kind) {
  switch (kind) {
    case DrawKind::kNone:
      return "none";
    case DrawKind::kStatic:
      return "static";
    case DrawKind::kMoving:
      return "moving";
    case DrawKind::kDeforming:
      return "deforming";
    case DrawKind::kBlended:
      return "blended";
    case DrawKind::kParticles:
      return "particles";
    case DrawKind::kMultipass:
      return "multipass";
    case DrawKind::kDecal:
      return "decal";
    case DrawKind::kOverlay:
      return "overlay";
    case DrawKind::kSky:
      return "sky";
    case DrawKind::kShadow:
      return "shadow";
    case DrawKind::kViewmodel:
      return "viewmodel";
    case DrawKind::kLines:
      return "lines";
    case DrawKind::kHidden:
      return "hidden";
  }
  return "none";
}

MainCamera find_main_camera(const rec::FrameRecord& record, const rec::DrawableConfig& drawable) {
  struct Tally {
    uint64_t triangles = 0;
    size_t first = 0;  // command of its first draw
    float depth_near = 0.0f, depth_far = 1.0f;
  };
  std::map<Camera, Tally> per_camera;
  for (size_t i = 0; i < record.commands.size(); ++i) {
    const auto* draw = std::get_if<rec::Draw>(&record.commands[i]);
    if (draw == nullptr) continue;
    const rec::StateSnapshot& state = record.states[draw->state];
    if (classify_ignoring_camera(*draw, state, drawable) != DrawClass::kTraced) continue;
    auto [it, added] = per_camera.try_emplace(camera_of(state));
    if (added) {
      it->second.first = i;
      it->second.depth_near = state.transform->depth_near;
      it->second.depth_far = state.transform->depth_far;
    }
    it->second.triangles += draw->vertices->vertex_count();
  }
  bool any_perspective = false;
  uint64_t most = 0;
  for (const auto& [camera, tally] : per_camera) {
    const bool perspective = is_perspective_projection(camera.projection);
    if (perspective && !any_perspective) most = 0;
    if (perspective || !any_perspective) most = std::max(most, tally.triangles);
    any_perspective = any_perspective || perspective;
  }
  MainCamera main;
  size_t first = ~size_t{0};
  for (const auto& [camera, tally] : per_camera) {
    if (any_perspective && !is_perspective_projection(camera.projection)) continue;
    // At least a fifth of the most: a sky of a dozen triangles drawn first is no candidate.
    if (tally.triangles * 5 < most || tally.first >= first) continue;
    first = tally.first;
    main.projection = camera.projection;
    main.viewport = camera.viewport;
    main.depth_near = tally.depth_near;
    main.depth_far = tally.depth_far;
    main.valid = true;
  }
  return main;
}

DrawClass classify_draw(const rec::Draw& draw, const rec::StateSnapshot& state,
                        const MainCamera& camera, const rec::DrawableConfig& drawable) {
  const DrawClass cls = classify_ignoring_camera(draw, state, drawable);
  if (cls != DrawClass::kTraced) return cls;
  if (!is_perspective_projection(state.transform->projection) &&
      (!camera.valid || is_perspective_projection(camera.projection)))
    return DrawClass::kOverlay;
  if (!camera.valid || !same_camera(camera_of(state), {camera.projection, camera.viewport}))
    return DrawClass::kOtherCamera;
  return DrawClass::kTraced;
}

namespace {

// Whether a draw's depth range puts it at the far plane or behind every depth the main camera's
// range can hold (the world in [0, 0.999], a sky dome in [0.999, 1], trigger-rally): whatever
// its size or place, it is seen only where nothing of the world is.
bool behind_the_world(const rec::TransformState& transform, const MainCamera& camera) {
  const float near_depth = std::min(transform.depth_near, transform.depth_far);
  if (near_depth == 1.0f) return true;
  if (!camera.valid ||
      (transform.depth_near == camera.depth_near && transform.depth_far == camera.depth_far))
    return false;
  return near_depth >= std::max(camera.depth_near, camera.depth_far);
}

}  // namespace

void find_sky(const rec::FrameRecord& record, const MainCamera& camera,
              std::vector<DrawClass>& classes) {
  // The run of unlit draws without depth writes or test before the first traced draw (their
  // union must hold the eye: six faces of a box each do not), draws at the far plane or behind
  // the main camera's depth range, and, after the world, an unlit box centred on the eye around
  // everything drawn before it. Draws under the main camera's view with other near and far
  // planes count as the main camera's here.
  std::vector<size_t> run;
  EyeBounds run_bounds, world;
  bool world_started = false;
  for (size_t i = 0; i < record.commands.size() && i < classes.size(); ++i) {
    if (classes[i] != DrawClass::kTraced && classes[i] != DrawClass::kOtherCamera) continue;
    const rec::Draw& draw = std::get<rec::Draw>(record.commands[i]);
    const rec::StateSnapshot& state = record.states[draw.state];
    if (classes[i] == DrawClass::kOtherCamera && !same_view_but_depth(camera_of(state), camera))
      continue;
    const rec::TransformState& transform = *state.transform;
    if (behind_the_world(transform, camera)) {
      classes[i] = DrawClass::kSky;
      continue;
    }
    const rec::FragmentOpsState& ops = state.raster->ops;
    EyeBounds bounds;
    const bool unlit_with_bounds = !state.lighting->enabled && eye_bounds_of(draw, state, bounds);
    if (world_started) {
      if (unlit_with_bounds && centred_on_the_eye(bounds) && encloses(bounds, world))
        classes[i] = DrawClass::kSky;
      else if (unlit_with_bounds || eye_bounds_of(draw, state, bounds))
        world.extend(bounds);
      continue;
    }
    if (unlit_with_bounds && (!ops.depth_write || !ops.depth_test)) {
      run.push_back(i);
      run_bounds.extend(bounds);
    } else if (unlit_with_bounds && centred_on_the_eye(bounds)) {
      classes[i] = DrawClass::kSky;
    } else {
      world_started = true;
      if (unlit_with_bounds || eye_bounds_of(draw, state, bounds)) world.extend(bounds);
    }
  }
  if (!run.empty() && holds_the_eye(run_bounds))
    for (size_t i : run) classes[i] = DrawClass::kSky;
}

void classify_frame(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
                    DrawIdentities* identities, FrameClassification& out) {
  const size_t n = record.commands.size();
  out.camera = find_main_camera(record, drawable);
  out.classes.assign(n, DrawClass::kNotTriangles);
  out.labels.assign(n, CommandLabel());
  for (size_t i = 0; i < n; ++i)
    if (const auto* draw = std::get_if<rec::Draw>(&record.commands[i]))
      out.classes[i] = classify_draw(*draw, record.states[draw->state], out.camera, drawable);
  find_sky(record, out.camera, out.classes);

  // Identities first: motion is per draw, relative to the previous frame.
  out.prints.clear();
  std::vector<size_t> printed;  // command of each fingerprint
  for (size_t i = 0; i < n; ++i) {
    const rec::Command& command = record.commands[i];
    if (const auto* draw = std::get_if<rec::Draw>(&command)) {
      out.prints.push_back(fingerprint_of(*draw, record.states[draw->state]));
    } else if (const auto* bitmap = std::get_if<rec::Bitmap>(&command)) {
      out.prints.push_back(pixel_fingerprint(1, bitmap->raster, bitmap->width, bitmap->height));
    } else if (const auto* pixels = std::get_if<rec::DrawPixels>(&command)) {
      if (!pixels->counted) continue;
      out.prints.push_back(pixel_fingerprint(2, pixels->raster, pixels->width, pixels->height));
    } else if (const auto* copy = std::get_if<rec::CopyPixels>(&command)) {
      if (!copy->counted) continue;
      out.prints.push_back(pixel_fingerprint(3, copy->raster, copy->width, copy->height));
    } else {
      continue;
    }
    printed.push_back(i);
  }
  out.identities.assign(out.prints.size(), DrawIdentity());
  if (identities != nullptr) identities->match(out.prints, out.identities);
  out.identity_of.assign(n, -1);
  for (size_t k = 0; k < printed.size(); ++k) {
    out.identity_of[printed[k]] = static_cast<int32_t>(k);
    CommandLabel& label = out.labels[printed[k]];
    label.id = out.identities[k].id;
    label.calls = 1;
  }

  // Particles: runs of consecutive blended draws whose faces are all small and face the camera,
  // eight faces or more in all (one draw of many quads, or one draw per billboard).
  std::vector<uint8_t> particle(n, 0);
  {
    size_t run_start = 0, run_faces = 0;
    bool in_run = false;
    auto close_run = [&](size_t end) {
      if (in_run && run_faces >= 8)
        for (size_t j = run_start; j < end; ++j) particle[j] = particle[j] == 2 ? 1 : 0;
      else
        for (size_t j = run_start; j < end && in_run; ++j) particle[j] = 0;
      in_run = false;
      run_faces = 0;
    };
    for (size_t i = 0; i < n; ++i) {
      const auto* draw = std::get_if<rec::Draw>(&record.commands[i]);
      if (draw == nullptr) continue;
      const rec::StateSnapshot& state = record.states[draw->state];
      const rec::VertexData& v = *draw->vertices;
      const bool blended = blends_visibly(*draw, state);
      bool candidate = false;
      size_t count = 0;
      if (blended && is_perspective_projection(state.transform->projection)) {
        if (rec::primitive_class(v.mode) == rec::PrimitiveClass::kPoints) {
          candidate = true;
          count = v.vertex_count();
        } else if (rec::primitive_class(v.mode) == rec::PrimitiveClass::kTriangles) {
          const Faces faces = faces_of(v, 64);
          candidate = small_and_facing(v, state.transform->modelview, faces);
          count = v.mode == GL_TRIANGLES ? (faces.total + 1) / 2 : faces.total;
        }
      }
      if (!candidate) {
        close_run(i);
        continue;
      }
      if (!in_run) {
        in_run = true;
        run_start = i;
      }
      particle[i] = 2;
      run_faces += count;
    }
    close_run(n);
  }

  bool world_started = false, world_depth_tested = false, volume_seen = false;
  bool depth_cleared_in_world = false;
  std::vector<const rec::Draw*> surfaces;  // opaque depth-writing draws so far
  std::vector<size_t> surface_commands;    // and their commands
  for (size_t i = 0; i < n; ++i) {
    const rec::Command& command = record.commands[i];
    CommandLabel& label = out.labels[i];
    if (const auto* clear = std::get_if<rec::Clear>(&command)) {
      if (world_started && (clear->mask & GL_DEPTH_BUFFER_BIT)) depth_cleared_in_world = true;
      continue;
    }
    if (const auto* bitmap = std::get_if<rec::Bitmap>(&command)) {
      label.kind = DrawKind::kOverlay;
      label.calls = bitmap->calls;
      continue;
    }
    if (std::holds_alternative<rec::DrawPixels>(command) ||
        std::holds_alternative<rec::CopyPixels>(command)) {
      if (label.calls > 0) label.kind = DrawKind::kOverlay;
      continue;
    }
    const auto* draw = std::get_if<rec::Draw>(&command);
    if (draw == nullptr) continue;
    const rec::StateSnapshot& state = record.states[draw->state];
    const rec::FragmentOpsState& ops = state.raster->ops;
    const rec::TransformState& transform = *state.transform;
    const rec::VertexData& v = *draw->vertices;
    label.calls = std::max<uint32_t>(1, static_cast<uint32_t>(v.primitives.size()));
    DrawClass& cls = out.classes[i];
    const bool triangles = rec::primitive_class(v.mode) == rec::PrimitiveClass::kTriangles;
    const bool perspective = is_perspective_projection(transform.projection);
    const bool blended = blends_visibly(*draw, state);
    auto set = [&](DrawKind kind, DrawClass render) {
      label.kind = kind;
      cls = render;
    };
    if (cls == DrawClass::kSky) {
      label.kind = DrawKind::kSky;
      continue;
    }
    if (is_shadow_volume(ops, drawable)) {
      volume_seen = true;
      set(DrawKind::kShadow, DrawClass::kShadow);
      continue;
    }
    if (!writes_color(ops, drawable)) {
      label.kind = DrawKind::kHidden;
      continue;
    }
    const bool dark_or_blended = blended || !state.lighting->enabled;
    if ((volume_seen && ops.stencil_test && ops.stencil_func != GL_ALWAYS && dark_or_blended) ||
        (triangles && perspective && is_flattening(transform.modelview) &&
         (dark_or_blended || ops.stencil_test))) {
      set(DrawKind::kShadow, DrawClass::kShadow);
      continue;
    }
    // The depth test off after a depth-tested world: drawn over it (a crosshair, a HUD in 3-D).
    // A program that never tests depth draws its world that way: that stays the world.
    // Parallel projections are 2-D over a perspective world. A program without one has its
    // world under its main parallel camera when it is 3-D (orthographic, depth-tested or lit);
    // a menu screen of unlit quads without the depth test is 2-D.
    const bool parallel_world =
        out.camera.valid && !is_perspective_projection(out.camera.projection) &&
        same_camera(camera_of(state), {out.camera.projection, out.camera.viewport}) &&
        (ops.depth_test || state.lighting->enabled);
    if ((!perspective && !parallel_world) || (!ops.depth_test && world_depth_tested)) {
      set(DrawKind::kOverlay,
          cls == DrawClass::kTraced || cls == DrawClass::kOtherCamera ? DrawClass::kOverlay : cls);
      continue;
    }
    if (particle[i]) {
      label.kind = DrawKind::kParticles;
      continue;
    }
    if (!triangles || cls == DrawClass::kUnfilled) {
      label.kind = DrawKind::kLines;
      continue;
    }
    const bool same_viewport = transform.viewport == out.camera.viewport;
    const bool own_depth_range = transform.depth_near != out.camera.depth_near ||
                                 transform.depth_far != out.camera.depth_far;
    const bool own_projection = !same_matrix(transform.projection, out.camera.projection);
    if (!blended && world_started && out.camera.valid && same_viewport &&
        (own_depth_range || (own_projection && depth_cleared_in_world))) {
      // Traced in its own depth range and projection when it could be traced at all.
      set(DrawKind::kViewmodel, cls == DrawClass::kTraced || cls == DrawClass::kOtherCamera
                                    ? DrawClass::kViewmodel
                                    : cls);
      continue;
    }
    const rec::PrimitiveState& primitive = state.raster->primitive;
    const bool offset = primitive.offset_fill &&
                        (primitive.offset_factor != 0.0f || primitive.offset_units != 0.0f);
    if (blended) {
      const bool later_pass = ops.depth_test && !ops.depth_write &&
                              (ops.depth_func == GL_EQUAL || ops.depth_func == GL_LEQUAL) &&
                              modulates_or_adds(ops);
      if (offset) {
        label.kind = DrawKind::kDecal;
      } else if (later_pass && (ops.depth_func == GL_EQUAL ||
                                redraws_a_surface(v, transform.modelview, surfaces, record))) {
        label.kind = DrawKind::kMultipass;
        if (modulates(ops))
          label.folds_onto = traced_surface_under(*draw, surface_commands, record, out.classes);
      } else if (!ops.depth_write && world_started && is_planar(v) &&
                 lies_on_a_surface(v, transform.modelview, surfaces, record)) {
        label.kind = DrawKind::kDecal;
      } else {
        label.kind = DrawKind::kBlended;
        // A solid object with see-through texels (windows, cut-out edges) under the main
        // camera: traced where its fragments are opaque, blended over the trace elsewhere.
        if (cls == DrawClass::kBlended && out.camera.valid && writes_all_channels(ops) &&
            same_camera(camera_of(state), {out.camera.projection, out.camera.viewport}) &&
            !own_depth_range && splits_by_alpha(*draw, state))
          cls = DrawClass::kSplitByAlpha;
      }
      continue;
    }
    if (world_started &&
        (offset || (!ops.depth_write && ops.depth_test && is_planar(v) &&
                    lies_on_a_surface(v, transform.modelview, surfaces, record)))) {
      label.kind = DrawKind::kDecal;
    } else {
      const size_t k = static_cast<size_t>(std::lower_bound(printed.begin(), printed.end(), i) -
                                           printed.begin());
      const DrawMotion motion =
          k < out.identities.size() ? out.identities[k].motion : DrawMotion::kNew;
      label.kind = motion == DrawMotion::kMoving      ? DrawKind::kMoving
                   : motion == DrawMotion::kDeforming ? DrawKind::kDeforming
                                                      : DrawKind::kStatic;
    }
    if (cls == DrawClass::kTraced && !world_started) {
      world_started = true;
      world_depth_tested = ops.depth_test;
    }
    if (ops.depth_write) {
      surfaces.push_back(draw);
      surface_commands.push_back(i);
    }
  }
}

}  // namespace glpt::rt
