// No C++ exception crosses glpt's C ABI (issue 7 item 5). This test binary replaces the global
// operator new so that the calling thread's N-th allocation throws std::bad_alloc, and sweeps N
// over every allocation a GLX or EGL entry point makes: each failure must come back as the API's
// own (EGL_BAD_ALLOC and the function's failure value; for GLX the failure value and, for a
// request the server would refuse, a BadAlloc X error), the call must work again once memory is
// back, and no exception may reach the test. glpt's libGL.so.1 takes operator new from the C++
// runtime through the dynamic linker, so the test's replacement is its operator new too.
//
// The second half: a context destroyed while current on another thread is deleted when that
// thread releases it (GLX 1.4 3.3.7, EGL 1.5 3.7.2); the replaced operator delete says when the
// context's memory is freed.

// gtest before the X headers: Xlib's macros (None, Bool, Status) break gtest's templates.
// clang-format off
#include <gtest/gtest.h>
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#define EGL_EGLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include "../common/x11_gl_test_util.hpp"
// clang-format on

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>
#include <thread>
#include <vector>

extern "C" void glXSwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval);

namespace {

// -1: allocations succeed. N >= 0: the calling thread's allocation after N more fails.
thread_local long t_allocations_until_failure = -1;
thread_local bool t_allocation_failed = false;
// The address whose freeing the destroy-when-released tests wait for.
std::atomic<void*> g_watched{nullptr};
std::atomic<bool> g_watched_freed{false};

void* allocate(std::size_t size) {
  if (t_allocations_until_failure == 0) {
    t_allocations_until_failure = -1;
    t_allocation_failed = true;
    throw std::bad_alloc();
  }
  if (t_allocations_until_failure > 0) --t_allocations_until_failure;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}

void release(void* p) {
  if (p != nullptr && p == g_watched.load()) g_watched_freed = true;
  std::free(p);
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
// The non-throwing forms too, so that every new/delete pair in the process is malloc/free
// (AddressSanitizer checks that they match).
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }

namespace {

// Runs `call` with its N-th allocation failing, for N = 0, 1, ... until a call makes fewer
// allocations than N (it then ran with all its memory). `check(result)` checks every call: a
// failure must be the function's own (its failure value and error), a success is undone (a
// function may recover by itself, as std::stable_sort does without its buffer). `check` returns
// whether the call failed. Returns how many calls failed: each entry point tested must fail at
// least once, or the test proves nothing.
template <typename Call, typename Check>
int sweep_allocation_failures(Call call, Check check) {
  constexpr long kMaxAllocations = 5000;
  int failed = 0;
  for (long n = 0; n < kMaxAllocations; ++n) {
    t_allocation_failed = false;
    t_allocations_until_failure = n;
    const auto result = call();
    t_allocations_until_failure = -1;
    const bool reached = t_allocation_failed;
    if (check(result)) ++failed;
    if (!reached || ::testing::Test::HasFailure()) return failed;
  }
  ADD_FAILURE() << "more than " << kMaxAllocations << " allocations";
  return failed;
}

std::vector<XErrorEvent> g_x_errors;
int record_x_error(Display*, XErrorEvent* e) {
  g_x_errors.push_back(*e);
  return 0;
}

constexpr int kXGlxCreateContext = 3;  // glxproto.h
constexpr int kXGlxMakeCurrent = 5;
constexpr int kXGlxCreateNewContext = 24;
constexpr int kXGlxCreatePbuffer = 27;
constexpr int kXGlxVendorPrivate = 16;
constexpr int kXGlxCreateWindow = 31;

class CAbi : public ::testing::Test {
 protected:
  void SetUp() override {
    dpy_ = XOpenDisplay(nullptr);
    ASSERT_NE(dpy_, nullptr) << "no X display (run under tests/e2e/with_xvfb.sh)";
    old_handler_ = XSetErrorHandler(record_x_error);
    g_x_errors.clear();
  }
  void TearDown() override {
    XSync(dpy_, False);
    XSetErrorHandler(old_handler_);
    XCloseDisplay(dpy_);
  }
  // The one X error the last failed call sent: BadAlloc for GLX request `minor`.
  void expect_bad_alloc(int minor) {
    ASSERT_EQ(g_x_errors.size(), 1u);
    EXPECT_EQ(g_x_errors[0].error_code, BadAlloc);
    EXPECT_EQ(g_x_errors[0].minor_code, minor);
    g_x_errors.clear();
  }
  GLXFBConfig fbconfig() {
    const int attribs[] = {GLX_DOUBLEBUFFER, True, GLX_DRAWABLE_TYPE,
                           GLX_WINDOW_BIT | GLX_PBUFFER_BIT, None};
    int n = 0;
    GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, attribs, &n);
    EXPECT_NE(configs, nullptr);
    if (configs == nullptr) return nullptr;
    GLXFBConfig c = configs[0];
    XFree(configs);
    return c;
  }
  Window window(GLXFBConfig config) {
    XVisualInfo* vi = glXGetVisualFromFBConfig(dpy_, config);
    EXPECT_NE(vi, nullptr);
    const Window w = glpt_test::create_mapped_window(dpy_, *vi, 16, 16);
    XFree(vi);
    return w;
  }
  Display* dpy_ = nullptr;
  XErrorHandler old_handler_ = nullptr;
};

TEST_F(CAbi, GlxAllocationFailureIsTheFunctionsFailureAndBadAlloc) {
  const int attribs[] = {GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 1, None};
  int n = 0;
  // Client-side in Mesa: NULL, no X error.
  const auto chose = [&](GLXFBConfig* configs) {
    EXPECT_TRUE(g_x_errors.empty());
    XFree(configs);
    return configs == nullptr;
  };
  EXPECT_GT(
      sweep_allocation_failures([&] { return glXChooseFBConfig(dpy_, 0, attribs, &n); }, chose), 0);
  const GLXFBConfig config = fbconfig();
  ASSERT_NE(config, nullptr);
  // Requests the server would refuse: the failure value and BadAlloc.
  const auto created_context = [&](int minor) {
    return [this, minor](GLXContext ctx) {
      if (ctx == nullptr) {
        expect_bad_alloc(minor);
        return true;
      }
      glXDestroyContext(dpy_, ctx);
      return false;
    };
  };
  EXPECT_GT(sweep_allocation_failures(
                [&] { return glXCreateNewContext(dpy_, config, GLX_RGBA_TYPE, nullptr, True); },
                created_context(kXGlxCreateNewContext)),
            0);
  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy_, config);
  ASSERT_NE(vi, nullptr);
  EXPECT_GT(sweep_allocation_failures([&] { return glXCreateContext(dpy_, vi, nullptr, True); },
                                      created_context(kXGlxCreateContext)),
            0);
  XFree(vi);
  const int pbuffer_attribs[] = {GLX_PBUFFER_WIDTH, 8, GLX_PBUFFER_HEIGHT, 8, None};
  EXPECT_GT(
      sweep_allocation_failures([&] { return glXCreatePbuffer(dpy_, config, pbuffer_attribs); },
                                [&](GLXPbuffer pbuffer) {
                                  if (pbuffer == None) {
                                    expect_bad_alloc(kXGlxCreatePbuffer);
                                    return true;
                                  }
                                  glXDestroyPbuffer(dpy_, pbuffer);
                                  return false;
                                }),
      0);

