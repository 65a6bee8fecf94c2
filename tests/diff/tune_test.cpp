// glpt tune's model (replay/cli/tune.hpp): the grid it sweeps, the Pareto front, the choice
// within a bound, the stats lines it reads; and relMSE (replay/diff/psnr.hpp).
#include "tune.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "psnr.hpp"
#include "quality_flags.hpp"

namespace glpt::cli {
namespace {

TEST(TuneGrid, EverySettingIsGlptsOwnFlagsAndNamedOnce) {
  for (const bool full : {false, true}) {
    const std::vector<TunePoint> grid = tune_grid(full, 8);
    std::set<std::string> names;
    for (const TunePoint& p : grid) {
      EXPECT_TRUE(names.insert(p.name).second) << "two settings named " << p.name;
      // Each flag is one `glpt run` accepts, with a value it accepts.
      std::vector<std::string> args;
      for (const auto& [flag, value] : p.flags) {
        args.push_back(flag);
        if (!value.empty()) args.push_back(value);
      }
      EnvSettings env;
      for (size_t i = 0; i < args.size();) {
        std::string error;
        ASSERT_EQ(parse_quality_flag(args, &i, &env, &error), FlagParse::kParsed)
            << p.name << ": " << error;
      }
      // Accumulation on exactly for the accumulation points.
      const EnvSettings point_env = tune_point_environment(p);
      ASSERT_FALSE(point_env.empty());
      EXPECT_EQ(point_env.back().first, "GLPT_ACCUMULATE");
      EXPECT_EQ(point_env.back().second, p.accumulate_frames > 0 ? "1" : "0") << p.name;
    }
    // What the issue asks to sweep: each knob is moved somewhere in the grid.
    for (const char* knob : {"--spp", "--bounces", "--shadows", "--ao", "--unlit", "--denoiser",
                             "--denoise-iterations", "--scale", "--mode"}) {
      EXPECT_TRUE(std::any_of(grid.begin(), grid.end(),
                              [&](const TunePoint& p) {
                                return std::any_of(p.flags.begin(), p.flags.end(),
                                                   [&](const auto& f) { return f.first == knob; });
                              }))
          << knob << " is not swept (full=" << full << ")";
    }
    EXPECT_TRUE(std::any_of(grid.begin(), grid.end(),
                            [](const TunePoint& p) { return p.accumulate_frames == 8; }));
    EXPECT_TRUE(names.count("default"));
    // No setting is measured twice under two names (flags as a set, defaults left out).
    std::set<std::set<std::pair<std::string, std::string>>> settings;
    for (const TunePoint& p : grid) {
      if (p.accumulate_frames != 0) continue;
      EXPECT_TRUE(settings.insert({p.flags.begin(), p.flags.end()}).second)
          << p.name << " repeats another setting";
    }
  }
  EXPECT_EQ(tune_grid(false, 8).size(), 15u);
  EXPECT_GT(tune_grid(true, 8).size(), 30u);
  // Accumulation lengths 2, 4, 8 in the full grid; none beyond the history window.
  size_t accumulation_points = 0;
  for (const TunePoint& p : tune_grid(true, 8)) {
    EXPECT_LE(p.accumulate_frames, 8u);
    accumulation_points += p.accumulate_frames > 0 ? 1 : 0;
  }
  EXPECT_EQ(accumulation_points, 3u);
}

TEST(TuneGrid, FlagsPrintAsGlptRunTakesThem) {
  TunePoint p{"spp4-raw", {{"--spp", "4"}, {"--denoiser", "off"}}, 0};
  EXPECT_EQ(tune_point_flags(p), "--spp 4 --denoiser off --no-accumulate");
  const EnvSettings env = tune_point_environment(p);
  ASSERT_EQ(env.size(), 3u);
  EXPECT_EQ(env[0], (std::pair<std::string, std::string>{"GLPT_SPP", "4"}));
  EXPECT_EQ(env[1], (std::pair<std::string, std::string>{"GLPT_DENOISER", "off"}));
}

TuneResult result(const char* name, double ms, double flip) {
  TuneResult r;
  r.name = name;
  r.frame_ms = ms;
  r.flip = flip;
  return r;
}

TEST(TunePareto, TheFrontHasNoSettingBeatenInBothTimeAndError) {
  std::vector<TuneResult> r = {result("fast-bad", 1, 0.3),   result("slow-good", 100, 0.01),
                               result("dominated", 50, 0.2), result("middle", 10, 0.05),
                               result("tie", 10, 0.05),      result("failed", 0.1, 0.0)};
  r[5].failure = "crashed";
  mark_pareto_front(r);
  EXPECT_TRUE(r[0].pareto);
  EXPECT_TRUE(r[1].pareto);
  EXPECT_FALSE(r[2].pareto);  // "middle" is faster and better
  EXPECT_TRUE(r[3].pareto);   // equal results do not dominate each other
  EXPECT_TRUE(r[4].pareto);
  EXPECT_FALSE(r[5].pareto);  // failures never count, nor do they push others off
}

TEST(TunePareto, ChoosesTheLeastErrorWithinABudgetAndTheFastestWithinABound) {
  std::vector<TuneResult> r = {result("a", 5, 0.2), result("b", 20, 0.05), result("c", 80, 0.02)};
  EXPECT_EQ(choose_within(r, 25.0, std::nullopt), 1u);
  EXPECT_EQ(choose_within(r, 1000.0, std::nullopt), 2u);
  EXPECT_EQ(choose_within(r, std::nullopt, 0.1), 1u);
  EXPECT_EQ(choose_within(r, std::nullopt, 0.5), 0u);
  // Nothing meets it: no choice, and the closest are the fastest (budget) or most accurate.
  EXPECT_FALSE(choose_within(r, 1.0, std::nullopt).has_value());
  EXPECT_FALSE(choose_within(r, std::nullopt, 0.001).has_value());
  EXPECT_EQ(closest_to_bound(r, true, 2), (std::vector<size_t>{0, 1}));
  EXPECT_EQ(closest_to_bound(r, false, 5), (std::vector<size_t>{2, 1, 0}));
  EXPECT_TRUE(closest_to_bound({}, true, 3).empty());
}

TEST(TuneStats, ReadsTheNumbersOfAStatsLine) {
  const auto v = parse_stats_line(
      "glpt: frame=3 size=320x240 trace_ms=251.70 rays=123864 classes=static:17 denoised=1");
  EXPECT_DOUBLE_EQ(v.at("frame"), 3);
  EXPECT_DOUBLE_EQ(v.at("trace_ms"), 251.70);
  EXPECT_DOUBLE_EQ(v.at("rays"), 123864);
  EXPECT_FALSE(v.count("size"));
  EXPECT_FALSE(v.count("classes"));
  EXPECT_TRUE(parse_stats_line("glpt: totals gl_errors=0").empty());
  EXPECT_TRUE(parse_stats_line("").empty());
  EXPECT_TRUE(parse_stats_line("glpt: frame=").empty());
  EXPECT_FALSE(parse_stats_line("glpt: frame=1 trace_ms=nan").count("trace_ms"));
  EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2);
  EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ(median({}), 0);
}

TEST(TuneStats, ReadsTheFrameCountOfGlptReplaysSummary) {
  EXPECT_EQ(frames_in_replay_log("glpt-replay: 9017652 calls, 1838 frames, 0 rendered, in 88 s\n"
                                 "glpt-replay: calls the replayer does not know:\n"
                                 "glpt-replay: 36 GL calls without a current context skipped\n"),
            1838u);
  EXPECT_EQ(frames_in_replay_log("glpt-replay: 0 calls, 0 frames, 0 rendered\n"), 0u);
  EXPECT_FALSE(frames_in_replay_log("glpt-replay: cannot open x.trace\n").has_value());
  EXPECT_FALSE(frames_in_replay_log("").has_value());
}

TEST(RelMse, WeighsErrorsByTheReferencesBrightness) {
  const uint8_t black[3] = {0, 0, 0}, grey[3] = {51, 51, 51}, white[3] = {255, 255, 255};
  auto view = [](const uint8_t* p) { return diff::Rgb8View{1, 1, 3, p}; };
  EXPECT_DOUBLE_EQ(diff::relmse_rgb8(view(grey), view(grey)), 0.0);
  // (0.2 - 0)^2 / (0 + 0.01) = 4 against black; (0.2 - 1)^2 / (1 + 0.01) against white.
  EXPECT_NEAR(diff::relmse_rgb8(view(grey), view(black)), 4.0, 1e-9);
  EXPECT_NEAR(diff::relmse_rgb8(view(grey), view(white)), 0.64 / 1.01, 1e-9);
}

}  // namespace
}  // namespace glpt::cli
