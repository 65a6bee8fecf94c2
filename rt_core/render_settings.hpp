// Settings of the path tracer, normally read from GLPT_* environment variables.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace glpt::rt {

// GLPT_MODE: how a frame record becomes pixels.
enum class RenderMode : uint8_t {
  kPathTraced,  // "path" (default): traced lighting, with raster pipelines for what is not traced
  kRaster,      // "raster": GL fixed function on Vulkan graphics pipelines, pixels equal Mesa's
};

// GLPT_UNLIT: what path tracing adds to draws with GL lighting off (docs/light-transport.md).
enum class UnlitPolicy : uint8_t {
  kKeep,  // "keep" (default): exactly GL's colour where seen; a diffuse reflector for bounces
  kAo,    // "ao": GL's colour darkened by ray-traced ambient occlusion
  kEmit,  // "emit": GL's colour where seen, and an emitter of it for the bounces of lit surfaces
};

// GLPT_ENVIRONMENT: what rays that leave the scene see.
enum class Environment : uint8_t {
  kBlack,  // "black" (default): nothing (GL's ambient light stands for the world around)
  kClear,  // "clear": the frame's clear colour, as radiance
};

// GLPT_LIGHT_CHOICE: how the light of a sample is chosen among a surface's GL lights.
enum class LightChoice : uint8_t {
  kContribution,  // "contribution" (default): in proportion to its estimated contribution
  kUniform,       // "uniform": every light alike
  kAll,           // "all": every light, one shadow ray each
};

// GLPT_DENOISER: what filters path-traced frames before they are shown (docs/denoiser.md).
enum class Denoiser : uint8_t {
  kSvgf,  // "svgf" (default): spatiotemporal variance-guided filtering (Schied et al. 2017)
  kOff,   // "off": the raw samples (averaged while accumulation runs)
};

// The denoiser's parameters, defaults from the SVGF paper where it gives them.
struct DenoiseSettings {
  Denoiser denoiser = Denoiser::kSvgf;
  uint32_t iterations = 5;       // GLPT_DENOISE_ITERATIONS: a-trous iterations, 0..10
  float alpha = 0.2f;            // GLPT_DENOISE_ALPHA: colour history's exponential weight
  float moments_alpha = 0.2f;    // GLPT_DENOISE_MOMENTS_ALPHA
  float sigma_depth = 1.0f;      // GLPT_DENOISE_SIGMA_DEPTH
  float sigma_normal = 128.0f;   // GLPT_DENOISE_SIGMA_NORMAL
  float sigma_luminance = 4.0f;  // GLPT_DENOISE_SIGMA_LUMINANCE
  // GLPT_DENOISE_KERNEL: the a-trous kernel. 0 (default): the 3x3 at step 1, then four of its
  // taps an iteration, a cross (steps 2, 8) and a diagonal cross (steps 4, 16) in turn; 1: 3x3;
  // 2: 5x5 (the paper's). The four taps measured as close to the reference as the 3x3 at half
  // its taps, the 3x3 as close as the 5x5 at a third (docs/denoiser.md).
  uint32_t kernel = 0;
  // Against stale light (not in the 2017 paper): the history is clamped to a fast average
  // (GLPT_DENOISE_FAST_ALPHA) plus or minus GLPT_DENOISE_CLAMP standard deviations; 0: off.
  float fast_clamp = 3.0f;
  float fast_alpha = 0.7f;
  // Once a still image has accumulated this many samples per pixel the accumulated average is
  // shown and the denoiser no longer runs (GLPT_DENOISE_UNTIL); before, the two are mixed.
  // 32: with stratified samples (trace/rng.h) the average of 32 has a lower error than the
  // mixed image at 64 before them (docs/denoiser.md).
  uint32_t until_samples = 32;
  // GLPT_DENOISE_VERTEX_MOTION: a deformed surface (a refit BLAS) reprojects each pixel through
  // its triangle's previous vertices, not through its draw's transform alone; 0: off (A/B).
  bool vertex_motion = true;
  // GLPT_DENOISE_MEAN_VARIANCE: the a-trous filter's luminance edge-stopping takes the variance
  // of the temporally integrated colour (the moments' variance over the history's length, or
  // a / (2 - a) of it once the history averages exponentially), not of one sample as in the
  // 2017 paper (0): the filter blurs less where the history is long (docs/denoiser.md).
  bool mean_variance = true;
  // GLPT_TAA: temporal anti-aliasing after the composite (the SVGF paper's last stage): frames
  // the denoiser runs on are jittered and, at edges of geometry, texture and shadow, blended
  // with their reprojected history, weight GLPT_TAA_ALPHA for a new frame (0.3 where Karis 2014
  // takes 0.1: with 0.1 or 0.2 a switched-on light took 6 frames to settle), the history clipped
  // to GLPT_TAA_GAMMA standard deviations of the 3x3 neighbourhood (Salvi 2016;
  // docs/denoiser.md, "Anti-aliasing").
  bool taa = true;
  float taa_alpha = 0.3f;
  float taa_gamma = 1.0f;
};

