// A glpt::Context made current for the duration of a test, without any window system. Tests
// call the exported entry points through their generated declarations.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/gl_entry_decls.h"

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override { glpt::set_current_context(&ctx_); }
  void TearDown() override { glpt::set_current_context(nullptr); }
  glpt::Context ctx_{nullptr};
};

// GlTest on a headless drawable of the given size (frames can end; the drawable size shows).
class HeadlessGlTest : public GlTest {
 protected:
  HeadlessGlTest(uint32_t width, uint32_t height) : target_(width, height) {}
  void SetUp() override {
    GlTest::SetUp();
    glpt::make_current_headless(ctx_, target_);
  }
  void TearDown() override {
    ctx_.target = nullptr;
    GlTest::TearDown();
  }
  glpt::HeadlessTarget target_;
};

namespace glpt_test {

// A renderbuffer of `format` and size, attached to the bound framebuffer at `attachment`.
inline GLuint attach_renderbuffer(GLenum attachment, GLenum format, GLsizei width, GLsizei height) {
  GLuint rb = 0;
  glGenRenderbuffersEXT(1, &rb);
  glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, format, width, height);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, attachment, GL_RENDERBUFFER_EXT, rb);
  return rb;
}

// A quad over the whole viewport under identity matrices, texture coordinates 0..1.
inline void full_viewport_textured_quad() {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(-1, -1);
  glTexCoord2f(1, 0);
  glVertex2f(1, -1);
  glTexCoord2f(1, 1);
  glVertex2f(1, 1);
  glTexCoord2f(0, 1);
  glVertex2f(-1, 1);
  glEnd();
}

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
