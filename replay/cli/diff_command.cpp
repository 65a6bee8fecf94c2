// `glpt diff A B`: FLIP, PSNR and the share of visibly different pixels for two images or two
// directories of PNGs matched by file name.
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include "commands.hpp"
#include "flip.hpp"
#include "heatmap.hpp"
#include "image_io.hpp"
#include "process.hpp"
#include "psnr.hpp"

namespace glpt::cli {
namespace {

namespace fs = std::filesystem;

// Defaults, explained in docs/image-diff.md. A pixel's FLIP is above 0.05 for a difference
// larger than two 8-bit steps of a flat mid grey (128 against 130 gives 0.048); a mean over 0.05
// is a difference visible across the image (+-6 levels of noise on a gradient gives 0.042).
constexpr double kDefaultPixelTolerance = 0.05;
constexpr double kDefaultThreshold = 0.05;

struct DiffOptions {
  std::string a, b;
  double ppd = diff::default_pixels_per_degree();
  double pixel_tolerance = kDefaultPixelTolerance;
  double threshold = kDefaultThreshold;
  std::string heatmap;  // empty: none
  bool json = false;
  bool ignore_unmatched = false;
};

struct Pair {
  std::string a, b;     // empty when the name is only on the other side
  std::string heatmap;  // where to write this pair's heat map; empty: nowhere
};

bool is_directory(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::string file_name(const std::string& path) { return fs::path(path).filename().string(); }

bool has_png_extension(const std::string& name) {
  if (name.size() < 4) return false;
  std::string ext = name.substr(name.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".png";
}

// The PNG files directly in `dir`, by file name.
std::optional<std::map<std::string, std::string>> list_pngs(const std::string& dir,
                                                            std::string* error) {
  std::error_code ec;
  std::map<std::string, std::string> names;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (has_png_extension(name) && it->is_regular_file(ec)) names[name] = it->path().string();
  }
  if (ec) {
    *error = "cannot list " + dir + ": " + ec.message();
    return std::nullopt;
  }
  return names;
}

std::string join(const std::string& dir, const std::string& name) {
  return (fs::path(dir) / name).string();
}

std::string json_string(const std::string& s) {
  std::string r = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"':
        r += "\\\"";
        break;
      case '\\':
        r += "\\\\";
        break;
      case '\n':
        r += "\\n";
        break;
      case '\t':
        r += "\\t";
        break;
      case '\r':
        r += "\\r";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          r += buf;
        } else {
          r += static_cast<char>(c);
        }
    }
  }
  return r + "\"";
}

std::string json_path(const std::string& s) { return s.empty() ? "null" : json_string(s); }

std::string number(double v, int precision = 9) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", precision, v);
  return buf;
}

bool parse_number(const std::string& text, double* out) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || errno != 0 || *end != '\0' || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

// Parses the command line; returns an error message, or nothing (and *help when --help).
std::optional<std::string> parse(std::span<const std::string> args, DiffOptions* o, bool* help) {
  std::vector<std::string> positional;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string a = args[i], value;
    bool has_value = false;
    if (const size_t eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = a.substr(eq + 1);
      a = a.substr(0, eq);
      has_value = true;
    }
    auto take_value = [&]() -> bool {
      if (has_value) return true;
      if (i + 1 >= args.size()) return false;
      value = args[++i];
      return true;
    };
    // A number >= 0 (> 0 when `positive`).
    auto take_number = [&](double* out, bool positive) -> std::optional<std::string> {
      if (!take_value()) return a + " needs a number";
      if (!parse_number(value, out) || *out < 0.0 || (positive && *out == 0.0)) {
        return a + ": \"" + value + "\" is not a number " + (positive ? "above 0" : ">= 0");
      }
      return std::nullopt;
    };
    std::optional<std::string> problem;
    if (is_help_flag(a)) {
      *help = true;
      return std::nullopt;
    } else if (a == "--ppd") {
      problem = take_number(&o->ppd, true);
    } else if (a == "--pixel-tolerance") {
      problem = take_number(&o->pixel_tolerance, false);
    } else if (a == "--threshold") {
      problem = take_number(&o->threshold, false);
    } else if (a == "--heatmap") {
      if (!take_value() || value.empty()) problem = "--heatmap needs a file or directory";
      o->heatmap = value;
    } else if (a == "--json" && !has_value) {
      o->json = true;
    } else if (a == "--ignore-unmatched" && !has_value) {
      o->ignore_unmatched = true;
    } else if (a == "--") {
      positional.insert(positional.end(), args.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                        args.end());
      break;
    } else if (a.size() > 1 && a[0] == '-') {
      problem = "unknown option " + args[i];
    } else {
      positional.push_back(a);
    }
    if (problem) return problem;
  }
  if (positional.size() != 2) {
    return "expected two images or directories, got " + std::to_string(positional.size()) +
           " argument(s)";
  }
  o->a = positional[0];
  o->b = positional[1];
  return std::nullopt;
}

