// Primitives in GL_SELECT and GL_FEEDBACK (GL 1.5 5.2, 5.3), computed on the CPU the way Mesa 25
// computes them: st/mesa hands the draw to a private gallium draw module (st_draw_feedback.c)
// whose vertex shader is the fixed-function program run by llvmpipe's JIT, and whose primitive
// pipeline is always on:
//
//   decompose -> clip -> cull -> two-side -> polygon offset -> flat shade -> unfilled -> report
//
// (draw_pipe_validate.c; a stage runs only when the state needs it). Reported vertices are what
// that pipeline leaves in its vertex headers; everything below was measured against OSMesa
// (tests/unit/mesa_reference/mesa_render_mode_probe.c), including Mesa's defects:
// - window coordinates live in Mesa's y-inverted window space (its window-system buffers are
//   y_0_top): y = H - (y_ndc * -h/2 + (H - (y0 + h/2))), feedback reports H - y;
// - the vertex shader computes clip coordinates as c0*x + c1*y + c2*z + c3*w, then
//   x_ndc = x * (1/w) and window = fma(x_ndc, scale, translate); feedback's w is 1 / (1/w);
//   vertices made by clipping use plain multiplies and adds instead (draw_pipe_clip.c);
// - the clip test counts a NaN as outside (unordered comparisons), so primitives with NaN
//   positions vanish; a vertex with w = 0 at the origin is inside and reports NaN coordinates;
// - triangles are reported as triangles (GL_POLYGON_TOKEN 3) in the draw module's order (quads
//   (0,1,3) (1,2,3), polygons (i+1, i+2, 0)); clipped ones as a fan from the polygon's first
//   vertex, each triangle's vertices (i-1, i, 0);
// - colours are clamped; flat shading changes reported colours only on lines and triangles
//   that go through the flat-shade stage (unfilled polygon modes) and on vertices made by
//   clipping (which take the provoking colour for lines, and a stale colour for polygons);
// - polygon offset adds factor * max slope (its units count nothing: the draw module's minimum
//   resolvable depth is 0) and clamps z to [0, 1]; it is decided for a whole draw by the face
//   of its first triangle;
// - GL_LINE_RESET_TOKEN only ever starts the edges of an unfilled polygon (lines themselves are
//   never reset);
// - with per-vertex edge flags (see ImmediateLayout in render_modes.hpp; an edge flag array) every
//   edge flag reads as false, so unfilled polygons report nothing but edges along user clip
//   planes; with a false current edge flag, unfilled faces are culled (st/mesa's
//   edgeflag_culls_prims).
// Lighting is the CPU lighting of the raster position (state/vertex_shading.hpp), which agrees
// with the JIT-compiled shader to a few ulps.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/render_modes/render_modes.hpp"
#include "gl_shim/state/lighting.hpp"
#include "gl_shim/state/mesa_matrix.hpp"
#include "gl_shim/state/vertex_shading.hpp"
#include "rt_core/record/decompose.hpp"

