#include "state_compare.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace glpt::statecompare {
namespace {

// A dump as the conformance runners write it.
const char kDump[] = R"json({
  "scene": "demo",
  "backend": "mesa",
  "error_after_scene": "GL_NO_ERROR",
  "state": {
    "glGetBooleanv(GL_DEPTH_WRITEMASK)": [true],
    "glGetIntegerv(GL_LINE_WIDTH)": [3],
    "glGetFloatv(GL_FOG_COLOR)": [0.25, 0.5, 1, 0],
    "unit1 glGetFloatv(GL_TEXTURE_MATRIX)": [1, -4.37113883e-08, 0, "nan"],
    "glGetIntegerv(GL_BOGUS)": "GL_INVALID_ENUM",
    "glGetIntegerv(GL_EMPTY)": []
  },
  "implementation": {
    "glGetIntegerv(GL_MAX_LIGHTS)": [8]
  }
}
)json";

StateDump parsed(const std::string& text) {
  StateDump dump;
  std::string error;
  EXPECT_TRUE(parse_state_dump(text, &dump, &error)) << error;
  return dump;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(StateDump, ParsesEveryValueKind) {
  const StateDump d = parsed(kDump);
  EXPECT_EQ(d.scene, "demo");
  EXPECT_EQ(d.backend, "mesa");
  EXPECT_EQ(d.error_after_scene, "GL_NO_ERROR");
  ASSERT_EQ(d.state.size(), 6u);
  EXPECT_EQ(d.state.at("glGetBooleanv(GL_DEPTH_WRITEMASK)").numbers, std::vector<double>{1.0});
  EXPECT_EQ(d.state.at("glGetFloatv(GL_FOG_COLOR)").numbers,
            (std::vector<double>{0.25, 0.5, 1, 0}));
  const Value& matrix = d.state.at("unit1 glGetFloatv(GL_TEXTURE_MATRIX)");
  ASSERT_EQ(matrix.numbers.size(), 4u);
  EXPECT_TRUE(std::isnan(matrix.numbers[3]));
  const Value& bogus = d.state.at("glGetIntegerv(GL_BOGUS)");
  EXPECT_TRUE(bogus.is_error);
  EXPECT_EQ(bogus.error, "GL_INVALID_ENUM");
  EXPECT_TRUE(d.state.at("glGetIntegerv(GL_EMPTY)").numbers.empty());
  EXPECT_EQ(d.implementation.at("glGetIntegerv(GL_MAX_LIGHTS)").numbers, std::vector<double>{8.0});
}

TEST(StateDump, RejectsMalformedInput) {
  StateDump d;
  std::string error;
  EXPECT_FALSE(parse_state_dump("", &d, &error));
  EXPECT_FALSE(parse_state_dump(R"({"scene": "x"})", &d, &error));  // no state
  EXPECT_FALSE(parse_state_dump(R"({"state": {"a": [1,]}})", &d, &error));
  EXPECT_FALSE(parse_state_dump(R"({"state": {"a": [1], "a": [2]}})", &d, &error));
  EXPECT_FALSE(parse_state_dump(R"({"state": {"a": ["text"]}})", &d, &error));
  EXPECT_FALSE(parse_state_dump(R"({"state": {}} trailing)", &d, &error));
  EXPECT_FALSE(error.empty());
}

TEST(StateCompare, FloatQueriesAreRecognisedByTheirGetter) {
  EXPECT_TRUE(is_float_query("glGetFloatv(GL_FOG_COLOR)"));
  EXPECT_TRUE(is_float_query("unit1 glGetFloatv(GL_TEXTURE_MATRIX)"));
  EXPECT_TRUE(is_float_query("glGetLightfv(GL_LIGHT0, GL_POSITION)"));
  EXPECT_TRUE(is_float_query("unit0 glGetTexGenfv(GL_S, GL_EYE_PLANE)"));
  EXPECT_TRUE(is_float_query("glGetClipPlane(GL_CLIP_PLANE0)"));
  EXPECT_FALSE(is_float_query("glGetIntegerv(GL_LINE_WIDTH)"));
  EXPECT_FALSE(is_float_query("glGetBooleanv(GL_FOG_COLOR)"));
  EXPECT_FALSE(is_float_query("unit1 glGetLightiv(GL_LIGHT0, GL_POSITION)"));
  EXPECT_FALSE(is_float_query("glIsEnabled(GL_FOG)"));
}

TEST(StateCompare, FloatToleranceIsRelativeAboveOneAndAbsoluteBelow) {
  EXPECT_TRUE(floats_match(1000.0, 1000.0009, 1e-6));
  EXPECT_FALSE(floats_match(1000.0, 1000.0011, 1e-6));
  EXPECT_TRUE(floats_match(0.0, -4.37e-8, 1e-6));
  EXPECT_FALSE(floats_match(0.0, 2e-6, 1e-6));
  EXPECT_TRUE(floats_match(INFINITY, INFINITY, 1e-6));
  EXPECT_FALSE(floats_match(INFINITY, 1e300, 1e-6));
}

TEST(StateCompare, IdenticalDumpsMatch) {
  EXPECT_TRUE(compare_states(parsed(kDump), parsed(kDump)).empty());
}

TEST(StateCompare, IntegersAndBooleansAreExactFloatsTolerant) {
  const StateDump ref = parsed(kDump);
  // A float within 1e-6 and a tiny value instead of exactly 0: no mismatch.
  const StateDump close =
      parsed(replaced(replaced(kDump, "0.25, 0.5", "0.2500001, 0.5"), "-4.37113883e-08", "0"));
  EXPECT_TRUE(compare_states(ref, close).empty());

  const StateDump int_off = parsed(replaced(kDump, "[3]", "[2]"));
  const auto m = compare_states(ref, int_off);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].key, "glGetIntegerv(GL_LINE_WIDTH)");
  EXPECT_EQ(m[0].reference, "[3]");
  EXPECT_EQ(m[0].test, "[2]");

  EXPECT_EQ(compare_states(ref, parsed(replaced(kDump, "[true]", "[false]"))).size(), 1u);
  EXPECT_EQ(compare_states(ref, parsed(replaced(kDump, "0.25, 0.5", "0.26, 0.5"))).size(), 1u);
  EXPECT_EQ(compare_states(ref, parsed(replaced(kDump, "\"nan\"", "0"))).size(), 1u);
}

