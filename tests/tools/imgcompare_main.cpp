// glpt_imgcompare: image checks for the end-to-end and conformance tests, and the comparison of
// two GL state dumps. Exit status 0 = pass, 1 = the check
// failed, 2 = usage or I/O error. Run without arguments for usage.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "image_io.hpp"
#include "imgcompare.hpp"
#include "state_compare.hpp"

namespace {

using glpt::ImageRGBA8;
namespace ic = glpt::imgcompare;

constexpr int kPass = 0, kFail = 1, kUsage = 2;

const char kUsageText[] =
    "usage:\n"
    "  glpt_imgcompare coverage A.png B.png --background R,G,B --tolerance T\n"
    "                  [--min-iou 0.98] [--diff OUT.png]\n"
    "      Coverage mask = pixels whose colour differs from the background by more than T\n"
    "      (largest channel difference, 0..255). Passes iff IoU(A, B) >= min-iou. Writes a diff\n"
    "      image (red: only A, green: only B, white: both) to OUT.png, or on failure next to A.\n"
    "  glpt_imgcompare lit-vs-away SHADED.png FACING.png --background R,G,B [--tolerance 24]\n"
    "                  [--lit 0.25] [--away 0.02] [--min-class-fraction 0.01]\n"
    "                  [--margin 0.05] [--ratio 1.5]\n"
    "      FACING is an N.L oracle (white, diffuse-only, flat). Its covered pixels brighter\n"
    "      than --lit are 'lit', darker than --away are 'away' (Rec. 709 luma, 0..1). Passes iff\n"
    "      both classes hold >= min-class-fraction of the covered pixels and SHADED's mean luma\n"
    "      over lit exceeds that over away by >= margin and by a factor >= ratio.\n"
    "  glpt_imgcompare within REFERENCE.png TEST.png [--max-diff 2] [--min-fraction 0.995]\n"
    "                  [--diff OUT.png]\n"
    "      Passes iff at least min-fraction of the pixels have every channel (RGBA) within\n"
    "      max-diff (0..255) of the reference. Prints that fraction, the largest channel\n"
    "      difference and the PSNR. Writes a difference image to OUT.png, or on failure next to\n"
    "      TEST (TEST.diff.png): four panels, reference | test | |difference| x16 | mask\n"
    "      (red: outside the tolerance, blue: differs within it, grey: identical).\n"
    "  glpt_imgcompare state REFERENCE.state.json TEST.state.json [--float-tolerance 1e-6]\n"
    "                  [--known KNOWN.txt]\n"
    "      Compares two GL state dumps of the conformance runners: integers, enums and booleans\n"
    "      exactly, floats within the tolerance (relative, absolute below magnitude 1), and\n"
    "      the error left by the scene. Lists every mismatching query; passes iff none but\n"
    "      those KNOWN.txt accepts (lines `REGEX  reason`, the regex searched in the key).\n"
    "  glpt_imgcompare psnr A.png B.png\n"
    "      Prints the PSNR over RGB in dB ('inf' for identical images).\n"
    "  glpt_imgcompare nonblank FILE.png... [--min-fraction 0.01] [--tolerance 0]\n"
    "      Passes iff in every file >= min-fraction of the pixels differ from the top-left one.\n"
    "exit status: 0 pass, 1 check failed, 2 usage or I/O error\n";

struct Args {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;
};

// Splits argv into positional arguments and "--key value" options; only `allowed` keys.
bool parse(int argc, char** argv, const std::set<std::string>& allowed, Args* out) {
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--", 0) == 0) {
      if (!allowed.count(a)) {
        std::fprintf(stderr, "glpt_imgcompare: unknown option %s\n", a.c_str());
        return false;
      }
      if (i + 1 >= argc) {
        std::fprintf(stderr, "glpt_imgcompare: %s needs a value\n", a.c_str());
        return false;
      }
      out->options[a] = argv[++i];
    } else {
      out->positional.push_back(a);
    }
  }
  return true;
}

bool get_double(const Args& args, const std::string& key, double* value) {
  const auto it = args.options.find(key);
  if (it == args.options.end()) return true;  // keep the default
  char* end = nullptr;
  *value = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || *end != '\0' || !std::isfinite(*value)) {
    std::fprintf(stderr, "glpt_imgcompare: %s: not a number: %s\n", key.c_str(),
                 it->second.c_str());
    return false;
  }
  return true;
}

