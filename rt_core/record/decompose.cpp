#include "rt_core/record/decompose.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "rt_core/record/texture.hpp"

namespace glpt::rec {
namespace {

constexpr uint8_t kEdge0 = 1, kEdge1 = 2, kEdge2 = 4, kAllEdges = 7;

// The most vertices Mesa's draw module processes at once (its llvm middle end's max_vertices).
constexpr uint32_t kBatchVertices = 4096;

// draw_pt_split_prim: a primitive needs `first` vertices, each further one `incr` more.
struct Split {
  uint32_t first, incr;
};
Split split_of(uint32_t mode) {
  switch (mode) {
    case GL_POINTS:
      return {1, 1};
    case GL_LINES:
      return {2, 2};
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      return {2, 1};
    case GL_TRIANGLES:
      return {3, 3};
    case GL_QUADS:
      return {4, 4};
    case GL_QUAD_STRIP:
      return {4, 2};
    default:  // strips, fans, polygons
      return {3, 1};
  }
}

uint32_t trim(uint32_t count, Split s) {
  return count < s.first ? 0 : count - (count - s.first) % s.incr;
}

// vbo_try_prim_conversion: a line strip of one segment is a line, a strip or fan of one triangle
// a triangle (so consecutive ones merge).
uint32_t converted_mode(uint32_t mode, uint32_t count) {
  if (mode == GL_LINE_STRIP && count == 2) return GL_LINES;
  if ((mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN) && count == 3) return GL_TRIANGLES;
  return mode;
}

// vbo_merge_draws: consecutive glBegin/glEnd of these modes become one draw while the previous
// ones hold whole primitives.
uint32_t merge_divisor(uint32_t mode) {
  switch (mode) {
    case GL_POINTS:
      return 1;
    case GL_LINES:
      return 2;
    case GL_TRIANGLES:
      return 3;
    case GL_QUADS:
      return 4;
    default:
      return 0;  // never merged
  }
}

// Emits the primitives of one batch; `element(i)` maps its i-th element to a vertex.
template <typename Element>
void emit_batch(uint32_t mode, uint32_t n, const Element& element, AssemblyPath path,
                bool constant_interpolation, const std::vector<uint8_t>& edge_flags,
                Decomposed& out) {
  auto edge_flag = [&](uint32_t v) -> bool {
    return edge_flags.empty() || (edge_flags.size() == 1 ? edge_flags[0] : edge_flags[v]) != 0;
  };
  // Structural edges of the GL primitive AND the edge flag of the vertex each edge starts at.
  // Mesa applies the flags to every polygon mode, strips and fans included (GL 1.5 2.6.2 says
  // they are ignored there; Mesa's draw module keeps each vertex's flag whatever the mode).
  auto triangle = [&](uint32_t a, uint32_t b, uint32_t c, uint8_t structural, bool reset = true) {
    uint8_t edges = structural;
    if ((edges & kEdge0) && !edge_flag(a)) edges &= ~kEdge0;
    if ((edges & kEdge1) && !edge_flag(b)) edges &= ~kEdge1;
    if ((edges & kEdge2) && !edge_flag(c)) edges &= ~kEdge2;
    out.triangles.push_back({{a, b, c}, edges, reset});
  };
  switch (mode) {
    case GL_POINTS:
      for (uint32_t i = 0; i < n; ++i) out.points.push_back(element(i));
      break;
    case GL_LINES:
      for (uint32_t i = 0; i + 1 < n; i += 2)
        out.lines.push_back({{element(i), element(i + 1)}, true});
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      if (n < 2) break;
      for (uint32_t i = 1; i < n; ++i) out.lines.push_back({{element(i - 1), element(i)}, i == 1});
      if (mode == GL_LINE_LOOP) out.lines.push_back({{element(n - 1), element(0)}, false});
      break;
    case GL_TRIANGLES:
      for (uint32_t i = 0; i + 2 < n; i += 3)
        triangle(element(i), element(i + 1), element(i + 2), kAllEdges);
      break;
    case GL_TRIANGLE_STRIP:
      for (uint32_t i = 0; i + 2 < n; ++i) {
        if (i & 1)
          triangle(element(i + 1), element(i), element(i + 2), kAllEdges);
        else
          triangle(element(i), element(i + 1), element(i + 2), kAllEdges);
      }
      break;
    case GL_TRIANGLE_FAN:
      for (uint32_t i = 0; i + 2 < n; ++i)
        triangle(element(0), element(i + 1), element(i + 2), kAllEdges);
      break;
    case GL_QUADS: {
      // lp_setup_draw_arrays draws a quad as rect(v0,v1,v2, v0,v2,v3) unless an input is
      // interpolated as a constant; lp_setup_draw_elements and draw_decompose split along 1-3.
      const bool diagonal_02 = path == AssemblyPath::kArrays && !constant_interpolation;
      for (uint32_t i = 0; i + 3 < n; i += 4) {
        const uint32_t a = element(i), b = element(i + 1), c = element(i + 2), d = element(i + 3);
        if (diagonal_02) {
          triangle(a, b, c, kEdge0 | kEdge1);
          triangle(a, c, d, kEdge1 | kEdge2, false);
        } else {
          triangle(a, b, d, kEdge0 | kEdge2);
          triangle(b, c, d, kEdge0 | kEdge1, false);
        }
      }
      break;
    }
    case GL_QUAD_STRIP:
      // Quad k is the polygon v(2k), v(2k+1), v(2k+3), v(2k+2); the same two triangles on every
      // path, emitted in the other order by the draw module's decomposition.
      for (uint32_t i = 0; i + 3 < n; i += 2) {
        const uint32_t a = element(i), b = element(i + 1), c = element(i + 2), d = element(i + 3);
        if (path == AssemblyPath::kPipeline) {
          triangle(c, a, d, kEdge0 | kEdge2);
          triangle(a, b, d, kEdge0 | kEdge1, false);
        } else {
          triangle(a, b, d, kEdge0 | kEdge1, false);
          triangle(c, a, d, kEdge0 | kEdge2);
        }
      }
      break;
    case GL_POLYGON:
      for (uint32_t i = 0; i + 2 < n; ++i) {
        uint8_t structural = kEdge0;
        if (i == 0) structural |= kEdge2;
        if (i + 3 == n) structural |= kEdge1;
        triangle(element(i + 1), element(i + 2), element(0), structural, i == 0);
      }
      break;
    default:
      break;
  }
}

// The clip-space position as the vertex shader computes it: c0*x + c1*y + c2*z + c3*w.
glm::vec4 transform(const glm::mat4& m, const glm::vec4& p) {
  return m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3] * p.w;
}

// llvmpipe's clip test (draw_llvm generate_clipmask, no guard band, depth clipping on): the
// comparisons Mesa makes, in its float arithmetic.
bool outside_clip_volume(const AssemblyState& a, const glm::vec4& position) {
  const glm::vec4 c = transform(a.modelview_projection, position);
  if (c.x > c.w || c.x + c.w < 0.0f || c.y > c.w || c.y + c.w < 0.0f || c.z > c.w ||
      c.z + c.w < 0.0f)
    return true;
  if (a.clip_plane_mask == 0) return false;
  const glm::vec4 eye = transform(a.modelview, position);
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if ((a.clip_plane_mask & (1u << i)) && glm::dot(a.clip_planes[i], eye) < 0.0f) return true;
  return false;
}

// Window coordinates as the draw module computes them (x * (1/w), then a fused multiply-add
// with the viewport scale and translation).
glm::vec2 window_xy(const AssemblyState& a, const glm::vec4& position) {
  const glm::vec4 c = transform(a.modelview_projection, position);
  const float inv_w = 1.0f / c.w;
  return {std::fma(c.x * inv_w, a.viewport_scale_x, a.viewport_offset_x),
          std::fma(c.y * inv_w, a.viewport_scale_y, a.viewport_offset_y)};
}

// lp_setup_analyse_triangles on a 9-vertex triangle list: when the last triangle is flat in y
// llvmpipe takes the list for a Windows Aero window border and draws only the rectangle the
// first six vertices may form, or nothing. Returns whether the batch is swallowed so, and in
// `rectangle` whether the first two triangles are still drawn.
template <typename Element>
bool aero_rectangle_quirk(const AssemblyState& a, const VertexData& v, const Element& element,
                          bool* rectangle) {
  glm::vec2 w[9];
  for (uint32_t i = 0; i < 9; ++i) w[i] = window_xy(a, v.position[element(i)]);
  if (!(w[8].y == w[7].y && w[8].y == w[6].y)) return false;
  *rectangle = w[0].x == w[1].x && w[0].x == w[5].x && w[2].x == w[3].x && w[2].x == w[4].x &&
               w[0].y == w[3].y && w[0].y == w[5].y && w[1].y == w[2].y && w[1].y == w[4].y;
  return true;
}

// Which parts of a texture environment's output depend on the primary colour.
struct ColorDependence {
  bool rgb = true, alpha = true;  // before the first enabled unit: the primary colour itself
};

bool is_color_operand(uint32_t operand) {
  return operand == GL_SRC_COLOR || operand == GL_ONE_MINUS_SRC_COLOR;
}

uint32_t combine_arguments(uint32_t combine) {
  switch (combine) {
    case GL_REPLACE:
      return 1;
    case GL_MODULATE:
    case GL_ADD:
    case GL_ADD_SIGNED:
    case GL_SUBTRACT:
    case GL_DOT3_RGB:
    case GL_DOT3_RGBA:
    case GL_DOT3_RGB_EXT:
    case GL_DOT3_RGBA_EXT:
      return 2;
    default:  // GL_INTERPOLATE
      return 3;
  }
}

// A texture environment as the combiner Mesa turns it into (texstate.c,
// calculate_derived_texenv): which sources each enabled argument reads.
struct Combiner {
  uint32_t rgb = GL_MODULATE, alpha = GL_MODULATE;
  std::array<uint32_t, 3> source_rgb{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<uint32_t, 3> source_alpha{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<uint32_t, 3> operand_rgb{GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  std::array<uint32_t, 3> operand_alpha{GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
};

Combiner combiner_of(const TexEnv& env, uint32_t base) {
  Combiner c;
  if (env.mode == GL_COMBINE) {
    c.rgb = env.combine_rgb;
    c.alpha = env.combine_alpha;
    c.source_rgb = env.source_rgb;
    c.source_alpha = env.source_alpha;
    c.operand_rgb = env.operand_rgb;
    c.operand_alpha = env.operand_alpha;
    return c;
  }
  // Components the texture lacks come from the previous stage.
  if (base == GL_ALPHA) c.source_rgb[0] = GL_PREVIOUS;
  if (base == GL_LUMINANCE || base == GL_RGB) c.source_alpha[0] = GL_PREVIOUS;
  switch (env.mode) {
    case GL_REPLACE:
    case GL_MODULATE:
      c.rgb = base == GL_ALPHA ? GL_REPLACE : env.mode;
      c.alpha = env.mode;
      break;
    case GL_DECAL:
      c.rgb = GL_INTERPOLATE;
      c.alpha = GL_REPLACE;
      c.source_alpha[0] = GL_PREVIOUS;
      if (base == GL_ALPHA || base == GL_LUMINANCE || base == GL_LUMINANCE_ALPHA ||
          base == GL_INTENSITY)
        c.source_rgb[0] = GL_PREVIOUS;
      else if (base == GL_RGB)
        c.rgb = GL_REPLACE;
      else
        c.source_rgb[2] = GL_TEXTURE;
      break;
    case GL_BLEND:
      c.rgb = GL_INTERPOLATE;
      c.alpha = GL_MODULATE;
      if (base == GL_ALPHA) {
        c.rgb = GL_REPLACE;
        break;
      }
      if (base == GL_INTENSITY) {
        c.alpha = GL_INTERPOLATE;
        c.source_alpha[0] = GL_CONSTANT;
        c.operand_alpha[2] = GL_SRC_ALPHA;
      }
      c.source_rgb[2] = GL_TEXTURE;
      c.source_alpha[2] = GL_TEXTURE;
      c.source_rgb[0] = GL_CONSTANT;
      c.operand_rgb[2] = GL_SRC_COLOR;
      break;
    case GL_ADD:
      c.rgb = base == GL_ALPHA ? GL_REPLACE : GL_ADD;
      c.alpha = base == GL_INTENSITY ? GL_ADD : GL_MODULATE;
      break;
    default:
      break;
  }
  return c;
}

// The unit's output after `c`, given what its previous stage depends on.
ColorDependence apply(const Combiner& c, ColorDependence previous) {
  auto reads = [&](uint32_t source, bool color) {
    if (source == GL_PRIMARY_COLOR) return true;
    if (source == GL_PREVIOUS) return color ? previous.rgb : previous.alpha;
    return false;  // the texture, another unit's texture, the constant colour
  };
  ColorDependence out{false, false};
  for (uint32_t i = 0; i < combine_arguments(c.rgb) && i < 3; ++i)
    out.rgb = out.rgb || reads(c.source_rgb[i], is_color_operand(c.operand_rgb[i]));
  if (c.rgb == GL_DOT3_RGBA || c.rgb == GL_DOT3_RGBA_EXT) {
    out.alpha = out.rgb;  // the dot product goes to all four components
  } else {
    for (uint32_t i = 0; i < combine_arguments(c.alpha) && i < 3; ++i)
      out.alpha = out.alpha || reads(c.source_alpha[i], false);
  }
  return out;
}

}  // namespace

PrimitiveClass primitive_class(uint32_t mode) {
  switch (mode) {
    case GL_POINTS:
      return PrimitiveClass::kPoints;
    case GL_LINES:
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      return PrimitiveClass::kLines;
    default:
      return PrimitiveClass::kTriangles;
  }
}

bool mesa_draws_strips_as_lines(const VertexData& vertices) {
  return vertices.source == PrimitiveSource::kDisplayList && vertices.mode == GL_LINE_STRIP &&
         vertices.primitives.size() >= 2;
}

void decompose(const VertexData& vertices, const AssemblyState& assembly, Decomposed& out) {
  const uint32_t vertex_count = vertices.vertex_count();
  const bool indexed = !vertices.indices.empty();
  const uint64_t element_count = indexed ? vertices.indices.size() : vertex_count;
  const PrimitiveSource source = vertices.source;
  const bool indexed_path =
      source == PrimitiveSource::kDisplayList || source == PrimitiveSource::kElements;
  const bool converts = source == PrimitiveSource::kImmediate ||
                        source == PrimitiveSource::kDisplayList;  // vbo_exec / vbo_save
  const bool strips_as_lines = mesa_draws_strips_as_lines(vertices);
  auto valid = [&](const PrimitiveRange& r) {
    return r.count != 0 && uint64_t{r.first} + r.count <= element_count;
  };
  const std::vector<PrimitiveRange>& ranges = vertices.primitives;
  size_t r = 0;
  while (r < ranges.size()) {
    if (!valid(ranges[r])) {
      ++r;
      continue;
    }
    // A group: the ranges Mesa draws as one primitive (immediate mode merges consecutive
    // glBegin/glEnd of independent primitives).
    uint32_t mode = vertices.mode;
    if (converts) mode = converted_mode(mode, ranges[r].count);
    if (strips_as_lines) mode = GL_LINE_STRIP;  // drawn segment by segment below
    const uint32_t group_first = ranges[r].first;
    uint32_t group_count = ranges[r].count;
    size_t next = r + 1;
    const uint32_t divisor = merge_divisor(mode);
    if (source == PrimitiveSource::kImmediate && !indexed && divisor != 0) {
      while (next < ranges.size() && valid(ranges[next]) &&
             ranges[next].first == group_first + group_count &&
             converted_mode(vertices.mode, ranges[next].count) == mode &&
             group_count % divisor == 0) {
        group_count += ranges[next].count;
        ++next;
      }
    }
    const size_t points = out.points.size(), lines = out.lines.size(),
                 triangles = out.triangles.size();
    bool bad_index = false;
    auto element = [&](uint32_t i) {
      if (!indexed) return group_first + i;
      const uint32_t v = vertices.indices[group_first + i];
      if (v >= vertex_count) bad_index = true;
      return v;
    };
    // Batches: the draw module cuts independent primitives every 4096 vertices (other modes are
    // kept whole: their order does not depend on the batch).
    const Split split = split_of(mode);
    const uint32_t count = trim(group_count, split);
    const uint32_t batch_max =
        split.first == split.incr ? trim(kBatchVertices, split) : std::max(count, 1u);
    for (uint32_t start = 0; start < count; start += batch_max) {
      const uint32_t n = std::min(batch_max, count - start);
      auto batch_element = [&](uint32_t i) { return element(start + i); };
      AssemblyPath path = indexed_path ? AssemblyPath::kElements : AssemblyPath::kArrays;
      const bool arrays_smooth = path == AssemblyPath::kArrays && !assembly.constant_interpolation;
      const bool aero = arrays_smooth && mode == GL_TRIANGLES && n == 9 && assembly.clip_test;
      const bool path_matters =
          (mode == GL_QUADS && arrays_smooth) || mode == GL_QUAD_STRIP || aero;
      // Quads also split by constant interpolation (emit_batch).
      if (path_matters || mode == GL_QUADS) out.assembly_consulted = true;
      if (path_matters) {
        bool pipeline = assembly.pipeline;
        for (uint32_t i = 0; i < n && !pipeline && assembly.clip_test; ++i) {
          const uint32_t v = batch_element(i);
          pipeline = v < vertex_count && outside_clip_volume(assembly, vertices.position[v]);
        }
        if (pipeline) path = AssemblyPath::kPipeline;
      }
      if (aero && path == AssemblyPath::kArrays && !bad_index) {
        bool rectangle = false;
        if (aero_rectangle_quirk(assembly, vertices, batch_element, &rectangle)) {
          if (rectangle)
            emit_batch(GL_TRIANGLES, 6, batch_element, path, false, vertices.edge_flag, out);
          continue;
        }
      }
      if (strips_as_lines) {
        for (uint32_t i = 1; i < n; ++i)
          out.lines.push_back({{batch_element(i - 1), batch_element(i)}, true});
        continue;
      }
      emit_batch(mode, n, batch_element, path, assembly.constant_interpolation, vertices.edge_flag,
                 out);
    }
    r = next;
    if (!bad_index) continue;
    // An index past the vertices drops the primitives that use it, not the whole draw.
    auto drop_bad = [&](auto& list, size_t from, auto uses_bad) {
      size_t keep = from;
      for (size_t i = from; i < list.size(); ++i)
        if (!uses_bad(list[i])) list[keep++] = list[i];
      list.resize(keep);
    };
    drop_bad(out.points, points, [&](uint32_t v) { return v >= vertex_count; });
    drop_bad(out.lines, lines, [&](const DecomposedLine& l) {
      return l.v[0] >= vertex_count || l.v[1] >= vertex_count;
    });
    drop_bad(out.triangles, triangles, [&](const DecomposedTriangle& t) {
      return t.v[0] >= vertex_count || t.v[1] >= vertex_count || t.v[2] >= vertex_count;
    });
  }
}

bool fragment_reads_primary_color(const TexturingState& texturing) {
  ColorDependence dependence;
  for (const TextureUnitState& unit : texturing.units) {
    if (unit.target == 0 || !unit.texture) continue;  // disabled units pass the colour on
    uint32_t base = unit.texture->base_format;
    if (base == GL_DEPTH_COMPONENT) base = unit.texture->sampler.depth_texture_mode;
    dependence = apply(combiner_of(unit.env, base), dependence);
  }
  return dependence.rgb || dependence.alpha;
}

AssemblyState assembly_state(const StateSnapshot& state, const VertexData& vertices) {
  AssemblyState a;
  const PrimitiveState& p = state.raster->primitive;
  const LightingState& lighting = *state.lighting;
  if (p.shade_model == GL_FLAT) {
    // Mesa's fragment shader takes a colour as a per-vertex input when lighting computes it or
    // the program gave it per vertex; otherwise the current colour is a constant of the shader.
    const bool primary_varying = lighting.enabled || (vertices.per_vertex & kPerVertexColor);
    const bool secondary_varying =
        lighting.enabled || (vertices.per_vertex & kPerVertexSecondaryColor);
    const bool reads_secondary =
        state.raster->ops.color_sum || (lighting.enabled && lighting.separate_specular);
    a.constant_interpolation =
        (primary_varying && fragment_reads_primary_color(*state.texturing)) ||
        (secondary_varying && reads_secondary);
  }
  // st/mesa gives a culled face the other face's polygon mode; an unfilled mode or polygon
  // stipple runs the draw module's pipeline (llvmpipe installs its polygon stipple stage).
  uint32_t fill_front = p.polygon_mode_front, fill_back = p.polygon_mode_back;
  if (p.cull_face) {
    if (p.cull_face_mode == GL_FRONT || p.cull_face_mode == GL_FRONT_AND_BACK)
      fill_front = fill_back;
    if (p.cull_face_mode == GL_BACK || p.cull_face_mode == GL_FRONT_AND_BACK)
      fill_back = fill_front;
  }
  a.pipeline = p.polygon_stipple || fill_front != GL_FILL || fill_back != GL_FILL;
  const TransformState& t = *state.transform;
  a.clip_test = true;
  a.modelview_projection = t.modelview_projection;
  a.modelview = t.modelview;
  a.clip_plane_mask = t.clip_plane_mask;
  a.clip_planes = t.clip_planes;
  a.viewport_scale_x = static_cast<float>(t.viewport[2]) * 0.5f;
  a.viewport_offset_x = static_cast<float>(t.viewport[0]) + a.viewport_scale_x;
  a.viewport_scale_y = static_cast<float>(t.viewport[3]) * 0.5f;
  a.viewport_offset_y = static_cast<float>(t.viewport[1]) + a.viewport_scale_y;
  return a;
}

bool triangles_in_element_order(const VertexData& vertices, const AssemblyState& assembly) {
  if (vertices.mode != GL_TRIANGLES || vertices.primitives.size() != 1) return false;
  const uint32_t vertex_count = vertices.vertex_count();
  const bool indexed = !vertices.indices.empty();
  const uint64_t elements = indexed ? vertices.indices.size() : vertex_count;
  const PrimitiveRange& range = vertices.primitives[0];
  if (range.first != 0 || range.count != elements || range.count == 0 || range.count % 3 != 0)
    return false;
  // The 9-vertex defect of the arrays path (decompose): batches are cut every 4095 vertices, so a
  // batch of 9 is the last one of a count of 4095k + 9.
  const bool indexed_path = vertices.source == PrimitiveSource::kDisplayList ||
                            vertices.source == PrimitiveSource::kElements;
  const uint32_t batch = trim(kBatchVertices, split_of(GL_TRIANGLES));
  if (!indexed_path && !assembly.constant_interpolation && assembly.clip_test &&
      range.count % batch == 9)
    return false;
  if (indexed)
    for (const uint32_t v : vertices.indices)
      if (v >= vertex_count) return false;
  return true;
}

void decompose(const VertexData& vertices, Decomposed& out) {
  decompose(vertices, AssemblyState{}, out);
}

}  // namespace glpt::rec
