#include "replay/trace/trace_model.hpp"

#include <cmath>
#include <limits>

namespace glpt::trace {
namespace {

// A C cast of an out-of-range double is undefined; a trace may hold any double, so saturate
// (NaN gives 0). In range it truncates toward zero, as apitrace's Double::toSInt does.
int64_t saturate_to_int64(double v) {
  if (std::isnan(v)) return 0;
  if (v >= 9223372036854775807.0) return std::numeric_limits<int64_t>::max();
  if (v <= -9223372036854775808.0) return std::numeric_limits<int64_t>::min();
  return static_cast<int64_t>(v);
}

// Negative values wrap (two's complement, as a negative integer does), large ones saturate.
uint64_t saturate_to_uint64(double v) {
  if (std::isnan(v)) return 0;
  if (v < 0) return static_cast<uint64_t>(saturate_to_int64(v));
  if (v >= 18446744073709551615.0) return std::numeric_limits<uint64_t>::max();
  return static_cast<uint64_t>(v);
}

const Value* machine_value(const Value& repr) {
  return repr.elements.size() == 2 ? &repr.elements[1] : nullptr;
}

}  // namespace

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
      return saturate_to_int64(real);
    case ValueKind::Repr:
      return machine_value(*this) ? machine_value(*this)->as_sint() : 0;
    default:
      return 0;
  }
}

uint64_t Value::as_uint() const {
  switch (kind) {
    case ValueKind::Bool:
      return boolean ? 1 : 0;
    case ValueKind::SInt:
    case ValueKind::Enum:
      return static_cast<uint64_t>(sint);
    case ValueKind::UInt:
    case ValueKind::Bitmask:
    case ValueKind::Pointer:
      return uint;
    case ValueKind::Float:
    case ValueKind::Double:
      return saturate_to_uint64(real);
    case ValueKind::Repr:
      return machine_value(*this) ? machine_value(*this)->as_uint() : 0;
    default:
      return 0;
  }
}

double Value::as_double() const {
  switch (kind) {
    case ValueKind::Bool:
      return boolean ? 1.0 : 0.0;
    case ValueKind::SInt:
    case ValueKind::Enum:
      return static_cast<double>(sint);
    case ValueKind::UInt:
    case ValueKind::Bitmask:
    case ValueKind::Pointer:
      return static_cast<double>(uint);
    case ValueKind::Float:
    case ValueKind::Double:
      return real;
    case ValueKind::Repr:
      return machine_value(*this) ? machine_value(*this)->as_double() : 0.0;
    default:
      return 0.0;
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

size_t Value::size() const { return data() ? bytes.size() : 0; }

}  // namespace glpt::trace
