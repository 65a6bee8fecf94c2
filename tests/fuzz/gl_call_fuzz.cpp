// libFuzzer target: random GL 1.x call sequences, valid and invalid, through glpt's exported
// entry points into the front end and the frame record, under ASan and UBSan. Built with clang
// by build_gl_fuzzer.sh; run briefly by ctest (gl.fuzz) from the seed corpus in gl_corpus/.
// README.md in this directory describes the input format, what is covered and what is not.
//
// Each input runs on a fresh context (no renderer: frames end in the clear-colour fallback, as on
// a machine without Vulkan) made current on a headless drawable. The input is a sequence of
// commands: a little-endian u16 picks a pseudo-command (kPseudo*) or a GL command of the table
// generated from gl.xml (gen_gl_fuzz_calls.py), whose arguments the Decoder draws from the bytes
// that follow. The bytes running out ends the input (every later read is 0).
//
// What counts as a glpt bug: any ASan or UBSan report, a hang, an abort, or a GL error value
// that is not one of GL's. The fuzzer never passes memory GL would legitimately read or write
// past: every pointer points into fuzz-owned memory big enough for what the spec lets the call
// touch with the values drawn (see the bounds at the regions below), and draws from client
// arrays whose indices would leave that memory are skipped (and counted) before the call.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <type_traits>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/frame/clear_fallback.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/gl_entry_decls.h"
#include "gl_shim/textures/texture_object.hpp"

namespace glpt::fuzz {

// --- fuzz-owned memory ------------------------------------------------------------------------
// Bounds that every valid call stays within (the Decoder draws no valid value beyond them):
//   images: width, height, depth <= kMaxExtent (texture sizes past GL's maximum are drawn too,
//     GL must refuse them before reading), unpack/pack row length, image height <= 64, skips
//     <= 64, at most 16 bytes a pixel: (64 + 66) images * 66 rows * 66 pixels * 16 < 9.1 MB;
//   counts (n, count, size, mapsize...) <= kMaxCount, at most 16 bytes an element: 64 KiB;
//   client arrays: stride <= 64, vertices < kMaxVertices, offset < 2 KiB: < 264 KiB.
// Pointers start within the first 2 KiB of their region, 8-aligned (as GL requires of a
// program's data: the alignment of its type).
inline constexpr int kMaxExtent = 66;  // 64 + 2 borders
inline constexpr int kMaxCount = 4096;
inline constexpr int kMaxVertices = 4096;
inline constexpr size_t kInputBytes = size_t{16} << 20;
inline constexpr size_t kOutputBytes = size_t{32} << 20;
// The part of the input memory the input writes (kPseudoFill*): reset before every input.
inline constexpr size_t kWritableInputBytes = size_t{64} << 10;
inline constexpr size_t kPointerOffsets = 2048;
// Index memory: u32 values below kIndexValues, so read as u8, u16 or u32 (from 4-aligned
// offsets) every index is below kIndexValues <= kMaxVertices.
inline constexpr size_t kIndexWords = kMaxCount + 64;
inline constexpr uint32_t kIndexValues = 64;

struct Memory {
  // Heap blocks, so ASan's redzones sit right after them.
  std::unique_ptr<uint8_t[]> input{new uint8_t[kInputBytes]()};
  std::unique_ptr<uint8_t[]> output{new uint8_t[kOutputBytes]()};
  std::unique_ptr<uint32_t[]> indices{new uint32_t[kIndexWords]};
  std::unique_ptr<GLint[]> small_ints{new GLint[kMaxCount + 64]};
  std::unique_ptr<const void* []> index_pointers { new const void*[kMaxCount] };
  Memory() {
    uint32_t x = 12345;  // a fixed sequence: every input sees the same values
    for (size_t i = 0; i < kIndexWords; ++i) {
      x = x * 1103515245u + 12345u;
      indices[i] = (x >> 16) % kIndexValues;
    }
    for (size_t i = 0; i < kMaxCount + 64; ++i) {
      x = x * 1103515245u + 12345u;
      small_ints[i] = GLint((x >> 16) % 66) - 2;  // counts and firsts in [-2, 63]
    }
  }
};
Memory& memory() {
  static Memory m;
  return m;
}

struct Command {
  const char* name;
  void (*call)(class Decoder&);
};

struct Stats {
  uint64_t calls = 0, unsafe_draws_skipped = 0;
};
Stats g_stats;

class Decoder {
 public:
  Decoder(const uint8_t* data, size_t size, Context& ctx)
      : p_(data), end_(data + size), ctx_(ctx) {}
  bool done() const { return p_ >= end_; }
  Context& ctx() { return ctx_; }

