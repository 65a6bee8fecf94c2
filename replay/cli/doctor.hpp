// `glpt doctor`: what this machine has of what glpt needs, each as ok or what to do. The checks
// are split from the probing: diagnose() turns what was found (DoctorFacts) into findings and an
// exit status, so every verdict is testable without changing the machine; probe_machine() finds
// the facts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/device_survey.hpp"

namespace glpt::cli {

struct DoctorFacts {
  // glpt's libGL.so.1 (the one `glpt run` would preload): where, and why it cannot be loaded.
  std::string library;                 // empty: not found
  std::string library_error;           // dlerror() text; empty: it loads
  std::string vulkan_loader_error;     // dlopen("libvulkan.so.1") failed with this; empty: found
  std::optional<DeviceSurvey> survey;  // from the library; nullopt when it could not be asked
  std::string survey_error;            // why there is no survey
  bool ray_queries_hidden = false;     // GLPT_VK_NO_RAY_QUERY is set
  std::string device_filter;           // GLPT_VK_DEVICE
  std::string display;                 // $DISPLAY; empty: unset
  std::string x_error;                 // empty: connected
  bool mit_shm = false;
  std::string osmesa_error;  // dlopen("libOSMesa.so.8") failed with this; empty: found
  std::string apitrace;      // its path; empty: not in PATH
  std::string output_dir;    // $GLPT_OUTPUT; empty: unset
  std::string output_error;  // why frames could not be written there; empty: they can
};

enum class Verdict { kOk, kWarn, kFail };

struct Finding {
  Verdict verdict = Verdict::kOk;
  std::string what;    // "ray queries"
  std::string detail;  // what was found
  std::string todo;    // what to do about it; empty when ok
};

struct Diagnosis {
  std::vector<Finding> findings;
  bool path_tracing = false;  // glpt run would path-trace
  bool raster = false;        // glpt run would at least rasterize
  std::string summary;        // the last line
  int exit_status() const { return path_tracing ? 0 : 1; }
};

Diagnosis diagnose(const DoctorFacts& facts);
DoctorFacts probe_machine(const std::string& library);
std::string format_diagnosis(const Diagnosis& diagnosis);

}  // namespace glpt::cli
