#include "gl_shim/geometry/triangulate.hpp"

#include <gtest/gtest.h>

#include "gl/gl_enums.h"

namespace {

using glpt::TriangleIndices;

std::vector<TriangleIndices> tris(GLenum mode, uint32_t n) {
  std::vector<TriangleIndices> out;
  EXPECT_TRUE(glpt::triangulate(mode, n, out));
  return out;
}

TEST(Triangulate, CountsPerPrimitiveType) {
  EXPECT_EQ(tris(GL_TRIANGLES, 7).size(), 2u);  // the incomplete third triangle is dropped
  EXPECT_EQ(tris(GL_TRIANGLE_STRIP, 6).size(), 4u);
  EXPECT_EQ(tris(GL_TRIANGLE_FAN, 6).size(), 4u);
  EXPECT_EQ(tris(GL_QUADS, 9).size(), 4u);
  EXPECT_EQ(tris(GL_QUAD_STRIP, 8).size(), 6u);
  EXPECT_EQ(tris(GL_POLYGON, 5).size(), 3u);
  EXPECT_EQ(tris(GL_POLYGON, 2).size(), 0u);
  EXPECT_EQ(tris(GL_LINES, 10).size(), 0u);
  std::vector<TriangleIndices> out;
  EXPECT_FALSE(glpt::triangulate(0x1234, 3, out));
}

TEST(Triangulate, ProvokingVerticesFollowGlTable) {
  // GL 1.5 table 2.9: last vertex of each triangle/quad, first of a polygon.
  EXPECT_EQ(tris(GL_TRIANGLES, 6)[1].provoking, 5u);
  EXPECT_EQ(tris(GL_TRIANGLE_STRIP, 5)[2].provoking, 4u);
  EXPECT_EQ(tris(GL_QUADS, 8)[2].provoking, 7u);
  EXPECT_EQ(tris(GL_QUADS, 8)[3].provoking, 7u);
  EXPECT_EQ(tris(GL_QUAD_STRIP, 6)[2].provoking, 5u);
  EXPECT_EQ(tris(GL_POLYGON, 5)[2].provoking, 0u);
}

TEST(Triangulate, StripKeepsWinding) {
  // Odd strip triangles swap their first two vertices: (1,0,2) keeps the orientation of (0,1,2).
  auto t = tris(GL_TRIANGLE_STRIP, 4);
  EXPECT_EQ(t[1].v[0], 2u);
  EXPECT_EQ(t[1].v[1], 1u);
  EXPECT_EQ(t[1].v[2], 3u);
  // Quad strip quad k is v(2k), v(2k+1), v(2k+3), v(2k+2).
  auto q = tris(GL_QUAD_STRIP, 4);
  EXPECT_EQ(q[0].v[2], 3u);
  EXPECT_EQ(q[1].v[1], 3u);
  EXPECT_EQ(q[1].v[2], 2u);
}

}  // namespace
