// Per-vertex lighting (GL 1.5 2.14.1): each light alone, viewer models, spot lights,
// attenuation, two-sided lighting, colour material, separate specular, normal rescaling,
// emission, global ambient, shininess, light positions under other modelviews, and the defects
// glpt had (colour material after disable, lights changing within a frame, odd projections).
#include <cmath>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// A perspective view for spheres of radius ~1 at z = -4 on a dark blue background, depth test
// and lighting on; with `light0`, GL_LIGHT0 shines from the upper left.
void begin_lit_view(int width, int height, bool light0 = false) {
  clear(0.1f, 0.1f, 0.25f);
  const double aspect = static_cast<double>(width) / height;
  if (light0) {
    lit_perspective_light0(35.0, aspect);
  } else {
    lit_perspective(35.0, aspect);
  }
}

void sphere_at(float x, float y, float z, float radius) {
  glPushMatrix();
  glTranslatef(x, y, z);
  sphere(radius, 32, 16);
  glPopMatrix();
}

// A cylinder around the y axis without caps, outward normals: seen from above its inside shows
// back faces.
void open_cylinder(float radius, float height, int slices, bool rainbow) {
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= slices; ++i) {
    const double a = 2 * kPi * i / slices;
    const float x = static_cast<float>(std::cos(a)), z = static_cast<float>(std::sin(a));
    if (rainbow) {
      glColor3f(0.5f + 0.5f * x, 0.5f + 0.5f * z, 0.5f - 0.5f * x);
    }
    glNormal3f(x, 0, z);
    // Bottom vertex first: counter-clockwise quads seen from outside (front faces).
    glVertex3f(radius * x, -height / 2, radius * z);
    glVertex3f(radius * x, height / 2, radius * z);
  }
  glEnd();
}

// An open cylinder tilted towards the viewer so that both its outside (front faces) and its
// inside (back faces) are visible.
void draw_tilted_cylinder(bool rainbow) {
  glPushMatrix();
  glTranslatef(0, -0.2f, -4.5f);
  glRotatef(40, 1, 0, 0);
  glRotatef(20, 0, 1, 0);
  open_cylinder(1.0f, 1.6f, 40, rainbow);
  glPopMatrix();
}

// Light `index` alone, in its own colour and direction; even lights directional, odd positional.
void light_alone(int index) {
  begin_lit_view(64, 64);
  static const float kColours[8][3] = {{1, 1, 1},       {1, 0.3f, 0.3f}, {0.3f, 1, 0.3f},
                                       {0.3f, 0.3f, 1}, {1, 1, 0.3f},    {1, 0.3f, 1},
                                       {0.3f, 1, 1},    {1, 0.6f, 0.2f}};
  const GLenum light = static_cast<GLenum>(GL_LIGHT0 + index);
  const double a = index * kPi / 4;
  const float x = static_cast<float>(2 * std::cos(a)), y = static_cast<float>(2 * std::sin(a));
  if (index % 2 == 0) {
    light4(light, GL_POSITION, x, y, 2.0f, 0.0f);
  } else {
    light4(light, GL_POSITION, x, y, -2.0f, 1.0f);
  }
  light4(light, GL_AMBIENT, 0.1f, 0.1f, 0.1f, 1);
  light4(light, GL_DIFFUSE, kColours[index][0], kColours[index][1], kColours[index][2], 1);
  light4(light, GL_SPECULAR, 1, 1, 1, 1);
  glEnable(light);
  material4(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f);
  glMaterialf(GL_FRONT, GL_SHININESS, 30);
  sphere_at(0, 0, -4, 1);
}

GLPT_SCENE(lighting_light0_alone, 64, 64) { light_alone(0); }
GLPT_SCENE(lighting_light1_alone, 64, 64) { light_alone(1); }
GLPT_SCENE(lighting_light2_alone, 64, 64) { light_alone(2); }
GLPT_SCENE(lighting_light3_alone, 64, 64) { light_alone(3); }
GLPT_SCENE(lighting_light4_alone, 64, 64) { light_alone(4); }
GLPT_SCENE(lighting_light5_alone, 64, 64) { light_alone(5); }
GLPT_SCENE(lighting_light6_alone, 64, 64) { light_alone(6); }
GLPT_SCENE(lighting_light7_alone, 64, 64) { light_alone(7); }

