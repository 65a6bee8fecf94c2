// Times glpt's apitrace reader over one trace: opens it, reads every call and reads each argument
// through the numeric views (as the replayer will), best of --repeat runs.
//   glpt_trace_bench TRACE [--repeat N]
// Prints calls, file size, seconds, calls/s and MB/s (of the file as stored).
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "replay/trace/trace_reader.hpp"

namespace {

struct Run {
  uint64_t calls = 0;
  uint64_t payload = 0;  // keeps the argument reads from being optimized away
  double seconds = 0;
};

bool read_trace(const char* path, Run& run) {
  auto start = std::chrono::steady_clock::now();
  std::string error;
  auto reader = glpt::trace::TraceReader::open(path, error);
  if (!reader) {
    std::fprintf(stderr, "glpt_trace_bench: %s\n", error.c_str());
    return false;
  }
  glpt::trace::Call call;
  glpt::trace::TraceReader::Status status;
  while ((status = reader->next(call, error)) == glpt::trace::TraceReader::Status::Call) {
    ++run.calls;
    for (const auto& arg : call.args) run.payload += arg.as_uint() + arg.size();
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status == glpt::trace::TraceReader::Status::Error) {
    std::fprintf(stderr, "glpt_trace_bench: %s: %s\n", path, error.c_str());
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && !(argc == 4 && std::strcmp(argv[2], "--repeat") == 0)) {
    std::fprintf(stderr, "usage: glpt_trace_bench TRACE [--repeat N]\n");
    return 2;
  }
  int repeat = argc == 4 ? std::max(1, std::atoi(argv[3])) : 1;
  struct stat info {};
  if (stat(argv[1], &info) != 0) {
    std::perror(argv[1]);
    return 1;
  }
  Run best;
  for (int i = 0; i < repeat; ++i) {
    Run run;
    if (!read_trace(argv[1], run)) return 1;
    if (i == 0 || run.seconds < best.seconds) best = run;
  }
  double mb = double(info.st_size) / 1e6;
  std::printf("calls %llu  file %.1f MB  best of %d: %.3f s  %.2f Mcalls/s  %.1f MB/s  (%llu)\n",
              (unsigned long long)best.calls, mb, repeat, best.seconds,
              double(best.calls) / best.seconds / 1e6, mb / best.seconds,
              (unsigned long long)(best.payload & 0xff));
  return 0;
}