  uint8_t byte() { return p_ < end_ ? *p_++ : 0; }
  uint16_t u16() { return uint16_t(byte() | byte() << 8); }
  uint32_t u32() { return uint32_t(u16()) | uint32_t(u16()) << 16; }
  uint64_t u64() { return uint64_t(u32()) | uint64_t(u32()) << 32; }

  // Every kind of value: the low 4 bits of a selector byte choose how it is drawn; 15 is always
  // "a literal follows" (u32, or the float's own bytes), which the seed writer uses.
  template <typename T>
  T integer() {
    const uint8_t sel = byte() & 15;
    if (sel < 8) return T(int8_t(byte()));
    if (sel < 11) return T(byte());
    if (sel == 11) {
      static constexpr int64_t kSpecial[] = {INT32_MIN, INT32_MAX, -1,      0x10000,
                                             0x7FFF,    0xFFFF,    1 << 20, kMaxTextureSize + 1,
                                             UINT32_MAX};
      return T(kSpecial[byte() % std::size(kSpecial)]);
    }
    return T(u32());
  }
  // Counts, sizes and lengths of what a pointer covers: mostly small, never past kMaxCount.
  GLint count() {
    const uint8_t sel = byte() & 15;
    if (sel < 10) return byte() % 65;
    if (sel < 12) return -1 - byte() % 4;
    if (sel < 14) return u16() % (kMaxCount + 1);
    if (sel == 14) return 0;
    return std::min(GLint(u32()), GLint{kMaxCount});
  }
  // Sizes of images without a GL maximum (glDrawPixels, glReadPixels, glBitmap).
  GLsizei extent() {
    const uint8_t sel = byte() & 15;
    if (sel < 12) return byte() % (kMaxExtent + 1);
    if (sel < 15) return -1 - byte() % 2;
    return std::min(GLsizei(u32()), GLsizei{kMaxExtent});
  }
  // Texture sizes: small ones, and invalid ones (negative, past GL_MAX_TEXTURE_SIZE) that GL
  // must refuse with GL_INVALID_VALUE before reading the image. Not while a display list is
  // being compiled: GL 1.5 5.4 compiles the image as given, its errors are raised only when the
  // list runs (Mesa's save_TexImage* unpack whatever size they are given).
  GLsizei texture_size() {
    const GLsizei size = any_texture_size();
    return ctx_.lists.compiling() && size > kMaxExtent ? kMaxExtent : size;
  }
  GLsizei any_texture_size() {
    const uint8_t sel = byte() & 15;
    if (sel < 12) {
      static constexpr GLsizei kSizes[] = {0,  1,  2,  3,  4,  5,  7,  8,  9,
                                           16, 17, 18, 32, 33, 34, 64, 65, 66};
      return kSizes[byte() % std::size(kSizes)];
    }
    if (sel == 12) return -1 - byte() % 2;
    if (sel < 15) {
      static constexpr GLsizei kTooBig[] = {kMaxTextureSize + 1, kMaxTextureSize + 2, 1 << 16,
                                            INT32_MAX, INT32_MIN};
      return kTooBig[byte() % std::size(kTooBig)];
    }
    const auto v = GLsizei(u32());
    return v > kMaxExtent && v <= kMaxTextureSize ? kMaxExtent : v;
  }
  GLsizei stride() {
    const uint8_t sel = byte() & 15;
    if (sel < 13) return byte() % 65;
    if (sel < 15) return -1 - byte() % 4;
    return std::min(GLsizei(u32()), GLsizei{64});
  }
  // glPixelStore values: row lengths, skips and image heights have no GL maximum.
  template <typename T>
  T pixel_store() {
    const uint8_t sel = byte() & 15;
    GLint v = sel < 13 ? byte() % 65 : sel < 15 ? -1 - byte() % 2 : std::min(GLint(u32()), 64);
    if constexpr (std::is_floating_point_v<T>) {
      if (sel == 14) return std::numeric_limits<T>::quiet_NaN();
    }
    return T(v);
  }
  template <typename T>
  T real() {
    const uint8_t sel = byte() & 15;
    switch (sel) {
      case 8:
        return std::numeric_limits<T>::quiet_NaN();
      case 9:
        return std::numeric_limits<T>::infinity();
      case 10:
        return -std::numeric_limits<T>::infinity();
      case 11:
        return T(-0.0);
      case 12:
        return byte() & 1 ? T(1e38) : T(-1e38);
      case 13:
        return T(std::numeric_limits<float>::denorm_min() * float(byte() + 1));
      case 14:
        return T(byte()) / T(255);
      case 15:
        if constexpr (sizeof(T) == 8)
          return std::bit_cast<T>(u64());
        else
          return std::bit_cast<T>(u32());
      default:
        return T(int8_t(byte())) / T(sel < 4 ? 1 : 16);
    }
  }
  uint32_t enumerant(int group);
  GLbitfield bits(int group);
  GLboolean boolean() {
    const uint8_t sel = byte() & 15;
    return sel < 6 ? GLboolean(sel & 1) : byte();
  }

