/* gearsdet: a deterministic glxgears for comparing renderers.
 *
 * Draws glxgears' three gears (same geometry, display lists, lighting and projection) at fixed
 * angles, so every run issues the same GL calls. Draws the same frame --frames times with
 * glXSwapBuffers in between; on the last frame it reads the back buffer with glReadPixels
 * before swapping and writes it to --out as an upright RGBA PNG.
 *
 * --mode shaded   glxgears' lighting: GL_LIGHT0 with GL defaults, light-model ambient 0.2, red,
 *                 green and blue materials, GL_FLAT faces and a GL_SMOOTH inner cylinder.
 * --mode facing   an oracle for "which faces turn toward the light": white material, light
 *                 diffuse 1, no specular, no ambient anywhere and GL_FLAT everywhere, so a pixel's
 *                 brightness is max(0, N.L) of its face: black iff the face turns away.
 *
 * The gear geometry is glxgears' (Brian Paul, public domain / MIT in Mesa demos).
 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glxgears_gear.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* The clear colour: a dark purple that none of the gear materials can produce (every gear colour
 * differs from it by at least 54 in some channel in Mesa's rendering), so "differs from the
 * background" means "geometry". In 8 bits it reads back as (64, 0, 64). */
static const GLfloat kClear[4] = {0.25f, 0.0f, 0.25f, 1.0f};

struct options {
  int width, height;
  int frames;
  int facing;
  const char* out;
  float angle;
  float light[3];
};

static void usage(FILE* f) {
  fprintf(f,
          "usage: gearsdet [--size WxH] [--frames N] [--mode shaded|facing] [--out FILE.png]\n"
          "                [--angle DEG] [--light X,Y,Z]\n"
          "  --size WxH      window size (default 400x400)\n"
          "  --frames N      draw the same frame N times, swapping in between (default 1)\n"
          "  --mode M        shaded: glxgears' lighting (default); facing: N.L oracle\n"
          "  --out FILE      write the last frame, read with glReadPixels before its swap\n"
          "  --angle DEG     gear rotation (default 12)\n"
          "  --light X,Y,Z   direction towards GL_LIGHT0, eye space (default 5,5,10)\n");
}

static int parse_args(int argc, char** argv, struct options* o) {
  o->width = 400;
  o->height = 400;
  o->frames = 1;
  o->facing = 0;
  o->out = NULL;
  o->angle = 12.0f;
  o->light[0] = 5.0f;
  o->light[1] = 5.0f;
  o->light[2] = 10.0f;
  /* Each option takes a value: two arguments per step. */
  for (int i = 1; i < argc; i += 2) {
    const char* a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : NULL;
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
      usage(stdout);
      exit(0);
    }
    if (!v) {
      fprintf(stderr, "gearsdet: %s needs a value (or is unknown)\n", a);
      return 0;
    }
    char end = 0;
    if (strcmp(a, "--size") == 0) {
      if (sscanf(v, "%dx%d%c", &o->width, &o->height, &end) != 2 || o->width <= 0 ||
          o->height <= 0 || o->width > 8192 || o->height > 8192) {
        fprintf(stderr, "gearsdet: bad --size '%s' (want WxH)\n", v);
        return 0;
      }
    } else if (strcmp(a, "--frames") == 0) {
      if (sscanf(v, "%d%c", &o->frames, &end) != 1 || o->frames < 1) {
        fprintf(stderr, "gearsdet: bad --frames '%s' (want N >= 1)\n", v);
        return 0;
      }
    } else if (strcmp(a, "--mode") == 0) {
      if (strcmp(v, "shaded") == 0) {
        o->facing = 0;
      } else if (strcmp(v, "facing") == 0) {
        o->facing = 1;
      } else {
        fprintf(stderr, "gearsdet: bad --mode '%s' (want shaded or facing)\n", v);
        return 0;
      }
    } else if (strcmp(a, "--out") == 0) {
      o->out = v;
    } else if (strcmp(a, "--angle") == 0) {
      if (sscanf(v, "%f%c", &o->angle, &end) != 1) {
        fprintf(stderr, "gearsdet: bad --angle '%s'\n", v);
        return 0;
      }
    } else if (strcmp(a, "--light") == 0) {
      if (sscanf(v, "%f,%f,%f%c", &o->light[0], &o->light[1], &o->light[2], &end) != 3) {
        fprintf(stderr, "gearsdet: bad --light '%s' (want X,Y,Z)\n", v);
        return 0;
      }
    } else {
      fprintf(stderr, "gearsdet: unknown option '%s'\n", a);
      return 0;
    }
  }
  return 1;
}

