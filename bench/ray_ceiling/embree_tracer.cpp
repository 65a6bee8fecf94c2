#include "embree_tracer.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>

namespace ray_ceiling {
namespace {

RTCDevice device_of(void* p) { return static_cast<RTCDevice>(p); }
RTCScene scene_of(void* p) { return static_cast<RTCScene>(p); }

void error_callback(void*, RTCError code, const char* message) {
  std::fprintf(stderr, "ray_ceiling: Embree error %d: %s\n", static_cast<int>(code),
               message ? message : "");
  std::abort();
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

EmbreeTracer::EmbreeTracer(unsigned threads) : threads_(std::max(threads, 1u)) {
  const std::string config = "threads=" + std::to_string(threads_);
  RTCDevice device = rtcNewDevice(config.c_str());
  if (!device) throw std::runtime_error("rtcNewDevice failed");
  rtcSetDeviceErrorFunction(device, error_callback, nullptr);
  device_ = device;
}

EmbreeTracer::~EmbreeTracer() {
  if (scene_) rtcReleaseScene(scene_of(scene_));
  if (device_) rtcReleaseDevice(device_of(device_));
}

bool EmbreeTracer::masks_supported() const {
  return rtcGetDeviceProperty(device_of(device_), RTC_DEVICE_PROPERTY_RAY_MASK_SUPPORTED) != 0;
}

std::string EmbreeTracer::description() const {
  return "Embree " + std::to_string(RTC_VERSION_MAJOR) + "." + std::to_string(RTC_VERSION_MINOR) +
         "." + std::to_string(RTC_VERSION_PATCH) + ", " + std::to_string(threads_) +
         " threads, build quality medium, ray masks " + (masks_supported() ? "on" : "OFF");
}

double EmbreeTracer::build(const AccelInput& input) {
  if (scene_) rtcReleaseScene(scene_of(scene_));
  RTCScene scene = rtcNewScene(device_of(device_));
  for (const AccelInput::Instance& instance : input.instances) {
    const std::vector<float>& p = input.shapes[instance.shape];
    const size_t triangles = p.size() / 9;
    RTCGeometry geometry = rtcNewGeometry(device_of(device_), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), triangles * 3));
    const std::array<float, 12>& m = instance.transform;
    for (size_t v = 0; v < triangles * 3; ++v)
      for (int row = 0; row < 3; ++row)
        vertices[3 * v + row] = m[4 * row] * p[3 * v] + m[4 * row + 1] * p[3 * v + 1] +
                                m[4 * row + 2] * p[3 * v + 2] + m[4 * row + 3];
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles));
    for (uint32_t i = 0; i < triangles * 3; ++i) indices[i] = i;
    rtcSetGeometryMask(geometry, instance.mask);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);  // ids 0, 1, ... in instance order
    rtcReleaseGeometry(geometry);
  }
  const auto t0 = std::chrono::steady_clock::now();
  rtcCommitScene(scene);
  scene_ = scene;
  return ms_since(t0);
}

std::vector<double> EmbreeTracer::trace(const std::vector<Ray>& rays, int repetitions,
                                        std::vector<Hit>& hits) {
  RTCScene scene = scene_of(scene_);
  const size_t n = rays.size();
  hits.assign(n, Hit{-1.0f, -1, -1, 0});
  constexpr size_t kChunk = 256;
  auto worker = [&](std::atomic<size_t>& next) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    for (;;) {
      const size_t begin = next.fetch_add(kChunk);
      if (begin >= n) break;
      const size_t end = std::min(n, begin + kChunk);
      for (size_t i = begin; i < end; ++i) {
        const Ray& r = rays[i];
        RTCRayHit rh;
        rh.ray.org_x = r.org[0];
        rh.ray.org_y = r.org[1];
        rh.ray.org_z = r.org[2];
        rh.ray.dir_x = r.dir[0];
        rh.ray.dir_y = r.dir[1];
        rh.ray.dir_z = r.dir[2];
        rh.ray.tnear = r.tmin;
        rh.ray.tfar = r.tmax;
        rh.ray.time = 0.0f;
        rh.ray.mask = r.mask;
        rh.ray.id = 0;
        rh.ray.flags = 0;
        if (r.flags & kTerminateOnFirstHit) {
          rtcOccluded1(scene, &context, &rh.ray);
          // A hit sets tfar to -inf.
          if (rh.ray.tfar < 0.0f) hits[i] = Hit{r.tmax, 0, 0, 0};
        } else {
          rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
          rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
          rtcIntersect1(scene, &context, &rh);
          if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
            hits[i] = Hit{rh.ray.tfar, static_cast<int32_t>(rh.hit.geomID),
                          static_cast<int32_t>(rh.hit.primID), 0};
        }
      }
    }
  };
  std::vector<double> times;
  for (int r = 0; r < repetitions; ++r) {
    std::atomic<size_t> next{0};
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads_; ++t) pool.emplace_back(worker, std::ref(next));
    worker(next);
    for (std::thread& thread : pool) thread.join();
    times.push_back(ms_since(t0));
  }
  return times;
}

}  // namespace ray_ceiling
