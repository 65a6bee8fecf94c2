// Texture coordinate generation (GL 1.5 2.11.4) and the texture matrix: object and eye linear
// planes, sphere, reflection and normal maps, and projective texturing.
#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

void plane(GLenum coord, GLenum pname, float a, float b, float c, float d) {
  const float v[4] = {a, b, c, d};
  glTexGenfv(coord, pname, v);
}

void begin_texgen_view() {
  clear(0.15f, 0.15f, 0.2f);
  perspective(35.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
}

void stripes_texture() {
  texture_2d(GL_RGB, 8, 8, checker(8, 8, 2, Rgba8{250, 220, 60, 255}, Rgba8{40, 90, 200, 255}),
             GL_NEAREST, GL_REPEAT);
}

// Object-linear s and t: the pattern sticks to the rotated sphere.
GLPT_SCENE(texgen_object_linear, 64, 64) {
  begin_texgen_view();
  stripes_texture();
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  plane(GL_S, GL_OBJECT_PLANE, 1.0f, 0.0f, 0.5f, 0.0f);
  plane(GL_T, GL_OBJECT_PLANE, 0.0f, 1.0f, 0.0f, 0.25f);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glTranslatef(0, 0, -4);
  glRotatef(40, 0, 1, 0);
  glRotatef(20, 1, 0, 0);
  sphere(1.2f, 32, 16);
}

// Eye-linear planes are transformed by the inverse of the modelview current at glTexGen time:
// set under a 30-degree roll, then the sphere is drawn under another modelview; the pattern is
// fixed in eye space (rolled by 30 degrees), not on the sphere.
GLPT_SCENE(texgen_eye_linear, 64, 64) {
  begin_texgen_view();
  stripes_texture();
  glPushMatrix();
  glRotatef(30, 0, 0, 1);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  plane(GL_S, GL_EYE_PLANE, 1.0f, 0.0f, 0.0f, 0.0f);
  plane(GL_T, GL_EYE_PLANE, 0.0f, 1.0f, 0.0f, 0.0f);
  glPopMatrix();
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glTranslatef(0, 0, -4);
  glRotatef(60, 0, 1, 0);
  sphere(1.2f, 32, 16);
}

// Sphere map: s, t from the eye-space reflection vector; an environment image with a grid.
GLPT_SCENE(texgen_sphere_map, 64, 64) {
  begin_texgen_view();
  texture_2d(GL_RGB, 32, 32,
             gradient(32, 32, Rgba8{40, 40, 120, 255}, Rgba8{120, 40, 40, 255},
                      Rgba8{200, 230, 255, 255}, Rgba8{255, 240, 180, 255}, 8),
             GL_LINEAR, GL_REPEAT);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glTranslatef(-0.3f, 0, -4);
  sphere(1.2f, 32, 16);
}

// A cube map with a distinct colour and a checker per face.
void cube_map_texture() {
  new_texture(GL_TEXTURE_CUBE_MAP, GL_NEAREST, GL_NEAREST);
  static const Rgba8 kColours[6] = {{230, 60, 60, 255},  {60, 230, 230, 255}, {60, 230, 60, 255},
                                    {230, 60, 230, 255}, {60, 60, 230, 255},  {230, 230, 60, 255}};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int face = 0; face < 6; ++face) {
    const Rgba8 c = kColours[face];
    const std::vector<uint8_t> texels =
        checker(8, 8, 2, c,
                Rgba8{static_cast<uint8_t>(c.r / 3), static_cast<uint8_t>(c.g / 3),
                      static_cast<uint8_t>(c.b / 3), 255});
    glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA, 8, 8, 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glEnable(GL_TEXTURE_CUBE_MAP);
}

void cube_map_texgen_scene(GLenum mode) {
  clear(0.15f, 0.15f, 0.2f);
  perspective(35.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  cube_map_texture();
  for (const GLenum coord : {GL_S, GL_T, GL_R})
    glTexGeni(coord, GL_TEXTURE_GEN_MODE, static_cast<GLint>(mode));
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  glColor3f(1, 1, 1);
  glTranslatef(0, 0, -4);
  glRotatef(30, 1, 1, 0);
  sphere(1.2f, 32, 16);
}

// Reflection map: (s, t, r) = the eye-space reflection vector.
GLPT_SCENE(texgen_reflection_map, 64, 64) { cube_map_texgen_scene(GL_REFLECTION_MAP); }
// Normal map: (s, t, r) = the eye-space normal (the sphere's rotation does not move it).
GLPT_SCENE(texgen_normal_map, 64, 64) { cube_map_texgen_scene(GL_NORMAL_MAP); }

// The texture matrix transforms texture coordinates: a checker quad under a rotation, scale and
// translation of its coordinates; a second quad with the matrix stack pushed and changed.
GLPT_SCENE(texgen_texture_matrix, 64, 64) {
  clear(0.15f, 0.15f, 0.2f);
  ortho_pixels(64, 64);
  glEnable(GL_TEXTURE_2D);
  stripes_texture();
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0);
  glRotatef(25, 0, 0, 1);
  glScalef(1.5f, 0.75f, 1);
  glMatrixMode(GL_MODELVIEW);
  glColor3f(1, 1, 1);
  quad(2, 2, 40, 40);
  glMatrixMode(GL_TEXTURE);
  glPushMatrix();
  glScalef(3, 3, 1);
  glMatrixMode(GL_MODELVIEW);
  quad(36, 30, 62, 62);
  glMatrixMode(GL_TEXTURE);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
}

// Projective texturing: eye-linear s, t, r, q (identity planes, so the coordinates are the eye
// position) and a texture matrix that is a projector's bias * frustum * view: an image is
// "slide-projected" onto a floor and a sphere, divided by q per fragment.
GLPT_SCENE(texgen_projective_texture_matrix, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  perspective(50.0, 1.0, 0.5, 20.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGB, 16, 16,
             gradient(16, 16, Rgba8{255, 60, 60, 255}, Rgba8{60, 255, 60, 255},
                      Rgba8{60, 60, 255, 255}, Rgba8{255, 255, 60, 255}, 4),
             GL_LINEAR, GL_CLAMP_TO_BORDER);
  const float border[4] = {0.3f, 0.3f, 0.3f, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  for (int i = 0; i < 4; ++i) {
    glTexGeni(coords[i], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    plane(coords[i], GL_EYE_PLANE, i == 0 ? 1.0f : 0.0f, i == 1 ? 1.0f : 0.0f, i == 2 ? 1.0f : 0.0f,
          i == 3 ? 1.0f : 0.0f);
  }
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  glEnable(GL_TEXTURE_GEN_Q);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.5f);
  glScalef(0.5f, 0.5f, 0.5f);
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  // The projector sits up and to the right of the camera, turned towards the sphere.
  glRotatef(-25, 0, 1, 0);
  glTranslatef(-1.0f, -0.5f, 0);
  glMatrixMode(GL_MODELVIEW);
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);  // the floor
  glVertex3f(-3, -1, -1);
  glVertex3f(3, -1, -1);
  glVertex3f(3, -1, -8);
  glVertex3f(-3, -1, -8);
  glEnd();
  glTranslatef(0.2f, -0.2f, -4);
  sphere(0.8f, 24, 12);
}

}  // namespace
