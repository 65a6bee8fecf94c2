// The apitrace stream parser (apitrace's docs/FORMAT.markdown, "Grammar"), over the uncompressed
// stream that trace_container.cpp produces. Calls come out in the order apitrace's
// trace::Parser::parse_call gives them: a call when its LEAVE event is read; at the end of the
// stream, the calls that entered and never left, in the order they entered, as incomplete.
//
// The file is never trusted: nothing is allocated for a declared count before the bytes behind
// it have been read (strings grow as their bytes arrive, arrays as their elements parse), value
// nesting and the number of values per call are bounded, and every loop consumes input. The
// parser stops at the first byte it cannot make sense of and says what and where.
#include "replay/trace/trace_reader.hpp"

#include <cstring>
#include <deque>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "replay/trace/trace_container.hpp"

namespace glpt::trace {
namespace {

using detail::Decompressor;

// The uncompressed stream ended inside an event: the event's call is dropped, as apitrace does.
struct EndOfStream {};
// Corrupt input. `offset` is in the uncompressed stream; a container error has its message
// complete (with a file offset) and `in_container` set.
struct Corrupt {
  std::string what;
  uint64_t offset = 0;
  bool in_container = false;
};

// Event, call detail and value tags (FORMAT.markdown).
enum : uint8_t { kEventEnter = 0, kEventLeave = 1 };
enum : uint8_t {
  kDetailEnd = 0,
  kDetailArg = 1,
  kDetailRet = 2,
  kDetailBacktrace = 4,
  kDetailFlags = 5,
};
enum : uint8_t {
  kTypeNull = 0,
  kTypeFalse,
  kTypeTrue,
  kTypeSInt,
  kTypeUInt,
  kTypeFloat,
  kTypeDouble,
  kTypeString,
  kTypeBlob,
  kTypeEnum,
  kTypeBitmask,
  kTypeArray,
  kTypeStruct,
  kTypeOpaque,
  kTypeRepr,
  kTypeWString,
};
constexpr uint64_t kTraceFlagFake = 1;  // the CALL_FLAGS detail's bit for a fake call

std::string hex_byte(uint8_t b) {
  static const char kDigits[] = "0123456789abcdef";
  return std::string("0x") + kDigits[b >> 4] + kDigits[b & 15];
}

// Reads the uncompressed stream a block at a time.
class Cursor {
 public:
  explicit Cursor(Decompressor& source) : source_(source) {}

  // True when the stream has no more bytes (tried to fetch more first).
  bool at_end() { return cur_ == end_ && !fill(); }
  uint64_t offset() const { return base_ + uint64_t(cur_ - begin_); }

  uint8_t byte() {
    if (cur_ == end_ && !fill()) throw EndOfStream{};
    return uint8_t(*cur_++);
  }

  // apitrace's `uint`: 7 bits a byte, least significant first, at most 64 bits.
  uint64_t varint() {
    uint64_t start = offset();
    uint64_t value = 0;
    for (unsigned i = 0; i < 10; ++i) {
      uint8_t b = byte();
      if (i == 9 && (b & 0x7e)) throw Corrupt{"integer wider than 64 bits", start};
      value |= uint64_t(b & 0x7f) << (7 * i);
      if (!(b & 0x80)) return value;
    }
    throw Corrupt{"integer longer than 10 bytes", start};
  }

  // Appends `n` bytes to `out` as they arrive, so a hostile `n` costs only the bytes that exist.
  void append(uint64_t n, std::string& out) {
    while (n > 0) {
      if (cur_ == end_ && !fill()) throw EndOfStream{};
      size_t take = size_t(std::min<uint64_t>(n, uint64_t(end_ - cur_)));
      out.append(cur_, take);
      cur_ += take;
      n -= take;
    }
  }

  void skip(uint64_t n) {
    while (n > 0) {
      if (cur_ == end_ && !fill()) throw EndOfStream{};
      size_t take = size_t(std::min<uint64_t>(n, uint64_t(end_ - cur_)));
      cur_ += take;
      n -= take;
    }
  }

