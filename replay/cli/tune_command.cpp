// `glpt tune TRACE`: the speed/accuracy sweep of glpt's knobs on the user's own trace
// (tune.hpp has the model; docs/BENCHMARKS.md what it measures and how to read it).
//
// For each setting it replays the trace with glpt-replay (its own process, so a setting that
// fails or crashes is reported, not fatal), reads the per-frame costs from GLPT_STATS_FILE and
// compares the written frames with the same frames rendered by GLPT_REFERENCE.
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "common/image_io.hpp"
#include "flip.hpp"
#include "process.hpp"
#include "psnr.hpp"
#include "quality_flags.hpp"
#include "replay/frame_selection.hpp"
#include "tune.hpp"

extern char** environ;

namespace glpt::cli {
namespace {

constexpr int kExitBoundNotMet = 1;
constexpr int kExitBadTrace = 3;  // as glpt-replay's

struct TuneOptions {
  std::string trace;
  std::optional<double> budget_ms, max_flip;
  std::string frames;  // empty: chosen from the trace's length
  std::string shard;
  bool full = false;
  std::string out;
  std::string scene;
  uint32_t reference_samples = 256;
  uint32_t history = 8;
  uint32_t windows = 3;
  std::vector<std::string> only;  // point names; empty: the whole grid
  EnvSettings base;               // quality flags given on the command line: every point
  bool plot = true;
};

bool parse_positive(const std::string& text, double* value) {
  errno = 0;
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return errno == 0 && !text.empty() && *end == '\0' && std::isfinite(*value) && *value > 0;
}

bool parse_count(const std::string& text, uint32_t min, uint32_t max, uint32_t* value) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
  const unsigned long v = std::strtoul(text.c_str(), nullptr, 10);
  if (v < min || v > max) return false;
  *value = static_cast<uint32_t>(v);
  return true;
}

std::string base_name(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  if (const size_t dot = name.rfind('.'); dot != std::string::npos && dot > 0) name.resize(dot);
  return name.empty() ? "trace" : name;
}

bool make_dirs(const std::string& path) {
  std::error_code error;
  std::filesystem::create_directories(path, error);
  return std::filesystem::is_directory(path, error);
}

// Removes what an earlier run of a setting left in `dir`: its PNGs and stats.
void remove_outputs(const std::string& dir) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
    const std::filesystem::path& path = entry.path();
    if (path.extension() == ".png" || path.filename() == "stats.txt")
      std::filesystem::remove(path, error);
  }
}

// Runs argv with `env` added to this process's environment, stdout discarded and stderr into
// `log`; returns the exit status (128 + signal when killed, 127 when it could not start).
int run_program(const std::vector<std::string>& argv, const EnvSettings& env,
                const std::string& log) {
  std::vector<std::string> environment;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    if (std::none_of(env.begin(), env.end(), [&](const auto& kv) { return kv.first == name; }))
      environment.push_back(entry);
  }
  for (const auto& setting : env) {
    // A later setting of a variable wins, as it does for glpt run's flags. (Not a structured
    // binding: Clang 14 cannot capture one in the lambda.)
    const std::string prefix = setting.first + "=";
    std::erase_if(environment, [&](const std::string& e) { return e.rfind(prefix, 0) == 0; });
    environment.push_back(prefix + setting.second);
  }
  std::vector<char*> c_env, c_argv;
  for (std::string& e : environment) c_env.push_back(e.data());
  c_env.push_back(nullptr);
  for (const std::string& a : argv) c_argv.push_back(const_cast<char*>(a.c_str()));
  c_argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, c_argv[0], &actions, nullptr, c_argv.data(), c_env.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return 127;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The last non-empty line of a log (what a failed replay said last).
