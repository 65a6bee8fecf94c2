// The scene table's validation: what makes the runners refuse a table.
#include <gtest/gtest.h>

#include "scene.hpp"

namespace glpt::conformance {
namespace {

void draw_nothing() {}

Scene scene(const char* name, Tolerance tolerance = Tolerance{}, int width = 64, int height = 64) {
  return Scene{name, "test.cpp", width, height, tolerance, &draw_nothing};
}

TEST(SceneTable, AcceptsAValidTable) {
  const std::vector<Scene> scenes = {scene("lighting_a"),
                                     scene("lines_b", relaxed(0.9, 4, "a reason"), 128, 16)};
  EXPECT_TRUE(validate_scenes(scenes).empty());
}

TEST(SceneTable, RejectsDuplicateAndMalformedNames) {
  EXPECT_EQ(validate_scenes({scene("same"), scene("same")}).size(), 1u);
  EXPECT_EQ(validate_scenes({scene("Upper")}).size(), 1u);
  EXPECT_EQ(validate_scenes({scene("with space")}).size(), 1u);
  EXPECT_EQ(validate_scenes({scene("")}).size(), 1u);
}

TEST(SceneTable, RejectsSizesOutsideTheRange) {
  EXPECT_EQ(validate_scenes({scene("a", Tolerance{}, 15, 64)}).size(), 1u);
  EXPECT_EQ(validate_scenes({scene("a", Tolerance{}, 64, 257)}).size(), 1u);
  EXPECT_TRUE(validate_scenes({scene("a", Tolerance{}, 16, 256)}).empty());
}

TEST(SceneTable, ANonDefaultToleranceNeedsAReasonAndOnlyThen) {
  EXPECT_EQ(validate_scenes({scene("a", relaxed(0.9, 2, nullptr))}).size(), 1u);
  EXPECT_EQ(validate_scenes({scene("a", relaxed(0.995, 3, ""))}).size(), 1u);
  EXPECT_EQ(validate_scenes({scene("a", relaxed(0.995, 2, "needless"))}).size(), 1u);
  EXPECT_EQ(validate_scenes({scene("a", relaxed(1.5, 2, "out of range"))}).size(), 1u);
  EXPECT_EQ(validate_scenes({scene("a", relaxed(0.9, 256, "out of range"))}).size(), 1u);
}

TEST(SceneTable, RejectsAMissingDrawFunction) {
  Scene s = scene("a");
  s.draw = nullptr;
  EXPECT_EQ(validate_scenes({s}).size(), 1u);
}

}  // namespace
}  // namespace glpt::conformance
