#include "doctor.hpp"

#include <dlfcn.h>
#include <unistd.h>
#include <xcb/shm.h>
#include <xcb/xcb.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "gl_shim/doctor/doctor_export.h"
#include "process.hpp"

namespace glpt::cli {
namespace {

// What to install, in Debian's words. lavapipe has VK_KHR_ray_query from Mesa 24.1 on; Debian 12
// ships 22.3, bookworm-backports 25.0.
constexpr const char* kInstallLavapipe =
    "install lavapipe with ray queries (Mesa >= 24.1, Debian 12: bookworm-backports): "
    "apt-get install -t bookworm-backports mesa-vulkan-drivers";

std::string joined(const std::vector<std::string>& parts) {
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : ", ") + part;
  return text;
}

std::string describe(const DeviceSurvey::Device& d) {
  std::string text = d.name + " (" + d.type;
  if (!d.driver.empty()) text += ", " + d.driver;
  text += ", Vulkan " + d.api_version + ")";
  return text;
}

bool is_lavapipe(const DeviceSurvey::Device& d) {
  return d.name.find("llvmpipe") != std::string::npos;
}

void device_findings(const DoctorFacts& facts, const DeviceSurvey& survey, Diagnosis* out) {
  auto add = [&](Verdict v, std::string what, std::string detail, std::string todo = {}) {
    out->findings.push_back({v, std::move(what), std::move(detail), std::move(todo)});
  };
  if (!survey.instance_error.empty()) {
    add(Verdict::kFail, "Vulkan driver", survey.instance_error, kInstallLavapipe);
    return;
  }
  if (survey.devices.empty()) {
    add(Verdict::kFail, "Vulkan device", "none found", kInstallLavapipe);
    return;
  }
  const DeviceSurvey::Device* chosen = survey.chosen();
  for (const DeviceSurvey::Device& d : survey.devices) {
    if (d.missing.empty()) {
      add(Verdict::kOk, "Vulkan device", describe(d) + (d.chosen ? ", the one glpt uses" : ""));
    } else {
      // A device glpt cannot use at all only matters when no other one can be used.
      add(chosen != nullptr ? Verdict::kWarn : Verdict::kFail, "Vulkan device",
          describe(d) + " lacks " + joined(d.missing), chosen != nullptr ? "" : kInstallLavapipe);
    }
  }
  if (chosen == nullptr) {
    std::string todo = kInstallLavapipe;
    if (!facts.device_filter.empty())
      todo = "GLPT_VK_DEVICE=\"" + facts.device_filter +
             "\" selects no usable device: unset it or name one of those above";
    add(Verdict::kFail, "device choice", survey.choice_error, todo);
    return;
  }

  if (chosen->missing_ray_query.empty()) {
    add(Verdict::kOk, "ray queries",
        chosen->name + " has VK_KHR_ray_query and VK_KHR_acceleration_structure");
  } else {
    std::string todo;
    const auto other = std::find_if(survey.devices.begin(), survey.devices.end(), [](auto& d) {
      return d.missing.empty() && d.missing_ray_query.empty();
    });
    if (facts.ray_queries_hidden) {
      todo = "unset GLPT_VK_NO_RAY_QUERY (it hides ray queries on purpose)";
    } else if (other != survey.devices.end()) {
      todo = "GLPT_VK_DEVICE=\"" + facts.device_filter + "\" chose " + chosen->name + "; " +
             other->name + " has ray queries: set GLPT_VK_DEVICE to part of its name";
    } else if (is_lavapipe(*chosen)) {
      todo = kInstallLavapipe;
    } else {
      todo = "update the driver of " + chosen->name + ", or " + kInstallLavapipe +
             " and set GLPT_VK_DEVICE=llvmpipe";
    }
    add(Verdict::kFail, "ray queries",
        chosen->name + " lacks " + joined(chosen->missing_ray_query) +
            ": glpt draws in raster mode",
        todo);
  }
  add(chosen->geometry_shader ? Verdict::kOk : Verdict::kFail, "geometry shaders",
      chosen->geometry_shader
          ? "yes (path-traced mode's G-buffer, GL's unfilled polygons)"
          : "no: path-traced mode's G-buffer pass needs them (raster mode draws without)",
      chosen->geometry_shader ? "" : kInstallLavapipe);
  const bool storage = chosen->storage_image_read && chosen->storage_image_write;
  add(storage ? Verdict::kOk : Verdict::kFail, "storage images",
      storage ? "read and written without a format (the trace pass)"
              : "no shaderStorageImageRead/WriteWithoutFormat: the trace pass needs them",
      storage ? "" : kInstallLavapipe);
}

}  // namespace