std::string last_line(const std::string& text) {
  std::string line, last;
  std::istringstream in(text);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

std::string png_of(const std::string& dir, uint64_t frame) {
  char name[32];
  std::snprintf(name, sizeof name, "/frame_%06llu.png", static_cast<unsigned long long>(frame));
  return dir + name;
}

std::vector<uint64_t> parse_frame_list(const std::string& list) {
  std::vector<uint64_t> frames;
  std::istringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    const size_t dash = item.find('-');
    const uint64_t first = std::strtoull(item.c_str(), nullptr, 10);
    const uint64_t last =
        dash == std::string::npos ? first : std::strtoull(item.c_str() + dash + 1, nullptr, 10);
    for (uint64_t f = first; f <= last && frames.size() < 100000; ++f) frames.push_back(f);
  }
  return frames;
}

std::string format(const char* fmt, double value) {
  char text[64];
  std::snprintf(text, sizeof text, fmt, value);
  return text;
}

// The plotting script: next to glpt in the build tree, PREFIX/share/glpt when installed.
std::string find_plot_script() {
  const std::string dir = executable_dir();
  for (const std::string& candidate :
       {dir + "/pareto_plot.py", dir + "/../share/glpt/pareto_plot.py"})
    if (is_regular_file(candidate)) return candidate;
  return {};
}

class Tuner {
 public:
  explicit Tuner(TuneOptions options) : o_(std::move(options)) {}

  int run() {
    replay_ = executable_dir() + "/glpt-replay";
    if (!is_executable_file(replay_)) {
      std::fprintf(stderr, "glpt tune: glpt-replay was not found next to glpt (expected %s)\n",
                   replay_.c_str());
      return kExitNotFound;
    }
    if (!is_regular_file(o_.trace)) {
      std::fprintf(stderr, "glpt tune: cannot read %s\n", o_.trace.c_str());
      return kExitUsage;
    }
    if (!make_dirs(o_.out + "/reference")) {
      std::fprintf(stderr, "glpt tune: cannot create %s: %s\n", o_.out.c_str(),
                   std::strerror(errno));
      return kExitUsage;
    }
    if (const int status = choose_frames(); status != 0) return status;
    if (const int status = render_reference(); status != 0) return status;
    const std::vector<TunePoint> grid = selected_grid();
    if (grid.empty()) {
      std::fprintf(stderr, "glpt tune: --only names no setting of the grid\n");
      return kExitUsage;
    }
    std::vector<TuneResult> results;
    for (size_t i = 0; i < grid.size(); ++i) {
      results.push_back(measure(grid[i]));
      print_progress(i + 1, grid.size(), results.back());
    }
    mark_pareto_front(results);
    print_table(results);
    write_csv(results);
    if (o_.plot) plot();
    return recommend(results);
  }

 private:
  int choose_frames() {
    if (!o_.frames.empty()) {
      frames_ = parse_frame_list(o_.frames);
      return 0;
    }
    // The trace's length, from a raster replay to its end that renders no frame (a frame index
    // beyond any trace's).
    const std::string log = o_.out + "/count.log";
    run_program({replay_, o_.trace, "--quiet", "--frames", "4000000000", "--out", o_.out},
                {{"GLPT_MODE", "raster"}, {"GLPT_QUIET", "1"}}, log);
    const std::optional<uint64_t> count = frames_in_replay_log(read_text(log));
    if (!count || *count == 0) {
      std::fprintf(stderr, "glpt tune: %s has no frames to measure (%s)\n", o_.trace.c_str(),
                   last_line(read_text(log)).c_str());
      return kExitBadTrace;
    }
    // The last frame of history windows 1, 2, ...: each compared frame is rendered after a
    // whole window of history (denoiser, accumulation), window 0 stays unrendered, and the
    // first rendered window is the warm-up the times leave out.
    for (uint64_t w = 1; w <= o_.windows && (w + 1) * o_.history <= *count; ++w)
      frames_.push_back((w + 1) * o_.history - 1);
    if (frames_.empty()) frames_.push_back(*count - 1);  // a short trace: its last frame
    return 0;
  }

  std::string frames_argument() const {
    std::string list;
    for (const uint64_t f : frames_) list += (list.empty() ? "" : ",") + std::to_string(f);
    return list;
  }