static void init_scene(const struct options* o, GLuint gears[3]) {
  static const GLfloat red[4] = {0.8f, 0.1f, 0.0f, 1.0f};
  static const GLfloat green[4] = {0.0f, 0.8f, 0.2f, 1.0f};
  static const GLfloat blue[4] = {0.2f, 0.2f, 1.0f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  const GLfloat pos[4] = {o->light[0], o->light[1], o->light[2], 0.0f};
  const GLfloat h = (GLfloat)o->height / (GLfloat)o->width;

  glViewport(0, 0, o->width, o->height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -h, h, 5.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* Identity modelview: the light direction is given in eye space, as in glxgears. */
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  if (o->facing) {
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, black);
    glLightfv(GL_LIGHT0, GL_AMBIENT, black);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
  }
  glEnable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  glClearColor(kClear[0], kClear[1], kClear[2], kClear[3]);

  const GLfloat* colors[3] = {red, green, blue};
  static const GLfloat params[3][5] = {
      /* inner radius, outer radius, width, teeth, tooth depth */
      {1.0f, 4.0f, 1.0f, 20.0f, 0.7f},
      {0.5f, 2.0f, 2.0f, 10.0f, 0.7f},
      {1.3f, 2.0f, 0.5f, 10.0f, 0.7f},
  };
  for (int g = 0; g < 3; ++g) {
    gears[g] = glGenLists(1);
    glNewList(gears[g], GL_COMPILE);
    if (o->facing) {
      glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);
      glMaterialfv(GL_FRONT, GL_SPECULAR, black);
      glMaterialfv(GL_FRONT, GL_EMISSION, black);
    } else {
      glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colors[g]);
    }
    glxgears_gear(params[g][0], params[g][1], params[g][2], (GLint)params[g][3], params[g][4],
                  o->facing);
    glEndList();
  }

  glTranslatef(0.0f, 0.0f, -40.0f);
}

static void draw(const struct options* o, const GLuint gears[3]) {
  static const GLfloat view_rotx = 20.0f, view_roty = 30.0f, view_rotz = 0.0f;
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glPushMatrix();
  glRotatef(view_rotx, 1.0f, 0.0f, 0.0f);
  glRotatef(view_roty, 0.0f, 1.0f, 0.0f);
  glRotatef(view_rotz, 0.0f, 0.0f, 1.0f);

  glPushMatrix();
  glTranslatef(-3.0f, -2.0f, 0.0f);
  glRotatef(o->angle, 0.0f, 0.0f, 1.0f);
  glCallList(gears[0]);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(3.1f, -2.0f, 0.0f);
  glRotatef(-2.0f * o->angle - 9.0f, 0.0f, 0.0f, 1.0f);
  glCallList(gears[1]);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-3.1f, 4.2f, 0.0f);
  glRotatef(-2.0f * o->angle - 25.0f, 0.0f, 0.0f, 1.0f);
  glCallList(gears[2]);
  glPopMatrix();

  glPopMatrix();
}

