// The pixel scenes rendered by glpt's front end in raster mode, linked statically (the entry
// points libGL.so.1 exports), drawing to a headless target. The scenes use the default draw
// and read buffers (glpt's back buffer, OSMesa's single buffer).
#include <cstdlib>
#include <memory>

#include "gl_shim/context.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "scene_runner.hpp"

namespace {

class GlptBackend final : public glpt::pixel_ops::Backend {
 public:
  ~GlptBackend() override { end_scene(); }
  bool begin_scene(int width, int height, std::string*) override {
    context_ = std::make_unique<glpt::Context>(nullptr);
    target_ = std::make_unique<glpt::HeadlessTarget>(uint32_t(width), uint32_t(height));
    glpt::make_current_headless(*context_, *target_);
    return true;
  }
  void end_scene() override {
    if (context_ == nullptr) return;
    glpt::set_current_context(nullptr);
    context_.reset();
    target_.reset();
  }

 private:
  std::unique_ptr<glpt::Context> context_;
  std::unique_ptr<glpt::HeadlessTarget> target_;
};

}  // namespace

int main(int argc, char** argv) {
  setenv("GLPT_MODE", "raster", 1);  // before the first GL call creates a renderer
  GlptBackend backend;
  return glpt::pixel_ops::run_main(argc, argv, backend);
}
