/* glx_oracle: prints what a libGL's GLX says about the X server it runs on, for comparing glpt
 * with Mesa on the same server (glx_oracle_test.sh runs it once plain, once with glpt preloaded).
 *
 *   glx_oracle configs  every visual and FBConfig with every attribute, and the results of a set
 *                       of glXChooseVisual / glXChooseFBConfig lists
 *   glx_oracle xfont    a string drawn with glXUseXFont("fixed") in a single-buffered window,
 *                       read back with XGetImage, as rows of '#' and '.'
 *   glx_oracle errors   the X errors (GLX's own as GLX+n) and return values of bad GLX calls
 *   glx_oracle queries  glXQueryDrawable / glXQueryContext / GL state of GLX windows, pbuffers and
 *                       pixmaps, single- and double-buffered
 *
 * Only configs glpt can render are listed (8-bit RGB, 0/8 alpha, single-sampled): glpt leaves
 * the others out, so lists are filtered the same way on both sides. */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <string.h>

static const struct {
  const char* name;
  int attrib;
} kAttribs[] = {
    {"use_gl", GLX_USE_GL},
    {"buffer", GLX_BUFFER_SIZE},
    {"level", GLX_LEVEL},
    {"rgba", GLX_RGBA},
    {"db", GLX_DOUBLEBUFFER},
    {"stereo", GLX_STEREO},
    {"aux", GLX_AUX_BUFFERS},
    {"r", GLX_RED_SIZE},
    {"g", GLX_GREEN_SIZE},
    {"b", GLX_BLUE_SIZE},
    {"a", GLX_ALPHA_SIZE},
    {"depth", GLX_DEPTH_SIZE},
    {"stencil", GLX_STENCIL_SIZE},
    {"ar", GLX_ACCUM_RED_SIZE},
    {"ag", GLX_ACCUM_GREEN_SIZE},
    {"ab", GLX_ACCUM_BLUE_SIZE},
    {"aa", GLX_ACCUM_ALPHA_SIZE},
    {"caveat", GLX_CONFIG_CAVEAT},
    {"vtype", GLX_X_VISUAL_TYPE},
    {"ttype", GLX_TRANSPARENT_TYPE},
    {"tindex", GLX_TRANSPARENT_INDEX_VALUE},
    {"tred", GLX_TRANSPARENT_RED_VALUE},
    {"tgreen", GLX_TRANSPARENT_GREEN_VALUE},
    {"tblue", GLX_TRANSPARENT_BLUE_VALUE},
    {"talpha", GLX_TRANSPARENT_ALPHA_VALUE},
    {"visual", GLX_VISUAL_ID},
    {"id", GLX_FBCONFIG_ID},
    {"dtype", GLX_DRAWABLE_TYPE},
    {"rtype", GLX_RENDER_TYPE},
    {"xrend", GLX_X_RENDERABLE},
    {"screen", GLX_SCREEN},
    {"pbw", GLX_MAX_PBUFFER_WIDTH},
    {"pbh", GLX_MAX_PBUFFER_HEIGHT},
    {"pbp", GLX_MAX_PBUFFER_PIXELS},
    {"sbuf", GLX_SAMPLE_BUFFERS},
    {"samples", GLX_SAMPLES},
    {"srgb", 0x20B2},
};
#define N_ATTRIBS (sizeof(kAttribs) / sizeof(kAttribs[0]))

/* A mapped window of `vi`, not synced (GLX must flush the program's Display itself). */
static Window create_window(Display* dpy, XVisualInfo* vi, int w, int h) {
  XSetWindowAttributes attr;
  memset(&attr, 0, sizeof attr);
  attr.colormap = XCreateColormap(dpy, RootWindow(dpy, 0), vi->visual, AllocNone);
  Window win = XCreateWindow(dpy, RootWindow(dpy, 0), 0, 0, w, h, 0, vi->depth, InputOutput,
                             vi->visual, CWColormap, &attr);
  XMapWindow(dpy, win);
  return win;
}