// A plane facing the viewer, lit by a positional light close to it: with an infinite viewer the
// highlight sits where the half vector of the light direction and (0,0,1) meets the normal
// (under the light); with a local viewer the eye direction varies across the plane and the
// highlight moves towards the centre (GL 1.5 2.14.1, v_bs).
void viewer_scene(bool local) {
  clear(0.05f, 0.05f, 0.05f);
  perspective(70.0, 1.0, 0.5, 20.0);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, 1.2f, 0.9f, -1.8f, 1.0f);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local ? GL_TRUE : GL_FALSE);
  material4(GL_FRONT, GL_DIFFUSE, 0.2f, 0.2f, 0.4f);
  material4(GL_FRONT, GL_SPECULAR, 1, 1, 0.8f);
  glMaterialf(GL_FRONT, GL_SHININESS, 30);
  glTranslatef(0, 0, -2.5f);
  grid(-2, -2, 2, 2, 40);
}

GLPT_SCENE(lighting_local_viewer, 64, 64) { viewer_scene(true); }
GLPT_SCENE(lighting_infinite_viewer, 64, 64) { viewer_scene(false); }

// A spot light shining obliquely on a finely tessellated plane.
void spot_scene(float cutoff, float exponent) {
  clear(0, 0, 0);
  perspective(50.0, 1.0, 0.5, 20.0);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, -1.0f, 1.0f, -1.5f, 1.0f);
  light4(GL_LIGHT0, GL_DIFFUSE, 1, 0.9f, 0.6f, 1);
  const float direction[3] = {1.2f, -1.2f, -1.5f};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
  glEnable(GL_LIGHT0);
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0.1f, 0.1f, 0.15f);
  glTranslatef(0, 0, -3);
  grid(-2, -2, 2, 2, 48);
}

GLPT_SCENE(lighting_spot_cutoff, 64, 64) { spot_scene(25, 0); }
GLPT_SCENE(lighting_spot_exponent, 64, 64) { spot_scene(60, 12); }

// Spot parameters of directional lights (piglit infinite-spot-light): GL 1.5 2.14.1 and Mesa
// weigh a directional light by its spot factor too, with the light's direction as VP. Light 0
// is inside its cone (spot cosine 0.8, exponent 2: factor 0.64); light 1, red, is outside its
// cone, so neither its ambient nor its diffuse term shows.
GLPT_SCENE(lighting_spot_directional, 64, 64) {
  clear(0, 0, 0);
  perspective(50.0, 1.0, 0.5, 20.0);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, 0, 0, 1, 0);
  light4(GL_LIGHT0, GL_AMBIENT, 0.2f, 0.2f, 0.2f, 1);
  const float inside[3] = {0.6f, 0, -0.8f};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, inside);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT1, GL_POSITION, 1, 1, 1, 0);
  light4(GL_LIGHT1, GL_AMBIENT, 0.6f, 0, 0, 1);
  light4(GL_LIGHT1, GL_DIFFUSE, 1, 0, 0, 1);
  const float outside[3] = {0, 0, 1};
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, outside);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 10);
  glEnable(GL_LIGHT1);
  sphere_at(0, 0, -5, 1.5f);  // not a plane: a directional light would light it uniformly
}

// A positional light 1 unit in front of a plane, with one attenuation term.
void attenuation_scene(float constant, float linear, float quadratic) {
  clear(0, 0, 0);
  perspective(50.0, 1.0, 0.5, 20.0);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, 0.3f, 0.2f, -2.0f, 1.0f);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, constant);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, linear);
  glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, quadratic);
  glEnable(GL_LIGHT0);
  material4(GL_FRONT, GL_DIFFUSE, 1, 0.8f, 0.5f);
  glTranslatef(0, 0, -3);
  grid(-2, -2, 2, 2, 40);
}

GLPT_SCENE(lighting_attenuation_constant, 64, 64) { attenuation_scene(2.5f, 0, 0); }
GLPT_SCENE(lighting_attenuation_linear, 64, 64) { attenuation_scene(0.2f, 1.5f, 0); }
GLPT_SCENE(lighting_attenuation_quadratic, 64, 64) { attenuation_scene(0.2f, 0, 1.5f); }

