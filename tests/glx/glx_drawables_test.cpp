// GLX drawables against glpt's libGL.so.1 on Xvfb: single-buffered windows shown by glFlush and
// glFinish, swapped frames once glXWaitGL returns (read back from the X server with XGetImage),
// a swap shown at once with GLPT_PRESENT=sync, drawables without depth, resize between
// frames, pixmaps, pbuffers, swap intervals, glXCopyContext, several contexts, and the errors GLX
// names for bad input (through the X error handler, as Mesa reports them).

// gtest before the X headers: Xlib's macros (None, Bool, Status) break gtest's templates.
// clang-format off
#include <gtest/gtest.h>
#include <GL/gl.h>
#include <GL/glx.h>
#include "../common/x11_gl_test_util.hpp"
#include "image_io.hpp"
// clang-format on

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#ifndef GLX_CONTEXT_MAJOR_VERSION_ARB
#define GLX_CONTEXT_MAJOR_VERSION_ARB 0x2091
#define GLX_CONTEXT_MINOR_VERSION_ARB 0x2092
#define GLX_CONTEXT_FLAGS_ARB 0x2094
#define GLX_CONTEXT_PROFILE_MASK_ARB 0x9126
#define GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB 0x2
#endif
#ifndef GLX_SWAP_INTERVAL_EXT
#define GLX_SWAP_INTERVAL_EXT 0x20F1
#endif

extern "C" {
void glXSwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval);
int glXSwapIntervalMESA(unsigned int interval);
int glXGetSwapIntervalMESA(void);
int glXSwapIntervalSGI(int interval);
GLXContext glXCreateContextAttribsARB(Display*, GLXFBConfig, GLXContext, Bool, const int*);
}

namespace {

// The errors the X error handler saw (Xlib calls it synchronously, on this thread).
std::vector<int> g_errors;
int record_x_error(Display*, XErrorEvent* e) {
  g_errors.push_back(e->error_code);
  return 0;
}

class GlxDrawables : public ::testing::Test {
 protected:
  void SetUp() override {
    dpy_ = XOpenDisplay(nullptr);
    ASSERT_NE(dpy_, nullptr) << "no X display (run under tests/e2e/with_xvfb.sh)";
    ASSERT_TRUE(glXQueryExtension(dpy_, &error_base_, &event_base_));
    g_errors.clear();
    old_handler_ = XSetErrorHandler(record_x_error);
  }
  void TearDown() override {
    glXMakeCurrent(dpy_, None, nullptr);
    for (GLXContext c : contexts_) glXDestroyContext(dpy_, c);
    for (Window w : windows_) XDestroyWindow(dpy_, w);
    XSync(dpy_, False);
    XSetErrorHandler(old_handler_);
    XCloseDisplay(dpy_);
  }
  XVisualInfo* visual(std::vector<int> attribs) {
    attribs.push_back(None);
    return glXChooseVisual(dpy_, 0, attribs.data());
  }
  // A mapped window, deliberately not synced: GLX must flush the program's Display itself.
  // Each at its own place: XGetImage of an obscured window part is undefined.
  Window unsynced_window(const XVisualInfo& vi, int w, int h) {
    const int x = 150 * static_cast<int>(windows_.size());
    XSetWindowAttributes attr{};
    attr.colormap = XCreateColormap(dpy_, RootWindow(dpy_, vi.screen), vi.visual, AllocNone);
    const Window win = XCreateWindow(dpy_, RootWindow(dpy_, vi.screen), x, 0, w, h, 0, vi.depth,
                                     InputOutput, vi.visual, CWColormap, &attr);
    XMapWindow(dpy_, win);
    windows_.push_back(win);
    return win;
  }
  // A double-buffered window (not synced) with a context of its visual.
  bool double_buffered_window(int w, int h, Window* win, GLXContext* ctx) {
    XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
    if (vi == nullptr) return false;
    *win = unsynced_window(*vi, w, h);
    *ctx = context(vi);
    XFree(vi);
    return *ctx != nullptr;
  }  // The same window, made current.
  bool current_double_buffered_window(int w, int h, Window* win) {
    GLXContext ctx = nullptr;
    return double_buffered_window(w, h, win, &ctx) && glXMakeCurrent(dpy_, *win, ctx);
  }

