// `glpt diff`, called in-process: pairing of files and directories, JSON, heat maps, exit
// statuses.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "image_io.hpp"
#include "temp_dir.hpp"

namespace glpt::cli {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  int status;
  std::string out, err;
};

Outcome diff(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int status = diff_main(args, out, err);
  return {status, out.str(), err.str()};
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> r;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) r.push_back(line);
  return r;
}

class DiffCommand : public ::testing::Test {
 protected:
  // Writes a w x h PNG filled with grey level `v`, with one pixel set to `spot`.
  std::string png(const std::string& relative, uint32_t w, uint32_t h, uint8_t v,
                  uint8_t spot = 0) {
    const std::string path = dir_ + "/" + relative;
    fs::create_directories(fs::path(path).parent_path());
    std::vector<uint8_t> rgba(size_t{w} * h * 4, v);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    if (spot) rgba[0] = rgba[1] = rgba[2] = spot;
    std::string error;
    EXPECT_TRUE(write_png_rgba8(path, w, h, rgba.data(), false, &error)) << error;
    return path;
  }
  static std::string data(const std::string& name) {
    return std::string(GLPT_DIFF_TEST_DATA) + "/" + name;
  }
  glpt::testing::ScopedTempDir temp_{"glpt_diff"};
  const std::string dir_ = temp_.path();
};

TEST_F(DiffCommand, IdenticalImagesPassWithNullPsnr) {
  const std::string a = png("a.png", 16, 16, 100), b = png("b.png", 16, 16, 100);
  const Outcome o = diff({"--json", a, b});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("\"a\":\"" + a + "\""), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\"b\":\"" + b + "\""), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\"flip_mean\":0,"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\"psnr\":null"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\"fraction_over_tolerance\":0,"), std::string::npos) << o.out;
  EXPECT_EQ(lines(o.out).size(), 1u);
}

TEST_F(DiffCommand, ExitsOneOverTheThreshold) {
  // NVlabs' FLIP mean for this pair is 0.566 (flip_reference_test.cpp).
  const std::string a = data("colors_a.png"), b = data("colors_b.png");
  EXPECT_EQ(diff({a, b}).status, 1);
  EXPECT_EQ(diff({"--threshold", "0.6", a, b}).status, 0);
  EXPECT_EQ(diff({"--threshold=0.5", a, b}).status, 1);
  const Outcome o = diff({a, b});
  EXPECT_NE(o.out.find("OVER threshold"), std::string::npos) << o.out;
}

TEST_F(DiffCommand, PpdChangesTheResult) {
  const std::string a = data("edges_a.png"), b = data("edges_b.png");
  const Outcome near = diff({"--json", a, b}), far = diff({"--json", "--ppd", "30", a, b});
  EXPECT_NE(near.out.find("\"flip_mean\":0.2706"), std::string::npos) << near.out;
  EXPECT_NE(far.out.find("\"flip_mean\":0.2090"), std::string::npos) << far.out;
  EXPECT_NE(far.out.find("\"ppd\":30,"), std::string::npos) << far.out;
}

TEST_F(DiffCommand, PixelToleranceCountsPixels) {
  // One pixel of 64 differs strongly; the FLIP filters spread it over its neighbours, so the
  // fraction over a tolerance grows as the tolerance falls.
  const std::string a = png("a.png", 8, 8, 50), b = png("b.png", 8, 8, 50, 250);
  auto fraction = [&](const char* tolerance) {
    const std::string out = diff({"--json", "--pixel-tolerance", tolerance, a, b}).out;
    const size_t at = out.find("\"fraction_over_tolerance\":");
    return std::stod(out.substr(at + 26));
  };
  EXPECT_GT(fraction("0.01"), fraction("0.5"));
  EXPECT_GT(fraction("0.5"), 0.0);
  EXPECT_EQ(fraction("1"), 0.0);
}

TEST_F(DiffCommand, SizeMismatchIsAnError) {
  const Outcome o = diff({png("a.png", 16, 16, 0), png("b.png", 16, 8, 0)});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("sizes differ"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("16x8"), std::string::npos) << o.err;
}