static int renderable(int r, int g, int b, int a, int samples) {
  return r == 8 && g == 8 && b == 8 && (a == 0 || a == 8) && samples == 0;
}

static int fb(Display* dpy, GLXFBConfig c, int attrib) {
  int v = -12345;
  if (glXGetFBConfigAttrib(dpy, c, attrib, &v) != Success) return -12345;
  return v;
}

static int fb_renderable(Display* dpy, GLXFBConfig c) {
  return renderable(fb(dpy, c, GLX_RED_SIZE), fb(dpy, c, GLX_GREEN_SIZE), fb(dpy, c, GLX_BLUE_SIZE),
                    fb(dpy, c, GLX_ALPHA_SIZE), fb(dpy, c, GLX_SAMPLE_BUFFERS));
}

static int cfg(Display* dpy, XVisualInfo* vi, int attrib) {
  int v = -12345;
  int rc = glXGetConfig(dpy, vi, attrib, &v);
  return rc == Success ? v : -1000 - rc;
}

static void configs(Display* dpy) {
  int n = 0;
  XVisualInfo templ;
  memset(&templ, 0, sizeof templ);
  XVisualInfo* vis = XGetVisualInfo(dpy, VisualNoMask, &templ, &n);
  for (int i = 0; i < n; ++i) {
    XVisualInfo* vi = &vis[i];
    if (cfg(dpy, vi, GLX_USE_GL) != 1) {
      printf("visual 0x%lx: no GL\n", vi->visualid);
      continue;
    }
    if (!renderable(cfg(dpy, vi, GLX_RED_SIZE), cfg(dpy, vi, GLX_GREEN_SIZE),
                    cfg(dpy, vi, GLX_BLUE_SIZE), cfg(dpy, vi, GLX_ALPHA_SIZE),
                    cfg(dpy, vi, GLX_SAMPLE_BUFFERS)))
      continue;
    printf("visual 0x%lx:", vi->visualid);
    /* GLX_FBCONFIG_ID onwards are FBConfig attributes; glXGetConfig's answers stop at samples */
    for (size_t k = 0; k < N_ATTRIBS; ++k)
      if (kAttribs[k].attrib != GLX_FBCONFIG_ID && kAttribs[k].attrib != GLX_SCREEN &&
          kAttribs[k].attrib != GLX_DRAWABLE_TYPE && kAttribs[k].attrib != GLX_RENDER_TYPE &&
          kAttribs[k].attrib != GLX_X_RENDERABLE && kAttribs[k].attrib != GLX_MAX_PBUFFER_WIDTH &&
          kAttribs[k].attrib != GLX_MAX_PBUFFER_HEIGHT &&
          kAttribs[k].attrib != GLX_MAX_PBUFFER_PIXELS)
        printf(" %s=%d", kAttribs[k].name, cfg(dpy, vi, kAttribs[k].attrib));
    printf("\n");
  }
  XFree(vis);

  GLXFBConfig* all = glXGetFBConfigs(dpy, 0, &n);
  for (int i = 0; i < n; ++i) {
    if (!fb_renderable(dpy, all[i])) continue;
    printf("fbconfig:");
    for (size_t k = 0; k < N_ATTRIBS; ++k)
      if (kAttribs[k].attrib != GLX_SCREEN && kAttribs[k].attrib != GLX_USE_GL)
        printf(" %s=%d", kAttribs[k].name, fb(dpy, all[i], kAttribs[k].attrib));
    printf("\n");
  }
  XFree(all);

  static int v_lists[][16] = {
      {GLX_RGBA, None},
      {GLX_RGBA, GLX_DOUBLEBUFFER, None},
      {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1, None},
      {GLX_RGBA, GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1, GLX_DEPTH_SIZE, 16, None},
      {GLX_RGBA, GLX_ALPHA_SIZE, 1, GLX_DOUBLEBUFFER, None},
      {GLX_RGBA, GLX_STENCIL_SIZE, 1, None},
      {GLX_RGBA, GLX_DEPTH_SIZE, 24, GLX_STENCIL_SIZE, 8, GLX_DOUBLEBUFFER, None},
      {GLX_RGBA, GLX_ACCUM_RED_SIZE, 1, None},
      {GLX_RGBA, GLX_DEPTH_SIZE, 32, None},
      {GLX_RGBA, GLX_BUFFER_SIZE, 24, None},
      {GLX_USE_GL, GLX_RGBA, GLX_DOUBLEBUFFER, None},
      {GLX_RGBA, GLX_LEVEL, 1, None},
      {GLX_RGBA, GLX_STEREO, None},
      {GLX_DOUBLEBUFFER, None},
      {None},
  };
  for (size_t l = 0; l < sizeof(v_lists) / sizeof(v_lists[0]); ++l) {
    XVisualInfo* vi = glXChooseVisual(dpy, 0, v_lists[l]);
    printf("choose visual %zu: ", l);
    if (vi)
      printf("0x%lx\n", vi->visualid);
    else
      printf("none\n");
    XFree(vi);
  }
  static int f_lists[][20] = {
      {None},
      {GLX_DOUBLEBUFFER, True, None},
      {GLX_DOUBLEBUFFER, False, None},
      {GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1, GLX_DEPTH_SIZE, 1, None},
      {GLX_ALPHA_SIZE, 1, GLX_DEPTH_SIZE, 24, GLX_STENCIL_SIZE, 8, None},
      {GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, None},
      {GLX_DRAWABLE_TYPE, GLX_PIXMAP_BIT, GLX_DEPTH_SIZE, 16, None},
      {GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT | GLX_PIXMAP_BIT, GLX_DOUBLEBUFFER, False, None},
      {GLX_X_VISUAL_TYPE, GLX_DIRECT_COLOR, None},
      {GLX_X_RENDERABLE, True, GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_BUFFER_SIZE, 32, None},
      {GLX_CONFIG_CAVEAT, GLX_NONE, GLX_STENCIL_SIZE, 1, None},
      {GLX_ACCUM_RED_SIZE, 1, None},
      {GLX_RGBA, True, None},
      {GLX_RENDER_TYPE, GLX_COLOR_INDEX_BIT, None},
      {GLX_DRAWABLE_TYPE, GLX_DONT_CARE, GLX_DEPTH_SIZE, 0, None},
      {0x7777, 1, GLX_DOUBLEBUFFER, True, None}, /* an unknown attribute is skipped */
  };
  for (size_t l = 0; l < sizeof(f_lists) / sizeof(f_lists[0]); ++l) {
    GLXFBConfig* chosen = glXChooseFBConfig(dpy, 0, f_lists[l], &n);
    printf("choose fbconfig %zu:", l);
    for (int i = 0; i < n; ++i)
      if (fb_renderable(dpy, chosen[i])) printf(" %d", fb(dpy, chosen[i], GLX_FBCONFIG_ID));
    printf("\n");
    XFree(chosen);
  }
}

