// The compressed containers apitrace writes a trace stream into (Snappy chunks, Brotli, gzip),
// behind one interface that hands out the uncompressed stream a block at a time. Internal to the
// trace reader (trace_reader.cpp); tests reach it for the container limits.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace glpt::trace::detail {

// The compressed bytes: a file read as it goes, or bytes in memory. Knows its total size, so a
// declared length can be checked against what remains.
class ByteInput {
 public:
  virtual ~ByteInput() = default;
  // Copies up to `n` bytes to `out`; fewer only at the end of the input.
  virtual size_t read(void* out, size_t n) = 0;
  virtual uint64_t size() const = 0;
  virtual void rewind() = 0;  // back to offset 0 (after sniffing the magic number)
  uint64_t offset() const { return offset_; }
  uint64_t remaining() const { return size() - offset_; }

 protected:
  uint64_t offset_ = 0;
};

std::unique_ptr<ByteInput> open_file_input(const std::string& path, std::string& error);
std::unique_ptr<ByteInput> memory_input(std::string bytes);

// One container format. `next_block` hands out the next piece of the uncompressed stream; the
// view stays valid until the next call.
class Decompressor {
 public:
  enum class Result { Block, End, Error };
  virtual ~Decompressor() = default;
  // Block: `block` is non-empty. End: the stream ended, cleanly or cut short (a cut container
  // gives every byte that can be decoded before the cut, then End). Error: the compressed data
  // is corrupt; `error` says what and at which file offset.
  virtual Result next_block(std::string_view& block, std::string& error) = 0;
  virtual const char* name() const = 0;  // "Snappy", "Brotli", "gzip"
};

// Picks the container from the first bytes as apitrace does ('a' 't': Snappy; 1f 8b: gzip;
// anything else: Brotli, which has no magic number). nullptr and `error` for formats glpt cannot
// read (Zstandard).
std::unique_ptr<Decompressor> make_decompressor(std::unique_ptr<ByteInput> input,
                                                std::string& error);

// Limits on what a container may declare. apitrace writes Snappy chunks of 1 MiB uncompressed.
inline constexpr uint64_t kMaxSnappyChunk = 64ull << 20;
// A Snappy element of n input bytes yields at most 64 / 3 * n output bytes (a 3-byte copy of 64),
// so a chunk that declares more than this many times its compressed size is corrupt.
inline constexpr uint64_t kMaxSnappyRatio = 22;
// Brotli and gzip are decoded in pieces of this size, whatever the stream's ratio.
inline constexpr size_t kStreamBlock = 1u << 20;

}  // namespace glpt::trace::detail