  // A 32x32 double-buffered window, current, with one red frame finished and swapped: the size
  // it had before a test resizes it.
  bool red_frame_shown(Window* win) {
    GLXContext ctx = nullptr;
    if (!double_buffered_window(32, 32, win, &ctx) || !glXMakeCurrent(dpy_, *win, ctx))
      return false;
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    glXSwapBuffers(dpy_, *win);
    return true;
  }
  GLXContext context(XVisualInfo* vi, GLXContext share = nullptr) {
    GLXContext c = glXCreateContext(dpy_, vi, share, True);
    if (c) contexts_.push_back(c);
    return c;
  }
  // A swap returns before the frame is on screen (as GLX allows; GLPT_PRESENT=later):
  // glXWaitGL makes it reach the window before the X requests that follow.
  void swap_and_wait(GLXDrawable d) {
    glXSwapBuffers(dpy_, d);
    glXWaitGL();
  }
  // The pixel (x, y) of an X drawable (rows top to bottom) as 0xRRGGBB.
  uint32_t x_pixel(Drawable d, int x, int y) {
    XImage* image = XGetImage(dpy_, d, x, y, 1, 1, AllPlanes, ZPixmap);
    if (image == nullptr) return 0xDEADBEEF;
    const uint32_t p = static_cast<uint32_t>(XGetPixel(image, 0, 0)) & 0xFFFFFF;
    XDestroyImage(image);
    return p;
  }
  bool saw_error(int code) {
    XSync(dpy_, False);
    for (int e : g_errors)
      if (e == code) return true;
    return false;
  }
  int glx_error(int offset) const { return error_base_ + offset; }

  Display* dpy_ = nullptr;
  int error_base_ = 0, event_base_ = 0;
  int (*old_handler_)(Display*, XErrorEvent*) = nullptr;
  std::vector<GLXContext> contexts_;
  std::vector<Window> windows_;
};

// GLX error codes (glxproto.h).
constexpr int kBadContext = 0, kBadDrawable = 2, kBadPixmap = 3, kBadFBConfig = 9, kBadPbuffer = 10,
              kBadWindow = 12;

void draw_red_left_half_on_blue() {
  unsigned char left[4], right[4];
  glpt_test::draw_half_red(1, 2, 1, left, right);  // the readback itself is not checked here
}

TEST_F(GlxDrawables, SingleBufferedGlFlushShowsTheImageWithoutXSync) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_RED_SIZE, 1});
  ASSERT_NE(vi, nullptr);
  int db = -1;
  ASSERT_EQ(glXGetConfig(dpy_, vi, GLX_DOUBLEBUFFER, &db), 0);
  ASSERT_EQ(db, 0);  // Mesa's choice too: single-buffered sorts first
  const Window win = unsynced_window(*vi, 40, 30);
  GLXContext ctx = context(vi);
  XFree(vi);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);  // the real size, not 0x0
  EXPECT_EQ(viewport[2], 40);
  EXPECT_EQ(viewport[3], 30);
  GLboolean doublebuffer = GL_TRUE;
  glGetBooleanv(GL_DOUBLEBUFFER, &doublebuffer);
  EXPECT_EQ(doublebuffer, GL_FALSE);
  GLint draw_buffer = 0, read_buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &draw_buffer);
  glGetIntegerv(GL_READ_BUFFER, &read_buffer);
  EXPECT_EQ(draw_buffer, GL_FRONT);
  EXPECT_EQ(read_buffer, GL_FRONT);

  draw_red_left_half_on_blue();
  glFlush();
  EXPECT_EQ(x_pixel(win, 5, 15), 0xFF0000u);
  EXPECT_EQ(x_pixel(win, 35, 15), 0x0000FFu);

  glClearColor(0, 1, 0, 1);  // the next frame ends with glFinish
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(x_pixel(win, 5, 15), 0x00FF00u);
  EXPECT_TRUE(g_errors.empty());
}

TEST_F(GlxDrawables, DoubleBufferedDrawsToTheBackAndSwapShowsIt) {
  Window win = 0;
  ASSERT_TRUE(current_double_buffered_window(32, 32, &win));
  GLboolean doublebuffer = GL_FALSE;
  glGetBooleanv(GL_DOUBLEBUFFER, &doublebuffer);
  EXPECT_EQ(doublebuffer, GL_TRUE);
  GLint draw_buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &draw_buffer);
  EXPECT_EQ(draw_buffer, GL_BACK);
  draw_red_left_half_on_blue();
  swap_and_wait(win);
  EXPECT_EQ(x_pixel(win, 2, 2), 0xFF0000u);
  EXPECT_EQ(x_pixel(win, 30, 2), 0x0000FFu);
}

// Frames swapped one after another without waiting are shown in order: after glXWaitGL the
// window holds the last (the presenting thread alternates between two shared-memory segments).
TEST_F(GlxDrawables, FramesSwappedWithoutWaitingAreShownInOrder) {
  Window win = 0;
  ASSERT_TRUE(current_double_buffered_window(24, 24, &win));
  for (int frame = 0; frame < 25; ++frame) {
    glClearColor(frame % 3 == 0 ? 1.0f : 0.0f, frame % 3 == 1 ? 1.0f : 0.0f,
                 frame % 3 == 2 ? 1.0f : 0.0f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy_, win);
  }
  glXWaitGL();
  EXPECT_EQ(x_pixel(win, 3, 3), 0xFF0000u);  // frame 24: 24 % 3 == 0
  EXPECT_EQ(x_pixel(win, 20, 20), 0xFF0000u);
  // glFinish waits for it as well.
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, win);
  glFinish();
  EXPECT_EQ(x_pixel(win, 3, 3), 0x0000FFu);
  EXPECT_TRUE(g_errors.empty());
}

