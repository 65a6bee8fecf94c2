// glibc's heap thresholds for a process that renders with glpt.
//
// Lavapipe (and Mesa's llvmpipe alike) allocate a frame's binned triangles in 64 KiB blocks, tens
// of megabytes per frame for 100 000 small triangles, and free them when the frame is done. With
// glibc's initial thresholds the heap top is then given back to the kernel (trim) and the next
// frame faults every page in again: ~5 900 page faults, ~10 ms of CPU per such frame on the
// development machine (docs/performance.md). The first context that renders therefore sets the
// thresholds glibc's own adaptive rule reaches after freeing a 32 MiB block (M_MMAP_THRESHOLD
// 32 MiB, M_TRIM_THRESHOLD 64 MiB, glibc's DEFAULT_MMAP_THRESHOLD_MAX and twice it): free memory
// at the top of a heap is kept for reuse up to 64 MiB per arena, and blocks below 32 MiB come
// from the heap instead of their own mapping. The settings are the process's (they apply to the
// program's own allocations too); GLPT_HEAP_TUNING=0 leaves glibc's defaults, and a program or
// user that set any malloc tunable (GLIBC_TUNABLES, MALLOC_*_ variables) keeps its choice.
#pragma once

namespace glpt {

// Applies the thresholds once per process (later calls do nothing). Returns whether they were
// applied by this or an earlier call.
bool tune_heap_for_rendering();

}  // namespace glpt
