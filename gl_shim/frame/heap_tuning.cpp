#include "gl_shim/frame/heap_tuning.hpp"

#include <malloc.h>

#include <cstdlib>
#include <cstring>
#include <mutex>

namespace glpt {
namespace {

constexpr int kMmapThreshold = 32 << 20;  // glibc's DEFAULT_MMAP_THRESHOLD_MAX on 64-bit
constexpr int kTrimThreshold = 2 * kMmapThreshold;

bool user_chose_malloc_settings() {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables != nullptr && std::strstr(tunables, "glibc.malloc.") != nullptr) return true;
  for (const char* name :
       {"MALLOC_TRIM_THRESHOLD_", "MALLOC_MMAP_THRESHOLD_", "MALLOC_TOP_PAD_", "MALLOC_MMAP_MAX_"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

bool apply() {
  const char* setting = std::getenv("GLPT_HEAP_TUNING");
  if (setting != nullptr && std::strcmp(setting, "0") == 0) return false;
  if (user_chose_malloc_settings()) return false;
  // mallopt returns 1 on success; an allocator that is not glibc's (a sanitizer's, jemalloc
  // preloaded) ignores it or refuses, which is fine.
  return mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1 &&
         mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1;
}

}  // namespace

bool tune_heap_for_rendering() {
  static std::once_flag once;
  static bool applied = false;
  std::call_once(once, [] { applied = apply(); });
  return applied;
}

}  // namespace glpt