Diagnosis diagnose(const DoctorFacts& facts) {
  Diagnosis out;
  auto add = [&](Verdict v, std::string what, std::string detail, std::string todo = {}) {
    out.findings.push_back({v, std::move(what), std::move(detail), std::move(todo)});
  };

  bool library_loads = false;
  if (facts.library.empty()) {
    add(Verdict::kFail, "glpt's libGL.so.1", "not found next to glpt",
        "reinstall glpt, or give the library with --lib PATH");
  } else if (!facts.library_error.empty()) {
    const bool vulkan = facts.library_error.find("libvulkan") != std::string::npos;
    add(Verdict::kFail, "glpt's libGL.so.1",
        facts.library + " cannot be loaded: " + facts.library_error,
        vulkan ? "install the Vulkan loader: apt-get install libvulkan1"
               : "reinstall glpt (the library or one it needs is missing or broken)");
  } else {
    library_loads = true;
    add(Verdict::kOk, "glpt's libGL.so.1", facts.library);
  }

  if (!facts.vulkan_loader_error.empty()) {
    add(Verdict::kFail, "Vulkan loader",
        "libvulkan.so.1 not found (" + facts.vulkan_loader_error + ")",
        "apt-get install libvulkan1");
  } else {
    std::string detail = "libvulkan.so.1";
    if (facts.survey && !facts.survey->loader_version.empty())
      detail += ", instance version " + facts.survey->loader_version;
    add(Verdict::kOk, "Vulkan loader", detail);
  }

  const DeviceSurvey::Device* chosen = nullptr;
  if (facts.survey) {
    device_findings(facts, *facts.survey, &out);
    chosen = facts.survey->chosen();
  } else if (library_loads) {
    add(Verdict::kFail, "Vulkan devices",
        "glpt's libGL.so.1 could not be asked: " + facts.survey_error,
        "reinstall glpt: the library does not match this glpt");
  }

  if (facts.display.empty()) {
    add(Verdict::kWarn, "X server", "DISPLAY is not set: programs cannot open a window",
        "run programs on an X server, or on a private one: xvfb-run -a glpt run -- PROGRAM "
        "(glpt replay needs none)");
  } else if (!facts.x_error.empty()) {
    add(Verdict::kWarn, "X server", "DISPLAY=" + facts.display + ": " + facts.x_error,
        "start the X server, or use a private one: xvfb-run -a glpt run -- PROGRAM");
  } else if (!facts.mit_shm) {
    add(Verdict::kWarn, "X server",
        "DISPLAY=" + facts.display + " has no MIT-SHM: frames reach the window through the socket",
        "run the program on the same machine as the X server, with MIT-SHM enabled");
  } else {
    add(Verdict::kOk, "X server", "DISPLAY=" + facts.display + ", with MIT-SHM");
  }

  if (facts.osmesa_error.empty()) {
    add(Verdict::kOk, "OSMesa", "libOSMesa.so.8 (glpt replay --backend mesa, the reference)");
  } else {
    add(Verdict::kWarn, "OSMesa", "libOSMesa.so.8 not found: glpt replay --backend mesa cannot run",
        "apt-get install -t bookworm-backports libosmesa6");
  }
  if (!facts.apitrace.empty()) {
    add(Verdict::kOk, "apitrace", facts.apitrace + " (glpt record)");
  } else {
    add(Verdict::kWarn, "apitrace", "not in PATH: glpt record cannot record",
        "apt-get install apitrace");
  }
  if (facts.survey && facts.survey->validation_layer) {
    add(Verdict::kOk, "validation layer", "VK_LAYER_KHRONOS_validation (GLPT_VALIDATION=1)");
  } else if (facts.survey) {
    add(Verdict::kWarn, "validation layer",
        "VK_LAYER_KHRONOS_validation is not installed: GLPT_VALIDATION=1 checks nothing",
        "apt-get install vulkan-validationlayers (only needed to debug glpt)");
  }
  if (facts.output_dir.empty()) {
    add(Verdict::kOk, "GLPT_OUTPUT", "not set (frames are written as PNG only when it is)");
  } else if (facts.output_error.empty()) {
    add(Verdict::kOk, "GLPT_OUTPUT", facts.output_dir + " is writable");
  } else {
    add(Verdict::kWarn, "GLPT_OUTPUT", facts.output_dir + ": " + facts.output_error,
        "set GLPT_OUTPUT to a directory you can write");
  }

  out.raster = library_loads && chosen != nullptr;
  out.path_tracing = out.raster && chosen->missing_ray_query.empty();
  if (out.path_tracing) {
    out.summary = "path tracing will work: `glpt run -- PROGRAM` path-traces PROGRAM";
  } else if (out.raster) {
    out.summary = "raster mode only: glpt draws, but path tracing needs what is marked FAIL";
  } else {
    out.summary = "glpt cannot draw on this machine: see what is marked FAIL";
  }
  return out;
}

