// Comparison of two GL state dumps written by the conformance runners
// (tests/conformance/state_dump.hpp): which queries differ between Mesa and glpt after a scene.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace glpt::statecompare {

// One query's result: the values (booleans as 0/1, "nan"/"inf" as such), or the name of the
// error the query raised.
struct Value {
  bool is_error = false;
  std::string error;            // when is_error, e.g. "GL_INVALID_ENUM"
  std::vector<double> numbers;  // otherwise
  std::string text;             // as written in the dump, for messages
};

struct StateDump {
  std::string scene, backend, error_after_scene;
  std::map<std::string, Value> state;           // compared
  std::map<std::string, Value> implementation;  // informational
};

// Parses a dump (the JSON subset the runners write). Returns false with *error on bad input.
bool parse_state_dump(const std::string& json, StateDump* out, std::string* error);

// True for queries that return floating-point values (glGetFloatv, glGetLightfv, glGetClipPlane,
// ...): compared with a tolerance; every other query (booleans, integers, enums) exactly.
bool is_float_query(const std::string& key);

// Floats a and b match when |a - b| <= tolerance * max(1, |a|, |b|): relative above magnitude 1,
// absolute below (a matrix entry of -4e-8 from cos(90 degrees) in float matches 0).
bool floats_match(double a, double b, double tolerance);

struct Mismatch {
  std::string key;
  std::string reference, test;  // the values as written, or "(missing)"
};

// Every query of `reference`'s state whose value in `test` differs (or is missing), every query
// only `test` has, and the error left by the scene (key "error_after_scene").
// Mismatches a known-differences file accepts: lines `REGEX  reason` (the regex is searched for
// in the query's key; `#` starts a comment line). Used for queries where glpt deliberately
// follows the GL 1.5 spec rather than Mesa, each with its reason.
struct KnownDifference {
  std::string pattern, reason;
};
bool parse_known_differences(const std::string& text, std::vector<KnownDifference>* out,
                             std::string* error);
// The known difference that accepts `mismatch`, or nullptr.
const KnownDifference* find_known(const std::vector<KnownDifference>& known,
                                  const Mismatch& mismatch);

std::vector<Mismatch> compare_states(const StateDump& reference, const StateDump& test,
                                     double float_tolerance = 1e-6);

}  // namespace glpt::statecompare
