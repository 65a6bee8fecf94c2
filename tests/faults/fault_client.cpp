// A small GL program for the fault tests (faults_test.sh), linked with glpt's libGL.so.1. Each
// mode prints what it saw as "key value" lines on stdout; the script runs it in a broken
// environment (no Vulkan, no ray queries, no X display, an unwritable GLPT_OUTPUT, a window
// destroyed under it) and checks those lines, the exit status and stderr.
//
//   fault_client draw FRAMES         a GLX window; per frame a clear to blue and a red quad over
//                                    the left half, swapped; then the pixels of the right half
//                                    (glReadPixels and the window's), GL state and errors; then
//                                    a frame from a second, unshared context
//   fault_client no-display          GLX and EGL without an X server
//   fault_client window-closed MODE  frames into a GLX window that another connection destroys
//                                    (MODE destroy) or whose client it kills (MODE kill) after
//                                    frame 3, or an EGL window it destroys (MODE destroy-egl);
//                                    then exits without destroying its context
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#define EGL_EGLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "../common/x11_gl_test_util.hpp"

namespace {

struct GlxWindow {
  Display* dpy = nullptr;
  Window window = 0;
  GLXContext ctx = nullptr;
  XVisualInfo visual{};
};

bool open_glx_window(GlxWindow* w, int size) {
  w->dpy = XOpenDisplay(nullptr);
  if (w->dpy == nullptr) return false;
  int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_DEPTH_SIZE, 1, None};
  XVisualInfo* vi = glXChooseVisual(w->dpy, DefaultScreen(w->dpy), attribs);
  if (vi == nullptr) return false;
  XSetWindowAttributes attr{};
  attr.colormap = XCreateColormap(w->dpy, RootWindow(w->dpy, vi->screen), vi->visual, AllocNone);
  w->window = XCreateWindow(w->dpy, RootWindow(w->dpy, vi->screen), 0, 0, size, size, 0, vi->depth,
                            InputOutput, vi->visual, CWColormap, &attr);
  XMapWindow(w->dpy, w->window);
  w->ctx = glXCreateContext(w->dpy, vi, nullptr, True);
  w->visual = *vi;
  XFree(vi);
  return w->ctx != nullptr && glXMakeCurrent(w->dpy, w->window, w->ctx);
}

// A blue clear and a red quad over the left half of the 32x32 window; the pixels at (8, 16) and
// (24, 16) as glReadPixels reads them.
void draw_frame(GLubyte left[4] = nullptr, GLubyte right[4] = nullptr) {
  GLubyte ignored[2][4];
  glpt_test::draw_half_red(8, 24, 16, left ? left : ignored[0], right ? right : ignored[1]);
}

int draw(int frames) {
  GlxWindow w;
  if (!open_glx_window(&w, 32)) return 2;
  for (int i = 0; i < frames; ++i) {
    draw_frame();
    glXSwapBuffers(w.dpy, w.window);
  }
  std::printf("frames %d\n", frames);
  // What the window shows (glpt presents over its own connection: the program's requests
  // after the swap see it).
  XSync(w.dpy, False);
  XImage* image = XGetImage(w.dpy, w.window, 24, 16, 1, 1, AllPlanes, ZPixmap);
  if (image != nullptr) {
    std::printf("window_right 0x%06lx\n", XGetPixel(image, 0, 0) & 0xFFFFFF);
    XDestroyImage(image);
  }
  // GL's state machine answers, whatever the renderer.
  GLubyte left[4] = {}, right[4] = {};
  draw_frame(left, right);
  std::printf("read_left %d %d %d %d\n", left[0], left[1], left[2], left[3]);
  std::printf("read_right %d %d %d %d\n", right[0], right[1], right[2], right[3]);
  GLfloat depth = -1;
  glReadPixels(24, 16, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  std::printf("read_depth_right %g\n", depth);
  GLfloat clear[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  std::printf("clear_value %g %g %g %g\n", clear[0], clear[1], clear[2], clear[3]);
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  std::printf("viewport %d %d %d %d\n", viewport[0], viewport[1], viewport[2], viewport[3]);
  glEnable(GL_LIGHTING);
  std::printf("lighting %d\n", glIsEnabled(GL_LIGHTING));
  glEnable(0x1234);  // an invalid capability: GL_INVALID_ENUM
  std::printf("error 0x%x\n", glGetError());
  std::printf("error_after 0x%x\n", glGetError());
  // A second context (another share group, so another renderer) says nothing new: what is
  // missing is said once per process.
  GLXContext second = glXCreateContext(w.dpy, &w.visual, nullptr, True);
  if (second != nullptr && glXMakeCurrent(w.dpy, w.window, second)) {
    draw_frame();
    glXSwapBuffers(w.dpy, w.window);
    std::printf("second_context drew\n");
  }
  glXMakeCurrent(w.dpy, None, nullptr);
  if (second != nullptr) glXDestroyContext(w.dpy, second);
  glXDestroyContext(w.dpy, w.ctx);
  XDestroyWindow(w.dpy, w.window);
  XCloseDisplay(w.dpy);
  return 0;
}

int no_display() {
  // An unset DISPLAY or a dead server: Xlib has no Display for the program to give GLX.
  Display* dpy = XOpenDisplay(nullptr);
  std::printf("XOpenDisplay %s\n", dpy ? "display" : "NULL");
  int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, None};
  std::printf("glXChooseVisual %s\n", glXChooseVisual(dpy, 0, attribs) ? "visual" : "NULL");
  int n = -1;
  GLXFBConfig* configs = glXChooseFBConfig(dpy, 0, nullptr, &n);
  std::printf("glXChooseFBConfig %s %d\n", configs ? "configs" : "NULL", n);
  std::printf("glXCreateContext %s\n",
              glXCreateContext(dpy, nullptr, nullptr, True) ? "context" : "NULL");
  std::printf("glXGetCurrentContext %s\n", glXGetCurrentContext() ? "context" : "NULL");
  // EGL: the default display has a handle; initializing it is EGL_NOT_INITIALIZED (EGL 1.5 3.2).
  EGLDisplay egl = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  std::printf("eglGetDisplay %s 0x%x\n", egl != EGL_NO_DISPLAY ? "display" : "EGL_NO_DISPLAY",
              eglGetError());
  EGLint major = 0, minor = 0;
  const EGLBoolean initialized = eglInitialize(egl, &major, &minor);
  std::printf("eglInitialize %d 0x%x\n", initialized, eglGetError());
  EGLint count = -1;
  const EGLBoolean got_configs = eglGetConfigs(egl, nullptr, 0, &count);
  std::printf("eglGetConfigs %d 0x%x\n", got_configs, eglGetError());
  // The surfaceless platform needs no X server.
  EGLDisplay surfaceless = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, nullptr, nullptr);
  std::printf("surfaceless %d\n", eglInitialize(surfaceless, nullptr, nullptr));
  eglTerminate(surfaceless);
  // GL without a current context: nothing happens, nothing crashes.
  glClear(GL_COLOR_BUFFER_BIT);
  std::printf("glGetError 0x%x\n", glGetError());
  return 0;
}