  // Make-current on a window glpt has not drawn to yet (its connection to the window is made):
  // False and BadAlloc, nothing current, and the context is free for the next attempt (also on
  // another thread).
  GLXContext ctx = glXCreateNewContext(dpy_, config, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  const Window win = window(config);
  EXPECT_GT(sweep_allocation_failures([&] { return glXMakeCurrent(dpy_, win, ctx); },
                                      [&](Bool made) {
                                        if (made) return false;
                                        expect_bad_alloc(kXGlxMakeCurrent);
                                        EXPECT_EQ(glXGetCurrentContext(), nullptr);
                                        return true;
                                      }),
            0);
  EXPECT_EQ(glXGetCurrentContext(), ctx);
  glXMakeCurrent(dpy_, None, nullptr);
  bool other_thread_made_it_current = false;
  std::thread([&] {
    Display* own = XOpenDisplay(nullptr);
    other_thread_made_it_current = glXMakeCurrent(own, win, ctx);
    glXMakeCurrent(own, None, nullptr);
    XCloseDisplay(own);
  }).join();
  EXPECT_TRUE(other_thread_made_it_current);

  // glXUseXFont makes display lists with GL commands: an allocation failure there is
  // GL_OUT_OF_MEMORY, as in those commands.
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  XFontStruct* font = XLoadQueryFont(dpy_, "fixed");
  ASSERT_NE(font, nullptr);
  const GLuint base = glGenLists(96);
  EXPECT_GT(sweep_allocation_failures(
                [&] {
                  glXUseXFont(font->fid, 32, 96, static_cast<int>(base));
                  return glGetError();
                },
                [&](GLenum error) {
                  if (error == GL_OUT_OF_MEMORY) {
                    GLint open_list = -1, alignment = 0;
                    glGetIntegerv(GL_LIST_INDEX, &open_list);
                    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
                    EXPECT_EQ(open_list, 0);  // closed again
                    EXPECT_EQ(alignment, 4);  // the program's, restored
                    return true;
                  }
                  EXPECT_EQ(error, static_cast<GLenum>(GL_NO_ERROR));
                  EXPECT_TRUE(glIsList(base + 33));  // 'A'
                  return false;
                }),
            0);
  XFreeFont(dpy_, font);

  // A GLX window over the X window, and its swap interval (GLX_EXT_swap_control's request).
  EXPECT_GT(sweep_allocation_failures([&] { return glXCreateWindow(dpy_, config, win, nullptr); },
                                      [&](GLXWindow glx_window) {
                                        if (glx_window == None) {
                                          expect_bad_alloc(kXGlxCreateWindow);
                                          return true;
                                        }
                                        glXDestroyWindow(dpy_, glx_window);
                                        return false;
                                      }),
            0);
  EXPECT_GT(sweep_allocation_failures(
                [&] {
                  glXSwapIntervalEXT(dpy_, win, 2);
                  return !g_x_errors.empty();
                },
                [&](bool failed) {
                  if (failed) expect_bad_alloc(kXGlxVendorPrivate);
                  return failed;
                }),
            0);
  unsigned interval = 0;
  glXQueryDrawable(dpy_, win, GLX_SWAP_INTERVAL_EXT, &interval);
  EXPECT_EQ(interval, 2u);

  // A swap renders the frame (the renderer exists after the first one). The renderer catches
  // its own failures (the frame is lost, said once on stderr) or the swap records
  // GL_OUT_OF_MEMORY; either way nothing escapes, no X error ends the program, and the next frame
  // is drawn as if nothing had happened. Counted: the swaps that met a failure.
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  unsigned char left[4], right[4];
  glpt_test::draw_half_red(4, 12, 8, left, right);
  glXSwapBuffers(dpy_, win);
  EXPECT_GT(sweep_allocation_failures(
                [&] {
                  const long n = t_allocations_until_failure;  // failing in the swap only
                  t_allocations_until_failure = -1;
                  glClearColor(0, 0, 1, 1);
                  glClear(GL_COLOR_BUFFER_BIT);
                  glRectf(-1, -1, 0, 1);
                  t_allocations_until_failure = n;
                  glXSwapBuffers(dpy_, win);
                  return glGetError();
                },
                [&](GLenum error) {
                  EXPECT_TRUE(error == GL_NO_ERROR || error == GL_OUT_OF_MEMORY) << error;
                  return t_allocation_failed;
                }),
            0);
  glpt_test::draw_half_red(4, 12, 8, left, right);
  EXPECT_EQ(left[0], 255);
  EXPECT_EQ(right[2], 255);
  EXPECT_TRUE(g_x_errors.empty());
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, ctx);
  XDestroyWindow(dpy_, win);
}

