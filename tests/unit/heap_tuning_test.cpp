// glibc's heap thresholds once a process renders (gl_shim/frame/heap_tuning.hpp): a 16 MiB block
// then comes from the heap (no mapping of its own, so its pages stay mapped after free), unless
// GLPT_HEAP_TUNING=0 or the user set malloc tunables. Each case runs in a child process: the
// thresholds are the process's and are applied once.
#include "gl_shim/frame/heap_tuning.hpp"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kGlibcAllocator = false;  // the sanitizer's allocator ignores mallopt
#else
constexpr bool kGlibcAllocator = true;
#endif

// Whether a fresh 16 MiB block gets a mapping of its own (glibc's mmap threshold below it).
bool large_block_is_mapped() {
  const size_t mapped_before = mallinfo2().hblks;
  void* block = std::malloc(size_t{16} << 20);
  asm volatile("" : : "r"(block) : "memory");  // the allocation is not elided
  const bool mapped = mallinfo2().hblks > mapped_before;
  std::free(block);
  return mapped;
}

TEST(HeapTuning, LargeBlocksComeFromTheHeapOnceAProcessRenders) {
  if (!kGlibcAllocator) GTEST_SKIP() << "not glibc's allocator";
  EXPECT_EXIT(
      {
        unsetenv("GLPT_HEAP_TUNING");
        unsetenv("GLIBC_TUNABLES");
        const bool mapped_before = large_block_is_mapped();
        const bool applied = glpt::tune_heap_for_rendering();
        const bool again = glpt::tune_heap_for_rendering();
        std::exit(mapped_before && applied && again && !large_block_is_mapped() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(HeapTuning, OptOutAndUserSettingsKeepGlibcsDefaults) {
  if (!kGlibcAllocator) GTEST_SKIP() << "not glibc's allocator";
  EXPECT_EXIT(
      {
        setenv("GLPT_HEAP_TUNING", "0", 1);
        const bool applied = glpt::tune_heap_for_rendering();
        std::exit(!applied && large_block_is_mapped() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EXIT(
      {
        unsetenv("GLPT_HEAP_TUNING");
        setenv("MALLOC_TRIM_THRESHOLD_", "131072", 1);
        std::exit(!glpt::tune_heap_for_rendering() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EXIT(
      {
        unsetenv("GLPT_HEAP_TUNING");
        setenv("GLIBC_TUNABLES", "glibc.malloc.check=0", 1);
        std::exit(!glpt::tune_heap_for_rendering() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
