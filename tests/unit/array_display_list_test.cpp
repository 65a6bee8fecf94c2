// Array draws in display lists (GL 1.5 5.4): the arrays are read when the list is compiled, the
// list replays the vertices it read, and client state commands execute immediately.
#include <array>
#include <cstdint>
#include <vector>

#include "array_test_util.hpp"

namespace {

class ArrayListTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, positions_.data());
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colours_.data());
  }
  std::array<float, 8> positions_ = {0, 0, 1, 0, 1, 1, 0, 1};
  std::array<uint8_t, 16> colours_ = {255, 0, 0,   255, 0,   255, 0,   255,
                                      0,   0, 255, 255, 255, 255, 255, 255};
};

TEST_F(ArrayListTest, CompiledDrawArraysKeepsTheArraysAsTheyWere) {
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  glEndList();
  EXPECT_TRUE(recorded_draws(ctx_).empty());  // GL_COMPILE draws nothing
  // Everything about the arrays changes after glEndList.
  positions_.fill(7);
  colours_.fill(0);
  glVertexPointer(3, GL_SHORT, 0, nullptr);
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(0.5f, 0.5f, 0.5f);
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto d = recorded_draws(ctx_);
  ASSERT_EQ(d.size(), 1u);
  const glpt::rec::VertexData& v = *d[0].vertices;
  EXPECT_EQ(v.mode, GLenum{GL_TRIANGLE_FAN});
  ASSERT_EQ(v.vertex_count(), 4u);
  EXPECT_EQ(v.position[2], glm::vec4(1, 1, 0, 1));
  // glColor4ubv's conversion (immediate mode, as Mesa compiles array draws): c / 255.
  EXPECT_EQ(at(v.color, 1), glm::vec4(0, 1, 0, 1));
  EXPECT_EQ(at(v.color, 2), glm::vec4(0, 0, 1, 1));
  // The list does not change the current colour (Mesa's compiled array draws do not).
  GLfloat current[4];
  glGetFloatv(GL_CURRENT_COLOR, current);
  EXPECT_EQ(current[0], 0.5f);
}

TEST_F(ArrayListTest, AttributesWithoutArraysTakeTheCurrentValueWhenTheListRuns) {
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(1, 0, 0);
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_POINTS, 0, 2);
  glEndList();
  glColor3f(0, 0, 1);
  glCallList(1);
  const auto d = recorded_draws(ctx_);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(at(d[0].vertices->color, 1), glm::vec4(0, 0, 1, 1));
}

TEST_F(ArrayListTest, CompiledElementsAndMultiDraws) {
  const GLushort indices[3] = {3, 1, 0};
  const GLint first[2] = {0, 2};
  const GLsizei count[2] = {2, 2};
  glNewList(1, GL_COMPILE);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, indices);
  glDrawRangeElements(GL_TRIANGLES, 0, 3, 3, GL_UNSIGNED_SHORT, indices);
  glMultiDrawArrays(GL_LINES, first, count, 2);
  const GLubyte a[2] = {0, 3};
  const void* lists[1] = {a};
  const GLsizei list_counts[1] = {2};
  glMultiDrawElements(GL_LINES, list_counts, GL_UNSIGNED_BYTE, lists, 1);
  glEndList();
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto d = recorded_draws(ctx_);
  // Replayed like glBegin/glEnd: primitives of one mode and state batch into one draw.
  ASSERT_EQ(d.size(), 2u);
  const glpt::rec::VertexData& triangles = *d[0].vertices;
  ASSERT_EQ(triangles.primitives.size(), 2u);
  EXPECT_EQ(triangles.vertex_count(), 6u);  // indices resolved when compiled
  EXPECT_EQ(triangles.position[0], glm::vec4(0, 1, 0, 1));
  EXPECT_EQ(triangles.position[5], glm::vec4(0, 0, 0, 1));
  const glpt::rec::VertexData& lines = *d[1].vertices;
  ASSERT_EQ(lines.primitives.size(), 3u);
  EXPECT_EQ(lines.position[2], glm::vec4(1, 1, 0, 1));
  EXPECT_EQ(lines.position[5], glm::vec4(0, 1, 0, 1));
}

