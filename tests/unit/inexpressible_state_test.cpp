// A state raster mode cannot express exactly (polygon/point/line smoothing) is
// counted in the frame's statistics (GLPT_STATS prints it as inexpressible=N) and drawn as near
// GL as the pipelines can: no error, no crash, the primitive still covers its pixels.
#include "gl_shim/frame/headless_target.hpp"
#include "gl_test_context.hpp"

namespace {

class InexpressibleStateTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glpt::make_current_headless(ctx_, target_);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  void TearDown() override {
    ctx_.target = nullptr;
    GlTest::TearDown();
  }
  // A white triangle over the lower left half of the window; the frame ends with a swap.
  uint32_t draw_triangle_and_count() {
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(-1, 1);
    glEnd();
    glpt::end_frame(ctx_, true);
    EXPECT_TRUE(ctx_.output);
    return ctx_.output ? ctx_.output->last_frame_stats().inexpressible : 0;
  }
  glpt_test::RasterMode raster_mode_;
  glpt::HeadlessTarget target_{16, 16};
};

TEST_F(InexpressibleStateTest, PlainDrawIsNotCounted) {
  EXPECT_EQ(draw_triangle_and_count(), 0u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(InexpressibleStateTest, PolygonSmoothIsCountedAndStillDrawn) {
  glEnable(GL_POLYGON_SMOOTH);
  EXPECT_EQ(draw_triangle_and_count(), 1u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // The triangle still covers the pixel well inside it (read from the front buffer after the swap).
  glReadBuffer(GL_FRONT);
  GLubyte rgba[4] = {};
  glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[0], 255);
  EXPECT_EQ(rgba[1], 255);
  EXPECT_EQ(rgba[2], 255);
}

TEST_F(InexpressibleStateTest, EachApproximatedDrawCounts) {
  glEnable(GL_POLYGON_SMOOTH);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(-1, 1);
  glEnd();
  glColor3f(1, 0, 0);  // a second draw: the colour changes between them (no batching across it)
  glEnable(GL_LINE_SMOOTH);
  glBegin(GL_LINES);
  glVertex2f(-1, 0.5f);
  glVertex2f(1, 0.5f);
  glEnd();
  EXPECT_EQ(draw_triangle_and_count(), 3u);
}

// Depth comparison (GL_ARB_shadow) is done exactly by the fragment shader: not counted.
TEST_F(InexpressibleStateTest, ShadowComparisonIsNotCounted) {
  const GLfloat depth[4] = {0.25f, 0.75f, 0.25f, 0.75f};
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  EXPECT_EQ(draw_triangle_and_count(), 0u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

}  // namespace

namespace {

// A frame that ends between glBegin and glEnd (a swap inside a primitive) leaves the open
// primitive drawable in the next frame: its state is taken into the new record (under ASan this
// read a destroyed snapshot before).
TEST_F(InexpressibleStateTest, FrameEndInsideBeginEndKeepsThePrimitiveValid) {
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glpt::end_frame(ctx_, true);
  // The open primitive names a state of the new record.
  EXPECT_LT(ctx_.assembly.state, ctx_.recorder.record().states.size());
  glVertex2f(1, -1);
  glVertex2f(-1, 1);
  glEnd();
  glpt::end_frame(ctx_, true);
  EXPECT_EQ(ctx_.output->last_frame_stats().draws, 1u);
}

}  // namespace
