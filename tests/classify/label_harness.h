/* label_harness.h: the harness every labelled classification program (tests/classify/programs)
 * includes. A program opens its window through label_run, issues GL 1.x drawing commands in its
 * frame callback and, right next to every drawing command, calls label() with the class it means
 * (docs: tests/classify/README.md). check_labels.py compares these labels with glpt's
 * GLPT_CLASSIFY_LOG.
 *
 * Drawing commands (each one label): a glBegin/glEnd pair, glDrawArrays, glDrawElements,
 * glDrawRangeElements, glRect*, glBitmap, glDrawPixels; also when executed from a display list
 * (label when the list is executed, once per drawing command inside it, never when it is
 * compiled).
 *
 * Every lbl_* geometry helper below issues exactly ONE drawing command and never labels, so a
 * program writes `label("static", "crate"); lbl_box(1, 1, 1);` and the two stay side by side.
 *
 * Command line of every program: [--dump DIR] writes each frame's back buffer, read before the
 * swap, to DIR/frame_<f>.ppm (debugging only; never used by the tests).
 *
 * Everything is static (inline), C11, and needs only libGL, libX11 and libm.
 */
#ifndef GLPT_TESTS_CLASSIFY_LABEL_HARNESS_H
#define GLPT_TESTS_CLASSIFY_LABEL_HARNESS_H

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { LBL_WIDTH = 160, LBL_HEIGHT = 120, LBL_MAX_LABELS_PER_FRAME = 2048, LBL_MAX_KEY = 64 };

#define LBL_PI 3.14159265358979323846f

/* ---------------------------------------------------------------------------------------------
 * Labels
 */

static int lbl_current_frame = -1;
static int lbl_labels_this_frame = 0;
static char lbl_keys_this_frame[LBL_MAX_LABELS_PER_FRAME][LBL_MAX_KEY];

static inline void lbl_fail(const char* what, const char* detail) {
  fprintf(stderr, "label_harness: %s: %s (frame %d)\n", what, detail, lbl_current_frame);
  exit(4);
}

/* The class of the drawing command issued right next to this call; key names the object. */
static inline void label(const char* cls, const char* key) {
  static const char* const classes[] = {"static",    "moving",    "deforming", "blended",
                                        "particles", "multipass", "decal",     "overlay",
                                        "sky",       "shadow",    "viewmodel"};
  int known = 0;
  for (size_t i = 0; i < sizeof classes / sizeof classes[0]; ++i) {
    if (strcmp(cls, classes[i]) == 0) known = 1;
  }
  if (!known) lbl_fail("unknown class", cls);
  if (lbl_current_frame < 0) lbl_fail("label outside a frame", key);
  size_t length = strlen(key);
  if (length == 0 || length >= LBL_MAX_KEY) lbl_fail("key empty or too long", key);
  for (size_t i = 0; i < length; ++i) {
    if (key[i] <= ' ' || key[i] > '~') lbl_fail("key with a space or a non-ASCII character", key);
  }
  for (int i = 0; i < lbl_labels_this_frame; ++i) {
    if (strcmp(lbl_keys_this_frame[i], key) == 0) lbl_fail("key labelled twice in a frame", key);
  }
  if (lbl_labels_this_frame >= LBL_MAX_LABELS_PER_FRAME) lbl_fail("too many labels", key);
  memcpy(lbl_keys_this_frame[lbl_labels_this_frame++], key, length + 1);
  printf("LABEL %d %s %s\n", lbl_current_frame, cls, key);
}

/* label() with a printf-formatted key, for keys built from indices. */
static inline void labelf(const char* cls, const char* key_format, int a, int b) {
  char key[LBL_MAX_KEY];
  snprintf(key, sizeof key, key_format, a, b);
  label(cls, key);
}

/* ---------------------------------------------------------------------------------------------
 * Deterministic pseudo-random numbers (a 32-bit LCG, Numerical Recipes constants)
 */

static inline uint32_t lbl_rand(uint32_t* state) {
  *state = *state * 1664525u + 1013904223u;
  return *state >> 8;
}
/* Uniform in [0, 1). */
static inline float lbl_randf(uint32_t* state) { return (float)lbl_rand(state) / 16777216.0f; }

/* ---------------------------------------------------------------------------------------------
 * Matrices (glu is not linked)
 */

static inline void lbl_perspective(float fovy_degrees, float aspect, float z_near, float z_far) {
  float h = z_near * tanf(fovy_degrees * LBL_PI / 360.0f);
  glFrustum(-h * aspect, h * aspect, -h, h, z_near, z_far);
}

static inline void lbl_normalize(float v[3]) {
  float n = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (n > 0.0f) {
    v[0] /= n;
    v[1] /= n;
    v[2] /= n;
  }
}

