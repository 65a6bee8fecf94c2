#include "replay/special_calls.hpp"

#include <algorithm>
#include <cstring>

#include "gl/gl_enums.h"

namespace glpt::replay::hand {
namespace {

// Counts and sizes from a trace are never trusted beyond this.
constexpr GLsizei kMaxGenerated = 1 << 16;

void generate(CallContext& c, NameKind kind) {
  const GLsizei n = std::clamp<GLsizei>(c.sint<GLsizei>(0), 0, kMaxGenerated);
  std::vector<GLuint> names(static_cast<size_t>(n) + 1, 0);
  reinterpret_cast<void (*)(GLsizei, GLuint*)>(c.proc())(c.sint<GLsizei>(0) < 0 ? -1 : n,
                                                         names.data());
  const trace::Value& recorded = c.arg(1);
  for (size_t i = 0; i < recorded.elements.size() && i < static_cast<size_t>(n); ++i)
    c.state().names->add(kind, recorded.elements[i].as_uint(), names[i]);
}

void map_buffer(CallContext& c) {
  const GLenum target = c.uint<GLenum>(0);
  void* address = reinterpret_cast<void* (*)(GLenum, GLenum)>(c.proc())(target, c.uint<GLenum>(1));
  auto& mappings = c.state().mappings;
  std::erase_if(mappings, [&](const BufferMapping& m) { return m.target == target; });
  if (address == nullptr || c.call().ret.kind == trace::ValueKind::Null) return;
  const GLenum binding =
      target == GL_ELEMENT_ARRAY_BUFFER ? GL_ELEMENT_ARRAY_BUFFER_BINDING : GL_ARRAY_BUFFER_BINDING;
  if (c.gl().get_integer(binding) == 0) return;
  auto get_parameter =
      reinterpret_cast<void (*)(GLenum, GLenum, GLint*)>(c.gl().find("glGetBufferParameteriv"));
  GLint size = 0;
  if (get_parameter != nullptr) get_parameter(target, GL_BUFFER_SIZE, &size);
  if (size <= 0) return;
  mappings.push_back(
      {target, c.call().ret.as_uint(), static_cast<uint8_t*>(address), static_cast<size_t>(size)});
}

void unmap_buffer(CallContext& c) {
  const GLenum target = c.uint<GLenum>(0);
  std::erase_if(c.state().mappings, [&](const BufferMapping& m) { return m.target == target; });
  reinterpret_cast<GLboolean (*)(GLenum)>(c.proc())(target);
}

void multi_draw_elements(CallContext& c) {
  const trace::Value& indices = c.arg(3);
  const GLsizei drawcount = std::clamp<GLsizei>(c.sint<GLsizei>(4), 0, kMaxGenerated);
  const TypedArray<GLsizei> counts(c, 1);
  if (counts.get() == nullptr || drawcount == 0) return;
  const bool buffer = c.gl().get_integer(GL_ELEMENT_ARRAY_BUFFER_BINDING) != 0;
  std::vector<const void*> pointers;
  std::vector<GLsizei> used_counts;
  for (size_t i = 0; i < indices.elements.size() && i < static_cast<size_t>(drawcount); ++i) {
    const trace::Value& v = indices.elements[i];
    const void* p = v.data();
    if (p == nullptr && buffer && v.kind != trace::ValueKind::Null)
      p = reinterpret_cast<const void*>(static_cast<uintptr_t>(v.as_uint()));
    if (p == nullptr || i >= counts.size()) continue;  // user memory the trace does not have
    pointers.push_back(p);
    used_counts.push_back(counts.get()[i]);
  }
  reinterpret_cast<void (*)(GLenum, const GLsizei*, GLenum, const void* const*, GLsizei)>(c.proc())(
      c.uint<GLenum>(0), used_counts.data(), c.uint<GLenum>(2), pointers.data(),
      static_cast<GLsizei>(pointers.size()));
}

}  // namespace

void glGenTextures(CallContext& c) { generate(c, NameKind::kTexture); }
void glGenTexturesEXT(CallContext& c) { generate(c, NameKind::kTexture); }
void glGenBuffers(CallContext& c) { generate(c, NameKind::kBuffer); }
void glGenBuffersARB(CallContext& c) { generate(c, NameKind::kBuffer); }
void glGenQueries(CallContext& c) { generate(c, NameKind::kQuery); }
void glGenQueriesARB(CallContext& c) { generate(c, NameKind::kQuery); }
void glGenFramebuffers(CallContext& c) { generate(c, NameKind::kFramebuffer); }
void glGenFramebuffersEXT(CallContext& c) { generate(c, NameKind::kFramebuffer); }
void glGenRenderbuffers(CallContext& c) { generate(c, NameKind::kRenderbuffer); }
void glGenRenderbuffersEXT(CallContext& c) { generate(c, NameKind::kRenderbuffer); }

void glGenLists(CallContext& c) {
  const GLsizei range = c.sint<GLsizei>(0);
  const GLuint base = reinterpret_cast<GLuint (*)(GLsizei)>(c.proc())(range);
  const uint64_t recorded = c.call().ret.as_uint();
  if (base == 0 || recorded == 0) return;
  for (GLsizei i = 0; i < std::min(range, kMaxGenerated); ++i)
    c.state().names->add(NameKind::kList, recorded + i, base + i);
}

void glReadPixels(CallContext& c) {
  // Enough memory for any format and type under the current pack modes: 16 bytes per pixel
  // (RGBA floats) over rows of max(width, row length) plus skips and alignment.
  const GLsizei width = c.sint<GLsizei>(2), height = c.sint<GLsizei>(3);
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) return;
  const int64_t row_length = std::max<int64_t>(width, c.gl().get_integer(GL_PACK_ROW_LENGTH));
  const int64_t rows = int64_t{height} + std::max(0, c.gl().get_integer(GL_PACK_SKIP_ROWS));
  const int64_t row_bytes =
      (row_length + std::max(0, c.gl().get_integer(GL_PACK_SKIP_PIXELS))) * 16 + 8;
  if (row_length > 16384 || rows > 32768) return;
  std::vector<uint8_t> scratch(static_cast<size_t>(row_bytes * rows));
  reinterpret_cast<void (*)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*)>(c.proc())(
      c.sint<GLint>(0), c.sint<GLint>(1), width, height, c.uint<GLenum>(4), c.uint<GLenum>(5),
      scratch.data());
}