  template <typename T>
  T scalar() {  // float or double, little endian (as apitrace writes them on x86)
    unsigned char raw[sizeof(T)];
    if (end_ - cur_ >= ptrdiff_t(sizeof(T))) {
      std::memcpy(raw, cur_, sizeof(T));
      cur_ += sizeof(T);
    } else {
      for (auto& b : raw) b = byte();
    }
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

 private:
  bool fill() {
    if (ended_) return false;
    base_ += uint64_t(end_ - begin_);
    begin_ = cur_ = end_ = nullptr;
    std::string_view block;
    std::string error;
    switch (source_.next_block(block, error)) {
      case Decompressor::Result::Block:
        begin_ = cur_ = block.data();
        end_ = block.data() + block.size();
        return true;
      case Decompressor::Result::End:
        ended_ = true;
        return false;
      case Decompressor::Result::Error:
        ended_ = true;
        throw Corrupt{error, offset(), true};
    }
    return false;
  }

  Decompressor& source_;
  const char* begin_ = nullptr;
  const char* cur_ = nullptr;
  const char* end_ = nullptr;
  uint64_t base_ = 0;  // stream offset of begin_
  bool ended_ = false;
};

// Signatures by id: ids are small and dense in traces apitrace writes; a hostile id goes to the
// map instead of sizing a vector.
template <typename Sig>
class SigTable {
 public:
  const Sig* find(uint64_t id) const {
    if (id < dense_.size()) return dense_[id].get();
    if (id < kDenseLimit) return nullptr;
    auto it = sparse_.find(id);
    return it == sparse_.end() ? nullptr : it->second.get();
  }
  const Sig* add(uint64_t id, std::unique_ptr<Sig> sig) {
    const Sig* stored = sig.get();
    if (id < kDenseLimit) {
      if (id >= dense_.size()) dense_.resize(id + 1);
      dense_[id] = std::move(sig);
    } else {
      sparse_[id] = std::move(sig);
    }
    return stored;
  }

 private:
  static constexpr uint64_t kDenseLimit = 1u << 16;
  std::vector<std::unique_ptr<Sig>> dense_;
  std::unordered_map<uint64_t, std::unique_ptr<Sig>> sparse_;
};

uint32_t frame_flags_for(const std::string& name) {
  constexpr uint32_t kSwap = kCallFlagSwapRenderTarget | kCallFlagEndFrame;
  static const std::pair<const char*, uint32_t> kFrameCalls[] = {
      {"glXSwapBuffers", kSwap},
      {"glXSwapBuffersMscOML", kSwap},
      {"eglSwapBuffers", kSwap},
      {"eglSwapBuffersWithDamageEXT", kSwap},
      {"eglSwapBuffersWithDamageKHR", kSwap},
      {"wglSwapBuffers", kSwap},
      {"wglSwapLayerBuffers", kSwap},
      {"wglSwapMultipleBuffers", kSwap},
      {"CGLFlushDrawable", kCallFlagEndFrame},
      {"glFrameTerminatorGREMEDY", kCallFlagEndFrame},
  };
  for (const auto& [call, flags] : kFrameCalls) {
    if (name == call) return flags;
  }
  return 0;
}

void append_utf8(uint64_t code, std::string& out) {
  if (code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) code = 0xfffd;  // not a character
  if (code < 0x80) {
    out += char(code);
  } else if (code < 0x800) {
    out += char(0xc0 | (code >> 6));
    out += char(0x80 | (code & 0x3f));
  } else if (code < 0x10000) {
    out += char(0xe0 | (code >> 12));
    out += char(0x80 | ((code >> 6) & 0x3f));
    out += char(0x80 | (code & 0x3f));
  } else {
    out += char(0xf0 | (code >> 18));
    out += char(0x80 | ((code >> 12) & 0x3f));
    out += char(0x80 | ((code >> 6) & 0x3f));
    out += char(0x80 | (code & 0x3f));
  }
}

class ApitraceReader final : public TraceReader {
 public:
  explicit ApitraceReader(std::unique_ptr<Decompressor> source)
      : source_(std::move(source)), in_(*source_) {}

