#include "state_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <regex>
#include <sstream>

namespace glpt::statecompare {
namespace {

// A recursive-descent reader for the JSON the runners write: objects, arrays, strings without
// escapes other than \" and \\, numbers, true and false.
class Reader {
 public:
  explicit Reader(const std::string& text) : text_(text) {}

  bool fail(const std::string& what, std::string* error) {
    if (error) *error = what + " at offset " + std::to_string(pos_);
    return false;
  }
  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n' ||
                                   text_[pos_] == '\r' || text_[pos_] == '\t'))
      ++pos_;
  }
  bool consume(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  bool peek(char c) {
    skip_space();
    return pos_ < text_.size() && text_[pos_] == c;
  }
  bool at_end() {
    skip_space();
    return pos_ == text_.size();
  }
  size_t pos() const { return pos_; }
  const std::string& text() const { return text_; }

  bool string(std::string* out, std::string* error) {
    if (!consume('"')) return fail("expected a string", error);
    out->clear();
    while (pos_ < text_.size() && text_[pos_] != '"') {
      if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) ++pos_;
      out->push_back(text_[pos_++]);
    }
    if (pos_ == text_.size()) return fail("unterminated string", error);
    ++pos_;
    return true;
  }

  // A number, true/false, or one of the strings "nan", "inf", "-inf".
  bool scalar(double* out, std::string* error) {
    skip_space();
    if (text_.compare(pos_, 4, "true") == 0) {
      pos_ += 4;
      *out = 1.0;
      return true;
    }
    if (text_.compare(pos_, 5, "false") == 0) {
      pos_ += 5;
      *out = 0.0;
      return true;
    }
    if (peek('"')) {
      std::string s;
      if (!string(&s, error)) return false;
      if (s == "nan")
        *out = std::numeric_limits<double>::quiet_NaN();
      else if (s == "inf")
        *out = std::numeric_limits<double>::infinity();
      else if (s == "-inf")
        *out = -std::numeric_limits<double>::infinity();
      else
        return fail("unexpected string '" + s + "' in an array", error);
      return true;
    }
    const char* start = text_.c_str() + pos_;
    char* end = nullptr;
    *out = std::strtod(start, &end);
    if (end == start) return fail("expected a number", error);
    pos_ += static_cast<size_t>(end - start);
    return true;
  }

 private:
  const std::string& text_;
  size_t pos_ = 0;
};

bool parse_value(Reader& r, Value* out, std::string* error) {
  const size_t start = r.pos();
  if (r.peek('"')) {
    out->is_error = true;
    if (!r.string(&out->error, error)) return false;
    out->text = out->error;
    return true;
  }
  if (!r.consume('[')) return r.fail("expected an array or a string", error);
  if (!r.consume(']')) {
    do {
      double v = 0;
      if (!r.scalar(&v, error)) return false;
      out->numbers.push_back(v);
    } while (r.consume(','));
    if (!r.consume(']')) return r.fail("expected ']'", error);
  }
  out->text = r.text().substr(start, r.pos() - start);
  const size_t first = out->text.find_first_not_of(" \n\t\r");
  out->text = first == std::string::npos ? "" : out->text.substr(first);
  return true;
}

bool parse_values(Reader& r, std::map<std::string, Value>* out, std::string* error) {
  if (!r.consume('{')) return r.fail("expected '{'", error);
  if (r.consume('}')) return true;
  do {
    std::string key;
    if (!r.string(&key, error)) return false;
    if (!r.consume(':')) return r.fail("expected ':'", error);
    Value v;
    if (!parse_value(r, &v, error)) return false;
    if (!out->emplace(key, v).second) return r.fail("duplicate key '" + key + "'", error);
  } while (r.consume(','));
  if (!r.consume('}')) return r.fail("expected '}'", error);
  return true;
}

