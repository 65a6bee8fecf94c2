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

struct RenderSettings {
  RenderMode mode = RenderMode::kPathTraced;
  // Samples per pixel per frame; GLPT_SPP.
  uint32_t samples_per_pixel = 1;
  // Diffuse bounces after the primary hit; GLPT_BOUNCES (0 = direct light only).
  uint32_t bounces = 1;
  // Average with previous frames while the frame is unchanged; GLPT_ACCUMULATE=0 disables.
  bool accumulate = true;
  // Stop adding samples once a pixel has this many; GLPT_MAX_SPP.
  uint32_t max_accumulated = 4096;
  // Angular radius of every light as seen from a surface (soft shadows); GLPT_LIGHT_SIZE_DEG.
  float light_angular_radius_deg = 1.0f;
  // GLPT_VALIDATION=1 enables VK_LAYER_KHRONOS_validation if present.
  bool validation = false;

  // Reads the variables above; bad values -> defaults + one stderr warning.
  static RenderSettings from_environment();
};

// from_environment() with the lookup injectable (tests): `lookup(name)` returns the variable's
// value or nullptr. Bad values keep their defaults and are described in *warning (empty if all
// were fine).
RenderSettings parse_render_settings(const std::function<const char*(const char*)>& lookup,
                                     std::string* warning);

}  // namespace glpt::rt
