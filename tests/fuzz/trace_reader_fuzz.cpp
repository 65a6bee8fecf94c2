// libFuzzer target: any bytes through TraceReader::open_memory and next() to the end. Built with
// clang's -fsanitize=fuzzer,address,undefined by build_trace_fuzzer.sh; run briefly by ctest
// (trace.fuzz) from the seed corpus in trace_corpus/.
#include <cstddef>
#include <cstdint>
#include <string>

#include "replay/trace/trace_reader.hpp"

namespace {

// Reads every value the way the replayer will, so the views run on whatever the parser built.
uint64_t touch(const glpt::trace::Value& value) {
  uint64_t sum = uint64_t(value.as_sint()) + value.as_uint() + uint64_t(value.as_double() != 0);
  sum += value.size() + (value.data() != nullptr);
  for (const auto& element : value.elements) sum += touch(element);
  return sum;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string error;
  auto reader = glpt::trace::TraceReader::open_memory(
      std::string(reinterpret_cast<const char*>(data), size), error);
  if (!reader) return 0;
  glpt::trace::Call call;
  uint64_t sink = 0;
  while (reader->next(call, error) == glpt::trace::TraceReader::Status::Call) {
    sink += call.no + call.sig->name.size() + touch(call.ret);
    for (const auto& arg : call.args) sink += touch(arg);
  }
  // After End or Error the reader stays at End.
  if (reader->next(call, error) != glpt::trace::TraceReader::Status::End) __builtin_trap();
  return sink == 42 ? 0 : 0;
}