  // Accumulation points render with shorter history windows; they write every frame from the
  // first compared frame's window on, so they render as many frames as the others do (unless
  // the compared frames lie far apart: then those frames only).
  std::string accumulation_frames_argument() const {
    const uint64_t first =
        *std::min_element(frames_.begin(), frames_.end()) / o_.history * o_.history;
    const uint64_t last = *std::max_element(frames_.begin(), frames_.end());
    if (last - first + 1 > frames_.size() * o_.history) return frames_argument();
    return std::to_string(first) + "-" + std::to_string(last);
  }

  std::vector<std::string> replay_argv(const std::string& dir, uint32_t history,
                                       const std::string& frames) const {
    std::vector<std::string> argv = {replay_, o_.trace,    "--quiet",
                                     "--out", dir,         "--frames",
                                     frames,  "--history", std::to_string(history)};
    if (!o_.shard.empty()) {
      argv.push_back("--shard");
      argv.push_back(o_.shard);
    }
    return argv;
  }

  int render_reference() {
    const std::string dir = o_.out + "/reference";
    std::printf("glpt tune: %s, frames %s, reference %u samples per pixel (%s)\n", o_.trace.c_str(),
                frames_argument().c_str(), o_.reference_samples, dir.c_str());
    std::fflush(stdout);
    remove_outputs(dir);
    EnvSettings env = o_.base;
    env.emplace_back("GLPT_MODE", "path");
    env.emplace_back("GLPT_REFERENCE", std::to_string(o_.reference_samples));
    env.emplace_back("GLPT_QUIET", "1");
    const std::string log = dir + "/replay.log";
    const int status = run_program(replay_argv(dir, 1, frames_argument()), env, log);
    std::vector<uint64_t> present;
    for (const uint64_t f : frames_)
      if (is_regular_file(png_of(dir, f))) present.push_back(f);
    if (present.empty()) {
      const std::optional<uint64_t> count = frames_in_replay_log(read_text(log));
      std::fprintf(stderr, "glpt tune: the reference wrote none of frames %s (status %d%s%s): %s\n",
                   frames_argument().c_str(), status, count ? ", the trace has " : "",
                   count ? (std::to_string(*count) + " frames").c_str() : "",
                   last_line(read_text(log)).c_str());
      return kExitBadTrace;
    }
    frames_ = present;
    return 0;
  }

  std::vector<TunePoint> selected_grid() const {
    std::vector<TunePoint> grid = tune_grid(o_.full, o_.history);
    if (!o_.only.empty())
      std::erase_if(grid, [&](const TunePoint& p) {
        return std::find(o_.only.begin(), o_.only.end(), p.name) == o_.only.end();
      });
    return grid;
  }

