/* glx_window.h: the window every bench/ program draws into: a double-buffered RGBA GLX window
 * with a 24-bit depth buffer, mapped, its context current and the viewport covering it. Linked
 * against the system libGL.so.1, so glpt's replaces it when preloaded. */
#ifndef GLPT_BENCH_GLX_WINDOW_H
#define GLPT_BENCH_GLX_WINDOW_H

#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <stdio.h>

typedef struct {
  Display* dpy;
  Window window;
  GLXContext context;
} GlxWindow;

/* 0 on success; otherwise says why on stderr, prefixed by `program`, and returns 1. */
static inline int glx_window_open(GlxWindow* w, const char* program, int width, int height) {
  w->dpy = XOpenDisplay(NULL);
  if (!w->dpy) {
    fprintf(stderr, "%s: cannot open display\n", program);
    return 1;
  }
  int attributes[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_DEPTH_SIZE, 24, None};
  XVisualInfo* visual = glXChooseVisual(w->dpy, DefaultScreen(w->dpy), attributes);
  if (!visual) {
    fprintf(stderr, "%s: no visual\n", program);
    XCloseDisplay(w->dpy);
    return 1;
  }
  Window root = RootWindow(w->dpy, visual->screen);
  XSetWindowAttributes wa = {0};
  wa.colormap = XCreateColormap(w->dpy, root, visual->visual, AllocNone);
  w->window = XCreateWindow(w->dpy, root, 0, 0, (unsigned)width, (unsigned)height, 0, visual->depth,
                            InputOutput, visual->visual, CWColormap, &wa);
  XMapWindow(w->dpy, w->window);
  XSync(w->dpy, False);
  w->context = glXCreateContext(w->dpy, visual, NULL, True);
  XFree(visual);
  glXMakeCurrent(w->dpy, w->window, w->context);
  glViewport(0, 0, width, height);
  return 0;
}

static inline void glx_window_close(GlxWindow* w) {
  glXMakeCurrent(w->dpy, None, NULL);
  glXDestroyContext(w->dpy, w->context);
  XDestroyWindow(w->dpy, w->window);
  XCloseDisplay(w->dpy);
}

#endif
