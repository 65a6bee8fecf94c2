// glpt_conformance_glpt: the conformance scenes rendered by glpt's GL front end in raster mode,
// linked statically (the same gl* entry points libGL.so.1 exports) and drawing to a headless
// target of the scene's size.
#include <cstdlib>
#include <memory>
#include <string>

#include "gl_shim/context.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "runner.hpp"

namespace {

class GlptBackend final : public glpt::conformance::Backend {
 public:
  ~GlptBackend() override { end_scene(); }
  const char* name() const override { return "glpt"; }

  bool begin_scene(int width, int height, std::string*) override {
    end_scene();
    context_ = std::make_unique<glpt::Context>(nullptr);
    // The buffers OSMesa's context has (mesa_runner.cpp): single-buffered RGBA8, 24-bit depth,
    // 8-bit stencil, 16-bit accumulation.
    glpt::rec::DrawableConfig config;
    config.double_buffered = false;
    config.depth_bits = 24;
    config.stencil_bits = 8;
    config.accum_bits = 16;
    target_ = std::make_unique<glpt::HeadlessTarget>(static_cast<uint32_t>(width),
                                                     static_cast<uint32_t>(height), config);
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
  // The conformance suite measures raster mode (Mesa-exact rasterization), not the path tracer.
  // Set before the first GL call: glpt reads it when it creates a context's renderer.
  // GLPT_CONFORMANCE_MODE=path renders the scenes path-traced instead, to look at by hand.
  const char* mode = std::getenv("GLPT_CONFORMANCE_MODE");
  setenv("GLPT_MODE", mode != nullptr && std::string_view(mode) == "path" ? "path" : "raster", 1);
  GlptBackend backend;
  return glpt::conformance::run_main(argc, argv, backend);
}
