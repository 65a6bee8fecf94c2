#include "rt_core/raster/pipeline_cache_file.hpp"

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/content_hash.hpp"

namespace glpt::rt {
namespace {

constexpr char kMagic[8] = {'G', 'L', 'P', 'T', 'P', 'C', 'A', 'C'};
constexpr uint32_t kFormatVersion = 1;

struct Header {
  char magic[8];
  uint32_t format_version;
  uint32_t vendor_id, device_id, driver_version;
  uint8_t cache_uuid[VK_UUID_SIZE];
  uint64_t data_size;
  uint64_t data_hash;
};
static_assert(sizeof(Header) == 8 + 4 * 4 + VK_UUID_SIZE + 16);

uint64_t hash_of(const char* data, size_t size) {
  ContentHash h;
  h.add_bytes(data, size);
  return h.value();
}

Header header_for(const VkPhysicalDeviceProperties& device) {
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.format_version = kFormatVersion;
  header.vendor_id = device.vendorID;
  header.device_id = device.deviceID;
  header.driver_version = device.driverVersion;
  std::memcpy(header.cache_uuid, device.pipelineCacheUUID, VK_UUID_SIZE);
  return header;
}

}  // namespace

PipelineCacheFile::PipelineCacheFile(std::string path, const VkPhysicalDeviceProperties& device)
    : path_(std::move(path)), device_(device) {}

std::string PipelineCacheFile::default_path(const std::string& device_name) {
  std::filesystem::path dir;
  if (const char* own = std::getenv("GLPT_CACHE_DIR"); own && *own)
    dir = own;
  else if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    dir = std::filesystem::path(xdg) / "glpt";
  else if (const char* home = std::getenv("HOME"); home && *home)
    dir = std::filesystem::path(home) / ".cache" / "glpt";
  else
    return {};
  std::string name = "pipelines-";
  for (char c : device_name) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return (dir / (name + ".bin")).string();
}

std::vector<char> PipelineCacheFile::load(std::string* message) const {
  if (path_.empty()) return {};
  std::ifstream in(path_, std::ios::binary);
  if (!in) return {};  // no cache yet
  std::vector<char> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto reject = [&](const char* why) {
    if (message) *message = "pipeline cache " + path_ + " " + why + ": ignored (rewritten)";
    return std::vector<char>();
  };
  if (file.size() >= sizeof kMagic && std::memcmp(file.data(), kMagic, sizeof kMagic) != 0)
    return reject("is not glpt's");
  Header header;
  if (file.size() < sizeof header) return reject("is truncated");
  std::memcpy(&header, file.data(), sizeof header);
  const Header expected = header_for(device_);
  if (header.format_version != kFormatVersion) return reject("has another format version");
  if (header.vendor_id != expected.vendor_id || header.device_id != expected.device_id ||
      header.driver_version != expected.driver_version ||
      std::memcmp(header.cache_uuid, expected.cache_uuid, VK_UUID_SIZE) != 0)
    return reject("is from another device or driver version");
  if (header.data_size != file.size() - sizeof header) return reject("is truncated");
  const char* data = file.data() + sizeof header;
  if (hash_of(data, header.data_size) != header.data_hash) return reject("is damaged");
  return std::vector<char>(data, data + header.data_size);
}

bool PipelineCacheFile::save(const std::vector<char>& data, std::string* message) const {
  if (path_.empty()) return true;
  Header header = header_for(device_);
  header.data_size = data.size();
  header.data_hash = hash_of(data.data(), data.size());
  auto fail = [&](const std::string& why) {
    if (message)
      *message = "cannot write the pipeline cache " + path_ + " (" + why +
                 "): the next run compiles its pipelines again";
    return false;
  };
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path_).parent_path(), ec);
  if (ec) return fail(ec.message());
  // A temporary name per process, renamed over the file: readers never see half a file.
  const std::string temporary = path_ + "." + std::to_string(::getpid()) + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return fail(std::strerror(errno));
    out.write(reinterpret_cast<const char*>(&header), sizeof header);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    out.flush();
    if (!out) {
      std::filesystem::remove(temporary, ec);
      return fail("write failed: disk full?");
    }
  }
  std::filesystem::rename(temporary, path_, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(temporary, ec);
    return fail(why);
  }
  return true;
}

}  // namespace glpt::rt