TEST(StateCompare, ErrorsMissingKeysAndTheSceneErrorAreMismatches) {
  const StateDump ref = parsed(kDump);
  // A query that works in one and raises an error in the other.
  EXPECT_EQ(compare_states(ref, parsed(replaced(kDump, "\"GL_INVALID_ENUM\"", "[0]"))).size(), 1u);
  EXPECT_EQ(compare_states(ref, parsed(replaced(kDump, "[3]", "\"GL_INVALID_ENUM\""))).size(), 1u);
  // A key only one side has: reported once from each side.
  const StateDump renamed = parsed(replaced(kDump, "GL_LINE_WIDTH", "GL_POINT_SIZE"));
  const auto m = compare_states(ref, renamed);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].test, "(missing)");
  EXPECT_EQ(m[1].reference, "(missing)");
  // The error the scene left.
  const auto e =
      compare_states(ref, parsed(replaced(kDump, "\"GL_NO_ERROR\"", "\"GL_INVALID_OPERATION\"")));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].key, "error_after_scene");
  // Different value counts.
  EXPECT_EQ(compare_states(ref, parsed(replaced(kDump, "[3]", "[3, 3]"))).size(), 1u);
  // Implementation-dependent values are not compared.
  EXPECT_TRUE(compare_states(ref, parsed(replaced(kDump, "[8]", "[16]"))).empty());
}

TEST(StateCompare, KnownDifferencesAcceptOnlyTheQueriesTheyName) {
  std::vector<KnownDifference> known;
  std::string error;
  ASSERT_TRUE(parse_known_differences(
      "# comment\n\nglGetIntegerv\\(GL_[A-Z]+_MATRIX\\)  the spec rounds matrices\n", &known,
      &error))
      << error;
  ASSERT_EQ(known.size(), 1u);
  EXPECT_EQ(known[0].reason, "the spec rounds matrices");
  EXPECT_NE(find_known(known, {"unit2 glGetIntegerv(GL_TEXTURE_MATRIX)", "", ""}), nullptr);
  EXPECT_EQ(find_known(known, {"glGetFloatv(GL_TEXTURE_MATRIX)", "", ""}), nullptr);
  EXPECT_EQ(find_known(known, {"glGetIntegerv(GL_VIEWPORT)", "", ""}), nullptr);
  // Each line needs a reason, and a valid regex.
  known.clear();
  EXPECT_FALSE(parse_known_differences("GL_FOO\n", &known, &error));
  EXPECT_FALSE(parse_known_differences("GL_(FOO  reason\n", &known, &error));
}

}  // namespace
}  // namespace glpt::statecompare
