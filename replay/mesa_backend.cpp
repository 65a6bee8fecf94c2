// Backend "mesa": real Mesa (OSMesa, llvmpipe) loaded at run time, the reference glpt's raster
// mode is compared with. Each recorded context is an OSMesa context (RGBA, depth 24, stencil 8,
// accumulation 16 per channel: the conformance suite's configuration); each recorded drawable a
// client-memory colour buffer OSMesa renders into.
#include <dlfcn.h>

#include <algorithm>
#include <map>

#include "gl/gl_enums.h"
#include "replay/backend.hpp"

namespace glpt::replay {
namespace {

// From <GL/osmesa.h> (not included: its <GL/gl.h> would redefine glpt's generated enums).
constexpr int kOsmesaFormat = 0x22, kOsmesaDepthBits = 0x30, kOsmesaStencilBits = 0x31,
              kOsmesaAccumBits = 0x32, kOsmesaProfile = 0x33, kOsmesaCompatProfile = 0x35;
using OSMesaContext = void*;
using CreateContextAttribs = OSMesaContext (*)(const int*, OSMesaContext);
using MakeCurrent = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using DestroyContext = void (*)(OSMesaContext);
using GetProcAddress = GlProc (*)(const char*);

class MesaBackend final : public Backend {
 public:
  static std::unique_ptr<Backend> create(std::string* error) {
    void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) {
      *error =
          std::string("cannot load libOSMesa.so.8 (Debian: libosmesa6 from bookworm-backports): ") +
          dlerror();
      return nullptr;
    }
    auto backend = std::unique_ptr<MesaBackend>(new MesaBackend(library));
    if (!backend->create_ || !backend->make_current_ || !backend->destroy_ || !backend->get_proc_) {
      *error = "libOSMesa.so.8 lacks the OSMesa entry points";
      return nullptr;
    }
    return backend;
  }

  ~MesaBackend() override {
    if (make_current_) make_current_(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    for (OSMesaContext c : contexts_) destroy_(c);
    dlclose(library_);
  }

  const char* name() const override { return "mesa"; }

  GlProc resolve(const char* name) override { return get_proc_(name); }

  ContextHandle create_context(ContextHandle share, std::string* error) override {
    const int attribs[] = {kOsmesaFormat,
                           GL_RGBA,
                           kOsmesaDepthBits,
                           24,
                           kOsmesaStencilBits,
                           8,
                           kOsmesaAccumBits,
                           16,
                           kOsmesaProfile,
                           kOsmesaCompatProfile,
                           0};
    OSMesaContext context = create_(attribs, share);
    if (context == nullptr) {
      *error = "OSMesaCreateContextAttribs failed";
      return nullptr;
    }
    contexts_.push_back(context);
    return context;
  }

  void destroy_context(ContextHandle context) override {
    const auto it = std::find(contexts_.begin(), contexts_.end(), context);
    if (it == contexts_.end()) return;
    if (current_ == context) {
      make_current_(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
      current_ = nullptr;
    }
    destroy_(context);
    contexts_.erase(it);
  }

  bool make_current(ContextHandle context, uint64_t surface, uint32_t width, uint32_t height,
                    bool /*double_buffered*/, std::string* error) override {
    if (context == nullptr) {
      make_current_(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
      current_ = nullptr;
      return true;
    }
    Surface& s = surfaces_[surface];
    if (s.rgba.empty()) {
      s.width = std::max(width, 1u);
      s.height = std::max(height, 1u);
      s.rgba.assign(size_t{s.width} * s.height * 4, 0);
    }
    current_ = context;
    current_surface_ = &s;
    if (!bind()) {
      *error = "OSMesaMakeCurrent failed";
      return false;
    }
    return true;
  }

  bool current_size(uint32_t* width, uint32_t* height) override {
    if (current_ == nullptr || current_surface_ == nullptr) return false;
    *width = current_surface_->width;
    *height = current_surface_->height;
    return true;
  }

  void resize_current(uint32_t width, uint32_t height) override {
    if (current_ == nullptr || current_surface_ == nullptr) return;
    current_surface_->width = std::max(width, 1u);
    current_surface_->height = std::max(height, 1u);
    current_surface_->rgba.assign(size_t{current_surface_->width} * current_surface_->height * 4,
                                  0);
    bind();
  }

  bool end_frame(bool /*swap*/, GlProc flush, bool render, FrameImage* image,
                 std::string* /*error*/) override {
    if (current_ == nullptr || current_surface_ == nullptr) return true;
    if (flush != nullptr) flush();
    if (!render || image == nullptr) return true;
    // OSMesa draws into the client buffer as commands arrive; glFinish waits for them.
    if (auto finish = reinterpret_cast<void (*)()>(get_proc_("glFinish"))) finish();
    image->width = current_surface_->width;
    image->height = current_surface_->height;
    image->rgba = current_surface_->rgba;  // rows bottom to top (OSMESA_Y_UP by default)
    for (size_t i = 3; i < image->rgba.size(); i += 4) image->rgba[i] = 255;
    return true;
  }

  std::vector<std::pair<std::string, uint64_t>> unimplemented_calls() const override { return {}; }

 private:
  struct Surface {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
  };

  explicit MesaBackend(void* library)
      : library_(library),
        create_(
            reinterpret_cast<CreateContextAttribs>(dlsym(library, "OSMesaCreateContextAttribs"))),
        make_current_(reinterpret_cast<MakeCurrent>(dlsym(library, "OSMesaMakeCurrent"))),
        destroy_(reinterpret_cast<DestroyContext>(dlsym(library, "OSMesaDestroyContext"))),
        get_proc_(reinterpret_cast<GetProcAddress>(dlsym(library, "OSMesaGetProcAddress"))) {}

  bool bind() {
    return make_current_(current_, current_surface_->rgba.data(), GL_UNSIGNED_BYTE,
                         static_cast<GLsizei>(current_surface_->width),
                         static_cast<GLsizei>(current_surface_->height)) != 0;
  }

  void* library_;
  CreateContextAttribs create_;
  MakeCurrent make_current_;
  DestroyContext destroy_;
  GetProcAddress get_proc_;
  std::vector<OSMesaContext> contexts_;
  std::map<uint64_t, Surface> surfaces_;
  OSMesaContext current_ = nullptr;
  Surface* current_surface_ = nullptr;
};

}  // namespace

std::unique_ptr<Backend> create_mesa_backend(std::string* error) {
  return MesaBackend::create(error);
}

}  // namespace glpt::replay
