// glpt-replay's command line.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "replay/frame_selection.hpp"

namespace glpt::replay {

// Exit codes.
enum ExitCode : int {
  kExitOk = 0,
  kExitReplayFailed = 1,  // the backend failed (no Vulkan device, no OSMesa) or a PNG write did
  kExitUsage = 2,
  kExitBadTrace = 3,  // the trace cannot be opened or is corrupt (frames before that are written)
};

struct Options {
  std::string trace;
  std::string out_dir;  // empty: write no PNGs
  FrameSelection frames;
  std::string backend = "glpt";
  bool quiet = false;
  bool window = false;  // --window: show the frames in a window
  bool paused = false;  // --paused: the window starts paused
  bool help = false;
  uint32_t history_window = 0;  // --history; 0: the default of the mode (history_window_of)
  // --repeat N: the trace replayed N times in one process, frames numbered on (the soak,
  // bench/soak.sh); each pass re-creates the trace's contexts, replacing the previous pass's.
  uint32_t repeat = 1;
  // GLPT_* variables the quality flags set for the glpt backend (--mode -> GLPT_MODE, ...).
  std::vector<std::pair<std::string, std::string>> environment;
};

// --history's bounds and its default in path-traced mode: SVGF's history (alpha 0.2) has most
// of its weight within 8 frames; a written frame costs up to W - 1 more rendered before it.
constexpr uint32_t kMaxHistoryWindow = 1024;
constexpr uint32_t kDefaultHistoryWindow = 8;
constexpr uint32_t kMaxRepeat = 100000;

// The history window a replay uses: --history, else 1 for --backend mesa and raster mode
// (`mode`: GLPT_MODE as the replay sees it, may be null), else kDefaultHistoryWindow.
uint32_t history_window_of(const Options& options, const char* mode);

// The --help text (with the quality flags' table, replay/cli/quality_flags.hpp).
std::string usage();

// False + message for bad usage.
bool parse_command_line(int argc, const char* const* argv, Options* options, std::string* error);

}  // namespace glpt::replay
