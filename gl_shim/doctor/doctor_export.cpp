// glpt_doctor_survey: how `glpt doctor` asks the libGL.so.1 that `glpt run` would preload what
// it makes of this machine's Vulkan devices. The command line dlopens the library and calls
// this, so a library that cannot load (a missing Vulkan loader, say) and a device the renderer
// would reject both show exactly as they would for a program.
#include "gl_shim/doctor/doctor_export.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "common/device_survey.hpp"
#include "gl_shim/c_abi_guard.hpp"
#include "rt_core/vk/vk_device.hpp"

size_t glpt_doctor_survey(char* buffer, size_t size) {
  return glpt::guard_c_abi(
      size_t{0}, [] {},
      [&] {
        const std::string text = glpt::encode_device_survey(
            glpt::rt::survey_devices(glpt::rt::DeviceOptions::from_environment(false)));
        if (buffer != nullptr && size > 0) {
          const size_t n = std::min(text.size(), size - 1);
          std::memcpy(buffer, text.data(), n);
          buffer[n] = '\0';
        }
        return text.size();
      });
}