class CAbiEgl : public CAbi {
 protected:
  void SetUp() override {
    CAbi::SetUp();
    egl_ = eglGetDisplay(reinterpret_cast<EGLNativeDisplayType>(dpy_));
    ASSERT_NE(egl_, EGL_NO_DISPLAY);
    ASSERT_TRUE(eglInitialize(egl_, nullptr, nullptr));
    ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
    const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                              EGL_OPENGL_BIT, EGL_NONE};
    EGLint n = 0;
    ASSERT_TRUE(eglChooseConfig(egl_, attribs, &config_, 1, &n));
    ASSERT_EQ(n, 1);
  }
  void TearDown() override {
    eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(egl_);
    CAbi::TearDown();
  }
  EGLDisplay egl_ = EGL_NO_DISPLAY;
  EGLConfig config_ = nullptr;
};

TEST_F(CAbiEgl, AllocationFailureIsEglBadAllocAndTheFailureValue) {
  // A failure is EGL_BAD_ALLOC and `failure`; a success is undone by `undo`.
  const auto bad_alloc = [](auto failure, auto undo) {
    return [failure, undo](auto result) {
      if (result != failure) {
        undo(result);
        return false;
      }
      EXPECT_EQ(eglGetError(), EGL_BAD_ALLOC);
      return true;
    };
  };
  const auto nothing = [](auto) {};
  const EGLint screen0[] = {EGL_PLATFORM_X11_SCREEN_KHR, 0, EGL_NONE};
  EXPECT_GT(sweep_allocation_failures(
                [&] { return eglGetPlatformDisplayEXT(EGL_PLATFORM_X11_KHR, dpy_, screen0); },
                bad_alloc(EGL_NO_DISPLAY, [&](EGLDisplay d) { EXPECT_EQ(d, egl_); })),
            0);
  // Initializing reads the screen's configs.
  ASSERT_TRUE(eglTerminate(egl_));
  EXPECT_GT(sweep_allocation_failures([&] { return eglInitialize(egl_, nullptr, nullptr); },
                                      bad_alloc(EGLBoolean{EGL_FALSE}, nothing)),
            0);
  const EGLint depth[] = {EGL_DEPTH_SIZE, 1, EGL_NONE};
  EGLConfig configs[4];
  EGLint n = 0;
  EXPECT_GT(sweep_allocation_failures([&] { return eglChooseConfig(egl_, depth, configs, 4, &n); },
                                      bad_alloc(EGLBoolean{EGL_FALSE}, nothing)),
            0);
  EXPECT_GT(sweep_allocation_failures(
                [&] { return eglCreateContext(egl_, config_, EGL_NO_CONTEXT, nullptr); },
                bad_alloc(EGL_NO_CONTEXT,
                          [&](EGLContext ctx) { EXPECT_TRUE(eglDestroyContext(egl_, ctx)); })),
            0);
  const EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
  EGLSurface pbuffer = EGL_NO_SURFACE;
  EXPECT_GT(
      sweep_allocation_failures([&] { return eglCreatePbufferSurface(egl_, config_, size); },
                                bad_alloc(EGL_NO_SURFACE, [&](EGLSurface s) { pbuffer = s; })),
      0);
  // A window surface (glpt's own connection to the window is made).
  const EGLint window_attribs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig window_config = nullptr;
  ASSERT_TRUE(eglChooseConfig(egl_, window_attribs, &window_config, 1, &n));
  EGLint visual_id = 0;
  ASSERT_TRUE(eglGetConfigAttrib(egl_, window_config, EGL_NATIVE_VISUAL_ID, &visual_id));
  XVisualInfo templ{};
  templ.visualid = static_cast<VisualID>(visual_id);
  int visuals = 0;
  XVisualInfo* vi = XGetVisualInfo(dpy_, VisualIDMask, &templ, &visuals);
  ASSERT_NE(vi, nullptr);
  const Window win = glpt_test::create_mapped_window(dpy_, *vi, 16, 16);
  XFree(vi);
  EXPECT_GT(sweep_allocation_failures(
                [&] { return eglCreateWindowSurface(egl_, window_config, win, nullptr); },
                bad_alloc(EGL_NO_SURFACE,
                          [&](EGLSurface s) { EXPECT_TRUE(eglDestroySurface(egl_, s)); })),
            0);
  XDestroyWindow(dpy_, win);
  // The objects made once memory was back work.
  EGLContext ctx = eglCreateContext(egl_, config_, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(egl_, pbuffer, pbuffer, ctx));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglDestroySurface(egl_, pbuffer));
  EXPECT_TRUE(eglDestroyContext(egl_, ctx));
}

