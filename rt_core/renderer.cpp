#include "rt_core/renderer.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <exception>

#include "rt_core/passes/path_tracer.hpp"
#include "rt_core/scene/scene_builder.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {
namespace {

bool is_front(uint32_t buffer) {
  return buffer == GL_FRONT || buffer == GL_FRONT_LEFT || buffer == GL_FRONT_RIGHT ||
         buffer == GL_LEFT || buffer == GL_RIGHT;
}

// Runs `body`, turning any exception into false + message (nothing may escape this API).
template <typename Body>
bool guarded(const char* what, std::string* error, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    if (error != nullptr) *error = std::string("glpt: ") + what + ": " + e.what();
  } catch (...) {
    if (error != nullptr) *error = std::string("glpt: ") + what + ": unknown error";
  }
  return false;
}

}  // namespace

class Renderer::Impl {
 public:
  Impl(RenderSettings settings, std::shared_ptr<VulkanDevice> device,
       std::unique_ptr<PathTracer> tracer)
      : settings_(settings), device_(std::move(device)), tracer_(std::move(tracer)) {}

  RenderMode mode() const { return settings_.mode; }
  const std::string& device_name() const { return device_->name(); }

  bool execute(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
               FrameStats& stats, std::string* error) {
    stats = FrameStats();
    if (drawable != drawable_) {
      drawable_ = drawable;
      const size_t bytes = size_t{drawable.width} * drawable.height * 4;
      front_.assign(bytes, 0);
      back_.assign(bytes, 0);
    }
    if (drawable.width == 0 || drawable.height == 0) return true;
    // Interim: the whole record is path traced into the draw buffer of its last command.
    build_trace_scene(record, drawable.width, drawable.height, scene_);
    uint32_t draw_buffer = drawable.double_buffered ? GL_BACK : GL_FRONT;
    for (const rec::Command& command : record.commands) {
      std::visit(
          [&](const auto& c) {
            if constexpr (requires { c.state; })
              draw_buffer = record.states[c.state].raster->ops.draw_buffer;
          },
          command);
    }
    std::vector<uint8_t>& target =
        is_front(draw_buffer) || !drawable.double_buffered ? front_ : back_;
    if (!tracer_->render(scene_.scene, target, stats, error)) return false;
    return true;
  }

  bool read_color(uint32_t buffer, int32_t x, int32_t y, uint32_t width, uint32_t height,
                  std::vector<uint8_t>& rgba) const {
    const std::vector<uint8_t>& source =
        is_front(buffer) || !drawable_.double_buffered ? front_ : back_;
    rgba.assign(size_t{width} * height * 4, 0);
    if (source.empty()) return false;
    for (uint32_t j = 0; j < height; ++j) {
      for (uint32_t i = 0; i < width; ++i) {
        const int64_t sx = int64_t{x} + i, sy = int64_t{y} + j;
        if (sx < 0 || sy < 0 || sx >= drawable_.width || sy >= drawable_.height) continue;
        std::memcpy(&rgba[(size_t{j} * width + i) * 4],
                    &source[static_cast<size_t>((sy * drawable_.width + sx) * 4)], 4);
      }
    }
    return true;
  }

  void swap_buffers() {
    if (drawable_.double_buffered) front_ = back_;
  }

 private:
  RenderSettings settings_;
  std::shared_ptr<VulkanDevice> device_;
  std::unique_ptr<PathTracer> tracer_;
  rec::DrawableConfig drawable_{0, 0};
  std::vector<uint8_t> front_, back_;
  SceneBuild scene_;
};

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

std::unique_ptr<Renderer> Renderer::create(const RenderSettings& settings, std::string* error,
                                           std::string* notice) {
  std::unique_ptr<Renderer> renderer;
  guarded("cannot create the Vulkan renderer", error, [&] {
    DeviceOptions options;
    options.validation = settings.validation;
    if (const char* filter = std::getenv("GLPT_VK_DEVICE")) options.name_filter = filter;
    std::shared_ptr<VulkanDevice> device = VulkanDevice::create(options);
    if (!device->has_ray_query()) {
      if (error != nullptr)
        *error = "glpt: " + device->name() + " has no ray queries (" + device->ray_query_missing() +
                 "). " + vulkan_install_hint();
      return false;
    }
    auto tracer = PathTracer::create(device, settings, error);
    if (!tracer) return false;
    renderer.reset(new Renderer(std::make_unique<Impl>(settings, device, std::move(tracer))));
    return true;
  });
  (void)notice;
  return renderer;
}

RenderMode Renderer::mode() const { return impl_->mode(); }
const std::string& Renderer::device_name() const { return impl_->device_name(); }

bool Renderer::execute(const rec::FrameRecord& record, const rec::DrawableConfig& drawable,
                       FrameStats& stats, std::string* error) {
  return guarded("render failed", error,
                 [&] { return impl_->execute(record, drawable, stats, error); });
}

bool Renderer::read_color(uint32_t buffer, int32_t x, int32_t y, uint32_t width, uint32_t height,
                          std::vector<uint8_t>& rgba, std::string* error) {
  return guarded("read failed", error,
                 [&] { return impl_->read_color(buffer, x, y, width, height, rgba); });
}

bool Renderer::read_depth(int32_t, int32_t, uint32_t, uint32_t, std::vector<float>& depth,
                          std::string*) {
  depth.clear();
  return false;
}

bool Renderer::read_stencil(int32_t, int32_t, uint32_t, uint32_t, std::vector<uint8_t>& stencil,
                            std::string*) {
  stencil.clear();
  return false;
}

bool Renderer::swap_buffers(std::string*) {
  impl_->swap_buffers();
  return true;
}

}  // namespace glpt::rt
