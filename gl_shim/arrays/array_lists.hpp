// Array draws in display lists (GL 1.5 5.4): glArrayElement, glDrawArrays, glDrawElements,
// glDrawRangeElements and glMultiDraw* are compiled with their array data dereferenced, so later
// changes to the arrays (or their pointers, or buffer objects) do not change the list.
//
// As Mesa compiles them: a draw becomes, per primitive, the vertices glBegin + glArrayElement(i)
// + glEnd would give (immediate-mode conversions); when the list runs, the primitive is drawn
// with the current values of the attributes whose arrays were disabled at compile time, batched
// like a replayed glBegin/glEnd, and leaves the current values unchanged (Mesa compiles these
// vertices without updating the current values on replay). A compiled glArrayElement replays
// the attribute values it read (and does update them). Errors are raised when the list runs.
//
// The generated entry points call the compile_* functions while a list is being compiled
// (gen_gl_api.py, HAND_COMPILED); the list replays the records through the replay_* functions.
#pragma once

#include "gl_shim/display_lists/list_stream.hpp"
#include "gl_shim/gl_types.h"

namespace glpt {

class Context;

void compile_array_element(Context& ctx, ListStream& list, GLint i);
void compile_draw_arrays(Context& ctx, ListStream& list, GLenum mode, GLint first, GLsizei count);
void compile_draw_elements(Context& ctx, ListStream& list, GLenum mode, GLsizei count, GLenum type,
                           const void* indices);
void compile_draw_range_elements(Context& ctx, ListStream& list, GLenum mode, GLuint start,
                                 GLuint end, GLsizei count, GLenum type, const void* indices);
void compile_multi_draw_arrays(Context& ctx, ListStream& list, GLenum mode, const GLint* first,
                               const GLsizei* count, GLsizei drawcount);
void compile_multi_draw_elements(Context& ctx, ListStream& list, GLenum mode, const GLsizei* count,
                                 GLenum type, const void* const* indices, GLsizei drawcount);

// Records written under CommandId::glArrayElement and CommandId::glDrawArrays.
void replay_array_element(Context& ctx, const ListStream::Reader& record);
void replay_array_primitive(Context& ctx, const ListStream::Reader& record);

}  // namespace glpt