// Rows land where GL put them while the presenting thread copies frames out of the front image
// (FrameEnd::front_pixels) and the program draws the next ones: GL's bottom row is the window's
// bottom row in every frame, and front-buffer drawing right after a swap waits for that copy.
TEST_F(GlxDrawables, SwappedFramesKeepTheirRowsWhileLaterFramesDraw) {
  Window win = 0;
  ASSERT_TRUE(current_double_buffered_window(24, 24, &win));
  glEnable(GL_SCISSOR_TEST);
  for (int frame = 0; frame < 20; ++frame) {
    glScissor(0, 0, 24, 12);  // GL's bottom half: red, then green in odd frames
    glClearColor(frame % 2 ? 0.0f : 1.0f, frame % 2 ? 1.0f : 0.0f, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(0, 12, 24, 12);  // the top half blue
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy_, win);
  }
  glXWaitGL();
  EXPECT_EQ(x_pixel(win, 5, 20), 0x00FF00u);  // X counts rows from the top
  EXPECT_EQ(x_pixel(win, 5, 3), 0x0000FFu);
  glClearColor(1, 0, 0, 1);
  glScissor(0, 0, 24, 24);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, win);
  glDrawBuffer(GL_FRONT);  // at once, while the frame may still be copied out
  glScissor(0, 0, 12, 24);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(x_pixel(win, 3, 3), 0xFFFFFFu);
  EXPECT_EQ(x_pixel(win, 20, 20), 0xFF0000u);
  glDisable(GL_SCISSOR_TEST);
  glDrawBuffer(GL_BACK);
  EXPECT_TRUE(g_errors.empty());
}

// A swap keeps the back buffer's contents (as Mesa's software swap does; glpt exchanges the
// colour images and copies the front back only where a frame uses the back before clearing all of
// it): a frame drawn without a clear, a partial (scissored) clear, reads of both buffers.
TEST_F(GlxDrawables, TheBackBufferKeepsItsContentsAcrossSwaps) {
  Window win = 0;
  ASSERT_TRUE(current_double_buffered_window(32, 32, &win));
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 32, 0, 32, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(1, 0, 0, 1);  // frame 1: red
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, win);
  glColor3f(0, 1, 0);  // frame 2: green left half over what the back holds
  glRectf(0, 0, 16, 32);
  swap_and_wait(win);
  EXPECT_EQ(x_pixel(win, 4, 4), 0x00FF00u);
  EXPECT_EQ(x_pixel(win, 28, 4), 0xFF0000u);
  for (GLenum buffer : {GL_BACK, GL_FRONT}) {
    glReadBuffer(buffer);
    unsigned char left[4] = {}, right[4] = {};
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, left);
    glReadPixels(28, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, right);
    EXPECT_EQ(left[1], 255) << buffer;
    EXPECT_EQ(left[0], 0) << buffer;
    EXPECT_EQ(right[0], 255) << buffer;
  }
  glReadBuffer(GL_BACK);
  glEnable(GL_SCISSOR_TEST);  // frame 3: only the right half cleared, blue
  glScissor(16, 0, 16, 32);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  swap_and_wait(win);
  EXPECT_EQ(x_pixel(win, 4, 4), 0x00FF00u);
  EXPECT_EQ(x_pixel(win, 28, 4), 0x0000FFu);
  glXSwapBuffers(dpy_, win);  // frame 4: nothing drawn, the same image
  glXSwapBuffers(dpy_, win);  // and again
  glFinish();
  EXPECT_EQ(x_pixel(win, 4, 4), 0x00FF00u);
  EXPECT_EQ(x_pixel(win, 28, 4), 0x0000FFu);
  glClearColor(1, 1, 1, 1);  // frame 5: a whole clear, then drawing into the front
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, win);
  glDrawBuffer(GL_FRONT);
  glColor3f(0, 0, 0);
  glRectf(0, 0, 8, 8);
  glFlush();
  EXPECT_EQ(x_pixel(win, 2, 29), 0x000000u);  // X rows run top to bottom
  EXPECT_EQ(x_pixel(win, 28, 4), 0xFFFFFFu);
  EXPECT_TRUE(g_errors.empty());
}

// GLPT_PRESENT=sync: the swap returns once the frame is on screen, as Mesa's software GLX.
TEST_F(GlxDrawables, WithSyncPresentingASwapShowsTheFrameAtOnce) {
  setenv("GLPT_PRESENT", "sync", 1);  // read when the context first renders
  Window win = 0;
  GLXContext ctx = nullptr;
  const bool made = double_buffered_window(24, 24, &win, &ctx) && glXMakeCurrent(dpy_, win, ctx);
  if (made) {
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy_, win);
  }
  const uint32_t shown = made ? x_pixel(win, 3, 3) : 0;
  unsetenv("GLPT_PRESENT");
  ASSERT_TRUE(made);
  EXPECT_EQ(shown, 0x00FF00u);
}

