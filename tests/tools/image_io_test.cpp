#include "image_io.hpp"

#include <dirent.h>
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace glpt {
namespace {

class ImageIo : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = ::testing::TempDir() + "glpt_image_io_XXXXXX";
    ASSERT_NE(mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override {
    for (const std::string& f : files()) unlink((dir_ + "/" + f).c_str());
    rmdir(dir_.c_str());
  }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    if (DIR* d = opendir(dir_.c_str())) {
      while (dirent* e = readdir(d)) {
        if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0) {
          names.push_back(e->d_name);
        }
      }
      closedir(d);
    }
    return names;
  }
  std::string dir_;
};

// A 3x2 image whose every byte is distinct, stored top row first.
std::vector<uint8_t> pattern(uint32_t w, uint32_t h) {
  std::vector<uint8_t> p(size_t{w} * h * 4);
  for (size_t i = 0; i < p.size(); ++i) p[i] = static_cast<uint8_t>(i * 7 + 3);
  return p;
}

TEST_F(ImageIo, RoundTripTopDown) {
  const auto px = pattern(3, 2);
  const std::string path = dir_ + "/a.png";
  std::string error;
  ASSERT_TRUE(write_png_rgba8(path, 3, 2, px.data(), false, &error)) << error;
  ImageRGBA8 img;
  ASSERT_TRUE(read_png_rgba8(path, &img, &error)) << error;
  EXPECT_EQ(img.width, 3u);
  EXPECT_EQ(img.height, 2u);
  EXPECT_EQ(img.pixels, px);
  EXPECT_EQ(files(), std::vector<std::string>{"a.png"});  // no temporary file left behind
}

TEST_F(ImageIo, BottomUpIsFlippedUpright) {
  const uint32_t w = 3, h = 4;
  const auto px = pattern(w, h);  // as glReadPixels returns it: row 0 = bottom
  const std::string path = dir_ + "/b.png";
  std::string error;
  ASSERT_TRUE(write_png_rgba8(path, w, h, px.data(), true, &error)) << error;
  ImageRGBA8 img;
  ASSERT_TRUE(read_png_rgba8(path, &img, &error)) << error;
  const size_t stride = size_t{w} * 4;
  for (uint32_t y = 0; y < h; ++y) {
    EXPECT_EQ(0, std::memcmp(&img.pixels[y * stride], &px[(h - 1 - y) * stride], stride))
        << "row " << y;
  }
}

TEST_F(ImageIo, OverwritesAtomically) {
  const std::string path = dir_ + "/c.png";
  const auto one = pattern(2, 2);
  std::vector<uint8_t> two(one.size(), 9);
  std::string error;
  ASSERT_TRUE(write_png_rgba8(path, 2, 2, one.data(), false, &error)) << error;
  ASSERT_TRUE(write_png_rgba8(path, 2, 2, two.data(), false, &error)) << error;
  ImageRGBA8 img;
  ASSERT_TRUE(read_png_rgba8(path, &img, &error)) << error;
  EXPECT_EQ(img.pixels, two);
  EXPECT_EQ(files(), std::vector<std::string>{"c.png"});
}

TEST_F(ImageIo, WriteErrorsAreReported) {
  const auto px = pattern(2, 2);
  std::string error;
  EXPECT_FALSE(write_png_rgba8(dir_ + "/missing/d.png", 2, 2, px.data(), false, &error));
  EXPECT_NE(error.find("missing/d.png"), std::string::npos) << error;
  EXPECT_FALSE(write_png_rgba8(dir_ + "/e.png", 0, 2, px.data(), false, &error));
  EXPECT_FALSE(write_png_rgba8(dir_ + "/e.png", 2, 2, nullptr, false, nullptr));
  EXPECT_TRUE(files().empty());
}

TEST_F(ImageIo, ReadErrorsAreReported) {
  ImageRGBA8 img;
  std::string error;
  EXPECT_FALSE(read_png_rgba8(dir_ + "/none.png", &img, &error));
  EXPECT_FALSE(error.empty());
  const std::string junk = dir_ + "/junk.png";
  FILE* f = std::fopen(junk.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  std::fputs("not a png", f);
  std::fclose(f);
  error.clear();
  EXPECT_FALSE(read_png_rgba8(junk, &img, &error));
  EXPECT_FALSE(error.empty());
}

// Writes a PNG of another colour type through libpng's simplified API.
void write_other(const std::string& path, uint32_t format, uint32_t w, uint32_t h, const void* data,
                 const void* colormap = nullptr, uint32_t colormap_entries = 0) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = w;
  image.height = h;
  image.format = format;
  image.colormap_entries = colormap_entries;
  ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, data, 0, colormap)) << image.message;
}

TEST_F(ImageIo, ReadsGreyAsRgbaOpaque) {
  const uint8_t grey[4] = {0, 85, 170, 255};
  const std::string path = dir_ + "/grey.png";
  write_other(path, PNG_FORMAT_GRAY, 2, 2, grey);
  ImageRGBA8 img;
  std::string error;
  ASSERT_TRUE(read_png_rgba8(path, &img, &error)) << error;
  ASSERT_EQ(img.pixels.size(), 16u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(img.pixels[i * 4 + 0], grey[i]);
    EXPECT_EQ(img.pixels[i * 4 + 1], grey[i]);
    EXPECT_EQ(img.pixels[i * 4 + 2], grey[i]);
    EXPECT_EQ(img.pixels[i * 4 + 3], 255);
  }
}

TEST_F(ImageIo, ReadsPaletteAsRgba) {
  const uint8_t palette[2 * 3] = {255, 0, 0, 10, 20, 30};
  const uint8_t indices[3] = {1, 0, 1};
  const std::string path = dir_ + "/palette.png";
  write_other(path, PNG_FORMAT_RGB_COLORMAP, 3, 1, indices, palette, 2);
  ImageRGBA8 img;
  std::string error;
  ASSERT_TRUE(read_png_rgba8(path, &img, &error)) << error;
  const std::vector<uint8_t> want = {10, 20, 30, 255, 255, 0, 0, 255, 10, 20, 30, 255};
  EXPECT_EQ(img.pixels, want);
}

TEST_F(ImageIo, Reads16BitEndpoints) {
  const uint16_t grey[2] = {0, 65535};
  const std::string path = dir_ + "/grey16.png";
  write_other(path, PNG_FORMAT_LINEAR_Y, 2, 1, grey);
  ImageRGBA8 img;
  std::string error;
  ASSERT_TRUE(read_png_rgba8(path, &img, &error)) << error;
  const std::vector<uint8_t> want = {0, 0, 0, 255, 255, 255, 255, 255};
  EXPECT_EQ(img.pixels, want);
}

}  // namespace
}  // namespace glpt
