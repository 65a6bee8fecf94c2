// GLX against glpt's libGL.so.1 on a real X server (Xvfb): visuals, FBConfigs, contexts,
// make-current, swap, proc addresses, and that a frame reaches glReadPixels.

// gtest before the X headers: Xlib's macros (None, Bool, Status) break gtest's templates.
// clang-format off
#include <gtest/gtest.h>
#include <GL/gl.h>
#include <GL/glx.h>
#include "../common/x11_gl_test_util.hpp"
// clang-format on

#include <cstdlib>
#include <cstring>

#ifndef GLX_CONTEXT_MAJOR_VERSION_ARB
#define GLX_CONTEXT_MAJOR_VERSION_ARB 0x2091
#define GLX_CONTEXT_MINOR_VERSION_ARB 0x2092
#endif

namespace {

class Glx : public ::testing::Test {
 protected:
  void SetUp() override {
    dpy_ = XOpenDisplay(nullptr);
    ASSERT_NE(dpy_, nullptr) << "no X display (run under tests/e2e/with_xvfb.sh)";
  }
  void TearDown() override {
    if (window_) XDestroyWindow(dpy_, window_);
    XCloseDisplay(dpy_);
  }
  Window make_window(XVisualInfo* vi, int w, int h) {
    window_ = glpt_test::create_mapped_window(dpy_, *vi, w, h);
    return window_;
  }
  Display* dpy_ = nullptr;
  Window window_ = 0;
};

TEST_F(Glx, QueriesDescribeGlx14) {
  int major = 0, minor = 0, err = -1, ev = -1;
  EXPECT_TRUE(glXQueryExtension(dpy_, &err, &ev));
  EXPECT_TRUE(glXQueryVersion(dpy_, &major, &minor));
  EXPECT_EQ(major, 1);
  EXPECT_EQ(minor, 4);
  const char* ext = glXQueryExtensionsString(dpy_, 0);
  ASSERT_NE(ext, nullptr);
  EXPECT_NE(std::strstr(ext, "GLX_ARB_get_proc_address"), nullptr);
  EXPECT_NE(std::strstr(ext, "GLX_ARB_create_context"), nullptr);
}

TEST_F(Glx, ChooseVisualNeedsRgba) {
  int rgba_db[] = {GLX_RGBA, GLX_RED_SIZE, 1, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1, None};
  XVisualInfo* vi = glXChooseVisual(dpy_, 0, rgba_db);
  ASSERT_NE(vi, nullptr);
  EXPECT_EQ(vi->c_class, TrueColor);
  int value = 0;
  EXPECT_EQ(glXGetConfig(dpy_, vi, GLX_DOUBLEBUFFER, &value), 0);
  EXPECT_EQ(value, 1);
  EXPECT_EQ(glXGetConfig(dpy_, vi, GLX_DEPTH_SIZE, &value), 0);
  EXPECT_GE(value, 1);
  XFree(vi);
  // Without GLX_RGBA Mesa 25 still matches RGBA visuals (its chooser leaves the render type
  // open), so glpt does too.
  int no_rgba[] = {GLX_DOUBLEBUFFER, None};
  XVisualInfo* any = glXChooseVisual(dpy_, 0, no_rgba);
  ASSERT_NE(any, nullptr);
  EXPECT_EQ(glXGetConfig(dpy_, any, GLX_DOUBLEBUFFER, &value), 0);
  EXPECT_EQ(value, 1);
  XFree(any);
  int too_deep[] = {GLX_RGBA, GLX_DEPTH_SIZE, 64, None};
  EXPECT_EQ(glXChooseVisual(dpy_, 0, too_deep), nullptr);
}

TEST_F(Glx, FBConfigsMatchAttributesAndRoundTrip) {
  const int attribs[] = {GLX_DRAWABLE_TYPE,
                         GLX_WINDOW_BIT,
                         GLX_RENDER_TYPE,
                         GLX_RGBA_BIT,
                         GLX_DOUBLEBUFFER,
                         True,
                         GLX_DEPTH_SIZE,
                         16,
                         GLX_STENCIL_SIZE,
                         8,
                         None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, attribs, &n);
  ASSERT_NE(configs, nullptr);
  ASSERT_GT(n, 0);
  int value = 0;
  EXPECT_EQ(glXGetFBConfigAttrib(dpy_, configs[0], GLX_DOUBLEBUFFER, &value), 0);
  EXPECT_EQ(value, 1);
  EXPECT_EQ(glXGetFBConfigAttrib(dpy_, configs[0], GLX_DEPTH_SIZE, &value), 0);
  EXPECT_GE(value, 16);
  int visual_id = 0;
  EXPECT_EQ(glXGetFBConfigAttrib(dpy_, configs[0], GLX_VISUAL_ID, &visual_id), 0);
  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy_, configs[0]);
  ASSERT_NE(vi, nullptr);
  EXPECT_EQ(static_cast<int>(vi->visualid), visual_id);
  XFree(vi);
  XFree(configs);
  const int pixmaps[] = {GLX_DRAWABLE_TYPE, GLX_PIXMAP_BIT, None};  // single-buffered ones
  GLXFBConfig* pixmap_configs = glXChooseFBConfig(dpy_, 0, pixmaps, &n);
  ASSERT_NE(pixmap_configs, nullptr);
  EXPECT_GT(n, 0);
  XFree(pixmap_configs);
}

