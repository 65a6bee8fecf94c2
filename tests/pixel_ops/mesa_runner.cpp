// The pixel scenes rendered by real Mesa (OSMesa, llvmpipe): the reference.
#include <GL/osmesa.h>

#include <vector>

#include "scene_runner.hpp"

namespace {

class MesaBackend final : public glpt::pixel_ops::Backend {
 public:
  ~MesaBackend() override { end_scene(); }
  bool begin_scene(int width, int height, std::string* error) override {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_ACCUM_BITS,
                           16,
                           OSMESA_PROFILE,
                           OSMESA_COMPAT_PROFILE,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    buffer_.assign(size_t(width) * height * 4, 0);
    if (context_ == nullptr ||
        !OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
      *error = "OSMesa context creation failed";
      end_scene();
      return false;
    }
    return true;
  }
  void end_scene() override {
    if (context_ == nullptr) return;
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(context_);
    context_ = nullptr;
  }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

int main(int argc, char** argv) {
  MesaBackend backend;
  return glpt::pixel_ops::run_main(argc, argv, backend);
}