// Open cylinder: orange front material outside, cyan back material inside. With two-sided
// lighting the inside is lit with the back material and reversed normals; without, the inside
// uses the front material and its normals point away from the light.
void two_sided_scene(bool two_sided) {
  begin_lit_view(64, 64, true);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two_sided ? GL_TRUE : GL_FALSE);
  material4(GL_FRONT, GL_DIFFUSE, 1, 0.5f, 0.1f);
  material4(GL_BACK, GL_DIFFUSE, 0.1f, 0.8f, 1);
  material4(GL_BACK, GL_SPECULAR, 0.8f, 0.8f, 0.8f);
  glMaterialf(GL_BACK, GL_SHININESS, 20);
  draw_tilted_cylinder(false);
}

GLPT_SCENE(lighting_two_sided, 64, 64) { two_sided_scene(true); }
GLPT_SCENE(lighting_two_sided_off, 64, 64) { two_sided_scene(false); }

// Three spheres whose glColor tracks one material property (GL 1.5 2.14.3).
void colour_material_mode_scene(GLenum mode) {
  begin_lit_view(128, 64, true);
  light4(GL_LIGHT0, GL_AMBIENT, 0.4f, 0.4f, 0.4f, 1);
  material4(GL_FRONT, GL_DIFFUSE, 0.5f, 0.5f, 0.5f);
  material4(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  glColorMaterial(GL_FRONT, mode);
  glEnable(GL_COLOR_MATERIAL);
  const float colours[3][3] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.3f, 0.3f, 1}};
  for (int i = 0; i < 3; ++i) {
    glColor3fv(colours[i]);
    sphere_at(-2.2f + 2.2f * i, 0, -6, 0.9f);
  }
}

GLPT_SCENE(lighting_colour_material_ambient, 128, 64) { colour_material_mode_scene(GL_AMBIENT); }
GLPT_SCENE(lighting_colour_material_diffuse, 128, 64) { colour_material_mode_scene(GL_DIFFUSE); }
GLPT_SCENE(lighting_colour_material_specular, 128, 64) { colour_material_mode_scene(GL_SPECULAR); }
GLPT_SCENE(lighting_colour_material_emission, 128, 64) { colour_material_mode_scene(GL_EMISSION); }
GLPT_SCENE(lighting_colour_material_ambient_and_diffuse, 128, 64) {
  colour_material_mode_scene(GL_AMBIENT_AND_DIFFUSE);
}

// Colour material applied to one face only (or both), on the two-sided open cylinder with a
// per-vertex rainbow: the other face keeps its grey material.
void colour_material_face_scene(GLenum face) {
  begin_lit_view(64, 64, true);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.6f, 0.6f, 0.6f);
  glColorMaterial(face, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  draw_tilted_cylinder(true);
}

GLPT_SCENE(lighting_colour_material_front, 64, 64) { colour_material_face_scene(GL_FRONT); }
GLPT_SCENE(lighting_colour_material_back, 64, 64) { colour_material_face_scene(GL_BACK); }
GLPT_SCENE(lighting_colour_material_front_and_back, 64, 64) {
  colour_material_face_scene(GL_FRONT_AND_BACK);
}

// A checker-textured sphere with a white highlight: with a separate specular colour the
// highlight is added after texturing and stays white on the dark squares (GL 1.5 3.9).
void specular_colour_scene(GLenum control) {
  begin_lit_view(64, 64, true);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, static_cast<GLint>(control));
  material4(GL_FRONT, GL_SPECULAR, 1, 1, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 15);
  texture_2d(GL_RGB, 16, 16,
             checker(16, 16, 2, Rgba8{255, 230, 120, 255}, Rgba8{40, 40, 160, 255}));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  sphere_at(0, 0, -4, 1.1f);
}

GLPT_SCENE(lighting_separate_specular, 64, 64) {
  specular_colour_scene(GL_SEPARATE_SPECULAR_COLOR);
}
GLPT_SCENE(lighting_single_colour_specular, 64, 64) { specular_colour_scene(GL_SINGLE_COLOR); }

// A sphere of radius 0.4 drawn under a scale: unit object normals become shorter in eye space
// (the inverse transpose scales them by 1/s). GL_NORMALIZE and GL_RESCALE_NORMAL restore unit
// length for a uniform scale; with neither the shading is dimmer and the highlight wider.
void normal_scale_scene(GLenum mode, float sx, float sy, float sz) {
  begin_lit_view(64, 64, true);
  material4(GL_FRONT, GL_SPECULAR, 0.8f, 0.8f, 0.8f);
  glMaterialf(GL_FRONT, GL_SHININESS, 25);
  if (mode != GL_NONE) glEnable(mode);
  glTranslatef(0, 0, -4);
  glScalef(sx, sy, sz);
  sphere(0.4f, 32, 16);
}

