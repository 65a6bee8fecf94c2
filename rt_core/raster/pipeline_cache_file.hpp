// The raster pipelines' VkPipelineCache on disk, so a program's second run compiles nothing:
// $GLPT_CACHE_DIR, else $XDG_CACHE_HOME/glpt, else ~/.cache/glpt, one file per device
// (pipelines-<device name>.bin).
//
// The file is glpt's header (magic, format version, the device's vendor, device and driver ids
// and pipeline cache UUID, the data's size and hash) and the driver's cache data. A file that is
// truncated, damaged, of another format or from another device or driver version is ignored
// with one message (the driver never sees it); the cache starts empty and is written anew.
// Writes go to a temporary file renamed over the old one, so processes writing at once never
// leave half a file; a directory that cannot be written (read-only, full) costs one message and
// the next run compiles again.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace glpt::rt {

class PipelineCacheFile {
 public:
  // `path` empty: no cache on disk (no directory known).
  PipelineCacheFile(std::string path, const VkPhysicalDeviceProperties& device);
  // The path for `device_name` from the environment (above); empty when none is known.
  static std::string default_path(const std::string& device_name);

  // The driver's cache data stored for this device, or nothing (absent, or rejected: then
  // *message says why, once).
  std::vector<char> load(std::string* message) const;
  // Stores `data`; false and *message when it cannot be written.
  bool save(const std::vector<char>& data, std::string* message) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  VkPhysicalDeviceProperties device_;
};

}  // namespace glpt::rt