namespace glpt {
namespace {

constexpr uint8_t kFaceFront = 1, kFaceBack = 2;
constexpr uint8_t kEdge0 = 1, kEdge1 = 2, kEdge2 = 4;
constexpr int kViewPlanes = 6;
constexpr int kMaxClippedVertices = 2 * (kViewPlanes + 8) + 1;  // draw_pipe_clip.c

// A vertex as the draw module carries it through its stages.
struct DrawVertex {
  glm::vec4 clip{0.0f};
  glm::vec4 window{0.0f};             // x, y (y-inverted window space), z, 1/w
  glm::vec4 front{0.0f}, back{0.0f};  // COL0, BCOL0
  glm::vec4 tex{0.0f};                // TEX0
  uint32_t clipmask = 0;
  bool edge_flag = true;  // the decomposition's edge flags already hold the program's
  int source = -1;        // which corner of the clipped triangle it is; -1: made by clipping
};

bool finite(float x) { return std::isfinite(x); }
// llvmpipe's clip test compares unordered: a NaN operand counts as outside.
bool greater_unordered(float a, float b) { return !(a <= b); }
float dot4(const glm::vec4& a, const glm::vec4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}

// The view volume planes as draw_context.c sets them (bit i of a clip mask is plane i).
constexpr float kViewVolume[kViewPlanes][4] = {{-1, 0, 0, 1}, {1, 0, 0, 1}, {0, -1, 0, 1},
                                               {0, 1, 0, 1},  {0, 0, 1, 1}, {0, 0, -1, 1}};

// Where reported primitives go.
class Sink {
 public:
  virtual ~Sink() = default;
  virtual void point(const DrawVertex& v) = 0;
  virtual void line(const DrawVertex& a, const DrawVertex& b) = 0;
  virtual void triangle(const DrawVertex& a, const DrawVertex& b, const DrawVertex& c) = 0;
  virtual void reset_stipple() = 0;
};

class FeedbackSink final : public Sink {
 public:
  FeedbackSink(FeedbackState& feedback, DrawModuleMemory& memory, float drawable_height)
      : f_(feedback), memory_(memory), height_(drawable_height) {}
  void point(const DrawVertex& v) override {
    feedback_value(f_, static_cast<float>(GL_POINT_TOKEN));
    vertex(v);
  }
  void line(const DrawVertex& a, const DrawVertex& b) override {
    const bool reset = memory_.line_reset_pending;
    memory_.line_reset_pending = false;
    feedback_value(f_, static_cast<float>(reset ? GL_LINE_RESET_TOKEN : GL_LINE_TOKEN));
    vertex(a);
    vertex(b);
  }
  void triangle(const DrawVertex& a, const DrawVertex& b, const DrawVertex& c) override {
    feedback_value(f_, static_cast<float>(GL_POLYGON_TOKEN));
    feedback_value(f_, 3.0f);
    vertex(a);
    vertex(b);
    vertex(c);
  }
  void reset_stipple() override { memory_.line_reset_pending = true; }

 private:
  // st_cb_feedback.c feedback_vertex: back to GL's window y, and w from 1/w.
  void vertex(const DrawVertex& v) {
    const glm::vec4 window(v.window.x, height_ - v.window.y, v.window.z, 1.0f / v.window.w);
    feedback_vertex(f_, window, v.front, v.tex);
  }
  FeedbackState& f_;
  DrawModuleMemory& memory_;
  float height_;
};

class SelectionSink final : public Sink {
 public:
  explicit SelectionSink(SelectionState& selection) : s_(selection) {}
  void point(const DrawVertex& v) override { selection_hit(s_, v.window.z); }
  void line(const DrawVertex& a, const DrawVertex& b) override {
    selection_hit(s_, a.window.z);
    selection_hit(s_, b.window.z);
  }
  void triangle(const DrawVertex& a, const DrawVertex& b, const DrawVertex& c) override {
    selection_hit(s_, a.window.z);
    selection_hit(s_, b.window.z);
    selection_hit(s_, c.window.z);
  }
  void reset_stipple() override {}

