#include "rt_core/scene/scene_dump.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace glpt::rt {
namespace {

std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() /
          (std::string(name) + "." +
           std::to_string(::testing::UnitTest::GetInstance()->random_seed())))
      .string();
}

TEST(SceneDump, WritesAndReadsBack) {
  SceneDump dump;
  dump.frame = 7;
  dump.width = 320;
  dump.height = 240;
  dump.viewport = {0, 0, 320, 240};
  for (int i = 0; i < 16; ++i) dump.projection[i] = static_cast<float>(i) * 0.5f;
  dump.camera_valid = 1;
  dump.samples = 1;
  dump.bounces = 1;
  dump.options = 3;
  dump.rays = 123456;
  dump.trace_ms = 42.5;
  dump.shapes.push_back({{0, 0, 0, 1, 0, 0, 0, 1, 0}});
  dump.shapes.push_back({{0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 1, 1, 2, 1, 1, 1, 2, 1}});
  SceneDumpInstance a;
  a.shape = 1;
  a.mask = 0x81;
  a.flags = 5;
  SceneDumpInstance b;
  b.shape = 0;
  b.mask = 0x80;
  b.transform = {2, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, -5};  // x scaled by 2, moved by (10, 0, -5)
  dump.instances = {a, b};
  place_instances(dump);
  ASSERT_EQ(dump.triangle_count(), 3u);
  EXPECT_EQ(dump.instances[1].first_triangle, 2u);
  EXPECT_EQ(dump.instances[1].triangle_count, 1u);
  // Instance b's second vertex (1, 0, 0) lands at (12, 0, -5).
  EXPECT_FLOAT_EQ(dump.eye_triangles[18 + 3], 12.0f);
  EXPECT_FLOAT_EQ(dump.eye_triangles[18 + 5], -5.0f);
  dump.lights.push_back({{1, 2, 3, 1}, 0.25f, 0x01});

  const std::string path = temp_path("glpt_scene_dump_test");
  std::string error;
  ASSERT_TRUE(write_scene_dump(path, dump, &error)) << error;
  SceneDump read;
  ASSERT_TRUE(read_scene_dump(path, read, &error)) << error;
  EXPECT_EQ(read.frame, 7u);
  EXPECT_EQ(read.viewport, dump.viewport);
  EXPECT_EQ(read.projection, dump.projection);
  EXPECT_EQ(read.rays, 123456u);
  EXPECT_DOUBLE_EQ(read.trace_ms, 42.5);
  ASSERT_EQ(read.shapes.size(), 2u);
  EXPECT_EQ(read.shapes[1].positions, dump.shapes[1].positions);
  ASSERT_EQ(read.instances.size(), 2u);
  EXPECT_EQ(read.instances[0].mask, 0x81u);
  EXPECT_EQ(read.instances[0].flags, 5u);
  EXPECT_EQ(read.instances[1].transform, b.transform);
  EXPECT_EQ(read.eye_triangles, dump.eye_triangles);
  ASSERT_EQ(read.lights.size(), 1u);
  EXPECT_FLOAT_EQ(read.lights[0].radius, 0.25f);
  EXPECT_EQ(read.lights[0].shadow_mask, 0x01u);

  // A truncated file is refused, not half read.
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 4);
  EXPECT_FALSE(read_scene_dump(path, read, &error));
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  std::filesystem::remove(path);
  EXPECT_FALSE(read_scene_dump(path, read, &error));
}

}  // namespace
}  // namespace glpt::rt
