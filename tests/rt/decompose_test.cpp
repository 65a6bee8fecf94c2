// GL primitive decomposition (rt_core/record/decompose.hpp): the triangles, lines and points of
// every GL mode, with GL's provoking vertex last, Mesa's diagonals, edge flags and stipple resets.
#include "rt_core/record/decompose.hpp"

#include <gtest/gtest.h>

namespace glpt::rec {
namespace {

VertexData primitive(uint32_t mode, uint32_t count) {
  VertexData d;
  d.mode = mode;
  d.position.assign(count, glm::vec4(0, 0, 0, 1));
  d.primitives.push_back({0, count});
  return d;
}

struct Tri {
  uint32_t a, b, c;
  uint8_t edges;
  bool operator==(const Tri&) const = default;
};

std::vector<Tri> triangles(const VertexData& d) {
  Decomposed out;
  decompose(d, out);
  std::vector<Tri> tris;
  for (const auto& t : out.triangles) tris.push_back({t.v[0], t.v[1], t.v[2], t.boundary_edges});
  return tris;
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

TEST(Decompose, QuadsSplitLikeMesaWithTheFourthVertexProvoking) {
  // Edges: (0,1,3) has 0->1 and 3->0 on the quad's boundary; (1,2,3) has 1->2 and 2->3.
  EXPECT_EQ(triangles(primitive(GL_QUADS, 4)),
            (std::vector<Tri>{{0, 1, 3, 1 | 4}, {1, 2, 3, 1 | 2}}));
}

TEST(Decompose, QuadStripProvokesWithTheLastVertexOfEachQuad) {
  EXPECT_EQ(
      triangles(primitive(GL_QUAD_STRIP, 6)),
      (std::vector<Tri>{{2, 0, 3, 1 | 4}, {0, 1, 3, 1 | 2}, {4, 2, 5, 1 | 4}, {2, 3, 5, 1 | 2}}));
}

TEST(Decompose, PolygonPutsTheFirstVertexLast) {
  // GL flat-shades a polygon with its first vertex; boundary edges: 0->1 in the first triangle,
  // i+1 -> i+2 in each, 4 -> 0 in the last.
  EXPECT_EQ(triangles(primitive(GL_POLYGON, 5)),
            (std::vector<Tri>{{1, 2, 0, 1 | 4}, {2, 3, 0, 1}, {3, 4, 0, 1 | 2}}));
}

TEST(Decompose, EdgeFlagsHideTheEdgesStartingAtFlaggedVertices) {
  VertexData d = primitive(GL_TRIANGLES, 3);
  d.edge_flag = {1, 0, 1};  // the edge 1 -> 2 is interior
  EXPECT_EQ(triangles(d), (std::vector<Tri>{{0, 1, 2, 1 | 4}}));
  VertexData strip = primitive(GL_TRIANGLE_STRIP, 3);
  strip.edge_flag = {0};  // ignored for strips (GL 1.5 2.6.2)
  EXPECT_EQ(triangles(strip), (std::vector<Tri>{{0, 1, 2, 7}}));
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

TEST(Decompose, BatchedRangesAndIndicesResolveToVertices) {
  VertexData d;
  d.mode = GL_TRIANGLES;
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

}  // namespace
}  // namespace glpt::rec