 private:
  SelectionState& s_;
};

// The rasterizer state st/mesa gives the draw module, and which stages it runs.
struct PipelineSettings {
  bool flat = false;
  bool front_ccw = true;  // in Mesa's y-inverted window space
  uint32_t fill_front = GL_FILL, fill_back = GL_FILL;
  uint8_t cull = 0;  // kFace* bits
  // Faces also culled in a draw without per-vertex edge flags whose current edge flag is false
  // (st/mesa's edgeflag_culls_prims: every edge of an unfilled face is hidden).
  uint8_t cull_without_edges = 0;
  bool two_side = false;
  bool offset_fill = false, offset_line = false, offset_point = false;
  float offset_factor = 0.0f;
  bool edge_flags_matter = false;  // some face is unfilled
  bool unfilled_stage = false, offset_stage = false, cull_stage = false;
  // The viewport in Mesa's y-inverted window space.
  glm::vec3 scale{1.0f}, translate{0.0f};
  uint8_t clip_plane_mask = 0;
  std::array<glm::vec4, rec::kMaxClipPlanes> clip_planes{};  // clip space
};

PipelineSettings pipeline_settings(Context& ctx) {
  const rec::PrimitiveState& p = ctx.raster.primitive;
  PipelineSettings s;
  s.flat = p.shade_model == GL_FLAT;
  // Gallium's facing is for y pointing down, as in Mesa's y-inverted window space: GL's
  // counter-clockwise is the draw module's.
  s.front_ccw = p.front_face == GL_CCW;
  // st/mesa gives a culled face the other face's polygon mode.
  s.fill_front = p.polygon_mode_front;
  s.fill_back = p.polygon_mode_back;
  if (p.cull_face) {
    if (p.cull_face_mode == GL_FRONT) {
      s.fill_front = s.fill_back;
      s.cull = kFaceFront;
    } else if (p.cull_face_mode == GL_BACK) {
      s.fill_back = s.fill_front;
      s.cull = kFaceBack;
    } else {
      s.cull = kFaceFront | kFaceBack;
    }
  }
  // Edge flags matter only for unfilled polygons; a false current edge flag hides every edge,
  // and st/mesa then culls the unfilled faces outright.
  s.edge_flags_matter = p.polygon_mode_front != GL_FILL || p.polygon_mode_back != GL_FILL;
  if (s.edge_flags_matter) {
    if (s.fill_front != GL_FILL) s.cull_without_edges |= kFaceFront;
    if (s.fill_back != GL_FILL) s.cull_without_edges |= kFaceBack;
  }
  s.two_side = ctx.lighting.enabled && ctx.lighting.two_side;
  s.offset_fill = p.offset_fill;
  s.offset_line = p.offset_line;
  s.offset_point = p.offset_point;
  s.offset_factor = p.offset_factor;
  s.unfilled_stage = s.fill_front != GL_FILL || s.fill_back != GL_FILL;
  s.offset_stage = s.offset_fill || s.offset_line || s.offset_point;
  s.cull_stage =
      s.unfilled_stage || s.offset_stage || s.two_side || (s.cull | s.cull_without_edges) != 0;
  glm::vec3 scale, translate;
  viewport_transform(ctx, scale, translate);
  const float height = ctx.render_mode.drawable_height;
  s.scale = glm::vec3(scale.x, -scale.y, scale.z);
  s.translate = glm::vec3(translate.x, height - translate.y, translate.z);
  // Mesa's _ClipUserPlane: the eye-space planes times the inverse projection.
  s.clip_plane_mask = ctx.transform.clip_plane_mask;
  if (s.clip_plane_mask != 0) {
    const glm::mat4& inverse = ctx.matrices.projection.top_matrix().inverse();
    for (int i = 0; i < rec::kMaxClipPlanes; ++i)
      if (s.clip_plane_mask & (1u << i))
        s.clip_planes[i] = transform_row_vector(ctx.transform.clip_planes[i], inverse);
  }
  return s;
}

// ---- the vertex shader ------------------------------------------------------------------------

// What the reported vertices carry besides their position.
struct VertexOutputs {
  bool colors = false, tex_coord = false;
};

// Mesa's STATE_NORMAL_SCALE (_ModelViewInvScale): 1, or from the inverse modelview's third row
// when the modelview does not preserve lengths.
float normal_scale(Context& ctx, bool eye) {
  MesaMatrix& modelview = ctx.matrices.modelview.top_matrix();
  if (modelview.length_preserving()) return 1.0f;
  const glm::mat4& inverse = modelview.inverse();
  float f =
      inverse[0][2] * inverse[0][2] + inverse[1][2] * inverse[1][2] + inverse[2][2] * inverse[2][2];
  if (f < 1e-12f) f = 1.0f;
  return eye ? 1.0f / std::sqrt(f) : std::sqrt(f);
}

class VertexShader {
 public:
  VertexShader(Context& ctx, const rec::StateSnapshot& state, const PipelineSettings& settings,
               VertexOutputs outputs)
      : ctx_(ctx), state_(state), s_(settings), outputs_(outputs) {
    const rec::TexturingState& texturing = *state.texturing;
    eye_space_ = need_eye_coordinates(ctx, texturing);
    lit_ = outputs.colors && ctx.lighting.enabled;
    needs_normal_ = lit_ || (outputs.tex_coord && texgen_on_unit0());
    if (needs_normal_) normal_scale_ = normal_scale(ctx, eye_space_);
  }