bool get_int(const Args& args, const std::string& key, int lo, int hi, int* value) {
  double v = *value;
  if (!get_double(args, key, &v)) return false;
  if (v != std::floor(v) || v < lo || v > hi) {
    std::fprintf(stderr, "glpt_imgcompare: %s must be an integer in %d..%d\n", key.c_str(), lo, hi);
    return false;
  }
  *value = static_cast<int>(v);
  return true;
}

bool get_background(const Args& args, ic::Rgb* bg) {
  const auto it = args.options.find("--background");
  if (it == args.options.end()) {
    std::fprintf(stderr, "glpt_imgcompare: --background R,G,B is required\n");
    return false;
  }
  if (!ic::parse_rgb(it->second, bg)) {
    std::fprintf(stderr, "glpt_imgcompare: bad --background '%s' (want R,G,B in 0..255)\n",
                 it->second.c_str());
    return false;
  }
  return true;
}

bool load(const std::string& path, ImageRGBA8* image) {
  std::string error;
  if (!glpt::read_png_rgba8(path, image, &error)) {
    std::fprintf(stderr, "glpt_imgcompare: %s\n", error.c_str());
    return false;
  }
  return true;
}

std::string sibling_path(const std::string& path, const std::string& suffix) {
  const std::string ext = ".png";
  if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0) {
    return path.substr(0, path.size() - ext.size()) + suffix;
  }
  return path + suffix;
}

// Writes `diff` where --diff says, or on failure to `failure_path`, and says where and how to read
// it. Returns false on an I/O error.
bool write_diff(const Args& args, bool pass, const std::string& failure_path,
                const ImageRGBA8& diff, const char* command, const std::string& legend) {
  std::string path;
  if (args.options.count("--diff")) {
    path = args.options.at("--diff");
  } else if (!pass) {
    path = failure_path;
  }
  if (path.empty()) return true;
  std::string error;
  if (!glpt::write_png_rgba8(path, diff.width, diff.height, diff.pixels.data(), false, &error)) {
    std::fprintf(stderr, "glpt_imgcompare: %s\n", error.c_str());
    return false;
  }
  std::printf("%s: diff image %s (%s)\n", command, path.c_str(), legend.c_str());
  return true;
}

int cmd_coverage(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, {"--background", "--tolerance", "--min-iou", "--diff"}, &args)) {
    return kUsage;
  }
  if (args.positional.size() != 2 || !args.options.count("--tolerance")) {
    std::fprintf(stderr, "glpt_imgcompare coverage: want A.png B.png and --tolerance T\n");
    return kUsage;
  }
  ic::Rgb bg;
  int tolerance = 0;
  double min_iou = 0.98;
  if (!get_background(args, &bg) || !get_int(args, "--tolerance", 0, 255, &tolerance) ||
      !get_double(args, "--min-iou", &min_iou)) {
    return kUsage;
  }
  ImageRGBA8 a, b, diff;
  if (!load(args.positional[0], &a) || !load(args.positional[1], &b)) return kUsage;
  ic::CoverageResult r;
  std::string error;
  if (!ic::coverage(a, b, bg, tolerance, &r, &diff, &error)) {
    std::fprintf(stderr, "glpt_imgcompare coverage: %s\n", error.c_str());
    return kFail;
  }
  const bool pass = r.iou >= min_iou;
  std::printf(
      "coverage: iou=%.5f min_iou=%.5f both=%llu only_a=%llu only_b=%llu neither=%llu "
      "tolerance=%d background=%d,%d,%d -> %s\n",
      r.iou, min_iou, static_cast<unsigned long long>(r.both),
      static_cast<unsigned long long>(r.only_a), static_cast<unsigned long long>(r.only_b),
      static_cast<unsigned long long>(r.neither), tolerance, bg.r, bg.g, bg.b,
      pass ? "PASS" : "FAIL");
  if (!write_diff(args, pass, sibling_path(args.positional[0], ".coverage_diff.png"), diff,
                  "coverage", "red: only A, green: only B, white: both")) {
    return kUsage;
  }
  return pass ? kPass : kFail;
}