  TuneResult measure(const TunePoint& point) {
    TuneResult r;
    r.name = point.name;
    r.flags = tune_point_flags(point);
    const std::string dir = o_.out + "/points/" + point.name;
    if (!make_dirs(dir)) {
      r.failure = "cannot create " + dir;
      return r;
    }
    remove_outputs(dir);
    EnvSettings env = o_.base;
    env.emplace_back("GLPT_MODE", "path");
    for (auto& kv : tune_point_environment(point)) env.push_back(std::move(kv));
    env.emplace_back("GLPT_STATS_FILE", dir + "/stats.txt");
    env.emplace_back("GLPT_QUIET", "1");
    const bool accumulates = point.accumulate_frames > 0;
    const std::string log = dir + "/replay.log";
    const int status =
        run_program(replay_argv(dir, accumulates ? point.accumulate_frames : o_.history,
                                accumulates ? accumulation_frames_argument() : frames_argument()),
                    env, log);
    if (status != 0) {
      r.failure =
          "glpt-replay exited with " + std::to_string(status) + ": " + last_line(read_text(log));
      return r;
    }
    // Times: every rendered frame after the first window (pipelines, first builds).
    std::vector<std::map<std::string, double>> frames;
    std::istringstream stats(read_text(dir + "/stats.txt"));
    for (std::string line; std::getline(stats, line);)
      if (auto values = parse_stats_line(line); !values.empty())
        frames.push_back(std::move(values));
    const size_t warmup = frames.size() > o_.history ? o_.history : (frames.size() > 1 ? 1 : 0);
    std::map<std::string, std::vector<double>> series;
    for (size_t i = warmup; i < frames.size(); ++i) {
      for (const char* key : {"total_ms", "raster_ms", "blas_ms", "tlas_ms", "trace_ms",
                              "denoise_ms", "composite_ms", "upload_ms", "capture_ms"})
        series[key].push_back(frames[i].count(key) ? frames[i].at(key) : 0.0);
      const double trace = frames[i].count("trace_ms") ? frames[i].at("trace_ms") : 0.0;
      const double rays = frames[i].count("rays") ? frames[i].at("rays") : 0.0;
      series["mrays_per_s"].push_back(trace > 0 ? rays / (trace * 1e3) : 0.0);
    }
    r.timed_frames = static_cast<uint32_t>(frames.size() - warmup);
    r.frame_ms = median(series["total_ms"]);
    for (const char* key : {"capture_ms", "upload_ms", "raster_ms", "blas_ms", "tlas_ms",
                            "trace_ms", "denoise_ms", "composite_ms"})
      r.pass_ms[key] = median(series[key]);
    r.mrays_per_s = median(series["mrays_per_s"]);
    // Errors against the reference, frame by frame.
    double flip = 0, relmse = 0, psnr = 0;
    for (const uint64_t f : frames_) {
      ImageRGBA8 test, reference;
      std::string error;
      if (!read_png_rgba8(png_of(dir, f), &test, &error) ||
          !read_png_rgba8(png_of(o_.out + "/reference", f), &reference, &error))
        continue;
      const diff::Rgb8View a{reference.width, reference.height, 4, reference.pixels.data()};
      const diff::Rgb8View b{test.width, test.height, 4, test.pixels.data()};
      diff::FlipResult result;
      if (!diff::compute_flip(a, b, diff::default_pixels_per_degree(), &result, &error)) continue;
      flip += result.mean;
      relmse += diff::relmse_rgb8(b, a);
      // Identical images: PSNR is infinite; 100 dB stands for it in means and the CSV.
      psnr += std::min(diff::psnr_rgb8(a, b), 100.0);
      ++r.compared_frames;
    }
    if (r.compared_frames == 0) {
      r.failure = "no frame to compare with the reference";
      return r;
    }
    r.flip = flip / r.compared_frames;
    r.relmse = relmse / r.compared_frames;
    r.psnr_db = psnr / r.compared_frames;
    return r;
  }

  static void print_progress(size_t index, size_t count, const TuneResult& r) {
    if (!r.failure.empty()) {
      std::printf("[%zu/%zu] %-18s failed: %s\n", index, count, r.name.c_str(), r.failure.c_str());
    } else {
      std::printf(
          "[%zu/%zu] %-18s %8.1f ms/frame  FLIP %.4f  relMSE %.5f  PSNR %5.2f dB  "
          "(%u frames timed, %u compared)\n",
          index, count, r.name.c_str(), r.frame_ms, r.flip, r.relmse, r.psnr_db, r.timed_frames,
          r.compared_frames);
    }
    std::fflush(stdout);
  }

  static void print_table(std::vector<TuneResult> results) {
    std::stable_sort(results.begin(), results.end(), [](const TuneResult& a, const TuneResult& b) {
      return a.frame_ms < b.frame_ms;
    });
    std::printf("\n  %-18s %9s %8s %9s %8s %9s %9s %8s  %s\n", "setting", "ms/frame", "FLIP",
                "relMSE", "PSNR dB", "trace ms", "denoise", "Mrays/s", "flags");
    for (const TuneResult& r : results) {
      if (!r.failure.empty()) continue;
      std::printf("%s %-18s %9.1f %8.4f %9.5f %8.2f %9.1f %9.1f %8.3f  %s\n", r.pareto ? "*" : " ",
                  r.name.c_str(), r.frame_ms, r.flip, r.relmse, r.psnr_db, r.pass_ms.at("trace_ms"),
                  r.pass_ms.at("denoise_ms"), r.mrays_per_s, r.flags.c_str());
    }
    std::printf("(* on the Pareto front of time per frame against FLIP)\n\nPareto front:\n");
    std::printf("  %-18s %9s %8s %9s %8s  %s\n", "setting", "ms/frame", "FLIP", "relMSE", "PSNR dB",
                "flags");
    for (const TuneResult& r : results)
      if (r.pareto)
        std::printf("  %-18s %9.1f %8.4f %9.5f %8.2f  %s\n", r.name.c_str(), r.frame_ms, r.flip,
                    r.relmse, r.psnr_db, r.flags.c_str());
  }

