// Several contexts in one process (issue 7 item 4): one Vulkan device for every context, one
// renderer per share group (its pipelines and acceleration structures made once), a drawable's
// buffers shared by every context drawing to it, and contexts current on several threads.
#include <array>
#include <thread>
#include <vector>

#include "gl_shim/frame/headless_target.hpp"
#include "gl_test_context.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace {

using glpt::Context;
using glpt::HeadlessTarget;
using Rgba = std::array<GLubyte, 4>;

Rgba pixel(int x, int y) {
  Rgba rgba{};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  return rgba;
}

// Clears a rectangle of the draw buffer to an opaque colour.
void clear_rect(int x, int y, int width, int height, const Rgba& color) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, width, height);
  glClearColor(color[0] / 255.0f, color[1] / 255.0f, color[2] / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

// A triangle over the lower left half of the drawable, facing the viewer.
void triangle() {
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex3f(-1, -1, -0.5f);
  glVertex3f(1, -1, -0.5f);
  glVertex3f(-1, 1, -0.5f);
  glEnd();
}

// The triangle, lit, in a frame ended by a swap: its statistics are what the context's renderer
// made for it.
const glpt::rt::FrameStats& draw_lit_triangle_frame(Context& ctx) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  triangle();
  glpt::end_frame(ctx, /*swap=*/true);
  EXPECT_TRUE(ctx.output);
  static const glpt::rt::FrameStats none;
  return ctx.output ? ctx.output->last_frame_stats() : none;
}

constexpr Rgba kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255};

class SharedDrawableTest : public ::testing::Test {
 protected:
  void TearDown() override { glpt::set_current_context(nullptr); }
  glpt_test::RasterMode raster_mode_;
  // Single-buffered: glFinish ends a frame, reads and draws both use the front buffer.
  static constexpr glpt::rec::DrawableConfig kSingle{0, 0, false};
};

TEST_F(SharedDrawableTest, ContextsDrawingToOneDrawableDrawIntoTheSameBuffers) {
  HeadlessTarget target(16, 16, kSingle);
  Context a(nullptr), b(nullptr);  // not even a share group
  glpt::make_current_headless(a, target);
  clear_rect(0, 0, 8, 16, kRed);
  glFinish();
  const uint64_t devices = glpt::rt::VulkanDevice::devices_created();

  glpt::make_current_headless(b, target);
  clear_rect(8, 0, 8, 16, kGreen);
  EXPECT_EQ(pixel(2, 2), kRed);  // what the other context drew
  EXPECT_EQ(pixel(12, 2), kGreen);
  glFinish();
  // The second context's renderer is on the same device: no new one was created.
  EXPECT_EQ(glpt::rt::VulkanDevice::devices_created(), devices);

  glpt::make_current_headless(a, target);
  EXPECT_EQ(pixel(12, 2), kGreen);
  EXPECT_EQ(target.presented().size(), size_t{16 * 16 * 4});
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(SharedDrawableTest, EachDrawableHasBuffersOfItsOwn) {
  HeadlessTarget first(16, 16, kSingle), second(16, 16, kSingle);
  Context ctx(nullptr);
  glpt::make_current_headless(ctx, first);
  clear_rect(0, 0, 16, 16, kBlue);
  glFinish();
  // Same size and configuration, but another drawable: it starts transparent black (as glpt's
  // new drawables do), not with the blue.
  glpt::make_current_headless(ctx, second);
  EXPECT_EQ(pixel(4, 4), (Rgba{0, 0, 0, 0}));
  glpt::make_current_headless(ctx, first);
  EXPECT_EQ(pixel(4, 4), kBlue);
}

TEST_F(SharedDrawableTest, AShareGroupSharesItsRendererAndOthersDoNot) {
  HeadlessTarget target(16, 16);
  Context a(nullptr), b(&a), c(nullptr);
  EXPECT_EQ(a.render_group, b.render_group);
  EXPECT_NE(a.render_group, c.render_group);
  glpt::make_current_headless(a, target);
  EXPECT_GT(draw_lit_triangle_frame(a).pipelines_created, 0u);
  // The same state in a context of the same share group: its pipelines exist already.
  glpt::make_current_headless(b, target);
  EXPECT_EQ(draw_lit_triangle_frame(b).pipelines_created, 0u);
  // Another share group has a renderer (and pipelines) of its own.
  glpt::make_current_headless(c, target);
  EXPECT_GT(draw_lit_triangle_frame(c).pipelines_created, 0u);
}

TEST_F(SharedDrawableTest, AShareGroupSharesAccelerationStructures) {
  setenv("GLPT_MODE", "path", 1);  // restored by raster_mode_'s destructor
  HeadlessTarget target(16, 16);
  Context a(nullptr), b(&a);
  glpt::make_current_headless(a, target);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  triangle();
  glEndList();
  const auto frame = [&](Context& ctx) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glCallList(list);
    glpt::end_frame(ctx, true);
    return ctx.output ? ctx.output->last_frame_stats() : glpt::rt::FrameStats{};
  };
  const glpt::rt::FrameStats first = frame(a);
  if (first.triangles == 0) GTEST_SKIP() << "no ray queries on this device: raster mode";
  EXPECT_EQ(first.blas_builds, 1u);
  glpt::make_current_headless(b, target);
  const glpt::rt::FrameStats second = frame(b);
  EXPECT_EQ(second.blas_builds, 0u);
  EXPECT_EQ(second.blas_reused, 1u);
}