// GLX 1.4 3.3.7: glXDestroyContext of a context current on another thread deletes it once that
// thread releases it; until then that thread keeps drawing with it.
TEST_F(CAbi, ARenderThatFailsAtTheSwapIsGlOutOfMemoryAndTheNextFrameRenders) {
  // Raster mode, 16x16: a frame whose N-th allocation during glXSwapBuffers fails, for every N
  // the swap reaches. A render that fails is reported as GL_OUT_OF_MEMORY (GL 1.5 2.5), never
  // lost silently or thrown; the next frame renders normally.
  ::setenv("GLPT_MODE", "raster", 1);
  const GLXFBConfig config = fbconfig();
  ASSERT_NE(config, nullptr);
  const Window win = window(config);
  GLXContext ctx = glXCreateNewContext(dpy_, config, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  // Frame k: a square on blue, red for even k and green for odd k, so a frame that was not
  // shown cannot pass for one that was.
  int frame = 0;
  const auto draw = [&frame] {
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(frame % 2 == 0 ? 1.0f : 0.0f, frame % 2 == 0 ? 0.0f : 1.0f, 0.0f);
    glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  };
  draw();
  glXSwapBuffers(dpy_, win);  // the renderer exists before the sweep
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  int out_of_memory = 0, absorbed = 0;
  // The sweep arms the failure before `call`: the frame is drawn first, outside it.
  draw();
  const int failed = sweep_allocation_failures(
      [&] {
        glXSwapBuffers(dpy_, win);
        t_allocations_until_failure = -1;  // the next frame is drawn with all its memory
        ++frame;
        draw();
        return 0;
      },
      [&](int) {
        t_allocations_until_failure = -1;
        const GLenum error = glGetError();
        XSync(dpy_, False);
        if (!t_allocation_failed) {
          EXPECT_EQ(error, static_cast<GLenum>(GL_NO_ERROR));
          return false;
        }
        // A failure the swap could not absorb is GL_OUT_OF_MEMORY (or an X BadAlloc where
        // glXSwapBuffers' own bookkeeping could not allocate); one it absorbed (a cache, a
        // statistic) left no error only if the frame was shown: the red square is in front.
        if (error == GL_NO_ERROR && g_x_errors.empty()) {
          uint8_t shown[4] = {};
          glReadBuffer(GL_FRONT);
          glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, shown);
          glReadBuffer(GL_BACK);
          // The swapped frame is the one before `frame`.
          EXPECT_EQ(shown[0], frame % 2 == 1 ? 255 : 0) << "a failed swap that reported nothing";
          EXPECT_EQ(shown[1], frame % 2 == 1 ? 0 : 255) << "a failed swap that reported nothing";
          ++absorbed;
        }
        out_of_memory += error == GL_OUT_OF_MEMORY ? 1 : 0;
        g_x_errors.clear();
        return true;
      });
  EXPECT_GT(failed, 0);
  EXPECT_GT(out_of_memory, 0);
  // Memory is back: the frame renders, the red square on blue.
  frame = 0;
  draw();
  glXSwapBuffers(dpy_, win);
  draw();
  glFinish();
  uint8_t centre[4] = {}, corner[4] = {};
  glReadBuffer(GL_BACK);
  glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, centre);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, corner);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(centre[0], 255);
  EXPECT_EQ(centre[2], 0);
  EXPECT_EQ(corner[2], 255);
  std::printf(
      "swaps with a failed allocation: %d, reported as GL_OUT_OF_MEMORY: %d, absorbed: %d\n",
      failed, out_of_memory, absorbed);
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, ctx);
  XDestroyWindow(dpy_, win);
  ::unsetenv("GLPT_MODE");
}

