// Snappy, Brotli and gzip containers of apitrace traces (apitrace's docs/FORMAT.markdown,
// "Compression"). Every length a container declares is checked against the bytes that remain
// and against what the compression can produce from them before anything is allocated for it.
#include "replay/trace/trace_container.hpp"

#include <brotli/decode.h>
#include <snappy.h>
#include <sys/stat.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

namespace glpt::trace::detail {
namespace {

class FileInput final : public ByteInput {
 public:
  FileInput(FILE* file, uint64_t size) : file_(file), size_(size) {}
  ~FileInput() override { std::fclose(file_); }
  size_t read(void* out, size_t n) override {
    size_t got = std::fread(out, 1, n, file_);
    offset_ += got;
    return got;
  }
  uint64_t size() const override { return size_; }
  void rewind() override {
    std::fseek(file_, 0, SEEK_SET);
    offset_ = 0;
  }

 private:
  FILE* file_;
  uint64_t size_;
};

class MemoryInput final : public ByteInput {
 public:
  explicit MemoryInput(std::string bytes) : bytes_(std::move(bytes)) {}
  size_t read(void* out, size_t n) override {
    size_t got = std::min<uint64_t>(n, remaining());
    if (got) std::memcpy(out, bytes_.data() + offset_, got);
    offset_ += got;
    return got;
  }
  uint64_t size() const override { return bytes_.size(); }
  void rewind() override { offset_ = 0; }

 private:
  std::string bytes_;
};

// Decodes the Snappy elements (Snappy's format_description.txt) of a chunk the input ends
// inside, as far as they are complete; a literal is kept up to the cut. Written out rather than
// snappy::UncompressAsMuchAsPossible, which needs an output buffer of the chunk's declared size
// (up to 64 MiB, however few bytes the file holds); this one writes at most `out.size()` bytes,
// sized by what the bytes present can produce. Returns the bytes decoded, or SIZE_MAX if an
// element is invalid (a copy from before the start).
size_t decode_cut_snappy(const uint8_t* in, size_t n, std::vector<char>& out) {
  size_t pos = 0, produced = 0;
  for (unsigned shift = 0; pos < n && shift < 35; shift += 7) {  // the length preamble
    if (!(in[pos++] & 0x80)) break;
  }
  while (pos < n) {
    const uint8_t tag = in[pos];
    size_t length = 0, offset = 0;
    if ((tag & 3) == 0) {  // literal
      size_t extra = (tag >> 2) >= 60 ? (tag >> 2) - 59 : 0;
      if (pos + 1 + extra > n) break;
      length = (tag >> 2) + 1;
      if (extra) {
        length = 0;
        for (size_t i = 0; i < extra; ++i) length |= size_t(in[pos + 1 + i]) << (8 * i);
        length += 1;
      }
      pos += 1 + extra;
      size_t take = std::min({length, n - pos, out.size() - produced});
      if (take) std::memcpy(out.data() + produced, in + pos, take);
      produced += take;
      pos += take;
      if (take < length) break;  // the cut (or the buffer's end) is inside this literal
      continue;
    }
    const size_t tag_bytes = (tag & 3) == 1 ? 2 : (tag & 3) == 2 ? 3 : 5;
    if (pos + tag_bytes > n) break;
    if ((tag & 3) == 1) {
      length = 4 + ((tag >> 2) & 7);
      offset = (size_t(tag >> 5) << 8) | in[pos + 1];
    } else {
      length = 1 + (tag >> 2);
      for (size_t i = 1; i < tag_bytes; ++i) offset |= size_t(in[pos + i]) << (8 * (i - 1));
    }
    pos += tag_bytes;
    if (offset == 0 || offset > produced || length > out.size() - produced) return SIZE_MAX;
    for (size_t i = 0; i < length; ++i, ++produced) {  // may overlap itself: byte by byte
      out[produced] = out[produced - offset];
    }
  }
  return produced;
}

// apitrace's Snappy container: 'a' 't', then chunks of (uint32 LE compressed length, raw
// Snappy data). A zero length ends the stream, as in apitrace.
class SnappyDecompressor final : public Decompressor {
 public:
  explicit SnappyDecompressor(std::unique_ptr<ByteInput> input) : input_(std::move(input)) {
    char magic[2];
    input_->read(magic, 2);
  }
  const char* name() const override { return "Snappy"; }