  bool read_header(std::string& error) {
    try {
      version_ = narrow_u32(in_.varint(), "format version");
      if (version_ < kMinVersion) {
        error = "trace format version " + std::to_string(version_) +
                " is too old (glpt reads version " + std::to_string(kMinVersion) +
                " and later; re-record it with a newer apitrace)";
        return false;
      }
      if (version_ > kMaxVersion) {
        error = "trace format version " + std::to_string(version_) +
                " is newer than this reader knows (" + std::to_string(kMaxVersion) + ")";
        return false;
      }
      if (version_ >= 6) {
        uint64_t semantic = in_.varint();
        if (semantic > version_) {
          error = "trace semantic version " + std::to_string(semantic) +
                  " is above its format version " + std::to_string(version_);
          return false;
        }
        for (;;) {
          std::string name = name_string();
          if (name.empty()) break;
          properties_[name] = name_string();
        }
      }
      in_header_ = false;
      return true;
    } catch (const EndOfStream&) {
      error = "the trace ends inside its header";
    } catch (const Corrupt& corrupt) {
      error = describe(corrupt);
    }
    return false;
  }

  Status next(Call& call, std::string& error) override {
    if (finished_) return Status::End;
    try {
      while (!stream_ended_) {
        if (in_.at_end()) {
          stream_ended_ = true;
          break;
        }
        uint8_t event = in_.byte();
        if (event == kEventEnter) {
          parse_enter();
        } else if (event == kEventLeave) {
          if (parse_leave(call)) return Status::Call;
        } else {
          context_no_ = -1;
          throw Corrupt{"unknown event " + hex_byte(event), in_.offset() - 1};
        }
      }
    } catch (const EndOfStream&) {
      stream_ended_ = true;  // the event being read is dropped
    } catch (const Corrupt& corrupt) {
      error = describe(corrupt);
      finished_ = true;
      pending_.clear();
      pending_cost_ = 0;
      return Status::Error;
    }
    // The stream ended: calls that entered and never left come out as they are.
    if (!pending_.empty()) {
      call = std::move(pending_.front().call);
      pending_cost_ -= pending_.front().cost;
      pending_.pop_front();
      call.complete = false;
      return Status::Call;
    }
    finished_ = true;
    return Status::End;
  }

  uint32_t version() const override { return version_; }
  const std::map<std::string, std::string>& properties() const override { return properties_; }

 private:
  std::string describe(const Corrupt& corrupt) const {
    if (corrupt.in_container) return corrupt.what;
    std::string where = corrupt.what + " at uncompressed offset " + std::to_string(corrupt.offset);
    if (context_no_ >= 0) {
      where += " in call " + std::to_string(context_no_);
      if (context_sig_) where += " (" + context_sig_->name + ")";
    } else if (in_header_) {
      where += " in the header";
    }
    return where;
  }

  uint32_t narrow_u32(uint64_t v, const char* what) {
    if (v > UINT32_MAX) throw Corrupt{std::string(what) + " too large", in_.offset()};
    return uint32_t(v);
  }

  // Signatures, properties and frames are kept for the reader's life: bounded all together.
  void charge_metadata(uint64_t bytes) {
    if (bytes > kMaxMetadataBytes - metadata_bytes_) {
      throw Corrupt{
          "signatures and properties above " + std::to_string(kMaxMetadataBytes >> 20) + " MiB",
          in_.offset()};
    }
    metadata_bytes_ += bytes;
  }
  static constexpr uint64_t kMetadataEntryCost = 32;

  // A name in a signature or a property.
  std::string name_string() {
    uint64_t length = in_.varint();
    charge_metadata(length + kMetadataEntryCost);
    std::string s;
    in_.append(length, s);
    return s;
  }

  // A String or Blob value's bytes, bounded per call.
  void value_bytes(uint64_t length, std::string& out) {
    if (length > kMaxBytesPerCall - bytes_in_event_) {
      throw Corrupt{"more than " + std::to_string(kMaxBytesPerCall >> 20) +
                        " MiB of strings and blobs in one call",
                    in_.offset()};
    }
    bytes_in_event_ += length;
    in_.append(length, out);
  }