static int xfont(Display* dpy) {
  int attribs[] = {GLX_RGBA, GLX_RED_SIZE, 1, None};
  XVisualInfo* vi = glXChooseVisual(dpy, 0, attribs);
  if (!vi) return 1;
  Window win = create_window(dpy, vi, 120, 24);
  GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
  glXMakeCurrent(dpy, win, ctx);
  Font font = XLoadFont(dpy, "fixed");
  GLuint base = glGenLists(128);
  glXUseXFont(font, 0, 128, base);
  glViewport(0, 0, 120, 24);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 120, 0, 24, -1, 1);
  glColor3f(1, 1, 1);
  glRasterPos2i(3, 7);
  glListBase(base);
  const char* text = "glpt Ag_|";
  glCallLists((GLsizei)strlen(text), GL_UNSIGNED_BYTE, text);
  glFlush();
  XSync(dpy, False);
  XImage* image = XGetImage(dpy, win, 0, 0, 120, 24, AllPlanes, ZPixmap);
  for (int y = 0; y < 24; ++y) {
    for (int x = 0; x < 120; ++x) putchar((XGetPixel(image, x, y) & 0xFF00) ? '#' : '.');
    putchar('\n');
  }
  XDestroyImage(image);
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, ctx);
  XFree(vi);
  return 0;
}