static inline void lbl_cross(const float a[3], const float b[3], float out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The camera basis of lbl_look_at: right, up and forward (unit vectors, world space). */
static inline void lbl_camera_basis(const float eye[3], const float center[3], const float up[3],
                                    float right_out[3], float up_out[3], float forward_out[3]) {
  float f[3] = {center[0] - eye[0], center[1] - eye[1], center[2] - eye[2]};
  lbl_normalize(f);
  float s[3];
  lbl_cross(f, up, s);
  lbl_normalize(s);
  float u[3];
  lbl_cross(s, f, u);
  memcpy(right_out, s, sizeof s);
  memcpy(up_out, u, sizeof u);
  memcpy(forward_out, f, sizeof f);
}

/* Multiplies the current matrix by gluLookAt's matrix. */
static inline void lbl_look_at(const float eye[3], const float center[3], const float up[3]) {
  float s[3], u[3], f[3];
  lbl_camera_basis(eye, center, up, s, u, f);
  const GLfloat m[16] = {s[0], u[0], -f[0], 0.0f, s[1], u[1], -f[1], 0.0f,
                         s[2], u[2], -f[2], 0.0f, 0.0f, 0.0f, 0.0f,  1.0f};
  glMultMatrixf(m);
  glTranslatef(-eye[0], -eye[1], -eye[2]);
}

/* Loads projection = perspective and modelview = look-at (the usual start of a 3-D frame). */
static inline void lbl_camera(float fovy_degrees, float aspect, float z_near, float z_far,
                              const float eye[3], const float center[3]) {
  static const float up[3] = {0.0f, 1.0f, 0.0f};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lbl_perspective(fovy_degrees, aspect, z_near, z_far);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  lbl_look_at(eye, center, up);
}

/* Loads projection = glOrtho in pixels of a width x height viewport, modelview = identity. */
static inline void lbl_ortho_pixels(int width, int height) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, width, 0.0, height, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* ---------------------------------------------------------------------------------------------
 * Geometry: each helper issues exactly one drawing command (one glBegin/glEnd pair) and no label.
 */

/* An axis-aligned box centred on the origin, half sizes hx, hy, hz, outward normals, texture
 * coordinates 0..1 on every face (GL_QUADS, 24 vertices). */
static inline void lbl_box(float hx, float hy, float hz) {
  static const float n[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  static const float v[6][4][3] = {{{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}},
                                   {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
                                   {{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}},
                                   {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},
                                   {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
                                   {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}}};
  static const float t[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  glBegin(GL_QUADS);
  for (int face = 0; face < 6; ++face) {
    glNormal3fv(n[face]);
    for (int k = 0; k < 4; ++k) {
      glTexCoord2fv(t[k]);
      glVertex3f(v[face][k][0] * hx, v[face][k][1] * hy, v[face][k][2] * hz);
    }
  }
  glEnd();
}

/* One face of a cube of half size h centred on the origin, seen from inside (for sky boxes):
 * face 0..5 = +x, -x, +y, -y, +z, -z. One GL_QUADS quad. */
static inline void lbl_box_face_inside(int face, float h) {
  static const float v[6][4][3] = {{{1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {1, 1, -1}},
                                   {{-1, -1, 1}, {-1, -1, -1}, {-1, 1, -1}, {-1, 1, 1}},
                                   {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}},
                                   {{-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}},
                                   {{1, -1, 1}, {-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}},
                                   {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}}};
  static const float t[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  glBegin(GL_QUADS);
  for (int k = 0; k < 4; ++k) {
    glTexCoord2fv(t[k]);
    glVertex3f(v[face][k][0] * h, v[face][k][1] * h, v[face][k][2] * h);
  }
  glEnd();
}

/* A flat square grid in the plane y = 0 from -half to +half on x and z, n x n cells, as
 * GL_TRIANGLES (2 n^2 triangles), normal +y, texture coordinates 0..n. */
static inline void lbl_grid(int n, float half) {
  float cell = 2.0f * half / (float)n;
  glBegin(GL_TRIANGLES);
  glNormal3f(0.0f, 1.0f, 0.0f);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      float x0 = -half + cell * (float)i, x1 = x0 + cell;
      float z0 = -half + cell * (float)j, z1 = z0 + cell;
      glTexCoord2f((float)i, (float)j);
      glVertex3f(x0, 0.0f, z0);
      glTexCoord2f((float)i, (float)j + 1);
      glVertex3f(x0, 0.0f, z1);
      glTexCoord2f((float)i + 1, (float)j + 1);
      glVertex3f(x1, 0.0f, z1);
      glTexCoord2f((float)i, (float)j);
      glVertex3f(x0, 0.0f, z0);
      glTexCoord2f((float)i + 1, (float)j + 1);
      glVertex3f(x1, 0.0f, z1);
      glTexCoord2f((float)i + 1, (float)j);
      glVertex3f(x1, 0.0f, z0);
    }
  }
  glEnd();
}

/* A quad in the plane z = z from (x0, y0) to (x1, y1), normal +z, texture coordinates 0..1. */
static inline void lbl_quad_xy(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glTexCoord2f(0.0f, 0.0f);
  glVertex3f(x0, y0, z);
  glTexCoord2f(1.0f, 0.0f);
  glVertex3f(x1, y0, z);
  glTexCoord2f(1.0f, 1.0f);
  glVertex3f(x1, y1, z);
  glTexCoord2f(0.0f, 1.0f);
  glVertex3f(x0, y1, z);
  glEnd();
}

/* A 2-D quad (glVertex2f) from (x0, y0) to (x1, y1), texture coordinates 0..1. */
static inline void lbl_quad_2d(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f);
  glVertex2f(x0, y0);
  glTexCoord2f(1.0f, 0.0f);
  glVertex2f(x1, y0);
  glTexCoord2f(1.0f, 1.0f);
  glVertex2f(x1, y1);
  glTexCoord2f(0.0f, 1.0f);
  glVertex2f(x0, y1);
  glEnd();
}

/* ---------------------------------------------------------------------------------------------
 * Textures
 */

/* A size x size RGBA checkerboard of cells of `cell` texels, colours a and b (0..255 RGBA),
 * nearest filtering, repeat. Returns the texture name (bound to GL_TEXTURE_2D). */
static inline GLuint lbl_checker_texture(int size, int cell, const GLubyte a[4],
                                         const GLubyte b[4]) {
  GLubyte* texels = malloc((size_t)size * (size_t)size * 4);
  if (!texels) lbl_fail("out of memory", "texture");
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const GLubyte* c = ((x / cell + y / cell) & 1) ? a : b;
      memcpy(texels + 4 * (y * size + x), c, 4);
    }
  }
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  free(texels);
  return name;
}

