// Stand-in for the trace reader until replay/trace/ has one: the Value views the replayer uses,
// and a reader that cannot open anything. Built only when replay/trace/ provides no library.
#include <cstring>

#include "replay/trace/trace_reader.hpp"

namespace glpt::trace {

int64_t Value::as_sint() const {
  switch (kind) {
    case ValueKind::Bool:
      return boolean ? 1 : 0;
    case ValueKind::SInt:
    case ValueKind::Enum:
      return sint;
    case ValueKind::UInt:
    case ValueKind::Bitmask:
    case ValueKind::Pointer:
      return static_cast<int64_t>(uint);
    case ValueKind::Float:
    case ValueKind::Double:
      return static_cast<int64_t>(real);
    case ValueKind::Repr:
      return elements.size() > 1 ? elements[1].as_sint() : 0;
    default:
      return 0;
  }
}

uint64_t Value::as_uint() const {
  switch (kind) {
    case ValueKind::SInt:
    case ValueKind::Enum:
      return static_cast<uint64_t>(sint);
    case ValueKind::Float:
    case ValueKind::Double:
      return static_cast<uint64_t>(static_cast<int64_t>(real));
    case ValueKind::Repr:
      return elements.size() > 1 ? elements[1].as_uint() : 0;
    default:
      return static_cast<uint64_t>(as_sint());
  }
}

double Value::as_double() const {
  switch (kind) {
    case ValueKind::Float:
    case ValueKind::Double:
      return real;
    case ValueKind::UInt:
    case ValueKind::Bitmask:
    case ValueKind::Pointer:
      return static_cast<double>(uint);
    case ValueKind::Repr:
      return elements.size() > 1 ? elements[1].as_double() : 0;
    default:
      return static_cast<double>(as_sint());
  }
}

const void* Value::data() const {
  switch (kind) {
    case ValueKind::String:
    case ValueKind::WString:
    case ValueKind::Blob:
      return bytes.data();
    default:
      return nullptr;
  }
}

size_t Value::size() const { return data() != nullptr ? bytes.size() : 0; }

std::unique_ptr<TraceReader> TraceReader::open(const std::string&, std::string& error) {
  error = "this build has no trace reader yet";
  return nullptr;
}

std::unique_ptr<TraceReader> TraceReader::open_memory(std::string, std::string& error) {
  error = "this build has no trace reader yet";
  return nullptr;
}

}  // namespace glpt::trace
