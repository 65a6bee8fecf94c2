#include "replay/call_context.hpp"

#include <algorithm>
#include <cstring>

#include "gl/gl_enums.h"
#include "replay/image_sizes.hpp"

namespace glpt::replay {

GLuint ObjectNames::map(NameKind kind, uint64_t recorded) const {
  const auto& names = maps_[static_cast<size_t>(kind)];
  const auto it = names.find(recorded);
  return it != names.end() ? it->second : static_cast<GLuint>(recorded);
}

void ObjectNames::add(NameKind kind, uint64_t recorded, GLuint replayed) {
  if (recorded != 0) maps_[static_cast<size_t>(kind)][recorded] = replayed;
}

GlFunctions::GlFunctions(Resolver resolve, void* backend) : resolve_(resolve), backend_(backend) {
  procs_.reserve(kDispatchTableSize);
  for (size_t i = 0; i < kDispatchTableSize; ++i)
    procs_.push_back(resolve_(backend_, kDispatchTable[i].name));
  get_integerv_ = reinterpret_cast<void (*)(GLenum, GLint*)>(resolve_(backend_, "glGetIntegerv"));
}

GLint GlFunctions::get_integer(GLenum pname) const {
  GLint value[16] = {};  // room for any pname's values
  if (get_integerv_ != nullptr) get_integerv_(pname, value);
  return value[0];
}

const trace::Value& CallContext::arg(size_t i) const {
  static const trace::Value kNull;
  return i < call_.args.size() ? call_.args[i] : kNull;
}

namespace {

bool is_number(const trace::Value& v) {
  switch (v.kind) {
    case trace::ValueKind::Bool:
    case trace::ValueKind::SInt:
    case trace::ValueKind::UInt:
    case trace::ValueKind::Float:
    case trace::ValueKind::Double:
    case trace::ValueKind::Enum:
    case trace::ValueKind::Bitmask:
    case trace::ValueKind::Pointer:
    case trace::ValueKind::Repr:
      return true;
    default:
      return false;
  }
}

}  // namespace

const void* CallContext::pointer(size_t i, PointerRole role) {
  const trace::Value& v = arg(i);
  switch (v.kind) {
    case trace::ValueKind::Blob:
    case trace::ValueKind::String:
    case trace::ValueKind::WString: {
      if (role != PointerRole::kVertexArray) return v.data();
      // Keyed by command (and texture unit): respecifying an array replaces its memory.
      std::string key(call_.sig != nullptr ? call_.sig->name : std::string());
      key += '#' + std::to_string(state_.client_texture_unit);
      std::string& kept = state_.vertex_arrays[key];
      kept.assign(static_cast<const char*>(v.data()), v.size());
      return kept.data();
    }
    case trace::ValueKind::Null:
      return nullptr;
    default:
      break;
  }
  if (!is_number(v)) return nullptr;
  // An opaque pointer: an offset when a buffer object is bound for this use (as the program
  // passed it); otherwise the address of memory this process does not have. Vertex arrays in
  // user memory are respecified by the tracer's fake calls before each draw that reads them.
  GLenum binding = 0;
  if (role == PointerRole::kVertexArray) binding = GL_ARRAY_BUFFER_BINDING;
  if (role == PointerRole::kIndices) binding = GL_ELEMENT_ARRAY_BUFFER_BINDING;
  if (binding == 0 || gl_.get_integer(binding) == 0) return nullptr;
  return reinterpret_cast<const void*>(static_cast<uintptr_t>(v.as_uint()));
}

namespace {

// Padding beyond this is not done: such a call is replayed without its data (NULL).
constexpr uint64_t kMaxPaddedBytes = uint64_t{1} << 30;

}  // namespace

const void* CallContext::padded(const trace::Value& v, uint64_t needed) {
  const void* data = v.data();
  if (data == nullptr) {
    if (v.kind != trace::ValueKind::Array) return nullptr;  // NULL (or an unusable pointer)
    padded_.clear();
    for (const trace::Value& e : v.elements) padded_.push_back(static_cast<char>(e.as_uint()));
    data = padded_.data();
    if (padded_.size() >= needed) return data;
  } else if (v.size() >= needed) {
    return data;
  }
  if (needed > kMaxPaddedBytes) return nullptr;
  if (data != padded_.data()) padded_.assign(static_cast<const char*>(data), v.size());
  padded_.resize(needed, '\0');
  return padded_.data();
}

const void* CallContext::image(size_t i, int64_t width, int64_t height, int64_t depth,
                               GLenum format, GLenum type, bool three_d) {
  const trace::Value& v = arg(i);
  if (v.kind == trace::ValueKind::Null) return nullptr;
  PixelStoreModes modes;
  modes.row_length = gl_.get_integer(GL_UNPACK_ROW_LENGTH);
  modes.skip_rows = gl_.get_integer(GL_UNPACK_SKIP_ROWS);
  modes.skip_pixels = gl_.get_integer(GL_UNPACK_SKIP_PIXELS);
  modes.alignment = gl_.get_integer(GL_UNPACK_ALIGNMENT);
  if (three_d) {
    modes.image_height = gl_.get_integer(GL_UNPACK_IMAGE_HEIGHT);
    modes.skip_images = gl_.get_integer(GL_UNPACK_SKIP_IMAGES);
  }
  // An unknown format or type (GL reports the error and reads nothing) or an absurd size: the
  // command gets no data.
  const std::optional<uint64_t> needed =
      image_bytes(width, height, depth, format, type, three_d, modes);
  return needed ? padded(v, *needed) : nullptr;
}

const void* CallContext::sized_data(size_t i, int64_t size) {
  return padded(arg(i), size > 0 ? static_cast<uint64_t>(size) : 0);
}

template <typename T>
TypedArray<T>::TypedArray(const CallContext& c, size_t i, int64_t count) {
  const trace::Value& v = c.arg(i);
  if (count > kMaxBytes / static_cast<int64_t>(sizeof(T))) return;  // NULL: nothing is read
  switch (v.kind) {
    case trace::ValueKind::Null:
      return;
    case trace::ValueKind::Array:
      values_.reserve(v.elements.size());
      for (const trace::Value& e : v.elements) {
        if constexpr (std::is_floating_point_v<T>)
          values_.push_back(static_cast<T>(e.as_double()));
        else if constexpr (std::is_signed_v<T>)
          values_.push_back(static_cast<T>(e.as_sint()));
        else
          values_.push_back(static_cast<T>(e.as_uint()));
      }
      break;
    case trace::ValueKind::Blob:
    case trace::ValueKind::String:
    case trace::ValueKind::WString: {
      const bool text = v.kind != trace::ValueKind::Blob;
      values_.resize((v.size() + sizeof(T) - 1) / sizeof(T) + (text ? 1 : 0));
      if (v.size() > 0) std::memcpy(values_.data(), v.data(), v.size());
      if (text) reinterpret_cast<char*>(values_.data())[v.size()] = '\0';
      break;
    }
    default:
      if (!is_number(v)) return;
      // A single value recorded for a pointer to one element.
      if constexpr (std::is_floating_point_v<T>)
        values_.push_back(static_cast<T>(v.as_double()));
      else
        values_.push_back(static_cast<T>(v.as_sint()));
      break;
  }
  null_ = false;
  values_.resize(
      std::max({values_.size(), kMinElements, static_cast<size_t>(std::max<int64_t>(count, 0))}),
      T{});
}

template class TypedArray<GLbyte>;
template class TypedArray<GLubyte>;
template class TypedArray<GLshort>;
template class TypedArray<GLushort>;
template class TypedArray<GLint>;
template class TypedArray<GLuint>;
template class TypedArray<GLfloat>;
template class TypedArray<GLdouble>;
template class TypedArray<GLchar>;
template class TypedArray<GLint64>;
template class TypedArray<GLuint64>;

NameArray::NameArray(const CallContext& c, size_t i, NameKind kind, int64_t count) {
  const TypedArray<GLuint> recorded(c, i, count);
  if (recorded.get() == nullptr) return;
  null_ = false;
  names_.assign(recorded.get(), recorded.get() + recorded.size());
  for (GLuint& name : names_) name = c.state().names->map(kind, name);
}

const DispatchEntry* find_dispatch_entry(std::string_view name) {
  const DispatchEntry* end = kDispatchTable + kDispatchTableSize;
  const DispatchEntry* it = std::lower_bound(
      kDispatchTable, end, name,
      [](const DispatchEntry& e, std::string_view n) { return std::string_view(e.name) < n; });
  return it != end && std::string_view(it->name) == name ? it : nullptr;
}

}  // namespace glpt::replay