struct RenderSettings {
  RenderMode mode = RenderMode::kPathTraced;
  // Samples per pixel per frame; GLPT_SPP.
  uint32_t samples_per_pixel = 1;
  // Bounces after the primary hit; GLPT_BOUNCES (0 = direct light only).
  uint32_t bounces = 1;
  // Shadow rays; GLPT_SHADOWS=0 lights every surface as if nothing were in the way.
  bool shadows = true;
  // GL's ambient light occluded by ray-traced ambient occlusion; GLPT_AO=0 leaves it unoccluded.
  bool ambient_occlusion = true;
  // Fixed ambient-occlusion radius in eye-space units; GLPT_AO_RADIUS. 0 (default): each
  // occluder occludes within its own size.
  float ao_radius = 0.0f;
  // Radius of positional GL lights (sphere lights) in eye-space units; GLPT_LIGHT_RADIUS.
  // Negative (default): the radius at which the light subtends GLPT_LIGHT_SIZE_DEG from the eye.
  // 0: point lights.
  float light_radius = -1.0f;
  UnlitPolicy unlit = UnlitPolicy::kKeep;
  // A lit scene without any enabled GL light gets a white directional light; GLPT_DEFAULT_LIGHT=1.
  bool default_light = false;
  Environment environment = Environment::kBlack;
  LightChoice light_choice = LightChoice::kContribution;
  // GLPT_REFERENCE=N: every frame is rendered with N samples per pixel (jittered over the pixel),
  // from scratch: the ground truth for accuracy measurements. 0: off.
  uint32_t reference_samples = 0;
  // GLPT_BLUE_NOISE=1: neighbouring pixels' sample points spread apart by a blue-noise mask
  // (shaders/trace/rng.h); by default each pixel's points are scrambled on their own.
  // Opt-in: measured in docs/light-transport.md, "Sample numbers", with what keeps it so.
  bool blue_noise = false;
  // A deforming object's BLAS refit to its new positions (BlasCache); GLPT_BLAS_REFIT=0 builds
  // each new shape anew (for measurements).
  bool blas_refit = true;
  // Average with previous frames while the frame is unchanged; GLPT_ACCUMULATE=0 disables.
  bool accumulate = true;
  // Stop adding samples once a pixel has this many; GLPT_MAX_SPP.
  uint32_t max_accumulated = 4096;
  // Angular radius of directional GL lights (soft shadows); GLPT_LIGHT_SIZE_DEG. Also sets the
  // default size of positional lights (light_radius).
  float light_angular_radius_deg = 1.0f;
  // Fraction of the window's width and height the trace pass traces per frame; GLPT_SCALE,
  // 0.25..1. Below 1 the pass traces one pixel per cell of a coarser grid (which pixel of its
  // cell moves from frame to frame) and fills the others from traced neighbours on the same
  // surface (joint bilateral upsampling guided by the full-resolution G-buffer), tracing a pixel
  // itself where no neighbour matches. The G-buffer, and so edges and textures, stay at full
  // resolution. Ignored by GLPT_REFERENCE.
  float trace_scale = 1.0f;
  // GLPT_CLASSIFY_LOG=FILE: every classified draw of every frame appended to FILE as a JSON
  // line (scene/classify_log.hpp), in either mode. Empty: off.
  std::string classify_log;
  // GLPT_CLASSIFY_DEBUG=1: each draw class tinted in the image (docs/classification.md).
  bool classify_debug = false;
  DenoiseSettings denoise;
  // GLPT_VALIDATION=1 enables VK_LAYER_KHRONOS_validation if present.
  bool validation = false;
  // Every submission timed on the device with timestamp queries (FrameStats' pass times).
  // from_environment() turns it on only when something reports the times (GLPT_STATS,
  // GLPT_STATS_FILE, GLPT_DUMP_SCENE) or GLPT_DEVICE_TIMING=1 asks: on lavapipe a pair of
  // timestamps makes every submission wait for llvmpipe's threads, which tripled what a
  // glReadPixels costs (bench/gl_readback.c). Off, the times are the host's, from submission to
  // the wait that saw it complete.
  bool device_timing = true;

  // Reads the variables above; bad values -> defaults + one stderr warning.
  static RenderSettings from_environment();

  // GLPT_SHADOWS=0 GLPT_BOUNCES=0 GLPT_AO=0: GL's own lighting equation, per pixel.
  bool gl_parity() const { return !shadows && !ambient_occlusion && bounces == 0; }
};

// from_environment() with the lookup injectable (tests): `lookup(name)` returns the variable's
// value or nullptr. Bad values keep their defaults and are described in *warning (empty if all
// were fine).
RenderSettings parse_render_settings(const std::function<const char*(const char*)>& lookup,
                                     std::string* warning);

}  // namespace glpt::rt
