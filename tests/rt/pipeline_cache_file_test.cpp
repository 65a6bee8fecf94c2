// PipelineCacheFile: the raster pipelines' cache on disk. What it stores comes back; a file that
// is truncated, damaged, foreign or from another driver is ignored with a message (never handed
// to the driver); a directory that cannot be written gives a message, not a failure.
#include "rt_core/raster/pipeline_cache_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace glpt::rt {
namespace {

VkPhysicalDeviceProperties device(uint32_t driver_version = 7) {
  VkPhysicalDeviceProperties p{};
  p.vendorID = 0x10005;
  p.deviceID = 42;
  p.driverVersion = driver_version;
  for (uint32_t i = 0; i < VK_UUID_SIZE; ++i) p.pipelineCacheUUID[i] = static_cast<uint8_t>(i);
  return p;
}

class PipelineCacheFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/glpt-cache-test.XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    dir_ = pattern;
    path_ = dir_ + "/sub/pipelines-test.bin";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string dir_, path_;
  const std::vector<char> data_{'p', 'i', 'p', 'e', 'l', 'i', 'n', 'e', 's'};
};

TEST_F(PipelineCacheFileTest, WhatIsSavedLoadsForTheSameDeviceOnly) {
  std::string message;
  ASSERT_TRUE(PipelineCacheFile(path_, device()).save(data_, &message)) << message;
  EXPECT_EQ(PipelineCacheFile(path_, device()).load(&message), data_);
  EXPECT_TRUE(message.empty()) << message;
  // Another driver version: ignored, said once.
  EXPECT_TRUE(PipelineCacheFile(path_, device(8)).load(&message).empty());
  EXPECT_NE(message.find("another device or driver version"), std::string::npos) << message;
}

TEST_F(PipelineCacheFileTest, TruncatedDamagedAndForeignFilesAreIgnoredWithAMessage) {
  std::string message;
  ASSERT_TRUE(PipelineCacheFile(path_, device()).save(data_, &message));
  const auto size = std::filesystem::file_size(path_);
  for (uintmax_t keep : {uintmax_t{0}, uintmax_t{10}, size - 1}) {
    ASSERT_TRUE(PipelineCacheFile(path_, device()).save(data_, &message));
    std::filesystem::resize_file(path_, keep);
    message.clear();
    EXPECT_TRUE(PipelineCacheFile(path_, device()).load(&message).empty()) << keep;
    EXPECT_NE(message.find("truncated"), std::string::npos) << keep << ": " << message;
  }
  ASSERT_TRUE(PipelineCacheFile(path_, device()).save(data_, &message));
  {
    std::fstream f(path_, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(-2, std::ios::end);
    f.put('X');  // one byte of the driver's data changed
  }
  message.clear();
  EXPECT_TRUE(PipelineCacheFile(path_, device()).load(&message).empty());
  EXPECT_NE(message.find("damaged"), std::string::npos) << message;
  std::ofstream(path_, std::ios::binary | std::ios::trunc) << "the driver's own raw cache data...";
  message.clear();
  EXPECT_TRUE(PipelineCacheFile(path_, device()).load(&message).empty());
  EXPECT_NE(message.find("not glpt's"), std::string::npos) << message;
  // No file at all: nothing, and nothing to say.
  std::filesystem::remove(path_);
  message.clear();
  EXPECT_TRUE(PipelineCacheFile(path_, device()).load(&message).empty());
  EXPECT_TRUE(message.empty());
}

TEST_F(PipelineCacheFileTest, AnUnwritableDirectoryIsAMessageNotAFailure) {
  // A plain file where the directory should be: no user (root included) can create it.
  std::ofstream(dir_ + "/blocked") << "x";
  std::string message;
  EXPECT_FALSE(PipelineCacheFile(dir_ + "/blocked/pipelines.bin", device()).save(data_, &message));
  EXPECT_NE(message.find("cannot write the pipeline cache"), std::string::npos) << message;
  EXPECT_TRUE(PipelineCacheFile(dir_ + "/blocked/pipelines.bin", device()).load(&message).empty());
}

TEST_F(PipelineCacheFileTest, GlptCacheDirChoosesTheDirectory) {
  ::setenv("GLPT_CACHE_DIR", dir_.c_str(), 1);
  const std::string path = PipelineCacheFile::default_path("llvmpipe (LLVM 19)");
  ::unsetenv("GLPT_CACHE_DIR");
  EXPECT_EQ(path, dir_ + "/pipelines-llvmpipe__LLVM_19_.bin");
}

}  // namespace
}  // namespace glpt::rt
