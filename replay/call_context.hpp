// What one replayed GL call sees: the recorded call, the entry point the backend resolved for
// it, and the replayer's per-context state that turns recorded values into values for this run
// (object names, vertex-array memory, buffer mappings). The generated dispatch
// (gen/gen_replay_dispatch.py) and the hand-written calls (special_calls.cpp) use it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gl_shim/gl_types.h"
#include "replay/trace/trace_model.hpp"

namespace glpt::replay {

using GlProc = void (*)();

// Objects whose names the replay maps from the recorded name to the name this run got.
enum class NameKind : uint8_t {
  kTexture,
  kBuffer,
  kQuery,
  kList,
  kFramebuffer,
  kRenderbuffer,
  kCount
};

// Recorded object name -> replayed name, per kind, for one share group. A name never generated
// maps to itself (GL 1.x binds unused names without glGen*).
class ObjectNames {
 public:
  GLuint map(NameKind kind, uint64_t recorded) const;
  void add(NameKind kind, uint64_t recorded, GLuint replayed);

 private:
  std::unordered_map<uint64_t, GLuint> maps_[static_cast<size_t>(NameKind::kCount)];
};

// A buffer object mapped by glMapBuffer: the tracer's fake memcpy calls write into it by the
// address it had when recording.
struct BufferMapping {
  GLenum target = 0;
  uint64_t recorded_address = 0;
  uint8_t* address = nullptr;
  size_t size = 0;
};

// The replayer's state of one recorded GL context.
struct ReplayContextState {
  std::shared_ptr<ObjectNames> names = std::make_shared<ObjectNames>();  // per share group
  GLenum client_texture_unit = 0;  // GL_TEXTURE0 + i, as glClientActiveTexture set it
  // Client vertex arrays recorded as blobs (apitrace records user memory at draw time as fake
  // gl*Pointer calls): GL reads them at later draws, so they live until the array is respecified.
  std::map<std::string, std::string, std::less<>> vertex_arrays;
  std::vector<GLfloat> feedback_buffer;  // GL writes into these until glRenderMode returns
  std::vector<GLuint> select_buffer;
  std::vector<BufferMapping> mappings;
};

// How a `const void *` argument is used, which decides what an opaque recorded pointer means.
enum class PointerRole : uint8_t {
  kData,         // image or buffer data: a blob, or NULL
  kVertexArray,  // gl*Pointer: a blob kept for later draws, or an offset into GL_ARRAY_BUFFER
  kIndices,      // glDrawElements: a blob, or an offset into GL_ELEMENT_ARRAY_BUFFER
};

// The backend's entry points, resolved once by name for every dispatch table entry.
class GlFunctions {
 public:
  using Resolver = GlProc (*)(void* backend, const char* name);
  GlFunctions(Resolver resolve, void* backend);
  GlProc proc(size_t entry) const { return procs_[entry]; }
  GlProc find(const char* name) const { return resolve_(backend_, name); }
  // glGetIntegerv through the backend (0 if the backend lacks it).
  GLint get_integer(GLenum pname) const;

 private:
  Resolver resolve_;
  void* backend_;
  std::vector<GlProc> procs_;
  void (*get_integerv_)(GLenum, GLint*) = nullptr;
};

class CallContext {
 public:
  CallContext(const trace::Call& call, GlProc proc, ReplayContextState& state,
              const GlFunctions& gl)
      : call_(call), proc_(proc), state_(state), gl_(gl) {}

  const trace::Call& call() const { return call_; }
  GlProc proc() const { return proc_; }
  ReplayContextState& state() const { return state_; }
  const GlFunctions& gl() const { return gl_; }

  // Argument `i` (a Null value when the trace has fewer arguments).
  const trace::Value& arg(size_t i) const;
  template <typename T>
  T sint(size_t i) const {
    return static_cast<T>(arg(i).as_sint());
  }
  template <typename T>
  T uint(size_t i) const {
    return static_cast<T>(arg(i).as_uint());
  }
  template <typename T>
  T real(size_t i) const {
    return static_cast<T>(arg(i).as_double());
  }
  GLuint name(NameKind kind, size_t i) const { return state_.names->map(kind, arg(i).as_uint()); }
  // A `const void *` argument as this run must pass it (see PointerRole).
  const void* pointer(size_t i, PointerRole role);
  // An image in client memory of the given shape, as the current unpack modes lay it out
  // (image_sizes.hpp): the recorded bytes, padded with zeros if the trace holds fewer than GL
  // will read; nullptr for NULL and for images too large to be real.
  const void* image(size_t i, int64_t width, int64_t height, int64_t depth, GLenum format,
                    GLenum type, bool three_d);
  // Data whose size is another argument (glBufferData, glCompressedTexImage*), padded likewise.
  const void* sized_data(size_t i, int64_t size);

 private:
  const trace::Call& call_;
  GlProc proc_;
  ReplayContextState& state_;
  const GlFunctions& gl_;
  std::string padded_;  // a short blob padded to the size GL reads (lives for the call)

  const void* padded(const trace::Value& v, uint64_t needed);
};

// A `const T *` argument: the recorded array (each element converted), blob or string (bytes;
// strings NUL-terminated) in a temporary array; nullptr for NULL. Padded with zeros to at least
// 256 bytes and to `count`, the elements GL reads as the call's other arguments say (the
// registry's len: glDeleteTextures' n, glMap2f's orders and strides), so GL never reads past a
// shorter recorded array. A count beyond kMaxBytes gives nullptr (GL reports NULL data).
template <typename T>
class TypedArray {
 public:
  static constexpr size_t kMinElements = std::max<size_t>(16, 256 / sizeof(T));
  static constexpr int64_t kMaxBytes = int64_t{256} << 20;
  TypedArray(const CallContext& c, size_t i, int64_t count = 0);
  const T* get() const { return null_ ? nullptr : values_.data(); }
  size_t size() const { return values_.size(); }

 private:
  std::vector<T> values_;
  bool null_ = true;
};

// A `const GLuint *` array of object names, each mapped (glDeleteTextures, glPrioritizeTextures).
class NameArray {
 public:
  NameArray(const CallContext& c, size_t i, NameKind kind, int64_t count = 0);
  const GLuint* get() const { return null_ ? nullptr : names_.data(); }

 private:
  std::vector<GLuint> names_;
  bool null_ = true;
};

using ReplayFn = void (*)(CallContext&);
struct DispatchEntry {
  const char* name;
  ReplayFn fn;
};
// Generated (replay_dispatch.cpp): every GL command glpt exports but the queries, by name.
extern const DispatchEntry kDispatchTable[];
extern const size_t kDispatchTableSize;
// The table entry for `name`, or nullptr.
const DispatchEntry* find_dispatch_entry(std::string_view name);

}  // namespace glpt::replay