  const void* input() { return memory().input.get() + size_t(byte()) * 8; }
  void* output() { return memory().output.get() + size_t(byte()) * 8; }
  // A client array: fuzz-owned memory, or an offset into the buffer object bound to
  // GL_ARRAY_BUFFER. Now and then the other one (a program's mistake GL must survive: an address
  // taken as an offset, or null).
  const void* array_pointer() {
    const uint8_t sel = byte();
    const uint8_t offset = byte();
    const bool buffer_bound = ctx_.arrays.array_buffer != nullptr;
    if (sel == 0) return nullptr;
    if ((sel < 8) == buffer_bound) return memory().input.get() + size_t(offset) * 8;
    return reinterpret_cast<const void*>(uintptr_t(offset));
  }
  const void* index_pointer() {
    const uint8_t offset = byte();
    if (ctx_.arrays.element_buffer != nullptr)
      return reinterpret_cast<const void*>(uintptr_t(offset));
    return memory().indices.get() + offset % 64;
  }
  const void* const* index_pointers() {
    const uint8_t offset = byte();
    for (size_t i = 0; i < kMaxCount; ++i) {
      memory().index_pointers[i] =
          ctx_.arrays.element_buffer != nullptr
              ? reinterpret_cast<const void*>(uintptr_t((offset + i) % 256))
              : memory().indices.get() + (offset + i) % 64;
    }
    return memory().index_pointers.get();
  }
  const GLint* small_ints() { return memory().small_ints.get() + byte() % 64; }

  // Guards of the draws that read client arrays (gen_gl_fuzz_calls.py's GUARDS).
  bool client_vertices_fit(GLint first, GLsizei count) {
    if (!reads_client_arrays() || count <= 0 || first < 0) return true;  // GL's to refuse
    return int64_t(first) + count <= kMaxVertices && client_pointers_fit();
  }
  bool client_indices_fit() {
    if (!reads_client_arrays()) return true;
    // Indices in a buffer object are whatever bytes it holds.
    return ctx_.arrays.element_buffer == nullptr && client_pointers_fit();
  }
  // glMultiDrawArrays: its firsts and counts are small_ints(), below kMaxVertices together; a
  // negative first would read before the array.
  bool client_multi_draw_fits(const GLint* first, const GLsizei* count, GLsizei drawcount) {
    if (!reads_client_arrays()) return true;
    for (GLsizei i = 0; i < drawcount; ++i)
      if (count[i] > 0 && first[i] < 0) return false;
    return client_pointers_fit();
  }
  bool client_range_fits(GLuint start, GLuint end) {
    return !reads_client_arrays() || end < start || end < GLuint{kMaxVertices};
  }
  // Guard of glEvalMesh1/2: at most 64K points (a reversed or empty span draws none).
  bool mesh_fits(GLint i1, GLint i2, GLint j1, GLint j2) {
    const auto span = [](GLint a, GLint b) { return std::max<int64_t>(0, int64_t{b} - a + 1); };
    return span(i1, i2) * std::max<int64_t>(1, span(j1, j2)) <= (int64_t{1} << 16);
  }
  void skip_unsafe_draw() { ++g_stats.unsafe_draws_skipped; }
  // glCallLists' count: small (each list named may call a chain of 64 more).
  GLsizei list_count() { return std::min(count(), GLint{64}); }
  // Guard of glCallList(s): at most one list call compiled into the list being compiled.
  bool list_calls_fit(GLsizei n) {
    if (!ctx_.lists.compiling() || n <= 0) return true;
    list_calls_compiled_ += n;
    return list_calls_compiled_ <= 1;
  }
  // Called after every command: a list that is no longer being compiled starts the count anew.
  void command_done() {
    if (!ctx_.lists.compiling()) list_calls_compiled_ = 0;
  }