// Each thread has its own context and drawable and draws frames of its own colour, while the
// other does the same: every read sees only its own thread's drawing.
TEST_F(SharedDrawableTest, ContextsOnSeveralThreadsDrawAtOnce) {
  constexpr int kFrames = 15;
  const auto run = [](Rgba color, int* good_frames) {
    HeadlessTarget target(24, 24, kSingle);
    Context ctx(nullptr);
    glpt::make_current_headless(ctx, target);
    for (int i = 0; i < kFrames; ++i) {
      const Rgba shade{color[0], color[1], static_cast<GLubyte>(i * 16), 255};
      clear_rect(0, 0, 24, 24, shade);
      glFinish();
      if (pixel(i, i) == shade && glGetError() == GL_NO_ERROR) ++*good_frames;
    }
    glpt::set_current_context(nullptr);
  };
  int good_a = 0, good_b = 0;
  std::thread a(run, kRed, &good_a), b(run, kGreen, &good_b);
  a.join();
  b.join();
  EXPECT_EQ(good_a, kFrames);
  EXPECT_EQ(good_b, kFrames);
}

// Two threads, two contexts of one share group, one drawable: each draws its half with a
// display list of the group, over and over; the drawable ends with both halves.
TEST_F(SharedDrawableTest, ShareGroupOnSeveralThreadsDrawsOneDrawable) {
  HeadlessTarget target(16, 16, kSingle);
  Context first(nullptr), second(&first);
  glpt::make_current_headless(first, target);
  const GLuint lists = glGenLists(2);
  for (GLuint i = 0; i < 2; ++i) {
    glNewList(lists + i, GL_COMPILE);
    clear_rect(static_cast<int>(8 * i), 0, 8, 16, i == 0 ? kRed : kGreen);
    glEndList();
  }
  glpt::set_current_context(nullptr);
  const auto run = [&](Context* ctx, GLuint list) {
    glpt::make_current_headless(*ctx, target);
    for (int i = 0; i < 20; ++i) {
      glCallList(list);
      glFinish();
    }
    glpt::set_current_context(nullptr);
  };
  std::thread a(run, &first, lists), b(run, &second, lists + 1);
  a.join();
  b.join();
  glpt::make_current_headless(first, target);
  EXPECT_EQ(pixel(2, 2), kRed);
  EXPECT_EQ(pixel(12, 2), kGreen);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

}  // namespace
