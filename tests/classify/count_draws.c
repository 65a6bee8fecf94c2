/* count_draws.c: an LD_PRELOAD library for real Mesa (never for glpt) that counts a program's
 * drawing commands per frame, as tests/classify defines them, and writes one line per frame to
 * $CLASSIFY_COUNT_LOG: `COUNT <frame> <commands>`. check_labels.py --labels-only --count-shim
 * compares these counts with the program's labels, so a labelled program that forgets a label,
 * or labels a command it does not issue, fails on Mesa, independently of glpt.
 *
 * Counted (one each): a glBegin/glEnd pair (counted at glBegin), glDrawArrays, glDrawElements,
 * glDrawRangeElements, glRect*, glBitmap, glDrawPixels; and, for glCallList, the commands the
 * list recorded when it was compiled (nested glCallList included). A frame ends at
 * glXSwapBuffers. Commands compiled with GL_COMPILE are not executed and not counted then;
 * GL_COMPILE_AND_EXECUTE counts them as executed too. glCallLists is not supported (the
 * labelled programs do not use it): it writes `UNSUPPORTED glCallLists` and counts nothing.
 */
#define _GNU_SOURCE
#include <GL/gl.h>
#include <GL/glx.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>

#define EXPORT __attribute__((visibility("default")))

enum { kMaxLists = 4096 };

static FILE* count_log;
static int frame_index;
static long frame_commands;
static long list_commands[kMaxLists]; /* drawing commands recorded in each list, by name */
static GLuint compiling;              /* the list being compiled; 0: none */
static GLenum compile_mode;

static void* next(const char* name) {
  void* f = dlsym(RTLD_NEXT, name);
  if (!f) {
    fprintf(stderr, "count_draws: %s not found in the next libGL\n", name);
    exit(99);
  }
  return f;
}

static FILE* out(void) {
  if (!count_log) {
    const char* path = getenv("CLASSIFY_COUNT_LOG");
    count_log = path && *path ? fopen(path, "w") : NULL;
    if (!count_log) {
      fprintf(stderr, "count_draws: set CLASSIFY_COUNT_LOG to a writable file\n");
      exit(99);
    }
  }
  return count_log;
}

/* n drawing commands issued now: recorded into the list being compiled, executed or both. */
static void count(long n) {
  if (compiling && compiling < kMaxLists) list_commands[compiling] += n;
  if (!compiling || compile_mode == GL_COMPILE_AND_EXECUTE) frame_commands += n;
}

#define COUNTED(name, params, args)          \
  EXPORT void name params {                  \
    static void(*real) params;               \
    if (!real) *(void**)&real = next(#name); \
    count(1);                                \
    real args;                               \
  }

COUNTED(glBegin, (GLenum mode), (mode))
COUNTED(glDrawArrays, (GLenum mode, GLint first, GLsizei n), (mode, first, n))
COUNTED(glDrawElements, (GLenum mode, GLsizei n, GLenum type, const void* indices),
        (mode, n, type, indices))
COUNTED(glDrawRangeElements,
        (GLenum mode, GLuint start, GLuint end, GLsizei n, GLenum type, const void* indices),
        (mode, start, end, n, type, indices))
COUNTED(glRectd, (GLdouble a, GLdouble b, GLdouble c, GLdouble d), (a, b, c, d))
COUNTED(glRectf, (GLfloat a, GLfloat b, GLfloat c, GLfloat d), (a, b, c, d))
COUNTED(glRecti, (GLint a, GLint b, GLint c, GLint d), (a, b, c, d))
COUNTED(glRects, (GLshort a, GLshort b, GLshort c, GLshort d), (a, b, c, d))
COUNTED(glRectdv, (const GLdouble* a, const GLdouble* b), (a, b))
COUNTED(glRectfv, (const GLfloat* a, const GLfloat* b), (a, b))
COUNTED(glRectiv, (const GLint* a, const GLint* b), (a, b))
COUNTED(glRectsv, (const GLshort* a, const GLshort* b), (a, b))
COUNTED(glBitmap,
        (GLsizei w, GLsizei h, GLfloat x, GLfloat y, GLfloat dx, GLfloat dy, const GLubyte* b),
        (w, h, x, y, dx, dy, b))
COUNTED(glDrawPixels, (GLsizei w, GLsizei h, GLenum format, GLenum type, const void* pixels),
        (w, h, format, type, pixels))

EXPORT void glNewList(GLuint list, GLenum mode) {
  static void (*real)(GLuint, GLenum);
  if (!real) *(void**)&real = next("glNewList");
  if (list < kMaxLists) list_commands[list] = 0;
  compiling = list;
  compile_mode = mode;
  real(list, mode);
}

EXPORT void glEndList(void) {
  static void (*real)(void);
  if (!real) *(void**)&real = next("glEndList");
  compiling = 0;
  real();
}

EXPORT void glCallList(GLuint list) {
  static void (*real)(GLuint);
  if (!real) *(void**)&real = next("glCallList");
  count(list < kMaxLists ? list_commands[list] : 0);
  real(list);
}

EXPORT void glDeleteLists(GLuint list, GLsizei range) {
  static void (*real)(GLuint, GLsizei);
  if (!real) *(void**)&real = next("glDeleteLists");
  for (GLsizei i = 0; i < range; ++i) {
    if (list + (GLuint)i < kMaxLists) list_commands[list + (GLuint)i] = 0;
  }
  real(list, range);
}

EXPORT void glCallLists(GLsizei n, GLenum type, const void* lists) {
  static void (*real)(GLsizei, GLenum, const void*);
  if (!real) *(void**)&real = next("glCallLists");
  fprintf(out(), "UNSUPPORTED glCallLists\n");
  real(n, type, lists);
}

EXPORT void glXSwapBuffers(Display* dpy, GLXDrawable drawable) {
  static void (*real)(Display*, GLXDrawable);
  if (!real) *(void**)&real = next("glXSwapBuffers");
  fprintf(out(), "COUNT %d %ld\n", frame_index, frame_commands);
  fflush(count_log);
  ++frame_index;
  frame_commands = 0;
  real(dpy, drawable);
}
