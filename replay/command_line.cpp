#include "replay/command_line.hpp"

#include <charconv>
#include <cstring>
#include <string_view>

#include "quality_flags.hpp"
#include "rt_core/render_settings.hpp"

namespace glpt::replay {

namespace {

const char* const kUsage =
    "usage: glpt-replay [options] TRACE\n"
    "Replays an apitrace trace (apitrace trace --api gl|egl) headless, in this process, and\n"
    "writes its frames as PNG. No X server is needed.\n"
    "\n"
    "  --out DIR            write the chosen frames as DIR/frame_NNNNNN.png (NNNNNN: the frame\n"
    "                       index from 0; the same names for every backend)\n"
    "  --frames LIST        frames to write, e.g. 10,20-30 (default: all)\n"
    "  --every N            only frames whose index is a multiple of N\n"
    "  --shard I/N          write only the chosen frames of every Nth history window (the\n"
    "                       windows w with w % N == I), replaying the state of all; N shards\n"
    "                       write exactly the frames of one replay\n"
    "  --history W          frames build on the denoiser's and accumulation's history of the\n"
    "                       frames before them in their window of W frames (0..W-1, W..2W-1,\n"
    "                       ...): a written frame is rendered after those of its window before\n"
    "                       it (default 8 in path-traced mode, 1 = none in raster mode and for\n"
    "                       --backend mesa)\n"
    "  --repeat N           replay the trace N times in this process, frame indices counting\n"
    "                       on (each pass re-creates the trace's contexts): a long run from a\n"
    "                       short trace (default 1)\n"
    "  --backend glpt|mesa  glpt (default) or real Mesa through OSMesa (the reference images)\n"
    "  --device SUBSTR      Vulkan device by name (GLPT_VK_DEVICE; also --vk-device)\n"
    "  --window             show the frames in a window (keys: space pause/resume, n or Right\n"
    "                       step one frame, q or Esc quit); needs a display\n"
    "  --paused             with --window: start paused (waiting at the first frame)\n"
    "  --quiet              no per-frame lines or progress\n"
    "  --help               this text\n"
    "\n"
    "glpt's settings, the same flags as `glpt run` (each sets the GLPT_* variable named):\n"
    "%QUALITY_FLAGS%"
    "\n"
    "Every written frame is rendered from the same start (the history of the frames before it\n"
    "in its window, its random numbers seeded by its index), so it does not depend on which\n"
    "frames were rendered before. Frames are not averaged with earlier ones unless\n"
    "GLPT_ACCUMULATE=1 is set: then unchanged frames accumulate within their window. The\n"
    "per-frame lines go to stdout; progress and the closing summary (calls glpt does not\n"
    "implement, calls the replayer does not know) to stderr.\n"
    "\n"
    "exit status: 0 ok, 1 replay failed (no renderer, cannot write PNG), 2 bad usage,\n"
    "3 bad trace (cannot be read, or corrupt: the frames before the damage are written)\n";

struct Flag {
  const char* name;
  const char* variable;  // GLPT_* it sets; nullptr for the replayer's own options
  bool takes_value;
};

constexpr Flag kFlags[] = {
    {"--out", nullptr, true},    {"--frames", nullptr, true},          {"--every", nullptr, true},
    {"--shard", nullptr, true},  {"--history", nullptr, true},         {"--backend", nullptr, true},
    {"--quiet", nullptr, false}, {"--window", nullptr, false},         {"--paused", nullptr, false},
    {"--help", nullptr, false},  {"--device", "GLPT_VK_DEVICE", true},
    {"--repeat", nullptr, true},
};

}  // namespace

uint32_t history_window_of(const Options& options, const char* mode) {
  if (options.history_window != 0) return options.history_window;
  if (options.backend == "mesa" || (mode != nullptr && std::string_view(mode) == "raster"))
    return 1;
  return kDefaultHistoryWindow;
}

std::string usage() {
  std::string text = kUsage;
  const std::string marker = "%QUALITY_FLAGS%";
  text.replace(text.find(marker), marker.size(), cli::quality_flags_help("  "));
  return text;
}

bool parse_command_line(int argc, const char* const* argv, Options* options, std::string* error) {
  const std::vector<std::string> args(argv, argv + argc);
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    const std::string_view name = arg.substr(0, arg.find('='));
    bool own = false;
    for (const Flag& f : kFlags) own = own || name == f.name;
    if (!own && arg.rfind("--", 0) == 0 && arg != "--") {
      // glpt's settings: the table `glpt run` uses too.
      size_t index = static_cast<size_t>(i);
      cli::EnvSettings quality;
      switch (cli::parse_quality_flag(args, &index, &quality, error)) {
        case cli::FlagParse::kParsed:
          options->environment.insert(options->environment.end(), quality.begin(), quality.end());
          i = static_cast<int>(index) - 1;
          continue;
        case cli::FlagParse::kError:
          return false;
        case cli::FlagParse::kNotAQualityFlag:
          break;
      }
    }
    std::string value;
    const size_t equals = arg.find('=');
    const bool inline_value = arg.rfind("--", 0) == 0 && equals != std::string_view::npos;
    if (inline_value) {
      value = std::string(arg.substr(equals + 1));
      arg = arg.substr(0, equals);
    }
    if (arg.rfind("--", 0) != 0 || arg == "--") {
      if (arg == "--" && i + 1 < argc) arg = argv[++i];
      if (!options->trace.empty()) {
        *error =
            "more than one trace given (\"" + options->trace + "\", \"" + std::string(arg) + "\")";
        return false;
      }
      options->trace = std::string(arg);
      continue;
    }
    const Flag* flag = nullptr;
    for (const Flag& f : kFlags)
      if (arg == f.name) flag = &f;
    if (flag == nullptr) {
      *error = "unknown option " + std::string(arg);
      return false;
    }
    if (flag->takes_value && !inline_value) {
      if (i + 1 >= argc) {
        *error = std::string(flag->name) + " needs a value";
        return false;
      }
      value = argv[++i];
    } else if (!flag->takes_value && inline_value) {
      *error = std::string(flag->name) + " takes no value";
      return false;
    }
    if (flag->variable != nullptr) {
      options->environment.emplace_back(flag->variable, flag->takes_value ? value : "1");
    } else if (arg == "--out") {
      options->out_dir = value;
    } else if (arg == "--frames") {
      if (!options->frames.parse_frames(value, error)) return false;
    } else if (arg == "--every") {
      uint64_t every = 0;
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), every);
      if (ec != std::errc() || end != value.data() + value.size() || every == 0) {
        *error = "--every: want a whole number >= 1, got \"" + value + "\"";
        return false;
      }
      options->frames.set_every(every);
    } else if (arg == "--shard") {
      if (!options->frames.parse_shard(value, error)) return false;
    } else if (arg == "--history") {
      uint32_t frames = 0;
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), frames);
      if (ec != std::errc() || end != value.data() + value.size() || frames == 0 ||
          frames > kMaxHistoryWindow) {
        *error = "--history: want a whole number from 1 to " + std::to_string(kMaxHistoryWindow) +
                 ", got \"" + value + "\"";
        return false;
      }
      options->history_window = frames;
    } else if (arg == "--repeat") {
      uint32_t passes = 0;
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), passes);
      if (ec != std::errc() || end != value.data() + value.size() || passes == 0 ||
          passes > kMaxRepeat) {
        *error = "--repeat: want a whole number from 1 to " + std::to_string(kMaxRepeat) +
                 ", got \"" + value + "\"";
        return false;
      }
      options->repeat = passes;
    } else if (arg == "--backend") {
      if (value != "glpt" && value != "mesa") {
        *error = "--backend: want glpt or mesa, got \"" + value + "\"";
        return false;
      }
      options->backend = value;
    } else if (arg == "--quiet") {
      options->quiet = true;
    } else if (arg == "--window") {
      options->window = true;
    } else if (arg == "--paused") {
      options->paused = true;
    } else if (arg == "--help") {
      options->help = true;
    }
  }
  if (options->help) return true;
  // The quality flags are checked as the renderer will read them.
  std::string warning;
  rt::parse_render_settings(
      [&](const char* name) -> const char* {
        for (const auto& [variable, value] : options->environment)
          if (variable == name) return value.c_str();
        return nullptr;
      },
      &warning);
  if (!warning.empty()) {
    *error = "bad quality flag: " + warning.substr(warning.find(": ") + 2);
    return false;
  }
  if (options->trace.empty()) {
    *error = "no trace given";
    return false;
  }
  return true;
}

}  // namespace glpt::replay