TEST_F(CAbi, GlxContextDestroyedWhileCurrentElsewhereIsDeletedWhenReleased) {
  const GLXFBConfig config = fbconfig();
  ASSERT_NE(config, nullptr);
  const Window win = window(config);
  GLXContext ctx = glXCreateNewContext(dpy_, config, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  g_watched_freed = false;
  g_watched = ctx;
  std::atomic<int> step{0};
  GLenum error_after_destroy = 1;
  GLfloat clear_after_destroy[4] = {};
  std::thread drawer([&] {
    Display* own = XOpenDisplay(nullptr);
    const bool made = glXMakeCurrent(own, win, ctx);
    step = 1;
    EXPECT_TRUE(made);
    while (step != 2) std::this_thread::yield();  // the main thread destroys it
    glClearColor(0.25f, 0.5f, 0.75f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear_after_destroy);
    error_after_destroy = glGetError();
    EXPECT_TRUE(glXMakeCurrent(own, None, nullptr));
    XCloseDisplay(own);
  });
  while (step != 1) std::this_thread::yield();
  glXDestroyContext(dpy_, ctx);
  XSync(dpy_, False);
  EXPECT_TRUE(g_x_errors.empty());
  EXPECT_FALSE(g_watched_freed);  // still current on the other thread
  step = 2;
  drawer.join();
  EXPECT_EQ(error_after_destroy, static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(clear_after_destroy[2], 0.75f);
  EXPECT_TRUE(g_watched_freed);  // released: deleted
  g_watched = nullptr;
  glXDestroyContext(dpy_, ctx);  // the handle is gone: GLXBadContext
  XSync(dpy_, False);
  EXPECT_EQ(g_x_errors.size(), 1u);
  XDestroyWindow(dpy_, win);
}

// EGL 1.5 3.7.2: likewise for eglDestroyContext; the handle is invalid at once.
TEST_F(CAbiEgl, ContextDestroyedWhileCurrentElsewhereIsDeletedWhenReleased) {
  const EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
  EGLSurface pbuffer = eglCreatePbufferSurface(egl_, config_, size);
  ASSERT_NE(pbuffer, EGL_NO_SURFACE);
  EGLContext ctx = eglCreateContext(egl_, config_, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  g_watched_freed = false;
  g_watched = ctx;
  std::atomic<int> step{0};
  GLenum error_after_destroy = 1;
  EGLContext current_after_destroy = EGL_NO_CONTEXT;
  std::thread drawer([&] {
    eglBindAPI(EGL_OPENGL_API);
    const bool made = eglMakeCurrent(egl_, pbuffer, pbuffer, ctx);
    step = 1;
    EXPECT_TRUE(made);
    while (step != 2) std::this_thread::yield();
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    error_after_destroy = glGetError();
    current_after_destroy = eglGetCurrentContext();
    EXPECT_TRUE(eglReleaseThread());
  });
  while (step != 1) std::this_thread::yield();
  EXPECT_TRUE(eglDestroyContext(egl_, ctx));
  EXPECT_FALSE(g_watched_freed);
  EXPECT_FALSE(eglDestroyContext(egl_, ctx));  // the handle is already invalid
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  step = 2;
  drawer.join();
  EXPECT_EQ(error_after_destroy, static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(current_after_destroy, ctx);
  EXPECT_TRUE(g_watched_freed);
  g_watched = nullptr;
  EXPECT_TRUE(eglDestroySurface(egl_, pbuffer));
}

}  // namespace