// A config without depth or stencil buffers: GL_*_BITS say so and the depth test always passes
// (GL 1.5 4.1.5: with no depth buffer it is as if the test always passed).
TEST_F(GlxDrawables, ADrawableWithoutDepthPassesTheDepthTest) {
  const int attribs[] = {GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 0, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, attribs, &n);
  ASSERT_GT(n, 0);
  int depth = -1, stencil = -1;
  glXGetFBConfigAttrib(dpy_, configs[0], GLX_DEPTH_SIZE, &depth);
  glXGetFBConfigAttrib(dpy_, configs[0], GLX_STENCIL_SIZE, &stencil);
  ASSERT_EQ(depth, 0);  // Mesa sorts "zero, else larger" depth first
  ASSERT_EQ(stencil, 0);
  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy_, configs[0]);
  ASSERT_NE(vi, nullptr);
  const Window win = unsynced_window(*vi, 16, 16);
  XFree(vi);
  GLXContext ctx = glXCreateNewContext(dpy_, configs[0], GLX_RGBA_TYPE, nullptr, True);
  contexts_.push_back(ctx);
  XFree(configs);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  GLint bits = -1;
  glGetIntegerv(GL_DEPTH_BITS, &bits);
  EXPECT_EQ(bits, 0);
  glGetIntegerv(GL_STENCIL_BITS, &bits);
  EXPECT_EQ(bits, 0);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glColor3f(1, 1, 0);
  glRectf(-1, -1, 1, 1);
  unsigned char pixel[4] = {};
  glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  EXPECT_EQ(pixel[0], 255);
  EXPECT_EQ(pixel[1], 255);
  EXPECT_EQ(pixel[2], 0);
}

TEST_F(GlxDrawables, AResizedWindowHasItsNewSizeNextFrame) {
  Window win = 0;
  ASSERT_TRUE(red_frame_shown(&win));
  XResizeWindow(dpy_, win, 100, 80);  // no XSync: the swap flushes the program's Display
  unsigned int width = 0, height = 0;
  glXQueryDrawable(dpy_, win, GLX_WIDTH, &width);
  glXQueryDrawable(dpy_, win, GLX_HEIGHT, &height);
  EXPECT_EQ(width, 100u);
  EXPECT_EQ(height, 80u);
  glViewport(0, 0, 100, 80);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  swap_and_wait(win);
  EXPECT_EQ(x_pixel(win, 95, 75), 0x00FF00u);  // outside the old 32x32
  EXPECT_EQ(x_pixel(win, 2, 2), 0x00FF00u);
}

// glpt asks X for the window's size at make-current, glViewport and each swap, not at every
// read or finish (X11WindowTarget::known_size): a program that resizes its window and never
// calls glViewport still draws the next frame at the new size.
TEST_F(GlxDrawables, AResizedWindowHasItsNewSizeNextFrameWithoutGlViewport) {
  Window win = 0;
  ASSERT_TRUE(red_frame_shown(&win));  // its size known
  XResizeWindow(dpy_, win, 100, 80);
  XSync(dpy_, False);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  unsigned char pixel[4] = {};
  glReadPixels(95, 75, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);  // outside the old 32x32
  EXPECT_EQ(pixel[2], 255);
  swap_and_wait(win);
  EXPECT_EQ(x_pixel(win, 95, 75), 0x0000FFu);
  // And a second resize within one frame is seen at its swap.
  XResizeWindow(dpy_, win, 60, 50);
  XSync(dpy_, False);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, win);
  glClear(GL_COLOR_BUFFER_BIT);
  swap_and_wait(win);
  EXPECT_EQ(x_pixel(win, 55, 45), 0x00FF00u);
}

TEST_F(GlxDrawables, GlxPixmapIsSingleBufferedAndGlFlushWritesIt) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_RED_SIZE, 1});
  ASSERT_NE(vi, nullptr);
  const Pixmap pixmap = XCreatePixmap(dpy_, RootWindow(dpy_, 0), 24, 20, vi->depth);
  const GLXPixmap glx_pixmap = glXCreateGLXPixmap(dpy_, vi, pixmap);
  ASSERT_NE(glx_pixmap, 0u);
  GLXContext ctx = context(vi);
  XFree(vi);
  ASSERT_TRUE(glXMakeCurrent(dpy_, glx_pixmap, ctx));
  GLboolean doublebuffer = GL_TRUE;
  glGetBooleanv(GL_DOUBLEBUFFER, &doublebuffer);
  EXPECT_EQ(doublebuffer, GL_FALSE);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy_, glx_pixmap);  // no effect on a pixmap
  glFlush();
  EXPECT_EQ(x_pixel(pixmap, 3, 3), 0x0000FFu);
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyGLXPixmap(dpy_, glx_pixmap);
  XFreePixmap(dpy_, pixmap);
  EXPECT_TRUE(g_errors.empty());
}