void glFeedbackBuffer(CallContext& c) {
  const GLsizei size = std::clamp<GLsizei>(c.sint<GLsizei>(0), 0, kMaxGenerated);
  c.state().feedback_buffer.assign(static_cast<size_t>(size) + 1, 0.0f);
  reinterpret_cast<void (*)(GLsizei, GLenum, GLfloat*)>(c.proc())(
      c.sint<GLsizei>(0) < 0 ? -1 : size, c.uint<GLenum>(1), c.state().feedback_buffer.data());
}

void glSelectBuffer(CallContext& c) {
  const GLsizei size = std::clamp<GLsizei>(c.sint<GLsizei>(0), 0, kMaxGenerated);
  c.state().select_buffer.assign(static_cast<size_t>(size) + 1, 0);
  reinterpret_cast<void (*)(GLsizei, GLuint*)>(c.proc())(c.sint<GLsizei>(0) < 0 ? -1 : size,
                                                         c.state().select_buffer.data());
}

void glMapBuffer(CallContext& c) { map_buffer(c); }
void glMapBufferARB(CallContext& c) { map_buffer(c); }
void glUnmapBuffer(CallContext& c) { unmap_buffer(c); }
void glUnmapBufferARB(CallContext& c) { unmap_buffer(c); }
void glMultiDrawElements(CallContext& c) { multi_draw_elements(c); }
void glMultiDrawElementsEXT(CallContext& c) { multi_draw_elements(c); }

}  // namespace glpt::replay::hand

namespace glpt::replay {

bool replay_memcpy(const trace::Call& call, ReplayContextState& state) {
  if (call.args.size() < 3) return false;
  const uint64_t dest = call.args[0].as_uint();
  const trace::Value& src = call.args[1];
  const uint64_t n = std::min<uint64_t>(call.args[2].as_uint(), src.size());
  if (src.data() == nullptr || n == 0) return true;
  for (const BufferMapping& m : state.mappings) {
    if (dest < m.recorded_address || dest - m.recorded_address >= m.size) continue;
    const uint64_t offset = dest - m.recorded_address;
    std::memcpy(m.address + offset, src.data(), std::min<uint64_t>(n, m.size - offset));
    return true;
  }
  return false;
}

}  // namespace glpt::replay
