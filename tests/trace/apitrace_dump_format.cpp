#include "apitrace_dump_format.hpp"

#include <iomanip>
#include <limits>
#include <sstream>

namespace glpt::trace::testing {
namespace {

// apitrace's Dumper::visitString: quotes, escapes \" and \\, drops \r, keeps \t and \n.
void dump_string(std::ostream& os, const std::string& s) {
  os << '"';
  for (unsigned char c : s) {
    if (c == '"') {
      os << "\\\"";
    } else if (c == '\\') {
      os << "\\\\";
    } else if ((c >= 0x20 && c <= 0x7e) || c == '\t' || c == '\n') {
      os << c;
    } else if (c == '\r') {
    } else {
      // apitrace prints bits 0-2 and, twice, bits 3-5, leaving out zero digits.
      unsigned low = c & 7, mid = (c >> 3) & 7;
      os << '\\';
      if (mid) os << mid << mid;
      os << low;
    }
  }
  os << '"';
}

const char* dump_members(std::ostream& os, const Value& s, const char* sep) {
  for (size_t i = 0; i < s.elements.size(); ++i) {
    const std::string& name = s.struct_sig->member_names[i];
    if (name.empty()) {  // an anonymous member: its own members are printed inline
      if (s.elements[i].kind == ValueKind::Struct) sep = dump_members(os, s.elements[i], sep);
      continue;
    }
    os << sep << name << " = ";
    dump_value(os, s.elements[i]);
    sep = ", ";
  }
  return sep;
}

}  // namespace

void dump_value(std::ostream& os, const Value& v) {
  switch (v.kind) {
    case ValueKind::Null:
      os << "NULL";
      break;
    case ValueKind::Bool:
      os << (v.boolean ? "true" : "false");
      break;
    case ValueKind::SInt:
      os << v.sint;
      break;
    case ValueKind::UInt:
      os << v.uint;
      break;
    case ValueKind::Float: {
      auto old = os.precision(std::numeric_limits<float>::digits10 + 1);
      os << static_cast<float>(v.real);
      os.precision(old);
      break;
    }
    case ValueKind::Double: {
      auto old = os.precision(std::numeric_limits<double>::digits10 + 1);
      os << v.real;
      os.precision(old);
      break;
    }
    case ValueKind::String:
      dump_string(os, v.bytes);
      break;
    case ValueKind::WString:
      os << 'L';
      dump_string(os, v.bytes);
      break;
    case ValueKind::Blob:
      os << "blob(" << v.bytes.size() << ")";
      break;
    case ValueKind::Enum: {
      for (const auto& [name, value] : v.enum_sig->values) {
        if (value == v.sint) {
          os << name;
          return;
        }
      }
      os << v.sint;
      break;
    }
    case ValueKind::Bitmask: {
      uint64_t rest = v.uint;
      bool first = true;
      for (const auto& [name, flag] : v.bitmask_sig->flags) {
        if ((flag && (rest & flag) == flag) || (!flag && rest == 0)) {
          if (!first) os << " | ";
          os << name;
          rest &= ~flag;
          first = false;
        }
        if (rest == 0) break;
      }
      if (rest || first) {
        if (!first) os << " | ";
        os << "0x" << std::hex << rest << std::dec;
      }
      break;
    }
    case ValueKind::Array:
      if (v.elements.size() == 1) {
        os << '&';
        dump_value(os, v.elements[0]);
      } else {
        os << '{';
        const char* sep = "";
        for (const Value& e : v.elements) {
          os << sep;
          dump_value(os, e);
          sep = ", ";
        }
        os << '}';
      }
      break;
    case ValueKind::Struct:
      os << '{';
      dump_members(os, v, "");
      os << '}';
      break;
    case ValueKind::Pointer:
      os << "0x" << std::hex << v.uint << std::dec;
      break;
    case ValueKind::Repr:
      dump_value(os, v.elements.at(0));
      break;
  }
}

void dump_call(std::ostream& os, const Call& call) {
  os << call.no << " @" << std::hex << call.thread << std::dec << ' ' << call.sig->name << '(';
  const char* sep = "";
  for (size_t i = 0; i < call.args.size(); ++i) {
    os << sep << call.sig->arg_names[i] << " = ";
    dump_value(os, call.args[i]);
    sep = ", ";
  }
  os << ')';
  if (call.has_ret) {
    os << " = ";
    dump_value(os, call.ret);
  }
  if ((call.flags & kCallFlagFake) || !call.complete) {
    os << " //";
    if (call.flags & kCallFlagFake) os << " fake";
    if (!call.complete) os << " incomplete";
  }
  os << '\n';
  if (call.sig->flags & kCallFlagEndFrame) os << '\n';
}

void dump_properties(std::ostream& os, const TraceReader& reader) {
  for (const auto& [name, value] : reader.properties()) {
    os << "// " << name << " = ";
    dump_string(os, value);
    os << '\n';
  }
}

std::string dump_trace(TraceReader& reader, std::string& error) {
  std::ostringstream os;
  dump_properties(os, reader);
  Call call;
  while (reader.next(call, error) == TraceReader::Status::Call) dump_call(os, call);
  return os.str();
}

}  // namespace glpt::trace::testing
