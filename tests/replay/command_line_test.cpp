// glpt-replay's command line and frame selection.
#include "replay/command_line.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "gl/gl_enums.h"
#include "replay/frame_selection.hpp"
#include "replay/image_sizes.hpp"

namespace {

using glpt::replay::FrameSelection;
using glpt::replay::Options;

bool parse(std::vector<const char*> args, Options* options, std::string* error) {
  args.insert(args.begin(), "glpt-replay");
  return glpt::replay::parse_command_line(static_cast<int>(args.size()), args.data(), options,
                                          error);
}

TEST(FrameSelection, FramesAndRanges) {
  FrameSelection s;
  std::string error;
  ASSERT_TRUE(s.parse_frames("3,10-12", &error)) << error;
  std::vector<uint64_t> chosen;
  for (uint64_t f = 0; f < 20; ++f)
    if (s.chosen(f)) chosen.push_back(f);
  EXPECT_EQ(chosen, (std::vector<uint64_t>{3, 10, 11, 12}));
  EXPECT_EQ(s.last_chosen(), 12u);
  for (const char* bad : {"", "1,", "a", "5-3", "-2", "1-", "1.5"})
    EXPECT_FALSE(s.parse_frames(bad, &error)) << bad;
}

TEST(FrameSelection, ShardsSplitTheChosenFramesByIndex) {
  FrameSelection s;
  std::string error;
  s.set_every(2);
  ASSERT_TRUE(s.parse_shard("1/3", &error)) << error;
  std::vector<uint64_t> rendered;
  for (uint64_t f = 0; f < 20; ++f)
    if (s.rendered(f)) rendered.push_back(f);
  // Chosen: the even frames; of those, f % 3 == 1.
  EXPECT_EQ(rendered, (std::vector<uint64_t>{4, 10, 16}));
  EXPECT_EQ(s.last_chosen(), UINT64_MAX);
  for (const char* bad : {"3/3", "1", "1/0", "/2", "a/b", "-1/2"})
    EXPECT_FALSE(s.parse_shard(bad, &error)) << bad;
}

TEST(FrameSelection, HistoryWindowsGoWholeToOneShardWithTheFramesBeforeAWrittenOne) {
  FrameSelection s;
  std::string error;
  ASSERT_TRUE(s.parse_frames("2,5,9-10,13", &error)) << error;
  ASSERT_TRUE(s.parse_shard("1/2", &error)) << error;
  s.set_history_window(4);
  std::vector<uint64_t> written, rendered;
  for (uint64_t f = 0; f < 20; ++f) {
    if (s.written(f)) written.push_back(f);
    if (s.rendered(f)) rendered.push_back(f);
  }
  // Windows 1 (4-7) and 3 (12-15) are shard 1's; frames after the last written one of a window
  // are not rendered.
  EXPECT_EQ(written, (std::vector<uint64_t>{5, 13}));
  EXPECT_EQ(rendered, (std::vector<uint64_t>{4, 5, 12, 13}));
}

TEST(CommandLine, QualityFlagsBecomeTheRenderersVariables) {
  Options o;
  std::string error;
  ASSERT_TRUE(
      parse({"--mode", "raster", "--spp=4", "--out", "d", "x.trace", "--validation"}, &o, &error))
      << error;
  EXPECT_EQ(o.trace, "x.trace");
  EXPECT_EQ(o.out_dir, "d");
  using Env = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(o.environment,
            (Env{{"GLPT_MODE", "raster"}, {"GLPT_SPP", "4"}, {"GLPT_VALIDATION", "1"}}));

  // The same table as `glpt run`: the light-transport knobs and the reference.
  Options knobs;
  ASSERT_TRUE(parse({"--shadows", "0", "--bounces", "0", "--ao=0", "--reference", "256", "--unlit",
                     "ao", "--quiet", "x.trace"},
                    &knobs, &error))
      << error;
  EXPECT_TRUE(knobs.quiet);  // glpt-replay's own --quiet, not GLPT_QUIET
  EXPECT_EQ(knobs.environment, (Env{{"GLPT_SHADOWS", "0"},
                                    {"GLPT_BOUNCES", "0"},
                                    {"GLPT_AO", "0"},
                                    {"GLPT_REFERENCE", "256"},
                                    {"GLPT_UNLIT", "ao"}}));
  EXPECT_NE(glpt::replay::usage().find("--reference N"), std::string::npos);

  // The history window: --history, else none for raster mode and Mesa, else the default.
  using glpt::replay::history_window_of;
  Options window;
  ASSERT_TRUE(parse({"--history", "3", "x.trace"}, &window, &error)) << error;
  EXPECT_EQ(history_window_of(window, "raster"), 3u);
  Options plain;
  ASSERT_TRUE(parse({"x.trace"}, &plain, &error)) << error;
  EXPECT_EQ(history_window_of(plain, "raster"), 1u);
  EXPECT_EQ(history_window_of(plain, nullptr), glpt::replay::kDefaultHistoryWindow);
  Options mesa;
  ASSERT_TRUE(parse({"--backend", "mesa", "x.trace"}, &mesa, &error)) << error;
  EXPECT_EQ(history_window_of(mesa, "path"), 1u);
  EXPECT_EQ(glpt::replay::usage().find("%QUALITY_FLAGS%"), std::string::npos);

  // --repeat: passes over the trace in one process (the soak's long runs).
  Options repeated;
  ASSERT_TRUE(parse({"--repeat", "4", "x.trace"}, &repeated, &error)) << error;
  EXPECT_EQ(repeated.repeat, 4u);
  EXPECT_EQ(plain.repeat, 1u);
}

TEST(CommandLine, BadUsageIsRejected) {
  const std::vector<std::vector<const char*>> bad = {
      {},                             // no trace
      {"a.trace", "b.trace"},         // two traces
      {"--spp", "0", "a.trace"},      // out of range
      {"--mode", "fast", "a.trace"},  // no such mode
      {"--backend", "d3d", "a.trace"},
      {"--every", "0", "a.trace"},
      {"--frames", "x", "a.trace"},
      {"--shard", "2/2", "a.trace"},
      {"--history", "0", "a.trace"},
      {"--history", "1025", "a.trace"},
      {"--repeat", "0", "a.trace"},
      {"--repeat", "2x", "a.trace"},
      {"--bogus", "a.trace"},
      {"a.trace", "--out"},  // missing value
      {"--quiet=1", "a.trace"},
      {"--unlit", "glow", "a.trace"},  // not one of keep|ao|emit
  };
  for (const auto& args : bad) {
    Options o;
    std::string error;
    EXPECT_FALSE(parse(args, &o, &error)) << (args.empty() ? "(none)" : args[0]);
    EXPECT_FALSE(error.empty());
  }
  Options o;
  std::string error;
  EXPECT_TRUE(parse({"--help"}, &o, &error));
  EXPECT_TRUE(o.help);
}

}  // namespace