  Result next_block(std::string_view& block, std::string& error) override {
    while (!ended_) {
      uint64_t chunk_offset = input_->offset();
      unsigned char length_bytes[4];
      if (input_->read(length_bytes, 4) < 4) break;  // clean end, or cut inside the length
      uint64_t declared = uint64_t(length_bytes[0]) | uint64_t(length_bytes[1]) << 8 |
                          uint64_t(length_bytes[2]) << 16 | uint64_t(length_bytes[3]) << 24;
      if (declared == 0) break;
      if (declared > snappy::MaxCompressedLength(kMaxSnappyChunk)) {
        error = "Snappy chunk at file offset " + std::to_string(chunk_offset) + " declares " +
                std::to_string(declared) + " compressed bytes (limit " +
                std::to_string(snappy::MaxCompressedLength(kMaxSnappyChunk)) + ")";
        return Result::Error;
      }
      // A chunk longer than what remains is the one a cut went through: decode what is there.
      const bool cut = declared > input_->remaining();
      const size_t available = cut ? size_t(input_->remaining()) : size_t(declared);
      compressed_.resize(available);
      if (input_->read(compressed_.data(), available) != available) {
        error = "read error in Snappy chunk at file offset " + std::to_string(chunk_offset);
        return Result::Error;
      }
      size_t uncompressed = 0;
      if (!snappy::GetUncompressedLength(compressed_.data(), available, &uncompressed)) {
        if (cut) break;
        error = "corrupt Snappy chunk at file offset " + std::to_string(chunk_offset) +
                " (bad length header)";
        return Result::Error;
      }
      if (uncompressed > kMaxSnappyChunk || uncompressed > kMaxSnappyRatio * declared) {
        error = "Snappy chunk at file offset " + std::to_string(chunk_offset) + " declares " +
                std::to_string(uncompressed) + " bytes from " + std::to_string(declared) +
                " compressed bytes";
        return Result::Error;
      }
      if (cut) {
        ended_ = true;
        // What `available` bytes can produce is bounded by the same ratio.
        uncompressed_.resize(std::min<uint64_t>(uncompressed, kMaxSnappyRatio * available));
        size_t produced = decode_cut_snappy(reinterpret_cast<const uint8_t*>(compressed_.data()),
                                            available, uncompressed_);
        if (produced == SIZE_MAX) {
          error = "corrupt Snappy chunk at file offset " + std::to_string(chunk_offset) +
                  " (the file also ends inside it)";
          return Result::Error;
        }
        if (produced == 0) break;
        block = std::string_view(uncompressed_.data(), produced);
        return Result::Block;
      }
      uncompressed_.resize(uncompressed);
      if (!snappy::RawUncompress(compressed_.data(), available, uncompressed_.data())) {
        error = "corrupt Snappy chunk at file offset " + std::to_string(chunk_offset);
        return Result::Error;
      }
      if (uncompressed == 0) continue;  // apitrace never writes one; skip it
      block = std::string_view(uncompressed_.data(), uncompressed);
      return Result::Block;
    }
    ended_ = true;
    return Result::End;
  }

 private:
  std::unique_ptr<ByteInput> input_;
  std::vector<char> compressed_;
  std::vector<char> uncompressed_;
  bool ended_ = false;
};

// `apitrace repack --brotli`: one Brotli stream, decoded a block at a time.
class BrotliDecompressor final : public Decompressor {
 public:
  explicit BrotliDecompressor(std::unique_ptr<ByteInput> input)
      : input_(std::move(input)),
        state_(BrotliDecoderCreateInstance(nullptr, nullptr, nullptr)),
        in_(64 * 1024),
        out_(kStreamBlock) {}
  ~BrotliDecompressor() override { BrotliDecoderDestroyInstance(state_); }
  const char* name() const override { return "Brotli"; }

  Result next_block(std::string_view& block, std::string& error) override {
    if (ended_) return Result::End;
    if (!state_) {
      error = "out of memory creating the Brotli decoder";
      return Result::Error;
    }
    size_t available_out = out_.size();
    uint8_t* next_out = out_.data();
    while (available_out > 0 && !ended_) {
      BrotliDecoderResult result = BrotliDecoderDecompressStream(
          state_, &available_in_, &next_in_, &available_out, &next_out, nullptr);
      if (result == BROTLI_DECODER_RESULT_ERROR) {
        uint64_t at = input_->offset() - available_in_;
        error = std::string(produced_any_ ? "corrupt Brotli stream"
                                          : "not a trace (not Snappy, gzip or Brotli)") +
                " at file offset " + std::to_string(at) + ": " +
                BrotliDecoderErrorString(BrotliDecoderGetErrorCode(state_));
        ended_ = true;
        return Result::Error;
      }
      if (result == BROTLI_DECODER_RESULT_SUCCESS) ended_ = true;
      if (result == BROTLI_DECODER_RESULT_NEEDS_MORE_INPUT) {
        available_in_ = input_->read(in_.data(), in_.size());
        next_in_ = in_.data();
        if (available_in_ == 0) ended_ = true;  // cut short: keep what was decoded
      }
    }
    size_t produced = out_.size() - available_out;
    if (produced == 0) return Result::End;
    produced_any_ = true;
    block = std::string_view(reinterpret_cast<const char*>(out_.data()), produced);
    return Result::Block;
  }

