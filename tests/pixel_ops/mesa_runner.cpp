// The pixel scenes rendered by real Mesa (OSMesa, llvmpipe): the reference.
#include <memory>

#include "osmesa_context.hpp"
#include "scene_runner.hpp"

namespace {

class MesaBackend final : public glpt::pixel_ops::Backend {
 public:
  bool begin_scene(int width, int height, std::string* error) override {
    context_ = std::make_unique<glpt::test::OSMesaScope>(width, height);
    if (!context_->ok()) *error = "OSMesa context creation failed";
    return context_->ok();
  }
  void end_scene() override { context_.reset(); }

 private:
  std::unique_ptr<glpt::test::OSMesaScope> context_;
};

}  // namespace

int main(int argc, char** argv) {
  MesaBackend backend;
  return glpt::pixel_ops::run_main(argc, argv, backend);
}
