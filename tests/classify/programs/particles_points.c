/* particles_points: falling snow as blended GL_POINTS (SRC_ALPHA, ONE_MINUS_SRC_ALPHA, depth
 * writes off, point size 3) and fireflies as additive GL_POINTS (ONE, ONE, point size 2), over a
 * still world, still camera. This is the one program that uses points: blended GL_POINTS
 * (>= 8 of them) are particles.
 *
 * Labels: snow (60 points) and fireflies (16 points) `particles` in every frame; the ground and
 * the four houses are `static`.
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.15f, 0.15f, 0.25f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {0.0f, 3.0f, 10.0f}, center[3] = {0.0f, 1.5f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 60.0f, eye, center);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  lbl_light(0.3f, 1.0f, 0.6f);
  glColor3f(0.85f, 0.85f, 0.9f);
  label("static", "ground");
  lbl_grid(6, 10.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-4.5f + 3.0f * (float)i, 1.0f, -3.0f - (float)(i % 2));
    glColor3f(0.6f, 0.25f + 0.1f * (float)i, 0.2f);
    labelf("static", "house%d", i, 0);
    lbl_box(1.0f, 1.0f, 1.0f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  glEnable(GL_BLEND);
  glDepthMask(GL_FALSE);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glPointSize(3.0f);
  uint32_t state = 99u;
  label("particles", "snow");
  glBegin(GL_POINTS);
  for (int i = 0; i < 60; ++i) {
    float x = (lbl_randf(&state) - 0.5f) * 14.0f, z = (lbl_randf(&state) - 0.5f) * 8.0f;
    float y0 = lbl_randf(&state) * 6.0f;
    float y = fmodf(y0 + 6.0f - 0.45f * (float)f, 6.0f);
    glColor4f(1.0f, 1.0f, 1.0f, 0.8f);
    glVertex3f(x + 0.2f * sinf((float)f + (float)i), y, z);
  }
  glEnd();

  glBlendFunc(GL_ONE, GL_ONE);
  glPointSize(2.0f);
  label("particles", "fireflies");
  glBegin(GL_POINTS);
  for (int i = 0; i < 16; ++i) {
    float a = 0.7f * (float)f + 0.4f * (float)i;
    glColor3f(0.6f, 0.9f, 0.2f);
    glVertex3f(3.0f * cosf(a), 1.0f + 0.5f * sinf(1.7f * a), 2.0f + 1.5f * sinf(a));
  }
  glEnd();
  glPointSize(1.0f);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
