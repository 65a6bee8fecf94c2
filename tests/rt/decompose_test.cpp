// GL primitive decomposition (rt_core/record/decompose.hpp): the triangles, lines and points of
// every GL mode in Mesa 25's order (llvmpipe's lp_setup_vbuf.c and the draw module's
// draw_decompose_tmp.h), with GL's provoking vertex last, edge flags and stipple resets. The
// expected orders were measured against OSMesa (Mesa 25.0.7): each GL primitive rendered by
// Mesa is bit-identical to the triangles below rendered as GL_TRIANGLES in the same order, and
// differs from every other candidate order.
#include "rt_core/record/decompose.hpp"

#include <gtest/gtest.h>

#include "rt_core/record/texture.hpp"

namespace glpt::rec {
namespace {

VertexData primitive(uint32_t mode, uint32_t count,
                     PrimitiveSource source = PrimitiveSource::kImmediate) {
  VertexData d;
  d.mode = mode;
  d.source = source;
  d.position.assign(count, glm::vec4(0, 0, 0, 1));
  d.primitives.push_back({0, count});
  return d;
}

// Appends a glBegin/glEnd of `count` vertices at the origin.
void add_range(VertexData& d, uint32_t count) {
  d.primitives.push_back({d.vertex_count(), count});
  d.position.resize(d.position.size() + count, glm::vec4(0, 0, 0, 1));
}

struct Tri {
  uint32_t a, b, c;
  uint8_t edges;
  bool operator==(const Tri&) const = default;
};

std::vector<Tri> triangles(const VertexData& d, const AssemblyState& a = {}) {
  Decomposed out;
  decompose(d, a, out);
  std::vector<Tri> tris;
  for (const auto& t : out.triangles) tris.push_back({t.v[0], t.v[1], t.v[2], t.boundary_edges});
  return tris;
}

// An assembly state whose clip test sees positions as clip coordinates (identity transform).
AssemblyState clip_tested() {
  AssemblyState a;
  a.clip_test = true;
  return a;
}

const std::vector<Tri> kQuadDiagonal02 = {{0, 1, 2, 1 | 2}, {0, 2, 3, 2 | 4}};
const std::vector<Tri> kQuadDiagonal13 = {{0, 1, 3, 1 | 4}, {1, 2, 3, 1 | 2}};

// Decomposed::assembly_consulted: whether the result may change with the AssemblyState (rt_core's
// resident geometry keeps a decomposition across frames only when it did not, or for the same
// state).
TEST(Decompose, SaysWhenTheAssemblyStateDecided) {
  auto consulted = [](const VertexData& d) {
    Decomposed out;
    decompose(d, clip_tested(), out);
    return out.assembly_consulted;
  };
  EXPECT_FALSE(consulted(primitive(GL_TRIANGLES, 12, PrimitiveSource::kArrays)));
  EXPECT_FALSE(consulted(primitive(GL_TRIANGLE_STRIP, 9, PrimitiveSource::kArrays)));
  EXPECT_FALSE(consulted(primitive(GL_TRIANGLES, 9, PrimitiveSource::kElements)));
  EXPECT_FALSE(consulted(primitive(GL_POLYGON, 9, PrimitiveSource::kArrays)));
  // The 9-vertex defect of the arrays path, quads (constant interpolation, path), quad strips.
  EXPECT_TRUE(consulted(primitive(GL_TRIANGLES, 9, PrimitiveSource::kArrays)));
  EXPECT_TRUE(consulted(primitive(GL_QUADS, 8, PrimitiveSource::kElements)));
  EXPECT_TRUE(consulted(primitive(GL_QUAD_STRIP, 8, PrimitiveSource::kArrays)));
  // Appending keeps what an earlier decomposition said; clear() forgets it.
  Decomposed out;
  decompose(primitive(GL_QUADS, 4, PrimitiveSource::kArrays), clip_tested(), out);
  decompose(primitive(GL_TRIANGLES, 6, PrimitiveSource::kArrays), clip_tested(), out);
  EXPECT_TRUE(out.assembly_consulted);
  out.clear();
  EXPECT_FALSE(out.assembly_consulted);
}

// triangles_in_element_order answers what decomposing says for triangle lists, and no otherwise.
TEST(Decompose, TrianglesInElementOrderWithoutDecomposing) {
  auto decomposed_in_order = [](const VertexData& d, const AssemblyState& a) {
    Decomposed out;
    decompose(d, a, out);
    const uint64_t elements = d.indices.empty() ? d.vertex_count() : d.indices.size();
    if (out.triangles.empty() || 3 * out.triangles.size() != elements) return false;
    for (size_t t = 0; t < out.triangles.size(); ++t)
      for (uint32_t k = 0; k < 3; ++k) {
        const size_t e = 3 * t + k;
        if (out.triangles[t].v[k] != (d.indices.empty() ? e : d.indices[e])) return false;
      }
    return true;
  };
  auto indexed = [](uint32_t count, uint32_t bad_at = ~0u) {
    VertexData d = primitive(GL_TRIANGLES, count, PrimitiveSource::kElements);
    for (uint32_t i = 0; i < count; ++i) d.indices.push_back(i == bad_at ? count : count - 1 - i);
    return d;
  };
  VertexData two_ranges = primitive(GL_TRIANGLES, 6, PrimitiveSource::kArrays);
  add_range(two_ranges, 3);
  const std::vector<VertexData> cases = {
      primitive(GL_TRIANGLES, 12, PrimitiveSource::kArrays),
      primitive(GL_TRIANGLES, 12, PrimitiveSource::kImmediate),
      primitive(GL_TRIANGLES, 9, PrimitiveSource::kArrays),  // the 9-vertex defect's batch
      primitive(GL_TRIANGLES, 4095 * 2 + 9, PrimitiveSource::kArrays),
      primitive(GL_TRIANGLES, 9, PrimitiveSource::kElements),
      primitive(GL_TRIANGLES, 10, PrimitiveSource::kArrays),  // a trailing vertex
      indexed(12),
      indexed(12, 5),  // an index past the vertices
      primitive(GL_QUADS, 8, PrimitiveSource::kArrays),
      primitive(GL_TRIANGLE_STRIP, 3, PrimitiveSource::kImmediate),
      two_ranges,
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    for (const AssemblyState& a : {AssemblyState{}, clip_tested()}) {
      if (triangles_in_element_order(cases[i], a)) {
        EXPECT_TRUE(decomposed_in_order(cases[i], a)) << "case " << i;
      }
    }
  }
  EXPECT_TRUE(triangles_in_element_order(cases[0], clip_tested()));
  EXPECT_TRUE(triangles_in_element_order(cases[4], clip_tested()));
  EXPECT_TRUE(triangles_in_element_order(cases[6], clip_tested()));
  EXPECT_FALSE(triangles_in_element_order(cases[2], clip_tested()));
  EXPECT_FALSE(triangles_in_element_order(cases[3], clip_tested()));
  EXPECT_FALSE(triangles_in_element_order(cases[7], clip_tested()));
}

TEST(Decompose, TrianglesKeepOrderAndAllEdges) {
  EXPECT_EQ(triangles(primitive(GL_TRIANGLES, 7)),
            (std::vector<Tri>{{0, 1, 2, 7}, {3, 4, 5, 7}}));  // the 7th vertex is dropped
}

TEST(Decompose, StripSwapsOddTrianglesSoTheNewestVertexIsLast) {
  EXPECT_EQ(triangles(primitive(GL_TRIANGLE_STRIP, 5)),
            (std::vector<Tri>{{0, 1, 2, 7}, {2, 1, 3, 7}, {2, 3, 4, 7}}));
}

TEST(Decompose, FanKeepsTheHubFirst) {
  EXPECT_EQ(triangles(primitive(GL_TRIANGLE_FAN, 5)),
            (std::vector<Tri>{{0, 1, 2, 7}, {0, 2, 3, 7}, {0, 3, 4, 7}}));
}

TEST(Decompose, PolygonPutsTheFirstVertexLast) {
  // GL flat-shades a polygon with its first vertex; boundary edges: 0->1 in the first triangle,
  // i+1 -> i+2 in each, 4 -> 0 in the last.
  EXPECT_EQ(triangles(primitive(GL_POLYGON, 5)),
            (std::vector<Tri>{{1, 2, 0, 1 | 4}, {2, 3, 0, 1}, {3, 4, 0, 1 | 2}}));
}

// llvmpipe's lp_setup_draw_arrays draws a smooth quad as rect(v0,v1,v2, v0,v2,v3).
TEST(Decompose, ImmediateSmoothQuadsSplitAlongTheFirstDiagonal) {
  EXPECT_EQ(triangles(primitive(GL_QUADS, 4)), kQuadDiagonal02);
  EXPECT_EQ(triangles(primitive(GL_QUADS, 4, PrimitiveSource::kArrays)), kQuadDiagonal02);
}

// Indexed draws (display lists are compiled to them), an interpolated-as-constant input, and the
// draw module's pipeline all split along 1-3 with the fourth vertex last (it provokes).
TEST(Decompose, QuadsSplitAlongTheSecondDiagonalOtherwise) {
  EXPECT_EQ(triangles(primitive(GL_QUADS, 4, PrimitiveSource::kDisplayList)), kQuadDiagonal13);
  EXPECT_EQ(triangles(primitive(GL_QUADS, 4, PrimitiveSource::kElements)), kQuadDiagonal13);
  AssemblyState flat;
  flat.constant_interpolation = true;
  EXPECT_EQ(triangles(primitive(GL_QUADS, 4), flat), kQuadDiagonal13);
  AssemblyState unfilled;
  unfilled.pipeline = true;
  EXPECT_EQ(triangles(primitive(GL_QUADS, 4), unfilled), kQuadDiagonal13);
}

// llvmpipe clips without a guard band: a vertex beyond the view volume sends its whole batch
// (here two merged glBegin/glEnd) through the draw module's pipeline.
TEST(Decompose, AClippedVertexSendsItsWholeBatchThroughThePipeline) {
  VertexData d = primitive(GL_QUADS, 4);
  add_range(d, 4);
  EXPECT_EQ(triangles(d, clip_tested()).front(), kQuadDiagonal02.front());
  for (const glm::vec4& outside : {glm::vec4(1.5f, 0, 0, 1), glm::vec4(0, -1.01f, 0, 1),
                                   glm::vec4(0, 0, -2, 1), glm::vec4(0, 0, 1.5f, 1)}) {
    d.position[6] = outside;  // in the second glBegin/glEnd
    const std::vector<Tri> t = triangles(d, clip_tested());
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[0], kQuadDiagonal13[0]) << outside.x << " " << outside.y << " " << outside.z;
    EXPECT_EQ(t[2], (Tri{4, 5, 7, 1 | 4}));
  }
  d.position[6] = glm::vec4(1, -1, 1, 1);  // on the boundary: inside
  EXPECT_EQ(triangles(d, clip_tested())[0], kQuadDiagonal02[0]);
  // Without a clip test (no transform) nothing is outside.
  d.position[6] = glm::vec4(5, 0, 0, 1);
  EXPECT_EQ(triangles(d)[0], kQuadDiagonal02[0]);
}

TEST(Decompose, UserClipPlanesAreTestedInEyeSpace) {
  VertexData d = primitive(GL_QUADS, 4);
  d.position[2] = glm::vec4(0.5f, 0, 0, 1);
  AssemblyState a = clip_tested();
  a.clip_plane_mask = 2;
  a.clip_planes[1] = glm::vec4(-1, 0, 0, 0.25f);  // keeps x <= 0.25
  EXPECT_EQ(triangles(d, a), kQuadDiagonal13);
  a.modelview = glm::mat4(0.25f);  // eye x = 0.125: inside
  a.modelview[3][3] = 1.0f;
  EXPECT_EQ(triangles(d, a), kQuadDiagonal02);
}

// Mesa's draw module processes at most 4096 vertices at once: 1025 quads are two batches, and a
// clipped vertex in the first does not affect the second.
TEST(Decompose, BatchesEndEvery4096Vertices) {
  VertexData d = primitive(GL_QUADS, 4100);
  d.position[0] = glm::vec4(0, 0, -3, 1);
  const std::vector<Tri> t = triangles(d, clip_tested());
  ASSERT_EQ(t.size(), 2050u);
  EXPECT_EQ(t[2046], (Tri{4092, 4093, 4095, 1 | 4}));
  EXPECT_EQ(t[2048], (Tri{4096, 4097, 4098, 1 | 2}));
}

// Immediate mode merges consecutive quads only while the earlier ones hold whole quads (Mesa's
// vbo_merge_draws); the incomplete quad's extra vertices are dropped and the next range is a new
// batch.
TEST(Decompose, AnIncompleteQuadEndsTheMergedBatch) {
  VertexData d = primitive(GL_QUADS, 6);
  add_range(d, 4);
  d.position[8] = glm::vec4(9, 0, 0, 1);  // outside, in the second range
  EXPECT_EQ(
      triangles(d, clip_tested()),
      (std::vector<Tri>{{0, 1, 2, 1 | 2}, {0, 2, 3, 2 | 4}, {6, 7, 9, 1 | 4}, {7, 8, 9, 1 | 2}}));
}

TEST(Decompose, QuadStripTriangleOrderDependsOnThePath) {
  // Quad k is v(2k), v(2k+1), v(2k+3), v(2k+2); the fourth vertex provokes.
  const std::vector<Tri> setup_order = {{0, 1, 3, 1 | 2}, {2, 0, 3, 1 | 4}};
  const std::vector<Tri> pipeline_order = {{2, 0, 3, 1 | 4}, {0, 1, 3, 1 | 2}};
  EXPECT_EQ(triangles(primitive(GL_QUAD_STRIP, 4)), setup_order);
  EXPECT_EQ(triangles(primitive(GL_QUAD_STRIP, 4, PrimitiveSource::kDisplayList)), setup_order);
  VertexData clipped = primitive(GL_QUAD_STRIP, 4, PrimitiveSource::kDisplayList);
  clipped.position[1] = glm::vec4(0, 2, 0, 1);
  EXPECT_EQ(triangles(clipped, clip_tested()), pipeline_order);
  AssemblyState stipple;
  stipple.pipeline = true;
  EXPECT_EQ(triangles(primitive(GL_QUAD_STRIP, 4), stipple), pipeline_order);
}

// Mesa keeps each vertex's edge flag in every polygon mode (GL 1.5 2.6.2 ignores them for
// strips and fans): the edge v[k] -> v[k+1] of each emitted triangle is hidden when v[k]'s flag
// is off.
TEST(Decompose, EdgeFlagsHideTheEdgesStartingAtFlaggedVerticesInEveryMode) {
  VertexData d = primitive(GL_TRIANGLES, 3);
  d.edge_flag = {1, 0, 1};  // the edge 1 -> 2 is interior
  EXPECT_EQ(triangles(d), (std::vector<Tri>{{0, 1, 2, 1 | 4}}));
  VertexData strip = primitive(GL_TRIANGLE_STRIP, 4);
  strip.edge_flag = {1, 0, 1, 1};
  EXPECT_EQ(triangles(strip), (std::vector<Tri>{{0, 1, 2, 1 | 4}, {2, 1, 3, 1 | 4}}));
  VertexData fan = primitive(GL_TRIANGLE_FAN, 4);
  fan.edge_flag = {0};  // one shared value: every edge starts at a flagged vertex
  EXPECT_EQ(triangles(fan), (std::vector<Tri>{{0, 1, 2, 0}, {0, 2, 3, 0}}));
  VertexData quad_strip = primitive(GL_QUAD_STRIP, 4);
  quad_strip.edge_flag = {1, 1, 0, 1};
  EXPECT_EQ(triangles(quad_strip), (std::vector<Tri>{{0, 1, 3, 1 | 2}, {2, 0, 3, 4}}));
}

// lp_setup_analyse_triangles: a 9-vertex triangle list drawn on llvmpipe's arrays path, smooth,
// whose last triangle has one window y, is taken for a Windows Aero window border: nothing is
// drawn (measured: Mesa leaves the framebuffer untouched).
TEST(Decompose, MesaDropsNineTriangleListVerticesEndingInAHorizontalLine) {
  VertexData d = primitive(GL_TRIANGLES, 9);
  for (uint32_t i = 0; i < 6; ++i) d.position[i] = glm::vec4(0.1f * i, 0.02f * i * i, 0, 1);
  d.position[6] = glm::vec4(-0.5f, 0.25f, 0, 1);
  d.position[7] = glm::vec4(0.5f, 0.25f, 0, 1);
  d.position[8] = glm::vec4(0.1f, 0.25f, 0, 1);
  EXPECT_TRUE(triangles(d, clip_tested()).empty());
  // Three glBegin/glEnd of one triangle merge into the same 9 vertices.
  VertexData merged = d;
  merged.primitives = {{0, 3}, {3, 3}, {6, 3}};
  EXPECT_TRUE(triangles(merged, clip_tested()).empty());
  // Not on the other paths, nor with a constant-interpolated input, nor with 12 vertices.
  VertexData list = d;
  list.source = PrimitiveSource::kDisplayList;
  EXPECT_EQ(triangles(list, clip_tested()).size(), 3u);
  AssemblyState flat = clip_tested();
  flat.constant_interpolation = true;
  EXPECT_EQ(triangles(d, flat).size(), 3u);
  VertexData clipped = d;
  clipped.position[0] = glm::vec4(0, 0, 5, 1);
  EXPECT_EQ(triangles(clipped, clip_tested()).size(), 3u);
  VertexData twelve = d;
  add_range(twelve, 3);
  EXPECT_EQ(triangles(twelve, clip_tested()).size(), 4u);
  VertexData sloped = d;
  sloped.position[8].y = 0.3f;
  EXPECT_EQ(triangles(sloped, clip_tested()).size(), 3u);
}

TEST(Decompose, LinesResetTheStipplePerSegmentAndStripsOnce) {
  Decomposed out;
  decompose(primitive(GL_LINES, 5), out);
  ASSERT_EQ(out.lines.size(), 2u);
  EXPECT_TRUE(out.lines[0].reset_stipple && out.lines[1].reset_stipple);
  out.clear();
  decompose(primitive(GL_LINE_LOOP, 3), out);
  ASSERT_EQ(out.lines.size(), 3u);
  EXPECT_TRUE(out.lines[0].reset_stipple);
  EXPECT_FALSE(out.lines[1].reset_stipple || out.lines[2].reset_stipple);
  EXPECT_EQ(out.lines[2].v[0], 2u);  // the loop closes 2 -> 0
  EXPECT_EQ(out.lines[2].v[1], 0u);
}

// Mesa compiles consecutive line strips of a display list into a line list: the stipple
// restarts at every segment (measured). One strip, or strips drawn directly, stay strips.
TEST(Decompose, DisplayListLineStripsBecomeSegments) {
  VertexData list = primitive(GL_LINE_STRIP, 3, PrimitiveSource::kDisplayList);
  EXPECT_FALSE(mesa_draws_strips_as_lines(list));
  add_range(list, 3);
  EXPECT_TRUE(mesa_draws_strips_as_lines(list));
  Decomposed out;
  decompose(list, AssemblyState{}, out);
  ASSERT_EQ(out.lines.size(), 4u);
  for (const DecomposedLine& l : out.lines) EXPECT_TRUE(l.reset_stipple);
  EXPECT_EQ(out.lines[2].v[0], 3u);
  EXPECT_EQ(out.lines[2].v[1], 4u);
  VertexData immediate = list;
  immediate.source = PrimitiveSource::kImmediate;
  EXPECT_FALSE(mesa_draws_strips_as_lines(immediate));
}

TEST(Decompose, BatchedRangesAndIndicesResolveToVertices) {
  VertexData d;
  d.mode = GL_TRIANGLES;
  d.source = PrimitiveSource::kElements;
  d.position.assign(4, glm::vec4(0, 0, 0, 1));
  d.indices = {3, 2, 1, 0, 9, 1};  // the second triangle uses a vertex that does not exist
  d.primitives = {{0, 3}, {3, 3}};
  EXPECT_EQ(triangles(d), (std::vector<Tri>{{3, 2, 1, 7}}));
  d.primitives = {{2, 9}};  // a range past the indices is ignored
  EXPECT_TRUE(triangles(d).empty());
}

TEST(Decompose, PrimitiveClasses) {
  EXPECT_EQ(primitive_class(GL_POINTS), PrimitiveClass::kPoints);
  EXPECT_EQ(primitive_class(GL_LINE_LOOP), PrimitiveClass::kLines);
  EXPECT_EQ(primitive_class(GL_QUAD_STRIP), PrimitiveClass::kTriangles);
}

// ---- assembly_state: what Mesa's state decides (each case measured with OSMesa: flat-shaded
// immediate-mode quads split along 0-2 exactly when no input is interpolated as a constant)

class AssemblyStateTest : public ::testing::Test {
 protected:
  AssemblyStateTest() {
    state_.transform = std::make_shared<TransformState>();
    state_.lighting = std::make_shared<LightingState>(lighting_);
    state_.texturing = std::make_shared<TexturingState>(texturing_);
    state_.raster = std::make_shared<RasterState>(raster_);
    state_.pixel_transfer = std::make_shared<PixelTransferState>();
  }
  AssemblyState assemble(uint8_t per_vertex = kPerVertexColor) {
    state_.lighting = std::make_shared<LightingState>(lighting_);
    state_.texturing = std::make_shared<TexturingState>(texturing_);
    state_.raster = std::make_shared<RasterState>(raster_);
    VertexData v = primitive(GL_QUADS, 4);
    v.per_vertex = per_vertex;
    return assembly_state(state_, v);
  }
  void texture(int unit, uint32_t base_format, uint32_t env_mode) {
    auto t = std::make_shared<TextureObjectSnapshot>();
    t->base_format = base_format;
    texturing_.units[unit].target = GL_TEXTURE_2D;
    texturing_.units[unit].texture = t;
    texturing_.units[unit].env.mode = env_mode;
  }
  StateSnapshot state_;
  LightingState lighting_;
  TexturingState texturing_;
  RasterState raster_;
};

TEST_F(AssemblyStateTest, SmoothShadingHasNoConstantInput) {
  EXPECT_FALSE(assemble().constant_interpolation);
}

TEST_F(AssemblyStateTest, FlatShadingOfAPerVertexColour) {
  raster_.primitive.shade_model = GL_FLAT;
  EXPECT_TRUE(assemble(kPerVertexColor).constant_interpolation);
  // A colour set only outside glBegin/glEnd is a constant of Mesa's fragment shader.
  EXPECT_FALSE(assemble(0).constant_interpolation);
  lighting_.enabled = true;  // lighting computes it per vertex
  EXPECT_TRUE(assemble(0).constant_interpolation);
}

TEST_F(AssemblyStateTest, TexturesThatReplaceTheColourCutItsInput) {
  raster_.primitive.shade_model = GL_FLAT;
  texture(0, GL_RGBA, GL_REPLACE);
  EXPECT_FALSE(assemble().constant_interpolation);
  texture(0, GL_INTENSITY, GL_REPLACE);
  EXPECT_FALSE(assemble().constant_interpolation);
  texture(0, GL_RGB, GL_REPLACE);  // alpha from the fragment colour
  EXPECT_TRUE(assemble().constant_interpolation);
  texture(0, GL_ALPHA, GL_REPLACE);  // colour from the fragment colour
  EXPECT_TRUE(assemble().constant_interpolation);
  texture(0, GL_RGBA, GL_MODULATE);
  EXPECT_TRUE(assemble().constant_interpolation);
  texture(0, GL_RGBA, GL_DECAL);
  EXPECT_TRUE(assemble().constant_interpolation);
}

TEST_F(AssemblyStateTest, TextureUnitsChainThePrimaryColour) {
  raster_.primitive.shade_model = GL_FLAT;
  texture(0, GL_RGBA, GL_MODULATE);
  texture(1, GL_RGBA, GL_REPLACE);  // replaces what unit 0 took from the colour
  EXPECT_FALSE(assemble().constant_interpolation);
  texture(1, GL_RGB, GL_REPLACE);  // keeps unit 0's alpha, which has the colour's
  EXPECT_TRUE(assemble().constant_interpolation);
  texturing_.units[0] = TextureUnitState{};  // unit 1's previous is the colour itself
  texture(1, GL_RGBA, GL_MODULATE);
  EXPECT_TRUE(assemble().constant_interpolation);
}

TEST_F(AssemblyStateTest, CombineReadsOnlyItsArguments) {
  raster_.primitive.shade_model = GL_FLAT;
  texture(0, GL_RGBA, GL_COMBINE);
  TexEnv& env = texturing_.units[0].env;
  env.source_rgb[1] = GL_CONSTANT;
  env.source_alpha[1] = GL_CONSTANT;
  EXPECT_FALSE(assemble().constant_interpolation);  // MODULATE(texture, constant)
  env.combine_alpha = GL_REPLACE;
  env.source_alpha[0] = GL_PRIMARY_COLOR;
  EXPECT_TRUE(assemble().constant_interpolation);
  env.source_alpha[0] = GL_TEXTURE;
  env.combine_rgb = GL_DOT3_RGBA;  // uses only the RGB arguments, for all four components
  env.source_alpha[1] = GL_PREVIOUS;
  EXPECT_FALSE(assemble().constant_interpolation);
  env.combine_rgb = GL_INTERPOLATE;  // a third argument: GL_CONSTANT by default
  EXPECT_FALSE(assemble().constant_interpolation);
  env.source_rgb[2] = GL_PREVIOUS;
  env.operand_rgb[2] = GL_SRC_ALPHA;
  EXPECT_TRUE(assemble().constant_interpolation);
}

TEST_F(AssemblyStateTest, TheSecondaryColourCountsWhenItIsAdded) {
  raster_.primitive.shade_model = GL_FLAT;
  texture(0, GL_RGBA, GL_REPLACE);
  raster_.ops.color_sum = true;
  EXPECT_FALSE(assemble(0).constant_interpolation);
  EXPECT_TRUE(assemble(kPerVertexSecondaryColor).constant_interpolation);
  raster_.ops.color_sum = false;
  EXPECT_FALSE(assemble(kPerVertexSecondaryColor).constant_interpolation);
  lighting_.enabled = true;
  EXPECT_FALSE(assemble(0).constant_interpolation);
  lighting_.separate_specular = true;
  EXPECT_TRUE(assemble(0).constant_interpolation);
}

TEST_F(AssemblyStateTest, UnfilledPolygonsAndPolygonStippleNeedThePipeline) {
  EXPECT_FALSE(assemble().pipeline);
  raster_.primitive.polygon_mode_back = GL_LINE;
  EXPECT_TRUE(assemble().pipeline);
  raster_.primitive.cull_face = true;  // culled back faces take the front faces' mode
  EXPECT_FALSE(assemble().pipeline);
  raster_.primitive.cull_face_mode = GL_FRONT;  // front faces take the back faces' line mode
  EXPECT_TRUE(assemble().pipeline);
  raster_.primitive = PrimitiveState{};
  raster_.primitive.polygon_stipple = true;
  EXPECT_TRUE(assemble().pipeline);
  raster_.primitive = PrimitiveState{};
  raster_.primitive.offset_fill = true;  // measured: polygon offset alone does not
  EXPECT_FALSE(assemble().pipeline);
}

TEST_F(AssemblyStateTest, TheClipTestUsesTheDrawsTransformAndViewport) {
  auto t = std::make_shared<TransformState>();
  t->modelview_projection = glm::mat4(2.0f);
  t->clip_plane_mask = 1;
  t->viewport = {10, 20, 64, 32};
  state_.transform = t;
  const AssemblyState a = assemble();
  EXPECT_TRUE(a.clip_test);
  EXPECT_EQ(a.modelview_projection, glm::mat4(2.0f));
  EXPECT_EQ(a.clip_plane_mask, 1u);
  EXPECT_EQ(a.viewport_scale_x, 32.0f);
  EXPECT_EQ(a.viewport_offset_x, 42.0f);
  EXPECT_EQ(a.viewport_scale_y, 16.0f);
  EXPECT_EQ(a.viewport_offset_y, 36.0f);
}

}  // namespace
}  // namespace glpt::rec