  void parse_enter() {
    uint32_t thread = uint32_t(in_.varint());  // apitrace keeps the low bits too
    context_no_ = next_call_no_;
    context_sig_ = nullptr;
    const FunctionSig* sig = function_sig();
    context_sig_ = sig;
    if (pending_.size() >= kMaxPendingCalls) {
      throw Corrupt{
          "more than " + std::to_string(kMaxPendingCalls) + " calls entered without leaving",
          in_.offset()};
    }
    Call call;
    call.no = next_call_no_++;
    call.thread = thread;
    call.sig = sig;
    call.args.resize(sig->arg_names.size());
    values_in_event_ = 0;
    bytes_in_event_ = 0;
    parse_details(call, false);
    // What a call waiting for its LEAVE holds, bounded over all of them (each event is bounded by
    // itself, but up to kMaxPendingCalls of them can wait).
    uint64_t cost = bytes_in_event_ + values_in_event_ * sizeof(Value);
    if (cost > kMaxPendingCallBytes - pending_cost_) {
      throw Corrupt{"calls entered without leaving hold more than " +
                        std::to_string(kMaxPendingCallBytes >> 20) + " MiB",
                    in_.offset()};
    }
    pending_cost_ += cost;
    pending_.push_back({std::move(call), cost});
  }

  bool parse_leave(Call& out) {
    uint64_t no = in_.varint();
    context_no_ = int64_t(no);
    context_sig_ = nullptr;
    values_in_event_ = 0;
    bytes_in_event_ = 0;
    auto it = pending_.begin();
    while (it != pending_.end() && it->call.no != no) ++it;
    if (it == pending_.end()) {
      // apitrace skips the details of a LEAVE with no ENTER and yields nothing.
      Call stray;
      parse_details(stray, true);
      return false;
    }
    Call call = std::move(it->call);
    pending_cost_ -= it->cost;
    pending_.erase(it);
    context_sig_ = call.sig;
    parse_details(call, false);  // the stream ending here drops the call, as in apitrace
    call.complete = true;
    out = std::move(call);
    return true;
  }

  void parse_details(Call& call, bool discard) {
    for (;;) {
      uint8_t detail = in_.byte();
      switch (detail) {
        case kDetailEnd:
          return;
        case kDetailArg: {
          uint64_t index_offset = in_.offset();
          uint64_t index = in_.varint();
          Value value;
          parse_value(value, 0);
          if (discard) break;
          if (index >= call.args.size()) {
            throw Corrupt{"argument index " + std::to_string(index) + " out of range (" +
                              std::to_string(call.args.size()) + " arguments)",
                          index_offset};
          }
          call.args[index] = std::move(value);
          break;
        }
        case kDetailRet:
          call.ret = Value{};
          parse_value(call.ret, 0);
          call.has_ret = true;
          break;
        case kDetailBacktrace:
          skip_backtrace();
          break;
        case kDetailFlags:
          if (in_.varint() & kTraceFlagFake) call.flags |= kCallFlagFake;
          break;
        default:
          throw Corrupt{"unknown call detail " + hex_byte(detail), in_.offset() - 1};
      }
    }
  }

  // Backtraces are read past: the replayer has no use for them. Frames are defined at first use
  // like signatures, so their ids are remembered.
  void skip_backtrace() {
    uint64_t frames = in_.varint();
    for (uint64_t i = 0; i < frames; ++i) {  // each frame consumes input, so this ends
      uint64_t id = in_.varint();
      if (known_frames_.count(id)) continue;
      charge_metadata(kMetadataEntryCost);
      for (;;) {
        uint8_t detail = in_.byte();
        if (detail == 0) break;
        if (detail >= 1 && detail <= 3) {
          in_.skip(in_.varint());  // module, function or file name
        } else if (detail == 4 || detail == 5) {
          in_.varint();  // line number or offset
        } else {
          throw Corrupt{"unknown backtrace detail " + hex_byte(detail), in_.offset() - 1};
        }
      }
      known_frames_.insert(id);
    }
  }

