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

// GLPT_* variables for one render, set while its context exists.
using Settings = std::vector<std::pair<const char*, std::string>>;

// A fresh single-buffered size x size headless context, current while it exists, with the
// GLPT_* `settings` set in the environment (a context reads them when it creates its renderer).
class HeadlessSession {
 public:
  HeadlessSession(int size, const Settings& settings) : settings_(settings) {
    for (const auto& [name, value] : settings_) ::setenv(name, value.c_str(), 1);
    rec::DrawableConfig config;
    config.double_buffered = false;
    target_ = std::make_unique<HeadlessTarget>(size, size, config);
    context_ = std::make_unique<Context>(nullptr);
    make_current_headless(*context_, *target_);
  }
  ~HeadlessSession() {
    set_current_context(nullptr);
    context_.reset();
    for (const auto& [name, value] : settings_) ::unsetenv(name);
  }
  HeadlessSession(const HeadlessSession&) = delete;
  HeadlessSession& operator=(const HeadlessSession&) = delete;
  // The last frame's costs and counts (GLPT_STATS' numbers).
  rt::FrameStats last_frame_stats() const {
    return context_->output ? context_->output->last_frame_stats() : rt::FrameStats{};
  }

 private:
  Settings settings_;
  std::unique_ptr<HeadlessTarget> target_;
  std::unique_ptr<Context> context_;
};

// Draws `scene` `frames` times (each ended by glFinish) on a fresh single-buffered size x size
// context with `settings`, and returns the last frame as RGBA8 rows from the bottom (GL's
// glReadPixels order). GLPT_TEST_IMAGES=DIR keeps it as DIR/<test>_<tag>.png. `stats`: where
// to put the last frame's costs and counts (GLPT_STATS' numbers).
inline std::vector<uint8_t> render_headless(int size, const Settings& settings,
                                            const std::function<void()>& scene, int frames,
                                            const std::string& tag,
                                            rt::FrameStats* stats = nullptr) {
  HeadlessSession session(size, settings);
  std::vector<uint8_t> rgba(size_t(size) * size_t(size) * 4);
  for (int frame = 0; frame < frames; ++frame) {
    scene();
    glFinish();
  }
  glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  if (stats != nullptr) *stats = session.last_frame_stats();
  if (const char* dir = std::getenv("GLPT_TEST_IMAGES")) {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string path = std::string(dir) + "/" + test->name() + "_" + tag + ".png";
    write_png_rgba8(path, size, size, rgba.data(), true, nullptr);
  }
  return rgba;
}

// Draws `scene(frame)` for frame = 0 .. frames - 1 (each ended by glFinish) on one fresh
// single-buffered size x size context with `settings` and reads every frame back (rows from the
// bottom): for what changes from frame to frame (the denoiser's history, accumulation).
// `stats`, if given, gets each frame's costs and counts.
inline std::vector<std::vector<uint8_t>> render_headless_frames(
    int size, const Settings& settings, const std::function<void(int)>& scene, int frames,
    std::vector<rt::FrameStats>* stats = nullptr) {
  HeadlessSession session(size, settings);
  std::vector<std::vector<uint8_t>> images;
  for (int frame = 0; frame < frames; ++frame) {
    scene(frame);
    glFinish();
    std::vector<uint8_t>& rgba = images.emplace_back(size_t(size) * size_t(size) * 4);
    glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    if (stats != nullptr) stats->push_back(session.last_frame_stats());
  }
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  return images;
}

}  // namespace glpt::test
