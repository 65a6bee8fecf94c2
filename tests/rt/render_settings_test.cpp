#include "rt_core/render_settings.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace glpt::rt {
namespace {

RenderSettings parse(const std::map<std::string, std::string>& environment, std::string* warning) {
  return parse_render_settings(
      [&](const char* name) -> const char* {
        auto found = environment.find(name);
        return found == environment.end() ? nullptr : found->second.c_str();
      },
      warning);
}

TEST(RenderSettings, DefaultsWhenUnset) {
  std::string warning = "stale";
  RenderSettings settings = parse({}, &warning);
  EXPECT_TRUE(warning.empty());
  EXPECT_EQ(settings.samples_per_pixel, 1u);
  EXPECT_EQ(settings.bounces, 1u);
  EXPECT_TRUE(settings.accumulate);
  EXPECT_EQ(settings.max_accumulated, 4096u);
  EXPECT_EQ(settings.light_angular_radius_deg, 1.0f);
  EXPECT_FALSE(settings.validation);
}

// Timestamp queries only where something reports the times they measure (RenderSettings::
// device_timing): on lavapipe they made every glReadPixels wait for llvmpipe's threads.
TEST(RenderSettings, DeviceTimingOnlyWhenTimesAreReported) {
  std::string warning;
  EXPECT_FALSE(parse({}, &warning).device_timing);
  EXPECT_FALSE(parse({{"GLPT_STATS", "0"}, {"GLPT_STATS_FILE", ""}}, &warning).device_timing);
  EXPECT_TRUE(parse({{"GLPT_STATS", "1"}}, &warning).device_timing);
  EXPECT_TRUE(parse({{"GLPT_STATS_FILE", "/tmp/stats"}}, &warning).device_timing);
  EXPECT_TRUE(parse({{"GLPT_DUMP_SCENE", "/tmp/scene.json"}}, &warning).device_timing);
  EXPECT_TRUE(parse({{"GLPT_DEVICE_TIMING", "1"}}, &warning).device_timing);
  EXPECT_FALSE(parse({{"GLPT_STATS", "1"}, {"GLPT_DEVICE_TIMING", "0"}}, &warning).device_timing);
  EXPECT_TRUE(warning.empty());
  // Code that makes its own settings (tests, benchmarks) times its passes unless it says not to.
  EXPECT_TRUE(RenderSettings{}.device_timing);
}

TEST(RenderSettings, ReadsValidValues) {
  std::string warning;
  RenderSettings settings = parse({{"GLPT_SPP", "4"},
                                   {"GLPT_BOUNCES", "0"},
                                   {"GLPT_ACCUMULATE", "0"},
                                   {"GLPT_MAX_SPP", "64"},
                                   {"GLPT_LIGHT_SIZE_DEG", "2.5"},
                                   {"GLPT_SCALE", "0.75"},
                                   {"GLPT_VALIDATION", "1"}},
                                  &warning);
  EXPECT_TRUE(warning.empty()) << warning;
  EXPECT_EQ(settings.samples_per_pixel, 4u);
  EXPECT_EQ(settings.bounces, 0u);
  EXPECT_FALSE(settings.accumulate);
  EXPECT_EQ(settings.max_accumulated, 64u);
  EXPECT_EQ(settings.light_angular_radius_deg, 2.5f);
  EXPECT_EQ(settings.trace_scale, 0.75f);
  EXPECT_TRUE(settings.validation);
}

TEST(RenderSettings, BadValuesKeepDefaultsAndWarnOnce) {
  std::string warning;
  RenderSettings settings = parse({{"GLPT_SPP", "0"},
                                   {"GLPT_BOUNCES", "-1"},
                                   {"GLPT_ACCUMULATE", "yes"},
                                   {"GLPT_MAX_SPP", "x"},
                                   {"GLPT_LIGHT_SIZE_DEG", "nan"},
                                   {"GLPT_SCALE", "0.1"}},
                                  &warning);
  EXPECT_EQ(settings.samples_per_pixel, 1u);
  EXPECT_EQ(settings.bounces, 1u);
  EXPECT_TRUE(settings.accumulate);
  EXPECT_EQ(settings.max_accumulated, 4096u);
  EXPECT_EQ(settings.light_angular_radius_deg, 1.0f);
  EXPECT_EQ(settings.trace_scale, 1.0f);
  for (const char* name : {"GLPT_SPP", "GLPT_BOUNCES", "GLPT_ACCUMULATE", "GLPT_MAX_SPP",
                           "GLPT_LIGHT_SIZE_DEG", "GLPT_SCALE"}) {
    EXPECT_NE(warning.find(name), std::string::npos) << name << " missing from: " << warning;
  }
  EXPECT_EQ(warning.find('\n'), std::string::npos);  // one line
}

TEST(RenderSettings, LightTransportKnobs) {
  std::string warning;
  RenderSettings defaults = parse({}, &warning);
  EXPECT_TRUE(defaults.shadows);
  EXPECT_TRUE(defaults.ambient_occlusion);
  EXPECT_EQ(defaults.ao_radius, 0.0f);
  EXPECT_LT(defaults.light_radius, 0.0f);  // automatic
  EXPECT_EQ(defaults.unlit, UnlitPolicy::kKeep);
  EXPECT_FALSE(defaults.default_light);
  EXPECT_EQ(defaults.environment, Environment::kBlack);
  EXPECT_EQ(defaults.light_choice, LightChoice::kContribution);
  EXPECT_EQ(defaults.reference_samples, 0u);
  EXPECT_FALSE(defaults.gl_parity());

  RenderSettings set = parse({{"GLPT_SHADOWS", "0"},
                              {"GLPT_AO", "0"},
                              {"GLPT_BOUNCES", "0"},
                              {"GLPT_AO_RADIUS", "2.5"},
                              {"GLPT_LIGHT_RADIUS", "0"},
                              {"GLPT_UNLIT", "emit"},
                              {"GLPT_DEFAULT_LIGHT", "1"},
                              {"GLPT_ENVIRONMENT", "clear"},
                              {"GLPT_LIGHT_CHOICE", "all"},
                              {"GLPT_REFERENCE", "1024"}},
                             &warning);
  EXPECT_TRUE(warning.empty()) << warning;
  EXPECT_TRUE(set.gl_parity());
  EXPECT_EQ(set.ao_radius, 2.5f);
  EXPECT_EQ(set.light_radius, 0.0f);
  EXPECT_EQ(set.unlit, UnlitPolicy::kEmit);
  EXPECT_TRUE(set.default_light);
  EXPECT_EQ(set.environment, Environment::kClear);
  EXPECT_EQ(set.light_choice, LightChoice::kAll);
  EXPECT_EQ(set.reference_samples, 1024u);

  RenderSettings bad = parse({{"GLPT_UNLIT", "glow"},
                              {"GLPT_AO_RADIUS", "-1"},
                              {"GLPT_LIGHT_RADIUS", "inf"},
                              {"GLPT_ENVIRONMENT", "sky"},
                              {"GLPT_REFERENCE", "100000000"}},
                             &warning);
  EXPECT_EQ(bad.unlit, UnlitPolicy::kKeep);
  EXPECT_EQ(bad.ao_radius, 0.0f);
  EXPECT_LT(bad.light_radius, 0.0f);
  EXPECT_EQ(bad.environment, Environment::kBlack);
  EXPECT_EQ(bad.reference_samples, 0u);
  for (const char* name :
       {"GLPT_UNLIT", "GLPT_AO_RADIUS", "GLPT_LIGHT_RADIUS", "GLPT_ENVIRONMENT", "GLPT_REFERENCE"})
    EXPECT_NE(warning.find(name), std::string::npos) << name << " missing from: " << warning;
}

}  // namespace
}  // namespace glpt::rt
