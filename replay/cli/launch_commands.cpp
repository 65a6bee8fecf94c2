// `glpt run`, `glpt record` and `glpt replay`: each starts another program.
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "commands.hpp"
#include "common/device_survey.hpp"
#include "process.hpp"
#include "quality_flags.hpp"

namespace glpt::cli {
namespace {

// Splits "[OPTIONS] [--] PROGRAM ARGS": options are consumed by `option` (which returns false
// for an argument it does not know); the program starts after "--" or at the first argument
// that does not start with '-'.
// "-h"/"--help" before the program prints `help` instead.
enum class Split { kProgram, kHelpShown, kError };

template <typename Option>
Split split_program(std::span<const std::string> args, const char* who, std::string (*help)(),
                    Option option, std::vector<std::string>* program) {
  size_t i = 0;
  while (i < args.size()) {
    const std::string& a = args[i];
    if (a == "--") {
      ++i;
      break;
    }
    if (a.empty() || a[0] != '-') break;
    if (is_help_flag(a)) {
      std::fputs(help().c_str(), stdout);
      return Split::kHelpShown;
    }
    const size_t before = i;
    std::string error;
    if (!option(&i, &error)) {
      std::fprintf(stderr, "glpt %s: %s (see glpt %s --help)\n", who,
                   error.empty() ? ("unknown option " + a).c_str() : error.c_str(), who);
      return Split::kError;
    }
    if (i == before) ++i;
  }
  program->assign(args.begin() + static_cast<std::ptrdiff_t>(i), args.end());
  if (program->empty()) {
    std::fprintf(stderr, "glpt %s: no program given (see glpt %s --help)\n", who, who);
    return Split::kError;
  }
  return Split::kProgram;
}

// The exit status for a command line that gave no program to run.
int status_without_program(Split split) { return split == Split::kHelpShown ? 0 : kExitUsage; }

// The value of option args[*i] ("-o FILE", "--output=FILE"); advances *i past it.
bool option_value(std::span<const std::string> args, size_t* i, std::string* value,
                  std::string* error) {
  const std::string& a = args[*i];
  if (const size_t eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
    *value = a.substr(eq + 1);
    *i += 1;
  } else if (*i + 1 < args.size()) {
    *value = args[*i + 1];
    *i += 2;
  } else {
    *error = a + " needs a value";
    return false;
  }
  if (value->empty()) {
    *error = a + " needs a non-empty value";
    return false;
  }
  return true;
}

bool option_is(const std::string& arg, std::string_view name) {
  return arg == name || (arg.rfind(std::string(name) + "=", 0) == 0 && name.starts_with("--"));
}

}  // namespace

std::string find_glpt_library(const std::string& exe_dir) {
  if (exe_dir.empty()) return {};
  for (const char* relative : {"/../gl_shim/libGL.so.1", "/../lib/glpt/libGL.so.1"}) {
    const std::string candidate = exe_dir + relative;
    if (is_regular_file(candidate)) return candidate;
  }
  return {};
}

std::string run_help() {
  return "usage: glpt run [OPTIONS] [--] PROGRAM [ARGS...]\n"
         "\n"
         "Runs PROGRAM with glpt's libGL.so.1 preloaded (LD_PRELOAD), so its OpenGL 1.x\n"
         "drawing is path-traced (or rasterized with --mode raster). The options set glpt's\n"
         "environment variables (shown in brackets) for the program; glpt then replaces itself\n"
         "with PROGRAM (no shell), so PROGRAM's exit status is glpt's.\n"
         "\n"
         "options:\n" +
         quality_flags_help() +
         "  --lib PATH  the libGL.so.1 to preload (default: found next to glpt: the build\n"
         "              tree's gl_shim/libGL.so.1, or PREFIX/lib/glpt/libGL.so.1)\n"
         "\n"
         "exit status: PROGRAM's; 2 for a bad command line or no libGL.so.1 found (or one\n"
         "that cannot be loaded), 126/127 when PROGRAM cannot be started / is not found.\n"
         "Where path tracing is not possible, glpt draws in raster mode and says why once;\n"
         "`glpt doctor` says what the machine lacks.\n"
         "\n"
         "example: glpt run --spp 4 --output /tmp/frames -- glxgears\n";
}

int run_main(std::span<const std::string> args) {
  EnvSettings env;
  std::string lib;
  std::vector<std::string> program;
  auto option = [&](size_t* i, std::string* error) {
    const std::string& a = args[*i];
    if (option_is(a, "--lib")) return option_value(args, i, &lib, error);
    return parse_quality_flag(args, i, &env, error) == FlagParse::kParsed;
  };
  if (const Split split = split_program(args, "run", run_help, option, &program);
      split != Split::kProgram) {
    return status_without_program(split);
  }
  if (lib.empty()) {
    lib = find_glpt_library(executable_dir());
    if (lib.empty()) {
      std::fprintf(stderr,
                   "glpt run: glpt's libGL.so.1 was not found next to glpt (looked in "
                   "%s/../gl_shim and %s/../lib/glpt); give it with --lib PATH\n",
                   executable_dir().c_str(), executable_dir().c_str());
      return kExitUsage;
    }
  } else if (!is_regular_file(lib)) {
    std::fprintf(stderr, "glpt run: --lib %s: no such file\n", lib.c_str());
    return kExitUsage;
  }
  // A library the dynamic linker cannot load (a missing Vulkan loader, say) would be skipped with
  // a warning, and the program would run on the system's libGL as if nothing were wrong.
  if (dlopen(lib.c_str(), RTLD_LAZY | RTLD_LOCAL) == nullptr) {
    const char* why = dlerror();
    std::fprintf(stderr, "glpt run: %s cannot be loaded (%s); %s\n", lib.c_str(),
                 why != nullptr ? why : "unknown error", kDoctorHint);
    return kExitUsage;
  }
  // glpt's library goes first, ahead of any preloads the user already has.
  const char* preload = std::getenv("LD_PRELOAD");
  env.emplace_back("LD_PRELOAD", preload && *preload ? lib + ":" + preload : lib);
  return exec_program(program, env, "run");
}

std::string record_help() {
  return "usage: glpt record [--api gl|egl] [-o FILE] [--] PROGRAM [ARGS...]\n"
         "\n"
         "Records PROGRAM's OpenGL calls into an apitrace trace, running it on the system's\n"
         "own libGL (real Mesa), with `apitrace trace --api API --output FILE PROGRAM ARGS`.\n"
         "Replay the trace with `glpt replay`. Needs apitrace (Debian package apitrace).\n"
         "\n"
         "options:\n"
         "  --api gl|egl         the API to trace: gl (GLX, the default) or egl\n"
         "  -o, --output FILE    the trace file (default: apitrace's, PROGRAM.trace)\n"
         "\n"
         "exit status: apitrace's (PROGRAM's); 2 for a bad command line, 127 when apitrace\n"
         "is not installed.\n";
}

int record_main(std::span<const std::string> args) {
  std::string api = "gl", output;
  std::vector<std::string> program;
  auto option = [&](size_t* i, std::string* error) {
    const std::string& a = args[*i];
    if (option_is(a, "--api")) {
      if (!option_value(args, i, &api, error)) return false;
      if (api != "gl" && api != "egl") {
        *error = "--api must be gl or egl, not \"" + api + "\"";
        return false;
      }
      return true;
    }
    if (a == "-o" || option_is(a, "--output")) return option_value(args, i, &output, error);
    return false;
  };
  if (const Split split = split_program(args, "record", record_help, option, &program);
      split != Split::kProgram) {
    return status_without_program(split);
  }
  const std::string apitrace = find_program("apitrace");
  if (apitrace.empty()) {
    std::fprintf(stderr,
                 "glpt record: apitrace was not found in PATH; install it (Debian package "
                 "apitrace)\n");
    return kExitNotFound;
  }
  std::vector<std::string> argv = {apitrace, "trace", "--api", api};
  if (!output.empty()) argv.insert(argv.end(), {"--output", output});
  argv.insert(argv.end(), program.begin(), program.end());
  return exec_program(argv, {}, "record");
}

namespace {
std::string replay_executable() {
  const std::string dir = executable_dir();
  return dir.empty() ? std::string("glpt-replay") : dir + "/glpt-replay";
}
}  // namespace

std::string replay_help() {
  return "usage: glpt replay TRACE [OPTIONS]\n"
         "\n"
         "Replays an apitrace trace headless through glpt and writes chosen frames as PNG.\n"
         "All arguments go to glpt-replay, installed next to glpt; `glpt-replay --help`\n"
         "lists its options.\n";
}

int replay_main(std::span<const std::string> args) {
  const std::string replay = replay_executable();
  if (!is_executable_file(replay) && !args.empty() && is_help_flag(args[0])) {
    std::fputs(replay_help().c_str(), stdout);
    std::printf("\n(glpt-replay is not built yet: expected %s)\n", replay.c_str());
    return 0;
  }
  if (!is_executable_file(replay)) {
    std::fprintf(stderr,
                 "glpt replay: glpt-replay was not found next to glpt (expected %s); build "
                 "the glpt-replay target\n",
                 replay.c_str());
    return kExitNotFound;
  }
  std::vector<std::string> argv = {replay};
  argv.insert(argv.end(), args.begin(), args.end());
  return exec_program(argv, {}, "replay");
}

}  // namespace glpt::cli
