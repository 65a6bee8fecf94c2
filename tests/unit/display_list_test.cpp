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
  EXPECT_EQ(d[0].vertices->keys().geometry, d[1].vertices->keys().geometry);
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

namespace {

std::vector<GLfloat> material(GLenum face, GLenum pname) {
  GLfloat v[4] = {-9, -9, -9, -9};
  glGetMaterialfv(face, pname, v);
  return {v[0], v[1], v[2], v[3]};
}

std::vector<GLfloat> border_colour() {
  GLfloat v[4] = {-9, -9, -9, -9};
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, v);
  return {v[0], v[1], v[2], v[3]};
}

// Mesa's scalar parameter commands pass (param, 0, 0, 0) to their vector form for any pname
// (piglit gl-1.0-beginend-coverage calls glMaterialf(GL_AMBIENT), glLightModelf(GL_AMBIENT)).
TEST_F(GlTest, ScalarFormsOfVectorParametersTakeTheValueAndZeros) {
  glMaterialf(GL_FRONT, GL_AMBIENT, 0.5f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(material(GL_FRONT, GL_AMBIENT), (std::vector<GLfloat>{0.5f, 0, 0, 0}));
  glMateriali(GL_BACK, GL_EMISSION, 1);  // converted as a float, not as a colour integer
  EXPECT_EQ(material(GL_BACK, GL_EMISSION), (std::vector<GLfloat>{1, 0, 0, 0}));
  glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.25f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLfloat v[4] = {};
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
  EXPECT_EQ(std::vector<GLfloat>(v, v + 4), (std::vector<GLfloat>{0.25f, 0, 0, 0}));
  glLightf(GL_LIGHT1, GL_DIFFUSE, 0.75f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glGetLightfv(GL_LIGHT1, GL_DIFFUSE, v);
  EXPECT_EQ(std::vector<GLfloat>(v, v + 4), (std::vector<GLfloat>{0.75f, 0, 0, 0}));
  glMaterialf(GL_FRONT, GL_SHININESS, 200.0f);  // still validated
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glMaterialf(GL_FRONT, GL_POSITION, 1.0f);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
}

// Executed at once, glTexParameterf(GL_TEXTURE_BORDER_COLOR) is an error in Mesa; compiled, Mesa
// records it as glTexParameterfv with (param, 0, 0, 0) (piglit gl-1.0-beginend-coverage).
TEST_F(GlTest, CompiledScalarParametersAreTheirVectorForm) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(border_colour(), (std::vector<GLfloat>{0, 0, 0, 0}));

  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(border_colour(), (std::vector<GLfloat>{0.5f, 0, 0, 0}));

  // glTexParameteri compiles as glTexParameterfv of the value as a float (not a colour integer).
  glNewList(list, GL_COMPILE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glEndList();
  EXPECT_EQ(border_colour(), (std::vector<GLfloat>{0.5f, 0, 0, 0}));  // not executed
  glCallList(list);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(border_colour(), (std::vector<GLfloat>{1, 0, 0, 0}));
  GLint filter = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
  EXPECT_EQ(filter, GL_LINEAR);
  glDeleteLists(list, 1);
  glDeleteTextures(1, &texture);
}

// While GL_COLOR_MATERIAL tracks a material colour, glMaterial leaves that colour alone (Mesa's
// _mesa_Materialfv), executed at once or from a display list (piglit dlist-color-material).
TEST_F(GlTest, MaterialOfATrackedColourIsIgnored) {
  const GLfloat red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor4f(0, 1, 0, 1);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red);
  EXPECT_EQ(material(GL_FRONT, GL_DIFFUSE), (std::vector<GLfloat>{0, 1, 0, 1}));
  EXPECT_EQ(material(GL_FRONT, GL_AMBIENT), (std::vector<GLfloat>{1, 0, 0, 1}));  // untracked
  EXPECT_EQ(material(GL_BACK, GL_DIFFUSE), (std::vector<GLfloat>{1, 0, 0, 1}));   // untracked

  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
  glEndList();
  glCallList(list);
  EXPECT_EQ(material(GL_FRONT, GL_DIFFUSE), (std::vector<GLfloat>{0, 1, 0, 1}));
  // Not tracked any more: glMaterial applies again.
  glDisable(GL_COLOR_MATERIAL);
  glCallList(list);
  EXPECT_EQ(material(GL_FRONT, GL_DIFFUSE), (std::vector<GLfloat>{0, 0, 1, 1}));
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

}  // namespace