// An EGL window surface and context current on `dpy`'s window `*window` (as xscreensaver's
// hacks make theirs).
bool open_egl_window(Display* dpy, Window* window) {
  EGLDisplay egl = eglGetDisplay(reinterpret_cast<EGLNativeDisplayType>(dpy));
  if (!eglInitialize(egl, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API)) return false;
  const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                            EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  if (!eglChooseConfig(egl, attribs, &config, 1, &n) || n != 1) return false;
  EGLint visual_id = 0;
  eglGetConfigAttrib(egl, config, EGL_NATIVE_VISUAL_ID, &visual_id);
  XVisualInfo templ{};
  templ.visualid = static_cast<VisualID>(visual_id);
  XVisualInfo* vi = XGetVisualInfo(dpy, VisualIDMask, &templ, &n);
  if (vi == nullptr) return false;
  XSetWindowAttributes attr{};
  attr.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
  *window = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, 32, 32, 0, vi->depth, InputOutput,
                          vi->visual, CWColormap, &attr);
  XFree(vi);
  XMapWindow(dpy, *window);
  XSync(dpy, False);
  EGLSurface surface = eglCreateWindowSurface(egl, config, *window, nullptr);
  EGLContext ctx = eglCreateContext(egl, config, EGL_NO_CONTEXT, nullptr);
  return surface != EGL_NO_SURFACE && ctx != EGL_NO_CONTEXT &&
         eglMakeCurrent(egl, surface, surface, ctx);
}

int window_closed(const char* mode) {
  const bool egl = std::strcmp(mode, "destroy-egl") == 0;
  GlxWindow w;
  if (egl) {
    w.dpy = XOpenDisplay(nullptr);
    if (w.dpy == nullptr || !open_egl_window(w.dpy, &w.window)) return 2;
  } else if (!open_glx_window(&w, 32)) {
    return 2;
  }
  Display* other = XOpenDisplay(nullptr);
  if (other == nullptr) return 2;
  for (int frame = 0; frame < 8; ++frame) {
    if (frame == 3) {
      // Mid-frame: drawn but not swapped yet.
      draw_frame();
      if (std::strcmp(mode, "kill") == 0)
        XKillClient(other, w.window);  // the program's connection dies with its window
      else
        XDestroyWindow(other, w.window);
      XSync(other, False);
      std::printf("closed %d\n", frame);
      std::fflush(stdout);
    }
    draw_frame();
    if (egl)
      eglSwapBuffers(eglGetCurrentDisplay(), eglGetCurrentSurface(EGL_DRAW));
    else
      glXSwapBuffers(w.dpy, w.window);
    std::printf("frame %d\n", frame);
    std::fflush(stdout);
  }
  // Exits with the context current and nothing destroyed.
  std::printf("exit\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::strcmp(argv[1], "draw") == 0) return draw(std::atoi(argv[2]));
  if (argc >= 2 && std::strcmp(argv[1], "no-display") == 0) return no_display();
  if (argc >= 3 && std::strcmp(argv[1], "window-closed") == 0) return window_closed(argv[2]);
  std::fprintf(stderr, "usage: fault_client draw FRAMES | no-display | window-closed MODE\n");
  return 2;
}
