// The command-line flags that mirror glpt's environment variables (README.md, "Using it on any
// program"): one table, used both to parse `glpt run` (and any other subcommand that renders)
// and to print its --help, so the two cannot drift apart.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace glpt::cli {

enum class FlagValue {
  kNone,    // a switch: sets the variable to `fixed_value`
  kCount,   // a non-negative integer
  kNumber,  // a finite non-negative real number
  kText,    // any non-empty text (a directory, a device name)
  kChoice,  // one of the words in `metavar`, separated by '|'
};

struct QualityFlag {
  std::string_view flag;      // "--spp"
  std::string_view variable;  // "GLPT_SPP"
  FlagValue value;
  std::string_view metavar;  // "N", "DIR", "path|raster"; the value for switches
  std::string_view help;
};

// Every flag, in --help order.
std::span<const QualityFlag> quality_flags();

// Environment settings collected from the command line, in order (a later flag for the same
// variable wins when they are applied).
using EnvSettings = std::vector<std::pair<std::string, std::string>>;

enum class FlagParse { kNotAQualityFlag, kParsed, kError };

// Tries to parse args[*i] ("--spp 4", "--spp=4" or a switch) as a quality flag. On kParsed,
// appends the variable to *env and advances *i past the flag and its value. On kError sets
// *error to a message naming the flag. On kNotAQualityFlag changes nothing.
FlagParse parse_quality_flag(std::span<const std::string> args, size_t* i, EnvSettings* env,
                             std::string* error);

// The flags as an aligned help table, one flag per line, each line starting with `indent`.
std::string quality_flags_help(std::string_view indent = "  ");

}  // namespace glpt::cli