  DrawVertex shade(const rec::VertexData& d, uint32_t i) const {
    const CurrentAttributes& c = ctx_.current;
    DrawVertex v;
    const glm::vec4 object = d.position[i];
    const glm::mat4& m = state_.transform->modelview_projection;
    v.clip = m[0] * object.x + m[1] * object.y + m[2] * object.z + m[3] * object.w;
    v.clipmask = clip_mask(v.clip);
    const float oow = 1.0f / v.clip.w;
    for (int k = 0; k < 3; ++k)
      v.window[k] = std::fma(v.clip[k] * oow, s_.scale[k], s_.translate[k]);
    v.window.w = oow;
    if (!outputs_.colors && !outputs_.tex_coord) return v;

    const glm::vec4 color = rec::attribute_at(d.color, i, c.color);
    glm::vec4 eye(0.0f);
    glm::vec3 normal(0.0f);
    if (needs_normal_) {
      eye = transform_point(ctx_.matrices.modelview.top(), object);
      normal = rec::attribute_at(d.normal, i, c.normal);
      if (eye_space_)
        normal = transform_normal(normal, ctx_.matrices.modelview.top_matrix().inverse());
      if (state_.transform->normalize)
        normal = normalize3(normal);
      else if (eye_space_ == state_.transform->rescale_normal)
        normal *= normal_scale_;
    }
    if (outputs_.colors) {
      if (lit_) {
        const rec::LightingState& l = *state_.lighting;
        const std::array<rec::Material, 2>& materials =
            rec::attribute_at(d.material, i, l.material);
        const glm::vec3 position = eye_space_ ? glm::vec3(eye) : glm::vec3(object);
        v.front = light_vertex(ctx_, with_color_material(materials[0], l, 0, color), eye_space_,
                               position, normal)
                      .color;
        if (s_.two_side)
          v.back = light_vertex(ctx_, with_color_material(materials[1], l, 1, color), eye_space_,
                                position, -normal)
                       .color;
      } else {
        v.front = v.back = glm::clamp(color, 0.0f, 1.0f);  // the vertex colour is clamped
      }
    }
    if (outputs_.tex_coord) {
      // Texture coordinate generation and the texture matrix apply to enabled units only.
      v.tex = rec::attribute_at(d.tex_coord[0], i, c.tex_coord[0]);
      const TextureUnit& unit = ctx_.textures.units[0];
      if (unit.enabled_targets != 0) {
        if (unit.texgen_mask != 0) v.tex = generate_tex_coord(unit, object, eye, normal, v.tex);
        const glm::mat4& texture_matrix = ctx_.matrices.texture[0].top();
        if (texture_matrix != glm::mat4(1.0f)) v.tex = transform_point(texture_matrix, v.tex);
      }
    }
    return v;
  }

 private:
  bool texgen_on_unit0() const {
    const TextureUnit& unit = ctx_.textures.units[0];
    return unit.enabled_targets != 0 && unit.texgen_mask != 0;
  }

  // draw_llvm.c generate_clipmask: view volume, then the user planes (fused dot product).
  uint32_t clip_mask(const glm::vec4& c) const {
    uint32_t mask = 0;
    if (greater_unordered(c.x, c.w)) mask |= 1u << 0;
    if (greater_unordered(0.0f, c.x + c.w)) mask |= 1u << 1;
    if (greater_unordered(c.y, c.w)) mask |= 1u << 2;
    if (greater_unordered(0.0f, c.y + c.w)) mask |= 1u << 3;
    if (greater_unordered(0.0f, c.z + c.w)) mask |= 1u << 4;
    if (greater_unordered(c.z, c.w)) mask |= 1u << 5;
    for (int i = 0; i < rec::kMaxClipPlanes; ++i) {
      if (!(s_.clip_plane_mask & (1u << i))) continue;
      const glm::vec4& p = s_.clip_planes[i];
      float sum = p.x * c.x;
      sum = std::fma(p.y, c.y, sum);
      sum = std::fma(p.z, c.z, sum);
      sum = std::fma(p.w, c.w, sum);
      if (greater_unordered(0.0f, sum)) mask |= 1u << (kViewPlanes + i);
    }
    return mask;
  }

  Context& ctx_;
  const rec::StateSnapshot& state_;
  const PipelineSettings& s_;
  VertexOutputs outputs_;
  bool eye_space_ = false, lit_ = false, needs_normal_ = false;
  float normal_scale_ = 1.0f;
};

// ---- the primitive pipeline -------------------------------------------------------------------

class DrawPipeline {
 public:
  // `per_vertex_edge_flags`: the draw has them (they read as false: Mesa's defect);
  // `current_edge_flag`: the one that applies otherwise.
  DrawPipeline(const PipelineSettings& settings, DrawModuleMemory& memory, Sink& sink,
               bool per_vertex_edge_flags, bool current_edge_flag)
      : s_(settings),
        memory_(memory),
        sink_(sink),
        per_vertex_edge_flags_(s_.edge_flags_matter && per_vertex_edge_flags),
        cull_(s_.cull | (per_vertex_edge_flags_ || current_edge_flag ? 0 : s_.cull_without_edges)) {
  }