TEST_F(GlxDrawables, PbufferIsAHeadlessDrawable) {
  const int attribs[] = {GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_DOUBLEBUFFER, False, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, attribs, &n);
  ASSERT_GT(n, 0);
  const int size[] = {GLX_PBUFFER_WIDTH, 32, GLX_PBUFFER_HEIGHT, 16, None};
  const GLXPbuffer pbuffer = glXCreatePbuffer(dpy_, configs[0], size);
  ASSERT_NE(pbuffer, 0u);
  GLXContext ctx = glXCreateNewContext(dpy_, configs[0], GLX_RGBA_TYPE, nullptr, True);
  contexts_.push_back(ctx);
  unsigned int w = 0, h = 0, id = 0, preserved = 0;
  glXQueryDrawable(dpy_, pbuffer, GLX_WIDTH, &w);
  glXQueryDrawable(dpy_, pbuffer, GLX_HEIGHT, &h);
  glXQueryDrawable(dpy_, pbuffer, GLX_FBCONFIG_ID, &id);
  glXQueryDrawable(dpy_, pbuffer, GLX_PRESERVED_CONTENTS, &preserved);
  EXPECT_EQ(w, 32u);
  EXPECT_EQ(h, 16u);
  int config_id = 0;
  glXGetFBConfigAttrib(dpy_, configs[0], GLX_FBCONFIG_ID, &config_id);
  EXPECT_EQ(id, static_cast<unsigned>(config_id));
  EXPECT_EQ(preserved, 1u);  // the default
  XFree(configs);
  ASSERT_TRUE(glXMakeContextCurrent(dpy_, pbuffer, pbuffer, ctx));
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 32);
  EXPECT_EQ(viewport[3], 16);
  unsigned char left[4] = {}, right[4] = {};
  glpt_test::draw_half_red(4, 28, 8, left, right);
  EXPECT_EQ(left[0], 255);
  EXPECT_EQ(right[2], 255);
  glXMakeContextCurrent(dpy_, None, None, nullptr);
  glXDestroyPbuffer(dpy_, pbuffer);
  EXPECT_TRUE(g_errors.empty());
  glXDestroyPbuffer(dpy_, pbuffer);  // twice: GLXBadPbuffer
  EXPECT_TRUE(saw_error(glx_error(kBadPbuffer)));
}

TEST_F(GlxDrawables, SwapIntervalsAreRememberedPerDrawable) {
  Window win = 0;
  GLXContext ctx = nullptr;
  ASSERT_TRUE(double_buffered_window(8, 8, &win, &ctx));
  EXPECT_EQ(glXSwapIntervalSGI(1), GLX_BAD_CONTEXT);  // no current context
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  unsigned int interval = 0;
  glXQueryDrawable(dpy_, win, GLX_SWAP_INTERVAL_EXT, &interval);
  EXPECT_EQ(interval, 1u);  // the default
  glXSwapIntervalEXT(dpy_, win, 2);
  glXQueryDrawable(dpy_, win, GLX_SWAP_INTERVAL_EXT, &interval);
  EXPECT_EQ(interval, 2u);
  EXPECT_EQ(glXGetSwapIntervalMESA(), 2);
  EXPECT_EQ(glXSwapIntervalMESA(0), 0);
  EXPECT_EQ(glXGetSwapIntervalMESA(), 0);
  EXPECT_EQ(glXSwapIntervalSGI(0), GLX_BAD_VALUE);
  EXPECT_EQ(glXSwapIntervalSGI(3), 0);
  EXPECT_EQ(glXGetSwapIntervalMESA(), 3);
  EXPECT_TRUE(g_errors.empty());
  glXSwapIntervalEXT(dpy_, win, -1);  // no GLX_EXT_swap_control_tear: BadValue
  EXPECT_TRUE(saw_error(BadValue));
}

TEST_F(GlxDrawables, CopyContextCopiesTheMaskedGroupsOnly) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vi, nullptr);
  const Window win = unsynced_window(*vi, 8, 8);
  GLXContext src = context(vi);
  GLXContext dst = context(vi);
  XFree(vi);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, src));
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);  // GL_COLOR_BUFFER_BIT
  glLineWidth(3.0f);                       // GL_LINE_BIT, not copied
  glXCopyContext(dpy_, src, dst, GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, dst));
  GLfloat clear[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  EXPECT_FLOAT_EQ(clear[0], 0.25f);
  EXPECT_FLOAT_EQ(clear[2], 0.75f);
  GLfloat width = 0;
  glGetFloatv(GL_LINE_WIDTH, &width);
  EXPECT_FLOAT_EQ(width, 1.0f);
  GLint depth = -1;
  glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &depth);
  EXPECT_EQ(depth, 0);
  EXPECT_TRUE(g_errors.empty());
  glXCopyContext(dpy_, src, dst, GL_ALL_ATTRIB_BITS);  // dst is current: BadAccess
  EXPECT_TRUE(saw_error(BadAccess));
}