static int g_error_base;
static int x_error(Display* dpy, XErrorEvent* e) {
  (void)dpy;
  if (e->error_code >= g_error_base && e->error_code < g_error_base + 14)
    printf("  error GLX+%d minor %d\n", e->error_code - g_error_base, e->minor_code);
  else
    printf("  error %d minor %d\n", e->error_code, e->minor_code);
  return 0;
}

typedef GLXContext (*CreateAttribs)(Display*, GLXFBConfig, GLXContext, Bool, const int*);

static int errors(Display* dpy) {
  int event_base;
  glXQueryExtension(dpy, &g_error_base, &event_base);
  XSetErrorHandler(x_error);
  int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, None};
  XVisualInfo* vi = glXChooseVisual(dpy, 0, attribs);
  Window win = create_window(dpy, vi, 16, 16);
  GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
  const int any[] = {GLX_DOUBLEBUFFER, True, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy, 0, any, &n);
  CreateAttribs create =
      (CreateAttribs)glXGetProcAddressARB((const GLubyte*)"glXCreateContextAttribsARB");
#define STEP(name, call)                                     \
  do {                                                       \
    printf("%s:\n", name);                                   \
    long result = (long)(call) != 0;                         \
    XSync(dpy, False);                                       \
    printf("  returned %s\n", result ? "non-zero" : "zero"); \
  } while (0)
  /* Not compared: a window that does not exist, where Mesa reports BadDrawable twice and then
   * GLXBadContext, glpt GLXBadDrawable as GLX 1.4 3.3.7 names it (glx_drawables_test). */
  STEP("make current draw None", glXMakeContextCurrent(dpy, None, win, ctx));
  STEP("make current window without context", glXMakeCurrent(dpy, win, NULL));
  STEP("new context colour index",
       glXCreateNewContext(dpy, configs[0], GLX_COLOR_INDEX_TYPE, NULL, True));
  STEP("new context NULL config", glXCreateNewContext(dpy, NULL, GLX_RGBA_TYPE, NULL, True));
  static const int unknown[] = {0x7777, 1, None};
  static const int gl17[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 7,
                             None};
  static const int bad_flags[] = {GLX_CONTEXT_FLAGS_ARB, 0x100, None};
  static const int no_profile[] = {GLX_CONTEXT_MAJOR_VERSION_ARB,
                                   3,
                                   GLX_CONTEXT_MINOR_VERSION_ARB,
                                   2,
                                   GLX_CONTEXT_PROFILE_MASK_ARB,
                                   0,
                                   None};
  static const int fwd1[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_FLAGS_ARB,
                             GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB, None};
  static const int ci[] = {GLX_RENDER_TYPE, GLX_COLOR_INDEX_TYPE, None};
  static const int gl15[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 5,
                             None};
  STEP("attribs unknown attribute", create(dpy, configs[0], NULL, True, unknown));
  STEP("attribs version 1.7", create(dpy, configs[0], NULL, True, gl17));
  STEP("attribs unknown flag", create(dpy, configs[0], NULL, True, bad_flags));
  STEP("attribs no profile 3.2", create(dpy, configs[0], NULL, True, no_profile));
  STEP("attribs forward-compatible 1.0", create(dpy, configs[0], NULL, True, fwd1));
  STEP("attribs colour index", create(dpy, configs[0], NULL, True, ci));
  STEP("attribs NULL config", create(dpy, NULL, NULL, True, gl15));
  STEP("attribs 1.5", create(dpy, configs[0], NULL, True, gl15));
  unsigned int value = 0;
  printf("query drawable None:\n");
  glXQueryDrawable(dpy, None, GLX_WIDTH, &value);
  XSync(dpy, False);
  printf("destroy no such GLX window:\n");
  glXDestroyWindow(dpy, 0x7FFFFF1);
  XSync(dpy, False);
  printf("destroy no such pbuffer:\n");
  glXDestroyPbuffer(dpy, 0x7FFFFF2);
  XSync(dpy, False);
  printf("destroy no such GLX pixmap:\n");
  glXDestroyGLXPixmap(dpy, 0x7FFFFF3);
  XSync(dpy, False);
  int v = 0;
  printf("get config attribute 0x7777: %d\n", glXGetConfig(dpy, vi, 0x7777, &v));
  printf("get fbconfig attribute 0x7777: %d\n", glXGetFBConfigAttrib(dpy, configs[0], 0x7777, &v));
  printf("swap interval SGI without context: %d\n",
         ((int (*)(int))glXGetProcAddressARB((const GLubyte*)"glXSwapIntervalSGI"))(1));
  XFree(configs);
  XFree(vi);
  return 0;
}

