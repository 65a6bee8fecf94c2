// `glpt doctor`: each verdict from the facts that lead to it (diagnose, without touching the
// machine), the survey's text encoding, and the real command on this machine's lavapipe.
#include "doctor.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "common/device_survey.hpp"
#include "shell.hpp"

namespace glpt::cli {
namespace {

DeviceSurvey::Device lavapipe(bool ray_query = true) {
  DeviceSurvey::Device d;
  d.name = "llvmpipe (LLVM 15.0.6, 256 bits)";
  d.type = "cpu";
  d.driver = "llvmpipe Mesa 25.0.7";
  d.api_version = "1.4.305";
  if (!ray_query) d.missing_ray_query = {"VK_KHR_acceleration_structure", "VK_KHR_ray_query"};
  d.geometry_shader = d.storage_image_read = d.storage_image_write = true;
  d.chosen = true;
  return d;
}

// A machine where everything glpt wants is present.
DoctorFacts healthy() {
  DoctorFacts f;
  f.library = "/usr/lib/glpt/libGL.so.1";
  DeviceSurvey survey;
  survey.loader_version = "1.3.239";
  survey.validation_layer = true;
  survey.devices = {lavapipe()};
  f.survey = survey;
  f.display = ":0";
  f.mit_shm = true;
  f.apitrace = "/usr/bin/apitrace";
  return f;
}

const Finding* find(const Diagnosis& d, const std::string& what) {
  for (const Finding& f : d.findings)
    if (f.what == what) return &f;
  return nullptr;
}

size_t count(const Diagnosis& d, Verdict v) {
  size_t n = 0;
  for (const Finding& f : d.findings) n += f.verdict == v;
  return n;
}

TEST(Doctor, AHealthyMachinePathTraces) {
  const Diagnosis d = diagnose(healthy());
  EXPECT_EQ(d.exit_status(), 0);
  EXPECT_TRUE(d.path_tracing);
  EXPECT_EQ(count(d, Verdict::kFail) + count(d, Verdict::kWarn), 0u) << format_diagnosis(d);
  for (const char* what :
       {"glpt's libGL.so.1", "Vulkan loader", "Vulkan device", "ray queries", "geometry shaders",
        "storage images", "X server", "OSMesa", "apitrace", "validation layer", "GLPT_OUTPUT"})
    EXPECT_NE(find(d, what), nullptr) << what;
  const std::string text = format_diagnosis(d);
  EXPECT_NE(
      text.find("llvmpipe (LLVM 15.0.6, 256 bits) (cpu, llvmpipe Mesa 25.0.7, Vulkan 1.4.305)"),
      std::string::npos)
      << text;
  EXPECT_NE(text.find("path tracing will work"), std::string::npos) << text;
}

TEST(Doctor, LavapipeWithoutRayQueriesSaysWhichPackage) {
  DoctorFacts f = healthy();
  f.survey->devices = {lavapipe(false)};
  const Diagnosis d = diagnose(f);
  EXPECT_EQ(d.exit_status(), 1);
  EXPECT_TRUE(d.raster);
  const Finding* rq = find(d, "ray queries");
  ASSERT_NE(rq, nullptr);
  EXPECT_EQ(rq->verdict, Verdict::kFail);
  EXPECT_NE(rq->detail.find("VK_KHR_ray_query"), std::string::npos) << rq->detail;
  EXPECT_NE(rq->todo.find("bookworm-backports mesa-vulkan-drivers"), std::string::npos) << rq->todo;
  EXPECT_NE(format_diagnosis(d).find("raster mode only"), std::string::npos);
}

TEST(Doctor, HiddenRayQueriesAreNamed) {
  DoctorFacts f = healthy();
  f.ray_queries_hidden = true;
  f.survey->devices[0].missing_ray_query = {"ray queries: hidden by GLPT_VK_NO_RAY_QUERY"};
  const Diagnosis d = diagnose(f);
  EXPECT_EQ(d.exit_status(), 1);
  EXPECT_NE(find(d, "ray queries")->todo.find("unset GLPT_VK_NO_RAY_QUERY"), std::string::npos);
}

TEST(Doctor, ADeviceFilterThatSkipsTheRayQueryDeviceIsNamed) {
  DoctorFacts f = healthy();
  DeviceSurvey::Device gpu = lavapipe(false);
  gpu.name = "Old GPU";
  gpu.type = "discrete GPU";
  DeviceSurvey::Device cpu = lavapipe();
  cpu.chosen = false;
  f.survey->devices = {gpu, cpu};
  f.device_filter = "Old";
  const Diagnosis d = diagnose(f);
  EXPECT_EQ(d.exit_status(), 1);
  const std::string todo = find(d, "ray queries")->todo;
  EXPECT_NE(todo.find("GLPT_VK_DEVICE=\"Old\""), std::string::npos) << todo;
  EXPECT_NE(todo.find("llvmpipe"), std::string::npos) << todo;
}

TEST(Doctor, MissingGeometryShadersOrStorageImagesFail) {
  DoctorFacts f = healthy();
  f.survey->devices[0].geometry_shader = false;
  f.survey->devices[0].storage_image_write = false;
  f.survey->devices[0].missing_ray_query = {"geometryShader",
                                            "shaderStorageImageWriteWithoutFormat"};
  const Diagnosis d = diagnose(f);
  EXPECT_EQ(d.exit_status(), 1);
  EXPECT_EQ(find(d, "geometry shaders")->verdict, Verdict::kFail);
  EXPECT_EQ(find(d, "storage images")->verdict, Verdict::kFail);
}

TEST(Doctor, AMissingVulkanLoaderSaysWhatToInstall) {
  DoctorFacts f = healthy();
  f.vulkan_loader_error =
      "libvulkan.so.1: cannot open shared object file: No such file or directory";
  f.library_error = f.vulkan_loader_error;
  f.survey.reset();
  const Diagnosis d = diagnose(f);
  EXPECT_EQ(d.exit_status(), 1);
  EXPECT_FALSE(d.raster);
  EXPECT_NE(find(d, "Vulkan loader")->todo.find("apt-get install libvulkan1"), std::string::npos);
  EXPECT_NE(find(d, "glpt's libGL.so.1")->todo.find("libvulkan1"), std::string::npos);
  EXPECT_NE(format_diagnosis(d).find("glpt cannot draw on this machine"), std::string::npos);
}

TEST(Doctor, NoDriverOrNoUsableDevice) {
  DoctorFacts f = healthy();
  f.survey->devices.clear();
  f.survey->instance_error = "cannot create a Vulkan instance (VK_ERROR_INCOMPATIBLE_DRIVER)";
  Diagnosis d = diagnose(f);
  EXPECT_EQ(d.exit_status(), 1);
  EXPECT_NE(find(d, "Vulkan driver")->todo.find("mesa-vulkan-drivers"), std::string::npos);

  f = healthy();
  f.survey->devices[0].missing = {"VK_EXT_custom_border_color"};
  f.survey->devices[0].chosen = false;
  f.survey->choice_error = "glpt: no usable Vulkan device (...)";
  d = diagnose(f);
  EXPECT_FALSE(d.raster);
  EXPECT_EQ(find(d, "Vulkan device")->verdict, Verdict::kFail);
  EXPECT_EQ(find(d, "device choice")->verdict, Verdict::kFail);
}

TEST(Doctor, OptionalPartsWarnButDoNotDecide) {
  DoctorFacts f = healthy();
  f.display.clear();
  f.osmesa_error = "libOSMesa.so.8: cannot open shared object file";
  f.apitrace.clear();
  f.survey->validation_layer = false;
  f.output_dir = "/etc/passwd/frames";
  f.output_error = "cannot be created: /etc/passwd is not a directory";
  const Diagnosis d = diagnose(f);
  EXPECT_EQ(d.exit_status(), 0);
  EXPECT_EQ(count(d, Verdict::kWarn), 5u) << format_diagnosis(d);
  EXPECT_NE(find(d, "OSMesa")->todo.find("libosmesa6"), std::string::npos);
  EXPECT_NE(find(d, "apitrace")->todo.find("apt-get install apitrace"), std::string::npos);
  EXPECT_NE(find(d, "validation layer")->todo.find("vulkan-validationlayers"), std::string::npos);
  EXPECT_NE(find(d, "X server")->todo.find("xvfb-run"), std::string::npos);

  f = healthy();
  f.mit_shm = false;
  EXPECT_EQ(find(diagnose(f), "X server")->verdict, Verdict::kWarn);
}

TEST(DeviceSurveyText, RoundTripsAndRejectsOtherText) {
  DeviceSurvey survey;
  survey.loader_version = "1.3.239";
  survey.validation_layer = true;
  survey.choice_error = "a\tb";
  DeviceSurvey::Device a = lavapipe(false);
  a.missing = {"Vulkan 1.3", "bresenhamLines"};
  DeviceSurvey::Device b = lavapipe();
  b.name = "second\ndevice";
  b.driver.clear();
  b.chosen = false;
  survey.devices = {a, b};
  const std::optional<DeviceSurvey> decoded = decode_device_survey(encode_device_survey(survey));
  ASSERT_TRUE(decoded);
  // Tabs and newlines inside values become spaces; everything else is kept.
  survey.choice_error = "a b";
  survey.devices[1].name = "second device";
  EXPECT_EQ(*decoded, survey);
  EXPECT_EQ(decoded->chosen(), &decoded->devices[0]);
  EXPECT_FALSE(decode_device_survey(""));
  EXPECT_FALSE(decode_device_survey("glpt-device-survey\t2\n"));
  EXPECT_FALSE(decode_device_survey("glpt-device-survey\t1\ndevice\tonly two\n"));
}

// The real command, asking the real libGL.so.1 about this machine (lavapipe with ray queries,
// which every path-traced test needs too).
TEST(Doctor, TheCommandOnThisMachine) {
  const std::string glpt = GLPT_CLI_EXE, lib = GLPT_SHIM_LIB;
  if (lib.empty()) GTEST_SKIP() << "built without libGL.so.1 (GLPT_BUILD_SHIM=OFF)";
  const Result ok =
      shell("env -u GLPT_VK_NO_RAY_QUERY -u GLPT_VK_DEVICE " + glpt + " doctor --lib " + lib);
  EXPECT_EQ(ok.status, 0) << ok.out;
  EXPECT_NE(ok.out.find("ok    ray queries"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find(", the one glpt uses"), std::string::npos) << ok.out;

  const Result hidden = shell("GLPT_VK_NO_RAY_QUERY=1 " + glpt + " doctor --lib " + lib);
  EXPECT_EQ(hidden.status, 1) << hidden.out;
  EXPECT_NE(hidden.out.find("FAIL  ray queries"), std::string::npos) << hidden.out;

  const Result no_device = shell("GLPT_VK_DEVICE=no-such-device " + glpt + " doctor --lib " + lib);
  EXPECT_EQ(no_device.status, 1) << no_device.out;
  EXPECT_NE(no_device.out.find("GLPT_VK_DEVICE=\"no-such-device\""), std::string::npos)
      << no_device.out;

  const Result not_a_library = shell(glpt + " doctor --lib /etc/passwd");
  EXPECT_EQ(not_a_library.status, 1) << not_a_library.out;
  EXPECT_NE(not_a_library.out.find("cannot be loaded"), std::string::npos) << not_a_library.out;

  EXPECT_EQ(shell(glpt + " doctor --frobnicate").status, 2);
  EXPECT_EQ(shell(glpt + " doctor --lib").status, 2);
  EXPECT_EQ(shell(glpt + " doctor --help").status, 0);
}

}  // namespace
}  // namespace glpt::cli