// Pairs up the inputs. A file is matched with the file of the same name in a directory on the
// other side; two directories are matched name by name.
std::optional<std::vector<Pair>> make_pairs(const DiffOptions& o, std::string* error) {
  const bool a_dir = is_directory(o.a), b_dir = is_directory(o.b);
  for (const auto& [path, dir] : {std::pair{o.a, a_dir}, std::pair{o.b, b_dir}}) {
    if (!dir && !is_regular_file(path)) {
      *error = path + ": no such file or directory";
      return std::nullopt;
    }
  }
  const bool heatmap_dir = !o.heatmap.empty() && ((a_dir && b_dir) || is_directory(o.heatmap));
  auto heatmap_for = [&](const std::string& name) {
    if (o.heatmap.empty()) return std::string();
    return heatmap_dir ? join(o.heatmap, name) : o.heatmap;
  };
  std::vector<Pair> pairs;
  if (!a_dir && !b_dir) {
    pairs.push_back({o.a, o.b, heatmap_for(file_name(o.b))});
  } else if (a_dir != b_dir) {
    const std::string& file = a_dir ? o.b : o.a;
    const std::string other = join(a_dir ? o.a : o.b, file_name(file));
    pairs.push_back(a_dir ? Pair{other, file, heatmap_for(file_name(file))}
                          : Pair{file, other, heatmap_for(file_name(file))});
  } else {
    const auto a_names = list_pngs(o.a, error);
    if (!a_names) return std::nullopt;
    const auto b_names = list_pngs(o.b, error);
    if (!b_names) return std::nullopt;
    std::map<std::string, Pair> by_name;
    for (const auto& [name, path] : *a_names) by_name[name].a = path;
    for (const auto& [name, path] : *b_names) by_name[name].b = path;
    for (auto& [name, pair] : by_name) {
      if (!pair.a.empty() && !pair.b.empty()) pair.heatmap = heatmap_for(name);
      pairs.push_back(pair);
    }
  }
  return pairs;
}

// The outcome of one pair, for the report and the exit status.
enum class Outcome { kWithinThreshold, kOverThreshold, kUnmatched, kError };

struct Comparison {
  Outcome outcome = Outcome::kError;
  std::string error;
  uint32_t width = 0, height = 0;
  double flip_mean = 0, flip_max = 0, psnr = 0, fraction_over = 0;
};

Comparison compare(const Pair& pair, const DiffOptions& o) {
  Comparison c;
  if (pair.a.empty() || pair.b.empty()) {
    c.outcome = Outcome::kUnmatched;
    c.error = "no file of this name in " + (pair.a.empty() ? o.a : o.b);
    return c;
  }
  ImageRGBA8 a, b;
  std::string error;
  if (!read_png_rgba8(pair.a, &a, &error) || !read_png_rgba8(pair.b, &b, &error)) {
    c.error = error;
    return c;
  }
  if (a.width != b.width || a.height != b.height) {
    c.error = "sizes differ: " + pair.a + " is " + std::to_string(a.width) + "x" +
              std::to_string(a.height) + ", " + pair.b + " is " + std::to_string(b.width) + "x" +
              std::to_string(b.height);
    return c;
  }
  const diff::Rgb8View va{a.width, a.height, 4, a.pixels.data()};
  const diff::Rgb8View vb{b.width, b.height, 4, b.pixels.data()};
  diff::FlipResult flip;
  if (!diff::compute_flip(va, vb, o.ppd, &flip, &error)) {
    c.error = error;
    return c;
  }
  if (!pair.heatmap.empty()) {
    const std::vector<uint8_t> rgba = diff::heatmap_rgba8(flip);
    if (!write_png_rgba8(pair.heatmap, flip.width, flip.height, rgba.data(), false, &error)) {
      c.error = "heat map: " + error;
      return c;
    }
  }
  c.width = flip.width;
  c.height = flip.height;
  c.flip_mean = flip.mean;
  c.flip_max = flip.max;
  c.psnr = diff::psnr_rgb8(va, vb);
  c.fraction_over = diff::fraction_over(flip, o.pixel_tolerance);
  c.outcome = flip.mean > o.threshold ? Outcome::kOverThreshold : Outcome::kWithinThreshold;
  return c;
}

void report_json(const Pair& pair, const Comparison& c, const DiffOptions& o, std::ostream& out) {
  out << "{\"a\":" << json_path(pair.a) << ",\"b\":" << json_path(pair.b);
  if (c.outcome == Outcome::kUnmatched || c.outcome == Outcome::kError) {
    out << ",\"error\":" << json_string(c.error) << "}\n";
    return;
  }
  // JSON has no infinity: identical images (infinite PSNR) report "psnr": null.
  out << ",\"width\":" << c.width << ",\"height\":" << c.height
      << ",\"flip_mean\":" << number(c.flip_mean) << ",\"flip_max\":" << number(c.flip_max)
      << ",\"psnr\":" << (std::isinf(c.psnr) ? "null" : number(c.psnr))
      << ",\"pixel_tolerance\":" << number(o.pixel_tolerance)
      << ",\"fraction_over_tolerance\":" << number(c.fraction_over) << ",\"ppd\":" << number(o.ppd)
      << ",\"threshold\":" << number(o.threshold)
      << ",\"over_threshold\":" << (c.outcome == Outcome::kOverThreshold ? "true" : "false");
  if (!pair.heatmap.empty()) out << ",\"heatmap\":" << json_string(pair.heatmap);
  out << "}\n";
}

