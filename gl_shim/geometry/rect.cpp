// glRect{s,i,f,d}{,v} (GL 1.5 spec 2.10): one rectangle in the z = 0 plane, drawn through the
// same glBegin/glVertex/glEnd path as any primitive, so it is recorded like one.
#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/geometry/attributes.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

// The spec defines glRect as Begin(POLYGON), the four corners, End. Mesa draws it as one
// GL_QUADS quad (main/draw.c _mesa_Rectf). The two differ only where the spec leaves room or
// Mesa departs from it: how the quadrilateral is split into triangles (which decides depth and
// interpolation rounding on the shared diagonal) and which vertex is the provoking one for flat
// shading (the last for quads, the first for polygons; only visible with lighting, where the
// corners' lit colours can differ). glpt records what Mesa draws, for pixel parity.
constexpr GLenum kRectPrimitive = GL_QUADS;

// The corners are converted to float first, as Mesa does.
void rect(Context& ctx, float x1, float y1, float x2, float y2) {
  impl::glBegin(ctx, kRectPrimitive);
  attribute_vertex(ctx, glm::vec4(x1, y1, 0.0f, 1.0f));
  attribute_vertex(ctx, glm::vec4(x2, y1, 0.0f, 1.0f));
  attribute_vertex(ctx, glm::vec4(x2, y2, 0.0f, 1.0f));
  attribute_vertex(ctx, glm::vec4(x1, y2, 0.0f, 1.0f));
  impl::glEnd(ctx);
}

template <typename T>
void rect(Context& ctx, T x1, T y1, T x2, T y2) {
  rect(ctx, static_cast<float>(x1), static_cast<float>(y1), static_cast<float>(x2),
       static_cast<float>(y2));
}

template <typename T>
void rect_v(Context& ctx, const T* v1, const T* v2) {
  if (v1 == nullptr || v2 == nullptr) return;  // undefined in GL; ignored
  rect(ctx, v1[0], v1[1], v2[0], v2[1]);
}

}  // namespace

namespace impl {

void glRectd(Context& ctx, GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) {
  rect(ctx, x1, y1, x2, y2);
}
void glRectdv(Context& ctx, const GLdouble* v1, const GLdouble* v2) { rect_v(ctx, v1, v2); }
void glRectf(Context& ctx, GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) {
  rect(ctx, x1, y1, x2, y2);
}
void glRectfv(Context& ctx, const GLfloat* v1, const GLfloat* v2) { rect_v(ctx, v1, v2); }
void glRecti(Context& ctx, GLint x1, GLint y1, GLint x2, GLint y2) { rect(ctx, x1, y1, x2, y2); }
void glRectiv(Context& ctx, const GLint* v1, const GLint* v2) { rect_v(ctx, v1, v2); }
void glRects(Context& ctx, GLshort x1, GLshort y1, GLshort x2, GLshort y2) {
  rect(ctx, x1, y1, x2, y2);
}
void glRectsv(Context& ctx, const GLshort* v1, const GLshort* v2) { rect_v(ctx, v1, v2); }

}  // namespace impl
}  // namespace glpt
