/* statetour: an ordinary GLX program that moves nearly every piece of GL 1.x state away from its
 * default (every attribute group, client arrays and buffer objects, textures of every target,
 * texgen and texenv on two units, pixel store, transfer and maps, evaluators, clip planes, the
 * matrix and attribute stacks), draws a textured, lit, fogged scene and swaps, N frames. It
 * exists to be traced: apitrace's state dump (glretrace -D CALL) of its trace is compared between
 * real Mesa and glpt (tests/e2e/apitrace_state_test.sh). Every frame issues the same calls.
 *
 * usage: statetour [--frames N]
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kWidth = 160, kHeight = 120 };

static void checkerboard(GLubyte* texels, int size, const GLubyte a[4], const GLubyte b[4]) {
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const GLubyte* c = ((x / 2 + y / 2) & 1) ? a : b;
      memcpy(texels + 4 * (y * size + x), c, 4);
    }
  }
}

static GLuint textures[4];
static GLuint buffers[2];

/* State that stays for the whole run, set once (textures, lists, buffers, pixel maps). */
static void set_up_objects(void) {
  static const GLubyte red[4] = {255, 32, 16, 255}, blue[4] = {16, 48, 255, 128};
  static const GLubyte green[4] = {32, 220, 64, 200}, white[4] = {250, 250, 250, 255};
  GLubyte texels[8 * 8 * 4];
  glGenTextures(4, textures);

  glBindTexture(GL_TEXTURE_2D, textures[0]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  checkerboard(texels, 8, red, blue);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0.25f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -2.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 5.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 2);
  {
    static const GLfloat border[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  }

  glBindTexture(GL_TEXTURE_1D, textures[1]);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE_ALPHA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);

  glBindTexture(GL_TEXTURE_3D, textures[2]);
  checkerboard(texels, 4, green, white);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB5_A1, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);

  glBindTexture(GL_TEXTURE_CUBE_MAP, textures[3]);
  for (int face = 0; face < 6; ++face) {
    checkerboard(texels, 4, face & 1 ? red : green, face & 2 ? white : blue);
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGB8, 4, 4, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  /* A vertex buffer and an index buffer. */
  {
    static const GLfloat quad[] = {-0.8f, -0.8f, 0.0f, 0.8f, -0.8f, 0.0f,
                                   0.8f,  0.8f,  0.0f, -0.8f, 0.8f, 0.0f};
    static const GLushort indices[] = {0, 1, 2, 0, 2, 3};
    glGenBuffers(2, buffers);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_DYNAMIC_DRAW);
  }

  /* Evaluators. */
  {
    static const GLfloat curve[4][3] = {{-1, -1, 0}, {-0.5f, 1, 0}, {0.5f, -1, 0}, {1, 1, 0}};
    static const GLfloat patch[2][2][3] = {{{-1, -1, 0}, {1, -1, 0}}, {{-1, 1, 0}, {1, 1, 0}}};
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, &patch[0][0][0]);
    glMapGrid1f(7, 0.25f, 0.75f);
    glMapGrid2d(3, 0.0, 1.0, 5, 0.5, 1.0);
  }

  /* Pixel maps, transfer and zoom (take effect on pixel paths only). */
  {
    static const GLfloat ramp[4] = {0.0f, 0.3f, 0.6f, 1.0f};
    static const GLushort stencil_map[2] = {1, 0};
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, ramp);
    glPixelMapusv(GL_PIXEL_MAP_S_TO_S, 2, stencil_map);
  }

  /* A display list. */
  glNewList(5, GL_COMPILE);
  glRectf(-0.9f, -0.9f, -0.6f, -0.6f);
  glEndList();
}

