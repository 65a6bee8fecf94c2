// Mesa-identical matrix arithmetic (see mesa_matrix.hpp). Built with -ffp-contract=off: a fused
// multiply-add would round differently from Mesa's separate multiplies and adds.
#include "gl_shim/state/mesa_matrix.hpp"

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <numbers>
#include <utility>

namespace glpt {
namespace {

// Mesa's matrix flags (MAT_FLAG_*, MAT_DIRTY_*): what is known about a matrix's shape.
constexpr uint32_t kGeneral = 0x1;
constexpr uint32_t kRotation = 0x2;
constexpr uint32_t kTranslation = 0x4;
constexpr uint32_t kUniformScale = 0x8;
constexpr uint32_t kGeneralScale = 0x10;
constexpr uint32_t kGeneral3D = 0x20;
constexpr uint32_t kPerspective = 0x40;
constexpr uint32_t kSingular = 0x80;
constexpr uint32_t kDirtyType = 0x100;
constexpr uint32_t kDirtyFlags = 0x200;
constexpr uint32_t kDirtyInverse = 0x400;

constexpr uint32_t kAnglePreserving = kRotation | kTranslation | kUniformScale;
constexpr uint32_t kGeometryFlags = kGeneral | kRotation | kTranslation | kUniformScale |
                                    kGeneralScale | kGeneral3D | kPerspective | kSingular;
constexpr uint32_t k3DFlags = kRotation | kTranslation | kUniformScale | kGeneralScale | kGeneral3D;
constexpr uint32_t kDirty = kDirtyType | kDirtyFlags | kDirtyInverse;

constexpr float kIdentity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

float* ptr(glm::mat4& m) { return &m[0][0]; }
const float* ptr(const glm::mat4& m) { return &m[0][0]; }

// Element (row, column) of a column-major 4x4 array.
float& at(float* m, int row, int col) { return m[col * 4 + row]; }
float at(const float* m, int row, int col) { return m[col * 4 + row]; }

// product = a * b. `product` may be `a` (each row of a is read before it is overwritten), never b.
void multiply_4x4(float* product, const float* a, const float* b) {
  for (int i = 0; i < 4; ++i) {
    const float ai0 = at(a, i, 0), ai1 = at(a, i, 1), ai2 = at(a, i, 2), ai3 = at(a, i, 3);
    at(product, i, 0) =
        ai0 * at(b, 0, 0) + ai1 * at(b, 1, 0) + ai2 * at(b, 2, 0) + ai3 * at(b, 3, 0);
    at(product, i, 1) =
        ai0 * at(b, 0, 1) + ai1 * at(b, 1, 1) + ai2 * at(b, 2, 1) + ai3 * at(b, 3, 1);
    at(product, i, 2) =
        ai0 * at(b, 0, 2) + ai1 * at(b, 1, 2) + ai2 * at(b, 2, 2) + ai3 * at(b, 3, 2);
    at(product, i, 3) =
        ai0 * at(b, 0, 3) + ai1 * at(b, 1, 3) + ai2 * at(b, 2, 3) + ai3 * at(b, 3, 3);
  }
}

// The same product for two matrices whose bottom row is (0, 0, 0, 1): the terms that would
// multiply by those zeros are left out, which only changes signed zeros and non-finite values.
void multiply_3x4(float* product, const float* a, const float* b) {
  for (int i = 0; i < 3; ++i) {
    const float ai0 = at(a, i, 0), ai1 = at(a, i, 1), ai2 = at(a, i, 2), ai3 = at(a, i, 3);
    at(product, i, 0) = ai0 * at(b, 0, 0) + ai1 * at(b, 1, 0) + ai2 * at(b, 2, 0);
    at(product, i, 1) = ai0 * at(b, 0, 1) + ai1 * at(b, 1, 1) + ai2 * at(b, 2, 1);
    at(product, i, 2) = ai0 * at(b, 0, 2) + ai1 * at(b, 1, 2) + ai2 * at(b, 2, 2);
    at(product, i, 3) = ai0 * at(b, 0, 3) + ai1 * at(b, 1, 3) + ai2 * at(b, 2, 3) + ai3;
  }
  at(product, 3, 0) = 0;
  at(product, 3, 1) = 0;
  at(product, 3, 2) = 0;
  at(product, 3, 3) = 1;
}

bool geometry_within(uint32_t flags, uint32_t allowed) {
  return (kGeometryFlags & ~allowed & flags) == 0;
}

float square(float x) { return x * x; }
float dot2(const float* a, const float* b) { return a[0] * b[0] + a[1] * b[1]; }
float dot3(const float* a, const float* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Gaussian elimination with partial pivoting, loops unrolled as in Mesa's util_invert_mat4x4
// (and with its skips of zero terms, which decide signed zeros).
bool invert_general(float* out, const float* m) {
  float rows[4][8];
  float* r0 = rows[0];
  float* r1 = rows[1];
  float* r2 = rows[2];
  float* r3 = rows[3];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) rows[r][c] = at(m, r, c);
    for (int c = 4; c < 8; ++c) rows[r][c] = c - 4 == r ? 1.0f : 0.0f;
  }
  auto pivot = [](float*& below, float*& above, int column) {
    if (std::fabs(below[column]) > std::fabs(above[column])) std::swap(below, above);
  };
  // Subtracts `factor` times the pivot row's entry at `col` from row `r`.
  auto eliminate = [](float* r, float factor, float pivot_entry) { *r -= factor * pivot_entry; };

