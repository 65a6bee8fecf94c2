// A display list as a compact byte stream of recorded commands.
//
// Each record is [header][argument struct][arrays], 8-byte aligned. The generated code defines
// one argument struct per compilable command (gl_entry_points.cpp) and replays a stream by
// calling the same validation + implementation path as the live entry point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "gl_shim/gl_commands.hpp"

namespace glpt {

class ListStream {
 public:
  struct Header {
    CommandId command;
    uint16_t reserved;
    uint32_t size;  // bytes of this whole record, header included
  };

  // Appends one record. Arrays go after the argument struct; their offsets are relative to the
  // start of the argument struct, so records are position independent.
  class Writer {
   public:
    Writer(ListStream& list, CommandId command, size_t record_size)
        : bytes_(list.bytes_), start_(bytes_.size()) {
      record_size_ = align(record_size);
      bytes_.resize(start_ + sizeof(Header) + record_size_, std::byte{0});
      Header h{command, 0, 0};
      std::memcpy(bytes_.data() + start_, &h, sizeof h);
    }
    ~Writer() {
      const uint32_t size = static_cast<uint32_t>(bytes_.size() - start_);
      std::memcpy(bytes_.data() + start_ + offsetof(Header, size), &size, sizeof size);
    }
    Writer(const Writer&) = delete;
    Writer& operator=(const Writer&) = delete;

    template <typename T>
    void set_record(const T& rec) {
      std::memcpy(bytes_.data() + start_ + sizeof(Header), &rec, sizeof rec);
    }

    // Copies `count` elements (null source: zeros). At least kMinArrayBytes are reserved so an
    // implementation that rejects a bad enum after peeking at the array never reads past it.
    template <typename T>
    uint32_t append_array(const T* src, uint32_t count) {
      const size_t offset = bytes_.size() - (start_ + sizeof(Header));
      const size_t n = count * sizeof(T);
      bytes_.resize(bytes_.size() + align(n < kMinArrayBytes ? kMinArrayBytes : n), std::byte{0});
      if (src != nullptr && n > 0)
        std::memcpy(bytes_.data() + start_ + sizeof(Header) + offset, src, n);
      return static_cast<uint32_t>(offset);
    }

   private:
    std::vector<std::byte>& bytes_;
    size_t start_;
    size_t record_size_;
  };

  class Reader {
   public:
    explicit Reader(const ListStream& list) : bytes_(list.bytes_) {}
    bool done() const { return pos_ + sizeof(Header) > bytes_.size(); }
    void next() { pos_ += header().size; }
    CommandId command() const { return header().command; }
    template <typename T>
    T record() const {
      T rec;
      std::memcpy(&rec, bytes_.data() + pos_ + sizeof(Header), sizeof rec);
      return rec;
    }
    template <typename T>
    const T* payload(uint32_t offset) const {
      return reinterpret_cast<const T*>(bytes_.data() + pos_ + sizeof(Header) + offset);
    }

   private:
    Header header() const {
      Header h;
      std::memcpy(&h, bytes_.data() + pos_, sizeof h);
      return h;
    }
    const std::vector<std::byte>& bytes_;
    size_t pos_ = 0;
  };

  size_t size_bytes() const { return bytes_.size(); }
  bool empty() const { return bytes_.empty(); }

 private:
  static constexpr size_t kMinArrayBytes = 64;
  static size_t align(size_t n) { return (n + 7) & ~size_t{7}; }
  std::vector<std::byte> bytes_;
};

class Context;
// Executes a recorded list (generated in gl_entry_points.cpp).
void replay_list(Context& ctx, const ListStream& list);

}  // namespace glpt
