#include "gl_shim/arrays/array_fetch.hpp"

#include <algorithm>
#include <cstring>

#include "gl/gl_enums.h"
#include "gl_shim/state/normalized_values.hpp"

namespace glpt {
namespace {

template <typename T>
T load(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// llvmpipe's vertex fetch of normalized integers (see the header).
float fetch_normalized(GLubyte c) { return float(c) * (1.0f / 255.0f); }
float fetch_normalized(GLushort c) { return float(c) * (1.0f / 65535.0f); }
float fetch_normalized(GLbyte c) { return std::max(float(c) * (1.0f / 127.0f), -1.0f); }
float fetch_normalized(GLshort c) { return std::max(float(c) * (1.0f / 32767.0f), -1.0f); }
float fetch_normalized(GLint c) { return std::max(float(c) * float(1.0 / 2147483647.0), -1.0f); }
// 32-bit unorm: the 23 high bits become a float mantissa, rescaled to reach 1.0.
float fetch_normalized(GLuint c) { return float(c >> 9) * 0x1p-23f * float(8388608.0 / 8388607.0); }
float fetch_normalized(GLfloat c) { return c; }
float fetch_normalized(GLdouble c) { return float(c); }

template <typename T, ArrayConversion C, bool N>
float component(T v) {
  if constexpr (!N)
    return float(v);
  else if constexpr (C == ArrayConversion::kVertexFetch)
    return fetch_normalized(v);
  else
    return normalized_component(v);
}

template <typename T, ArrayConversion C, bool N>
glm::vec4 element(const uint8_t* p, int size) {
  glm::vec4 out(0.0f, 0.0f, 0.0f, 1.0f);
  for (int k = 0; k < size; ++k) out[k] = component<T, C, N>(load<T>(p + size_t(k) * sizeof(T)));
  return out;
}

// element() for a whole selection, the component count known at compile time.
template <typename T, ArrayConversion C, bool N, int Size>
void gather(const uint8_t* base, size_t stride, const VertexSelection& selection, glm::vec4* out) {
  for (size_t i = 0; i < selection.count; ++i) {
    const uint8_t* p = base + size_t(selection.at(i)) * stride;
    glm::vec4 v(0.0f, 0.0f, 0.0f, 1.0f);
    for (int k = 0; k < Size; ++k) v[k] = component<T, C, N>(load<T>(p + size_t(k) * sizeof(T)));
    out[i] = v;
  }
}

template <typename T, ArrayConversion C, bool N>
ArrayReader::GatherFn gather_fn(int size) {
  switch (size) {
    case 1:
      return &gather<T, C, N, 1>;
    case 2:
      return &gather<T, C, N, 2>;
    case 3:
      return &gather<T, C, N, 3>;
    default:
      return &gather<T, C, N, 4>;
  }
}

template <typename T>
ArrayReader::GatherFn gather_fn(ArrayConversion c, bool normalized, int size) {
  if (!normalized) return gather_fn<T, ArrayConversion::kVertexFetch, false>(size);
  return c == ArrayConversion::kVertexFetch
             ? gather_fn<T, ArrayConversion::kVertexFetch, true>(size)
             : gather_fn<T, ArrayConversion::kImmediate, true>(size);
}

template <typename T>
ArrayReader::ElementFn element_fn(ArrayConversion c, bool normalized) {
  if (!normalized) return &element<T, ArrayConversion::kVertexFetch, false>;
  return c == ArrayConversion::kVertexFetch ? &element<T, ArrayConversion::kVertexFetch, true>
                                            : &element<T, ArrayConversion::kImmediate, true>;
}

// Calls f with a value of the C type of `type`, one of GL 1.5 table 2.4's (the pointer commands
// accept no other).
template <typename F>
auto with_component_type(GLenum type, F&& f) {
  switch (type) {
    case GL_BYTE:
      return f(GLbyte{});
    case GL_UNSIGNED_BYTE:
      return f(GLubyte{});
    case GL_SHORT:
      return f(GLshort{});
    case GL_UNSIGNED_SHORT:
      return f(GLushort{});
    case GL_INT:
      return f(GLint{});
    case GL_UNSIGNED_INT:
      return f(GLuint{});
    case GL_DOUBLE:
      return f(GLdouble{});
    default:
      return f(GLfloat{});
  }
}

ArrayReader::ElementFn element_fn(GLenum type, ArrayConversion c, bool normalized) {
  return with_component_type(
      type, [&](auto value) { return element_fn<decltype(value)>(c, normalized); });
}

ArrayReader::GatherFn gather_fn(GLenum type, ArrayConversion c, bool normalized, int size) {
  return with_component_type(
      type, [&](auto value) { return gather_fn<decltype(value)>(c, normalized, size); });
}

}  // namespace

ArrayReader::ArrayReader(const ClientArray& array, ArrayConversion conversion)
    : bytes_(array.orphaned ? nullptr : array.buffer, array.orphaned ? nullptr : array.pointer),
      stride_(array.effective_stride()),
      element_bytes_(array.element_bytes()),
      size_(array.size),
      element_(element_fn(array.type, conversion, array.normalized)),
      gather_(gather_fn(array.type, conversion, array.normalized, array.size)) {}

glm::vec4 ArrayReader::read(uint64_t i) const {
  const uint8_t* base = bytes_.bytes();
  if (base == nullptr) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  // Both factors are below 2^32, so the product cannot overflow.
  const uint64_t offset = i * stride_;
  if (offset > bytes_.size() || bytes_.size() - offset < element_bytes_)
    return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  return element_(base + offset, size_);
}

void ArrayReader::read(const VertexSelection& selection, glm::vec4* out) const {
  if (selection.count == 0) return;
  uint32_t last = selection.first + uint32_t(selection.count - 1);
  if (selection.list != nullptr)
    last = *std::max_element(selection.list, selection.list + selection.count);
  // Every element inside the data (the common case): no check per element.
  const uint8_t* base = bytes_.bytes();
  const uint64_t end = uint64_t{last} * stride_;
  if (base != nullptr && size_ >= 1 && size_ <= 4 && end <= bytes_.size() &&
      bytes_.size() - end >= element_bytes_)
    return gather_(base, stride_, selection, out);
  for (size_t i = 0; i < selection.count; ++i) out[i] = read(selection.at(i));
}

}  // namespace glpt
