// Builds trace::Calls by hand, as the trace reader would produce them, for the replayer's tests.
#pragma once

#include <deque>
#include <initializer_list>
#include <string>
#include <vector>

#include "replay/trace/trace_model.hpp"

namespace glpt_test {

namespace trace = glpt::trace;

inline trace::Value sint(int64_t v) {
  trace::Value value;
  value.kind = trace::ValueKind::SInt;
  value.sint = v;
  return value;
}
inline trace::Value uintv(uint64_t v) {
  trace::Value value;
  value.kind = trace::ValueKind::UInt;
  value.uint = v;
  return value;
}
inline trace::Value enumv(int64_t v) {
  trace::Value value = sint(v);
  value.kind = trace::ValueKind::Enum;
  return value;
}
inline trace::Value real(double v) {
  trace::Value value;
  value.kind = trace::ValueKind::Float;
  value.real = v;
  return value;
}
inline trace::Value pointer(uint64_t address) {
  trace::Value value = uintv(address);
  value.kind = trace::ValueKind::Pointer;
  return value;
}
inline trace::Value null() { return trace::Value(); }
inline trace::Value blob(const void* data, size_t size) {
  trace::Value value;
  value.kind = trace::ValueKind::Blob;
  value.bytes.assign(static_cast<const char*>(data), size);
  return value;
}
inline trace::Value array(std::initializer_list<trace::Value> elements) {
  trace::Value value;
  value.kind = trace::ValueKind::Array;
  value.elements = elements;
  return value;
}
inline trace::Value reals(std::initializer_list<double> values) {
  trace::Value value;
  value.kind = trace::ValueKind::Array;
  for (double v : values) value.elements.push_back(real(v));
  return value;
}
inline trace::Value ints(std::initializer_list<int64_t> values) {
  trace::Value value;
  value.kind = trace::ValueKind::Array;
  for (int64_t v : values) value.elements.push_back(sint(v));
  return value;
}

// Owns the function signatures the calls point to.
class CallBuilder {
 public:
  trace::Call call(const std::string& name, std::vector<trace::Value> args,
                   trace::Value ret = trace::Value()) {
    trace::Call c;
    c.no = next_no_++;
    c.sig = &sig(name);
    c.args = std::move(args);
    c.ret = std::move(ret);
    c.complete = true;
    return c;
  }

 private:
  const trace::FunctionSig& sig(const std::string& name) {
    for (const trace::FunctionSig& s : sigs_)
      if (s.name == name) return s;
    trace::FunctionSig& s = sigs_.emplace_back();
    s.id = static_cast<uint32_t>(sigs_.size() - 1);
    s.name = name;
    // As the reader flags them (trace_model.hpp): the swaps end frames.
    if (name.find("SwapBuffers") != std::string::npos)
      s.flags = trace::kCallFlagSwapRenderTarget | trace::kCallFlagEndFrame;
    return s;
  }
  std::deque<trace::FunctionSig> sigs_;
  uint32_t next_no_ = 0;
};

}  // namespace glpt_test