  pivot(r3, r2, 0);
  pivot(r2, r1, 0);
  pivot(r1, r0, 0);
  if (r0[0] == 0.0f) return false;
  float m1 = r1[0] / r0[0], m2 = r2[0] / r0[0], m3 = r3[0] / r0[0];
  for (int c = 1; c < 4; ++c) {
    const float s = r0[c];
    eliminate(&r1[c], m1, s);
    eliminate(&r2[c], m2, s);
    eliminate(&r3[c], m3, s);
  }
  for (int c = 4; c < 8; ++c) {
    const float s = r0[c];
    if (s != 0.0f) {
      eliminate(&r1[c], m1, s);
      eliminate(&r2[c], m2, s);
      eliminate(&r3[c], m3, s);
    }
  }

  pivot(r3, r2, 1);
  pivot(r2, r1, 1);
  if (r1[1] == 0.0f) return false;
  m2 = r2[1] / r1[1];
  m3 = r3[1] / r1[1];
  for (int c = 2; c < 4; ++c) {
    eliminate(&r2[c], m2, r1[c]);
    eliminate(&r3[c], m3, r1[c]);
  }
  for (int c = 4; c < 8; ++c) {
    const float s = r1[c];
    if (s != 0.0f) {
      eliminate(&r2[c], m2, s);
      eliminate(&r3[c], m3, s);
    }
  }

  pivot(r3, r2, 2);
  if (r2[2] == 0.0f) return false;
  m3 = r3[2] / r2[2];
  for (int c = 3; c < 8; ++c) eliminate(&r3[c], m3, r2[c]);
  if (r3[3] == 0.0f) return false;

  float s = 1.0f / r3[3];  // back substitution, row 3
  for (int c = 4; c < 8; ++c) r3[c] *= s;

  float m0;
  m2 = r2[3];  // row 2
  s = 1.0f / r2[2];
  for (int c = 4; c < 8; ++c) r2[c] = s * (r2[c] - r3[c] * m2);
  m1 = r1[3];
  for (int c = 4; c < 8; ++c) r1[c] -= r3[c] * m1;
  m0 = r0[3];
  for (int c = 4; c < 8; ++c) r0[c] -= r3[c] * m0;