  void write_csv(const std::vector<TuneResult>& results) const {
    const std::string path = o_.out + "/tune.csv";
    std::ofstream csv(path);
    csv << "scene,setting,flags,timed_frames,frame_ms,capture_ms,upload_ms,raster_ms,blas_ms,"
           "tlas_ms,trace_ms,denoise_ms,composite_ms,mrays_per_s,compared_frames,flip,relmse,"
           "psnr_db,pareto,failure\n";
    for (const TuneResult& r : results) {
      auto pass = [&](const char* key) {
        return r.pass_ms.count(key) ? format("%.3f", r.pass_ms.at(key)) : std::string("0");
      };
      std::string failure = r.failure;
      std::replace(failure.begin(), failure.end(), '"', '\'');
      csv << o_.scene << ',' << r.name << ",\"" << r.flags << "\"," << r.timed_frames << ','
          << format("%.3f", r.frame_ms) << ',' << pass("capture_ms") << ',' << pass("upload_ms")
          << ',' << pass("raster_ms") << ',' << pass("blas_ms") << ',' << pass("tlas_ms") << ','
          << pass("trace_ms") << ',' << pass("denoise_ms") << ',' << pass("composite_ms") << ','
          << format("%.4f", r.mrays_per_s) << ',' << r.compared_frames << ','
          << format("%.5f", r.flip) << ',' << format("%.6f", r.relmse) << ','
          << format("%.3f", r.psnr_db) << ',' << (r.pareto ? 1 : 0) << ",\"" << failure << "\"\n";
    }
    std::printf("CSV: %s\n", path.c_str());
  }

  void plot() const {
    const std::string script = find_plot_script();
    // Debian's python3 (where python3-matplotlib is) before another one first in PATH.
    const std::string python =
        is_executable_file("/usr/bin/python3") ? "/usr/bin/python3" : find_program("python3");
    const std::string png = o_.out + "/pareto.png";
    if (script.empty() || python.empty()) {
      std::printf("plot: skipped (%s)\n",
                  script.empty() ? "pareto_plot.py not installed" : "python3 not found");
      return;
    }
    const std::string log = o_.out + "/plot.log";
    const int status = run_program({python, script, o_.out + "/tune.csv", png, o_.scene}, {}, log);
    if (status == 0)
      std::printf("plot: %s\n", png.c_str());
    else
      std::printf("plot: not written (%s)\n", last_line(read_text(log)).c_str());
  }

  int recommend(const std::vector<TuneResult>& results) const {
    if (!o_.budget_ms && !o_.max_flip) return 0;
    const std::optional<size_t> best = choose_within(results, o_.budget_ms, o_.max_flip);
    if (!best) {
      const bool by_time = o_.budget_ms.has_value();
      std::printf("\nno setting meets %s; the closest:\n",
                  by_time ? format("the budget of %.1f ms per frame", *o_.budget_ms).c_str()
                          : format("the FLIP bound of %.4f", *o_.max_flip).c_str());
      for (const size_t i : closest_to_bound(results, by_time, 3))
        std::printf("  %-18s %8.1f ms/frame  FLIP %.4f  %s\n", results[i].name.c_str(),
                    results[i].frame_ms, results[i].flip, results[i].flags.c_str());
      return kExitBoundNotMet;
    }
    const TuneResult& r = results[*best];
    std::printf("\nbest %s: %s (%.1f ms per frame, FLIP %.4f, relMSE %.5f, PSNR %.2f dB)\n",
                o_.budget_ms ? "within the budget" : "within the error bound", r.name.c_str(),
                r.frame_ms, r.flip, r.relmse, r.psnr_db);
    const std::vector<TunePoint> grid = tune_grid(true, o_.history);
    for (const TunePoint& p : grid) {
      if (p.name != r.name) continue;
      std::string variables;
      for (const auto& [name, value] : tune_point_environment(p))
        variables += name + "=" + value + " ";
      std::printf("  environment: %s\n  glpt run %s -- PROGRAM\n", variables.c_str(),
                  r.flags.rfind('(', 0) == 0 ? "" : r.flags.c_str());
    }
    return 0;
  }