/* Per-frame state: every attribute group away from its default. */
static void set_state(void) {
  static const GLfloat light_pos[4] = {1.0f, 2.0f, 3.0f, 0.0f};
  static const GLfloat spot_pos[4] = {-1.0f, 0.5f, 2.0f, 1.0f};
  static const GLfloat spot_dir[3] = {0.5f, -0.25f, -1.0f};
  static const GLfloat warm[4] = {0.9f, 0.7f, 0.5f, 1.0f};
  static const GLfloat cool[4] = {0.2f, 0.3f, 0.6f, 0.75f};
  static const GLfloat ambient[4] = {0.15f, 0.1f, 0.05f, 1.0f};
  static const GLfloat fog_color[4] = {0.3f, 0.35f, 0.4f, 1.0f};
  static const GLfloat plane_s[4] = {1.0f, 0.5f, 0.0f, 0.25f};
  static const GLfloat plane_t[4] = {0.0f, 1.0f, 0.5f, -0.25f};
  static const GLdouble clip0[4] = {1.0, 0.0, 0.0, 0.95};
  static const GLdouble clip3[4] = {0.0, -1.0, 0.25, 2.0};
  static const GLfloat env_color[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  static const GLfloat attenuation[3] = {1.0f, 0.1f, 0.01f};
  GLubyte stipple[128];
  for (int i = 0; i < 128; ++i) stipple[i] = (GLubyte)(i * 37 + 11);

  /* Transform: projection, modelview with a pushed matrix, texture matrices, normalize. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -0.75, 0.75, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glPushMatrix();
  glRotatef(20.0f, 1.0f, 0.5f, 0.0f);
  glEnable(GL_NORMALIZE);
  glEnable(GL_RESCALE_NORMAL);
  glClipPlane(GL_CLIP_PLANE0, clip0);
  glEnable(GL_CLIP_PLANE0);
  glClipPlane(GL_CLIP_PLANE3, clip3);

  /* Lighting. */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, warm);
  glEnable(GL_LIGHT3);
  glLightfv(GL_LIGHT3, GL_POSITION, spot_pos);
  glLightfv(GL_LIGHT3, GL_SPOT_DIRECTION, spot_dir);
  glLightf(GL_LIGHT3, GL_SPOT_CUTOFF, 35.0f);
  glLightf(GL_LIGHT3, GL_SPOT_EXPONENT, 4.0f);
  glLightf(GL_LIGHT3, GL_CONSTANT_ATTENUATION, attenuation[0]);
  glLightf(GL_LIGHT3, GL_LINEAR_ATTENUATION, attenuation[1]);
  glLightf(GL_LIGHT3, GL_QUADRATIC_ATTENUATION, attenuation[2]);
  glLightfv(GL_LIGHT3, GL_SPECULAR, cool);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glMaterialfv(GL_FRONT, GL_SPECULAR, warm);
  glMaterialf(GL_FRONT, GL_SHININESS, 42.0f);
  glMaterialfv(GL_BACK, GL_EMISSION, cool);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glShadeModel(GL_FLAT);

  /* Fog. */
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 0.2f);
  glFogf(GL_FOG_START, 2.0f);
  glFogf(GL_FOG_END, 9.0f);
  glFogfv(GL_FOG_COLOR, fog_color);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
  glHint(GL_FOG_HINT, GL_NICEST);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_FASTEST);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);

  /* Rasterization: points, lines, polygons. */
  glPointSize(3.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 1.5f);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 2.0f);
  {
    static const GLfloat point_attenuation[3] = {1.0f, 0.5f, 0.25f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, point_attenuation);
  }
  glLineWidth(2.0f);
  glLineStipple(3, 0xF0F0);
  glEnable(GL_LINE_STIPPLE);
  glPolygonMode(GL_BACK, GL_LINE);
  glPolygonOffset(1.5f, 2.0f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glFrontFace(GL_CW);
  glCullFace(GL_FRONT);
  glPolygonStipple(stipple);

  /* Fragment operations. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 6, kWidth - 10, kHeight - 12);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GEQUAL, 0.125f);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NOTEQUAL, 3, 0x7F);
  glStencilOp(GL_KEEP, GL_INCR_WRAP, GL_INVERT);
  glStencilMask(0xF3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthRange(0.05, 0.95);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
  glBlendEquation(GL_FUNC_ADD);
  glBlendColor(0.1f, 0.2f, 0.3f, 0.4f);
  glLogicOp(GL_XOR);
  glDisable(GL_DITHER);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  glClearColor(0.05f, 0.1f, 0.15f, 1.0f);
  glClearDepth(0.75);
  glClearStencil(5);
  glClearAccum(0.25f, -0.5f, 0.75f, 1.0f);
  glClearIndex(3.0f);

  /* Texturing: unit 0 2-D with texgen, unit 1 combine environment and a texture matrix. */
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.5f);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane_s);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_T, GL_EYE_PLANE, plane_t);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_1D, textures[1]);
  glBindTexture(GL_TEXTURE_3D, textures[2]);
  glBindTexture(GL_TEXTURE_CUBE_MAP, textures[3]);
  glEnable(GL_TEXTURE_1D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_ADD_SIGNED);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glScalef(2.0f, 0.5f, 1.0f);
  glMatrixMode(GL_MODELVIEW);

  /* Pixel store, transfer and zoom. */
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 12);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.125f);
  glPixelTransferi(GL_INDEX_SHIFT, 2);
  glPixelZoom(1.5f, -2.0f);

  /* Evaluator enables and auto normals. */
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glListBase(4);

  /* Current attributes. */
  glSecondaryColor3f(0.2f, 0.4f, 0.6f);
  glFogCoordf(1.25f);
  glMultiTexCoord4f(GL_TEXTURE1, 0.5f, 0.25f, 0.125f, 2.0f);
  glEdgeFlag(GL_FALSE);
  glIndexi(7);
  glNormal3f(0.0f, 0.6f, 0.8f);
  glRasterPos3f(0.1f, -0.2f, 0.3f);
}