  m1 = r1[2];  // row 1
  s = 1.0f / r1[1];
  for (int c = 4; c < 8; ++c) r1[c] = s * (r1[c] - r2[c] * m1);
  m0 = r0[2];
  for (int c = 4; c < 8; ++c) r0[c] -= r2[c] * m0;

  m0 = r0[1];  // row 0
  s = 1.0f / r0[0];
  for (int c = 4; c < 8; ++c) r0[c] = s * (r0[c] - r1[c] * m0);

  const float* result[4] = {r0, r1, r2, r3};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) at(out, r, c) = result[r][c + 4];
  return true;
}

// The translation column of the inverse of an affine matrix whose upper 3x3 inverse is in `out`.
void invert_translation(float* out, const float* in) {
  for (int r = 0; r < 3; ++r)
    at(out, r, 3) = -(at(in, 0, 3) * at(out, r, 0) + at(in, 1, 3) * at(out, r, 1) +
                      at(in, 2, 3) * at(out, r, 2));
}

// Inverse of an affine matrix with a general upper 3x3 (cofactors over the determinant). Row 3 of
// `out` is left as it was, as in Mesa.
bool invert_3d_general(float* out, const float* in) {
  // The determinant, positive and negative terms summed separately.
  float pos = 0.0f, neg = 0.0f;
  const float terms[6] = {
      at(in, 0, 0) * at(in, 1, 1) * at(in, 2, 2),  at(in, 1, 0) * at(in, 2, 1) * at(in, 0, 2),
      at(in, 2, 0) * at(in, 0, 1) * at(in, 1, 2),  -at(in, 2, 0) * at(in, 1, 1) * at(in, 0, 2),
      -at(in, 1, 0) * at(in, 0, 1) * at(in, 2, 2), -at(in, 0, 0) * at(in, 2, 1) * at(in, 1, 2),
  };
  for (float t : terms) {
    if (t >= 0.0f)
      pos += t;
    else
      neg += t;
  }
  float det = pos + neg;
  if (std::fabs(det) < 1e-25f) return false;
  det = 1.0f / det;
  at(out, 0, 0) = (at(in, 1, 1) * at(in, 2, 2) - at(in, 2, 1) * at(in, 1, 2)) * det;
  at(out, 0, 1) = -(at(in, 0, 1) * at(in, 2, 2) - at(in, 2, 1) * at(in, 0, 2)) * det;
  at(out, 0, 2) = (at(in, 0, 1) * at(in, 1, 2) - at(in, 1, 1) * at(in, 0, 2)) * det;
  at(out, 1, 0) = -(at(in, 1, 0) * at(in, 2, 2) - at(in, 2, 0) * at(in, 1, 2)) * det;
  at(out, 1, 1) = (at(in, 0, 0) * at(in, 2, 2) - at(in, 2, 0) * at(in, 0, 2)) * det;
  at(out, 1, 2) = -(at(in, 0, 0) * at(in, 1, 2) - at(in, 1, 0) * at(in, 0, 2)) * det;
  at(out, 2, 0) = (at(in, 1, 0) * at(in, 2, 1) - at(in, 2, 0) * at(in, 1, 1)) * det;
  at(out, 2, 1) = -(at(in, 0, 0) * at(in, 2, 1) - at(in, 2, 0) * at(in, 0, 1)) * det;
  at(out, 2, 2) = (at(in, 0, 0) * at(in, 1, 1) - at(in, 1, 0) * at(in, 0, 1)) * det;
  invert_translation(out, in);
  return true;
}

