// Helpers shared by the window-system tests (tests/glx, tests/egl): a mapped X window of a visual,
// and a frame whose pixels are known. Include after <gtest/gtest.h> (Xlib's macros break gtest).
#pragma once

#include <GL/gl.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace glpt_test {

// A mapped window of `vi`'s visual, synced so the server knows it before GL looks at it.
inline Window create_mapped_window(Display* dpy, const XVisualInfo& vi, int w, int h) {
  XSetWindowAttributes attr{};
  attr.colormap = XCreateColormap(dpy, RootWindow(dpy, vi.screen), vi.visual, AllocNone);
  const Window window = XCreateWindow(dpy, RootWindow(dpy, vi.screen), 0, 0, w, h, 0, vi.depth,
                                      InputOutput, vi.visual, CWColormap, &attr);
  XMapWindow(dpy, window);
  XSync(dpy, False);
  return window;
}

// An unlit red quad over the left half on a blue background; returns the pixels at (x0, y) and
// (x1, y) read back with glReadPixels.
inline void draw_half_red(int x0, int x1, int y, unsigned char left[4], unsigned char right[4]) {
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 1, 0, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1, 0, 0);
  glBegin(GL_QUADS);
  glVertex2f(0, 0);
  glVertex2f(0.5f, 0);
  glVertex2f(0.5f, 1);
  glVertex2f(0, 1);
  glEnd();
  glReadPixels(x0, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, left);
  glReadPixels(x1, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, right);
}

}  // namespace glpt_test