TEST_F(DiffCommand, UnreadableOrMissingInputIsAnError) {
  const std::string a = png("a.png", 4, 4, 0);
  std::ofstream(dir_ + "/text.png") << "not a png";
  Outcome o = diff({a, dir_ + "/text.png"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("text.png"), std::string::npos) << o.err;
  o = diff({a, dir_ + "/missing.png"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("missing.png: no such file"), std::string::npos) << o.err;
  // In JSON, the pair still gets its object, with the error.
  o = diff({"--json", a, dir_ + "/text.png"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.out.find("\"error\":"), std::string::npos) << o.out;
}

TEST_F(DiffCommand, BadCommandLinesExitTwo) {
  const std::string a = png("a.png", 4, 4, 0);
  EXPECT_EQ(diff({}).status, 2);
  EXPECT_EQ(diff({a}).status, 2);
  EXPECT_EQ(diff({a, a, a}).status, 2);
  EXPECT_EQ(diff({"--ppd", "0", a, a}).status, 2);
  EXPECT_EQ(diff({"--ppd", "x", a, a}).status, 2);
  EXPECT_EQ(diff({"--pixel-tolerance", "-0.1", a, a}).status, 2);
  EXPECT_EQ(diff({"--threshold=-1", a, a}).status, 2);
  EXPECT_EQ(diff({"--threshold=0", a, a}).status, 0);
  EXPECT_EQ(diff({"--threshold", a, a}).status, 2);  // "a.png" is not a number
  EXPECT_EQ(diff({"--frobnicate", a, a}).status, 2);
  EXPECT_EQ(diff({a, a, "--ppd"}).status, 2);
  const Outcome help = diff({"--help"});
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--pixel-tolerance"), std::string::npos);
}

TEST_F(DiffCommand, DirectoriesAreMatchedByName) {
  png("ref/same.png", 8, 8, 90);
  png("ref/changed.png", 8, 8, 90);
  png("ref/only_ref.png", 8, 8, 90);
  png("test/same.png", 8, 8, 90);
  png("test/changed.png", 8, 8, 0);
  png("test/only_test.png", 8, 8, 0);
  std::ofstream(dir_ + "/test/notes.txt") << "not an image";
  const Outcome o = diff({"--json", "--heatmap", dir_ + "/heat", dir_ + "/ref", dir_ + "/test"});
  EXPECT_EQ(o.status, 2) << "unmatched names fail";  // and win over "changed" being over
  const std::vector<std::string> objects = lines(o.out);
  ASSERT_EQ(objects.size(), 4u) << o.out;  // sorted by name; notes.txt is not a PNG
  EXPECT_NE(objects[0].find("changed.png"), std::string::npos);
  EXPECT_NE(objects[0].find("\"over_threshold\":true"), std::string::npos);
  EXPECT_NE(objects[1].find("\"a\":\"" + dir_ + "/ref/only_ref.png\",\"b\":null,\"error\""),
            std::string::npos)
      << objects[1];
  EXPECT_NE(objects[2].find("\"a\":null,\"b\":\"" + dir_ + "/test/only_test.png\""),
            std::string::npos)
      << objects[2];
  EXPECT_NE(objects[3].find("same.png"), std::string::npos);
  EXPECT_NE(objects[3].find("\"over_threshold\":false"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ + "/heat/changed.png"));
  EXPECT_TRUE(fs::exists(dir_ + "/heat/same.png"));
  EXPECT_FALSE(fs::exists(dir_ + "/heat/only_ref.png"));

  EXPECT_EQ(diff({"--ignore-unmatched", dir_ + "/ref", dir_ + "/test"}).status, 1);
  fs::remove(dir_ + "/test/changed.png");
  EXPECT_EQ(diff({"--ignore-unmatched", dir_ + "/ref", dir_ + "/test"}).status, 0);
  const Outcome text = diff({dir_ + "/ref", dir_ + "/test"});
  EXPECT_NE(text.err.find("only_ref.png: no file of this name in " + dir_ + "/test"),
            std::string::npos)
      << text.err;
  EXPECT_NE(text.out.find("1 pair(s) compared, 0 over the threshold, 3 unmatched"),
            std::string::npos)
      << text.out;
}

TEST_F(DiffCommand, FileAgainstDirectory) {
  const std::string a = png("frame.png", 8, 8, 10);
  png("goldens/frame.png", 8, 8, 10);
  Outcome o = diff({"--json", a, dir_ + "/goldens"});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("\"b\":\"" + dir_ + "/goldens/frame.png\""), std::string::npos) << o.out;
  o = diff({dir_ + "/goldens", a});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(diff({png("other.png", 8, 8, 10), dir_ + "/goldens"}).status, 2);
}

TEST_F(DiffCommand, HeatmapFile) {
  const std::string a = png("a.png", 12, 10, 60), b = png("b.png", 12, 10, 60, 255);
  const std::string heat = dir_ + "/heat.png";
  ASSERT_EQ(diff({"--heatmap", heat, "--threshold", "1", a, b}).status, 0);
  ImageRGBA8 img;
  std::string error;
  ASSERT_TRUE(read_png_rgba8(heat, &img, &error)) << error;
  EXPECT_EQ(img.width, 12u);
  EXPECT_EQ(img.height, 10u);
  // The changed corner is bright, the far corner (no error) black.
  const uint8_t* corner = &img.pixels[0];
  const uint8_t* far = &img.pixels[img.pixels.size() - 4];
  EXPECT_GT(corner[0] + corner[1] + corner[2], 200);
  EXPECT_LE(far[0] + far[1] + far[2], 10);
  EXPECT_EQ(far[3], 255);
}

}  // namespace
}  // namespace glpt::cli