int cmd_lit_vs_away(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv,
             {"--background", "--tolerance", "--lit", "--away", "--min-class-fraction", "--margin",
              "--ratio"},
             &args)) {
    return kUsage;
  }
  if (args.positional.size() != 2) {
    std::fprintf(stderr, "glpt_imgcompare lit-vs-away: want SHADED.png FACING.png\n");
    return kUsage;
  }
  ic::Rgb bg;
  ic::LitAwayOptions o;
  if (!get_background(args, &bg) || !get_int(args, "--tolerance", 0, 255, &o.tolerance) ||
      !get_double(args, "--lit", &o.lit_threshold) ||
      !get_double(args, "--away", &o.away_threshold) ||
      !get_double(args, "--min-class-fraction", &o.min_class_fraction) ||
      !get_double(args, "--margin", &o.min_margin) || !get_double(args, "--ratio", &o.min_ratio)) {
    return kUsage;
  }
  ImageRGBA8 shaded, facing;
  if (!load(args.positional[0], &shaded) || !load(args.positional[1], &facing)) return kUsage;
  ic::LitAwayResult r;
  std::string error;
  if (!ic::lit_vs_away(shaded, facing, bg, o, &r, &error)) {
    std::fprintf(stderr, "glpt_imgcompare lit-vs-away: %s\n", error.c_str());
    return kFail;
  }
  std::printf(
      "lit-vs-away: %s covered=%llu lit=%llu away=%llu mean_lit=%.4f mean_away=%.4f "
      "(need margin >= %.3f, ratio >= %.2f, classes >= %.1f%% of covered) -> %s%s%s\n",
      args.positional[0].c_str(), static_cast<unsigned long long>(r.covered),
      static_cast<unsigned long long>(r.lit), static_cast<unsigned long long>(r.away), r.mean_lit,
      r.mean_away, o.min_margin, o.min_ratio, 100.0 * o.min_class_fraction,
      r.pass ? "PASS" : "FAIL", r.pass ? "" : ": ", r.reason.c_str());
  return r.pass ? kPass : kFail;
}

int cmd_within(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, {"--max-diff", "--min-fraction", "--diff"}, &args)) return kUsage;
  if (args.positional.size() != 2) {
    std::fprintf(stderr, "glpt_imgcompare within: want REFERENCE.png TEST.png\n");
    return kUsage;
  }
  int max_diff = 2;
  double min_fraction = 0.995;
  if (!get_int(args, "--max-diff", 0, 255, &max_diff) ||
      !get_double(args, "--min-fraction", &min_fraction)) {
    return kUsage;
  }
  ImageRGBA8 reference, test, diff;
  if (!load(args.positional[0], &reference) || !load(args.positional[1], &test)) return kUsage;
  ic::WithinResult r;
  double db = 0.0;
  std::string error;
  if (!ic::within_tolerance(reference, test, max_diff, &r, &diff, &error) ||
      !ic::psnr(reference, test, &db, &error)) {
    std::fprintf(stderr, "glpt_imgcompare within: %s\n", error.c_str());
    return kFail;
  }
  const bool pass = r.fraction >= min_fraction;
  char psnr_text[32];
  std::snprintf(psnr_text, sizeof psnr_text, std::isinf(db) ? "inf" : "%.2f", db);
  std::printf(
      "within: fraction=%.6f max_diff=%d psnr=%s (tolerance: %d/255 on >= %.4f of %llu "
      "pixels) -> %s\n",
      r.fraction, r.max_diff, psnr_text, max_diff, min_fraction,
      static_cast<unsigned long long>(r.pixels), pass ? "PASS" : "FAIL");
  if (!write_diff(args, pass, sibling_path(args.positional[1], ".diff.png"), diff, "within",
                  ic::kDiffPanels)) {
    return kUsage;
  }
  return pass ? kPass : kFail;
}

bool load_state(const std::string& path, glpt::statecompare::StateDump* out) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    std::fprintf(stderr, "glpt_imgcompare state: cannot read %s\n", path.c_str());
    return false;
  }
  std::stringstream text;
  text << file.rdbuf();
  std::string error;
  if (!glpt::statecompare::parse_state_dump(text.str(), out, &error)) {
    std::fprintf(stderr, "glpt_imgcompare state: %s: %s\n", path.c_str(), error.c_str());
    return false;
  }
  return true;
}

