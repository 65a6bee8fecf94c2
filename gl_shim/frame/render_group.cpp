#include "gl_shim/frame/render_group.hpp"

namespace glpt {

std::shared_ptr<rt::Renderer> RenderGroup::renderer(std::string* error, std::string* notice) {
  std::lock_guard lock(mutex_);
  if (!renderer_)
    renderer_ = rt::Renderer::create(rt::RenderSettings::from_environment(), error, notice);
  return renderer_;
}

}  // namespace glpt
