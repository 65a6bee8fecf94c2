#include "gl_test_context.hpp"

namespace {

void quad_strip() {
  glBegin(GL_QUAD_STRIP);
  glNormal3f(0, 0, 1);
  glVertex3f(0, 0, 0);
  glVertex3f(0, 1, 0);
  glNormal3f(1, 0, 0);
  glVertex3f(1, 0, 0);
  glVertex3f(1, 1, 0);
  glEnd();
}

TEST_F(GlTest, FlatShadingCopiesTheProvokingVertexNormal) {
  glShadeModel(GL_FLAT);
  quad_strip();
  const auto& g = *ctx_.capture.instances().at(0).geometry;
  ASSERT_EQ(g.triangle_count(), 2u);
  for (const auto& n : g.normals) EXPECT_EQ(n, glm::vec3(1, 0, 0));  // vertex 3's normal
}

TEST_F(GlTest, SmoothShadingKeepsPerVertexNormals) {
  glShadeModel(GL_SMOOTH);
  quad_strip();
  const auto& g = *ctx_.capture.instances().at(0).geometry;
  EXPECT_EQ(g.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(g.normals[2], glm::vec3(1, 0, 0));
}

TEST_F(GlTest, ConsecutiveDrawsWithOneModelviewBatchIntoOneGeometry) {
  for (int i = 0; i < 50; ++i) quad_strip();
  glPushMatrix();  // push/pop without change keeps the batch open
  glPopMatrix();
  quad_strip();
  EXPECT_EQ(ctx_.capture.instances().size(), 1u);
  EXPECT_EQ(ctx_.capture.instances()[0].geometry->triangle_count(), 102u);
}

TEST_F(GlTest, ClearDiscardsEarlierDraws) {
  quad_strip();
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  EXPECT_TRUE(ctx_.capture.instances().empty());
  glClear(0x80000000u);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
}

TEST_F(GlTest, UnlitDrawsCarryTheirColourAndLitOnesTheMaterial) {
  glColor3ub(255, 0, 0);
  quad_strip();  // lighting off
  glTranslatef(1, 0, 0);
  glEnable(GL_LIGHTING);
  quad_strip();
  const auto& inst = ctx_.capture.instances();
  ASSERT_EQ(inst.size(), 2u);
  EXPECT_FALSE(inst[0].geometry->materials[0].lit);
  EXPECT_EQ(inst[0].geometry->colors[0], glm::vec4(1, 0, 0, 1));
  EXPECT_TRUE(inst[1].geometry->materials[0].lit);
}

void triangle() {
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0);
  glVertex3f(1, 0, 0);
  glVertex3f(0, 1, 0);
  glEnd();
}

TEST_F(GlTest, FrameSeesLightAndProjectionChangesBetweenDraws) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  triangle();
  ASSERT_EQ(ctx_.pending.lights.size(), 1u);
  const GLfloat red[4] = {1, 0, 0, 1};
  glLightfv(GL_LIGHT0, GL_DIFFUSE, red);
  glEnable(GL_LIGHT1);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-2, 2, -2, 2, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  triangle();
  ASSERT_EQ(ctx_.pending.lights.size(), 2u);
  EXPECT_EQ(ctx_.pending.lights[0].diffuse, glm::vec4(1, 0, 0, 1));
  EXPECT_FLOAT_EQ(ctx_.pending.projection[0][0], 0.5f);
}

}  // namespace
