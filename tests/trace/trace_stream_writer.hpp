// Builds apitrace trace streams byte by byte from apitrace's docs/FORMAT.markdown, for tests of
// inputs apitrace never writes (corrupt, hostile, multi-threaded), and wraps them in containers
// with the compression libraries directly. Test code only.
#pragma once

#include <snappy.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace glpt::trace::testing {

class StreamWriter {
 public:
  StreamWriter& byte(uint8_t b) {
    out_ += char(b);
    return *this;
  }
  StreamWriter& uint(uint64_t v) {
    do {
      uint8_t b = v & 0x7f;
      v >>= 7;
      byte(v ? b | 0x80 : b);
    } while (v);
    return *this;
  }
  StreamWriter& string(const std::string& s) {
    uint(s.size());
    out_ += s;
    return *this;
  }
  StreamWriter& raw(const std::string& bytes) {
    out_ += bytes;
    return *this;
  }
  template <typename T>
  StreamWriter& scalar(T v) {
    char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    out_.append(b, sizeof v);
    return *this;
  }
  // Header of a version-6 trace with the given properties.
  StreamWriter& header6(const std::string& key = "", const std::string& value = "") {
    uint(6).uint(6);
    if (!key.empty()) string(key).string(value);
    return string("");
  }
  // ENTER with a function signature defined here (first use) or referenced (`name` empty).
  StreamWriter& enter(uint64_t thread, uint64_t sig_id, const std::string& name = "",
                      std::initializer_list<std::string> args = {}) {
    byte(0).uint(thread).uint(sig_id);
    if (!name.empty()) {
      string(name).uint(args.size());
      for (const auto& a : args) string(a);
    }
    return *this;
  }
  StreamWriter& leave(uint64_t call_no) { return byte(1).uint(call_no); }
  StreamWriter& arg(uint64_t index) { return byte(1).uint(index); }  // then a value
  StreamWriter& ret() { return byte(2); }                            // then a value
  StreamWriter& end() { return byte(0); }                            // ends the details

  // Values (the type byte; follow with the payload where there is one).
  StreamWriter& v_uint(uint64_t v) { return byte(4).uint(v); }
  StreamWriter& v_sint(int64_t v) { return v < 0 ? byte(3).uint(0 - uint64_t(v)) : v_uint(v); }
  StreamWriter& v_float(float v) { return byte(5).scalar(v); }
  StreamWriter& v_double(double v) { return byte(6).scalar(v); }
  StreamWriter& v_string(const std::string& s) { return byte(7).string(s); }
  StreamWriter& v_blob(const std::string& s) { return byte(8).string(s); }

  const std::string& bytes() const { return out_; }

 private:
  std::string out_;
};

// apitrace's Snappy container: "at", then (uint32 LE length, Snappy data) chunks.
inline std::string snappy_container(const std::string& stream, size_t chunk = 1 << 20) {
  std::string file = "at";
  for (size_t at = 0; at < stream.size(); at += chunk) {
    std::string compressed;
    snappy::Compress(stream.data() + at, std::min(chunk, stream.size() - at), &compressed);
    uint32_t n = uint32_t(compressed.size());
    for (int i = 0; i < 4; ++i) file += char((n >> (8 * i)) & 0xff);
    file += compressed;
  }
  return file;
}

// gzip, in `members` members back to back (gzread reads them as one stream).
inline std::string gzip_container(const std::string& stream, int members = 1) {
  std::string file;
  size_t part = stream.size() / members + 1;
  for (size_t at = 0; at < stream.size(); at += part) {
    z_stream z{};
    deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
    size_t n = std::min(part, stream.size() - at);
    std::string out(deflateBound(&z, n) + 64, '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(stream.data() + at));
    z.avail_in = uInt(n);
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = uInt(out.size());
    deflate(&z, Z_FINISH);
    out.resize(z.total_out);
    deflateEnd(&z);
    file += out;
  }
  return file;
}

// The uncompressed stream of a Snappy-container trace (every chunk complete).
inline std::string snappy_stream(const std::string& file) {
  std::string stream;
  size_t at = 2;
  while (at + 4 <= file.size()) {
    uint32_t n = 0;
    for (int i = 0; i < 4; ++i) n |= uint32_t(uint8_t(file[at + i])) << (8 * i);
    at += 4;
    if (n == 0 || at + n > file.size()) break;
    std::string chunk;
    snappy::Uncompress(file.data() + at, n, &chunk);
    stream += chunk;
    at += n;
  }
  return stream;
}

}  // namespace glpt::trace::testing
