// A context drawn into and released from an exit handler registered before glpt's Vulkan device
// existed (piglit's teardown releases its context so, through glXMakeCurrent): by then exit() has
// torn down lavapipe's LLVM, whose code generation then hangs or crashes. glpt renders nothing
// once the process is exiting (rt::process_exiting), so such a process exits at once.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>

#include "gl_shim/frame/headless_target.hpp"
#include "gl_test_context.hpp"

namespace {

void draw_triangle() {
  glBegin(GL_TRIANGLES);
  glVertex2f(-1.0f, -1.0f);
  glVertex2f(1.0f, -1.0f);
  glVertex2f(0.0f, 1.0f);
  glEnd();
}

// Runs after the device's exit handler and LLVM's teardown (registered later, so run earlier).
void draw_and_release_at_exit() {
  // Texturing: a state no pipeline was compiled for yet (other specialization constants).
  static const GLubyte texel[4] = {200, 100, 50, 255};
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexCoord2f(0.5f, 0.5f);
  draw_triangle();
  glFinish();
  glpt::set_current_context(nullptr);
}

[[noreturn]] void draw_then_exit() {
  alarm(60);  // a hang (the failure this guards against) ends as a death by SIGALRM
  setenv("GLPT_MODE", "raster", 1);
  std::atexit(draw_and_release_at_exit);  // before the device exists, as piglit's teardown
  // Left to the process's end (an exit handler uses them).
  auto* target = new glpt::HeadlessTarget(16, 16);
  auto* context = new glpt::Context(nullptr);
  glpt::set_current_context(context);
  glpt::make_current_headless(*context, *target);
  glClear(GL_COLOR_BUFFER_BIT);
  draw_triangle();
  glFinish();  // the device is created here, and with it its exit handler
  std::exit(0);
}

TEST(ExitHandler, AContextReleasedAtExitRendersNothingAndTheProcessExits) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");  // a fresh process: no device yet
  EXPECT_EXIT(draw_then_exit(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