 private:
  std::unique_ptr<ByteInput> input_;
  BrotliDecoderState* state_;
  std::vector<uint8_t> in_;
  std::vector<uint8_t> out_;
  const uint8_t* next_in_ = nullptr;
  size_t available_in_ = 0;
  bool ended_ = false;
  bool produced_any_ = false;
};

// `apitrace repack --zlib` and old traces: gzip, possibly several members back to back.
class GzipDecompressor final : public Decompressor {
 public:
  explicit GzipDecompressor(std::unique_ptr<ByteInput> input)
      : input_(std::move(input)), in_(64 * 1024), out_(kStreamBlock) {
    initialized_ = inflateInit2(&stream_, 15 + 16) == Z_OK;
  }
  ~GzipDecompressor() override {
    if (initialized_) inflateEnd(&stream_);
  }
  const char* name() const override { return "gzip"; }

  Result next_block(std::string_view& block, std::string& error) override {
    if (ended_) return Result::End;
    if (!initialized_) {
      error = "out of memory creating the zlib decoder";
      return Result::Error;
    }
    stream_.next_out = out_.data();
    stream_.avail_out = static_cast<uInt>(out_.size());
    while (stream_.avail_out > 0 && !ended_) {
      if (stream_.avail_in == 0) {
        stream_.avail_in = static_cast<uInt>(input_->read(in_.data(), in_.size()));
        stream_.next_in = in_.data();
        if (stream_.avail_in == 0) {  // the input ended (a cut stream keeps what was decoded)
          ended_ = true;
          break;
        }
      }
      int status = inflate(&stream_, Z_NO_FLUSH);
      if (status == Z_STREAM_END) {
        // Another gzip member may follow, as gzread reads them.
        if (stream_.avail_in == 0 && input_->remaining() == 0) {
          ended_ = true;
        } else {
          inflateReset(&stream_);
        }
      } else if (status != Z_OK && status != Z_BUF_ERROR) {
        uint64_t at = input_->offset() - stream_.avail_in;
        error = "corrupt gzip stream at file offset " + std::to_string(at) + ": " +
                (stream_.msg ? stream_.msg : zError(status));
        ended_ = true;
        return Result::Error;
      }
    }
    size_t produced = out_.size() - stream_.avail_out;
    if (produced == 0) return Result::End;
    block = std::string_view(reinterpret_cast<const char*>(out_.data()), produced);
    return Result::Block;
  }

 private:
  std::unique_ptr<ByteInput> input_;
  z_stream stream_{};
  bool initialized_ = false;
  std::vector<Bytef> in_;
  std::vector<Bytef> out_;
  bool ended_ = false;
};

}  // namespace

std::unique_ptr<ByteInput> open_file_input(const std::string& path, std::string& error) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    error = std::strerror(errno);
    return nullptr;
  }
  struct stat info {};
  if (fstat(fileno(file), &info) != 0 || !S_ISREG(info.st_mode)) {
    error = "not a regular file";
    std::fclose(file);
    return nullptr;
  }
  return std::make_unique<FileInput>(file, uint64_t(info.st_size));
}

std::unique_ptr<ByteInput> memory_input(std::string bytes) {
  return std::make_unique<MemoryInput>(std::move(bytes));
}

std::unique_ptr<Decompressor> make_decompressor(std::unique_ptr<ByteInput> input,
                                                std::string& error) {
  unsigned char magic[4] = {};
  size_t got = input->read(magic, sizeof magic);
  input->rewind();
  if (got == 0) {
    error = "empty file";
    return nullptr;
  }
  if (got < 2) {
    error = "too short to be a trace (1 byte)";
    return nullptr;
  }
  if (magic[0] == 'a' && magic[1] == 't') {
    return std::make_unique<SnappyDecompressor>(std::move(input));
  }
  if (magic[0] == 0x1f && magic[1] == 0x8b) {
    return std::make_unique<GzipDecompressor>(std::move(input));
  }
  if (got == 4 && magic[0] == 0x28 && magic[1] == 0xb5 && magic[2] == 0x2f && magic[3] == 0xfd) {
    error =
        "Zstandard-compressed traces are not supported; convert with `apitrace repack --snappy`";
    return nullptr;
  }
  return std::make_unique<BrotliDecompressor>(std::move(input));
}

}  // namespace glpt::trace::detail
