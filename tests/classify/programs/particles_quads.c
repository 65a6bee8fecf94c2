/* particles_quads: two particle systems of small camera-facing textured quads, additive
 * (glBlendFunc(GL_ONE, GL_ONE)) with depth writes off, over a still world; the camera is still
 * but looks down at the scene at an angle, so the billboards are built from the camera's right
 * and up vectors (each quad's plane is parallel to the view plane, not to a world axis).
 *
 * Fire: 24 quads in one glBegin(GL_QUADS), every particle moving every frame. Sparks: a second
 * emitter whose particle count changes from frame to frame (12, 16, 20, 24, ...), always >= 8.
 * Quad size 0.24 at 9 to 13 units from the eye: about 2 % of the distance (< 5 %).
 *
 * Labels: both emitters `particles` in every frame (frame 0 included: the class does not depend
 * on history). The ground and four crates are `static` (same vertices, same modelview). The
 * sparks' key names the frame (sparks_f<F>): their vertex count changes, so they are a new
 * draw each frame as far as identity goes.
 */
#include "../label_harness.h"

static const float eye[3] = {3.0f, 6.0f, 10.0f}, center[3] = {0.0f, 1.0f, 0.0f};
static const float up[3] = {0.0f, 1.0f, 0.0f};
static GLuint blob;

static void setup(void) {
  static const GLubyte orange[3] = {255, 140, 40};
  blob = lbl_blob_texture(32, orange, 1);
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

/* One quad of half size h at p, facing the camera. */
static void billboard(const float p[3], float h, const float right[3], const float upv[3]) {
  static const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k) {
    float sx = corners[k][0] * h, sy = corners[k][1] * h;
    glTexCoord2f(0.5f + 0.5f * corners[k][0], 0.5f + 0.5f * corners[k][1]);
    glVertex3f(p[0] + sx * right[0] + sy * upv[0], p[1] + sx * right[1] + sy * upv[1],
               p[2] + sx * right[2] + sy * upv[2]);
  }
}

static void emitter(int f, int count, uint32_t seed, const float origin[3], float speed,
                    const float right[3], const float upv[3]) {
  uint32_t state = seed;
  glBegin(GL_QUADS);
  for (int i = 0; i < count; ++i) {
    float vx = (lbl_randf(&state) - 0.5f) * speed, vz = (lbl_randf(&state) - 0.5f) * speed;
    float vy = 0.8f + lbl_randf(&state) * speed;
    float age = (float)((f + i) % 6) * 0.25f + 0.1f;
    float p[3] = {origin[0] + vx * age, origin[1] + vy * age, origin[2] + vz * age};
    glColor3f(1.0f - 0.12f * age, 0.7f - 0.2f * age, 0.3f);
    billboard(p, 0.12f, right, upv);
  }
  glEnd();
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 60.0f, eye, center);
  float right[3], upv[3], forward[3];
  lbl_camera_basis(eye, center, up, right, upv, forward);

  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDisable(GL_TEXTURE_2D);
  lbl_light(0.2f, 1.0f, 0.4f);
  glColor3f(0.35f, 0.3f, 0.25f);
  label("static", "ground");
  lbl_grid(6, 8.0f);
  static const float crates[4][2] = {{-3, -2}, {3, -3}, {-4, 2}, {2.5f, 2}};
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(crates[i][0], 0.6f, crates[i][1]);
    glColor3f(0.6f, 0.45f, 0.25f);
    labelf("static", "crate%d", i, 0);
    lbl_box(0.6f, 0.6f, 0.6f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, blob);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glDepthMask(GL_FALSE);
  static const float fire[3] = {0.0f, 0.2f, 0.0f}, sparks[3] = {-1.5f, 0.5f, 1.5f};
  label("particles", "fire");
  emitter(f, 24, 12345u, fire, 0.6f, right, upv);
  /* the sparks' count changes every frame: a new topology, so no identity is asked of them
   * across frames (a key of their own in every frame); their own translation keeps them from
   * merging with the fire */
  glPushMatrix();
  glTranslatef(sparks[0], sparks[1], sparks[2]);
  labelf("particles", "sparks_f%d", f, 0);
  static const float here[3] = {0.0f, 0.0f, 0.0f};
  emitter(f, 12 + 4 * (f % 4), 777u, here, 2.0f, right, upv);
  glPopMatrix();
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