static void print_drawable(Display* dpy, const char* name, GLXDrawable d) {
  static const struct {
    const char* name;
    int attrib;
  } kQueries[] = {{"width", GLX_WIDTH},
                  {"height", GLX_HEIGHT},
                  {"preserved", GLX_PRESERVED_CONTENTS},
                  {"largest", GLX_LARGEST_PBUFFER},
                  {"event_mask", GLX_EVENT_MASK},
                  {"fbconfig", GLX_FBCONFIG_ID}};
  printf("%s:", name);
  for (size_t i = 0; i < sizeof(kQueries) / sizeof(kQueries[0]); ++i) {
    unsigned int v = 12345;
    glXQueryDrawable(dpy, d, kQueries[i].attrib, &v);
    printf(" %s=%u", kQueries[i].name, v);
  }
  printf("\n");
}

static void print_gl_state(const char* name) {
  GLint draw = 0, read = 0, depth = 0, stencil = 0, alpha = 0, accum = 0, viewport[4] = {0};
  GLboolean db = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &draw);
  glGetIntegerv(GL_READ_BUFFER, &read);
  glGetIntegerv(GL_DEPTH_BITS, &depth);
  glGetIntegerv(GL_STENCIL_BITS, &stencil);
  glGetIntegerv(GL_ALPHA_BITS, &alpha);
  glGetIntegerv(GL_ACCUM_RED_BITS, &accum);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetBooleanv(GL_DOUBLEBUFFER, &db);
  printf("%s gl: draw=0x%x read=0x%x db=%d depth=%d stencil=%d alpha=%d accum=%d viewport=%dx%d\n",
         name, draw, read, db, depth, stencil, alpha, accum, viewport[2], viewport[3]);
}

