// glpt: one command line for glpt: run a program on glpt, record and replay GL traces, compare
// images. `glpt --help` lists the subcommands; `glpt help CMD` or `glpt CMD --help` explains one.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "process.hpp"

namespace {

using glpt::cli::Command;

void print_usage(std::FILE* to) {
  std::fputs(
      "usage: glpt COMMAND [ARGS...]\n"
      "\n"
      "glpt makes unmodified OpenGL 1.x programs path-traced (a drop-in libGL.so.1).\n"
      "\n"
      "commands:\n",
      to);
  for (const Command& c : glpt::cli::commands()) {
    std::fprintf(to, "  %-8s %s\n", std::string(c.name).c_str(), std::string(c.summary).c_str());
  }
  std::fputs(
      "  help CMD  the options of CMD (as does glpt CMD --help)\n"
      "\n"
      "example: glpt run --mode raster -- glxgears\n",
      to);
}

const Command* find_command(const std::string& name) {
  const auto all = glpt::cli::commands();
  const auto it =
      std::find_if(all.begin(), all.end(), [&](const Command& c) { return c.name == name; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_usage(stderr);
    return glpt::cli::kExitUsage;
  }
  if (glpt::cli::is_help_flag(args[0])) {
    print_usage(stdout);
    return 0;
  }
  if (args[0] == "help") {
    if (args.size() == 1) {
      print_usage(stdout);
      return 0;
    }
    if (const Command* c = find_command(args[1])) {
      std::fputs(c->help().c_str(), stdout);
      return 0;
    }
    std::fprintf(stderr, "glpt help: no command \"%s\" (see glpt --help)\n", args[1].c_str());
    return glpt::cli::kExitUsage;
  }
  const Command* c = find_command(args[0]);
  if (c == nullptr) {
    std::fprintf(stderr, "glpt: no command \"%s\" (see glpt --help)\n", args[0].c_str());
    return glpt::cli::kExitUsage;
  }
  return c->main(std::span<const std::string>(args).subspan(1));
}