  uint32_t sig_id(uint64_t id) { return narrow_u32(id, "signature id"); }

  const FunctionSig* function_sig() {
    uint64_t id = in_.varint();
    if (const FunctionSig* known = functions_.find(id)) return known;
    charge_metadata(kMetadataEntryCost);
    auto sig = std::make_unique<FunctionSig>();
    sig->id = sig_id(id);
    sig->name = name_string();
    uint64_t count = in_.varint();
    for (uint64_t i = 0; i < count; ++i) sig->arg_names.push_back(name_string());
    sig->flags = frame_flags_for(sig->name);
    return functions_.add(id, std::move(sig));
  }

  const EnumSig* enum_sig() {
    uint64_t id = in_.varint();
    if (const EnumSig* known = enums_.find(id)) return known;
    charge_metadata(kMetadataEntryCost);
    auto sig = std::make_unique<EnumSig>();
    sig->id = sig_id(id);
    uint64_t count = in_.varint();
    for (uint64_t i = 0; i < count; ++i) {
      std::string name = name_string();
      sig->values.emplace_back(std::move(name), signed_integer());
    }
    return enums_.add(id, std::move(sig));
  }

  const BitmaskSig* bitmask_sig() {
    uint64_t id = in_.varint();
    if (const BitmaskSig* known = bitmasks_.find(id)) return known;
    charge_metadata(kMetadataEntryCost);
    auto sig = std::make_unique<BitmaskSig>();
    sig->id = sig_id(id);
    uint64_t count = in_.varint();
    for (uint64_t i = 0; i < count; ++i) {
      std::string name = name_string();
      sig->flags.emplace_back(std::move(name), in_.varint());
    }
    return bitmasks_.add(id, std::move(sig));
  }

  const StructSig* struct_sig() {
    uint64_t id = in_.varint();
    if (const StructSig* known = structs_.find(id)) return known;
    charge_metadata(kMetadataEntryCost);
    auto sig = std::make_unique<StructSig>();
    sig->id = sig_id(id);
    sig->name = name_string();
    uint64_t count = in_.varint();
    for (uint64_t i = 0; i < count; ++i) sig->member_names.push_back(name_string());
    return structs_.add(id, std::move(sig));
  }

  // An enum's value: written as a value of type SInt or UInt.
  int64_t signed_integer() {
    uint8_t type = in_.byte();
    if (type == kTypeSInt) return int64_t(0 - in_.varint());
    if (type == kTypeUInt) return int64_t(in_.varint());
    throw Corrupt{"enum value of type " + hex_byte(type) + " (not an integer)", in_.offset() - 1};
  }

