// A glpt::Context made current for the duration of a test, without any window system. Tests
// call the exported entry points through their generated declarations.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "gl_shim/context.hpp"
#include "gl_shim/gl_entry_decls.h"
#include "gl/gl_enums.h"

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override { glpt::set_current_context(&ctx_); }
  void TearDown() override { glpt::set_current_context(nullptr); }
  glpt::Context ctx_{nullptr};
};

namespace glpt_test {

// Raster mode: it executes every command, depth and stencil clears included (the path-traced
// mode is not the subject here).
class RasterMode {
 public:
  RasterMode() {
    if (const char* old = std::getenv("GLPT_MODE")) saved_ = old;
    setenv("GLPT_MODE", "raster", 1);
  }
  ~RasterMode() {
    if (saved_.empty()) {
      unsetenv("GLPT_MODE");
    } else {
      setenv("GLPT_MODE", saved_.c_str(), 1);
    }
  }

 private:
  std::string saved_;
};

}  // namespace glpt_test