  void point(const DrawVertex& v) {
    if (v.clipmask == 0) sink_.point(v);
  }

  void line(const DrawVertex& a, const DrawVertex& b) {
    const uint32_t any = a.clipmask | b.clipmask;
    if (any == 0)
      after_clip_line(a, b);
    else if ((a.clipmask & b.clipmask) == 0)
      clip_line(a, b, any);
  }

  void triangle(const DrawVertex& a, const DrawVertex& b, const DrawVertex& c, uint8_t edges,
                bool reset) {
    // The program's edge flags are in the decomposition's edges; per-vertex ones read as false.
    Triangle t{a, b, c};
    for (DrawVertex& v : t) v.edge_flag = !per_vertex_edge_flags_;
    const uint32_t any = a.clipmask | b.clipmask | c.clipmask;
    if (any == 0)
      after_clip_triangle(t, edges, reset);
    else if ((a.clipmask & b.clipmask & c.clipmask) == 0)
      clip_triangle(t, edges, any);
  }

 private:
  using Triangle = std::array<DrawVertex, 3>;

  // ---- clip stage (draw_pipe_clip.c) ----

  float clip_distance(const DrawVertex& v, int plane) const {
    if (plane >= kViewPlanes) return dot4(v.clip, s_.clip_planes[size_t(plane - kViewPlanes)]);
    const float* p = kViewVolume[plane];
    return dot4(v.clip, glm::vec4(p[0], p[1], p[2], p[3]));
  }

  // A vertex between `out` and `in`: out + t * (in - out), window coordinates recomputed with
  // plain arithmetic. Its flat-shaded colours are not written: they are whatever temporary
  // `slot` held.
  DrawVertex interpolate(float t, const DrawVertex& out, const DrawVertex& in, int slot) const {
    auto lerp = [t](const glm::vec4& o, const glm::vec4& i) { return o + t * (i - o); };
    DrawVertex v;
    v.clip = lerp(out.clip, in.clip);
    const float oow = 1.0f / v.clip.w;
    for (int k = 0; k < 3; ++k) v.window[k] = v.clip[k] * oow * s_.scale[k] + s_.translate[k];
    v.window.w = oow;
    v.tex = lerp(out.tex, in.tex);
    DrawModuleMemory::Colors& temporary = memory_.clip_temporaries[size_t(slot)];
    if (!s_.flat) {
      temporary.front = lerp(out.front, in.front);
      temporary.back = lerp(out.back, in.back);
    }
    v.front = temporary.front;
    v.back = temporary.back;
    return v;
  }

  // copy_flat: the provoking vertex's colours into a vertex made by clipping (and its temporary).
  void copy_flat(DrawVertex& v, const DrawVertex& provoking, int slot) const {
    if (!s_.flat) return;
    v.front = provoking.front;
    v.back = provoking.back;
    memory_.clip_temporaries[size_t(slot)] = {v.front, v.back};
  }

  void clip_line(const DrawVertex& v0, const DrawVertex& v1, uint32_t mask) {
    float t0 = 0.0f, t1 = 0.0f;
    while (mask != 0) {
      const int plane = std::countr_zero(mask);
      const float dp0 = clip_distance(v0, plane), dp1 = clip_distance(v1, plane);
      if (!finite(dp0) || !finite(dp1)) return;
      if (dp1 < 0.0f) t1 = std::max(t1, dp1 / (dp1 - dp0));
      if (dp0 < 0.0f) t0 = std::max(t0, dp0 / (dp0 - dp1));
      if (t0 + t1 >= 1.0f) return;
      mask &= mask - 1;
    }
    DrawVertex a = v0, b = v1;
    if (v0.clipmask != 0) {
      a = interpolate(t0, v0, v1, 0);
      copy_flat(a, v1, 0);  // GL's provoking vertex of a line is its last
    }
    if (v1.clipmask != 0) {
      b = interpolate(t1, v1, v0, 1);
      copy_flat(b, v1, 1);
    }
    after_clip_line(a, b);
  }