/* The camera at eye looking at center, its translation removed (the rotation only): what a
 * sky box centred on the eye is drawn under. Loads the modelview. */
static inline void lbl_camera_rotation(const float eye[3], const float center[3],
                                       const float up[3]) {
  static const float origin[3] = {0.0f, 0.0f, 0.0f};
  const float direction[3] = {center[0] - eye[0], center[1] - eye[1], center[2] - eye[2]};
  glLoadIdentity();
  lbl_look_at(origin, direction, up);
}

/* A sky box's six face textures (checkers of sky blues and white, the -y face dark). */
static inline void lbl_sky_textures(GLuint textures[6]) {
  static const GLubyte colors[6][4] = {{120, 160, 230, 255}, {110, 150, 220, 255},
                                       {150, 190, 255, 255}, {60, 70, 90, 255},
                                       {130, 170, 240, 255}, {100, 140, 210, 255}};
  static const GLubyte white[4] = {235, 240, 250, 255};
  for (int i = 0; i < 6; ++i) textures[i] = lbl_checker_texture(16, 4, colors[i], white);
}

/* The six faces of a sky box of half size h around the origin, each its own draw labelled
 * `sky` (sky_face0..5), textured with `textures` (GL_REPLACE; texturing off afterwards). */
static inline void lbl_sky_box(const GLuint textures[6], float h) {
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int face = 0; face < 6; ++face) {
    glBindTexture(GL_TEXTURE_2D, textures[face]);
    labelf("sky", "sky_face%d", face, 0);
    lbl_box_face_inside(face, h);
  }
  glDisable(GL_TEXTURE_2D);
}

/* A size x size RGBA radial blob: colour c, alpha (and, if premultiplied, colour) falling from
 * 1 at the centre to 0 at the edge. Linear filtering, clamp. */
static inline GLuint lbl_blob_texture(int size, const GLubyte c[3], int premultiplied) {
  GLubyte* texels = malloc((size_t)size * (size_t)size * 4);
  if (!texels) lbl_fail("out of memory", "texture");
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      float dx = ((float)x + 0.5f) / (float)size * 2.0f - 1.0f;
      float dy = ((float)y + 0.5f) / (float)size * 2.0f - 1.0f;
      float a = 1.0f - sqrtf(dx * dx + dy * dy);
      if (a < 0.0f) a = 0.0f;
      GLubyte* t = texels + 4 * (y * size + x);
      for (int k = 0; k < 3; ++k) t[k] = (GLubyte)(premultiplied ? (float)c[k] * a : (float)c[k]);
      t[3] = (GLubyte)(255.0f * a);
    }
  }
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  free(texels);
  return name;
}