// Inverse of an affine matrix that is a rotation, optionally uniformly scaled, optionally
// translated; anything else goes to invert_3d_general.
bool invert_3d(float* out, const float* in, uint32_t flags) {
  if (!geometry_within(flags, kAnglePreserving)) return invert_3d_general(out, in);
  if (flags & kUniformScale) {
    float scale =
        at(in, 0, 0) * at(in, 0, 0) + at(in, 0, 1) * at(in, 0, 1) + at(in, 0, 2) * at(in, 0, 2);
    if (scale == 0.0f) return false;
    scale = 1.0f / scale;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) at(out, c, r) = scale * at(in, r, c);
  } else if (flags & kRotation) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) at(out, c, r) = at(in, r, c);
  } else {  // a pure translation
    std::memcpy(out, kIdentity, sizeof(kIdentity));
    for (int r = 0; r < 3; ++r) at(out, r, 3) = -at(in, r, 3);
    return true;
  }
  if (flags & kTranslation) {
    invert_translation(out, in);
  } else {
    at(out, 0, 3) = at(out, 1, 3) = at(out, 2, 3) = 0.0f;
  }
  return true;
}

// Inverse of a scale (+ translation) without rotation; `dims` is 2 or 3 scaled axes.
bool invert_no_rotation(float* out, const float* in, uint32_t flags, int dims) {
  for (int i = 0; i < dims; ++i)
    if (at(in, i, i) == 0) return false;
  std::memcpy(out, kIdentity, sizeof(kIdentity));
  for (int i = 0; i < dims; ++i) at(out, i, i) = 1.0f / at(in, i, i);
  if (flags & kTranslation)
    for (int i = 0; i < dims; ++i) at(out, i, 3) = -(at(in, i, 3) * at(out, i, i));
  return true;
}

}  // namespace

bool MesaMatrix::geometry_flags_within(uint32_t allowed) const {
  return geometry_within(flags_, allowed);
}

bool MesaMatrix::dirty() const { return (flags_ & kDirty) != 0; }

bool MesaMatrix::length_preserving() const {
  return geometry_flags_within(kTranslation | kRotation);
}

void MesaMatrix::set_identity() {
  m_ = glm::mat4(1.0f);
  inv_ = glm::mat4(1.0f);
  type_ = Type::kIdentity;
  // Mesa keeps the geometry flags here: a later product may use the full 4x4 method although
  // the matrix is the identity.
  flags_ &= ~kDirty;
}

void MesaMatrix::load(const float* m) {
  std::memcpy(ptr(m_), m, sizeof(float) * 16);
  flags_ = kGeneral | kDirty;
}

void MesaMatrix::multiply(const float* m) {
  flags_ |= kGeneral | kDirty;
  multiply_4x4(ptr(m_), ptr(m_), m);
}

void MesaMatrix::multiply_with_flags(const float* m, uint32_t flags) {
  flags_ |= flags | kDirtyType | kDirtyInverse;
  if (geometry_flags_within(k3DFlags))
    multiply_3x4(ptr(m_), ptr(m_), m);
  else
    multiply_4x4(ptr(m_), ptr(m_), m);
}

MesaMatrix MesaMatrix::product(const MesaMatrix& a, const MesaMatrix& b) {
  MesaMatrix dest;
  dest.flags_ = a.flags_ | b.flags_ | kDirtyType | kDirtyInverse;
  if (dest.geometry_flags_within(k3DFlags))
    multiply_3x4(ptr(dest.m_), ptr(a.m_), ptr(b.m_));
  else
    multiply_4x4(ptr(dest.m_), ptr(a.m_), ptr(b.m_));
  return dest;
}