TEST_F(GlxDrawables, TwoContextsTwoWindowsShareLists) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vi, nullptr);
  const Window a = unsynced_window(*vi, 16, 16);
  const Window b = unsynced_window(*vi, 16, 16);
  GLXContext ca = context(vi);
  GLXContext cb = context(vi, ca);
  XFree(vi);
  ASSERT_TRUE(glXMakeCurrent(dpy_, a, ca));
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClear(GL_COLOR_BUFFER_BIT);
  glEndList();
  glClearColor(1, 0, 0, 1);
  glCallList(list);
  ASSERT_TRUE(glXMakeCurrent(dpy_, b, cb));
  glClearColor(0, 1, 0, 1);
  glCallList(list);
  glXSwapBuffers(dpy_, b);
  ASSERT_TRUE(glXMakeCurrent(dpy_, a, ca));
  swap_and_wait(a);
  EXPECT_EQ(x_pixel(a, 4, 4), 0xFF0000u);
  EXPECT_EQ(x_pixel(b, 4, 4), 0x00FF00u);
}

// Contexts writing PNGs into one GLPT_OUTPUT (gl_shim/frame/png_streams.hpp): two contexts
// drawing at once write distinct files, and a context created after one was destroyed numbers on
// after that one's frames instead of writing over them.
TEST_F(GlxDrawables, ContextsWritingPngsIntoOneDirectoryNeverOverwriteEachOther) {
  char dir_template[] = "/tmp/glpt-pngs-XXXXXX";
  ASSERT_NE(mkdtemp(dir_template), nullptr);
  const std::string dir = dir_template;
  setenv("GLPT_OUTPUT", dir.c_str(), 1);
  XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vi, nullptr);
  const Window a = unsynced_window(*vi, 8, 8);
  const Window b = unsynced_window(*vi, 8, 8);
  GLXContext first = glXCreateContext(dpy_, vi, nullptr, True);
  GLXContext second = context(vi);
  const auto frame = [&](Window w, GLXContext c, float r, float g, float bl) {
    ASSERT_TRUE(glXMakeCurrent(dpy_, w, c));
    glClearColor(r, g, bl, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy_, w);
  };
  for (int i = 0; i < 2; ++i) {
    frame(a, first, 1, 0, 0);
    frame(b, second, 0, 1, 0);
  }
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, first);
  GLXContext third = context(vi);
  XFree(vi);
  frame(a, third, 0, 0, 1);
  glXMakeCurrent(dpy_, None, nullptr);
  unsetenv("GLPT_OUTPUT");

  const std::vector<std::pair<std::string, uint32_t>> expected = {
      {"frame_000000.png", 0xFF0000u},
      {"frame_000001.png", 0xFF0000u},
      {"ctx2_frame_000000.png", 0x00FF00u},
      {"ctx2_frame_000001.png", 0x00FF00u},
      {"frame_000002.png", 0x0000FFu}};
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, expected.size());
  for (const auto& [name, colour] : expected) {
    glpt::ImageRGBA8 image;
    std::string error;
    ASSERT_TRUE(glpt::read_png_rgba8(dir + "/" + name, &image, &error)) << name << ": " << error;
    const uint32_t pixel = uint32_t(image.pixels[0]) << 16 | uint32_t(image.pixels[1]) << 8 |
                           uint32_t(image.pixels[2]);
    EXPECT_EQ(pixel, colour) << name;
  }
  std::filesystem::remove_all(dir);
}

// GLX 1.4 3.3.7: make-current flushes the context it replaces, and the buffers are the
// window's: contexts drawing in turn into one window, without any flush, all land in it (as
// piglit's glx-multi-context-single-window).
TEST_F(GlxDrawables, SeveralContextsDrawIntoOneWindow) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vi, nullptr);
  const Window win = unsynced_window(*vi, 24, 8);
  GLXContext contexts[3] = {context(vi), context(vi), context(vi)};
  XFree(vi);
  const GLfloat colors[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(glXMakeCurrent(dpy_, win, contexts[i]));
    glEnable(GL_SCISSOR_TEST);
    glScissor(8 * i, 0, 8, 8);
    glClearColor(colors[i][0], colors[i][1], colors[i][2], 1);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, contexts[0]));
  for (int i = 0; i < 3; ++i) {
    GLubyte rgba[4] = {};
    glReadPixels(8 * i + 4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    EXPECT_EQ(rgba[0], colors[i][0] * 255) << "context " << i;
    EXPECT_EQ(rgba[1], colors[i][1] * 255) << "context " << i;
    EXPECT_EQ(rgba[2], colors[i][2] * 255) << "context " << i;
  }
  swap_and_wait(win);
  EXPECT_EQ(x_pixel(win, 20, 4), 0x0000FFu);
  EXPECT_TRUE(g_errors.empty());
}

