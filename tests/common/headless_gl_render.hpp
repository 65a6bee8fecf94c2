// Renders a GL scene through glpt's front end on a headless drawable and reads it back: the
// harness of the path-traced GL tests (tests/path, tests/light_transport). Header-only; the test
// links glpt_gl_front_whole and glpt_image_io.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/image_io.hpp"
#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/frame/frame_output.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/gl_entry_decls.h"

namespace glpt::test {

// GLPT_* variables for one render, set while its context exists (a context reads them when it
// creates its renderer).
using Settings = std::vector<std::pair<const char*, std::string>>;

// Draws `scene` `frames` times (each ended by glFinish) on a fresh single-buffered size x size
// context with `settings`, and returns the last frame as RGBA8 rows from the bottom (GL's
// glReadPixels order). GLPT_TEST_IMAGES=DIR keeps it as DIR/<test>_<tag>.png. `stats`: where
// to put the last frame's costs and counts (GLPT_STATS' numbers).
inline std::vector<uint8_t> render_headless(int size, const Settings& settings,
                                            const std::function<void()>& scene, int frames,
                                            const std::string& tag,
                                            rt::FrameStats* stats = nullptr) {
  for (const auto& [name, value] : settings) ::setenv(name, value.c_str(), 1);
  rec::DrawableConfig config;
  config.double_buffered = false;
  auto target = std::make_unique<HeadlessTarget>(size, size, config);
  auto context = std::make_unique<Context>(nullptr);
  make_current_headless(*context, *target);
  std::vector<uint8_t> rgba(size_t(size) * size_t(size) * 4);
  for (int frame = 0; frame < frames; ++frame) {
    scene();
    glFinish();
  }
  glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  if (stats != nullptr)
    *stats = context->output ? context->output->last_frame_stats() : rt::FrameStats{};
  if (const char* dir = std::getenv("GLPT_TEST_IMAGES")) {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string path = std::string(dir) + "/" + test->name() + "_" + tag + ".png";
    write_png_rgba8(path, size, size, rgba.data(), true, nullptr);
  }
  set_current_context(nullptr);
  context.reset();
  for (const auto& [name, value] : settings) ::unsetenv(name);
  return rgba;
}

// Draws `scene(frame)` for frame = 0 .. frames - 1 (each ended by glFinish) on one fresh
// single-buffered size x size context with `settings` and reads every frame back (rows from the
// bottom): for what changes from frame to frame (the denoiser's history, accumulation).
// `stats`, if given, gets each frame's costs and counts.
inline std::vector<std::vector<uint8_t>> render_headless_frames(
    int size, const Settings& settings, const std::function<void(int)>& scene, int frames,
    std::vector<rt::FrameStats>* stats = nullptr) {
  for (const auto& [name, value] : settings) ::setenv(name, value.c_str(), 1);
  rec::DrawableConfig config;
  config.double_buffered = false;
  auto target = std::make_unique<HeadlessTarget>(size, size, config);
  auto context = std::make_unique<Context>(nullptr);
  make_current_headless(*context, *target);
  std::vector<std::vector<uint8_t>> images;
  for (int frame = 0; frame < frames; ++frame) {
    scene(frame);
    glFinish();
    std::vector<uint8_t>& rgba = images.emplace_back(size_t(size) * size_t(size) * 4);
    glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    if (stats != nullptr)
      stats->push_back(context->output ? context->output->last_frame_stats() : rt::FrameStats{});
  }
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  set_current_context(nullptr);
  context.reset();
  for (const auto& [name, value] : settings) ::unsetenv(name);
  return images;
}

}  // namespace glpt::test
