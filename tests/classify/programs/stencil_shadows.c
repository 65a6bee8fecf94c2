/* stencil_shadows: Doom 3-style stencil shadow volumes (z-pass). After the lit world, the side
 * quads of two occluders' shadow volumes (their silhouette edges seen from a moving point light,
 * extruded away from it) are drawn twice with glColorMask all GL_FALSE, glDepthMask(GL_FALSE),
 * the stencil test on: front faces with glStencilOp(KEEP, KEEP, GL_INCR), back faces with
 * GL_DECR (face culling picks which). Then a black, half transparent full-window quad under
 * glOrtho, depth test off, with glStencilFunc(GL_NOTEQUAL, 0, ~0) darkens the shadowed pixels.
 * Still camera.
 *
 * Labels: floor, back wall, crate and pillar `static`; both volume passes and the darkening pass
 * `shadow` (the darkening quad is 2-D, but it is the last pass of the stencil shadow, not an
 * overlay).
 */
#include "../label_harness.h"

typedef struct {
  float c[3], h[3];
} Box;
static const Box occluders[2] = {{{-1.0f, 0.75f, 0.5f}, {0.75f, 0.75f, 0.75f}},
                                 {{1.8f, 1.25f, -0.5f}, {0.3f, 1.25f, 0.3f}}};
static float light[3];

/* The box's faces as corner indices (corner bit 0: +x, bit 1: +y, bit 2: +z), counter-clockwise
 * seen from outside, and their outward normals. */
static const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
static const float normals[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};

static void corner(const Box* b, int k, float out[3]) {
  for (int a = 0; a < 3; ++a) out[a] = b->c[a] + ((k >> a) & 1 ? b->h[a] : -b->h[a]);
}

static int faces_light(const Box* b, int face) {
  float p[3];
  corner(b, faces[face][0], p);
  float d = 0.0f;
  for (int a = 0; a < 3; ++a) d += normals[face][a] * (light[a] - p[a]);
  return d > 0.0f;
}

/* The side quads of every occluder's volume, in one glBegin(GL_QUADS). */
static void shadow_volumes(void) {
  glBegin(GL_QUADS);
  for (int o = 0; o < 2; ++o) {
    const Box* b = &occluders[o];
    for (int face = 0; face < 6; ++face) {
      if (!faces_light(b, face)) continue;
      for (int e = 0; e < 4; ++e) {
        int k0 = faces[face][e], k1 = faces[face][(e + 1) % 4];
        /* the neighbour across edge (k0, k1) has it as (k1, k0) */
        int neighbour = -1;
        for (int g = 0; g < 6 && neighbour < 0; ++g) {
          for (int h = 0; h < 4; ++h) {
            if (faces[g][h] == k1 && faces[g][(h + 1) % 4] == k0) neighbour = g;
          }
        }
        if (neighbour < 0 || faces_light(b, neighbour)) continue;
        float v0[3], v1[3], e0[3], e1[3];
        corner(b, k0, v0);
        corner(b, k1, v1);
        for (int a = 0; a < 3; ++a) {
          e0[a] = v0[a] + (v0[a] - light[a]) * 20.0f;
          e1[a] = v1[a] + (v1[a] - light[a]) * 20.0f;
        }
        glVertex3fv(v1);
        glVertex3fv(v0);
        glVertex3fv(e0);
        glVertex3fv(e1);
      }
    }
  }
  glEnd();
}

static void setup(void) {
  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glClearStencil(0);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  light[0] = -2.0f + 0.8f * (float)f;
  light[1] = 5.0f;
  light[2] = 2.0f;
  const float eye[3] = {1.0f, 4.5f, 8.0f}, center[3] = {0.0f, 0.5f, -1.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 100.0f, eye, center);
  const GLfloat position[4] = {light[0], light[1], light[2], 1.0f};
  lbl_light(0.0f, 1.0f, 0.0f);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glDepthFunc(GL_LESS);
  glColor3f(0.7f, 0.7f, 0.65f);
  label("static", "floor");
  lbl_grid(8, 6.0f);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  glColor3f(0.6f, 0.65f, 0.75f);
  label("static", "back_wall");
  lbl_grid(4, 6.0f);
  glPopMatrix();
  static const char* const names[2] = {"crate", "pillar"};
  for (int o = 0; o < 2; ++o) {
    glPushMatrix();
    glTranslatef(occluders[o].c[0], occluders[o].c[1], occluders[o].c[2]);
    glColor3f(0.75f, 0.5f, 0.25f + 0.3f * (float)o);
    label("static", names[o]);
    lbl_box(occluders[o].h[0], occluders[o].h[1], occluders[o].h[2]);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, ~0u);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  label("shadow", "volume_front");
  shadow_volumes();
  glCullFace(GL_FRONT);
  glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
  label("shadow", "volume_back");
  shadow_volumes();
  glDisable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  glStencilFunc(GL_NOTEQUAL, 0, ~0u);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
  label("shadow", "darken");
  lbl_quad_2d(0.0f, 0.0f, (float)LBL_WIDTH, (float)LBL_HEIGHT);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
