// glMatrixMode, glLoadIdentity, glLoad/MultMatrix, glRotate/Translate/Scale, glFrustum/Ortho,
// glPush/PopMatrix (GL 1.5 spec 2.11.2).
#include "gl_shim/state/matrix_stack.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {

MatrixStack& MatrixState::current(uint32_t active_texture) {
  switch (mode) {
    case GL_PROJECTION:
      return projection;
    case GL_TEXTURE:
      return texture[active_texture];
    default:
      return modelview;
  }
}

void MatrixState::changed() {
  if (mode == GL_MODELVIEW)
    ++modelview_version;
  else if (mode == GL_PROJECTION)
    ++projection_version;
}

namespace {

MatrixStack& current_stack(Context& ctx) { return ctx.matrices.current(ctx.textures.active); }

void multiply(Context& ctx, const glm::mat4& m) {
  current_stack(ctx).top() *= m;
  ctx.matrices.changed();
}

void load(Context& ctx, const glm::mat4& m) {
  current_stack(ctx).top() = m;
  ctx.matrices.changed();
}

template <typename T>
glm::mat4 from_column_major(const T* m) {
  glm::mat4 r;
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) r[c][row] = static_cast<float>(m[c * 4 + row]);
  return r;
}

void rotate(Context& ctx, double angle_deg, double x, double y, double z) {
  const double len = std::sqrt(x * x + y * y + z * z);
  // GL leaves a zero axis undefined; treat it as no rotation rather than producing NaNs.
  if (!(len > 0.0) || !std::isfinite(len)) return;
  multiply(ctx, glm::rotate(glm::mat4(1.0f), static_cast<float>(glm::radians(angle_deg)),
                            glm::vec3(static_cast<float>(x / len), static_cast<float>(y / len),
                                      static_cast<float>(z / len))));
}

void frustum(Context& ctx, double l, double r, double b, double t, double n, double f) {
  if (n <= 0 || f <= 0 || l == r || b == t || n == f) {
    record_error(ctx, GL_INVALID_VALUE);
    return;
  }
  // Built in double precision, as the spec writes it, then stored as float.
  glm::dmat4 m(0.0);
  m[0][0] = 2 * n / (r - l);
  m[1][1] = 2 * n / (t - b);
  m[2][0] = (r + l) / (r - l);
  m[2][1] = (t + b) / (t - b);
  m[2][2] = -(f + n) / (f - n);
  m[2][3] = -1;
  m[3][2] = -2 * f * n / (f - n);
  multiply(ctx, glm::mat4(m));
}

void ortho(Context& ctx, double l, double r, double b, double t, double n, double f) {
  if (l == r || b == t || n == f) {
    record_error(ctx, GL_INVALID_VALUE);
    return;
  }
  glm::dmat4 m(1.0);
  m[0][0] = 2 / (r - l);
  m[1][1] = 2 / (t - b);
  m[2][2] = -2 / (f - n);
  m[3][0] = -(r + l) / (r - l);
  m[3][1] = -(t + b) / (t - b);
  m[3][2] = -(f + n) / (f - n);
  multiply(ctx, glm::mat4(m));
}

}  // namespace

namespace impl {

void glMatrixMode(Context& ctx, GLenum mode) {
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
    record_error(ctx, GL_INVALID_ENUM);
    return;
  }
  ctx.matrices.mode = mode;
}

void glLoadIdentity(Context& ctx) { load(ctx, glm::mat4(1.0f)); }
void glLoadMatrixf(Context& ctx, const GLfloat* m) { load(ctx, from_column_major(m)); }
void glLoadMatrixd(Context& ctx, const GLdouble* m) { load(ctx, from_column_major(m)); }
void glMultMatrixf(Context& ctx, const GLfloat* m) { multiply(ctx, from_column_major(m)); }
void glMultMatrixd(Context& ctx, const GLdouble* m) { multiply(ctx, from_column_major(m)); }
void glLoadTransposeMatrixf(Context& ctx, const GLfloat* m) {
  load(ctx, glm::transpose(from_column_major(m)));
}
void glLoadTransposeMatrixd(Context& ctx, const GLdouble* m) {
  load(ctx, glm::transpose(from_column_major(m)));
}
void glMultTransposeMatrixf(Context& ctx, const GLfloat* m) {
  multiply(ctx, glm::transpose(from_column_major(m)));
}
void glMultTransposeMatrixd(Context& ctx, const GLdouble* m) {
  multiply(ctx, glm::transpose(from_column_major(m)));
}

void glRotatef(Context& ctx, GLfloat angle, GLfloat x, GLfloat y, GLfloat z) {
  rotate(ctx, angle, x, y, z);
}
void glRotated(Context& ctx, GLdouble angle, GLdouble x, GLdouble y, GLdouble z) {
  rotate(ctx, angle, x, y, z);
}

void glTranslatef(Context& ctx, GLfloat x, GLfloat y, GLfloat z) {
  multiply(ctx, glm::translate(glm::mat4(1.0f), glm::vec3(x, y, z)));
}
void glTranslated(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  multiply(ctx, glm::mat4(glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z))));
}
void glScalef(Context& ctx, GLfloat x, GLfloat y, GLfloat z) {
  multiply(ctx, glm::scale(glm::mat4(1.0f), glm::vec3(x, y, z)));
}
void glScaled(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  multiply(ctx, glm::mat4(glm::scale(glm::dmat4(1.0), glm::dvec3(x, y, z))));
}

void glFrustum(Context& ctx, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n,
               GLdouble f) {
  frustum(ctx, l, r, b, t, n, f);
}
void glOrtho(Context& ctx, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  ortho(ctx, l, r, b, t, n, f);
}

void glPushMatrix(Context& ctx) {
  if (!current_stack(ctx).push()) record_error(ctx, GL_STACK_OVERFLOW);
}
void glPopMatrix(Context& ctx) {
  if (!current_stack(ctx).pop()) {
    record_error(ctx, GL_STACK_UNDERFLOW);
    return;
  }
  ctx.matrices.changed();
}

}  // namespace impl
}  // namespace glpt