void MesaMatrix::rotate(float angle, float x, float y, float z) {
  // Mesa: the angle in radians is computed in double, then sinf/cosf of it as a float.
  const float radians = static_cast<float>(static_cast<double>(angle) * std::numbers::pi / 180.0);
  const float s = ::sinf(radians);
  const float c = ::cosf(radians);
  float m[16];
  std::memcpy(m, kIdentity, sizeof(m));
  // A rotation about a coordinate axis is written directly (the sign of the axis flips s).
  bool about_axis = false;
  if (x == 0.0f) {
    if (y == 0.0f) {
      if (z != 0.0f) {
        about_axis = true;
        at(m, 0, 0) = c;
        at(m, 1, 1) = c;
        at(m, 0, 1) = z < 0.0f ? s : -s;
        at(m, 1, 0) = z < 0.0f ? -s : s;
      }
    } else if (z == 0.0f) {
      about_axis = true;
      at(m, 0, 0) = c;
      at(m, 2, 2) = c;
      at(m, 0, 2) = y < 0.0f ? -s : s;
      at(m, 2, 0) = y < 0.0f ? s : -s;
    }
  } else if (y == 0.0f && z == 0.0f) {
    about_axis = true;
    at(m, 1, 1) = c;
    at(m, 2, 2) = c;
    at(m, 1, 2) = x < 0.0f ? s : -s;
    at(m, 2, 1) = x < 0.0f ? -s : s;
  }
  if (!about_axis) {
    const float mag = std::sqrt(x * x + y * y + z * z);
    if (mag <= 1.0e-4f) return;  // no rotation: the matrix is left as it is
    x /= mag;
    y /= mag;
    z /= mag;
    const float xx = x * x, yy = y * y, zz = z * z;
    const float xy = x * y, yz = y * z, zx = z * x;
    const float xs = x * s, ys = y * s, zs = z * s;
    const float one_c = 1.0f - c;
    at(m, 0, 0) = (one_c * xx) + c;
    at(m, 0, 1) = (one_c * xy) - zs;
    at(m, 0, 2) = (one_c * zx) + ys;
    at(m, 1, 0) = (one_c * xy) + zs;
    at(m, 1, 1) = (one_c * yy) + c;
    at(m, 1, 2) = (one_c * yz) - xs;
    at(m, 2, 0) = (one_c * zx) - ys;
    at(m, 2, 1) = (one_c * yz) + xs;
    at(m, 2, 2) = (one_c * zz) + c;
  }
  multiply_with_flags(m, kRotation);
}

void MesaMatrix::translate(float x, float y, float z) {
  float* m = ptr(m_);
  for (int r = 0; r < 4; ++r) m[12 + r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r];
  flags_ |= kTranslation | kDirtyType | kDirtyInverse;
}

void MesaMatrix::scale(float x, float y, float z) {
  float* m = ptr(m_);
  for (int r = 0; r < 4; ++r) {
    m[r] *= x;
    m[4 + r] *= y;
    m[8 + r] *= z;
  }
  if (std::fabs(x - y) < 1e-8f && std::fabs(x - z) < 1e-8f)
    flags_ |= kUniformScale;
  else
    flags_ |= kGeneralScale;
  flags_ |= kDirtyType | kDirtyInverse;
}

void MesaMatrix::frustum(float l, float r, float b, float t, float n, float f) {
  float m[16] = {};
  at(m, 0, 0) = (2.0f * n) / (r - l);
  at(m, 1, 1) = (2.0f * n) / (t - b);
  at(m, 0, 2) = (r + l) / (r - l);
  at(m, 1, 2) = (t + b) / (t - b);
  at(m, 2, 2) = -(f + n) / (f - n);
  at(m, 2, 3) = -(2.0f * f * n) / (f - n);
  at(m, 3, 2) = -1.0f;
  multiply_with_flags(m, kPerspective);
}

void MesaMatrix::ortho(float l, float r, float b, float t, float n, float f) {
  float m[16] = {};
  at(m, 0, 0) = 2.0f / (r - l);
  at(m, 0, 3) = -(r + l) / (r - l);
  at(m, 1, 1) = 2.0f / (t - b);
  at(m, 1, 3) = -(t + b) / (t - b);
  at(m, 2, 2) = -2.0f / (f - n);
  at(m, 2, 3) = -(f + n) / (f - n);
  at(m, 3, 3) = 1.0f;
  multiply_with_flags(m, kGeneralScale | kTranslation);
}