GLPT_SCENE(lighting_scaled_normals_neither, 64, 64) {
  normal_scale_scene(GL_NONE, 2.5f, 2.5f, 2.5f);
}
GLPT_SCENE(lighting_scaled_normals_normalize, 64, 64) {
  normal_scale_scene(GL_NORMALIZE, 2.5f, 2.5f, 2.5f);
}
GLPT_SCENE(lighting_scaled_normals_rescale, 64, 64) {
  normal_scale_scene(GL_RESCALE_NORMAL, 2.5f, 2.5f, 2.5f);
}
GLPT_SCENE(lighting_nonuniform_scale_normalize, 64, 64) {
  normal_scale_scene(GL_NORMALIZE, 3.2f, 1.5f, 2.5f);
}
// GL_RESCALE_NORMAL under a non-uniform scale: defined (the factor comes from the third row of
// the inverse modelview, GL 1.5 2.11.3) though not unit length.
GLPT_SCENE(lighting_nonuniform_scale_rescale, 64, 64) {
  normal_scale_scene(GL_RESCALE_NORMAL, 3.2f, 1.5f, 2.5f);
}

// Emissive spheres under a dim light: emission adds regardless of the light.
GLPT_SCENE(lighting_emission, 128, 64) {
  begin_lit_view(128, 64);
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0, 0, 0);
  light4(GL_LIGHT0, GL_POSITION, 1, 1, 1, 0);
  light4(GL_LIGHT0, GL_DIFFUSE, 0.4f, 0.4f, 0.4f, 1);
  glEnable(GL_LIGHT0);
  const float emission[3][3] = {{0.6f, 0, 0}, {0, 0.5f, 0.2f}, {0.2f, 0.2f, 0.7f}};
  for (int i = 0; i < 3; ++i) {
    material4(GL_FRONT, GL_EMISSION, emission[i][0], emission[i][1], emission[i][2]);
    sphere_at(-2.2f + 2.2f * i, 0, -6, 0.9f);
  }
}

// A strong coloured global ambient on a sphere with a bright ambient material, one dim light.
GLPT_SCENE(lighting_global_ambient, 64, 64) {
  begin_lit_view(64, 64);
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0.5f, 0.25f, 0.1f);
  material4(GL_FRONT, GL_AMBIENT, 0.9f, 0.9f, 0.9f);
  light4(GL_LIGHT0, GL_POSITION, 1, 0, 1, 0);
  light4(GL_LIGHT0, GL_DIFFUSE, 0.3f, 0.4f, 0.6f, 1);
  glEnable(GL_LIGHT0);
  sphere_at(0, 0, -4, 1.1f);
}

// Four spheres with shininess 0, 5, 30 and 128.
GLPT_SCENE(lighting_specular_exponents, 128, 64) {
  begin_lit_view(128, 64, true);
  material4(GL_FRONT, GL_DIFFUSE, 0.3f, 0.2f, 0.5f);
  material4(GL_FRONT, GL_SPECULAR, 1, 1, 1);
  const float shininess[4] = {0, 5, 30, 128};
  for (int i = 0; i < 4; ++i) {
    glMaterialf(GL_FRONT, GL_SHININESS, shininess[i]);
    sphere_at(-2.7f + 1.8f * i, 0, -7, 0.8f);
  }
}

// Light positions are transformed by the modelview current when glLight is called: light 0's
// (0,0,1,0) under a 90-degree turn about y comes from the right; light 1's origin under a
// translation sits above the sphere. The sphere is drawn under a different modelview.
GLPT_SCENE(lighting_position_under_modelview, 64, 64) {
  begin_lit_view(64, 64);
  glPushMatrix();
  glRotatef(90, 0, 1, 0);
  light4(GL_LIGHT0, GL_POSITION, 0, 0, 1, 0);
  glPopMatrix();
  light4(GL_LIGHT0, GL_DIFFUSE, 1, 0.3f, 0.3f, 1);
  glEnable(GL_LIGHT0);
  glPushMatrix();
  glTranslatef(0, 2.5f, -4);
  light4(GL_LIGHT1, GL_POSITION, 0, 0, 0, 1);
  glPopMatrix();
  light4(GL_LIGHT1, GL_DIFFUSE, 0.3f, 0.3f, 1, 1);
  glEnable(GL_LIGHT1);
  glTranslatef(0.3f, 0, 0);
  sphere_at(0, 0, -4, 1);
}