static void draw_frame(void) {
  /* The whole buffer is cleared: what a swap leaves in the back and ancillary buffers is
     undefined (Mesa discards depth and stencil on swap). */
  glDisable(GL_SCISSOR_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  set_state();
  /* Client arrays: positions from the buffer object, colours and normals from client memory. */
  {
    static const GLubyte colors[] = {255, 0, 0, 255, 0, 255, 0, 200, 0, 0, 255, 150, 255, 255, 0, 100};
    static const GLfloat normals[] = {0, 0, 1, 0.3f, 0, 1, 0, 0.3f, 1, -0.3f, -0.3f, 1};
    glClientActiveTexture(GL_TEXTURE1);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glVertexPointer(3, GL_FLOAT, 0, (const void*)0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glNormalPointer(GL_FLOAT, 0, normals);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (const void*)0);
    glDisableClientState(GL_NORMAL_ARRAY);
    /* The current values of enabled arrays are indeterminate after a draw (GL 1.5 2.8). */
    glNormal3f(0.1f, 0.2f, 0.9f);
    glColor4f(0.7f, 0.6f, 0.5f, 0.9f);
  }
  glCallList(5);
  glEvalMesh2(GL_FILL, 0, 3, 0, 5);
  glPopMatrix();
  glPushMatrix();
  glPushAttrib(GL_LIGHTING_BIT | GL_FOG_BIT);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glFlush();
  /* Undo the stacks before the swap so every frame starts alike. */
  glPopClientAttrib();
  glPopAttrib();
  glPopMatrix();
}

int main(int argc, char** argv) {
  int frames = 2;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      frames = atoi(argv[++i]);
    } else {
      fprintf(stderr, "usage: statetour [--frames N]\n");
      return 2;
    }
  }
  Display* dpy = XOpenDisplay(NULL);
  if (!dpy) {
    fprintf(stderr, "statetour: cannot open display\n");
    return 1;
  }
  int attributes[] = {GLX_RGBA,       GLX_DOUBLEBUFFER, GLX_RED_SIZE,     8, GLX_GREEN_SIZE, 8,
                      GLX_BLUE_SIZE,  8,                GLX_DEPTH_SIZE,   24, GLX_STENCIL_SIZE, 8,
                      None};
  XVisualInfo* visual = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
  if (!visual) {
    fprintf(stderr, "statetour: no visual\n");
    return 1;
  }
  Window root = RootWindow(dpy, visual->screen);
  XSetWindowAttributes window_attributes = {0};
  window_attributes.colormap = XCreateColormap(dpy, root, visual->visual, AllocNone);
  Window window = XCreateWindow(dpy, root, 0, 0, kWidth, kHeight, 0, visual->depth, InputOutput,
                                visual->visual, CWColormap, &window_attributes);
  XMapWindow(dpy, window);
  XSync(dpy, False);
  GLXContext context = glXCreateContext(dpy, visual, NULL, True);
  glXMakeCurrent(dpy, window, context);
  glViewport(0, 0, kWidth, kHeight);
  set_up_objects();
  for (int frame = 0; frame < frames; ++frame) {
    draw_frame();
    glXSwapBuffers(dpy, window);
  }
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, context);
  XDestroyWindow(dpy, window);
  XFree(visual);
  XCloseDisplay(dpy);
  return 0;
}