  TuneOptions o_;
  std::string replay_;
  std::vector<uint64_t> frames_;
};

}  // namespace

std::string tune_help() {
  return "usage: glpt tune TRACE [--budget-ms X | --max-flip Y] [--frames LIST] [--shard I/N]\n"
         "                 [--full] [--out DIR] [OPTIONS] [QUALITY FLAGS]\n"
         "\n"
         "Measures what each of glpt's quality settings costs and buys on your own apitrace\n"
         "trace: every setting of a grid replays the trace (glpt-replay) and is timed per frame\n"
         "(median of the frames after a warm-up window; ms per pass from Vulkan timestamps), and\n"
         "its frames are compared with the same frames rendered by GLPT_REFERENCE (FLIP,\n"
         "relMSE, PSNR). Prints a progress line per setting, the table with the Pareto front of\n"
         "time against FLIP marked, writes DIR/tune.csv and the plot DIR/pareto.png (needs\n"
         "python3-matplotlib), and with a bound the setting to use.\n"
         "\n"
         "  --budget-ms X      recommend the least error within X ms per frame\n"
         "  --max-flip Y       recommend the fastest setting with a mean FLIP of at most Y\n"
         "  --frames LIST      the frames compared, e.g. 15,23,31 (default: the last frame of\n"
         "                     history windows 1..--windows, so each follows a warm history)\n"
         "  --shard I/N        replay only shard I of N (glpt-replay's --shard), for splitting\n"
         "                     a long tune across machines\n"
         "  --full             the full grid (49 settings) instead of the reduced one (15)\n"
         "  --out DIR          where frames, the CSV and the plot go (default glpt-tune-NAME)\n"
         "  --reference N      samples per pixel of the reference (default 256)\n"
         "  --history W        frames of denoiser/accumulation history before each compared\n"
         "                     frame (default 8; glpt-replay's --history)\n"
         "  --windows K        how many windows' last frames are compared (default 3)\n"
         "  --only A,B,...     only the named settings (names as in the table)\n"
         "  --scene NAME       the name in the CSV and the plot (default: the trace's)\n"
         "  --no-plot          do not draw the plot\n"
         "  Any of glpt run's quality flags (e.g. --light-size-deg 2) applies to every setting.\n"
         "\n"
         "What the knobs trade (docs/BENCHMARKS.md has measured curves):\n"
         "  raster             GL's own image on Vulkan: fastest, no light transport at all\n"
         "  gl-parity          --shadows 0 --bounces 0 --ao 0: GL's lighting per pixel, no rays\n"
         "  --spp N            samples per pixel per frame: noise falls as 1/sqrt(N), time rises "
         "~N\n"
         "  --bounces N        indirect light: each bounce adds rays and darker-corner accuracy\n"
         "  --shadows / --ao   shadow rays and ambient occlusion: one ray per sample each\n"
         "  --unlit ao|emit    trace unlit draws too (AO, or as light sources)\n"
         "  --denoiser         SVGF: removes most noise at a fixed cost per shaded pixel;\n"
         "                     --denoise-iterations trades blur range for time\n"
         "  --no-taa           no temporal anti-aliasing after it: saves its pass, edges alias\n"
         "  --scale S          trace S x S of the pixels, interpolate the rest: rays fall ~S^2\n"
         "  accumulateK        a still image averaged over K frames (glpt does this by default\n"
         "                     while nothing moves): time per frame unchanged, error falls\n"
         "Every setting but the accumulation points runs with --no-accumulate, so each frame pays\n"
         "for its own samples.\n"
         "\n"
         "exit status: 0 ok, 1 no setting meets the bound (the closest are printed), 2 bad usage,\n"
         "3 the trace has no frame to measure, 127 glpt-replay not found\n";
}