TEST_F(Glx, ProcAddressesAreGlptsOwnEntryPoints) {
  auto get = [](const char* name) {
    return glXGetProcAddressARB(reinterpret_cast<const GLubyte*>(name));
  };
  EXPECT_EQ(get("glXSwapBuffers"), reinterpret_cast<__GLXextFuncPtr>(&glXSwapBuffers));
  EXPECT_EQ(get("glVertex3f"), reinterpret_cast<__GLXextFuncPtr>(&glVertex3f));
  EXPECT_EQ(glXGetProcAddress(reinterpret_cast<const GLubyte*>("glCallList")),
            reinterpret_cast<__GLXextFuncPtr>(&glCallList));
  EXPECT_EQ(get("glPolygonOffsetEXT"), nullptr);  // exported, not implemented
  EXPECT_EQ(get("glXNoSuchThing"), nullptr);
  EXPECT_EQ(get("glNoSuchThing"), nullptr);
}

TEST_F(Glx, ContextLifecycleAndAFrameReachesReadPixels) {
  int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 16, None};
  XVisualInfo* vi = glXChooseVisual(dpy_, 0, attribs);
  ASSERT_NE(vi, nullptr);
  Window win = make_window(vi, 64, 48);
  GLXContext ctx = glXCreateContext(dpy_, vi, nullptr, True);
  XFree(vi);
  ASSERT_NE(ctx, nullptr);
  EXPECT_TRUE(glXIsDirect(dpy_, ctx));
  EXPECT_EQ(glXGetCurrentContext(), nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  EXPECT_EQ(glXGetCurrentContext(), ctx);
  EXPECT_EQ(glXGetCurrentDrawable(), win);
  EXPECT_EQ(glXGetCurrentDisplay(), dpy_);
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);  // initialised to the window size
  EXPECT_EQ(viewport[2], 64);
  EXPECT_EQ(viewport[3], 48);
  unsigned int width = 0;
  glXQueryDrawable(dpy_, win, GLX_WIDTH, &width);
  EXPECT_EQ(width, 64u);

  unsigned char left[4] = {}, right[4] = {};
  glpt_test::draw_half_red(10, 50, 24, left, right);
  EXPECT_EQ(left[0], 255);
  EXPECT_EQ(left[2], 0);
  EXPECT_EQ(right[0], 0);
  EXPECT_EQ(right[2], 255);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glXSwapBuffers(dpy_, win);

  EXPECT_TRUE(glXMakeCurrent(dpy_, None, nullptr));
  EXPECT_EQ(glXGetCurrentContext(), nullptr);
  glXDestroyContext(dpy_, ctx);
}

