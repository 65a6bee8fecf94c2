#include "tune.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <sstream>

namespace glpt::cli {
namespace {

TunePoint point(std::string name, std::vector<std::pair<std::string, std::string>> flags) {
  return TunePoint{std::move(name), std::move(flags), 0};
}

}  // namespace

std::vector<TunePoint> tune_grid(bool full, uint32_t history_window) {
  std::vector<TunePoint> grid;
  // Cheapest first: GL's own image, GL's lighting per pixel, then the path tracer.
  grid.push_back(point("raster", {{"--mode", "raster"}}));
  grid.push_back(point("gl-parity", {{"--shadows", "0"}, {"--bounces", "0"}, {"--ao", "0"}}));
  grid.push_back(point("default", {}));
  // Each knob moved alone from the defaults.
  for (const char* spp : {"2", "4"})
    grid.push_back(point(std::string("spp") + spp, {{"--spp", spp}}));
  for (const char* b : {"0", "2"})
    grid.push_back(point(std::string("bounces") + b, {{"--bounces", b}}));
  grid.push_back(point("no-shadows", {{"--shadows", "0"}}));
  grid.push_back(point("no-ao", {{"--ao", "0"}}));
  grid.push_back(point("denoiser-off", {{"--denoiser", "off"}}));
  grid.push_back(point("denoise-iter3", {{"--denoise-iterations", "3"}}));
  for (const char* s : {"0.5", "0.75"})
    grid.push_back(point(std::string("scale") + s, {{"--scale", s}}));
  grid.push_back(point("unlit-ao", {{"--unlit", "ao"}}));
  if (full) {
    grid.push_back(point("spp8", {{"--spp", "8"}}));
    grid.push_back(point("bounces4", {{"--bounces", "4"}}));
    grid.push_back(point("unlit-emit", {{"--unlit", "emit"}}));
    grid.push_back(point("denoise-iter1", {{"--denoise-iterations", "1"}}));
    grid.push_back(point("denoise-kernel3x3", {{"--denoise-kernel", "1"}}));
    grid.push_back(point("denoise-kernel5x5", {{"--denoise-kernel", "2"}}));
    grid.push_back(point("no-taa", {{"--no-taa", ""}}));
    grid.push_back(point("no-shadows-no-ao", {{"--shadows", "0"}, {"--ao", "0"}}));
    // Samples x bounces x denoiser: where more samples stop paying for themselves.
    // Default values (1 sample, 1 bounce) are left out of a point's flags, so a combination
    // that is already in the grid under its own name is not measured twice.
    for (const std::string spp : {"1", "2", "4", "8"})
      for (const std::string b : {"0", "1", "2", "4"})
        for (const bool denoise : {true, false}) {
          std::string name;
          std::vector<std::pair<std::string, std::string>> flags;
          if (spp != "1") {
            name = "spp" + spp;
            flags.emplace_back("--spp", spp);
          }
          if (b != "1") {
            name += (name.empty() ? "bounces" : "-bounces") + b;
            flags.emplace_back("--bounces", b);
          }
          if (!denoise) {
            name += name.empty() ? "raw" : "-raw";
            flags.emplace_back("--denoiser", "off");
          }
          if (!flags.empty() && std::none_of(grid.begin(), grid.end(), [&](const TunePoint& p) {
                return std::is_permutation(p.flags.begin(), p.flags.end(), flags.begin(),
                                           flags.end());
              }))
            grid.push_back(point(name, flags));
        }
    for (const char* s : {"0.5", "0.75"})
      grid.push_back(point(std::string("scale") + s + "-spp4", {{"--scale", s}, {"--spp", "4"}}));
  }
  // Accumulation over k still frames, k = 2, 4, ... up to the history window (the reduced grid:
  // the longest only).
  std::vector<uint32_t> lengths;
  for (uint32_t k = 2; k <= history_window; k *= 2) lengths.push_back(k);
  if (!full && lengths.size() > 1) lengths.erase(lengths.begin(), lengths.end() - 1);
  for (const uint32_t k : lengths) {
    TunePoint p = point("accumulate" + std::to_string(k), {});
    p.accumulate_frames = k;
    grid.push_back(std::move(p));
  }
  return grid;
}

EnvSettings tune_point_environment(const TunePoint& point) {
  EnvSettings env;
  std::vector<std::string> args;
  for (const auto& [flag, value] : point.flags) {
    args.push_back(flag);
    if (!value.empty()) args.push_back(value);
  }
  for (size_t i = 0; i < args.size();) {
    std::string error;
    // The grid is built from the table's own flags: a failure here is a bug in tune_grid.
    if (parse_quality_flag(args, &i, &env, &error) != FlagParse::kParsed) break;
  }
  env.emplace_back("GLPT_ACCUMULATE", point.accumulate_frames > 0 ? "1" : "0");
  return env;
}

std::string tune_point_flags(const TunePoint& point) {
  std::string text;
  for (const auto& [flag, value] : point.flags) {
    if (!text.empty()) text += ' ';
    text += flag;
    if (!value.empty()) text += ' ' + value;
  }
  if (point.accumulate_frames == 0) {
    text += text.empty() ? "--no-accumulate" : " --no-accumulate";
  } else if (text.empty()) {
    text = "(defaults: accumulates while still)";
  }
  return text;
}

void mark_pareto_front(std::span<TuneResult> results) {
  for (TuneResult& r : results) {
    r.pareto = false;
    if (!r.failure.empty()) continue;
    r.pareto = std::none_of(results.begin(), results.end(), [&](const TuneResult& other) {
      return &other != &r && other.failure.empty() && other.frame_ms <= r.frame_ms &&
             other.flip <= r.flip && (other.frame_ms < r.frame_ms || other.flip < r.flip);
    });
  }
}

std::optional<size_t> choose_within(std::span<const TuneResult> results,
                                    std::optional<double> budget_ms,
                                    std::optional<double> max_flip) {
  std::optional<size_t> best;
  for (size_t i = 0; i < results.size(); ++i) {
    const TuneResult& r = results[i];
    if (!r.failure.empty()) continue;
    if (budget_ms && r.frame_ms > *budget_ms) continue;
    if (max_flip && r.flip > *max_flip) continue;
    if (!best) {
      best = i;
      continue;
    }
    const TuneResult& b = results[*best];
    // Within a budget: the least error (then the fastest); within an error bound: the fastest
    // (then the least error).
    const bool better =
        budget_ms ? (r.flip < b.flip || (r.flip == b.flip && r.frame_ms < b.frame_ms))
                  : (r.frame_ms < b.frame_ms || (r.frame_ms == b.frame_ms && r.flip < b.flip));
    if (better) best = i;
  }
  return best;
}

std::vector<size_t> closest_to_bound(std::span<const TuneResult> results, bool by_time,
                                     size_t count) {
  std::vector<size_t> order;
  for (size_t i = 0; i < results.size(); ++i)
    if (results[i].failure.empty()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return by_time ? results[a].frame_ms < results[b].frame_ms : results[a].flip < results[b].flip;
  });
  if (order.size() > count) order.resize(count);
  return order;
}

