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

namespace {

TEST_F(GlTest, StackDepthsAreMesas) {
  const struct {
    GLenum mode;
    GLenum max_pname;
    GLint max;
  } stacks[] = {{GL_MODELVIEW, GL_MAX_MODELVIEW_STACK_DEPTH, 32},
                {GL_PROJECTION, GL_MAX_PROJECTION_STACK_DEPTH, 32},
                {GL_TEXTURE, GL_MAX_TEXTURE_STACK_DEPTH, 10}};
  for (const auto& s : stacks) {
    glMatrixMode(s.mode);
    GLint max = 0;
    glGetIntegerv(s.max_pname, &max);
    EXPECT_EQ(max, s.max);
    for (GLint i = 1; i < max; ++i) glPushMatrix();
    EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
    glPushMatrix();
    EXPECT_EQ(glGetError(), GLenum{GL_STACK_OVERFLOW});
  }
}

// Mesa converts the bounds to float before it checks them.
TEST_F(GlTest, ProjectionBoundsAreCheckedAsFloats) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1e-50, 10);  // near becomes 0
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glOrtho(1.0, 1.0 + 1e-12, -1, 1, -1, 1);  // left == right in float
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  GLfloat m[16];
  glGetFloatv(GL_PROJECTION_MATRIX, m);
  EXPECT_EQ(m[0], 1.0f);
  EXPECT_EQ(m[14], 0.0f);
}

TEST_F(GlTest, NullMatrixPointersAreIgnored) {
  glLoadMatrixf(nullptr);
  glMultMatrixd(nullptr);
  glLoadTransposeMatrixf(nullptr);
  glMultTransposeMatrixd(nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[0], 1.0f);
}

// The contract with the draw recorder: a draw analyses the modelview and texture matrices, and
// the projection only while a clip plane is enabled (what Mesa's state validation does).
TEST_F(GlTest, DrawsAnalyseTheMatricesMesaAnalyses) {
  const GLfloat m[16] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1};
  glLoadMatrixf(m);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(m);
  glMatrixMode(GL_TEXTURE);
  glLoadMatrixf(m);
  glMatrixMode(GL_MODELVIEW);
  EXPECT_TRUE(ctx_.matrices.modelview.top_matrix().dirty());
  glBegin(GL_POINTS);
  glEnd();
  EXPECT_FALSE(ctx_.matrices.modelview.top_matrix().dirty());
  EXPECT_FALSE(ctx_.matrices.texture[0].top_matrix().dirty());
  EXPECT_TRUE(ctx_.matrices.projection.top_matrix().dirty());
  glEnable(GL_CLIP_PLANE0);
  EXPECT_FALSE(ctx_.matrices.projection.top_matrix().dirty());
}

// The combined matrix is projection * modelview, summed left to right like Mesa's product.
TEST_F(GlTest, ModelProjectionIsProjectionTimesModelview) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1.1, 0.9, -0.8, 1.2, 1.5, 97.3);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0.3f, -0.2f, -40.0f);
  glRotatef(33.0f, 1.0f, 0.5f, 0.25f);
  ctx_.matrices.validate_for_draw(0);
  GLfloat p[16], mv[16];
  glGetFloatv(GL_PROJECTION_MATRIX, p);
  glGetFloatv(GL_MODELVIEW_MATRIX, mv);
  const glm::mat4 mvp = ctx_.matrices.model_projection();
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      float sum = p[r] * mv[c * 4];
      for (int k = 1; k < 4; ++k) sum += p[k * 4 + r] * mv[c * 4 + k];
      EXPECT_EQ(mvp[c][r], sum) << "row " << r << " column " << c;
    }
  }
}

}  // namespace
