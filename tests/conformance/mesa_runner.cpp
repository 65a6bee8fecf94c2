// glpt_conformance_mesa: the conformance scenes rendered by real Mesa (OSMesa, llvmpipe): the
// reference glpt's raster mode is measured against.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "runner.hpp"

namespace {

class MesaBackend final : public glpt::conformance::Backend {
 public:
  ~MesaBackend() override { end_scene(); }
  const char* name() const override { return "mesa"; }

  bool begin_scene(int width, int height, std::string* error) override {
    end_scene();
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
    if (context_ == nullptr) {
      *error = "OSMesaCreateContextAttribs failed";
      return false;
    }
    buffer_.assign(static_cast<size_t>(width) * height * 4, 0);
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
      *error = "OSMesaMakeCurrent failed";
      end_scene();
      return false;
    }
    return check_version(error);
  }

  void end_scene() override {
    if (context_ == nullptr) return;
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(context_);
    context_ = nullptr;
  }

 private:
  // The scenes are GL 1.5 programs: they need a compatibility context of version 1.5 or later.
  static bool check_version(std::string* error) {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    int major = 0, minor = 0;
    if (version == nullptr || std::sscanf(version, "%d.%d", &major, &minor) != 2) {
      *error = "GL_VERSION is unreadable";
      return false;
    }
    if (major < 1 || (major == 1 && minor < 5)) {
      *error = std::string("GL 1.5 or later is needed, got ") + version;
      return false;
    }
    if (major > 3 || (major == 3 && minor >= 2)) {
      GLint mask = 0;
      glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
      if ((mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) == 0) {
        *error = std::string("not a compatibility profile: ") + version;
        return false;
      }
    }
    return true;
  }

  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

int main(int argc, char** argv) {
  MesaBackend backend;
  return glpt::conformance::run_main(argc, argv, backend);
}