std::map<std::string, double> parse_stats_line(std::string_view line) {
  std::map<std::string, double> values;
  constexpr std::string_view kPrefix = "glpt: frame=";
  if (line.substr(0, kPrefix.size()) != kPrefix) return values;
  line.remove_prefix(std::string_view("glpt: ").size());
  while (!line.empty()) {
    const size_t space = std::min(line.find(' '), line.size());
    const std::string_view field = line.substr(0, space);
    line.remove_prefix(std::min(space + 1, line.size()));
    const size_t eq = field.find('=');
    if (eq == std::string_view::npos || eq == 0) continue;
    const std::string value(field.substr(eq + 1));
    errno = 0;
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    if (errno != 0 || value.empty() || *end != '\0' || !std::isfinite(number)) continue;
    values[std::string(field.substr(0, eq))] = number;
  }
  return values;
}

std::optional<uint64_t> frames_in_replay_log(const std::string& text) {
  std::optional<uint64_t> frames;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("glpt-replay: ", 0) != 0) continue;
    const size_t calls = line.find(" calls, ");
    if (calls == std::string::npos) continue;
    char* end = nullptr;
    const unsigned long long count = std::strtoull(line.c_str() + calls + 8, &end, 10);
    if (end != nullptr && std::strncmp(end, " frames", 7) == 0) frames = count;
  }
  return frames;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  if (values.size() % 2 == 1) return values[mid];
  const double upper = values[mid];
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

}  // namespace glpt::cli