bool values_match(const std::string& key, const Value& a, const Value& b, double tolerance) {
  if (a.is_error || b.is_error) return a.is_error == b.is_error && a.error == b.error;
  if (a.numbers.size() != b.numbers.size()) return false;
  const bool floats = is_float_query(key);
  for (size_t i = 0; i < a.numbers.size(); ++i) {
    const double x = a.numbers[i], y = b.numbers[i];
    if (std::isnan(x) || std::isnan(y)) {
      if (std::isnan(x) != std::isnan(y)) return false;
    } else if (floats ? !floats_match(x, y, tolerance) : x != y) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool parse_state_dump(const std::string& json, StateDump* out, std::string* error) {
  Reader r(json);
  *out = StateDump{};
  bool seen_state = false;
  if (!r.consume('{')) return r.fail("expected '{'", error);
  do {
    std::string key;
    if (!r.string(&key, error)) return false;
    if (!r.consume(':')) return r.fail("expected ':'", error);
    if (key == "state" || key == "implementation") {
      if (!parse_values(r, key == "state" ? &out->state : &out->implementation, error))
        return false;
      seen_state = seen_state || key == "state";
    } else {
      std::string value;
      if (!r.string(&value, error)) return false;
      if (key == "scene")
        out->scene = value;
      else if (key == "backend")
        out->backend = value;
      else if (key == "error_after_scene")
        out->error_after_scene = value;
    }
  } while (r.consume(','));
  if (!r.consume('}')) return r.fail("expected '}'", error);
  if (!r.at_end()) return r.fail("text after the dump", error);
  if (!seen_state) return r.fail("no \"state\" object", error);
  return true;
}

bool is_float_query(const std::string& key) {
  // Keys are "glGetFloatv(GL_FOG_COLOR)", optionally after a "unitN " prefix.
  const size_t space = key.find(' ');
  const size_t paren = key.find('(');
  const size_t begin = space != std::string::npos && space < paren ? space + 1 : 0;
  const std::string fn = key.substr(begin, paren == std::string::npos ? paren : paren - begin);
  const auto ends_with = [&](const char* suffix) {
    const std::string s = suffix;
    return fn.size() >= s.size() && fn.compare(fn.size() - s.size(), s.size(), s) == 0;
  };
  return ends_with("fv") || ends_with("dv") || fn == "glGetFloatv" || fn == "glGetDoublev" ||
         fn == "glGetClipPlane";
}

bool floats_match(double a, double b, double tolerance) {
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::fabs(a - b) <= tolerance * std::max({1.0, std::fabs(a), std::fabs(b)});
}

std::vector<Mismatch> compare_states(const StateDump& reference, const StateDump& test,
                                     double float_tolerance) {
  std::vector<Mismatch> out;
  if (reference.error_after_scene != test.error_after_scene)
    out.push_back({"error_after_scene", reference.error_after_scene, test.error_after_scene});
  for (const auto& [key, value] : reference.state) {
    const auto it = test.state.find(key);
    if (it == test.state.end()) {
      out.push_back({key, value.text, "(missing)"});
    } else if (!values_match(key, value, it->second, float_tolerance)) {
      out.push_back({key, value.text, it->second.text});
    }
  }
  for (const auto& [key, value] : test.state) {
    if (!reference.state.count(key)) out.push_back({key, "(missing)", value.text});
  }
  return out;
}

bool parse_known_differences(const std::string& text, std::vector<KnownDifference>* out,
                             std::string* error) {
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    const size_t gap = line.find("  ", start);
    if (gap == std::string::npos) {
      *error = "line " + std::to_string(number) + ": want `REGEX  reason` (two spaces)";
      return false;
    }
    KnownDifference known{line.substr(start, gap - start), line.substr(gap)};
    known.reason.erase(0, known.reason.find_first_not_of(' '));
    try {
      (void)std::regex(known.pattern);
    } catch (const std::regex_error&) {
      *error = "line " + std::to_string(number) + ": bad regex " + known.pattern;
      return false;
    }
    if (known.reason.empty()) {
      *error = "line " + std::to_string(number) + ": a known difference needs its reason";
      return false;
    }
    out->push_back(std::move(known));
  }
  return true;
}

const KnownDifference* find_known(const std::vector<KnownDifference>& known,
                                  const Mismatch& mismatch) {
  for (const KnownDifference& k : known)
    if (std::regex_search(mismatch.key, std::regex(k.pattern))) return &k;
  return nullptr;
}

}  // namespace glpt::statecompare
