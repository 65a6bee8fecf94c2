// What glpt's libGL.so.1 finds about the machine's Vulkan devices, for `glpt doctor`: the shim
// fills it (rt_core's survey_devices, the same judgement a renderer makes) and hands it across
// its C ABI as text (glpt_doctor_survey in gl_shim/doctor_export.cpp); the command line decodes
// it. Plain C++, so the command line needs neither Vulkan nor the shim to build.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glpt {

// The hint every "path tracing is not possible here" message ends with (the shim's notice when
// it falls back to raster mode, `glpt run` when glpt's library cannot load).
constexpr const char* kDoctorHint =
    "run `glpt doctor` to see what this machine lacks and how to install it";

struct DeviceSurvey {
  struct Device {
    std::string name;
    std::string type;                  // "cpu", "discrete GPU", ...
    std::string driver;                // driver name and info; empty where the device is not usable
    std::string api_version;           // "1.3.305"
    std::vector<std::string> missing;  // what raster mode needs and the device lacks
    std::vector<std::string> missing_ray_query;  // what path tracing needs and the device lacks
    bool geometry_shader = false;
    bool storage_image_read = false, storage_image_write = false;  // without format
    bool chosen = false;  // the device a renderer with the same settings would use
    bool operator==(const Device&) const = default;
  };
  std::string instance_error;     // non-empty: no Vulkan instance could be created
  std::string loader_version;     // the loader's instance version, "1.3.239"
  bool validation_layer = false;  // VK_LAYER_KHRONOS_validation is installed
  std::vector<Device> devices;
  std::string choice_error;  // non-empty: no device is usable (the renderer's message)
  bool operator==(const DeviceSurvey&) const = default;

  // The chosen device, or null.
  const Device* chosen() const;
};

// One record per line, fields separated by tabs (tabs and newlines in values become spaces),
// lists by "; ". decode_device_survey returns nullopt for text that is not such an encoding.
std::string encode_device_survey(const DeviceSurvey& survey);
std::optional<DeviceSurvey> decode_device_survey(std::string_view text);

}  // namespace glpt
