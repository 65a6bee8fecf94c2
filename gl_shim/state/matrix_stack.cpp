// glMatrixMode, glLoadIdentity, glLoad/MultMatrix (and transposed), glRotate/Translate/Scale,
// glFrustum/Ortho, glPush/PopMatrix (GL 1.5 spec 2.11.2). The arithmetic is Mesa's
// (mesa_matrix.hpp), and so are the command-level details that decide it: double arguments are
// converted to float first, and a load of the same matrix, a multiply by the identity and a
// rotation by 0 degrees leave the matrix (and what Mesa knows about it) untouched.
#include "gl_shim/state/matrix_stack.hpp"

#include <cstring>

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

void MatrixState::validate_for_draw(uint8_t clip_plane_mask) {
  modelview.top_matrix().analyse();
  // Mesa only needs the projection's inverse (for clip-space planes) when a plane is enabled.
  if (clip_plane_mask != 0) projection.top_matrix().analyse();
  for (MatrixStack& t : texture) t.top_matrix().analyse();
}

glm::mat4 MatrixState::model_projection() const {
  return MesaMatrix::product(projection.top_matrix(), modelview.top_matrix()).matrix();
}

namespace {

constexpr float kIdentity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

MesaMatrix& current_top(Context& ctx) {
  return ctx.matrices.current(ctx.textures.active).top_matrix();
}

void load(Context& ctx, const float* m) {
  MesaMatrix& top = current_top(ctx);
  if (std::memcmp(m, top.data(), sizeof(kIdentity)) == 0) return;
  top.load(m);
  ctx.matrices.changed();
}

void multiply(Context& ctx, const float* m) {
  if (std::memcmp(m, kIdentity, sizeof(kIdentity)) == 0) return;  // bitwise, as Mesa tests it
  current_top(ctx).multiply(m);
  ctx.matrices.changed();
}

// A column-major array of 16 values as floats; `transpose` reads a row-major one.
template <typename T>
void to_floats(const T* m, bool transpose, float* out) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      out[c * 4 + r] = static_cast<float>(transpose ? m[r * 4 + c] : m[c * 4 + r]);
}

template <typename T>
void load_matrix(Context& ctx, const T* m, bool transpose) {
  if (m == nullptr) return;  // GL leaves this undefined; Mesa ignores it too
  float f[16];
  to_floats(m, transpose, f);
  load(ctx, f);
}

template <typename T>
void mult_matrix(Context& ctx, const T* m, bool transpose) {
  if (m == nullptr) return;
  float f[16];
  to_floats(m, transpose, f);
  multiply(ctx, f);
}

void rotate(Context& ctx, float angle, float x, float y, float z) {
  if (angle == 0.0f) return;
  current_top(ctx).rotate(angle, x, y, z);
  ctx.matrices.changed();
}

void translate(Context& ctx, float x, float y, float z) {
  current_top(ctx).translate(x, y, z);
  ctx.matrices.changed();
}

void scale(Context& ctx, float x, float y, float z) {
  current_top(ctx).scale(x, y, z);
  ctx.matrices.changed();
}

// The bounds are converted to float before they are checked, as in Mesa: bounds that only
// differ in double precision are equal (GL_INVALID_VALUE).
void frustum(Context& ctx, float l, float r, float b, float t, float n, float f) {
  if (n <= 0 || f <= 0 || n == f || l == r || t == b) return record_error(ctx, GL_INVALID_VALUE);
  current_top(ctx).frustum(l, r, b, t, n, f);
  ctx.matrices.changed();
}

void ortho(Context& ctx, float l, float r, float b, float t, float n, float f) {
  if (l == r || b == t || n == f) return record_error(ctx, GL_INVALID_VALUE);
  current_top(ctx).ortho(l, r, b, t, n, f);
  ctx.matrices.changed();
}

float f32(GLdouble v) { return static_cast<float>(v); }

}  // namespace

namespace impl {

void glMatrixMode(Context& ctx, GLenum mode) {
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE)
    return record_error(ctx, GL_INVALID_ENUM);
  ctx.matrices.mode = mode;
}

void glLoadIdentity(Context& ctx) {
  current_top(ctx).set_identity();
  ctx.matrices.changed();
}
void glLoadMatrixf(Context& ctx, const GLfloat* m) { load_matrix(ctx, m, false); }
void glLoadMatrixd(Context& ctx, const GLdouble* m) { load_matrix(ctx, m, false); }
void glMultMatrixf(Context& ctx, const GLfloat* m) { mult_matrix(ctx, m, false); }
void glMultMatrixd(Context& ctx, const GLdouble* m) { mult_matrix(ctx, m, false); }
void glLoadTransposeMatrixf(Context& ctx, const GLfloat* m) { load_matrix(ctx, m, true); }
void glLoadTransposeMatrixd(Context& ctx, const GLdouble* m) { load_matrix(ctx, m, true); }
void glMultTransposeMatrixf(Context& ctx, const GLfloat* m) { mult_matrix(ctx, m, true); }
void glMultTransposeMatrixd(Context& ctx, const GLdouble* m) { mult_matrix(ctx, m, true); }

void glRotatef(Context& ctx, GLfloat angle, GLfloat x, GLfloat y, GLfloat z) {
  rotate(ctx, angle, x, y, z);
}
void glRotated(Context& ctx, GLdouble angle, GLdouble x, GLdouble y, GLdouble z) {
  rotate(ctx, f32(angle), f32(x), f32(y), f32(z));
}
void glTranslatef(Context& ctx, GLfloat x, GLfloat y, GLfloat z) { translate(ctx, x, y, z); }
void glTranslated(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  translate(ctx, f32(x), f32(y), f32(z));
}
void glScalef(Context& ctx, GLfloat x, GLfloat y, GLfloat z) { scale(ctx, x, y, z); }
void glScaled(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  scale(ctx, f32(x), f32(y), f32(z));
}

void glFrustum(Context& ctx, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n,
               GLdouble f) {
  frustum(ctx, f32(l), f32(r), f32(b), f32(t), f32(n), f32(f));
}
void glOrtho(Context& ctx, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  ortho(ctx, f32(l), f32(r), f32(b), f32(t), f32(n), f32(f));
}

void glPushMatrix(Context& ctx) {
  if (!ctx.matrices.current(ctx.textures.active).push()) record_error(ctx, GL_STACK_OVERFLOW);
}
void glPopMatrix(Context& ctx) {
  if (!ctx.matrices.current(ctx.textures.active).pop())
    return record_error(ctx, GL_STACK_UNDERFLOW);
  ctx.matrices.changed();
}

}  // namespace impl
}  // namespace glpt
