#include "quality_flags.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace glpt::cli {
namespace {

// The ranges in the help texts are rt_core's (rt_core/render_settings.cpp): it validates the
// values and warns about and ignores those outside them.
constexpr std::array kFlags = {
    QualityFlag{"--mode", "GLPT_MODE", FlagValue::kChoice, "path|raster",
                "path tracing (default) or GL fixed function on Vulkan raster pipelines"},
    QualityFlag{"--spp", "GLPT_SPP", FlagValue::kCount, "N",
                "samples per pixel per frame, 1..1024 (default 1)"},
    QualityFlag{"--bounces", "GLPT_BOUNCES", FlagValue::kCount, "N",
                "bounces after the primary hit, 0..16 (default 1; 0 = direct light)"},
    QualityFlag{"--scale", "GLPT_SCALE", FlagValue::kNumber, "S",
                "trace S x S of the pixels per frame, 0.25..1 (default 1), the rest filled from "
                "traced neighbours on the same surface"},
    QualityFlag{"--shadows", "GLPT_SHADOWS", FlagValue::kChoice, "0|1",
                "shadow rays (default 1); --shadows 0 --ao 0 --bounces 0 is GL's own lighting"},
    QualityFlag{"--ao", "GLPT_AO", FlagValue::kChoice, "0|1",
                "GL's ambient light occluded by ray-traced ambient occlusion (default 1)"},
    QualityFlag{"--ao-radius", "GLPT_AO_RADIUS", FlagValue::kNumber, "R",
                "fixed AO radius in eye-space units (default 0: each occluder's own size)"},
    QualityFlag{"--unlit", "GLPT_UNLIT", FlagValue::kChoice, "keep|ao|emit",
                "what tracing adds to unlit draws: nothing (default), AO, or their light"},
    QualityFlag{"--light-radius", "GLPT_LIGHT_RADIUS", FlagValue::kNumber, "R",
                "radius of positional lights in eye-space units (default: --light-size-deg "
                "seen from the eye; 0 = point lights)"},
    QualityFlag{"--light-choice", "GLPT_LIGHT_CHOICE", FlagValue::kChoice,
                "contribution|uniform|all",
                "the light of a sample: by its contribution (default), uniformly, or all"},
    QualityFlag{"--default-light", "GLPT_DEFAULT_LIGHT", FlagValue::kNone, "1",
                "give a lit scene without any GL light a white directional light"},
    QualityFlag{"--environment", "GLPT_ENVIRONMENT", FlagValue::kChoice, "black|clear",
                "what rays that miss see: nothing (default) or the clear colour"},
    QualityFlag{"--reference", "GLPT_REFERENCE", FlagValue::kCount, "N",
                "render every frame with N samples per pixel from scratch (ground truth)"},
    QualityFlag{"--no-accumulate", "GLPT_ACCUMULATE", FlagValue::kNone, "0",
                "do not average frames while nothing changes"},
    QualityFlag{"--no-blas-refit", "GLPT_BLAS_REFIT", FlagValue::kNone, "0",
                "build a deforming object's BLAS anew every frame instead of refitting it"},
    QualityFlag{"--blue-noise", "GLPT_BLUE_NOISE", FlagValue::kNone, "1",
                "pixels share their sample points, offset by a blue-noise mask (less noise in "
                "one denoised frame; see docs/light-transport.md)"},
    QualityFlag{"--max-spp", "GLPT_MAX_SPP", FlagValue::kCount, "N",
                "stop accumulating at N samples per pixel"},
    QualityFlag{"--light-size-deg", "GLPT_LIGHT_SIZE_DEG", FlagValue::kNumber, "D",
                "angular radius of directional lights (and, seen from the eye, of positional "
                "ones), 0..45 (default 1)"},
    QualityFlag{"--denoiser", "GLPT_DENOISER", FlagValue::kChoice, "svgf|off",
                "filter each frame's samples with SVGF (default) or show them raw"},
    QualityFlag{"--denoise-iterations", "GLPT_DENOISE_ITERATIONS", FlagValue::kCount, "N",
                "SVGF a-trous iterations, 0..10 (default 5)"},
    QualityFlag{"--denoise-alpha", "GLPT_DENOISE_ALPHA", FlagValue::kNumber, "A",
                "SVGF colour history weight of a new frame, 0.01..1 (default 0.2)"},
    QualityFlag{"--denoise-moments-alpha", "GLPT_DENOISE_MOMENTS_ALPHA", FlagValue::kNumber, "A",
                "SVGF moments history weight, 0.01..1 (default 0.2)"},
    QualityFlag{"--denoise-sigma-depth", "GLPT_DENOISE_SIGMA_DEPTH", FlagValue::kNumber, "S",
                "SVGF depth edge-stopping, in pixel footprints (default 1)"},
    QualityFlag{"--denoise-sigma-normal", "GLPT_DENOISE_SIGMA_NORMAL", FlagValue::kNumber, "S",
                "SVGF normal edge-stopping exponent (default 128)"},
    QualityFlag{"--denoise-sigma-luminance", "GLPT_DENOISE_SIGMA_LUMINANCE", FlagValue::kNumber,
                "S", "SVGF luminance edge-stopping, in standard deviations (default 4)"},
    QualityFlag{"--denoise-kernel", "GLPT_DENOISE_KERNEL", FlagValue::kChoice, "0|1|2",
                "SVGF a-trous kernel: 0 = four taps, cross and diagonal in turn (default), "
                "1 = 3x3, 2 = 5x5 (the paper's)"},
    QualityFlag{"--denoise-clamp", "GLPT_DENOISE_CLAMP", FlagValue::kNumber, "K",
                "clamp the history to a fast average +- K deviations (default 3; 0 = off)"},
    QualityFlag{"--denoise-fast-alpha", "GLPT_DENOISE_FAST_ALPHA", FlagValue::kNumber, "A",
                "weight of a new frame in the fast average (default 0.7)"},
    QualityFlag{"--denoise-until", "GLPT_DENOISE_UNTIL", FlagValue::kCount, "N",
                "a still image shows its accumulated average from N samples on (default 32)"},
    QualityFlag{"--no-denoise-vertex-motion", "GLPT_DENOISE_VERTEX_MOTION", FlagValue::kNone, "0",
                "deformed surfaces reproject through their draw's transform only, not through "
                "their triangles' previous vertices (A/B)"},
    QualityFlag{"--denoise-sample-variance", "GLPT_DENOISE_MEAN_VARIANCE", FlagValue::kNone, "0",
                "the a-trous filter's luminance edge-stopping takes one sample's variance, as "
                "the 2017 paper (default: the integrated colour's)"},
    QualityFlag{"--no-taa", "GLPT_TAA", FlagValue::kNone, "0",
                "no temporal anti-aliasing after the denoiser (frames at pixel centres)"},
    QualityFlag{"--taa-alpha", "GLPT_TAA_ALPHA", FlagValue::kNumber, "A",
                "temporal anti-aliasing: weight of a new frame at edges, 0.01..1 (default 0.3)"},
    QualityFlag{"--taa-gamma", "GLPT_TAA_GAMMA", FlagValue::kNumber, "G",
                "temporal anti-aliasing: history clipped to the neighbourhood's mean +- G "
                "deviations (default 1)"},
    QualityFlag{"--output", "GLPT_OUTPUT", FlagValue::kText, "DIR",
                "also write every frame as DIR/frame_NNNNNN.png"},
    QualityFlag{"--output-every", "GLPT_OUTPUT_EVERY", FlagValue::kCount, "N",
                "with --output: only every Nth frame"},
    QualityFlag{"--stats", "GLPT_STATS", FlagValue::kNone, "1",
                "one line per frame on stderr: timings, draws, rays, BLAS builds"},
    QualityFlag{"--stats-file", "GLPT_STATS_FILE", FlagValue::kText, "FILE",
                "the --stats lines appended to FILE instead of stderr"},
    QualityFlag{"--classify-log", "GLPT_CLASSIFY_LOG", FlagValue::kText, "FILE",
                "append every draw's class and identity to FILE, one JSON line each "
                "(docs/classification.md)"},
    QualityFlag{"--classify-debug", "GLPT_CLASSIFY_DEBUG", FlagValue::kNone, "1",
                "tint every draw by its class (palette in docs/classification.md)"},
    QualityFlag{"--validation", "GLPT_VALIDATION", FlagValue::kNone, "1",
                "enable the Khronos Vulkan validation layer"},
    QualityFlag{"--vk-device", "GLPT_VK_DEVICE", FlagValue::kText, "SUBSTR",
                "pick the Vulkan device whose name contains SUBSTR"},
    QualityFlag{"--quiet", "GLPT_QUIET", FlagValue::kNone, "1",
                "no message for unimplemented GL commands"},
};

bool is_count(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool is_number(const std::string& s) {
  if (s.empty() || s[0] == '-' || s[0] == '+') return false;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return errno == 0 && *end == '\0' && std::isfinite(v);
}

bool is_choice(const std::string& s, std::string_view choices) {
  size_t start = 0;
  while (start <= choices.size()) {
    const size_t bar = std::min(choices.find('|', start), choices.size());
    if (choices.substr(start, bar - start) == s) return true;
    start = bar + 1;
  }
  return false;
}

bool valid(const QualityFlag& f, const std::string& value) {
  switch (f.value) {
    case FlagValue::kCount:
      return is_count(value);
    case FlagValue::kNumber:
      return is_number(value);
    case FlagValue::kText:
      return !value.empty();
    case FlagValue::kChoice:
      return is_choice(value, f.metavar);
    case FlagValue::kNone:
      return true;
  }
  return false;
}

const char* expected(FlagValue v) {
  switch (v) {
    case FlagValue::kCount:
      return "a whole number";
    case FlagValue::kNumber:
      return "a non-negative number";
    case FlagValue::kText:
      return "a non-empty value";
    case FlagValue::kChoice:
      return "one of";
    case FlagValue::kNone:
      return "no value";
  }
  return "";
}

}  // namespace

std::span<const QualityFlag> quality_flags() { return kFlags; }

FlagParse parse_quality_flag(std::span<const std::string> args, size_t* i, EnvSettings* env,
                             std::string* error) {
  const std::string& arg = args[*i];
  const size_t eq = arg.find('=');
  const std::string_view name = std::string_view(arg).substr(0, eq);
  const auto it = std::find_if(kFlags.begin(), kFlags.end(),
                               [&](const QualityFlag& f) { return f.flag == name; });
  if (it == kFlags.end()) return FlagParse::kNotAQualityFlag;
  const QualityFlag& f = *it;
  if (f.value == FlagValue::kNone) {
    if (eq != std::string::npos) {
      *error = std::string(f.flag) + " takes no value";
      return FlagParse::kError;
    }
    env->emplace_back(f.variable, f.metavar);
    *i += 1;
    return FlagParse::kParsed;
  }
  std::string value;
  size_t consumed = 1;
  if (eq != std::string::npos) {
    value = arg.substr(eq + 1);
  } else if (*i + 1 < args.size()) {
    value = args[*i + 1];
    consumed = 2;
  } else {
    *error = std::string(f.flag) + " needs a value (" + std::string(f.metavar) + ")";
    return FlagParse::kError;
  }
  if (!valid(f, value)) {
    // Appended piece by piece: GCC 12 at -O3 misjudges `" " + std::string(...)` (a temporary
    // inserted into) as an overlapping memcpy (-Werror=restrict, GCC bug 105329).
    *error = std::string(f.flag) + ": \"" + value + "\" is not " + expected(f.value);
    if (f.value == FlagValue::kChoice) error->append(" ").append(f.metavar);
    return FlagParse::kError;
  }
  env->emplace_back(f.variable, value);
  *i += consumed;
  return FlagParse::kParsed;
}

std::string quality_flags_help(std::string_view indent) {
  auto usage = [](const QualityFlag& f) {
    return f.value == FlagValue::kNone ? std::string(f.flag)
                                       : std::string(f.flag) + " " + std::string(f.metavar);
  };
  size_t width = 0;
  for (const QualityFlag& f : kFlags) width = std::max(width, usage(f).size());
  std::string text;
  for (const QualityFlag& f : kFlags) {
    const std::string u = usage(f);
    text += std::string(indent) + u + std::string(width + 2 - u.size(), ' ') + std::string(f.help) +
            " [" + std::string(f.variable) + "]\n";
  }
  return text;
}

}  // namespace glpt::cli
