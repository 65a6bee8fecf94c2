// The in-memory form of an apitrace trace: function signatures, values and calls, as the
// trace reader (trace_reader.hpp) produces them and the replayer (replay/) consumes them.
// Mirrors apitrace's docs/FORMAT.markdown; names follow it. This header is the contract
// between the reader and the replayer: change it only additively.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace glpt::trace {

struct EnumSig {
  uint32_t id = 0;
  std::vector<std::pair<std::string, int64_t>> values;  // name, value
};
struct BitmaskSig {
  uint32_t id = 0;
  std::vector<std::pair<std::string, uint64_t>> flags;
};
struct StructSig {
  uint32_t id = 0;
  std::string name;
  std::vector<std::string> member_names;
};
struct FunctionSig {
  uint32_t id = 0;
  std::string name;                    // "glVertex3f", "glXSwapBuffers", "memcpy", ...
  std::vector<std::string> arg_names;  // as recorded
  uint32_t flags = 0;                  // apitrace's call flags if known (fake, swap, ...); 0 else
};

enum class ValueKind : uint8_t {
  Null,
  Bool,
  SInt,
  UInt,
  Float,
  Double,
  String,   // bytes (NUL not included)
  WString,  // converted to UTF-8 in `bytes`
  Blob,     // bytes
  Enum,     // `sint`, with `enum_sig`
  Bitmask,  // `uint`, with `bitmask_sig`
  Array,    // `elements`
  Struct,   // `elements`, with `struct_sig`
  Pointer,  // opaque pointer value recorded by the tracer: `uint`
  Repr,     // `elements` = {human-readable value, machine value}
};

struct Value {
  ValueKind kind = ValueKind::Null;
  bool boolean = false;
  int64_t sint = 0;
  uint64_t uint = 0;
  double real = 0;  // Float and Double (a Float is stored widened; narrowing gives it back exactly)
  std::string bytes;
  std::vector<Value> elements;
  const EnumSig* enum_sig = nullptr;
  const BitmaskSig* bitmask_sig = nullptr;
  const StructSig* struct_sig = nullptr;

  // Numeric views used by the replayer; each converts any numeric kind (Bool, SInt, UInt, Float,
  // Double, Enum, Bitmask, Pointer; Repr uses its machine value) and gives 0 for other kinds.
  int64_t as_sint() const;
  uint64_t as_uint() const;
  double as_double() const;
  // Bytes of a String/WString/Blob; nullptr for Null and any other kind.
  const void* data() const;
  size_t size() const;
};

struct Call {
  uint32_t no = 0;      // call number, as apitrace numbers them (glretrace -D CALL uses it)
  uint32_t thread = 0;  // recording thread id (0 = main)
  const FunctionSig* sig = nullptr;
  std::vector<Value> args;  // by position; missing arguments are Null
  Value ret;                // Null when the call returns nothing or had no LEAVE event
  bool complete = false;    // both ENTER and LEAVE events were read
  uint32_t flags = 0;       // per-call flags recorded in the trace: kCallFlagFake
  bool has_ret = false;     // a return value was recorded (`ret` may still be a Null pointer)
};

// Flag bits, with apitrace's values (its trace_model.hpp, CALL_FLAG_*).
// Call::flags: the tracer emitted this call itself to record state the application had set up
// before tracing began or in a way the tracer cannot see; it is replayed like any other call.
inline constexpr uint32_t kCallFlagFake = 1u << 0;
// FunctionSig::flags, set by the reader from the function's name for the GL-family calls that
// present a frame (glXSwapBuffers, eglSwapBuffers*, wglSwap*Buffers, CGLFlushDrawable,
// glFrameTerminatorGREMEDY): the call swaps the render target and/or ends a frame.
inline constexpr uint32_t kCallFlagSwapRenderTarget = 1u << 4;
inline constexpr uint32_t kCallFlagEndFrame = 1u << 5;

}  // namespace glpt::trace
