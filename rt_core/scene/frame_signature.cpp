#include "rt_core/scene/frame_signature.hpp"

#include <cstring>

namespace glpt::rt {
namespace {

class WordWriter {
 public:
  explicit WordWriter(std::vector<uint32_t>& words) : words_(words) {}
  void add(uint32_t value) { words_.push_back(value); }
  void add(int32_t value) { words_.push_back(static_cast<uint32_t>(value)); }
  void add(uint64_t value) {
    words_.push_back(static_cast<uint32_t>(value));
    words_.push_back(static_cast<uint32_t>(value >> 32));
  }
  void add(float value) {
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    words_.push_back(bits);
  }
  template <glm::length_t N>
  void add(const glm::vec<N, float>& v) {
    for (glm::length_t i = 0; i < N; ++i) add(v[i]);
  }
  void add(const glm::mat4& m) {
    for (int column = 0; column < 4; ++column) add(m[column]);
  }

 private:
  std::vector<uint32_t>& words_;
};

}  // namespace

FrameSignature::FrameSignature(const TraceScene& frame) : valid_(true) {
  words_.reserve(64 + frame.lights.size() * 24 + frame.instances.size() * 18);
  WordWriter out(words_);
  out.add(frame.width);
  out.add(frame.height);
  out.add(frame.viewport.x);
  out.add(frame.viewport.y);
  out.add(frame.viewport.width);
  out.add(frame.viewport.height);
  out.add(frame.projection);
  out.add(frame.clear_color);
  out.add(frame.global_ambient);
  out.add(static_cast<uint32_t>(frame.lights.size()));
  for (const Light& light : frame.lights) {
    out.add(light.position);
    out.add(light.ambient);
    out.add(light.diffuse);
    out.add(light.specular);
    out.add(light.spot_direction);
    out.add(light.spot_exponent);
    out.add(light.spot_cutoff);
    out.add(light.constant_attenuation);
    out.add(light.linear_attenuation);
    out.add(light.quadratic_attenuation);
  }
  out.add(static_cast<uint32_t>(frame.instances.size()));
  for (const Instance& instance : frame.instances) {
    out.add(instance.geometry ? instance.geometry->content_hash : uint64_t{0});
    out.add(static_cast<uint32_t>(instance.geometry ? instance.geometry->triangle_count() : 0));
    out.add(instance.modelview);
  }
}

}  // namespace glpt::rt