TEST_F(ArrayListTest, BufferObjectDataIsCopiedWhenCompiled) {
  GLuint b[2] = {};
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof(float) * 8, positions_.data(), GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glDisableClientState(GL_COLOR_ARRAY);
  const GLuint indices[2] = {2, 3};
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);
  glNewList(1, GL_COMPILE);
  glDrawElements(GL_LINES, 2, GL_UNSIGNED_INT, nullptr);
  glEndList();
  glDeleteBuffers(2, b);
  glCallList(1);
  const auto d = recorded_draws(ctx_);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].vertices->position.at(1), glm::vec4(0, 1, 0, 1));
}

TEST_F(ArrayListTest, CompiledArrayElementSetsTheValuesItRead) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_POINTS);
  glArrayElement(2);
  glEnd();
  glArrayElement(1);  // outside glBegin/glEnd: the current values only
  glEndList();
  colours_.fill(9);
  glCallList(1);
  const auto d = recorded_draws(ctx_);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].vertices->position.at(0), glm::vec4(1, 1, 0, 1));
  EXPECT_EQ(at(d[0].vertices->color, 0), glm::vec4(0, 0, 1, 1));
  GLfloat current[4];
  glGetFloatv(GL_CURRENT_COLOR, current);
  EXPECT_EQ(current[1], 1.0f);  // vertex 1's green
  EXPECT_EQ(current[0], 0.0f);
}

TEST_F(ArrayListTest, ErrorsAreRaisedWhenTheListRuns) {
  const GLubyte indices[1] = {0};
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_POINTS, 0, -1);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glNewList(2, GL_COMPILE);
  glDrawElements(GL_POINTS, 1, GL_FLOAT, indices);
  glDrawRangeElements(GL_POINTS, 1, 0, 1, GL_UNSIGNED_BYTE, indices);
  glEndList();
  glCallList(2);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});  // the first of the two
  glNewList(3, GL_COMPILE);
  glMultiDrawArrays(GL_POINTS, nullptr, nullptr, -1);
  glEndList();
  glCallList(3);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  // A compiled draw replayed inside glBegin/glEnd is an error there.
  glNewList(4, GL_COMPILE);
  glDrawArrays(GL_POINTS, 0, 1);
  glEndList();
  glBegin(GL_POINTS);
  glCallList(4);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  // Also when it draws nothing: no vertex array when compiled (piglit gl-1.0-dlist-beginend).
  glDisableClientState(GL_VERTEX_ARRAY);
  glNewList(5, GL_COMPILE);
  glDrawArrays(GL_QUADS, 0, 4);
  glEndList();
  glBegin(GL_QUADS);
  glCallList(5);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_TRUE(recorded_draws(ctx_).empty());
}

TEST_F(ArrayListTest, ClientStateCommandsAreNotCompiled) {
  glNewList(1, GL_COMPILE);
  glDisableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_INT, 0, nullptr);
  glInterleavedArrays(GL_V2F, 0, positions_.data());
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glEndList();
  // Each ran at once...
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_SIZE), 2);
  EXPECT_EQ(get_integer(GL_CLIENT_ATTRIB_STACK_DEPTH), 1);
  glPopClientAttrib();
  glDisableClientState(GL_VERTEX_ARRAY);
  // ... and the list holds none of them.
  glCallList(1);
  EXPECT_FALSE(glIsEnabled(GL_VERTEX_ARRAY));
  EXPECT_EQ(get_integer(GL_CLIENT_ATTRIB_STACK_DEPTH), 0);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(ArrayListTest, DisabledVertexArrayCompilesNothing) {
  glDisableClientState(GL_VERTEX_ARRAY);
  glColor3f(0.5f, 0.5f, 0.5f);
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_POINTS, 0, 4);
  glEndList();
  glEnableClientState(GL_VERTEX_ARRAY);
  glCallList(1);
  EXPECT_TRUE(recorded_draws(ctx_).empty());
  GLfloat current[4];
  glGetFloatv(GL_CURRENT_COLOR, current);
  EXPECT_EQ(current[0], 0.5f);
}

}  // namespace