/* Reads the back buffer and writes it as an upright RGBA PNG. */
static int write_frame(const struct options* o) {
  const size_t stride = (size_t)o->width * 4;
  unsigned char* pixels = malloc(stride * (size_t)o->height);
  if (!pixels) {
    fprintf(stderr, "gearsdet: out of memory\n");
    return 0;
  }
  glFinish();
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, o->width, o->height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR) {
    fprintf(stderr, "gearsdet: glReadPixels failed: GL error 0x%x\n", err);
    free(pixels);
    return 0;
  }
  png_image image;
  memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = (png_uint_32)o->width;
  image.height = (png_uint_32)o->height;
  image.format = PNG_FORMAT_RGBA;
  /* glReadPixels returns the bottom row first; a negative stride tells libpng so. */
  const int ok = png_image_write_to_file(&image, o->out, 0, pixels, -(png_int_32)stride, NULL);
  if (!ok) fprintf(stderr, "gearsdet: writing %s failed: %s\n", o->out, image.message);
  free(pixels);
  return ok;
}

int main(int argc, char** argv) {
  struct options o;
  if (!parse_args(argc, argv, &o)) {
    usage(stderr);
    return 2;
  }

  Display* dpy = XOpenDisplay(NULL);
  if (!dpy) {
    fprintf(stderr, "gearsdet: cannot open display '%s'\n", XDisplayName(NULL));
    return 1;
  }
  /* clang-format off */
  int attribs[] = {GLX_RGBA,
                   GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1,
                   GLX_DOUBLEBUFFER,
                   GLX_DEPTH_SIZE, 16,
                   None};
  /* clang-format on */
  const int scrnum = DefaultScreen(dpy);
  const Window root = RootWindow(dpy, scrnum);
  XVisualInfo* visinfo = glXChooseVisual(dpy, scrnum, attribs);
  if (!visinfo) {
    fprintf(stderr, "gearsdet: no RGBA, double-buffered visual with a depth buffer\n");
    XCloseDisplay(dpy);
    return 1;
  }

  XSetWindowAttributes attr;
  memset(&attr, 0, sizeof attr);
  attr.background_pixel = 0;
  attr.border_pixel = 0;
  attr.colormap = XCreateColormap(dpy, root, visinfo->visual, AllocNone);
  attr.event_mask = StructureNotifyMask | ExposureMask;
  const unsigned long mask = CWBackPixel | CWBorderPixel | CWColormap | CWEventMask;
  Window win = XCreateWindow(dpy, root, 0, 0, (unsigned)o.width, (unsigned)o.height, 0,
                             visinfo->depth, InputOutput, visinfo->visual, mask, &attr);
  XSizeHints hints;
  memset(&hints, 0, sizeof hints);
  hints.flags = USSize | PMinSize | PMaxSize;
  hints.width = hints.min_width = hints.max_width = o.width;
  hints.height = hints.min_height = hints.max_height = o.height;
  XSetStandardProperties(dpy, win, "gearsdet", "gearsdet", None, NULL, 0, &hints);

  GLXContext ctx = glXCreateContext(dpy, visinfo, NULL, True);
  if (!ctx) {
    fprintf(stderr, "gearsdet: glXCreateContext failed\n");
    XDestroyWindow(dpy, win);
    XFreeColormap(dpy, attr.colormap);
    XFree(visinfo);
    XCloseDisplay(dpy);
    return 1;
  }
  XMapWindow(dpy, win);
  for (;;) { /* wait until the window is mapped */
    XEvent ev;
    XNextEvent(dpy, &ev);
    if (ev.type == MapNotify && ev.xmap.window == win) break;
  }

  int status = 0;
  if (!glXMakeCurrent(dpy, win, ctx)) {
    fprintf(stderr, "gearsdet: glXMakeCurrent failed\n");
    status = 1;
  } else {
    GLuint gears[3];
    init_scene(&o, gears);
    for (int f = 0; f < o.frames; ++f) {
      draw(&o, gears);
      if (f == o.frames - 1 && o.out && !write_frame(&o)) status = 1;
      glXSwapBuffers(dpy, win);
    }
    for (int g = 0; g < 3; ++g) glDeleteLists(gears[g], 1);
    glXMakeCurrent(dpy, None, NULL);
  }

  glXDestroyContext(dpy, ctx);
  XDestroyWindow(dpy, win);
  XFreeColormap(dpy, attr.colormap);
  XFree(visinfo);
  XCloseDisplay(dpy);
  return status;
}