// The spot direction is transformed by the upper 3x3 of the modelview at glLight time.
GLPT_SCENE(lighting_spot_direction_under_modelview, 64, 64) {
  clear(0, 0, 0);
  perspective(50.0, 1.0, 0.5, 20.0);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, 0, 0, -1.0f, 1);
  glPushMatrix();
  glRotatef(25, 0, 1, 0);
  glRotatef(-20, 1, 0, 0);
  const float direction[3] = {0, 0, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
  glPopMatrix();
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2);
  glEnable(GL_LIGHT0);
  glTranslatef(0, 0, -3);
  grid(-2, -2, 2, 2, 48);
}

// Two spheres in one frame, the lights changing between them: the left sphere is lit by a red
// light 0 from the left; then light 0 turns green from the right and light 1 (blue, from above)
// comes on for the right sphere. Each draw must use the lights as they were when it was drawn.
GLPT_SCENE(lighting_lights_change_between_draws, 128, 64) {
  begin_lit_view(128, 64);
  light4(GL_LIGHT0, GL_POSITION, -1, 0, 0.5f, 0);
  light4(GL_LIGHT0, GL_DIFFUSE, 1, 0.2f, 0.2f, 1);
  glEnable(GL_LIGHT0);
  sphere_at(-1.3f, 0, -5, 1);
  light4(GL_LIGHT0, GL_POSITION, 1, 0, 0.5f, 0);
  light4(GL_LIGHT0, GL_DIFFUSE, 0.2f, 1, 0.2f, 1);
  light4(GL_LIGHT1, GL_POSITION, 0, 1, 0.3f, 0);
  light4(GL_LIGHT1, GL_DIFFUSE, 0.2f, 0.2f, 1, 1);
  glEnable(GL_LIGHT1);
  sphere_at(1.3f, 0, -5, 1);
}

// Defect: a quad lit only by GL_LIGHT1 after GL_LIGHT0 lit an earlier quad in the same frame.
GLPT_SCENE(lighting_light1_after_light0, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  perspective(40.0, 1.0, 1.0, 10.0);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, -1, 0, 1, 0);
  light4(GL_LIGHT0, GL_DIFFUSE, 1, 0.4f, 0.1f, 1);
  glEnable(GL_LIGHT0);
  glTranslatef(0, 0, -4);
  grid(-1.4f, -1.2f, -0.1f, 1.2f, 8);
  glDisable(GL_LIGHT0);
  light4(GL_LIGHT1, GL_POSITION, 1, 0.5f, 1, 0);
  light4(GL_LIGHT1, GL_DIFFUSE, 0.2f, 0.6f, 1, 1);
  glEnable(GL_LIGHT1);
  grid(0.1f, -1.2f, 1.4f, 1.2f, 8);
}

// Defect: disabling GL_COLOR_MATERIAL keeps the colour it last wrote into the material. The
// left sphere is drawn with colour material tracking (1, 0.5, 0); after the disable a new
// glColor must not change the material, so the right sphere is orange too. The state dump shows
// the material (glGetMaterialfv) holding the tracked colour.
GLPT_SCENE(lighting_colour_material_disable_keeps_colour, 128, 64) {
  begin_lit_view(128, 64, true);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(1, 0.5f, 0);
  sphere_at(-1.3f, 0, -5, 1);
  glDisable(GL_COLOR_MATERIAL);
  glColor3f(0, 0, 1);
  sphere_at(1.3f, 0, -5, 1);
}

// Defect: lighting under an identity projection (clip space = eye space). The quad faces +z,
// towards the light; the sphere's visible half (nearest in depth, z < 0) faces away from the
// light at (0,0,1) and shows only its ambient term.
GLPT_SCENE(lighting_identity_projection, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, 0.3f, 0.4f, 1, 0);
  glEnable(GL_LIGHT0);
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0.3f, 0.1f, 0.1f);
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.9f, 0.3f);
  grid(-0.9f, -0.9f, -0.1f, 0.9f, 8);
  sphere_at(0.45f, 0, 0, 0.4f);
}