void report_text(const Pair& pair, const Comparison& c, const DiffOptions& o, std::ostream& out,
                 std::ostream& err) {
  if (c.outcome == Outcome::kUnmatched) {
    err << "glpt diff: " << (pair.a.empty() ? pair.b : pair.a) << ": " << c.error << "\n";
    return;
  }
  if (c.outcome == Outcome::kError) {
    err << "glpt diff: " << c.error << "\n";
    return;
  }
  out << pair.a << " vs " << pair.b << ": FLIP " << number(c.flip_mean, 4) << " (max "
      << number(c.flip_max, 3) << "), PSNR "
      << (std::isinf(c.psnr) ? std::string("inf (identical)") : number(c.psnr, 4) + " dB") << ", "
      << number(100.0 * c.fraction_over, 3) << "% of pixels over " << number(o.pixel_tolerance)
      << (c.outcome == Outcome::kOverThreshold ? ": OVER threshold " : ": within threshold ")
      << number(o.threshold) << "\n";
}

}  // namespace

std::string diff_help() {
  return "usage: glpt diff [OPTIONS] A B\n"
         "\n"
         "Compares images with FLIP (LDR-FLIP, Andersson et al., HPG 2020): the difference an\n"
         "observer sees when flipping between them, per pixel in [0, 1]; reports its mean and\n"
         "maximum, PSNR and the fraction of pixels over a tolerance. A and B are PNG files, or\n"
         "directories whose PNGs are matched by file name (a file and a directory: the file of\n"
         "the same name in the directory). A is the reference.\n"
         "\n"
         "options:\n"
         "  --ppd X               pixels per degree of the observer (default 67.02: 0.7 m from\n"
         "                        a 0.7 m wide monitor with 3840 pixels across)\n"
         "  --threshold T         a pair fails when its FLIP mean is over T (default 0.05)\n"
         "  --pixel-tolerance T   count pixels whose FLIP is over T (default 0.05)\n"
         "  --heatmap FILE|DIR    write the FLIP map as a colour-mapped PNG (black = equal,\n"
         "                        pale yellow = 1); a directory for directory inputs\n"
         "  --json                one JSON object per pair (JSON Lines) on stdout: a, b, width,\n"
         "                        height, flip_mean, flip_max, psnr (null when identical),\n"
         "                        pixel_tolerance, fraction_over_tolerance, ppd, threshold,\n"
         "                        over_threshold; or a, b, error\n"
         "  --ignore-unmatched    names found on one side only are reported, not failures\n"
         "\n"
         "exit status: 0 all pairs within the threshold; 1 some pair over it; 2 a bad command\n"
         "line, an unreadable image, a size mismatch or an unmatched name (this wins over 1).\n";
}

int diff_main(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
  DiffOptions o;
  bool help = false;
  if (const auto problem = parse(args, &o, &help)) {
    err << "glpt diff: " << *problem << " (see glpt diff --help)\n";
    return kExitUsage;
  }
  if (help) {
    out << diff_help();
    return 0;
  }
  std::string error;
  const auto pairs = make_pairs(o, &error);
  if (!pairs) {
    err << "glpt diff: " << error << "\n";
    return kExitUsage;
  }
  if (!o.heatmap.empty() && is_directory(o.a) && is_directory(o.b) && !is_directory(o.heatmap)) {
    std::error_code ec;
    if (!fs::create_directories(o.heatmap, ec) && ec) {
      err << "glpt diff: cannot create " << o.heatmap << ": " << ec.message() << "\n";
      return kExitUsage;
    }
  }
  int compared = 0, over = 0, unmatched = 0, errors = 0;
  for (const Pair& pair : *pairs) {
    const Comparison c = compare(pair, o);
    if (o.json) {
      report_json(pair, c, o, out);
      if (c.outcome == Outcome::kError) err << "glpt diff: " << c.error << "\n";
    } else {
      report_text(pair, c, o, out, err);
    }
    switch (c.outcome) {
      case Outcome::kWithinThreshold:
        ++compared;
        break;
      case Outcome::kOverThreshold:
        ++compared, ++over;
        break;
      case Outcome::kUnmatched:
        ++unmatched;
        break;
      case Outcome::kError:
        ++errors;
        break;
    }
  }
  if (pairs->size() > 1 && !o.json) {
    out << compared << " pair(s) compared, " << over << " over the threshold, " << unmatched
        << " unmatched, " << errors << " error(s)\n";
  }
  if (errors > 0 || (unmatched > 0 && !o.ignore_unmatched)) return kExitUsage;
  if (compared == 0 && !o.ignore_unmatched) {
    err << "glpt diff: no PNG pairs to compare\n";
    return kExitUsage;
  }
  return over > 0 ? 1 : 0;
}

int diff_main(std::span<const std::string> args) { return diff_main(args, std::cout, std::cerr); }

}  // namespace glpt::cli
