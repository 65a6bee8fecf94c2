// Reading elements of client arrays as the floats GL draws with (GL 1.5 2.8, table 2.9).
//
// Mesa converts array data two ways, and glpt reproduces both bit for bit:
//   kVertexFetch  glDrawArrays, glDrawElements and the other array draws: llvmpipe's vertex fetch
//                 (gallivm): unsigned bytes and shorts c * (1/255.0f), c * (1/65535.0f); signed
//                 c * (1/127.0f), c * (1/32767.0f), c * (1/2147483647.0f) clamped to -1 (not
//                 GL 1.5's (2c + 1) / (2^b - 1)); unsigned ints from their 23 high bits.
//   kImmediate    glArrayElement, and array draws compiled into display lists (Mesa compiles them
//                 as glBegin, glArrayElement per vertex, glEnd): the conversions of glColor*v,
//                 glNormal*v, ... (state/normalized_values.hpp).
// Both were measured against OSMesa 25.0.7 (every 8- and 16-bit value, 400000 random 32-bit ones;
// tests/unit/array_conversion_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gl_shim/arrays/vertex_arrays.hpp"
#include "gl_shim/buffers/buffer_objects.hpp"
#include "gl_shim/gl_types.h"

namespace glpt {

enum class ArrayConversion : uint8_t { kVertexFetch, kImmediate };

// The vertex numbers a draw reads: `list[i]` when a list is given, else `first + i`; i < count.
struct VertexSelection {
  const uint32_t* list = nullptr;
  uint32_t first = 0;
  size_t count = 0;

  static VertexSelection range(uint32_t first, size_t count) { return {nullptr, first, count}; }
  static VertexSelection of(const std::vector<uint32_t>& vertices) {
    return {vertices.data(), 0, vertices.size()};
  }
  uint32_t at(size_t i) const { return list != nullptr ? list[i] : first + uint32_t(i); }
};

// Reads the elements of one client array.
class ArrayReader {
 public:
  ArrayReader(const ClientArray& array, ArrayConversion conversion);
  ArrayReader(const ArrayReader&) = delete;
  ArrayReader& operator=(const ArrayReader&) = delete;

  // Element `i`; components the array does not have are (0, 0, 0, 1). Elements outside a buffer
  // object's store, and every element of an array without data (a null pointer, an orphaned
  // offset), read (0, 0, 0, 1) too.
  glm::vec4 read(uint64_t i) const;
  // read(selection.at(i)) into out[i] for every i: one call for a draw's vertices, the
  // conversion chosen once (a draw of 100 000 triangles reads 300 000 elements per array).
  void read(const VertexSelection& selection, glm::vec4* out) const;

  using ElementFn = glm::vec4 (*)(const uint8_t* element, int size);
  using GatherFn = void (*)(const uint8_t* base, size_t stride, const VertexSelection& selection,
                            glm::vec4* out);

 private:
  ArrayBytes bytes_;
  size_t stride_;
  size_t element_bytes_;
  int size_;
  ElementFn element_;
  GatherFn gather_;
};

}  // namespace glpt