TEST_F(Glx, NewContextAttribsAndMakeContextCurrent) {
  const int attribs[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DOUBLEBUFFER, True, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, attribs, &n);
  ASSERT_GT(n, 0);
  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy_, configs[0]);
  Window win = make_window(vi, 32, 32);
  XFree(vi);
  GLXWindow glx_win = glXCreateWindow(dpy_, configs[0], win, nullptr);
  ASSERT_NE(glx_win, 0u);
  GLXContext a = glXCreateNewContext(dpy_, configs[0], GLX_RGBA_TYPE, nullptr, True);
  ASSERT_NE(a, nullptr);
  using CreateAttribs = GLXContext (*)(Display*, GLXFBConfig, GLXContext, Bool, const int*);
  auto create_attribs = reinterpret_cast<CreateAttribs>(
      glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCreateContextAttribsARB")));
  ASSERT_NE(create_attribs, nullptr);
  const int gl13[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 3, None};
  GLXContext b = create_attribs(dpy_, configs[0], a, True, gl13);  // shares a's display lists
  ASSERT_NE(b, nullptr);
  const int gl33[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 3, None};
  // glpt is GL 1.5: a 3.3 context is GLXBadFBConfig, reported to the X error handler.
  auto* old_handler = XSetErrorHandler([](Display*, XErrorEvent*) { return 0; });
  EXPECT_EQ(create_attribs(dpy_, configs[0], nullptr, True, gl33), nullptr);
  XSync(dpy_, False);
  XSetErrorHandler(old_handler);

  ASSERT_TRUE(glXMakeContextCurrent(dpy_, glx_win, glx_win, a));
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEndList();
  ASSERT_TRUE(glXMakeContextCurrent(dpy_, glx_win, glx_win, b));
  EXPECT_TRUE(glIsList(list));  // shared list namespace
  EXPECT_EQ(glXGetCurrentReadDrawable(), glx_win);
  glXMakeContextCurrent(dpy_, None, None, nullptr);
  glXDestroyContext(dpy_, b);
  glXDestroyContext(dpy_, a);
  glXDestroyWindow(dpy_, glx_win);
  XFree(configs);
}

// GLX 1.4 3.3.3 and Mesa's glXChooseFBConfig: with no alpha requested, configs without alpha come
// first (Mesa 25 answers alpha 0 for this list); asking for alpha excludes them. A drawable
// without alpha reads alpha 1 and blends with destination alpha 1 (GL 1.5 4.1.8, 4.3.2).
TEST_F(Glx, ConfigsWithoutAlphaComeFirstAndReadAlphaOne) {
  const int rgb[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 1, GLX_DOUBLEBUFFER, True, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy_, 0, rgb, &n);
  ASSERT_GT(n, 0);
  int alpha = -1, buffer = 0;
  EXPECT_EQ(glXGetFBConfigAttrib(dpy_, configs[0], GLX_ALPHA_SIZE, &alpha), 0);
  EXPECT_EQ(alpha, 0);
  EXPECT_EQ(glXGetFBConfigAttrib(dpy_, configs[0], GLX_BUFFER_SIZE, &buffer), 0);
  EXPECT_EQ(buffer, 24);
  const int rgba[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_ALPHA_SIZE, 1, None};
  int n_alpha = 0;
  GLXFBConfig* with_alpha = glXChooseFBConfig(dpy_, 0, rgba, &n_alpha);
  ASSERT_GT(n_alpha, 0);
  for (int i = 0; i < n_alpha; ++i) {
    EXPECT_EQ(glXGetFBConfigAttrib(dpy_, with_alpha[i], GLX_ALPHA_SIZE, &alpha), 0);
    EXPECT_EQ(alpha, 8);
  }
  XFree(with_alpha);

  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy_, configs[0]);
  ASSERT_NE(vi, nullptr);
  Window win = make_window(vi, 16, 16);
  XFree(vi);
  GLXContext ctx = glXCreateNewContext(dpy_, configs[0], GLX_RGBA_TYPE, nullptr, True);
  XFree(configs);
  ASSERT_NE(ctx, nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy_, win, ctx));
  GLint alpha_bits = -1;
  glGetIntegerv(GL_ALPHA_BITS, &alpha_bits);
  EXPECT_EQ(alpha_bits, 0);
  glClearColor(0.2f, 0.4f, 0.6f, 0.25f);
  glClear(GL_COLOR_BUFFER_BIT);
  unsigned char cleared[4] = {};
  glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, cleared);
  EXPECT_EQ(cleared[3], 255);
  // Destination alpha is 1: GL_DST_ALPHA keeps the source, GL_ONE_MINUS_DST_ALPHA drops the
  // destination, so the quad's colour replaces the clear colour exactly.
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA);
  glColor4f(1.0f, 0.0f, 0.0f, 0.5f);
  glRectf(-1, -1, 1, 1);
  unsigned char blended[4] = {};
  glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, blended);
  EXPECT_EQ(blended[0], 255);
  EXPECT_EQ(blended[1], 0);
  EXPECT_EQ(blended[2], 0);
  EXPECT_EQ(blended[3], 255);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glXMakeCurrent(dpy_, None, nullptr);
  glXDestroyContext(dpy_, ctx);
}

}  // namespace
