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
  // GLPT_* variables the quality flags set for the glpt backend (--mode -> GLPT_MODE, ...).
  std::vector<std::pair<std::string, std::string>> environment;
};

// The --help text (with the quality flags' table, replay/cli/quality_flags.hpp).
std::string usage();

// False + message for bad usage.
bool parse_command_line(int argc, const char* const* argv, Options* options, std::string* error);

}  // namespace glpt::replay
