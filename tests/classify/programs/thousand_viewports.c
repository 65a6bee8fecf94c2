/* thousand_viewports: bad input for classification and identity - 1,000 glViewport calls per
 * frame, a 40 x 25 grid of 4 x 4-pixel viewports (the window is 160 x 120: the last rows are
 * cut), each with its own perspective view of one lit box turning with the frame under a still
 * camera, then a 2-D status bar under glOrtho over the whole window.
 *
 * Labels: every box `moving` from frame 1 on (a lone object turning before a still camera: in
 * its own view nothing stands still to share the camera's motion with), `static` in frame 0 (new
 * draws); the bar `overlay`. Every box keeps its key (and must keep its id) over the frames.
 * glpt must neither crash nor grow: identities and camera motions are per view, and a view is
 * one of a thousand here.
 */
#include "../label_harness.h"

enum { COLUMNS = 40, ROWS = 25, CELL = 4 };

static void setup(void) {
  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glViewport(0, 0, LBL_WIDTH, LBL_HEIGHT);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (int row = 0; row < ROWS; ++row) {
    for (int column = 0; column < COLUMNS; ++column) {
      glViewport(column * CELL, row * CELL, CELL, CELL);
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      lbl_perspective(50.0f, 1.0f, 0.5f, 20.0f);
      glMatrixMode(GL_MODELVIEW);
      glLoadIdentity();
      lbl_light(0.3f, 1.0f, 0.6f);
      glTranslatef(0.0f, 0.0f, -4.0f);
      glRotatef(20.0f * (float)f + (float)(row * COLUMNS + column), 0.3f, 1.0f, 0.0f);
      glColor3f(0.3f + 0.01f * (float)column, 0.5f, 0.3f + 0.02f * (float)row);
      if (f == 0)
        labelf("static", "box_%d_%d", row, column);
      else
        labelf("moving", "box_%d_%d", row, column);
      lbl_box(0.8f, 0.8f, 0.8f);
      glDisable(GL_LIGHTING);
    }
  }
  glViewport(0, 0, LBL_WIDTH, LBL_HEIGHT);
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glColor3f(0.9f, 0.9f, 0.9f);
  label("overlay", "status_bar");
  glRectf(0.0f, 108.0f, 160.0f, 120.0f);
  glEnable(GL_DEPTH_TEST);
}

int main(int argc, char** argv) { return label_run(argc, argv, 4, setup, frame); }