  template <typename T>
  void returned(T value) {
    if constexpr (std::is_same_v<T, const GLubyte*>) {
      if (value != nullptr) sink_ += std::strlen(reinterpret_cast<const char*>(value));
    } else if constexpr (std::is_pointer_v<T>) {
      sink_ += value != nullptr;
    } else {
      sink_ += uint64_t(value);
    }
  }

 private:
  // Whether a draw now would read an enabled array from client memory.
  bool reads_client_arrays() const {
    for (const ClientArray& a : ctx_.arrays.arrays)
      if (a.enabled && a.buffer == nullptr && !a.orphaned) return true;
    return false;
  }
  // Client arrays are only ever set to fuzz-owned memory, but an array enabled before any
  // pointer was given is null (GL reads address 0: the program's bug, not GL's).
  bool client_pointers_fit() const {
    const auto* base = memory().input.get();
    for (const ClientArray& a : ctx_.arrays.arrays) {
      if (!a.enabled || a.buffer != nullptr || a.orphaned) continue;
      const auto* p = static_cast<const uint8_t*>(a.pointer);
      if (p < base || p >= base + kPointerOffsets) return false;
    }
    return true;
  }

  const uint8_t* p_;
  const uint8_t* end_;
  Context& ctx_;
  uint64_t sink_ = 0;
  int64_t list_calls_compiled_ = 0;
};

#include "gl_fuzz_calls.inc"

uint32_t Decoder::enumerant(int group) {
  const uint8_t sel = byte() & 15;
  if (sel < 12 && group >= 0 && !kGroups[group].empty())
    return kGroups[group][u16() % kGroups[group].size()];
  if (sel < 14) return kAllEnums[u16() % std::size(kAllEnums)];
  if (sel == 14) return 0;
  return u32();
}

GLbitfield Decoder::bits(int group) {
  const uint8_t sel = byte() & 15;
  if (sel < 12 && group >= 0 && !kGroups[group].empty()) {
    GLbitfield mask = 0;
    for (int i = byte() % 4; i >= 0; --i) mask |= kGroups[group][u16() % kGroups[group].size()];
    return mask;
  }
  if (sel == 12) return ~GLbitfield{0};
  if (sel == 13) return 0;
  return u32();
}

// --- pseudo-commands: what a window system or the program's memory does between GL calls --------
enum Pseudo : uint16_t {
  kPseudoFillBytes,  // u16 offset, u8 length, bytes: the input's bytes into the input memory
  kPseudoFillReals,  // u16 offset, u8 count, reals: d.real<float>() values into it
  kPseudoSwap,       // the frame ends (glXSwapBuffers)
  kPseudoResize,     // the drawable takes a new size (u8, u8)
  kPseudoRebind,     // the context is released (flushed) and made current again
  kPseudoCount
};

bool valid_error(GLenum e) {
  switch (e) {
    case GL_NO_ERROR:
    case GL_INVALID_ENUM:
    case GL_INVALID_VALUE:
    case GL_INVALID_OPERATION:
    case GL_STACK_OVERFLOW:
    case GL_STACK_UNDERFLOW:
    case GL_OUT_OF_MEMORY:
    case GL_TABLE_TOO_LARGE:
      return true;
    default:
      return false;
  }
}

void run_pseudo(Decoder& d, uint16_t which, HeadlessTarget& target, bool double_buffered) {
  uint8_t* writable = memory().input.get();
  switch (which) {
    case kPseudoFillBytes: {
      size_t at = d.u16() % kWritableInputBytes;
      for (size_t n = d.byte(); n > 0 && at < kWritableInputBytes; --n) writable[at++] = d.byte();
      break;
    }
    case kPseudoFillReals: {
      size_t at = (d.u16() % kWritableInputBytes) & ~size_t{3};
      for (size_t n = d.byte() % 32; n > 0 && at + 4 <= kWritableInputBytes; --n, at += 4) {
        const float v = d.real<float>();
        std::memcpy(writable + at, &v, 4);
      }
      break;
    }
    case kPseudoSwap:
      end_frame(d.ctx(), double_buffered);
      break;
    case kPseudoResize: {
      const uint32_t w = d.byte() % (kMaxExtent + 1), h = d.byte() % (kMaxExtent + 1);
      target.resize(w, h);
      break;
    }
    case kPseudoRebind:
      flush_before_release(d.ctx());
      set_current_context(nullptr);
      bind_target_and_make_current(d.ctx(), &target);
      break;
    default:
      break;
  }
}

}  // namespace glpt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace glpt::fuzz;
  constexpr size_t kCommands = kPseudoCount + std::size(kGlCommands);
  std::memset(memory().input.get(), 0, kWritableInputBytes);
  // The first byte: the drawable's buffers (bit 0: double-buffered) and size.
  const uint8_t config_byte = size > 0 ? data[0] : 0;
  glpt::rec::DrawableConfig config;
  config.double_buffered = config_byte & 1;
  const uint32_t side = 1 + (config_byte >> 1) % 32;
  glpt::HeadlessTarget target(side, side, config);
  auto ctx = std::make_unique<glpt::Context>(nullptr);
  // No renderer: what ensure_output (context.cpp) does when none can be created, so that frame
  // ends, flushes and reads take the clear-colour fallback instead of Vulkan.
  ctx->renderer_unavailable = true;
  ctx->clear_fallback = std::make_unique<glpt::ClearFallback>();
  glpt::make_current_headless(*ctx, target);

  // GL_FUZZ_TRACE=1: each command and the GL error after it on stderr (to read an input).
  static const bool trace = std::getenv("GL_FUZZ_TRACE") != nullptr;
  // The fuzzer's own drops, said at exit beside libFuzzer's statistics.
  static const bool stats_registered =
      std::atexit([] {
        std::fprintf(stderr,
                     "gl fuzz: %llu commands, %llu draws and list calls skipped as unsafe\n",
                     static_cast<unsigned long long>(g_stats.calls),
                     static_cast<unsigned long long>(g_stats.unsafe_draws_skipped));
      }) == 0;
  (void)stats_registered;
  Decoder d(data + (size > 0), size - (size > 0), *ctx);
  while (!d.done()) {
    const uint16_t which = d.u16() % kCommands;
    if (which < kPseudoCount)
      run_pseudo(d, which, target, config.double_buffered);
    else
      kGlCommands[which - kPseudoCount].call(d);
    ++g_stats.calls;
    d.command_done();
    if (trace)
      std::fprintf(stderr, "%s -> 0x%X\n",
                   which < kPseudoCount ? "(pseudo)" : kGlCommands[which - kPseudoCount].name,
                   ctx->error);
    if (!valid_error(ctx->error)) {
      std::fprintf(
          stderr, "GL error 0x%X after %s is none of GL's\n", ctx->error,
          which < kPseudoCount ? "a pseudo-command" : kGlCommands[which - kPseudoCount].name);
      std::abort();
    }
  }
  // The last frame ends, as a program's does.
  glpt::end_frame(*ctx, config.double_buffered);
  glpt::set_current_context(nullptr);
  ctx.reset();
  return 0;
}
