// glMap1/glMap2 in display lists (GL 1.5 5.4): the control points are read when the command is
// compiled, so later changes to the client's array do not change the list.
//
// As Mesa compiles them (src/mesa/main/dlist.c): the points are copied packed, as floats (glMap*d
// converts them and the domain), and the list replays glMap*f with the packed strides, so errors
// are raised when the list runs, by glMap*f's checks. Like Mesa, a stride below the components
// (but not negative) is read as given at compile time, and the replay, seeing the packed
// stride, raises nothing. Points that cannot be read (null, an invalid target or order, a
// negative stride) are not copied; the replay then reports what glMap reports for them.
//
// The generated entry points call the compile_* functions while a list is being compiled
// (gen_gl_api.py, HAND_COMPILED); records of CommandId::glMap1f and glMap2f replay through
// replay_map1 and replay_map2.
#pragma once

#include "gl_shim/display_lists/list_stream.hpp"
#include "gl_shim/gl_types.h"

namespace glpt {

class Context;

void compile_map1f(Context& ctx, ListStream& list, GLenum target, GLfloat u1, GLfloat u2,
                   GLint stride, GLint order, const GLfloat* points);
void compile_map1d(Context& ctx, ListStream& list, GLenum target, GLdouble u1, GLdouble u2,
                   GLint stride, GLint order, const GLdouble* points);
void compile_map2f(Context& ctx, ListStream& list, GLenum target, GLfloat u1, GLfloat u2,
                   GLint ustride, GLint uorder, GLfloat v1, GLfloat v2, GLint vstride, GLint vorder,
                   const GLfloat* points);
void compile_map2d(Context& ctx, ListStream& list, GLenum target, GLdouble u1, GLdouble u2,
                   GLint ustride, GLint uorder, GLdouble v1, GLdouble v2, GLint vstride,
                   GLint vorder, const GLdouble* points);

void replay_map1(Context& ctx, const ListStream::Reader& record);
void replay_map2(Context& ctx, const ListStream::Reader& record);

}  // namespace glpt
