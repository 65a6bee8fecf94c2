#include <cmath>
#include <limits>
#include <variant>

#include "gl_test_context.hpp"

namespace {

TEST_F(GlTest, EndWithoutBeginIsInvalidOperation) {
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});  // the flag clears on read
}

TEST_F(GlTest, FirstErrorIsKeptUntilRead) {
  glEnable(0x1234);  // GL_INVALID_ENUM
  glEnd();           // GL_INVALID_OPERATION, not recorded over the first
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // Both are counted for GLPT_STATS's totals, though GL keeps only the first.
  EXPECT_EQ(ctx_.errors_recorded, 2u);
}

TEST_F(GlTest, BadEnumsAreRejected) {
  glBegin(0x1234);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glMatrixMode(GL_LIGHTING);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glShadeModel(GL_LINE);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(glIsEnabled(0x1234), 0);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(glGetString(0x1234), nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glViewport(0, 0, -1, 10);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
}

TEST_F(GlTest, EnableStateRoundTrips) {
  EXPECT_FALSE(glIsEnabled(GL_LIGHTING));
  EXPECT_TRUE(glIsEnabled(GL_DITHER));  // on by default
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT3);
  EXPECT_TRUE(glIsEnabled(GL_LIGHTING));
  EXPECT_TRUE(glIsEnabled(GL_LIGHT3));
  glDisable(GL_LIGHTING);
  EXPECT_FALSE(glIsEnabled(GL_LIGHTING));
}

TEST_F(GlTest, NestedBeginIsInvalidOperation) {
  glBegin(GL_TRIANGLES);
  glBegin(GL_TRIANGLES);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, GetErrorInsideBeginEndIsItselfAnError) {
  glBegin(GL_TRIANGLES);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});  // returns 0 and flags GL_INVALID_OPERATION
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

TEST_F(GlTest, UnimplementedCommandSetsInvalidOperationOnceAndCounts) {
  // EXT_polygon_offset (its bias semantics differ from GL 1.1's) is not implemented.
  glPolygonOffsetEXT(1.0f, 0.5f);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glPolygonOffsetEXT(1.0f, 0.5f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(ctx_.unimplemented_calls[static_cast<size_t>(glpt::CommandId::glPolygonOffsetEXT)], 2u);
}

TEST_F(GlTest, NonFiniteVerticesAreAcceptedAsGlDoes) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  glBegin(GL_TRIANGLES);
  glVertex3f(nan, 0, 0);
  glVertex3f(1, 0, 0);
  glVertex3f(0, 1, 0);
  glVertex3f(0, 0, 0);
  glVertex3f(inf, 0, 0);
  glVertex3f(0, 1, 0);
  glVertex3f(0, 0, 0);
  glVertex3f(1, 0, 0);
  glVertex3f(0, 1, 0);
  glVertex4f(1, 1, 1, 0);  // a point at infinity
  glVertex3f(1, 0, 0);
  glVertex3f(0, 1, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // GL accepts them: the record keeps every vertex as given (consumers keep them out of images).
  ctx_.recorder.seal();
  const auto& commands = ctx_.recorder.record().commands;
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(std::get<glpt::rec::Draw>(commands[0]).vertices->vertex_count(), 12u);
}

TEST_F(GlTest, NoCurrentContextIsHarmless) {
  glpt::set_current_context(nullptr);
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(glGetString(GL_VENDOR), nullptr);
}

}  // namespace