  void clip_triangle(const Triangle& tri, uint8_t edges, uint32_t mask) {
    std::array<DrawVertex, kMaxClippedVertices + 1> list_a, list_b;
    std::array<bool, kMaxClippedVertices + 1> edges_a{}, edges_b{};
    auto* in = &list_a;
    auto* out = &list_b;
    auto* in_edges = &edges_a;
    auto* out_edges = &edges_b;
    for (int k = 0; k < 3; ++k) {
      (*in)[k] = tri[k];
      (*in)[k].source = k;
      (*in_edges)[k] = (edges & (1u << k)) != 0;
    }
    int n = 3, temporaries = 0;
    while (mask != 0 && n >= 3) {
      const int plane = std::countr_zero(mask);
      const bool user_plane = plane >= kViewPlanes;
      mask &= mask - 1;
      int prev = 0;
      float dp_prev = clip_distance((*in)[0], plane);
      if (!finite(dp_prev) || n >= kMaxClippedVertices) return;
      (*in)[n] = (*in)[0];
      (*in_edges)[n] = (*in_edges)[0];
      int count = 0;
      for (int i = 1; i <= n; ++i) {
        const DrawVertex& vertex = (*in)[i];
        const DrawVertex& previous = (*in)[prev];
        const float dp = clip_distance(vertex, plane);
        if (!finite(dp)) return;
        bool different_sign;
        if (dp_prev >= 0.0f) {
          if (count >= kMaxClippedVertices) return;
          (*out_edges)[count] = (*in_edges)[prev];
          (*out)[count++] = previous;
          different_sign = dp < 0.0f;
        } else {
          different_sign = !(dp < 0.0f);
        }
        if (different_sign) {
          if (temporaries >= kMaxClippedVertices + 1 || count >= kMaxClippedVertices) return;
          const int slot = temporaries++;
          const float denominator = dp - dp_prev;
          DrawVertex made;
          bool made_edge;
          if (dp < 0.0f) {  // going out
            made = -dp < dp_prev ? interpolate(dp / denominator, vertex, previous, slot)
                                 : interpolate(-dp_prev / denominator, previous, vertex, slot);
            // An edge along a user clip plane is shown, one along the view volume is not.
            made_edge = user_plane || (*in_edges)[prev];
            made.edge_flag = user_plane;
          } else {  // coming back in
            made = -dp_prev < dp ? interpolate(-dp_prev / denominator, previous, vertex, slot)
                                 : interpolate(dp / denominator, vertex, previous, slot);
            made.edge_flag = previous.edge_flag;
            made_edge = (*in_edges)[prev];
          }
          (*out_edges)[count] = made_edge;
          (*out)[count++] = made;
        }
        prev = i;
        dp_prev = dp;
      }
      std::swap(in, out);
      std::swap(in_edges, out_edges);
      n = count;
    }
    if (n < 3) return;
    // Flat shading: the polygon's first vertex takes the provoking vertex's colours.
    if (s_.flat && (*in)[0].source != 2) {
      if (temporaries >= kMaxClippedVertices + 1) return;
      const int slot = temporaries++;
      (*in)[0].source = -1;
      copy_flat((*in)[0], tri[2], slot);
    }
    // emit_poly: a fan whose first vertex is last in every triangle.
    uint8_t first = (*in_edges)[0] ? kEdge2 : 0;
    bool reset = true;
    uint8_t flags = first | kEdge0;
    for (int i = 2; i < n; ++i, flags = kEdge0, reset = false) {
      if (!(*in_edges)[i - 1]) flags &= ~kEdge0;
      if (i == n - 1 && (*in_edges)[i]) flags |= kEdge1;
      after_clip_triangle({(*in)[i - 1], (*in)[i], (*in)[0]}, flags, reset);
    }
  }

  // ---- flat shade stage (lines), then the sink ----

  void after_clip_line(DrawVertex a, const DrawVertex& b) {
    if (s_.unfilled_stage && s_.flat) {
      a.front = b.front;
      a.back = b.back;
    }
    sink_.line(a, b);
  }

  // ---- cull, two-side, offset, flat shade, unfilled (draw_pipe_*.c) ----