namespace {

using glpt::replay::image_bytes;
using UnpackModes = glpt::PixelStoreModes;

// GL 1.5 3.6.4: rows of width * components * size bytes, each rounded up to the alignment.
TEST(ImageSizes, RowsFollowTheUnpackModes) {
  UnpackModes modes;  // alignment 4
  // Rows of 9 bytes start every 12; the last row ends after its 9 bytes.
  EXPECT_EQ(image_bytes(3, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, false, modes), 12u + 9);
  modes.alignment = 1;
  EXPECT_EQ(image_bytes(3, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, false, modes), 2u * 9);
  modes.row_length = 10;
  modes.skip_rows = 1;
  // One skipped row, then two rows of 10 groups of which the last is read up to its 3rd group.
  EXPECT_EQ(image_bytes(3, 2, 1, GL_RGBA, GL_FLOAT, false, modes), 2u * 160 + 3 * 16);
  EXPECT_EQ(image_bytes(3, 2, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, false, modes), 2u * 40 + 12);
  // Bitmaps: bits, rows of whole bytes rounded up to the alignment.
  UnpackModes bitmap;
  EXPECT_EQ(image_bytes(32, 32, 1, GL_COLOR_INDEX, GL_BITMAP, false, bitmap), 128u);
  EXPECT_EQ(image_bytes(9, 3, 1, GL_COLOR_INDEX, GL_BITMAP, false, bitmap), 4u + 4 + 2);
  // 3-D: image height and skipped images.
  UnpackModes volume;
  volume.alignment = 1;
  volume.image_height = 4;
  volume.skip_images = 1;
  // Image 0 skipped, images of 4 rows of 2 bytes; the last image ends after its 3rd row.
  EXPECT_EQ(image_bytes(2, 3, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, true, volume), 2u * 8 + 6);
}

TEST(ImageSizes, NonsenseHasNoSize) {
  const UnpackModes modes;
  EXPECT_FALSE(image_bytes(4, 4, 1, 0x1234, GL_UNSIGNED_BYTE, false, modes));
  EXPECT_FALSE(image_bytes(4, 4, 1, GL_RGBA, 0x1234, false, modes));
  EXPECT_FALSE(image_bytes(-1, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, false, modes));
  EXPECT_FALSE(image_bytes(1 << 30, 1 << 30, 1, GL_RGBA, GL_FLOAT, false, modes));
  EXPECT_EQ(image_bytes(0, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, false, modes), 0u);
}

}  // namespace
