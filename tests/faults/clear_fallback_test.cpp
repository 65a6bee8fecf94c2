// The frames of a context without a renderer (no Vulkan): ClearFallback keeps the values of the
// last clears and shows the colour one. Expected values by hand: colours are stored as in an
// RGBA8 buffer, round(c * 255).
#include "gl_shim/frame/clear_fallback.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "gl/gl_enums.h"

namespace {

class CapturingTarget : public glpt::WindowTarget {
 public:
  bool query_size(uint32_t* width, uint32_t* height) override {
    *width = 4;
    *height = 2;
    return true;
  }
  void present(const uint8_t* rgba, uint32_t width, uint32_t height) override {
    shown.assign(rgba, rgba + size_t{width} * height * 4);
    shown_width = width;
    shown_height = height;
  }
  std::vector<uint8_t> shown;
  uint32_t shown_width = 0, shown_height = 0;
};

glpt::rec::Clear clear(uint32_t mask, glm::vec4 color, float depth = 1, int32_t stencil = 0) {
  glpt::rec::Clear c;
  c.mask = mask;
  c.color = color;
  c.depth = depth;
  c.stencil = stencil;
  return c;
}

TEST(ClearFallback, TheLastClearOfEachBufferIsWhatTheFrameShows) {
  glpt::rec::FrameRecord record;
  record.commands.push_back(clear(GL_COLOR_BUFFER_BIT, {1, 1, 1, 1}));
  record.commands.push_back(
      clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, {0.2f, 0.4f, 0.6f, 1}, 0.25f));
  // Later clears of other buffers leave the colour alone.
  record.commands.push_back(clear(GL_STENCIL_BUFFER_BIT, {0, 0, 0, 0}, 1, 0x1FF));
  glpt::ClearFallback fallback;
  CapturingTarget target;
  fallback.end_frame(record, 4, 2, &target);
  ASSERT_EQ(target.shown_width, 4u);
  ASSERT_EQ(target.shown_height, 2u);
  ASSERT_EQ(target.shown.size(), 4u * 2 * 4);
  for (size_t i = 0; i < target.shown.size(); i += 4) {
    EXPECT_EQ(target.shown[i], 51);  // round(0.2 * 255)
    EXPECT_EQ(target.shown[i + 1], 102);
    EXPECT_EQ(target.shown[i + 2], 153);
    EXPECT_EQ(target.shown[i + 3], 255);
  }

  // glReadPixels of a rectangle reaching past the drawable's right edge.
  glpt::FramebufferPixels pixels;
  fallback.read(glpt::rec::PixelKind::kColor, 3, 1, 2, 1, 4, 2, pixels);
  ASSERT_EQ(pixels.color.size(), 2u);
  EXPECT_FLOAT_EQ(pixels.color[0].g, 102.0f / 255.0f);
  EXPECT_EQ(pixels.inside, (std::vector<uint8_t>{1, 0}));
  fallback.read(glpt::rec::PixelKind::kDepth, 0, 0, 1, 1, 4, 2, pixels);
  ASSERT_EQ(pixels.depth.size(), 1u);
  EXPECT_EQ(pixels.depth[0], 0.25f);
  fallback.read(glpt::rec::PixelKind::kStencil, 0, 0, 1, 1, 4, 2, pixels);
  ASSERT_EQ(pixels.stencil.size(), 1u);
  EXPECT_EQ(pixels.stencil[0], 0xFFu);  // an 8-bit stencil buffer keeps the low bits

  // A frame without clears shows what the last one left.
  fallback.end_frame(glpt::rec::FrameRecord(), 4, 2, &target);
  EXPECT_EQ(target.shown[0], 51);
}

TEST(ClearFallback, NothingClearedYetIsBlack) {
  glpt::ClearFallback fallback;
  glpt::FramebufferPixels pixels;
  fallback.read(glpt::rec::PixelKind::kColor, 0, 0, 1, 1, 4, 2, pixels);
  ASSERT_EQ(pixels.color.size(), 1u);
  EXPECT_EQ(pixels.color[0], glm::vec4(0.0f));
}

}  // namespace
