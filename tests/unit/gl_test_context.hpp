// A glpt::Context made current for the duration of a test, without any window system.
#pragma once

#include <gtest/gtest.h>

#include "gl_shim/context.hpp"
#include "gl_shim/gl_enums.h"

// The exported entry points (defined in the generated gl_entry_points.cpp).
#include "gl_shim/gl_commands.hpp"
extern "C" {
#include "gl_shim/gl_types.h"
}

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override { glpt::set_current_context(&ctx_); }
  void TearDown() override { glpt::set_current_context(nullptr); }
  glpt::Context ctx_{nullptr};
};

extern "C" {
void glBegin(GLenum);
void glEnd(void);
void glVertex3f(GLfloat, GLfloat, GLfloat);
void glVertex2i(GLint, GLint);
void glVertex4f(GLfloat, GLfloat, GLfloat, GLfloat);
void glNormal3f(GLfloat, GLfloat, GLfloat);
void glColor3ub(GLubyte, GLubyte, GLubyte);
void glColor4f(GLfloat, GLfloat, GLfloat, GLfloat);
void glMatrixMode(GLenum);
void glLoadIdentity(void);
void glPushMatrix(void);
void glPopMatrix(void);
void glTranslatef(GLfloat, GLfloat, GLfloat);
void glRotatef(GLfloat, GLfloat, GLfloat, GLfloat);
void glScalef(GLfloat, GLfloat, GLfloat);
void glFrustum(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble);
void glOrtho(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble);
void glGetFloatv(GLenum, GLfloat*);
void glGetIntegerv(GLenum, GLint*);
GLenum glGetError(void);
void glEnable(GLenum);
void glDisable(GLenum);
GLboolean glIsEnabled(GLenum);
GLuint glGenLists(GLsizei);
void glNewList(GLuint, GLenum);
void glEndList(void);
void glCallList(GLuint);
void glCallLists(GLsizei, GLenum, const void*);
void glListBase(GLuint);
void glDeleteLists(GLuint, GLsizei);
GLboolean glIsList(GLuint);
void glLightfv(GLenum, GLenum, const GLfloat*);
void glGetLightfv(GLenum, GLenum, GLfloat*);
void glMaterialfv(GLenum, GLenum, const GLfloat*);
void glGetMaterialfv(GLenum, GLenum, GLfloat*);
void glShadeModel(GLenum);
void glClear(GLbitfield);
void glViewport(GLint, GLint, GLsizei, GLsizei);
const GLubyte* glGetString(GLenum);
void glAccum(GLenum, GLfloat);
void glMultMatrixf(const GLfloat*);
}
