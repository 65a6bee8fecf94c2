#include "rt_core/render_settings.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <vector>

namespace glpt::rt {
namespace {

// Upper bounds that keep a typo from hanging the program (GLPT_SPP=1000000 per frame...).
constexpr uint32_t kMaxSamplesPerFrame = 1024;
constexpr uint32_t kMaxBounces = 16;
constexpr uint32_t kMaxAccumulated = 1u << 24;  // accumulated sums stay exact-ish in float
constexpr uint32_t kMaxReference = 1u << 16;

// A parser of one of the `names`, mapped to `values` in order.
template <typename Enum, size_t N>
auto choice_parser(const char* const (&names)[N], const Enum (&values)[N]) {
  return [&names, &values](const char* text) -> std::optional<Enum> {
    for (size_t i = 0; i < N; ++i)
      if (std::strcmp(text, names[i]) == 0) return values[i];
    return std::nullopt;
  };
}

constexpr const char* kUnlitNames[] = {"keep", "ao", "emit"};
constexpr UnlitPolicy kUnlitValues[] = {UnlitPolicy::kKeep, UnlitPolicy::kAo, UnlitPolicy::kEmit};
constexpr const char* kEnvironmentNames[] = {"black", "clear"};
constexpr Environment kEnvironmentValues[] = {Environment::kBlack, Environment::kClear};
constexpr const char* kLightChoiceNames[] = {"contribution", "uniform", "all"};
constexpr LightChoice kLightChoiceValues[] = {LightChoice::kContribution, LightChoice::kUniform,
                                              LightChoice::kAll};

std::optional<uint32_t> parse_uint(const char* text, uint32_t min, uint32_t max) {
  if (text == nullptr || *text == '\0' || std::strchr(text, '-') != nullptr) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  unsigned long value = std::strtoul(text, &end, 10);
  if (errno != 0 || *end != '\0' || value < min || value > max) return std::nullopt;
  return static_cast<uint32_t>(value);
}

std::optional<float> parse_float(const char* text, float min, float max) {
  if (text == nullptr || *text == '\0') return std::nullopt;
  errno = 0;
  char* end = nullptr;
  float value = std::strtof(text, &end);
  if (errno != 0 || *end != '\0' || !std::isfinite(value) || value < min || value > max) {
    return std::nullopt;
  }
  return value;
}

std::optional<bool> parse_bool(const char* text) {
  if (text == nullptr) return std::nullopt;
  if (std::strcmp(text, "0") == 0) return false;
  if (std::strcmp(text, "1") == 0) return true;
  return std::nullopt;
}

}  // namespace

RenderSettings parse_render_settings(const std::function<const char*(const char*)>& lookup,
                                     std::string* warning) {
  RenderSettings settings;
  std::vector<std::string> problems;
  // Sets `field` from variable `name` if it is set and `parse` accepts it; otherwise records a
  // problem (unset variables are not problems).
  auto apply = [&](const char* name, auto& field, auto parse, const char* expected) {
    const char* text = lookup(name);
    if (text == nullptr) return;
    if (auto parsed = parse(text)) {
      field = *parsed;
    } else {
      problems.push_back(std::string(name) + "=\"" + text + "\" (expected " + expected + ")");
    }
  };
  apply(
      "GLPT_MODE", settings.mode,
      [](const char* text) -> std::optional<RenderMode> {
        if (std::strcmp(text, "path") == 0) return RenderMode::kPathTraced;
        if (std::strcmp(text, "raster") == 0) return RenderMode::kRaster;
        return std::nullopt;
      },
      "path or raster");
  apply(
      "GLPT_SPP", settings.samples_per_pixel,
      [](const char* text) { return parse_uint(text, 1, kMaxSamplesPerFrame); }, "1..1024");
  apply(
      "GLPT_BOUNCES", settings.bounces,
      [](const char* text) { return parse_uint(text, 0, kMaxBounces); }, "0..16");
  apply("GLPT_ACCUMULATE", settings.accumulate, parse_bool, "0 or 1");
  apply("GLPT_BLAS_REFIT", settings.blas_refit, parse_bool, "0 or 1");
  apply("GLPT_BLUE_NOISE", settings.blue_noise, parse_bool, "0 or 1");
  apply(
      "GLPT_MAX_SPP", settings.max_accumulated,
      [](const char* text) { return parse_uint(text, 1, kMaxAccumulated); }, "1..16777216");
  apply(
      "GLPT_LIGHT_SIZE_DEG", settings.light_angular_radius_deg,
      [](const char* text) { return parse_float(text, 0.0f, 45.0f); }, "0..45 degrees");
  apply(
      "GLPT_SCALE", settings.trace_scale,
      [](const char* text) { return parse_float(text, 0.25f, 1.0f); }, "0.25..1");
  apply("GLPT_VALIDATION", settings.validation, parse_bool, "0 or 1");
  apply("GLPT_SHADOWS", settings.shadows, parse_bool, "0 or 1");
  apply("GLPT_AO", settings.ambient_occlusion, parse_bool, "0 or 1");
  apply(
      "GLPT_AO_RADIUS", settings.ao_radius,
      [](const char* text) { return parse_float(text, 0.0f, 1.0e30f); }, "a distance >= 0");
  apply(
      "GLPT_LIGHT_RADIUS", settings.light_radius,
      [](const char* text) { return parse_float(text, 0.0f, 1.0e30f); }, "a distance >= 0");
  apply("GLPT_UNLIT", settings.unlit, choice_parser(kUnlitNames, kUnlitValues), "keep, ao or emit");
  apply("GLPT_DEFAULT_LIGHT", settings.default_light, parse_bool, "0 or 1");
  apply("GLPT_ENVIRONMENT", settings.environment,
        choice_parser(kEnvironmentNames, kEnvironmentValues), "black or clear");
  apply("GLPT_LIGHT_CHOICE", settings.light_choice,
        choice_parser(kLightChoiceNames, kLightChoiceValues), "contribution, uniform or all");
  apply(
      "GLPT_REFERENCE", settings.reference_samples,
      [](const char* text) { return parse_uint(text, 0, kMaxReference); }, "0..65536");
  apply("GLPT_CLASSIFY_DEBUG", settings.classify_debug, parse_bool, "0 or 1");
  DenoiseSettings& denoise = settings.denoise;
  apply(
      "GLPT_DENOISER", denoise.denoiser,
      [](const char* text) -> std::optional<Denoiser> {
        if (std::strcmp(text, "svgf") == 0) return Denoiser::kSvgf;
        if (std::strcmp(text, "off") == 0) return Denoiser::kOff;
        return std::nullopt;
      },
      "svgf or off");
  apply(
      "GLPT_DENOISE_ITERATIONS", denoise.iterations,
      [](const char* text) { return parse_uint(text, 0, 10); }, "0..10");
  auto fraction = [](const char* text) { return parse_float(text, 0.01f, 1.0f); };
  apply("GLPT_DENOISE_ALPHA", denoise.alpha, fraction, "0.01..1");
  apply("GLPT_DENOISE_MOMENTS_ALPHA", denoise.moments_alpha, fraction, "0.01..1");
  apply("GLPT_DENOISE_FAST_ALPHA", denoise.fast_alpha, fraction, "0.01..1");
  apply(
      "GLPT_DENOISE_CLAMP", denoise.fast_clamp,
      [](const char* text) { return parse_float(text, 0.0f, 100.0f); }, "0..100");
  auto sigma = [](const char* text) { return parse_float(text, 1.0e-3f, 1.0e4f); };
  apply("GLPT_DENOISE_SIGMA_DEPTH", denoise.sigma_depth, sigma, "0.001..10000");
  apply("GLPT_DENOISE_SIGMA_NORMAL", denoise.sigma_normal, sigma, "0.001..10000");
  apply("GLPT_DENOISE_SIGMA_LUMINANCE", denoise.sigma_luminance, sigma, "0.001..10000");
  apply(
      "GLPT_DENOISE_KERNEL", denoise.kernel,
      [](const char* text) { return parse_uint(text, 0, 2); }, "0 (four taps), 1 (3x3) or 2 (5x5)");
  apply(
      "GLPT_DENOISE_UNTIL", denoise.until_samples,
      [](const char* text) { return parse_uint(text, 0, kMaxAccumulated); }, "0..16777216");
  apply("GLPT_DENOISE_VERTEX_MOTION", denoise.vertex_motion, parse_bool, "0 or 1");
  apply("GLPT_DENOISE_MEAN_VARIANCE", denoise.mean_variance, parse_bool, "0 or 1");
  apply("GLPT_TAA", denoise.taa, parse_bool, "0 or 1");
  apply("GLPT_TAA_ALPHA", denoise.taa_alpha, fraction, "0.01..1");
  apply(
      "GLPT_TAA_GAMMA", denoise.taa_gamma,
      [](const char* text) { return parse_float(text, 0.1f, 100.0f); }, "0.1..100");
  if (const char* path = lookup("GLPT_CLASSIFY_LOG"); path != nullptr && *path != '\0')
    settings.classify_log = path;
  const auto set = [&](const char* name) {
    const char* value = lookup(name);
    return value != nullptr && *value != '\0' && std::strcmp(value, "0") != 0;
  };
  settings.device_timing = set("GLPT_STATS") || set("GLPT_STATS_FILE") || set("GLPT_DUMP_SCENE");
  apply("GLPT_DEVICE_TIMING", settings.device_timing, parse_bool, "0 or 1");

  if (warning != nullptr) {
    warning->clear();
    for (const std::string& problem : problems) {
      *warning += warning->empty() ? "ignoring bad settings, using defaults: " : ", ";
      *warning += problem;
    }
  }
  return settings;
}

RenderSettings RenderSettings::from_environment() {
  // Part of the C-ABI-facing API: nothing may escape, not even bad_alloc from the strings.
  try {
    std::string warning;
    RenderSettings settings =
        parse_render_settings([](const char* name) { return std::getenv(name); }, &warning);
    if (!warning.empty()) std::fprintf(stderr, "glpt: %s\n", warning.c_str());
    return settings;
  } catch (...) {
    return RenderSettings{};
  }
}

}  // namespace glpt::rt
