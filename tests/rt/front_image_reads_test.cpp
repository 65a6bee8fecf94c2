// Raster mode presents a frame from the front image in place (FrameEnd::front_pixels): the host
// copies its rows out after execute returned, while the program records the next frames. Until
// the copy releases its token, nothing may draw into that image; the other image stays free.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

#include "record_builder.hpp"
#include "rt_core/renderer.hpp"

namespace glpt::rt {
namespace {

using test::RecordBuilder;

constexpr uint32_t kSize = 16;

RecordBuilder cleared_frame(glm::vec4 color) {
  RecordBuilder b(kSize, kSize);
  b.drawable.double_buffered = true;
  b.raster.ops.draw_buffer = b.raster.ops.read_buffer = GL_BACK;  // a frame drawn to the back
  b.clear(color);
  return b;
}

std::vector<uint8_t> rows_of(const FrameEnd::FrontPixels& front) {
  std::vector<uint8_t> bytes;
  for (uint32_t y = 0; y < kSize; ++y)
    bytes.insert(bytes.end(), front.rows + y * front.row_pitch,
                 front.rows + y * front.row_pitch + kSize * 4);
  return bytes;
}

TEST(RasterFrontReads, AFrameWaitsToDrawIntoTheImageTheHostStillReads) {
  RenderSettings settings;
  settings.mode = RenderMode::kRaster;
  settings.validation = RenderSettings::from_environment().validation;
  std::string error;
  const std::unique_ptr<Renderer> renderer = Renderer::create(settings, &error);
  ASSERT_NE(renderer, nullptr) << error;
  const std::shared_ptr<DrawableBuffers> buffers = create_drawable_buffers();
  std::vector<uint8_t> window(size_t{kSize} * kSize * 4);
  const HostImage host{window.data(), kSize, kSize, new_host_image_generation()};
  FrameStats stats;

  // Frame 1 (red) is swapped to the front and handed to the host to read in place.
  FrameEnd::FrontPixels front;
  FrameEnd end;
  end.swap = true;
  end.present_to = &host;
  end.present_later = true;
  end.present_bottom_up = true;
  end.front_pixels = &front;
  const RecordBuilder red = cleared_frame({1, 0, 0, 1});
  ASSERT_TRUE(renderer->execute(red.record, *buffers, red.drawable, stats, &error, &end)) << error;
  if (front.rows == nullptr) GTEST_SKIP() << "the device has no host-readable colour images";
  renderer->wait_for_frame(renderer->frame_ticket());
  const std::vector<uint8_t> red_rows = rows_of(front);

  // Frame 2 (green) draws into the other image: it does not wait for the read.
  FrameEnd swap_only;
  swap_only.swap = true;
  const RecordBuilder green = cleared_frame({0, 1, 0, 1});
  ASSERT_TRUE(renderer->execute(green.record, *buffers, green.drawable, stats, &error, &swap_only))
      << error;
  renderer->wait_for_frame(renderer->frame_ticket());
  EXPECT_EQ(rows_of(front), red_rows);

  // Frame 3 (blue) draws into the image being read: it waits until the read ends.
  std::atomic<bool> drawn{false};
  std::thread third([&] {
    const RecordBuilder blue = cleared_frame({0, 0, 1, 1});
    std::string thread_error;
    EXPECT_TRUE(renderer->execute(blue.record, *buffers, blue.drawable, stats, &thread_error))
        << thread_error;
    renderer->wait_for_frame(renderer->frame_ticket());
    drawn = true;
  });
  // (A renderer that does not wait has drawn well within this; one that waits never has.)
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_FALSE(drawn.load()) << "frame 3 drew while the host read the image";
  EXPECT_EQ(rows_of(front), red_rows) << "the rows being read changed under the reader";
  const uint8_t* rows = front.rows;
  const size_t pitch = front.row_pitch;
  front.reading.reset();  // the read ends
  third.join();
  EXPECT_TRUE(drawn.load());
  // And frame 3 did draw into that very image, so the checks above looked at the right one.
  FrameEnd::FrontPixels after{rows, pitch, nullptr};
  EXPECT_NE(rows_of(after), red_rows);
}

}  // namespace
}  // namespace glpt::rt