int cmd_state(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, {"--float-tolerance", "--known"}, &args)) return kUsage;
  if (args.positional.size() != 2) {
    std::fprintf(stderr, "glpt_imgcompare state: want REFERENCE.state.json TEST.state.json\n");
    return kUsage;
  }
  double tolerance = 1e-6;
  if (!get_double(args, "--float-tolerance", &tolerance)) return kUsage;
  std::vector<glpt::statecompare::KnownDifference> known;
  if (auto it = args.options.find("--known"); it != args.options.end()) {
    std::ifstream file(it->second);
    std::stringstream text;
    text << file.rdbuf();
    std::string error;
    if (!file || !glpt::statecompare::parse_known_differences(text.str(), &known, &error)) {
      std::fprintf(stderr, "glpt_imgcompare state: %s: %s\n", it->second.c_str(),
                   file ? error.c_str() : "cannot read");
      return kUsage;
    }
  }
  glpt::statecompare::StateDump reference, test;
  if (!load_state(args.positional[0], &reference) || !load_state(args.positional[1], &test))
    return kUsage;
  const auto mismatches = glpt::statecompare::compare_states(reference, test, tolerance);
  size_t unexpected = 0;
  for (const auto& m : mismatches) {
    const auto* k = glpt::statecompare::find_known(known, m);
    if (!k) ++unexpected;
    std::printf("state: %s: %s %s, %s %s%s%s\n", m.key.c_str(), reference.backend.c_str(),
                m.reference.c_str(), test.backend.c_str(), m.test.c_str(),
                k ? " (known: " : "", k ? (k->reason + ")").c_str() : "");
  }
  std::printf("state: %s: %zu queries, %zu mismatches (%zu known) -> %s\n",
              reference.scene.c_str(), reference.state.size() + 1, mismatches.size(),
              mismatches.size() - unexpected, unexpected == 0 ? "PASS" : "FAIL");
  return unexpected == 0 ? kPass : kFail;
}

int cmd_psnr(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, {}, &args)) return kUsage;
  if (args.positional.size() != 2) {
    std::fprintf(stderr, "glpt_imgcompare psnr: want A.png B.png\n");
    return kUsage;
  }
  ImageRGBA8 a, b;
  if (!load(args.positional[0], &a) || !load(args.positional[1], &b)) return kUsage;
  double db = 0.0;
  std::string error;
  if (!ic::psnr(a, b, &db, &error)) {
    std::fprintf(stderr, "glpt_imgcompare psnr: %s\n", error.c_str());
    return kUsage;
  }
  if (std::isinf(db)) {
    std::printf("psnr=inf\n");
  } else {
    std::printf("psnr=%.3f\n", db);
  }
  return kPass;
}

int cmd_nonblank(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, {"--min-fraction", "--tolerance"}, &args)) return kUsage;
  if (args.positional.empty()) {
    std::fprintf(stderr, "glpt_imgcompare nonblank: want at least one FILE.png\n");
    return kUsage;
  }
  double min_fraction = 0.01;
  int tolerance = 0;
  if (!get_double(args, "--min-fraction", &min_fraction) ||
      !get_int(args, "--tolerance", 0, 255, &tolerance)) {
    return kUsage;
  }
  int status = kPass;
  for (const std::string& path : args.positional) {
    ImageRGBA8 image;
    if (!load(path, &image)) return kUsage;
    const double f = ic::fraction_differing_from_corner(image, tolerance);
    const bool pass = f >= min_fraction;
    std::printf("nonblank: %s %ux%u differing_from_corner=%.4f min=%.4f -> %s\n", path.c_str(),
                image.width, image.height, f, min_fraction, pass ? "PASS" : "FAIL");
    if (!pass) status = kFail;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(kUsageText, stderr);
    return kUsage;
  }
  const std::string cmd = argv[1];
  if (cmd == "coverage") return cmd_coverage(argc, argv);
  if (cmd == "lit-vs-away") return cmd_lit_vs_away(argc, argv);
  if (cmd == "within") return cmd_within(argc, argv);
  if (cmd == "state") return cmd_state(argc, argv);
  if (cmd == "psnr") return cmd_psnr(argc, argv);
  if (cmd == "nonblank") return cmd_nonblank(argc, argv);
  if (cmd == "--help" || cmd == "-h") {
    std::fputs(kUsageText, stdout);
    return kPass;
  }
  std::fprintf(stderr, "glpt_imgcompare: unknown command '%s'\n%s", cmd.c_str(), kUsageText);
  return kUsage;
}
