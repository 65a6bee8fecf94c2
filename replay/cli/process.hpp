// Starting other programs from `glpt`: where glpt itself lives, PATH look-ups, and exec with
// extra environment variables. exec replaces glpt, so the program's exit status is glpt's.
#pragma once

#include <span>
#include <string>

#include "quality_flags.hpp"

namespace glpt::cli {

// Exit statuses glpt uses for its own failures (the shell's conventions for the last two).
constexpr int kExitUsage = 2;            // bad command line, unreadable input
constexpr int kExitCannotExecute = 126;  // the program was found but could not be started
constexpr int kExitNotFound = 127;       // the program (or glpt-replay, apitrace) was not found

// The directory holding the running executable (from /proc/self/exe), without a trailing
// slash; empty if it cannot be determined.
std::string executable_dir();

bool is_regular_file(const std::string& path);
bool is_executable_file(const std::string& path);

// The first executable `name` in $PATH (or `name` itself when it contains a '/' and is
// executable); empty when there is none.
std::string find_program(const std::string& name);

// Sets `env` in this process's environment and replaces the process with argv[0] (looked up in
// PATH when it has no '/'), without a shell. Returns only on failure, after printing
// "glpt <who>: cannot run ...: reason" to stderr: kExitNotFound or kExitCannotExecute.
int exec_program(std::span<const std::string> argv, const EnvSettings& env, const std::string& who);

}  // namespace glpt::cli