void MesaMatrix::analyse_from_scratch() {
  const float* m = ptr(m_);
  // Bit i: m[i] == 0; bits 16 + 5k (k = 0..3): diagonal element k == 1.
  constexpr auto zero = [](int i) { return uint32_t{1} << i; };
  constexpr auto one = [](int i) { return uint32_t{1} << (i + 16); };
  uint32_t mask = 0;
  for (int i = 0; i < 16; ++i)
    if (m[i] == 0.0f) mask |= zero(i);
  for (int i : {0, 5, 10, 15})
    if (m[i] == 1.0f) mask |= one(i);

  constexpr uint32_t kNoTranslation = zero(12) | zero(13) | zero(14);
  constexpr uint32_t kNo2DScale = one(0) | one(5);
  constexpr uint32_t kBottomRow = zero(3) | zero(7) | zero(11) | one(15);
  constexpr uint32_t kIdentityMask = one(0) | zero(4) | zero(8) | zero(12) | zero(1) | one(5) |
                                     zero(9) | zero(13) | zero(2) | zero(6) | one(10) | zero(14) |
                                     kBottomRow;
  constexpr uint32_t k2DNoRotMask =
      zero(4) | zero(8) | zero(1) | zero(9) | zero(2) | zero(6) | one(10) | zero(14) | kBottomRow;
  constexpr uint32_t k2DMask =
      zero(8) | zero(9) | zero(2) | zero(6) | one(10) | zero(14) | kBottomRow;
  constexpr uint32_t k3DNoRotMask =
      zero(4) | zero(8) | zero(1) | zero(9) | zero(2) | zero(6) | kBottomRow;
  constexpr uint32_t k3DMask = kBottomRow;
  constexpr uint32_t kPerspectiveMask =
      zero(4) | zero(12) | zero(1) | zero(13) | zero(2) | zero(6) | zero(3) | zero(7) | zero(15);
  constexpr float kEpsilonSquared = 1e-6f * 1e-6f;

  flags_ &= ~kGeometryFlags;
  if ((mask & kNoTranslation) != kNoTranslation) flags_ |= kTranslation;

  if (mask == kIdentityMask) {
    type_ = Type::kIdentity;
  } else if ((mask & k2DNoRotMask) == k2DNoRotMask) {
    type_ = Type::k2DNoRotation;
    if ((mask & kNo2DScale) != kNo2DScale) flags_ |= kGeneralScale;
  } else if ((mask & k2DMask) == k2DMask) {
    const float mm = dot2(m, m);
    const float m4m4 = dot2(m + 4, m + 4);
    const float mm4 = dot2(m, m + 4);
    type_ = Type::k2D;
    if (square(mm - 1) > kEpsilonSquared || square(m4m4 - 1) > kEpsilonSquared)
      flags_ |= kGeneralScale;
    flags_ |= square(mm4) > kEpsilonSquared ? kGeneral3D : kRotation;
  } else if ((mask & k3DNoRotMask) == k3DNoRotMask) {
    type_ = Type::k3DNoRotation;
    if (square(m[0] - m[5]) < kEpsilonSquared && square(m[0] - m[10]) < kEpsilonSquared) {
      if (square(m[0] - 1.0f) > kEpsilonSquared) flags_ |= kUniformScale;
    } else {
      flags_ |= kGeneralScale;
    }
  } else if ((mask & k3DMask) == k3DMask) {
    const float c1 = dot3(m, m);
    const float c2 = dot3(m + 4, m + 4);
    const float c3 = dot3(m + 8, m + 8);
    const float d1 = dot3(m, m + 4);
    type_ = Type::k3D;
    if (square(c1 - c2) < kEpsilonSquared && square(c1 - c3) < kEpsilonSquared) {
      if (square(c1 - 1.0f) > kEpsilonSquared) flags_ |= kUniformScale;
    } else {
      flags_ |= kGeneralScale;
    }
    if (square(d1) < kEpsilonSquared) {
      // A rotation if column 2 is the cross product of columns 0 and 1.
      float cp[3] = {m[1] * m[6] - m[2] * m[5], m[2] * m[4] - m[0] * m[6],
                     m[0] * m[5] - m[1] * m[4]};
      for (int i = 0; i < 3; ++i) cp[i] = cp[i] - m[8 + i];
      flags_ |= dot3(cp, cp) < kEpsilonSquared ? kRotation : kGeneral3D;
    } else {
      flags_ |= kGeneral3D;  // shear
    }
  } else if ((mask & kPerspectiveMask) == kPerspectiveMask && m[11] == -1.0f) {
    type_ = Type::kPerspective;
    flags_ |= kGeneral;
  } else {
    type_ = Type::kGeneral;
    flags_ |= kGeneral;
  }
}