  void after_clip_triangle(Triangle t, uint8_t edges, bool reset) {
    float det = 0.0f;
    if (s_.cull_stage) {
      const float ex = t[0].window.x - t[2].window.x, ey = t[0].window.y - t[2].window.y;
      const float fx = t[1].window.x - t[2].window.x, fy = t[1].window.y - t[2].window.y;
      det = ex * fy - ey * fx;
      if (det != 0.0f) {
        const bool ccw = det < 0.0f;
        const uint8_t face = ccw == s_.front_ccw ? kFaceFront : kFaceBack;
        if (face & cull_) return;
      } else if (cull_ & kFaceBack) {
        return;  // zero area counts as back-facing
      }
    }
    if (s_.two_side && det * (s_.front_ccw ? -1.0f : 1.0f) < 0.0f)
      for (DrawVertex& v : t) v.front = v.back;
    if (s_.offset_stage) offset(t, det);
    if (s_.unfilled_stage && s_.flat) {
      for (int k = 0; k < 2; ++k) {
        t[k].front = t[2].front;
        t[k].back = t[2].back;
      }
    }
    if (!s_.unfilled_stage) return sink_.triangle(t[0], t[1], t[2]);
    const bool cw = det >= 0.0f;
    const uint32_t mode = cw == s_.front_ccw ? s_.fill_back : s_.fill_front;  // unfilled->mode[cw]
    auto shown = [&](int k, uint8_t bit) { return (edges & bit) && t[k].edge_flag; };
    if (mode == GL_LINE) {
      if (reset) sink_.reset_stipple();
      if (shown(2, kEdge2)) sink_.line(t[2], t[0]);
      if (shown(0, kEdge0)) sink_.line(t[0], t[1]);
      if (shown(1, kEdge1)) sink_.line(t[1], t[2]);
    } else if (mode == GL_POINT) {
      if (shown(0, kEdge0)) sink_.point(t[0]);
      if (shown(1, kEdge1)) sink_.point(t[1]);
      if (shown(2, kEdge2)) sink_.point(t[2]);
    } else {
      sink_.triangle(t[0], t[1], t[2]);
    }
  }

  // draw_pipe_offset.c: decided once per draw by its first triangle's face.
  void offset(Triangle& t, float det) {
    if (!offset_scale_) {
      uint32_t mode = s_.fill_front;
      if (s_.fill_back != s_.fill_front && (det < 0.0f) != s_.front_ccw) mode = s_.fill_back;
      const bool on = mode == GL_FILL   ? s_.offset_fill
                      : mode == GL_LINE ? s_.offset_line
                                        : s_.offset_point;
      offset_scale_ = on ? s_.offset_factor : 0.0f;
    }
    const float inv_det = 1.0f / det;
    const glm::vec4 &v0 = t[0].window, &v1 = t[1].window, &v2 = t[2].window;
    const float ex = v0.x - v2.x, ey = v0.y - v2.y, ez = v0.z - v2.z;
    const float fx = v1.x - v2.x, fy = v1.y - v2.y, fz = v1.z - v2.z;
    const float a = ey * fz - ez * fy, b = ez * fx - ex * fz;
    const float dzdx = std::fabs(a * inv_det), dzdy = std::fabs(b * inv_det);
    const float z_offset = 0.0f + (dzdx > dzdy ? dzdx : dzdy) * *offset_scale_;
    for (DrawVertex& v : t) {
      const float z = v.window.z + z_offset;
      v.window.z = z < 0.0f ? 0.0f : (z > 1.0f ? 1.0f : z);
    }
  }