/* A simple white-light setup: GL_LIGHT0 directional from (x, y, z) in the current modelview's
 * space, colour material on ambient and diffuse. Enables lighting. */
static inline void lbl_light(float x, float y, float z) {
  const GLfloat position[4] = {x, y, z, 0.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat ambient[4] = {0.25f, 0.25f, 0.25f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
}

/* ---------------------------------------------------------------------------------------------
 * The run
 */

static inline void lbl_check_gl(const char* where) {
  GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  while (error != GL_NO_ERROR) {
    fprintf(stderr, "label_harness: GL error 0x%04x %s (frame %d)\n", (unsigned)error, where,
            lbl_current_frame);
    error = glGetError();
  }
  exit(3);
}

static inline void lbl_dump_frame(const char* directory, int f) {
  static GLubyte pixels[LBL_WIDTH * LBL_HEIGHT * 3];
  char path[4096];
  snprintf(path, sizeof path, "%s/frame_%d.ppm", directory, f);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, LBL_WIDTH, LBL_HEIGHT, GL_RGB, GL_UNSIGNED_BYTE, pixels);
  FILE* file = fopen(path, "wb");
  if (!file) lbl_fail("cannot write", path);
  fprintf(file, "P6\n%d %d\n255\n", LBL_WIDTH, LBL_HEIGHT);
  for (int y = LBL_HEIGHT - 1; y >= 0; --y) fwrite(pixels + 3 * LBL_WIDTH * y, 3, LBL_WIDTH, file);
  fclose(file);
}

/* Opens a 160x120 double-buffered RGBA window (depth 24, stencil 8) on $DISPLAY with
 * glXChooseVisual + glXCreateContext, maps it, calls setup() once, then frame(f) and
 * glXSwapBuffers for f = 0 .. frames-1, checks glGetError after setup and after every frame (an
 * error: message on stderr, exit status 3), then glFinish and tears everything down. Returns 0;
 * exits 1 without a display or visual, 2 on a bad command line. */
static inline int label_run(int argc, char** argv, int frames, void (*setup)(void),
                            void (*frame)(int f)) {
  const char* dump_directory = NULL;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--dump") == 0 && i + 1 < argc) {
      dump_directory = argv[++i];
    } else {
      fprintf(stderr, "usage: %s [--dump DIR]\n", argv[0]);
      return 2;
    }
  }
  if (frames < 4) frames = 6;
  Display* dpy = XOpenDisplay(NULL);
  if (!dpy) {
    fprintf(stderr, "label_harness: cannot open display\n");
    exit(1);
  }
  int attributes[] = {GLX_RGBA,
                      GLX_DOUBLEBUFFER,
                      GLX_RED_SIZE,
                      8,
                      GLX_GREEN_SIZE,
                      8,
                      GLX_BLUE_SIZE,
                      8,
                      GLX_DEPTH_SIZE,
                      24,
                      GLX_STENCIL_SIZE,
                      8,
                      None};
  XVisualInfo* visual = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
  if (!visual) {
    fprintf(stderr, "label_harness: no RGBA visual with depth 24 and stencil 8\n");
    exit(1);
  }
  Window root = RootWindow(dpy, visual->screen);
  XSetWindowAttributes window_attributes;
  memset(&window_attributes, 0, sizeof window_attributes);
  window_attributes.colormap = XCreateColormap(dpy, root, visual->visual, AllocNone);
  Window window = XCreateWindow(dpy, root, 0, 0, LBL_WIDTH, LBL_HEIGHT, 0, visual->depth,
                                InputOutput, visual->visual, CWColormap, &window_attributes);
  XStoreName(dpy, window, argv[0]);
  XMapWindow(dpy, window);
  XSync(dpy, False);
  GLXContext context = glXCreateContext(dpy, visual, NULL, True);
  if (!context || !glXMakeCurrent(dpy, window, context)) {
    fprintf(stderr, "label_harness: cannot create or bind a GLX context\n");
    exit(1);
  }
  glViewport(0, 0, LBL_WIDTH, LBL_HEIGHT);
  setup();
  lbl_check_gl("after setup");
  for (int f = 0; f < frames; ++f) {
    lbl_current_frame = f;
    lbl_labels_this_frame = 0;
    frame(f);
    lbl_check_gl("after the frame's commands");
    if (dump_directory) lbl_dump_frame(dump_directory, f);
    glXSwapBuffers(dpy, window);
  }
  lbl_current_frame = -1;
  glFinish();
  lbl_check_gl("at the end");
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, context);
  XDestroyWindow(dpy, window);
  XFreeColormap(dpy, window_attributes.colormap);
  XFree(visual);
  XCloseDisplay(dpy);
  fflush(stdout);
  return 0;
}

#endif /* GLPT_TESTS_CLASSIFY_LABEL_HARNESS_H */