void MesaMatrix::analyse_from_flags() {
  const float* m = ptr(m_);
  if (geometry_flags_within(0)) {
    type_ = Type::kIdentity;
  } else if (geometry_flags_within(kTranslation | kUniformScale | kGeneralScale)) {
    type_ = m[10] == 1.0f && m[14] == 0.0f ? Type::k2DNoRotation : Type::k3DNoRotation;
  } else if (geometry_flags_within(k3DFlags)) {
    const bool planar = m[8] == 0.0f && m[9] == 0.0f && m[2] == 0.0f && m[6] == 0.0f &&
                        m[10] == 1.0f && m[14] == 0.0f;
    type_ = planar ? Type::k2D : Type::k3D;
  } else if (m[4] == 0.0f && m[12] == 0.0f && m[1] == 0.0f && m[13] == 0.0f && m[2] == 0.0f &&
             m[6] == 0.0f && m[3] == 0.0f && m[7] == 0.0f && m[11] == -1.0f && m[15] == 0.0f) {
    type_ = Type::kPerspective;
  } else {
    type_ = Type::kGeneral;
  }
}

bool MesaMatrix::invert() {
  float* out = ptr(inv_);
  const float* in = ptr(m_);
  switch (type_) {
    case Type::kIdentity:
      std::memcpy(out, kIdentity, sizeof(kIdentity));
      return true;
    case Type::k3DNoRotation:
      return invert_no_rotation(out, in, flags_, 3);
    case Type::k2DNoRotation:
      return invert_no_rotation(out, in, flags_, 2);
    case Type::k2D:
    case Type::k3D:
      return invert_3d(out, in, flags_);
    case Type::kGeneral:
    case Type::kPerspective:
      break;
  }
  return invert_general(out, in);
}

void MesaMatrix::analyse() {
  if (flags_ & kDirtyType) {
    if (flags_ & kDirtyFlags)
      analyse_from_scratch();
    else
      analyse_from_flags();
  }
  if (flags_ & kDirtyInverse) {
    if (invert()) {
      flags_ &= ~kSingular;
    } else {
      flags_ |= kSingular;
      inv_ = glm::mat4(1.0f);
    }
    flags_ &= ~kDirtyInverse;
  }
  flags_ &= ~(kDirtyFlags | kDirtyType);
}

glm::vec4 transform_row_vector(const glm::vec4& v, const glm::mat4& m) {
  const float* p = &m[0][0];
  glm::vec4 u;
  for (int c = 0; c < 4; ++c)
    u[c] = v[0] * at(p, 0, c) + v[1] * at(p, 1, c) + v[2] * at(p, 2, c) + v[3] * at(p, 3, c);
  return u;
}

glm::vec4 transform_point(const glm::mat4& m, const glm::vec4& p) {
  const float* a = &m[0][0];
  glm::vec4 q;
  for (int r = 0; r < 4; ++r)
    q[r] = a[r] * p[0] + a[4 + r] * p[1] + a[8 + r] * p[2] + a[12 + r] * p[3];
  return q;
}

glm::vec3 transform_direction(const glm::vec3& d, const glm::mat4& m) {
  const float* a = &m[0][0];
  glm::vec3 t;
  for (int r = 0; r < 3; ++r) t[r] = d[0] * a[r] + d[1] * a[4 + r] + d[2] * a[8 + r];
  return t;
}

}  // namespace glpt
