// A GL matrix whose arithmetic is bit-identical to Mesa's (src/mesa/math/m_matrix.c), written
// anew from a reading of it.
//
// Why: pixel parity with Mesa (coplanar z-fighting winners, edge ties) needs the very same float
// results for every matrix (docs: /work/shared/reference/raster-parity.md). Mesa computes in
// float, builds glRotate/glFrustum/glOrtho matrices its own way, updates glTranslate/glScale
// columns in place, and multiplies with either a full 4x4 product or a 3x4 one depending on what
// it knows about the matrix (its "flags"). It also derives each matrix's inverse lazily with one
// of six methods chosen by the matrix's analysed type; that inverse transforms clip planes and
// texgen eye planes, and its transpose transforms normals. The flags and type therefore decide
// results bit for bit (signed zeros, inverse values), so they are tracked exactly as Mesa tracks
// them, including when Mesa analyses a matrix (see analyse() and its callers).
//
// Matrices are column-major; element (row r, column c) is m[c * 4 + r].
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

namespace glpt {

class MesaMatrix {
 public:
  // Mesa's matrix types (the analysed shape), in Mesa's order: the inverse method is chosen by it.
  enum class Type : uint8_t {
    kGeneral,
    kIdentity,
    k3DNoRotation,
    kPerspective,
    k2D,
    k2DNoRotation,
    k3D,
  };

  MesaMatrix() = default;  // the identity, analysed

  const glm::mat4& matrix() const { return m_; }
  const float* data() const { return &m_[0][0]; }

  // --- the operations behind the GL commands (arguments already converted to float) ---------
  void set_identity();                                          // glLoadIdentity
  void load(const float* m);                                    // glLoadMatrixf
  void multiply(const float* m);                                // glMultMatrixf
  void rotate(float angle_degrees, float x, float y, float z);  // glRotatef (angle != 0)
  void translate(float x, float y, float z);                    // glTranslatef
  void scale(float x, float y, float z);                        // glScalef
  void frustum(float left, float right, float bottom, float top, float near_val, float far_val);
  void ortho(float left, float right, float bottom, float top, float near_val, float far_val);

  // `a` * `b` into a new matrix, with the product method their flags select (Mesa's
  // _math_matrix_mul_matrix; the combined modelview-projection matrix is computed this way).
  static MesaMatrix product(const MesaMatrix& a, const MesaMatrix& b);

  // Mesa's _math_matrix_analyse: determines the type (from the flags, or from the values after a
  // load or a general multiply) and recomputes the inverse if it is out of date. A no-op for a
  // matrix that is not dirty. Mesa calls it when a draw validates state, at glPushMatrix, and
  // before using the inverse (glClipPlane, glTexGen eye planes, glLight spot direction).
  void analyse();
  bool dirty() const;
  // The inverse as Mesa computes it, analysing first if needed (the identity if singular).
  const glm::mat4& inverse() {
    analyse();
    return inv_;
  }
  Type type() const { return type_; }
  // Mesa's _math_matrix_is_length_preserving: only rotations and translations went into it.
  bool length_preserving() const;

  bool operator==(const MesaMatrix&) const = default;

 private:
  bool invert();
  void analyse_from_scratch();
  void analyse_from_flags();
  bool geometry_flags_within(uint32_t allowed) const;
  void multiply_with_flags(const float* m, uint32_t flags);

  glm::mat4 m_{1.0f};
  glm::mat4 inv_{1.0f};
  uint32_t flags_ = 0;
  Type type_ = Type::kIdentity;
};

// Mesa's fixed vector transforms (m_matrix.h), same order of operations.
// Row vector times matrix: how Mesa transforms plane equations by an inverse matrix.
glm::vec4 transform_row_vector(const glm::vec4& v, const glm::mat4& m);
// Column vector p transformed by m (glLight GL_POSITION).
glm::vec4 transform_point(const glm::mat4& m, const glm::vec4& p);
// Direction d by the upper 3x3 of m (glLight GL_SPOT_DIRECTION).
glm::vec3 transform_direction(const glm::vec3& d, const glm::mat4& m);

}  // namespace glpt