int tune_main(std::span<const std::string> args) {
  TuneOptions o;
  for (size_t i = 0; i < args.size();) {
    const std::string& a = args[i];
    if (is_help_flag(a)) {
      std::fputs(tune_help().c_str(), stdout);
      return 0;
    }
    auto value = [&](std::string* out) {
      if (i + 1 >= args.size()) {
        std::fprintf(stderr, "glpt tune: %s needs a value (see glpt tune --help)\n", a.c_str());
        return false;
      }
      *out = args[i + 1];
      i += 2;
      return true;
    };
    std::string v;
    auto bad = [&](const char* what) {
      std::fprintf(stderr, "glpt tune: %s \"%s\" is not %s\n", a.c_str(), v.c_str(), what);
      return kExitUsage;
    };
    if (a == "--budget-ms" || a == "--max-flip") {
      if (!value(&v)) return kExitUsage;
      double number = 0;
      if (!parse_positive(v, &number)) return bad("a positive number");
      (a == "--budget-ms" ? o.budget_ms : o.max_flip) = number;
    } else if (a == "--frames" || a == "--shard" || a == "--out" || a == "--scene") {
      if (!value(&v)) return kExitUsage;
      // Checked as glpt-replay checks them, so every replay of the sweep accepts them.
      replay::FrameSelection selection;
      std::string error;
      if (a == "--frames") {
        if (!selection.parse_frames(v, &error) || parse_frame_list(v).empty())
          return bad("a frame list like 10,20-30");
        o.frames = v;
      } else if (a == "--shard") {
        if (!selection.parse_shard(v, &error)) return bad("a shard I/N with 0 <= I < N");
        o.shard = v;
      } else {
        (a == "--out" ? o.out : o.scene) = v;
      }
    } else if (a == "--reference" || a == "--history" || a == "--windows") {
      if (!value(&v)) return kExitUsage;
      uint32_t* field = a == "--reference" ? &o.reference_samples
                        : a == "--history" ? &o.history
                                           : &o.windows;
      const uint32_t max = a == "--reference" ? 65536 : 64;
      if (!parse_count(v, 1, max, field))
        return bad(("a whole number 1.." + std::to_string(max)).c_str());
    } else if (a == "--only") {
      if (!value(&v)) return kExitUsage;
      std::istringstream in(v);
      for (std::string name; std::getline(in, name, ',');)
        if (!name.empty()) o.only.push_back(name);
    } else if (a == "--full") {
      o.full = true;
      ++i;
    } else if (a == "--no-plot") {
      o.plot = false;
      ++i;
    } else if (!a.empty() && a[0] == '-') {
      std::string error;
      const FlagParse parsed = parse_quality_flag(args, &i, &o.base, &error);
      if (parsed == FlagParse::kError) {
        std::fprintf(stderr, "glpt tune: %s\n", error.c_str());
        return kExitUsage;
      }
      if (parsed == FlagParse::kNotAQualityFlag) {
        std::fprintf(stderr, "glpt tune: unknown option %s (see glpt tune --help)\n", a.c_str());
        return kExitUsage;
      }
    } else if (o.trace.empty()) {
      o.trace = a;
      ++i;
    } else {
      std::fprintf(stderr, "glpt tune: one trace only (%s, then %s)\n", o.trace.c_str(), a.c_str());
      return kExitUsage;
    }
  }
  if (o.trace.empty()) {
    std::fprintf(stderr, "glpt tune: no trace given (see glpt tune --help)\n");
    return kExitUsage;
  }
  if (o.scene.empty()) o.scene = base_name(o.trace);
  if (o.out.empty()) o.out = "glpt-tune-" + o.scene;
  return Tuner(std::move(o)).run();
}

}  // namespace glpt::cli