// One context moving between two windows of one configuration: each keeps what was drawn into
// it (piglit's glx-make-glxdrawable-current).
TEST_F(GlxDrawables, OneContextMovingBetweenWindowsFindsEachOnesContents) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vi, nullptr);
  const Window one = unsynced_window(*vi, 8, 8);
  const Window two = unsynced_window(*vi, 8, 8);
  GLXContext ctx = context(vi);
  XFree(vi);
  ASSERT_TRUE(glXMakeCurrent(dpy_, one, ctx));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(glXMakeCurrent(dpy_, two, ctx));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const auto green_at_1_1 = [] {
    GLubyte rgba[4] = {};
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    return rgba[0] == 0 && rgba[1] == 255 && rgba[2] == 0;
  };
  ASSERT_TRUE(glXMakeCurrent(dpy_, one, ctx));
  EXPECT_TRUE(green_at_1_1());
  ASSERT_TRUE(glXMakeCurrent(dpy_, two, ctx));
  EXPECT_FALSE(green_at_1_1());  // red
  EXPECT_TRUE(g_errors.empty());
}

TEST_F(GlxDrawables, MakeContextCurrentKeepsSeparateReadDrawable) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vi, nullptr);
  const Window draw = unsynced_window(*vi, 8, 8);
  const Window read = unsynced_window(*vi, 8, 8);
  GLXContext ctx = context(vi);
  XFree(vi);
  ASSERT_TRUE(glXMakeContextCurrent(dpy_, draw, read, ctx));
  EXPECT_EQ(glXGetCurrentDrawable(), draw);
  EXPECT_EQ(glXGetCurrentReadDrawable(), read);
}

TEST_F(GlxDrawables, CreateContextAttribsErrorsAreTheExtensionsOnes) {
  const int any[] = {GLX_DOUBLEBUFFER, True, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, any, &n);
  ASSERT_GT(n, 0);
  GLXFBConfig c = configs[0];
  XFree(configs);
  struct Case {
    std::vector<int> attribs;
    int error;  // an X error code, or a GLX error offset (+1000)
  };
  const Case cases[] = {
      {{GLX_CONTEXT_MAJOR_VERSION_ARB, 2, GLX_CONTEXT_MINOR_VERSION_ARB, 1}, 1000 + kBadFBConfig},
      {{GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 7}, BadMatch},
      {{GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_FLAGS_ARB,
        GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB},
       BadMatch},
      {{GLX_CONTEXT_FLAGS_ARB, 0x100}, BadValue},
      {{GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 2,
        GLX_CONTEXT_PROFILE_MASK_ARB, 0},
       1000 + 13},  // GLXBadProfileARB
      {{0x7777, 1}, BadValue},
      {{GLX_RENDER_TYPE, GLX_COLOR_INDEX_TYPE}, BadValue},  // Mesa's code
  };
  for (const Case& k : cases) {
    std::vector<int> list = k.attribs;
    list.push_back(None);
    g_errors.clear();
    EXPECT_EQ(glXCreateContextAttribsARB(dpy_, c, nullptr, True, list.data()), nullptr);
    const int code = k.error >= 1000 ? glx_error(k.error - 1000) : k.error;
    EXPECT_TRUE(saw_error(code)) << "attribute 0x" << std::hex << k.attribs[0];
  }
  const int gl15[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 5, None};
  GLXContext ok = glXCreateContextAttribsARB(dpy_, c, nullptr, True, gl15);
  ASSERT_NE(ok, nullptr);
  contexts_.push_back(ok);
  g_errors.clear();
  EXPECT_EQ(glXCreateContextAttribsARB(dpy_, nullptr, nullptr, True, gl15), nullptr);
  EXPECT_TRUE(saw_error(glx_error(kBadFBConfig)));
}

// GLX 1.4 3.3.7: a context current on another thread is BadAccess; one destroyed while current
// lives until released (its thread keeps drawing with it).
TEST_F(GlxDrawables, ContextsAreCurrentOnOneThreadAtATime) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vi, nullptr);
  const Window win = unsynced_window(*vi, 8, 8);
  GLXContext ctx = glXCreateContext(dpy_, vi, nullptr, True);
  XFree(vi);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  XSync(dpy_, False);
  bool other_thread_made_it_current = true;
  std::thread other([&] {
    Display* own = XOpenDisplay(nullptr);  // Xlib connections are per thread here
    other_thread_made_it_current = glXMakeCurrent(own, win, ctx);
    XSync(own, False);
    XCloseDisplay(own);
  });
  other.join();
  EXPECT_FALSE(other_thread_made_it_current);
  EXPECT_TRUE(saw_error(BadAccess));
  glXDestroyContext(dpy_, ctx);  // current here: deferred
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  swap_and_wait(win);
  EXPECT_EQ(x_pixel(win, 4, 4), 0x0000FFu);
  EXPECT_EQ(glXGetCurrentContext(), ctx);
  ASSERT_TRUE(glXMakeCurrent(dpy_, None, nullptr));  // released: now it is gone
  g_errors.clear();
  glXDestroyContext(dpy_, ctx);
  EXPECT_TRUE(saw_error(glx_error(kBadContext)));
}

