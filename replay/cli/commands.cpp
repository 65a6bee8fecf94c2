#include "commands.hpp"

#include <array>

namespace glpt::cli {

namespace {
int diff_with_std_streams(std::span<const std::string> args) { return diff_main(args); }
}  // namespace

std::span<const Command> commands() {
  static constexpr std::array kCommands = {
      Command{"run", "run a program with glpt's libGL.so.1 preloaded", run_help, run_main},
      Command{"record", "record a program's GL calls with apitrace", record_help, record_main},
      Command{"replay", "replay an apitrace trace through glpt (glpt-replay)", replay_help,
              replay_main},
      Command{"diff", "compare images: FLIP, PSNR, heat maps", diff_help, diff_with_std_streams},
      Command{"tune", "measure every quality setting's time and error on a trace", tune_help,
              tune_main},
      Command{"doctor", "check what glpt needs on this machine, and say what to install",
              doctor_help, doctor_main},
  };
  return kCommands;
}

bool is_help_flag(std::string_view arg) { return arg == "-h" || arg == "--help"; }

}  // namespace glpt::cli
