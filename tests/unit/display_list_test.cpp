#include <variant>

#include "gl_test_context.hpp"

namespace {

std::vector<glpt::rec::Draw> draws(glpt::Context& ctx) {
  ctx.recorder.seal();
  std::vector<glpt::rec::Draw> out;
  for (const auto& c : ctx.recorder.record().commands)
    if (const auto* d = std::get_if<glpt::rec::Draw>(&c)) out.push_back(*d);
  return out;
}

TEST_F(GlTest, CompiledListReplaysGeometryAndMaterial) {
  const GLuint list = glGenLists(1);
  ASSERT_NE(list, 0u);
  const GLfloat red[4] = {0.8f, 0.1f, 0.0f, 1.0f};
  glEnable(GL_LIGHTING);
  glNewList(list, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex3f(0, 0, 0);
  glVertex3f(1, 0, 0);
  glVertex3f(0, 1, 0);
  glEnd();
  glEndList();
  // GL_COMPILE executes nothing.
  EXPECT_TRUE(draws(ctx_).empty());
  GLfloat diffuse[4];
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  EXPECT_FLOAT_EQ(diffuse[0], 0.8f);  // the default material diffuse
  EXPECT_TRUE(glIsList(list));

  glCallList(list);
  const auto d = draws(ctx_);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].vertices->position.at(1), glm::vec4(1, 0, 0, 1));
  const auto& state = ctx_.recorder.record().states.at(d[0].state);
  EXPECT_TRUE(state.lighting->enabled);
  EXPECT_FLOAT_EQ(state.lighting->material[0].diffuse.r, 0.8f);
  EXPECT_FLOAT_EQ(state.lighting->material[0].diffuse.g, 0.1f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, SameListUnderAnotherMatrixGivesSameGeometry) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_QUADS);
  glVertex3f(0, 0, 0);
  glVertex3f(1, 0, 0);
  glVertex3f(1, 1, 0);
  glVertex3f(0, 1, 0);
  glEnd();
  glEndList();
  glPushMatrix();
  glCallList(list);
  glPopMatrix();
  glTranslatef(3, 0, 0);  // a new modelview: a second draw
  glCallList(list);
  const auto d = draws(ctx_);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].vertices->geometry_key, d[1].vertices->geometry_key);
  const auto& states = ctx_.recorder.record().states;
  EXPECT_FLOAT_EQ(states.at(d[1].state).transform->modelview[3][0], 3.0f);
}

TEST_F(GlTest, CompileAndExecuteRunsImmediately) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glTranslatef(2, 0, 0);
  glEndList();
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_FLOAT_EQ(m[12], 2.0f);
  glCallList(list);
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_FLOAT_EQ(m[12], 4.0f);
}

TEST_F(GlTest, CallListsUsesListBaseAndTypes) {
  const GLuint base = glGenLists(3);
  for (GLuint i = 0; i < 3; ++i) {
    glNewList(base + i, GL_COMPILE);
    glTranslatef(static_cast<float>(i + 1), 0, 0);  // list k moves by k+1
    glEndList();
  }
  glListBase(base);
  const GLubyte names[2] = {0, 2};
  glCallLists(2, GL_UNSIGNED_BYTE, names);
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_FLOAT_EQ(m[12], 4.0f);  // 1 + 3
  glCallLists(1, 0x1234, names);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glCallLists(-1, GL_UNSIGNED_BYTE, names);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
}

TEST_F(GlTest, NestedListsAndRecursionAreBounded) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTranslatef(1, 0, 0);
  glCallList(list);  // calls itself: GL limits nesting to GL_MAX_LIST_NESTING
  glEndList();
  glCallList(list);
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  GLint max_nesting = 0;
  glGetIntegerv(GL_MAX_LIST_NESTING, &max_nesting);
  EXPECT_FLOAT_EQ(m[12], static_cast<float>(max_nesting));
}

TEST_F(GlTest, ListErrors) {
  glNewList(0, GL_COMPILE);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glNewList(1, 0x1234);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glEndList();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glNewList(5, GL_COMPILE);
  glNewList(6, GL_COMPILE);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glEndList();
  EXPECT_TRUE(glIsList(5));
  glDeleteLists(5, 1);
  EXPECT_FALSE(glIsList(5));
  glCallList(12345);  // an undefined list does nothing
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, LightPositionIsStoredInEyeSpaceAtCallTime) {
  glTranslatef(0, 0, -10);
  const GLfloat pos[4] = {1, 2, 3, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLoadIdentity();
  GLfloat got[4];
  glGetLightfv(GL_LIGHT0, GL_POSITION, got);
  EXPECT_FLOAT_EQ(got[2], -7.0f);
  EXPECT_FLOAT_EQ(got[3], 1.0f);
}

}  // namespace
