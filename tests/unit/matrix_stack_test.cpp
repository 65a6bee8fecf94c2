#include <cmath>

#include "gl_test_context.hpp"

namespace {

void expect_matrix(const GLfloat* got, const float (&want)[16], float tol = 1e-5f) {
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(got[i], want[i], tol) << "element " << i;
}

TEST_F(GlTest, TranslateRotateScaleComposeLikeGl) {
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(1, 2, 3);
  glRotatef(90, 0, 0, 1);
  glScalef(2, 2, 2);
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  // T * R(90 about z) * S(2): column-major, x axis -> (0,2,0), y axis -> (-2,0,0).
  const float want[16] = {0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1};
  expect_matrix(m, want);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, RotateNormalizesTheAxis) {
  glRotatef(90, 0, 0, 10);
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  const float want[16] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  expect_matrix(m, want);
}

TEST_F(GlTest, FrustumMatchesTheSpecFormula) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 5, 60);  // glxgears' projection
  GLfloat m[16];
  glGetFloatv(GL_PROJECTION_MATRIX, m);
  const float want[16] = {5, 0, 0, 0, 0, 5, 0, 0, 0, 0, -65.0f / 55.0f, -1, 0, 0, -600.0f / 55.0f,
                          0};
  expect_matrix(m, want);
}

TEST_F(GlTest, FrustumWithBadPlanesIsInvalidValueAndLeavesMatrix) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 0, 60);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glOrtho(0, 0, -1, 1, -1, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  GLfloat m[16];
  glGetFloatv(GL_PROJECTION_MATRIX, m);
  const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  expect_matrix(m, identity);
}

TEST_F(GlTest, PushPopRestoresAndReportsOverflowAndUnderflow) {
  glTranslatef(5, 0, 0);
  glPushMatrix();
  glTranslatef(1, 0, 0);
  glPopMatrix();
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_FLOAT_EQ(m[12], 5.0f);
  glPopMatrix();
  EXPECT_EQ(glGetError(), GLenum{GL_STACK_UNDERFLOW});
  GLint max_depth = 0;
  glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, &max_depth);
  for (int i = 1; i < max_depth; ++i) glPushMatrix();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glPushMatrix();
  EXPECT_EQ(glGetError(), GLenum{GL_STACK_OVERFLOW});
  GLint depth = 0;
  glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
  EXPECT_EQ(depth, max_depth);
}

TEST_F(GlTest, MatrixOpsAreIllegalBetweenBeginAndEnd) {
  glBegin(GL_TRIANGLES);
  glTranslatef(1, 0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_FLOAT_EQ(m[12], 0.0f);
}

}  // namespace