// Defect: a y-flipped glOrtho reverses the winding in window coordinates, so a quad that is
// counter-clockwise in object coordinates is a back face (GL 1.5 2.14.1 uses the window-space
// area). With two-sided lighting the left quad (CCW in object space) is a back face: the blue
// back material with the normal reversed, away from the light, so only its ambient term shows.
// The right quad (CW) is a front face: orange and lit.
GLPT_SCENE(lighting_flipped_ortho, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, 1, -1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_LIGHTING);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  light4(GL_LIGHT0, GL_POSITION, 0, 0, 1, 0);
  glEnable(GL_LIGHT0);
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0.6f, 0.6f, 0.6f);
  material4(GL_FRONT, GL_DIFFUSE, 1, 0.5f, 0.1f);
  material4(GL_BACK, GL_AMBIENT, 0.2f, 0.4f, 1);
  material4(GL_BACK, GL_DIFFUSE, 0.2f, 0.4f, 1);
  glNormal3f(0, 0, 1);
  glBegin(GL_QUADS);
  glVertex2f(-0.9f, -0.8f);  // counter-clockwise in object coordinates
  glVertex2f(-0.1f, -0.8f);
  glVertex2f(-0.1f, 0.6f);
  glVertex2f(-0.9f, 0.6f);
  glVertex2f(0.1f, -0.6f);  // clockwise in object coordinates
  glVertex2f(0.1f, 0.8f);
  glVertex2f(0.9f, 0.8f);
  glVertex2f(0.9f, -0.6f);
  glEnd();
}

}  // namespace

// glMaterial between glBegin and glEnd (piglit gl-1.0-dlist-materials): every vertex is lit with
// the material in effect at it, as Mesa's fixed-function program reads per-vertex material
// attributes. One triangle strip per material parameter (rows: ambient, diffuse, specular,
// emission), red at its third vertex and green at its fifth; the left column in immediate mode,
// the right one replayed from a display list. `shade_model` GL_FLAT: each triangle takes the
// material of its provoking (last) vertex; GL_SMOOTH: colours blend between vertices, and the
// display list's first two vertices take the red given after them (Mesa's display lists copy a
// material's first value in the list into the vertices before it).
void materials_between_begin_end(GLenum shade_model) {
  clear(0, 0, 0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 128, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);  // directional along +z: n . L = 1, and n . H = 1 for any shininess
  light4(GL_LIGHT0, GL_AMBIENT, 1, 1, 1, 1);
  light4(GL_LIGHT0, GL_SPECULAR, 1, 1, 1, 1);
  glShadeModel(shade_model);
  const GLenum params[4] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION};
  const float red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1}, black[4] = {0, 0, 0, 1};
  const GLuint list = glGenLists(1);
  for (int column = 0; column < 2; ++column) {
    for (int row = 0; row < 4; ++row) {
      for (GLenum p : params) glMaterialfv(GL_FRONT_AND_BACK, p, black);
      if (column == 1) glNewList(list, GL_COMPILE);
      const float x = 4.0f + 64.0f * column, y = 2.0f + 16.0f * row;
      glBegin(GL_TRIANGLE_STRIP);
      glNormal3f(0, 0, 1);
      glVertex2f(x, y);
      glVertex2f(x, y + 12);
      glMaterialfv(GL_FRONT_AND_BACK, params[row], red);
      glVertex2f(x + 28, y);
      glVertex2f(x + 28, y + 12);
      glMaterialfv(GL_FRONT_AND_BACK, params[row], green);
      glVertex2f(x + 56, y);
      glVertex2f(x + 56, y + 12);
      glEnd();
      if (column == 1) {
        glEndList();
        glCallList(list);
      }
    }
  }
  glDeleteLists(list, 1);
}

GLPT_SCENE(lighting_materials_between_begin_end_flat, 128, 64) {
  materials_between_begin_end(GL_FLAT);
}
GLPT_SCENE(lighting_materials_between_begin_end_smooth, 128, 64) {
  materials_between_begin_end(GL_SMOOTH);
}

// glMaterial of a colour GL_COLOR_MATERIAL tracks is ignored (piglit dlist-color-material):
// the current colour stays the material, whether glMaterial runs at once or from a display list
// (left: diffuse tracked, right: ambient tracked; both set to red by glMaterial after glColor
// green). Untracked components still change: the emission set with them shows as blue.
GLPT_SCENE(lighting_material_of_tracked_colour_ignored, 128, 64) {
  begin_lit_view(128, 64, true);
  const float red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 0.4f, 1};
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
  glColor3f(0, 1, 0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, blue);
  sphere_at(-1.3f, 0, -5, 1);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT);
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0.8f, 0.8f, 0.8f);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red);
  glEndList();
  glCallList(list);
  glDeleteLists(list, 1);
  sphere_at(1.3f, 0, -5, 1);
}