  const PipelineSettings& s_;
  DrawModuleMemory& memory_;
  Sink& sink_;
  const bool per_vertex_edge_flags_;
  const uint8_t cull_;
  std::optional<float> offset_scale_;
};

// Where a draw's per-vertex edge flags begin: none, all of it, or (a glEdgeFlag first given
// inside glBegin/glEnd after some vertices) the primitives that use a vertex from that one on.
// Mesa draws the primitives before it on their own, as a draw with the edge flag of before.
struct EdgeFlagSplit {
  static constexpr uint32_t kNone = UINT32_MAX;
  uint32_t per_vertex_from = kNone;
  bool flag_before = true;
};

void report_primitives(Context& ctx, const rec::StateSnapshot& state,
                       const rec::VertexData& vertices, const EdgeFlagSplit& split) {
  RenderModeState& r = ctx.render_mode;
  if (r.mode == GL_RENDER || vertices.position.empty()) return;
  const PipelineSettings settings = pipeline_settings(ctx);
  VertexOutputs outputs;
  if (r.mode == GL_FEEDBACK) {
    const GLenum type = r.feedback.type;
    outputs.colors =
        type == GL_3D_COLOR || type == GL_3D_COLOR_TEXTURE || type == GL_4D_COLOR_TEXTURE;
    outputs.tex_coord = type == GL_3D_COLOR_TEXTURE || type == GL_4D_COLOR_TEXTURE;
  }
  const VertexShader shader(ctx, state, settings, outputs);
  std::vector<DrawVertex> shaded(vertices.position.size());
  for (uint32_t i = 0; i < shaded.size(); ++i) shaded[i] = shader.shade(vertices, i);

  // The draw module decomposes every primitive itself (its pipeline path).
  rec::AssemblyState assembly;
  assembly.pipeline = true;
  rec::Decomposed primitives;
  rec::decompose(vertices, assembly, primitives);

  FeedbackSink feedback(r.feedback, r.draw_module, r.drawable_height);
  SelectionSink selection(r.selection);
  Sink& sink = r.mode == GL_FEEDBACK ? static_cast<Sink&>(feedback) : selection;
  // Edge flags only change what unfilled triangles report.
  const bool split_draw =
      split.per_vertex_from != 0 && split.per_vertex_from != EdgeFlagSplit::kNone;
  DrawPipeline before(settings, r.draw_module, sink, false,
                      split_draw ? split.flag_before : ctx.current.edge_flag);
  DrawPipeline pipeline(settings, r.draw_module, sink,
                        split.per_vertex_from != EdgeFlagSplit::kNone, ctx.current.edge_flag);
  for (uint32_t v : primitives.points) pipeline.point(shaded[v]);
  for (const rec::DecomposedLine& l : primitives.lines)
    pipeline.line(shaded[l.v[0]], shaded[l.v[1]]);
  for (const rec::DecomposedTriangle& t : primitives.triangles) {
    const uint32_t last = std::max({t.v[0], t.v[1], t.v[2]});
    DrawPipeline& p = split_draw && last < split.per_vertex_from ? before : pipeline;
    p.triangle(shaded[t.v[0]], shaded[t.v[1]], shaded[t.v[2]], t.boundary_edges, t.reset_stipple);
  }
}

}  // namespace

void render_mode_array_draw(Context& ctx, const rec::StateSnapshot& state,
                            const rec::VertexData& vertices, bool edge_flag_array) {
  render_mode_flush_vertices(ctx);
  EdgeFlagSplit split;
  if (edge_flag_array) split.per_vertex_from = 0;
  report_primitives(ctx, state, vertices, split);
}

void render_mode_assembled_primitive(Context& ctx, const VertexAssembly& assembly) {
  ImmediateLayout& layout = ctx.render_mode.immediate;
  const rec::VertexData& vertices = assembly.vertices;
  const rec::StateSnapshot& state = ctx.recorder.record().states[assembly.state];
  EdgeFlagSplit split;
  if (vertices.source != rec::PrimitiveSource::kImmediate) {
    // Replayed from a display list: its own layout, whose edge flags are per vertex throughout
    // when the list gave any inside glBegin/glEnd.
    render_mode_flush_vertices(ctx);
    if (assembly.first_edge_flag_vertex) split.per_vertex_from = 0;
    return report_primitives(ctx, state, vertices, split);
  }
  if (layout.vertices_stored && layout.stored_state != assembly.state)
    render_mode_flush_vertices(ctx);  // a state change flushed them
  if (layout.edge_flag) {
    split.per_vertex_from = 0;
  } else if (assembly.first_edge_flag_vertex) {
    split.per_vertex_from = *assembly.first_edge_flag_vertex;
    // Mesa draws an even number of a strip's triangles before the split, to keep their facing.
    if (vertices.mode == GL_TRIANGLE_STRIP) split.per_vertex_from &= ~1u;
    split.flag_before = assembly.edge_flag_before_first;
  }
  report_primitives(ctx, state, vertices, split);
  if (assembly.first_edge_flag_vertex) layout.edge_flag = true;
  layout.vertices_stored = true;
  layout.stored_state = assembly.state;
}

void render_mode_edge_flag(Context& ctx) {
  // Inside glBegin/glEnd the assembly noted it; a display list's replay is not immediate mode.
  if (ctx.assembly.inside || ctx.lists.call_depth > 0) return;
  ImmediateLayout& layout = ctx.render_mode.immediate;
  if (layout.vertices_stored) layout.edge_flag = true;
}

}  // namespace glpt