TEST_F(GlxDrawables, BadInputGetsTheErrorGlxNamesNeverACrash) {
  XVisualInfo* vi = visual({GLX_RGBA, GLX_DOUBLEBUFFER});
  ASSERT_NE(vi, nullptr);
  const Window win = unsynced_window(*vi, 8, 8);
  GLXContext ctx = context(vi);
  int not_a_thing = 0;
  auto* bogus_context = reinterpret_cast<GLXContext>(&not_a_thing);
  auto* bogus_config = reinterpret_cast<GLXFBConfig>(&not_a_thing);

  // No display at all: NULL/False, nothing else.
  int attribs[] = {GLX_RGBA, None};
  EXPECT_EQ(glXChooseVisual(nullptr, 0, attribs), nullptr);
  EXPECT_EQ(glXCreateContext(nullptr, vi, nullptr, True), nullptr);
  EXPECT_FALSE(glXMakeCurrent(nullptr, win, ctx));
  int n = 5;
  EXPECT_EQ(glXGetFBConfigs(nullptr, 0, &n), nullptr);
  EXPECT_EQ(n, 0);
  EXPECT_EQ(glXGetFBConfigs(dpy_, 99, &n), nullptr);  // no such screen
  glXSwapBuffers(nullptr, win);
  XFree(vi);

  EXPECT_FALSE(glXMakeCurrent(dpy_, 0x7FFFFF0, ctx));  // no such window
  EXPECT_TRUE(saw_error(glx_error(kBadDrawable)));
  EXPECT_EQ(glXGetCurrentContext(), nullptr);
  g_errors.clear();
  EXPECT_FALSE(glXMakeCurrent(dpy_, win, bogus_context));
  EXPECT_TRUE(saw_error(glx_error(kBadContext)));
  g_errors.clear();
  EXPECT_FALSE(glXMakeContextCurrent(dpy_, None, win, ctx));
  EXPECT_TRUE(saw_error(BadMatch));
  g_errors.clear();
  EXPECT_FALSE(glXMakeCurrent(dpy_, win, nullptr));  // a drawable without a context
  EXPECT_TRUE(saw_error(BadMatch));
  g_errors.clear();
  glXDestroyContext(dpy_, bogus_context);
  EXPECT_TRUE(saw_error(glx_error(kBadContext)));

  int value = 0;
  EXPECT_EQ(glXGetFBConfigAttrib(dpy_, bogus_config, GLX_DEPTH_SIZE, &value), kBadFBConfig);
  g_errors.clear();
  EXPECT_EQ(glXCreateNewContext(dpy_, bogus_config, GLX_RGBA_TYPE, nullptr, True), nullptr);
  EXPECT_TRUE(saw_error(glx_error(kBadFBConfig)));
  g_errors.clear();
  EXPECT_EQ(glXCreateWindow(dpy_, bogus_config, win, nullptr), 0u);
  EXPECT_TRUE(saw_error(glx_error(kBadFBConfig)));
  g_errors.clear();
  glXDestroyWindow(dpy_, 0x7FFFFF1);
  EXPECT_TRUE(saw_error(glx_error(kBadWindow)));
  g_errors.clear();
  glXDestroyGLXPixmap(dpy_, 0x7FFFFF2);
  EXPECT_TRUE(saw_error(glx_error(kBadPixmap)));
  g_errors.clear();
  unsigned int width = 0;
  glXQueryDrawable(dpy_, None, GLX_WIDTH, &width);
  EXPECT_TRUE(saw_error(glx_error(kBadDrawable)));
  g_errors.clear();
  glXQueryDrawable(dpy_, win, 0x7777, &width);
  EXPECT_TRUE(saw_error(BadValue));
  EXPECT_EQ(glXQueryContext(dpy_, bogus_context, GLX_FBCONFIG_ID, &value), GLX_BAD_CONTEXT);

  const int any[] = {GLX_DOUBLEBUFFER, True, None};
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, any, &n);
  ASSERT_GT(n, 0);
  g_errors.clear();
  EXPECT_EQ(glXCreateNewContext(dpy_, configs[0], GLX_COLOR_INDEX_TYPE, nullptr, True), nullptr);
  EXPECT_TRUE(saw_error(BadValue));  // Mesa's code
  g_errors.clear();
  const int huge[] = {GLX_PBUFFER_WIDTH, 1 << 20, GLX_PBUFFER_HEIGHT, 4, None};
  EXPECT_EQ(glXCreatePbuffer(dpy_, configs[0], huge), 0u);
  EXPECT_TRUE(saw_error(BadAlloc));
  XFree(configs);

  // Still working afterwards.
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  EXPECT_EQ(glXGetCurrentContext(), ctx);
}

}  // namespace