std::string format_diagnosis(const Diagnosis& diagnosis) {
  std::string text;
  for (const Finding& f : diagnosis.findings) {
    const char* verdict = f.verdict == Verdict::kOk     ? "ok  "
                          : f.verdict == Verdict::kWarn ? "warn"
                                                        : "FAIL";
    std::string what = f.what;
    what.resize(std::max<size_t>(what.size(), 18), ' ');
    text += std::string(verdict) + "  " + what + "  " + f.detail + "\n";
    if (!f.todo.empty()) text += std::string(26, ' ') + "-> " + f.todo + "\n";
  }
  text += "\n" + diagnosis.summary + "\n";
  return text;
}

namespace {

std::string dl_error() {
  const char* e = dlerror();
  return e != nullptr ? e : "unknown error";
}

// Loads `library` and asks it for its device survey (gl_shim/doctor/doctor_export.cpp). The
// library stays loaded: the process ends soon, and a Vulkan driver may keep threads.
void ask_library(const std::string& library, DoctorFacts* facts) {
  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    facts->library_error = dl_error();
    return;
  }
  auto survey = reinterpret_cast<glpt_doctor_survey_function>(dlsym(handle, "glpt_doctor_survey"));
  if (survey == nullptr) {
    facts->survey_error = "it has no glpt_doctor_survey (an older glpt, or not glpt's)";
    return;
  }
  std::string text(4096, '\0');
  size_t length = survey(text.data(), text.size());
  if (length >= text.size()) {
    text.assign(length + 1, '\0');
    length = survey(text.data(), text.size());
  }
  if (length == 0 || length >= text.size()) {
    facts->survey_error = "the survey failed";
    return;
  }
  text.resize(length);
  facts->survey = decode_device_survey(text);
  if (!facts->survey) facts->survey_error = "its survey could not be read";
}

void probe_x(DoctorFacts* facts) {
  if (facts->display.empty()) return;
  xcb_connection_t* connection = xcb_connect(facts->display.c_str(), nullptr);
  if (xcb_connection_has_error(connection)) {
    facts->x_error = "cannot connect to the X server";
  } else {
    const xcb_query_extension_reply_t* shm = xcb_get_extension_data(connection, &xcb_shm_id);
    facts->mit_shm = shm != nullptr && shm->present;
  }
  xcb_disconnect(connection);
}

