// Issues a reference::Scene (reference_scene.hpp) as GL 1.x calls on the current context: the
// one way the tests draw a scene in glpt, so glpt and the CPU reference see the same data.
// Header-only; the caller links libGL (glpt's front end: glpt_gl_front_whole in the tests).
#pragma once

#include "gl/gl_enums.h"
#include "gl_shim/gl_entry_decls.h"
#include "reference_scene.hpp"

namespace glpt::reference {

inline void set_material(const Material& m) {
  const float a[] = {m.ambient.r, m.ambient.g, m.ambient.b, 1};
  const float d[] = {m.diffuse.r, m.diffuse.g, m.diffuse.b, 1};
  const float s[] = {m.specular.r, m.specular.g, m.specular.b, 1};
  const float e[] = {m.emission.r, m.emission.g, m.emission.b, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, a);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, d);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, e);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, m.shininess);
}

// One frame of `scene`: projection, clear, lights (eye space: identity modelview), objects.
inline void issue_gl(const Scene& scene) {
  glViewport(0, 0, scene.size, scene.size);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const Camera& c = scene.camera;
  if (c.perspective)
    glFrustum(c.left, c.right, c.bottom, c.top, c.near_plane, c.far_plane);
  else
    glOrtho(c.left, c.right, c.bottom, c.top, c.near_plane, c.far_plane);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(scene.clear_color.r, scene.clear_color.g, scene.clear_color.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(scene.depth_less_equal ? GL_LEQUAL : GL_LESS);
  glDisable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glShadeModel(GL_SMOOTH);
  const float ambient[] = {scene.global_ambient.r, scene.global_ambient.g, scene.global_ambient.b,
                           1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, scene.two_side ? 1.0f : 0.0f);
  for (size_t i = 0; i < 8; ++i) {
    const GLenum light = GL_LIGHT0 + static_cast<GLenum>(i);
    if (i >= scene.lights.size()) {
      glDisable(light);
      continue;
    }
    const Light& l = scene.lights[i];
    const float p[] = {l.position.x, l.position.y, l.position.z, l.position.w};
    const float a[] = {l.ambient.r, l.ambient.g, l.ambient.b, 1};
    const float d[] = {l.diffuse.r, l.diffuse.g, l.diffuse.b, 1};
    const float s[] = {l.specular.r, l.specular.g, l.specular.b, 1};
    const float dir[] = {l.spot_direction.x, l.spot_direction.y, l.spot_direction.z};
    glLightfv(light, GL_POSITION, p);
    glLightfv(light, GL_AMBIENT, a);
    glLightfv(light, GL_DIFFUSE, d);
    glLightfv(light, GL_SPECULAR, s);
    glLightfv(light, GL_SPOT_DIRECTION, dir);
    glLightf(light, GL_SPOT_EXPONENT, l.spot_exponent);
    glLightf(light, GL_SPOT_CUTOFF, l.spot_cutoff);
    glLightf(light, GL_CONSTANT_ATTENUATION, l.constant_attenuation);
    glLightf(light, GL_LINEAR_ATTENUATION, l.linear_attenuation);
    glLightf(light, GL_QUADRATIC_ATTENUATION, l.quadratic_attenuation);
    glEnable(light);
  }
  for (const Object& o : scene.objects) {
    glLoadIdentity();
    if (o.translation != glm::vec3(0.0f))
      glTranslatef(o.translation.x, o.translation.y, o.translation.z);
    set_material(o.material);
    glBegin(GL_TRIANGLES);
    for (const Vertex& v : o.vertices) {
      glNormal3f(v.normal.x, v.normal.y, v.normal.z);
      glVertex3f(v.position.x, v.position.y, v.position.z);
    }
    glEnd();
  }
  glLoadIdentity();
}

}  // namespace glpt::reference
