// Reads apitrace traces (format version 5 and later; Snappy and Brotli containers): a stream
// of calls in the order apitrace's own parser yields them. Never trusts the file: every length
// is checked against the bytes that remain, and a trace cut at any byte ends cleanly with the
// calls read so far.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "replay/trace/trace_model.hpp"

namespace glpt::trace {

class TraceReader {
 public:
  virtual ~TraceReader() = default;

  // Opens `path`; on failure returns nullptr and says why in `error` (one line, for users).
  static std::unique_ptr<TraceReader> open(const std::string& path, std::string& error);
  // The same over bytes already in memory (the fuzzer and tests use it).
  static std::unique_ptr<TraceReader> open_memory(std::string bytes, std::string& error);

  enum class Status { Call, End, Error };
  // The next call. End: the trace ended (a truncated last call is dropped, not an error).
  // Error: corrupt input; `error` says what and where; the reader stays at End afterwards.
  virtual Status next(Call& call, std::string& error) = 0;

  virtual uint32_t version() const = 0;                                  // format version
  virtual const std::map<std::string, std::string>& properties() const = 0;  // version >= 6

  // Format versions read: 5 (call backtraces) and 6 (properties, fake-call flag; apitrace today).
  static constexpr uint32_t kMinVersion = 5;
  static constexpr uint32_t kMaxVersion = 6;
  // Bounds that a valid trace never reaches; input beyond them is reported as an Error.
  static constexpr unsigned kMaxValueDepth = 64;                  // arrays/structs/reprs nested
  static constexpr uint64_t kMaxValuesPerCall = 1u << 20;         // values, all nesting levels
  static constexpr uint64_t kMaxBytesPerCall = 512u << 20;        // string/blob bytes, one event
  static constexpr size_t kMaxPendingCalls = 4096;                // entered and not yet left
  static constexpr uint64_t kMaxPendingCallBytes = 1024u << 20;   // what those hold together
  static constexpr uint64_t kMaxMetadataBytes = 64u << 20;        // signatures, properties and
                                                                  // backtrace frames: names + 32
                                                                  // bytes a piece
};

}  // namespace glpt::trace