static int queries(Display* dpy) {
  int event_base;
  glXQueryExtension(dpy, &g_error_base, &event_base);
  XSetErrorHandler(x_error);
  static const int kLists[][12] = {
      {GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 24, GLX_STENCIL_SIZE, 8, None},
      {GLX_DOUBLEBUFFER, False, GLX_ALPHA_SIZE, 8, None},
      {GLX_DOUBLEBUFFER, False, GLX_DEPTH_SIZE, 16, None},
      {GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 0, None},
  };
  for (size_t l = 0; l < sizeof(kLists) / sizeof(kLists[0]); ++l) {
    int n = 0;
    GLXFBConfig* configs = glXChooseFBConfig(dpy, 0, kLists[l], &n);
    if (n == 0) continue;
    GLXFBConfig c = configs[0];
    XFree(configs);
    int id = 0;
    glXGetFBConfigAttrib(dpy, c, GLX_FBCONFIG_ID, &id);
    printf("config list %zu: fbconfig %d\n", l, id);
    XVisualInfo* vi = glXGetVisualFromFBConfig(dpy, c);
    Window win = create_window(dpy, vi, 33, 17);
    GLXWindow glx_win = glXCreateWindow(dpy, c, win, NULL);
    glXSelectEvent(dpy, glx_win, GLX_PBUFFER_CLOBBER_MASK);
    print_drawable(dpy, "  glx window", glx_win);
    const int size[] = {
        GLX_PBUFFER_WIDTH, 21, GLX_PBUFFER_HEIGHT, 9, GLX_PRESERVED_CONTENTS, False, None};
    GLXPbuffer pbuffer = glXCreatePbuffer(dpy, c, size);
    print_drawable(dpy, "  pbuffer", pbuffer);
    int drawable_type = 0;
    glXGetFBConfigAttrib(dpy, c, GLX_DRAWABLE_TYPE, &drawable_type);
    if (drawable_type & GLX_PIXMAP_BIT) {
      Pixmap pixmap = XCreatePixmap(dpy, RootWindow(dpy, 0), 7, 5, vi->depth);
      GLXPixmap glx_pixmap = glXCreatePixmap(dpy, c, pixmap, NULL);
      print_drawable(dpy, "  glx pixmap", glx_pixmap);
      GLXContext pctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
      glXMakeContextCurrent(dpy, glx_pixmap, glx_pixmap, pctx);
      print_gl_state("  glx pixmap");
      glClearColor(1, 0, 1, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glFlush();
      XImage* image = XGetImage(dpy, pixmap, 0, 0, 1, 1, AllPlanes, ZPixmap);
      printf("  glx pixmap pixel 0x%06lx\n", XGetPixel(image, 0, 0) & 0xFFFFFF);
      XDestroyImage(image);
      glXMakeContextCurrent(dpy, None, None, NULL);
      glXDestroyContext(dpy, pctx);
      glXDestroyPixmap(dpy, glx_pixmap);
      XFreePixmap(dpy, pixmap);
    }
    GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
    int value = 0;
    glXQueryContext(dpy, ctx, GLX_FBCONFIG_ID, &value);
    printf("  context fbconfig %d", value);
    glXQueryContext(dpy, ctx, GLX_RENDER_TYPE, &value);
    printf(" render type 0x%x", value);
    glXQueryContext(dpy, ctx, GLX_SCREEN, &value);
    printf(" screen %d\n", value);
    glXMakeContextCurrent(dpy, glx_win, glx_win, ctx);
    print_gl_state("  glx window");
    printf("  current drawable is the GLX window: %d\n", glXGetCurrentDrawable() == glx_win);
    glXMakeContextCurrent(dpy, None, None, NULL);
    GLXContext ctx2 = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
    glXMakeContextCurrent(dpy, pbuffer, pbuffer, ctx2);
    print_gl_state("  pbuffer");
    glXMakeContextCurrent(dpy, None, None, NULL);
    XSync(dpy, False);
    glXDestroyContext(dpy, ctx);
    glXDestroyContext(dpy, ctx2);
    glXDestroyPbuffer(dpy, pbuffer);
    glXDestroyWindow(dpy, glx_win);
    XDestroyWindow(dpy, win);
    XFree(vi);
  }
  int attribs[] = {GLX_RGBA, GLX_RED_SIZE, 1, None};
  XVisualInfo* vi = glXChooseVisual(dpy, 0, attribs);
  Pixmap pixmap = XCreatePixmap(dpy, RootWindow(dpy, 0), 13, 11, vi->depth);
  GLXPixmap glx_pixmap = glXCreateGLXPixmap(dpy, vi, pixmap);
  GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
  glXMakeCurrent(dpy, glx_pixmap, ctx);
  print_gl_state("glx pixmap");
  glXMakeCurrent(dpy, None, NULL);
  XSync(dpy, False);
  glXDestroyContext(dpy, ctx);
  glXDestroyGLXPixmap(dpy, glx_pixmap);
  XFreePixmap(dpy, pixmap);
  XFree(vi);
  return 0;
}

int main(int argc, char** argv) {
  Display* dpy = XOpenDisplay(NULL);
  if (!dpy) return 2;
  int rc = 0;
  if (argc > 1 && strcmp(argv[1], "xfont") == 0)
    rc = xfont(dpy);
  else if (argc > 1 && strcmp(argv[1], "errors") == 0)
    rc = errors(dpy);
  else if (argc > 1 && strcmp(argv[1], "queries") == 0)
    rc = queries(dpy);
  else
    configs(dpy);
  XCloseDisplay(dpy);
  return rc;
}
