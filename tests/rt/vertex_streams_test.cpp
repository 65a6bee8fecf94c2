// The record's shared vertex streams (rt_core/raster/vertex_streams.hpp): the draws they take lie
// back to back, one stream per attribute any of them gives, a draw's single value (or the
// attribute's default) repeated over its vertices; nothing is written for a draw not counted.
#include "rt_core/raster/vertex_streams.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "raster_types.h"
#include "rt_core/raster/raster_recording.hpp"
#include "rt_core/raster/resident_geometry.hpp"

namespace glpt::rt {
namespace {

// The renderer's defaults, laid out as for_each_attribute's default_at expects.
const glm::vec4 kDefaults[] = {glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 1, 0), glm::vec4(1.0f),
                               glm::vec4(0, 0, 0, 1), glm::vec4(0.0f)};
const auto* kDefaultBytes = reinterpret_cast<const uint8_t*>(kDefaults);

rec::VertexData triangle_fan(uint32_t n, float x) {
  rec::VertexData v;
  v.mode = GL_TRIANGLE_FAN;
  for (uint32_t i = 0; i < n; ++i) v.position.push_back(glm::vec4(x + float(i), 0, 0, 1));
  v.primitives.push_back({0, n});
  return v;
}

template <typename T>
T read(const std::vector<uint8_t>& bytes, VkDeviceSize at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

TEST(VertexStreams, DrawsLieBackToBackWithSingleValuesRepeatedPerVertex) {
  rec::VertexData a = triangle_fan(3, 0.0f);
  a.normal = {glm::vec3(0, 0, -1)};  // one normal for the whole draw
  rec::VertexData b = triangle_fan(2, 10.0f);
  b.normal = {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  b.color = {glm::vec4(0.5f, 0.25f, 0.125f, 1.0f)};  // a has no colour: the default
  ASSERT_TRUE(VertexStreams::takes(a));
  ASSERT_TRUE(VertexStreams::takes(b));

  std::vector<uint8_t> local;
  Arena arena(local);
  const VkDeviceSize default_offset = arena.add(kDefaults, std::size(kDefaults));
  VertexStreams streams;
  streams.count(a);
  streams.count(b);
  ASSERT_TRUE(streams.reserve(arena));
  EXPECT_EQ(streams.add(a, arena, kDefaultBytes), 0);
  EXPECT_EQ(streams.add(b, arena, kDefaultBytes), 3);  // b's vertexOffset
  EXPECT_FALSE(streams.fits(1));                       // all that was counted is placed

  std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT> offsets{}, strides{};
  streams.locate(default_offset, offsets, strides);
  EXPECT_EQ(strides[GLPT_RASTER_ATTR_POSITION], sizeof(glm::vec4));
  EXPECT_EQ(strides[GLPT_RASTER_ATTR_NORMAL], sizeof(glm::vec3));
  EXPECT_EQ(strides[GLPT_RASTER_ATTR_COLOR], sizeof(glm::vec4));
  // No draw gives texture coordinates: the default, stride 0.
  EXPECT_EQ(strides[GLPT_RASTER_ATTR_TEXCOORD0], 0u);
  EXPECT_EQ(offsets[GLPT_RASTER_ATTR_TEXCOORD0], default_offset + 48);

  std::vector<uint8_t> buffer(arena.size());
  arena.write_to(buffer.data());
  for (uint32_t i = 0; i < 5; ++i)
    EXPECT_EQ(read<glm::vec4>(buffer, offsets[GLPT_RASTER_ATTR_POSITION] + 16 * i).x,
              i < 3 ? float(i) : 10.0f + float(i - 3));
  const glm::vec3 normals[] = {glm::vec3(0, 0, -1), glm::vec3(0, 0, -1), glm::vec3(0, 0, -1),
                               glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  for (uint32_t i = 0; i < 5; ++i)
    EXPECT_EQ(read<glm::vec3>(buffer, offsets[GLPT_RASTER_ATTR_NORMAL] + 12 * i), normals[i]);
  for (uint32_t i = 0; i < 5; ++i)
    EXPECT_EQ(read<glm::vec4>(buffer, offsets[GLPT_RASTER_ATTR_COLOR] + 16 * i),
              i < 3 ? glm::vec4(1.0f) : glm::vec4(0.5f, 0.25f, 0.125f, 1.0f));
}

TEST(VertexStreams, PlacesNothingForADrawThatWasNotCounted) {
  const rec::VertexData a = triangle_fan(3, 0.0f);
  const rec::VertexData b = triangle_fan(4, 5.0f);
  std::vector<uint8_t> local;
  Arena arena(local);
  VertexStreams streams;
  EXPECT_FALSE(streams.fits(1));  // nothing reserved yet
  streams.count(a);
  ASSERT_TRUE(streams.reserve(arena));
  EXPECT_EQ(streams.add(a, arena, kDefaultBytes), 0);
  const size_t size = arena.size();
  EXPECT_FALSE(streams.fits(b.vertex_count()));
  EXPECT_EQ(streams.add(b, arena, kDefaultBytes), 0);
  EXPECT_EQ(arena.size(), size);
  std::vector<uint8_t> buffer(arena.size());
  arena.write_to(buffer.data());  // no piece reaches past the streams (ASan would tell)
}

TEST(VertexStreams, TakesSmallDrawsWithoutPerVertexMaterials) {
  rec::VertexData v = triangle_fan(4, 0.0f);
  EXPECT_TRUE(VertexStreams::takes(v));
  v.color = {glm::vec4(1.0f), glm::vec4(0.5f)};  // neither one value nor one per vertex
  EXPECT_FALSE(VertexStreams::takes(v));
  v.color.clear();
  v.material.resize(4);  // glMaterial between glBegin and glEnd: found by gl_VertexIndex
  EXPECT_FALSE(VertexStreams::takes(v));
  v.material.clear();
  v.position.resize(ResidentGeometry::kMinBytes / sizeof(glm::vec4));  // big: read in place
  EXPECT_FALSE(VertexStreams::takes(v));
  EXPECT_FALSE(VertexStreams::takes(rec::VertexData{}));  // no vertices
}

}  // namespace
}  // namespace glpt::rt
