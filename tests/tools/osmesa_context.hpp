// A real-Mesa (OSMesa, llvmpipe) GL context for tests that compare glpt with Mesa: RGBA8, depth
// 24, stencil 8, accumulation 16, compatibility profile, single-buffered, drawing into its own
// memory; current from construction to destruction. Link with pkg-config osmesa.
#pragma once

#include <GL/osmesa.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glpt::test {

class OSMesaScope {
 public:
  OSMesaScope(int width, int height) : buffer_(size_t(width) * size_t(height) * 4, 0) {
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
    current_ = context_ != nullptr &&
               OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height);
  }
  ~OSMesaScope() {
    if (context_ == nullptr) return;
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(context_);
  }
  OSMesaScope(const OSMesaScope&) = delete;
  OSMesaScope& operator=(const OSMesaScope&) = delete;

  // False if the context could not be created or made current.
  bool ok() const { return current_; }

 private:
  std::vector<uint8_t> buffer_;
  OSMesaContext context_ = nullptr;
  bool current_ = false;
};

}  // namespace glpt::test
