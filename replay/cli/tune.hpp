// `glpt tune`'s model, free of I/O: the settings it sweeps (each a set of glpt's own quality
// flags, so what it recommends is exactly what `glpt run` accepts), what one measured setting
// produced, the Pareto front of time against error, and the choice within a budget or an error
// bound. tune_command.cpp runs the sweep; docs/BENCHMARKS.md describes it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "quality_flags.hpp"

namespace glpt::cli {

// One setting of the sweep.
struct TunePoint {
  std::string name;  // "spp4", "scale0.5": a CSV key and a plot label
  // glpt's quality flags and their values ("--spp", "4"); a switch has an empty value.
  std::vector<std::pair<std::string, std::string>> flags;
  // Accumulation over this many still frames (GLPT_ACCUMULATE=1 with a history window of this
  // many frames); 0: accumulation off, every frame pays for its own samples.
  uint32_t accumulate_frames = 0;
};

// The sweep: `full` false is the reduced grid (each knob moved alone from the defaults, 15
// points), true the full one (49: also samples x bounces x denoiser, more values of each knob).
// Accumulation points are made for k in {2, 4, 8, ...} up to `history_window` frames.
std::vector<TunePoint> tune_grid(bool full, uint32_t history_window);

// The environment variables of `point` (through the quality-flag table) and the equivalent
// `glpt run` flags as one line ("--spp 4 --denoiser off"; "(defaults)" for none).
EnvSettings tune_point_environment(const TunePoint& point);
std::string tune_point_flags(const TunePoint& point);

// What one setting measured over the sweep's frames.
struct TuneResult {
  std::string name;
  std::string flags;          // tune_point_flags
  uint32_t timed_frames = 0;  // frames whose times make up the medians
  double frame_ms = 0;        // median ms per frame (GLPT_STATS' total_ms)
  // Median ms per pass (device time from Vulkan timestamp queries) and rays per second in the
  // trace pass (rays / trace_ms).
  std::map<std::string, double> pass_ms;
  double mrays_per_s = 0;
  // Error against the reference, the mean over the compared frames.
  uint32_t compared_frames = 0;
  double flip = 0, relmse = 0, psnr_db = 0;
  bool pareto = false;  // on the front of (frame_ms, flip)
  std::string failure;  // non-empty: the setting could not be measured (why)
};

// Marks the results on the Pareto front of time against FLIP: no other result is at least as
// fast and as accurate and better in one of them. Failed results are never on it.
void mark_pareto_front(std::span<TuneResult> results);

// The result that minimises FLIP among those within `budget_ms` per frame, or minimises time
// among those within `max_flip` (the other bound absent). nullopt when none qualifies.
std::optional<size_t> choose_within(std::span<const TuneResult> results,
                                    std::optional<double> budget_ms,
                                    std::optional<double> max_flip);

// The results nearest to a bound nobody met: the fastest ones (for a budget) or the most
// accurate ones (for an error bound), at most `count`, best first.
std::vector<size_t> closest_to_bound(std::span<const TuneResult> results, bool by_time,
                                     size_t count);

// One GLPT_STATS line ("glpt: frame=3 size=320x240 trace_ms=12.5 ...") as numbers by key; keys
// whose values are not numbers (size, classes) are left out. Empty for other lines.
std::map<std::string, double> parse_stats_line(std::string_view line);

// The frame count of glpt-replay's closing summary in its stderr `text` ("glpt-replay: 1422
// calls, 3 frames, 3 rendered ..."; other lines start with "glpt-replay: " too). nullopt when
// there is none (the replay did not get that far).
std::optional<uint64_t> frames_in_replay_log(const std::string& text);

// The median of `values` (0 for none).
double median(std::vector<double> values);

}  // namespace glpt::cli