  void parse_value(Value& value, unsigned depth) {
    uint64_t at = in_.offset();
    if (depth > kMaxValueDepth) {
      throw Corrupt{"values nested deeper than " + std::to_string(kMaxValueDepth), at};
    }
    if (++values_in_event_ > kMaxValuesPerCall) {
      throw Corrupt{"more than " + std::to_string(kMaxValuesPerCall) + " values in one call", at};
    }
    uint8_t type = in_.byte();
    switch (type) {
      case kTypeNull:
        value.kind = ValueKind::Null;
        break;
      case kTypeFalse:
      case kTypeTrue:
        value.kind = ValueKind::Bool;
        value.boolean = type == kTypeTrue;
        break;
      case kTypeSInt:
        value.kind = ValueKind::SInt;
        value.sint = int64_t(0 - in_.varint());
        break;
      case kTypeUInt:
        value.kind = ValueKind::UInt;
        value.uint = in_.varint();
        break;
      case kTypeFloat:
        value.kind = ValueKind::Float;
        value.real = in_.scalar<float>();
        break;
      case kTypeDouble:
        value.kind = ValueKind::Double;
        value.real = in_.scalar<double>();
        break;
      case kTypeString:
      case kTypeBlob:
        value.kind = type == kTypeString ? ValueKind::String : ValueKind::Blob;
        value_bytes(in_.varint(), value.bytes);
        break;
      case kTypeEnum:
        value.kind = ValueKind::Enum;
        value.enum_sig = enum_sig();
        value.sint = signed_integer();
        break;
      case kTypeBitmask:
        value.kind = ValueKind::Bitmask;
        value.bitmask_sig = bitmask_sig();
        value.uint = in_.varint();
        break;
      case kTypeArray: {
        value.kind = ValueKind::Array;
        uint64_t count = in_.varint();
        if (count > kMaxValuesPerCall - values_in_event_) {
          throw Corrupt{"array of " + std::to_string(count) + " elements", at};
        }
        // Grows as elements parse (each takes at least a byte), never by the declared count.
        value.elements.reserve(size_t(std::min<uint64_t>(count, 64)));
        for (uint64_t i = 0; i < count; ++i) parse_value(value.elements.emplace_back(), depth + 1);
        break;
      }
      case kTypeStruct: {
        value.kind = ValueKind::Struct;
        value.struct_sig = struct_sig();
        size_t members = value.struct_sig->member_names.size();
        value.elements.reserve(std::min<size_t>(members, 64));
        for (size_t i = 0; i < members; ++i) parse_value(value.elements.emplace_back(), depth + 1);
        break;
      }
      case kTypeOpaque:
        value.kind = ValueKind::Pointer;
        value.uint = in_.varint();
        break;
      case kTypeRepr:
        value.kind = ValueKind::Repr;
        value.elements.resize(2);
        parse_value(value.elements[0], depth + 1);
        parse_value(value.elements[1], depth + 1);
        break;
      case kTypeWString: {
        value.kind = ValueKind::WString;
        uint64_t count = in_.varint();
        if (count > (kMaxBytesPerCall - bytes_in_event_) / 4) {  // up to 4 UTF-8 bytes each
          throw Corrupt{"wide string of " + std::to_string(count) + " characters", at};
        }
        bytes_in_event_ += 4 * count;
        for (uint64_t i = 0; i < count; ++i) append_utf8(in_.varint(), value.bytes);
        break;
      }
      default:
        throw Corrupt{"unknown value type " + hex_byte(type), at};
    }
  }

  std::unique_ptr<Decompressor> source_;
  Cursor in_;
  uint32_t version_ = 0;
  std::map<std::string, std::string> properties_;
  SigTable<FunctionSig> functions_;
  SigTable<EnumSig> enums_;
  SigTable<BitmaskSig> bitmasks_;
  SigTable<StructSig> structs_;
  std::unordered_set<uint64_t> known_frames_;
  struct Pending {
    Call call;
    uint64_t cost;  // bytes it holds, roughly
  };
  std::deque<Pending> pending_;  // entered, not yet left, in the order they entered
  uint64_t pending_cost_ = 0;
  uint32_t next_call_no_ = 0;
  uint64_t values_in_event_ = 0;
  uint64_t bytes_in_event_ = 0;
  uint64_t metadata_bytes_ = 0;
  bool stream_ended_ = false;  // no more events: only pending calls remain to hand out
  bool finished_ = false;      // End (or Error) returned
  bool in_header_ = true;
  // The call being parsed, for error messages (-1: none).
  int64_t context_no_ = -1;
  const FunctionSig* context_sig_ = nullptr;
};

std::unique_ptr<TraceReader> open_input(std::unique_ptr<detail::ByteInput> input,
                                        std::string& error) {
  std::unique_ptr<Decompressor> source = detail::make_decompressor(std::move(input), error);
  if (!source) return nullptr;
  auto reader = std::make_unique<ApitraceReader>(std::move(source));
  if (!reader->read_header(error)) return nullptr;
  return reader;
}

}  // namespace

std::unique_ptr<TraceReader> TraceReader::open(const std::string& path, std::string& error) {
  std::unique_ptr<detail::ByteInput> input = detail::open_file_input(path, error);
  std::unique_ptr<TraceReader> reader = input ? open_input(std::move(input), error) : nullptr;
  if (!reader) error = path + ": " + error;
  return reader;
}

std::unique_ptr<TraceReader> TraceReader::open_memory(std::string bytes, std::string& error) {
  return open_input(detail::memory_input(std::move(bytes)), error);
}

}  // namespace glpt::trace
