// Fog (GL 1.5 3.10): LINEAR, EXP and EXP2 with the eye distance, and the fog coordinate source.
#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// A row of lit cubes receding into grey fog over a floor.
void fog_scene(GLenum mode) {
  clear(0.6f, 0.6f, 0.65f);
  perspective(45.0, 2.0, 1.0, 40.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, static_cast<GLint>(mode));
  fog_colour(0.6f, 0.6f, 0.65f);
  glFogf(GL_FOG_START, 3);
  glFogf(GL_FOG_END, 18);
  glFogf(GL_FOG_DENSITY, mode == GL_EXP ? 0.12f : 0.09f);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, -1, 2, 1, 0);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(0.2f, 0.5f, 0.2f);
  glBegin(GL_QUADS);
  glNormal3f(0, 1, 0);
  glVertex3f(-8, -1, -1);
  glVertex3f(8, -1, -1);
  glVertex3f(8, -1, -30);
  glVertex3f(-8, -1, -30);
  glEnd();
  for (int i = 0; i < 6; ++i) {
    glPushMatrix();
    glTranslatef(-2.5f + 1.2f * i, 0, -3.0f - 3.0f * i);
    glRotatef(30, 0, 1, 0);
    glColor3f(0.9f, 0.3f + 0.1f * i, 0.2f);
    cube(0.6f);
    glPopMatrix();
  }
}

GLPT_SCENE(fog_linear, 128, 64) { fog_scene(GL_LINEAR); }
GLPT_SCENE(fog_exp, 128, 64) { fog_scene(GL_EXP); }
GLPT_SCENE(fog_exp2, 128, 64) { fog_scene(GL_EXP2); }

// GL_FOG_COORDINATE_SOURCE = GL_FOG_COORDINATE: the fog distance is the per-vertex fog
// coordinate, not the eye depth. A flat quad facing the viewer fogs from left to right and
// a second one from top to bottom.
GLPT_SCENE(fog_coordinate_source, 64, 64) {
  clear(0.2f, 0.2f, 0.3f);
  ortho_pixels(64, 64);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0);
  glFogf(GL_FOG_END, 10);
  fog_colour(1.0f, 0.9f, 0.7f);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glColor3f(0.1f, 0.3f, 0.8f);
  glBegin(GL_QUADS);
  glFogCoordf(0);
  glVertex2f(4, 34);
  glFogCoordf(10);
  glVertex2f(60, 34);
  glFogCoordf(10);
  glVertex2f(60, 60);
  glFogCoordf(0);
  glVertex2f(4, 60);
  glFogCoordf(2);
  glVertex2f(4, 4);
  glFogCoordf(2);
  glVertex2f(60, 4);
  glFogCoordf(8);
  glVertex2f(60, 30);
  glFogCoordf(12);  // beyond the end: fully fogged
  glVertex2f(4, 30);
  glEnd();
}

// Fog applies after texturing and the secondary colour: textured, lit spheres receding.
GLPT_SCENE(fog_after_texture, 128, 64) {
  clear(0.5f, 0.55f, 0.6f);
  perspective(40.0, 2.0, 1.0, 40.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 0.1f);
  fog_colour(0.5f, 0.55f, 0.6f);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, -1, 1, 1, 0);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  material4(GL_FRONT, GL_SPECULAR, 1, 1, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGB, 8, 8, checker(8, 8, 2, Rgba8{255, 220, 120, 255}, Rgba8{120, 40, 40, 255}));
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-2.4f + 1.9f * i, 0, -4.0f - 3.5f * i);
    sphere(0.9f, 24, 12);
    glPopMatrix();
  }
}

// Defect: the colour sum was clamped to 1 before fog. Mesa fogs the unclamped sum of a bright
// texture and a strong specular highlight (GL 1.5 3.9 clamps it; Mesa's fixed-function fragment
// program does not), so highlights on saturated texels stay brighter through the fog.
GLPT_SCENE(fog_unclamped_color_sum, 128, 64) {
  clear(0.3f, 0.35f, 0.4f);
  perspective(40.0, 2.0, 1.0, 40.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 0.2f);
  fog_colour(0.3f, 0.35f, 0.4f);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, -1, 1, 2, 0);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  material4(GL_FRONT, GL_SPECULAR, 1, 1, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 8);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGB, 8, 8, checker(8, 8, 2, Rgba8{255, 40, 20, 255}, Rgba8{250, 250, 250, 255}));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-2.0f + 2.0f * i, 0, -4.0f - 1.5f * i);
    sphere(0.9f, 24, 12);
    glPopMatrix();
  }
}

}  // namespace
