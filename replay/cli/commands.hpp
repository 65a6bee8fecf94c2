// The subcommands of `glpt`. Each takes the arguments after its name and returns the process
// exit status (run, record and replay normally exec another program and do not return).
#pragma once

#include <iosfwd>
#include <span>
#include <string>
#include <string_view>

namespace glpt::cli {

struct Command {
  std::string_view name;
  std::string_view summary;  // one line for `glpt --help`
  std::string (*help)();     // the full text for `glpt help NAME` / `glpt NAME --help`
  int (*main)(std::span<const std::string> args);
};

// All subcommands, in `glpt --help` order.
std::span<const Command> commands();

std::string run_help();
int run_main(std::span<const std::string> args);

std::string record_help();
int record_main(std::span<const std::string> args);

std::string replay_help();
int replay_main(std::span<const std::string> args);

std::string diff_help();
int diff_main(std::span<const std::string> args);
// The same, with its output streams given (for tests).
int diff_main(std::span<const std::string> args, std::ostream& out, std::ostream& err);

std::string tune_help();
int tune_main(std::span<const std::string> args);

std::string doctor_help();
int doctor_main(std::span<const std::string> args);

// True for "-h" and "--help".
bool is_help_flag(std::string_view arg);

// Where `glpt run` looks for glpt's libGL.so.1 when --lib is not given, relative to the
// directory of the glpt executable: the build tree (build/replay/glpt next to
// build/gl_shim/libGL.so.1), then an installed layout (PREFIX/bin/glpt, PREFIX/lib/glpt/).
std::string find_glpt_library(const std::string& exe_dir);

}  // namespace glpt::cli
