// EGL 1.5 against glpt's libGL.so.1 on a real X server (Xvfb): displays, configs (EGL 1.5
// 3.4.1 matching and sorting), errors, contexts, window and pbuffer surfaces, make-current, and
// that a frame reaches glReadPixels through each kind of surface. Expected values come from the
// EGL 1.5 specification (sections named at each test) and from glpt's config model: RGB8 with and
// without 8 alpha bits, 24-bit depth, 8-bit stencil, OpenGL only.

// gtest before the X headers: Xlib's macros (None, Bool, Status) break gtest's templates.
// clang-format off
#include <gtest/gtest.h>
#include <GL/gl.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#define EGL_EGLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include "../common/x11_gl_test_util.hpp"
// clang-format on

#include <dlfcn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <thread>
#include <vector>

namespace {

constexpr EGLint kWindowConfig[] = {EGL_SURFACE_TYPE,
                                    EGL_WINDOW_BIT | EGL_PBUFFER_BIT,
                                    EGL_RENDERABLE_TYPE,
                                    EGL_OPENGL_BIT,
                                    EGL_RED_SIZE,
                                    8,
                                    EGL_DEPTH_SIZE,
                                    1,
                                    EGL_NONE};

class Egl : public ::testing::Test {
 protected:
  void SetUp() override {
    dpy_ = XOpenDisplay(nullptr);
    ASSERT_NE(dpy_, nullptr) << "no X display (run under tests/e2e/with_xvfb.sh)";
    egl_ = eglGetDisplay(reinterpret_cast<EGLNativeDisplayType>(dpy_));
    ASSERT_NE(egl_, EGL_NO_DISPLAY);
    ASSERT_TRUE(eglInitialize(egl_, nullptr, nullptr));
    ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  }
  void TearDown() override {
    eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(egl_);
    if (window_) XDestroyWindow(dpy_, window_);
    XCloseDisplay(dpy_);
  }
  EGLConfig choose(const EGLint* attribs) {
    EGLConfig config = nullptr;
    EGLint n = 0;
    EXPECT_TRUE(eglChooseConfig(egl_, attribs, &config, 1, &n));
    EXPECT_EQ(n, 1);
    return config;
  }
  EGLint attrib(EGLConfig config, EGLint name) {
    EGLint value = -12345;
    EXPECT_TRUE(eglGetConfigAttrib(egl_, config, name, &value)) << std::hex << name;
    return value;
  }
  // A mapped window of the config's visual.
  Window make_window(EGLConfig config, int w, int h) {
    XVisualInfo templ{};
    templ.visualid = static_cast<VisualID>(attrib(config, EGL_NATIVE_VISUAL_ID));
    int n = 0;
    XVisualInfo* vi = XGetVisualInfo(dpy_, VisualIDMask, &templ, &n);
    EXPECT_NE(vi, nullptr);
    if (vi == nullptr) return 0;
    window_ = glpt_test::create_mapped_window(dpy_, *vi, w, h);
    XFree(vi);
    return window_;
  }
  Display* dpy_ = nullptr;
  EGLDisplay egl_ = EGL_NO_DISPLAY;
  Window window_ = 0;
};

using glpt_test::draw_half_red;

// EGL 1.5 3.2, 3.3: displays, initialization, strings.
TEST_F(Egl, DisplaysInitializeAndDescribeThemselves) {
  EGLint major = 0, minor = 0;
  EXPECT_TRUE(eglInitialize(egl_, &major, &minor));
  EXPECT_EQ(major, 1);
  EXPECT_EQ(minor, 5);
  // The same native display is the same EGLDisplay, by either entry point.
  EXPECT_EQ(eglGetDisplay(reinterpret_cast<EGLNativeDisplayType>(dpy_)), egl_);
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, dpy_, nullptr), egl_);
  const EGLAttrib screen0[] = {EGL_PLATFORM_X11_SCREEN_KHR, 0, EGL_NONE};
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, dpy_, screen0), egl_);
  EXPECT_STREQ(eglQueryString(egl_, EGL_CLIENT_APIS), "OpenGL");
  EXPECT_EQ(std::strncmp(eglQueryString(egl_, EGL_VERSION), "1.5", 3), 0);
  EXPECT_NE(std::strstr(eglQueryString(egl_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"),
            nullptr);
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  ASSERT_NE(client, nullptr);
  EXPECT_NE(std::strstr(client, "EGL_KHR_platform_x11"), nullptr);
  EXPECT_NE(std::strstr(client, "EGL_MESA_platform_surfaceless"), nullptr);
  EXPECT_EQ(eglQueryString(EGL_NO_DISPLAY, EGL_VENDOR), nullptr);
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_EQ(eglQueryString(egl_, 0x1234), nullptr);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);

  // Unknown platforms and attributes; a display handle that is none of glpt's.
  EXPECT_EQ(eglGetPlatformDisplay(0x1234, dpy_, nullptr), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  const EGLAttrib bogus[] = {0x1234, 0, EGL_NONE};
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, dpy_, bogus), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EGLDisplay not_a_display = reinterpret_cast<EGLDisplay>(&major);
  EXPECT_FALSE(eglInitialize(not_a_display, nullptr, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_FALSE(eglTerminate(EGL_NO_DISPLAY));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);  // eglGetError resets the error

  // After eglTerminate calls need initialization again (EGL 1.5 3.2).
  EXPECT_TRUE(eglTerminate(egl_));
  EGLint n = 0;
  EXPECT_FALSE(eglGetConfigs(egl_, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_TRUE(eglInitialize(egl_, nullptr, nullptr));
}

// EGL 1.5 3.4: every config is RGB8 (with or without alpha), depth 24, stencil 8, OpenGL,
// windows and pbuffers, with a native visual.
TEST_F(Egl, ConfigsDescribeGlptsBuffers) {
  EGLint n = 0;
  ASSERT_TRUE(eglGetConfigs(egl_, nullptr, 0, &n));
  ASSERT_GT(n, 0);
  std::vector<EGLConfig> configs(n);
  EGLint got = 0;
  ASSERT_TRUE(eglGetConfigs(egl_, configs.data(), n, &got));
  EXPECT_EQ(got, n);
  bool with_alpha = false, without_alpha = false;
  for (EGLConfig c : configs) {
    EXPECT_EQ(attrib(c, EGL_RED_SIZE), 8);
    EXPECT_EQ(attrib(c, EGL_DEPTH_SIZE), 24);
    EXPECT_EQ(attrib(c, EGL_STENCIL_SIZE), 8);
    EXPECT_EQ(attrib(c, EGL_RENDERABLE_TYPE), EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT);
    EXPECT_EQ(attrib(c, EGL_CONFORMANT), EGL_OPENGL_BIT);
    EXPECT_EQ(attrib(c, EGL_SURFACE_TYPE), EGL_WINDOW_BIT | EGL_PBUFFER_BIT);
    EXPECT_EQ(attrib(c, EGL_COLOR_BUFFER_TYPE), EGL_RGB_BUFFER);
    EXPECT_EQ(attrib(c, EGL_NATIVE_VISUAL_TYPE), TrueColor);
    EXPECT_NE(attrib(c, EGL_NATIVE_VISUAL_ID), 0);
    EXPECT_GT(attrib(c, EGL_CONFIG_ID), 0);
    const EGLint alpha = attrib(c, EGL_ALPHA_SIZE);
    EXPECT_EQ(attrib(c, EGL_BUFFER_SIZE), 24 + alpha);
    (alpha == 8 ? with_alpha : without_alpha) = true;
  }
  EXPECT_TRUE(with_alpha);
  EXPECT_TRUE(without_alpha);
  // Fewer slots than configs: only as many are written.
  EGLConfig one[2] = {nullptr, nullptr};
  ASSERT_TRUE(eglGetConfigs(egl_, one, 1, &got));
  EXPECT_EQ(got, 1);
  EXPECT_EQ(one[1], nullptr);

  EGLint value = 0;
  EXPECT_FALSE(eglGetConfigAttrib(egl_, configs[0], 0x1234, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglGetConfigAttrib(egl_, reinterpret_cast<EGLConfig>(uintptr_t{1} << 40),
                                  EGL_RED_SIZE, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  EXPECT_FALSE(eglGetConfigs(egl_, nullptr, 0, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

// EGL 1.5 3.4.1.2: matching (AtLeast, Exact, Mask, EGL_CONFIG_ID alone) and sorting (more colour
// bits among the components asked for, then the smaller buffer, then the config id).
TEST_F(Egl, ChooseConfigMatchesAndSortsAsTheSpecifies) {
  // Alpha not asked for: no-alpha configs (smaller EGL_BUFFER_SIZE) come first.
  const EGLint rgb[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_RED_SIZE, 1, EGL_NONE};
  EGLint n = 0;
  ASSERT_TRUE(eglChooseConfig(egl_, rgb, nullptr, 0, &n));
  ASSERT_GT(n, 1);
  std::vector<EGLConfig> sorted(n);
  ASSERT_TRUE(eglChooseConfig(egl_, rgb, sorted.data(), n, &n));
  EXPECT_EQ(attrib(sorted.front(), EGL_ALPHA_SIZE), 0);
  EXPECT_EQ(attrib(sorted.back(), EGL_ALPHA_SIZE), 8);
  for (size_t i = 1; i < sorted.size(); ++i) {
    const EGLint a = attrib(sorted[i - 1], EGL_BUFFER_SIZE), b = attrib(sorted[i], EGL_BUFFER_SIZE);
    EXPECT_LE(a, b);
    if (a == b) {
      EXPECT_LT(attrib(sorted[i - 1], EGL_CONFIG_ID), attrib(sorted[i], EGL_CONFIG_ID));
    }
  }
  // Alpha asked for: only alpha configs (AtLeast).
  const EGLint rgba[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_ALPHA_SIZE, 1, EGL_NONE};
  EGLConfig c = choose(rgba);
  EXPECT_EQ(attrib(c, EGL_ALPHA_SIZE), 8);
  // Alpha of size 0 asked for counts no alpha bits: sorting puts no-alpha first again.
  const EGLint alpha0[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_ALPHA_SIZE, 0, EGL_NONE};
  EXPECT_EQ(attrib(choose(alpha0), EGL_ALPHA_SIZE), 0);
  // The default EGL_RENDERABLE_TYPE is EGL_OPENGL_ES_BIT, which glpt's configs name (though
  // only OpenGL contexts can be made), as Mesa's do: the same configs match without it.
  const EGLint es_default[] = {EGL_RED_SIZE, 1, EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(egl_, es_default, nullptr, 0, &n));
  EXPECT_EQ(n, static_cast<EGLint>(sorted.size()));
  const EGLint es2[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(egl_, es2, nullptr, 0, &n));
  EXPECT_EQ(n, 0);
  // xscreensaver 6.06's request (Debian's GL hacks): EGL_OPENGL_ES_BIT, stencil, alpha.
  const EGLint xscreensaver[] = {EGL_SURFACE_TYPE,
                                 EGL_WINDOW_BIT,
                                 EGL_COLOR_BUFFER_TYPE,
                                 EGL_RGB_BUFFER,
                                 EGL_RED_SIZE,
                                 8,
                                 EGL_GREEN_SIZE,
                                 8,
                                 EGL_BLUE_SIZE,
                                 8,
                                 EGL_ALPHA_SIZE,
                                 8,
                                 EGL_DEPTH_SIZE,
                                 8,
                                 EGL_STENCIL_SIZE,
                                 1,
                                 EGL_RENDERABLE_TYPE,
                                 EGL_OPENGL_ES_BIT,
                                 EGL_NONE};
  EXPECT_EQ(attrib(choose(xscreensaver), EGL_ALPHA_SIZE), 8);
  const EGLint too_deep[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_DEPTH_SIZE, 32, EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(egl_, too_deep, nullptr, 0, &n));
  EXPECT_EQ(n, 0);
  const EGLint pixmaps[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PIXMAP_BIT,
                            EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(egl_, pixmaps, nullptr, 0, &n));
  EXPECT_EQ(n, 0);
  // EGL_CONFIG_ID alone decides: the other attributes (even an impossible depth) are ignored.
  const EGLint id = attrib(sorted.back(), EGL_CONFIG_ID);
  const EGLint by_id[] = {EGL_DEPTH_SIZE, 64, EGL_CONFIG_ID, id, EGL_NONE};
  EXPECT_EQ(attrib(choose(by_id), EGL_CONFIG_ID), id);
  // EGL_NATIVE_VISUAL_ID and EGL_MAX_PBUFFER_* are ignored by matching.
  const EGLint ignored[] = {EGL_RENDERABLE_TYPE,
                            EGL_OPENGL_BIT,
                            EGL_NATIVE_VISUAL_ID,
                            0x7fff,
                            EGL_MAX_PBUFFER_WIDTH,
                            1 << 30,
                            EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(egl_, ignored, nullptr, 0, &n));
  EXPECT_EQ(n, static_cast<EGLint>(sorted.size()));

  // Unknown attributes and invalid values: EGL_BAD_ATTRIBUTE.
  const EGLint unknown[] = {0x1234, 1, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(egl_, unknown, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint negative[] = {EGL_RED_SIZE, -3, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(egl_, negative, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint bad_enum[] = {EGL_COLOR_BUFFER_TYPE, 0x1234, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(egl_, bad_enum, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglChooseConfig(egl_, rgb, nullptr, 0, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_FALSE(eglChooseConfig(EGL_NO_DISPLAY, rgb, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
}

// EGL 1.5 3.7: OpenGL is the only API; contexts of OpenGL 1.0 to 1.5, shared or not.
TEST_F(Egl, ContextsNeedOpenGlUpToVersion15) {
  EXPECT_EQ(eglQueryAPI(), EGL_OPENGL_API);
  EXPECT_FALSE(eglBindAPI(EGL_OPENGL_ES_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_FALSE(eglBindAPI(EGL_OPENVG_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglQueryAPI(), EGL_OPENGL_API);
  // Each thread starts with EGL_NONE (OpenGL ES unsupported), so a context needs eglBindAPI.
  EGLConfig config = choose(kWindowConfig);
  std::thread([&] {
    EXPECT_EQ(eglQueryAPI(), static_cast<EGLenum>(EGL_NONE));
    EXPECT_EQ(eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr), EGL_NO_CONTEXT);
    EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  }).join();

  const EGLint gl13[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 3, EGL_NONE};
  EGLContext a = eglCreateContext(egl_, config, EGL_NO_CONTEXT, gl13);
  ASSERT_NE(a, EGL_NO_CONTEXT);
  EGLint value = 0;
  EXPECT_TRUE(eglQueryContext(egl_, a, EGL_CONTEXT_CLIENT_TYPE, &value));
  EXPECT_EQ(value, EGL_OPENGL_API);
  EXPECT_TRUE(eglQueryContext(egl_, a, EGL_CONFIG_ID, &value));
  EXPECT_EQ(value, attrib(config, EGL_CONFIG_ID));
  EXPECT_TRUE(eglQueryContext(egl_, a, EGL_RENDER_BUFFER, &value));
  EXPECT_EQ(value, EGL_NONE);  // not bound to a surface
  EXPECT_FALSE(eglQueryContext(egl_, a, 0x1234, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);

  const EGLint gl15[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 5, EGL_NONE};
  EGLContext b = eglCreateContext(egl_, config, a, gl15);  // shares a's objects
  ASSERT_NE(b, EGL_NO_CONTEXT);
  const EGLint gl16[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 6, EGL_NONE};
  const EGLint gl3[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
  for (const EGLint* too_new : {gl16, gl3}) {
    EXPECT_EQ(eglCreateContext(egl_, config, EGL_NO_CONTEXT, too_new), EGL_NO_CONTEXT);
    EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  }
  const EGLint unknown[] = {0x1234, 0, EGL_NONE};
  EXPECT_EQ(eglCreateContext(egl_, config, EGL_NO_CONTEXT, unknown), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint forward[] = {EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE, EGL_TRUE, EGL_NONE};
  EXPECT_EQ(eglCreateContext(egl_, config, EGL_NO_CONTEXT, forward), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_EQ(eglCreateContext(egl_, nullptr, EGL_NO_CONTEXT, nullptr), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  EXPECT_EQ(eglCreateContext(egl_, config, reinterpret_cast<EGLContext>(&value), nullptr),
            EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);

  // Sharing: a display list made in `a` exists in `b` (surfaceless make-current).
  ASSERT_TRUE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, a));
  EXPECT_EQ(eglGetCurrentContext(), a);
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetCurrentDisplay(), egl_);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEndList();
  ASSERT_TRUE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, b));
  EXPECT_TRUE(glIsList(list));
  // A context current here cannot be made current on another thread (EGL_BAD_ACCESS).
  std::thread([&] {
    eglBindAPI(EGL_OPENGL_API);
    EXPECT_FALSE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, b));
    EXPECT_EQ(eglGetError(), EGL_BAD_ACCESS);
    EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);  // current contexts are per thread
  }).join();
  // Destroying the current context defers its deletion until it is released; the handle is
  // invalid at once.
  EXPECT_TRUE(eglDestroyContext(egl_, b));
  EXPECT_EQ(eglGetCurrentContext(), b);
  EXPECT_TRUE(glIsList(list));
  EXPECT_FALSE(eglDestroyContext(egl_, b));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_TRUE(eglReleaseThread());
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_EQ(eglQueryAPI(), static_cast<EGLenum>(EGL_NONE));  // eglReleaseThread resets the API
  EXPECT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EXPECT_TRUE(eglDestroyContext(egl_, a));
}

// EGL 1.5 3.7.3: make-current errors.
TEST_F(Egl, MakeCurrentReportsTheErrorsEglNames) {
  EGLConfig config = choose(kWindowConfig);
  EGLContext ctx = eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  const EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
  EGLSurface pbuffer = eglCreatePbufferSurface(egl_, config, size);
  ASSERT_NE(pbuffer, EGL_NO_SURFACE);
  EXPECT_FALSE(eglMakeCurrent(egl_, pbuffer, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglMakeCurrent(egl_, pbuffer, pbuffer, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglMakeCurrent(egl_, pbuffer, pbuffer, reinterpret_cast<EGLContext>(&ctx)));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_FALSE(eglMakeCurrent(egl_, reinterpret_cast<EGLSurface>(&ctx), pbuffer, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_FALSE(eglMakeCurrent(EGL_NO_DISPLAY, pbuffer, pbuffer, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  // A surface of another config than the context's (as Mesa requires the same config).
  EGLint n = 0;
  ASSERT_TRUE(eglGetConfigs(egl_, nullptr, 0, &n));
  std::vector<EGLConfig> all(n);
  ASSERT_TRUE(eglGetConfigs(egl_, all.data(), n, &n));
  EGLConfig other = all[0] == config ? all[1] : all[0];
  EGLSurface other_pbuffer = eglCreatePbufferSurface(egl_, other, size);
  ASSERT_NE(other_pbuffer, EGL_NO_SURFACE);
  EXPECT_FALSE(eglMakeCurrent(egl_, other_pbuffer, other_pbuffer, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_TRUE(eglMakeCurrent(egl_, pbuffer, pbuffer, ctx));
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), pbuffer);
  EXPECT_EQ(eglGetCurrentSurface(EGL_READ), pbuffer);
  EXPECT_EQ(eglGetCurrentSurface(0x1234), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // A surface current here cannot be current to another thread's context.
  std::thread([&] {
    eglBindAPI(EGL_OPENGL_API);
    EGLContext mine = eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr);
    ASSERT_NE(mine, EGL_NO_CONTEXT);
    EXPECT_FALSE(eglMakeCurrent(egl_, pbuffer, pbuffer, mine));
    EXPECT_EQ(eglGetError(), EGL_BAD_ACCESS);
    EXPECT_TRUE(eglDestroyContext(egl_, mine));
  }).join();
  // Swapping a surface that is not this thread's draw surface.
  EXPECT_FALSE(eglSwapBuffers(egl_, other_pbuffer));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_TRUE(eglSwapBuffers(egl_, pbuffer));  // no effect on a pbuffer
  EXPECT_TRUE(eglSwapInterval(egl_, 0));
  EXPECT_TRUE(eglWaitClient());
  EXPECT_TRUE(eglWaitGL());
  EXPECT_TRUE(eglWaitNative(EGL_CORE_NATIVE_ENGINE));
  EXPECT_FALSE(eglWaitNative(0x1234));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // Destroying the current surface defers it; eglWaitClient then reports the lost surface.
  EXPECT_TRUE(eglDestroySurface(egl_, pbuffer));
  EXPECT_FALSE(eglWaitClient());
  EXPECT_EQ(eglGetError(), EGL_BAD_CURRENT_SURFACE);
  EXPECT_FALSE(eglDestroySurface(egl_, pbuffer));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_TRUE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_FALSE(eglSwapInterval(egl_, 1));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_TRUE(eglDestroySurface(egl_, other_pbuffer));
  EXPECT_TRUE(eglDestroyContext(egl_, ctx));
}

// EGL 1.5 3.5.1, 3.5.6, 3.10: a window surface, its queries, and a frame that reaches
// glReadPixels and the window.
TEST_F(Egl, WindowSurfaceFrameReachesReadPixels) {
  EGLConfig config = choose(kWindowConfig);
  Window win = make_window(config, 64, 48);
  ASSERT_NE(win, 0u);
  EGLSurface surface = eglCreatePlatformWindowSurface(egl_, config, &win, nullptr);
  ASSERT_NE(surface, EGL_NO_SURFACE);
  // One surface per window.
  EXPECT_EQ(eglCreateWindowSurface(egl_, config, win, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ALLOC);
  EXPECT_EQ(eglCreateWindowSurface(egl_, config, 0, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_WINDOW);
  EXPECT_EQ(eglCreatePlatformWindowSurface(egl_, config, nullptr, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_WINDOW);
  const EGLint bad[] = {0x1234, 0, EGL_NONE};
  EXPECT_EQ(eglCreateWindowSurface(egl_, config, win, bad), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_EQ(eglCreateWindowSurface(egl_, nullptr, win, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);

  EGLint value = 0;
  EXPECT_TRUE(eglQuerySurface(egl_, surface, EGL_WIDTH, &value));
  EXPECT_EQ(value, 64);
  EXPECT_TRUE(eglQuerySurface(egl_, surface, EGL_HEIGHT, &value));
  EXPECT_EQ(value, 48);
  EXPECT_TRUE(eglQuerySurface(egl_, surface, EGL_RENDER_BUFFER, &value));
  EXPECT_EQ(value, EGL_BACK_BUFFER);
  EXPECT_TRUE(eglQuerySurface(egl_, surface, EGL_CONFIG_ID, &value));
  EXPECT_EQ(value, attrib(config, EGL_CONFIG_ID));
  EXPECT_FALSE(eglQuerySurface(egl_, surface, 0x1234, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);

  const EGLint gl13[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 3, EGL_NONE};
  EGLContext ctx = eglCreateContext(egl_, config, EGL_NO_CONTEXT, gl13);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(egl_, surface, surface, ctx));
  EXPECT_TRUE(eglQueryContext(egl_, ctx, EGL_RENDER_BUFFER, &value));
  EXPECT_EQ(value, EGL_BACK_BUFFER);
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);  // the draw surface's size (EGL 1.5 3.7.3)
  EXPECT_EQ(viewport[2], 64);
  EXPECT_EQ(viewport[3], 48);
  GLint doublebuffer = 0;
  glGetIntegerv(GL_DOUBLEBUFFER, &doublebuffer);
  EXPECT_EQ(doublebuffer, 1);

  unsigned char left[4] = {}, right[4] = {};
  draw_half_red(10, 50, 24, left, right);
  EXPECT_EQ(left[0], 255);
  EXPECT_EQ(left[2], 0);
  EXPECT_EQ(right[0], 0);
  EXPECT_EQ(right[2], 255);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(eglSwapBuffers(egl_, surface));
  // The swapped frame is in the window once native rendering may follow (eglWaitClient).
  EXPECT_TRUE(eglWaitClient());
  XImage* image = XGetImage(dpy_, win, 0, 0, 64, 48, AllPlanes, ZPixmap);
  ASSERT_NE(image, nullptr);
  const unsigned long left_pixel = XGetPixel(image, 10, 24), right_pixel = XGetPixel(image, 50, 24);
  XDestroyImage(image);
  EXPECT_EQ(left_pixel & 0xffffff, 0xff0000u);
  EXPECT_EQ(right_pixel & 0xffffff, 0x0000ffu);

  EXPECT_TRUE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_TRUE(eglDestroySurface(egl_, surface));
  EXPECT_TRUE(eglDestroyContext(egl_, ctx));
  // After destruction the window may get a surface again.
  surface = eglCreateWindowSurface(egl_, config, win, nullptr);
  EXPECT_NE(surface, EGL_NO_SURFACE);
  EXPECT_TRUE(eglDestroySurface(egl_, surface));
}

// eglMakeCurrent renders the frame of the context it releases before it takes EGL's
// process-wide lock: while that rendering waits (here: presenting a single-buffered surface to an
// X server that another connection has grabbed), another thread's EGL calls go on. With the
// rendering inside the lock, the other thread's call would wait for the ungrab.
TEST_F(Egl, ReleasingAContextRendersOutsideEglsLock) {
  EGLConfig config = choose(kWindowConfig);
  Window win = make_window(config, 32, 32);
  ASSERT_NE(win, 0u);
  const EGLint single[] = {EGL_RENDER_BUFFER, EGL_SINGLE_BUFFER, EGL_NONE};
  EGLSurface surface = eglCreateWindowSurface(egl_, config, win, single);
  ASSERT_NE(surface, EGL_NO_SURFACE);
  EGLContext ctx = eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  Display* grabber = XOpenDisplay(nullptr);
  ASSERT_NE(grabber, nullptr);

  std::mutex mutex;
  std::condition_variable changed;
  bool recorded = false, grabbed = false, queried = false;
  std::thread releaser([&] {
    ASSERT_TRUE(eglMakeCurrent(egl_, surface, surface, ctx));
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);  // recorded, not yet rendered
    {
      std::unique_lock lock(mutex);
      recorded = true;
      changed.notify_all();
      changed.wait(lock, [&] { return grabbed; });
    }
    eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);  // renders, presents
  });
  {
    std::unique_lock lock(mutex);
    changed.wait(lock, [&] { return recorded; });
  }
  XGrabServer(grabber);
  XSync(grabber, False);
  {
    std::lock_guard lock(mutex);
    grabbed = true;
    changed.notify_all();
  }
  // Time for the release to reach the presentation, which waits for the ungrab.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  std::thread querier([&] {
    EXPECT_NE(eglQueryString(egl_, EGL_VENDOR), nullptr);
    std::lock_guard lock(mutex);
    queried = true;
    changed.notify_all();
  });
  bool went_on = false;
  {
    std::unique_lock lock(mutex);
    went_on = changed.wait_for(lock, std::chrono::seconds(10), [&] { return queried; });
  }
  XUngrabServer(grabber);
  XSync(grabber, False);
  querier.join();
  releaser.join();
  XCloseDisplay(grabber);
  EXPECT_TRUE(went_on) << "another thread's eglQueryString waited for the released frame";
  EXPECT_TRUE(eglDestroySurface(egl_, surface));
  EXPECT_TRUE(eglDestroyContext(egl_, ctx));
}

// A forked child that exits without exec'ing runs the static destructors that tear glpt's EGL
// displays down (xscreensaver's image-loading hacks do this when xscreensaver-getimage is
// missing); the parent's presenting connection to the X server must survive it.
TEST_F(Egl, ForkedChildExitingLeavesTheParentPresenting) {
  EGLConfig config = choose(kWindowConfig);
  Window win = make_window(config, 64, 48);
  ASSERT_NE(win, 0u);
  EGLSurface surface = eglCreateWindowSurface(egl_, config, win, nullptr);
  ASSERT_NE(surface, EGL_NO_SURFACE);
  EGLContext ctx = eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(egl_, surface, surface, ctx));
  unsigned char left[4] = {}, right[4] = {};
  draw_half_red(10, 50, 24, left, right);
  ASSERT_TRUE(eglSwapBuffers(egl_, surface));  // the window target is connected and presenting

  const pid_t child = fork();
  if (child == 0) std::exit(0);  // static destructors run here, with the parent's sockets
  int status = -1;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;

  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_TRUE(eglSwapBuffers(egl_, surface));
  EXPECT_TRUE(eglWaitClient());  // the frame on screen before it is read
  XImage* image = XGetImage(dpy_, win, 0, 0, 64, 48, AllPlanes, ZPixmap);
  ASSERT_NE(image, nullptr);
  const unsigned long pixel = XGetPixel(image, 10, 24);
  XDestroyImage(image);
  EXPECT_EQ(pixel & 0xffffff, 0x00ff00u);
  EXPECT_TRUE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglDestroySurface(egl_, surface));
  EXPECT_TRUE(eglDestroyContext(egl_, ctx));
}

// EGL 1.5 3.5.2: pbuffers render off-screen; glReadPixels reads them.
TEST_F(Egl, PbufferFrameReachesReadPixels) {
  EGLConfig config = choose(kWindowConfig);
  const EGLint size[] = {EGL_WIDTH, 40, EGL_HEIGHT, 20, EGL_NONE};
  EGLSurface pbuffer = eglCreatePbufferSurface(egl_, config, size);
  ASSERT_NE(pbuffer, EGL_NO_SURFACE);
  EGLint value = 0;
  EXPECT_TRUE(eglQuerySurface(egl_, pbuffer, EGL_WIDTH, &value));
  EXPECT_EQ(value, 40);
  EXPECT_TRUE(eglQuerySurface(egl_, pbuffer, EGL_HEIGHT, &value));
  EXPECT_EQ(value, 20);
  EXPECT_TRUE(eglQuerySurface(egl_, pbuffer, EGL_LARGEST_PBUFFER, &value));
  EXPECT_EQ(value, EGL_FALSE);
  EGLContext ctx = eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(egl_, pbuffer, pbuffer, ctx));
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 40);
  EXPECT_EQ(viewport[3], 20);
  unsigned char left[4] = {}, right[4] = {};
  draw_half_red(5, 35, 10, left, right);
  EXPECT_EQ(left[0], 255);
  EXPECT_EQ(left[2], 0);
  EXPECT_EQ(right[0], 0);
  EXPECT_EQ(right[2], 255);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  // Attribute errors.
  const EGLint negative[] = {EGL_WIDTH, -1, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(egl_, config, negative), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  const EGLint texture[] = {EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGBA, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(egl_, config, texture), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint unknown[] = {0x1234, 1, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(egl_, config, unknown), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint huge[] = {EGL_WIDTH,           1 << 30,  EGL_HEIGHT, 1,
                         EGL_LARGEST_PBUFFER, EGL_TRUE, EGL_NONE};
  EGLSurface largest = eglCreatePbufferSurface(egl_, config, huge);
  ASSERT_NE(largest, EGL_NO_SURFACE);
  EXPECT_TRUE(eglQuerySurface(egl_, largest, EGL_WIDTH, &value));
  EXPECT_EQ(value, attrib(config, EGL_MAX_PBUFFER_WIDTH));
  EXPECT_TRUE(eglDestroySurface(egl_, largest));

  // A 0x0 pbuffer (the default size) draws nothing and does not fail.
  EGLSurface empty = eglCreatePbufferSurface(egl_, config, nullptr);
  ASSERT_NE(empty, EGL_NO_SURFACE);
  EGLContext other = eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(egl_, empty, empty, other));
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_TRUE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglDestroyContext(egl_, other));
  EXPECT_TRUE(eglDestroySurface(egl_, empty));
  EXPECT_TRUE(eglDestroySurface(egl_, pbuffer));
  EXPECT_TRUE(eglDestroyContext(egl_, ctx));
}

// EGL_MESA_platform_surfaceless: pbuffer configs without visuals, no window surfaces.
TEST_F(Egl, SurfacelessPlatformOffersPbuffers) {
  EGLDisplay sl =
      eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  ASSERT_NE(sl, EGL_NO_DISPLAY);
  EXPECT_NE(sl, egl_);
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, dpy_, nullptr), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  ASSERT_TRUE(eglInitialize(sl, nullptr, nullptr));
  const EGLint windows[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};  // default: windows
  EGLint n = -1;
  ASSERT_TRUE(eglChooseConfig(sl, windows, nullptr, 0, &n));
  EXPECT_EQ(n, 0);
  const EGLint pbuffers[] = {EGL_RENDERABLE_TYPE,
                             EGL_OPENGL_BIT,
                             EGL_SURFACE_TYPE,
                             EGL_PBUFFER_BIT,
                             EGL_ALPHA_SIZE,
                             8,
                             EGL_NONE};
  EGLConfig config = nullptr;
  ASSERT_TRUE(eglChooseConfig(sl, pbuffers, &config, 1, &n));
  ASSERT_EQ(n, 1);
  const EGLint size[] = {EGL_WIDTH, 4, EGL_HEIGHT, 4, EGL_NONE};
  EGLSurface pbuffer = eglCreatePbufferSurface(sl, config, size);
  ASSERT_NE(pbuffer, EGL_NO_SURFACE);
  EGLContext ctx = eglCreateContext(sl, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(sl, pbuffer, pbuffer, ctx));
  glClearColor(0, 1, 0, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  unsigned char pixel[4] = {};
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  EXPECT_EQ(pixel[0], 0);
  EXPECT_EQ(pixel[1], 255);
  EXPECT_NEAR(pixel[3], 128, 1);
  Window root = DefaultRootWindow(dpy_);
  EXPECT_EQ(eglCreateWindowSurface(sl, config, root, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_TRUE(eglMakeCurrent(sl, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglTerminate(sl));  // frees the surface and the context
}

// Sync objects, images, pixmap and client-buffer surfaces are not offered: each reports the error
// EGL names for an unsupported type, target or config, after the display's own errors.
TEST_F(Egl, UnsupportedObjectsReportErrors) {
  EXPECT_EQ(eglCreateSync(egl_, EGL_SYNC_FENCE, nullptr), EGL_NO_SYNC);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_FALSE(eglDestroySync(egl_, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglCreateImage(egl_, EGL_NO_CONTEXT, EGL_GL_TEXTURE_2D, nullptr, nullptr),
            EGL_NO_IMAGE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglCreateSync(EGL_NO_DISPLAY, EGL_SYNC_FENCE, nullptr), EGL_NO_SYNC);
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EGLConfig config = choose(kWindowConfig);
  EXPECT_EQ(eglCreatePixmapSurface(egl_, config, 1, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_EQ(eglCreatePbufferFromClientBuffer(egl_, 0x1234, nullptr, config, nullptr),
            EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

// EGL_KHR_get_all_proc_addresses: the same entry points as the exported ones, GL and EGL.
TEST_F(Egl, ProcAddressesAreGlptsOwnEntryPoints) {
  using Proc = __eglMustCastToProperFunctionPointerType;
  EXPECT_EQ(eglGetProcAddress("eglSwapBuffers"), reinterpret_cast<Proc>(&eglSwapBuffers));
  EXPECT_EQ(eglGetProcAddress("glVertex3f"), reinterpret_cast<Proc>(&glVertex3f));
  EXPECT_EQ(eglGetProcAddress("glCallList"), reinterpret_cast<Proc>(&glCallList));
  EXPECT_EQ(eglGetProcAddress("eglNoSuchThing"), nullptr);
  EXPECT_EQ(eglGetProcAddress("glNoSuchThing"), nullptr);
  EXPECT_EQ(eglGetProcAddress(nullptr), nullptr);
}

// glpt's libEGL.so.1 (a filter on libGL.so.1, loaded with it): a program that dlopens
// "libEGL.so.1" gets glpt's EGL, not the system's.
TEST_F(Egl, DlopenLibEglGivesGlptsEntryPoints) {
  void* lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_NOLOAD);
  ASSERT_NE(lib, nullptr) << "glpt's libEGL.so.1 is not loaded with libGL.so.1";
  EXPECT_EQ(dlsym(lib, "eglGetDisplay"), reinterpret_cast<void*>(&eglGetDisplay));
  EXPECT_EQ(dlsym(lib, "eglCreatePlatformWindowSurface"),
            reinterpret_cast<void*>(&eglCreatePlatformWindowSurface));
  dlclose(lib);
}

// Two contexts (not sharing) drawing in turn to one pbuffer: eglMakeCurrent flushes the context
// it replaces (EGL 1.5 3.7.3), and the surface's buffers are the surface's, so the second sees
// what the first drew.
TEST_F(Egl, ContextsDrawingInTurnShareTheSurfacesBuffers) {
  EGLConfig config = choose(kWindowConfig);
  const EGLint size[] = {EGL_WIDTH, 16, EGL_HEIGHT, 8, EGL_NONE};
  EGLSurface pbuffer = eglCreatePbufferSurface(egl_, config, size);
  ASSERT_NE(pbuffer, EGL_NO_SURFACE);
  EGLContext a = eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr);
  EGLContext b = eglCreateContext(egl_, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(a != EGL_NO_CONTEXT && b != EGL_NO_CONTEXT);
  const auto clear_half = [](int x, float r, float g) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, 0, 8, 8);
    glClearColor(r, g, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
  };
  ASSERT_TRUE(eglMakeCurrent(egl_, pbuffer, pbuffer, a));
  clear_half(0, 1, 0);  // no flush: switching contexts does it
  ASSERT_TRUE(eglMakeCurrent(egl_, pbuffer, pbuffer, b));
  clear_half(8, 0, 1);
  unsigned char left[4] = {}, right[4] = {};
  glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, left);
  glReadPixels(12, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, right);
  EXPECT_EQ(left[0], 255);
  EXPECT_EQ(left[1], 0);
  EXPECT_EQ(right[0], 0);
  EXPECT_EQ(right[1], 255);
  EXPECT_TRUE(eglMakeCurrent(egl_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglDestroyContext(egl_, a));
  EXPECT_TRUE(eglDestroyContext(egl_, b));
  EXPECT_TRUE(eglDestroySurface(egl_, pbuffer));
}

}  // namespace
