// common/content_hash.hpp: equal contents hash equal, and a change anywhere in a long array (the
// lanes of the bulk loop, the words after it, the tail) changes the hash.
#include "common/content_hash.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace glpt {
namespace {

uint64_t hash_of(const std::vector<unsigned char>& bytes) {
  ContentHash h;
  h.add_bytes(bytes.data(), bytes.size());
  return h.value();
}

TEST(ContentHash, EqualBytesHashEqualAndEveryByteCounts) {
  for (size_t size : {0u, 7u, 8u, 63u, 64u, 100u, 1027u}) {
    std::vector<unsigned char> bytes(size);
    for (size_t i = 0; i < size; ++i) bytes[i] = static_cast<unsigned char>(i * 37 + 11);
    const uint64_t base = hash_of(bytes);
    EXPECT_EQ(hash_of(bytes), base);
    for (size_t i = 0; i < size; ++i) {
      std::vector<unsigned char> changed = bytes;
      changed[i] ^= 1;
      EXPECT_NE(hash_of(changed), base) << "size " << size << " byte " << i;
    }
  }
}

TEST(ContentHash, LanesAreNotInterchangeable) {
  // Two 8-byte words swapped between lanes of the bulk loop.
  std::vector<unsigned char> a(64, 0), b(64, 0);
  a[0] = 1;
  b[8] = 1;
  EXPECT_NE(hash_of(a), hash_of(b));
}

TEST(ContentHash, LengthCounts) {
  EXPECT_NE(hash_of(std::vector<unsigned char>(64, 0)), hash_of(std::vector<unsigned char>(72, 0)));
}

}  // namespace
}  // namespace glpt