// Whether the shim could write PNGs into `dir` (creating it as it would): nothing is created.
std::string output_problem(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path path = fs::absolute(dir, ec);
  if (ec) return ec.message();
  if (fs::exists(path, ec)) {
    if (!fs::is_directory(path, ec)) return "exists and is not a directory";
    if (access(path.c_str(), W_OK | X_OK) != 0)
      return std::string("not writable: ") + std::strerror(errno);
    return {};
  }
  // It would be created: its nearest existing ancestor must be a writable directory.
  for (fs::path parent = path.parent_path();; parent = parent.parent_path()) {
    if (fs::exists(parent, ec)) {
      if (!fs::is_directory(parent, ec))
        return "cannot be created: " + parent.string() + " is not a directory";
      if (access(parent.c_str(), W_OK | X_OK) != 0)
        return "cannot be created: " + parent.string() + " is not writable";
      return {};
    }
    if (parent == parent.root_path() || parent.empty()) return "cannot be created";
  }
}

std::string env(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

}  // namespace

DoctorFacts probe_machine(const std::string& library) {
  DoctorFacts facts;
  facts.library = library;
  if (void* loader = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL); loader == nullptr)
    facts.vulkan_loader_error = dl_error();
  if (!library.empty()) ask_library(library, &facts);
  const std::string hide = env("GLPT_VK_NO_RAY_QUERY");
  facts.ray_queries_hidden = !hide.empty() && hide != "0";
  facts.device_filter = env("GLPT_VK_DEVICE");
  facts.display = env("DISPLAY");
  probe_x(&facts);
  if (void* osmesa = dlopen("libOSMesa.so.8", RTLD_LAZY | RTLD_LOCAL); osmesa == nullptr)
    facts.osmesa_error = dl_error();
  facts.apitrace = find_program("apitrace");
  facts.output_dir = env("GLPT_OUTPUT");
  if (!facts.output_dir.empty()) facts.output_error = output_problem(facts.output_dir);
  return facts;
}

std::string doctor_help() {
  return "usage: glpt doctor [--lib PATH]\n"
         "\n"
         "Checks what glpt needs on this machine and prints each check as ok, warn or FAIL,\n"
         "with what to do about it: glpt's libGL.so.1 and the Vulkan loader; every Vulkan\n"
         "device (name, type, driver, version) as glpt judges it, the one it would use, and\n"
         "whether that one has ray queries, geometry shaders and storage images (path-traced\n"
         "mode needs all three); the X server and MIT-SHM; OSMesa (glpt replay --backend\n"
         "mesa); apitrace (glpt record); the Vulkan validation layer (GLPT_VALIDATION=1); and\n"
         "whether frames can be written into GLPT_OUTPUT. GLPT_VK_DEVICE and\n"
         "GLPT_VK_NO_RAY_QUERY count as they would for a program.\n"
         "\n"
         "options:\n"
         "  --lib PATH  the libGL.so.1 to check (default: the one glpt run preloads)\n"
         "\n"
         "exit status: 0 when path tracing will work, 1 when it will not (raster mode only,\n"
         "or nothing), 2 for a bad command line.\n";
}

int doctor_main(std::span<const std::string> args) {
  std::string lib;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (is_help_flag(a)) {
      std::cout << doctor_help();
      return 0;
    }
    if (a == "--lib" && i + 1 < args.size() && !args[i + 1].empty()) {
      lib = args[++i];
    } else if (a.rfind("--lib=", 0) == 0 && a.size() > 6) {
      lib = a.substr(6);
    } else {
      std::cerr << "glpt doctor: "
                << (a == "--lib" ? "--lib needs a value" : "unknown argument " + a)
                << " (see glpt doctor --help)\n";
      return kExitUsage;
    }
  }
  if (lib.empty()) lib = find_glpt_library(executable_dir());
  // dlopen searches the library path for a name without a slash: a file is meant.
  if (!lib.empty() && lib.find('/') == std::string::npos) lib = "./" + lib;
  std::error_code ec;
  if (const auto canonical = std::filesystem::weakly_canonical(lib, ec); !ec && !lib.empty())
    lib = canonical.string();
  const Diagnosis diagnosis = diagnose(probe_machine(lib));
  std::cout << format_diagnosis(diagnosis) << std::flush;
  return diagnosis.exit_status();
}

}  // namespace glpt::cli
