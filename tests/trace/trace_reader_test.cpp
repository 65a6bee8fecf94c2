// The apitrace reader against apitrace itself: real traces recorded with apitrace, compared with
// `apitrace dump` of the same files (tests/trace/data/README.md), in every container; and against
// hand-built streams (FORMAT.markdown) for what apitrace never writes: cuts at any byte,
// corruption, hostile lengths.
#include "replay/trace/trace_reader.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "apitrace_dump_format.hpp"
#include "replay/trace/trace_container.hpp"
#include "trace_stream_writer.hpp"

namespace glpt::trace {
namespace {

using testing::dump_trace;
using testing::gzip_container;
using testing::snappy_container;
using testing::snappy_stream;
using testing::StreamWriter;
using Status = TraceReader::Status;

std::string data_path(const std::string& name) {
  return std::string(GLPT_TRACE_TEST_DATA) + "/" + name;
}

std::string read_file(const std::string& name) {
  std::ifstream in(data_path(name), std::ios::binary);
  EXPECT_TRUE(in) << data_path(name);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string dump_memory(const std::string& bytes, std::string& error) {
  auto reader = TraceReader::open_memory(bytes, error);
  if (!reader) return "<open failed: " + error + ">";
  return dump_trace(*reader, error);
}

struct Summary {
  std::vector<std::string> lines;  // one dump line per call, in order
  std::vector<bool> complete;
  Status last = Status::End;
  std::string error;
};

Summary summarize(TraceReader& reader) {
  Summary s;
  Call call;
  for (;;) {
    s.last = reader.next(call, s.error);
    if (s.last != Status::Call) break;
    std::ostringstream line;
    testing::dump_call(line, call);
    s.lines.push_back(line.str());
    s.complete.push_back(call.complete);
  }
  return s;
}

// --- Against apitrace dump -----------------------------------------------------------------

// Opens the trace by path (as `glpt replay` will) and compares with apitrace's dump of it.
void expect_file_matches_apitrace(const std::string& trace, const std::string& dump) {
  std::string error;
  auto reader = TraceReader::open(data_path(trace), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(dump_trace(*reader, error), read_file(dump));
  EXPECT_EQ(error, "");
}

TEST(ApitraceDump, GearsSnappyMatchesApitrace) {
  expect_file_matches_apitrace("gears.trace", "gears.dump.txt");
}

TEST(ApitraceDump, GearsBrotliMatchesApitrace) {
  expect_file_matches_apitrace("gears.brotli.trace", "gears.dump.txt");
}

TEST(ApitraceDump, GearsGzipMatchesApitrace) {
  std::string stream = snappy_stream(read_file("gears.trace"));
  ASSERT_GT(stream.size(), 100000u);
  std::string error;
  EXPECT_EQ(dump_memory(gzip_container(stream), error), read_file("gears.dump.txt"));
  EXPECT_EQ(dump_memory(gzip_container(stream, 3), error), read_file("gears.dump.txt"));
  EXPECT_EQ(error, "");
}

TEST(ApitraceDump, GearsInSmallSnappyChunksMatchesApitrace) {
  // Values and signatures straddling chunk boundaries.
  std::string stream = snappy_stream(read_file("gears.trace"));
  std::string error;
  EXPECT_EQ(dump_memory(snappy_container(stream, 7), error), read_file("gears.dump.txt"));
  EXPECT_EQ(error, "");
}

TEST(ApitraceDump, EglinfoMatchesApitrace) {
  expect_file_matches_apitrace("eglinfo.trace", "eglinfo.dump.txt");
}

TEST(ApitraceDump, CutTraceMatchesApitrace) {
  // apitrace's dump of the first 61000 bytes: 1314 lines of the full dump, then the call whose
  // LEAVE was cut off, marked incomplete.
  std::istringstream full(read_file("gears.dump.txt"));
  std::string expected, line;
  for (int i = 0; i < 1314 && std::getline(full, line); ++i) expected += line + "\n";
  expected += read_file("gears.cut61000.last-line.txt");
  std::string error;
  EXPECT_EQ(dump_memory(read_file("gears.trace").substr(0, 61000), error), expected);
  EXPECT_EQ(error, "");
}

// --- The model as the replayer sees it ------------------------------------------------------

TEST(TraceReader, VersionPropertiesAndFrames) {
  std::string error;
  auto reader = TraceReader::open(data_path("gears.trace"), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->version(), 6u);
  ASSERT_EQ(reader->properties().count("process.name"), 1u);
  EXPECT_NE(reader->properties().at("process.name").find("gearsdet"), std::string::npos);
  Call call;
  int swaps = 0, fake = 0;
  std::map<std::string, const FunctionSig*> first_sig;
  const FunctionSig* vertex = nullptr;
  float first_vertex_x = 0;
  while (reader->next(call, error) == Status::Call) {
    EXPECT_TRUE(call.complete);
    EXPECT_EQ(call.args.size(), call.sig->arg_names.size());
    // A function's signature is one object for the reader's life.
    auto [it, inserted] = first_sig.emplace(call.sig->name, call.sig);
    EXPECT_EQ(it->second, call.sig) << call.sig->name;
    if (call.sig->flags & kCallFlagEndFrame) {
      EXPECT_EQ(call.sig->name, "glXSwapBuffers");
      ++swaps;
    }
    if (call.flags & kCallFlagFake) ++fake;
    if (!vertex && call.sig->name == "glVertex3f") {
      vertex = call.sig;
      first_vertex_x = float(call.args[0].as_double());
      EXPECT_EQ(call.args[0].kind, ValueKind::Float);
    }
  }
  EXPECT_EQ(error, "");
  EXPECT_EQ(swaps, 2);  // --frames 2
  EXPECT_EQ(fake, 2);   // glViewport and glScissor at the first glXMakeCurrent (see the dump)
  ASSERT_TRUE(vertex);
  EXPECT_EQ(vertex->arg_names, (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(first_vertex_x, 1.0f);                    // "24 @0 glVertex3f(x = 1, y = 0, z = 0.25)"
  EXPECT_EQ(reader->next(call, error), Status::End);  // and stays there
}

TEST(TraceReader, OpenErrors) {
  std::string error;
  EXPECT_FALSE(TraceReader::open(data_path("no-such.trace"), error));
  EXPECT_NE(error.find("no-such.trace"), std::string::npos) << error;
  EXPECT_FALSE(TraceReader::open(GLPT_TRACE_TEST_DATA, error));
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  EXPECT_FALSE(TraceReader::open_memory("", error));
  EXPECT_EQ(error, "empty file");
  EXPECT_FALSE(TraceReader::open_memory(std::string("\x28\xb5\x2f\xfd\0\0", 6), error));
  EXPECT_NE(error.find("Zstandard"), std::string::npos) << error;
  EXPECT_FALSE(TraceReader::open_memory("this is not a trace at all, just text", error));
  EXPECT_NE(error.find("not a trace"), std::string::npos) << error;
}

TEST(TraceReader, VersionsOutsideFiveToSixRejected) {
  std::string error;
  for (uint64_t version : {0, 4, 7, 1000}) {
    EXPECT_FALSE(
        TraceReader::open_memory(snappy_container(StreamWriter().uint(version).bytes()), error));
    EXPECT_NE(error.find("version " + std::to_string(version)), std::string::npos) << error;
  }
  // Version 5: no semantic version and no properties.
  StreamWriter v5;
  v5.uint(5).enter(0, 0, "glFinish").end().leave(0).end();
  auto reader = TraceReader::open_memory(snappy_container(v5.bytes()), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->version(), 5u);
  EXPECT_TRUE(reader->properties().empty());
  Call call;
  ASSERT_EQ(reader->next(call, error), Status::Call);
  EXPECT_EQ(call.sig->name, "glFinish");
  // A semantic version above the format version is corrupt.
  EXPECT_FALSE(
      TraceReader::open_memory(snappy_container(StreamWriter().uint(6).uint(7).bytes()), error));
}

// Every value kind, output arguments in LEAVE, the fake flag and backtraces, written per
// FORMAT.markdown.
TEST(TraceReader, EveryValueKind) {
  StreamWriter w;
  w.header6("k", "v").enter(0, 0, "f", {"a", "b", "c", "d"});
  w.arg(0).v_sint(-5);
  w.arg(1).byte(9).uint(3).uint(2).string("E_A").v_sint(-2).string("E_B").v_uint(7).v_sint(7);
  w.arg(2).byte(10).uint(1).uint(2).string("B_0").uint(1).string("B_1").uint(2).uint(3);
  w.arg(3).byte(11).uint(3).byte(0).byte(2).v_string("s");
  w.byte(5).uint(1);                                                               // flags: fake
  w.byte(4).uint(2).uint(9).byte(1).string("libfoo.so").byte(4).uint(12).byte(0);  // frames
  w.uint(9);  // frame 9 again: referenced, no details
  w.end();
  w.leave(0).arg(3).byte(12).uint(4).string("S").uint(2).string("m").string("").v_float(1.5f);
  w.byte(12).uint(5).string("T").uint(1).string("n").v_double(-0.25);  // anonymous member
  w.ret().byte(14).v_string("human").byte(13).uint(0xdeadbeef);
  w.end();
  w.enter(0, 0).arg(0).byte(15).uint(3).uint('h').uint(0xe9).uint(0x1f600);
  w.arg(1).v_blob(std::string("\0\1\2", 3)).arg(2).byte(9).uint(3).v_uint(7);  // sig 3 again
  w.end();
  w.leave(1).ret().byte(0).end();
  std::string error;
  auto reader = TraceReader::open_memory(snappy_container(w.bytes()), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->properties().at("k"), "v");
  Call call;
  ASSERT_EQ(reader->next(call, error), Status::Call) << error;
  EXPECT_EQ(call.no, 0u);
  EXPECT_TRUE(call.complete);
  EXPECT_EQ(call.flags, kCallFlagFake);
  EXPECT_EQ(call.args[0].kind, ValueKind::SInt);
  EXPECT_EQ(call.args[0].as_sint(), -5);
  EXPECT_EQ(call.args[1].kind, ValueKind::Enum);
  EXPECT_EQ(call.args[1].sint, 7);
  ASSERT_TRUE(call.args[1].enum_sig);
  EXPECT_EQ(call.args[1].enum_sig->values,
            (std::vector<std::pair<std::string, int64_t>>{{"E_A", -2}, {"E_B", 7}}));
  EXPECT_EQ(call.args[2].kind, ValueKind::Bitmask);
  EXPECT_EQ(call.args[2].uint, 3u);
  EXPECT_EQ(call.args[2].bitmask_sig->flags.size(), 2u);
  // Argument 3 was replaced by the LEAVE's output value: a struct {m = 1.5, {n = -0.25}}.
  ASSERT_EQ(call.args[3].kind, ValueKind::Struct);
  EXPECT_EQ(call.args[3].struct_sig->name, "S");
  ASSERT_EQ(call.args[3].elements.size(), 2u);
  EXPECT_EQ(call.args[3].elements[0].kind, ValueKind::Float);
  EXPECT_EQ(call.args[3].elements[0].real, 1.5);
  EXPECT_EQ(call.args[3].elements[1].elements.at(0).real, -0.25);
  std::ostringstream dumped;
  testing::dump_value(dumped, call.args[3]);
  EXPECT_EQ(dumped.str(), "{m = 1.5, n = -0.25}");
  ASSERT_TRUE(call.has_ret);
  EXPECT_EQ(call.ret.kind, ValueKind::Repr);
  EXPECT_EQ(call.ret.elements[0].bytes, "human");
  EXPECT_EQ(call.ret.as_uint(), 0xdeadbeefu);  // the machine value
  EXPECT_EQ(call.ret.data(), nullptr);

  ASSERT_EQ(reader->next(call, error), Status::Call) << error;
  EXPECT_EQ(call.no, 1u);
  EXPECT_EQ(call.flags, 0u);
  EXPECT_EQ(call.args[0].kind, ValueKind::WString);
  EXPECT_EQ(call.args[0].bytes, "h\xc3\xa9\xf0\x9f\x98\x80");  // UTF-8 of h, U+00E9, U+1F600
  EXPECT_EQ(call.args[1].kind, ValueKind::Blob);
  EXPECT_EQ(call.args[1].size(), 3u);
  EXPECT_EQ(std::memcmp(call.args[1].data(), "\0\1\2", 3), 0);
  EXPECT_EQ(call.args[2].enum_sig->values.size(), 2u);  // the same enum signature, by id
  EXPECT_EQ(call.args[3].kind, ValueKind::Null);        // never written
  EXPECT_TRUE(call.has_ret);
  EXPECT_EQ(call.ret.kind, ValueKind::Null);  // returned NULL
  EXPECT_EQ(reader->next(call, error), Status::End);
  EXPECT_EQ(error, "");
}

// apitrace's order: a call comes out at its LEAVE; at the end, calls that never left, in the
// order they entered. A LEAVE for no pending call is skipped.
TEST(TraceReader, CallOrderFollowsLeaveEvents) {
  StreamWriter w;
  w.header6().enter(0, 0, "a").end().enter(1, 1, "b").end().enter(2, 2, "c").end();
  w.leave(1).end().leave(77).arg(0).v_uint(1).end().leave(0).end();
  w.enter(0, 0).end();  // call 3, never leaves
  std::string error;
  auto reader = TraceReader::open_memory(snappy_container(w.bytes()), error);
  ASSERT_TRUE(reader) << error;
  Summary s = summarize(*reader);
  EXPECT_EQ(s.last, Status::End) << s.error;
  EXPECT_EQ(s.lines,
            (std::vector<std::string>{"1 @1 b()\n", "0 @0 a()\n", "2 @2 c() // incomplete\n",
                                      "3 @0 a() // incomplete\n"}));
}

// --- Bad input --------------------------------------------------------------------------------

Status read_all(const std::string& file, std::string& error, size_t* calls = nullptr) {
  auto reader = TraceReader::open_memory(file, error);
  if (!reader) return Status::Error;
  Call call;
  Status status;
  size_t n = 0;
  while ((status = reader->next(call, error)) == Status::Call) ++n;
  if (calls) *calls = n;
  if (status == Status::Error) {
    EXPECT_EQ(reader->next(call, error), Status::End) << "an Error is followed by End";
  }
  return status;
}

StreamWriter one_call_prefix() {
  StreamWriter w;
  w.header6().enter(0, 0, "glFoo", {"x"}).end().leave(0);
  return w;
}

TEST(BadInput, CorruptionSaysWhatAndWhere) {
  std::string error;
  StreamWriter event = one_call_prefix();
  event.end().byte(7);
  EXPECT_EQ(read_all(snappy_container(event.bytes()), error), Status::Error);
  EXPECT_EQ(error, "unknown event 0x07 at uncompressed offset " +
                       std::to_string(event.bytes().size() - 1));

  StreamWriter type = one_call_prefix();
  type.arg(0).byte(0x1f);
  EXPECT_EQ(read_all(snappy_container(type.bytes()), error), Status::Error);
  EXPECT_EQ(error, "unknown value type 0x1f at uncompressed offset " +
                       std::to_string(type.bytes().size() - 1) + " in call 0 (glFoo)");

  StreamWriter index = one_call_prefix();
  index.arg(1).v_uint(0).end();
  EXPECT_EQ(read_all(snappy_container(index.bytes()), error), Status::Error);
  EXPECT_NE(error.find("argument index 1 out of range (1 arguments)"), std::string::npos) << error;

  StreamWriter detail = one_call_prefix();
  detail.byte(9);
  EXPECT_EQ(read_all(snappy_container(detail.bytes()), error), Status::Error);
  EXPECT_NE(error.find("unknown call detail 0x09"), std::string::npos) << error;

  StreamWriter varint = one_call_prefix();
  varint.arg(0).byte(4).raw(std::string(11, '\xff'));
  EXPECT_EQ(read_all(snappy_container(varint.bytes()), error), Status::Error);
  EXPECT_NE(error.find("integer"), std::string::npos) << error;
}

TEST(BadInput, NestingIsBounded) {
  StreamWriter w = one_call_prefix();
  w.arg(0);
  for (int i = 0; i < 100000; ++i) w.byte(11).uint(1);  // arrays of arrays of ...
  w.byte(0).end();
  std::string error;
  EXPECT_EQ(read_all(snappy_container(w.bytes()), error), Status::Error);
  EXPECT_NE(error.find("nested deeper than 64"), std::string::npos) << error;
}

TEST(BadInput, HostileCountsAllocateNothingUnjustified) {
  // Each declares more than follows but no more than a trace could hold: the reader must reach
  // the end of the input (the call is dropped as cut) without allocating what was declared.
  const uint64_t plausible = uint64_t(256) << 20;
  std::vector<StreamWriter> cases(6, one_call_prefix());
  cases[0].arg(0).byte(7).uint(plausible).raw("abc");                                // string
  cases[1].arg(0).byte(8).uint(plausible).raw("abc");                                // blob
  cases[2].arg(0).byte(11).uint(1000000).byte(0).byte(0);                            // array
  cases[3].arg(0).byte(15).uint(1000000).uint(65);                                   // wide string
  cases[4].arg(0).byte(12).uint(0).string("S").uint(uint64_t(1) << 62).string("m");  // struct sig
  cases[5].byte(4).uint(uint64_t(1) << 62).uint(0).byte(0);  // backtrace frames
  for (size_t i = 0; i < cases.size(); ++i) {
    std::string error;
    size_t calls = 99;
    EXPECT_EQ(read_all(snappy_container(cases[i].bytes()), error, &calls), Status::End)
        << i << ": " << error;
    EXPECT_EQ(calls, 0u) << i;  // call 0's LEAVE was cut: dropped, as apitrace does
  }
}

TEST(BadInput, CountsBeyondTheLimitsAreErrors) {
  const uint64_t huge = uint64_t(1) << 62;
  const std::pair<StreamWriter, std::string> cases[] = {
      {one_call_prefix().arg(0).byte(7).uint(huge), "MiB of strings and blobs in one call"},
      {one_call_prefix().arg(0).byte(8).uint(TraceReader::kMaxBytesPerCall + 1),
       "MiB of strings and blobs in one call"},
      {one_call_prefix().arg(0).byte(11).uint(huge), "array of 4611686018427387904 elements"},
      {one_call_prefix().arg(0).byte(15).uint(huge), "wide string of"},
      {one_call_prefix().arg(0).byte(9).uint(1).uint(1).uint(TraceReader::kMaxMetadataBytes),
       "signatures and properties above 64 MiB"},
  };
  for (const auto& [stream, message] : cases) {
    std::string error;
    EXPECT_EQ(read_all(snappy_container(stream.bytes()), error), Status::Error) << message;
    EXPECT_NE(error.find(message), std::string::npos) << error;
    EXPECT_NE(error.find("in call 0 (glFoo)"), std::string::npos) << error;
  }
  // An array count that fits but whose elements cross the per-call value limit.
  StreamWriter many = one_call_prefix();
  many.arg(0).byte(11).uint(TraceReader::kMaxValuesPerCall - 1).byte(11).uint(2);
  many.raw(std::string(TraceReader::kMaxValuesPerCall + 1, '\0')).end();
  std::string error;
  EXPECT_EQ(read_all(snappy_container(many.bytes()), error), Status::Error);
  EXPECT_NE(error.find("values in one call"), std::string::npos) << error;
}

TEST(BadInput, CallsThatNeverLeaveAreBounded) {
  StreamWriter w;
  w.header6().enter(0, 0, "f").end();
  for (size_t i = 0; i < TraceReader::kMaxPendingCalls; ++i) w.enter(0, 0).end();
  std::string error;
  EXPECT_EQ(read_all(snappy_container(w.bytes()), error), Status::Error);
  EXPECT_NE(error.find("entered without leaving"), std::string::npos) << error;
}

TEST(BadInput, SnappyChunkLengthsAreChecked) {
  std::string stream = one_call_prefix().end().bytes();
  std::string good = snappy_container(stream);
  std::string error;
  ASSERT_EQ(read_all(good, error), Status::End) << error;

  // A compressed length above what a 64 MiB chunk can compress to.
  std::string too_long = good;
  too_long.replace(2, 4, std::string("\xff\xff\xff\x7f", 4));
  EXPECT_EQ(read_all(too_long, error), Status::Error);
  EXPECT_NE(error.find("declares 2147483647 compressed bytes"), std::string::npos) << error;

  // An uncompressed length (Snappy's own preamble) that the compressed bytes cannot produce.
  std::string bomb = "at";
  std::string chunk = "\xff\xff\xff\x1f";  // preamble: 64 MiB - 1
  chunk += std::string("\x00x", 2);        // a 1-byte literal
  for (int i = 0; i < 4; ++i) bomb += char((chunk.size() >> (8 * i)) & 0xff);
  bomb += chunk;
  EXPECT_FALSE(TraceReader::open_memory(bomb, error));
  EXPECT_NE(error.find("declares 67108863 bytes from 6 compressed bytes"), std::string::npos)
      << error;

  // A chunk whose data is corrupt: a copy from before the start.
  std::string corrupt = "at";
  chunk = std::string("\x08\x01\x05", 3);  // length 8, then copy-1 length 4, offset 5
  for (int i = 0; i < 4; ++i) corrupt += char((chunk.size() >> (8 * i)) & 0xff);
  corrupt += chunk;
  EXPECT_FALSE(TraceReader::open_memory(corrupt, error));
  EXPECT_NE(error.find("corrupt Snappy chunk at file offset 2"), std::string::npos) << error;
}

// A cut at any byte: every call completed before the cut, then End, in every container.
void expect_cuts_give_prefixes(const std::string& file, const std::vector<size_t>& cuts) {
  std::string error;
  auto full_reader = TraceReader::open_memory(file, error);
  ASSERT_TRUE(full_reader) << error;
  Summary full = summarize(*full_reader);
  ASSERT_EQ(full.last, Status::End) << full.error;
  ASSERT_GT(full.lines.size(), 50u);
  size_t cuts_with_calls = 0, cuts_with_incomplete = 0;
  bool opened = false;
  for (size_t cut : cuts) {
    auto reader = TraceReader::open_memory(file.substr(0, cut), error);
    if (!reader) {
      // Only while the cut is inside the header: once open succeeds, longer cuts open too.
      EXPECT_FALSE(opened) << "cut " << cut << ": " << error;
      EXPECT_TRUE(error.find("header") != std::string::npos ||
                  error.find("empty file") != std::string::npos ||
                  error.find("too short") != std::string::npos)
          << "cut " << cut << ": " << error;
      continue;
    }
    opened = true;
    Summary s = summarize(*reader);
    EXPECT_EQ(s.last, Status::End) << "cut " << cut << ": " << s.error;
    ASSERT_LE(s.lines.size(), full.lines.size()) << "cut " << cut;
    cuts_with_calls += !s.lines.empty();
    cuts_with_incomplete += !s.complete.empty() && !s.complete.back();
    for (size_t i = 0; i < s.lines.size(); ++i) {
      if (s.complete[i]) {
        ASSERT_EQ(s.lines[i], full.lines[i]) << "cut " << cut << ", call " << i;
      } else {  // the one call whose LEAVE was cut: same number and function
        ASSERT_EQ(i + 1, s.lines.size()) << "cut " << cut;
        ASSERT_EQ(s.lines[i].substr(0, s.lines[i].find('(')),
                  full.lines[i].substr(0, full.lines[i].find('(')))
            << "cut " << cut;
      }
    }
  }
  // The cuts did reach the calls, and some fell between an ENTER and its LEAVE.
  EXPECT_GT(cuts_with_calls, cuts.size() / 4);
  EXPECT_GT(cuts_with_incomplete, 0u);
}

std::vector<size_t> cut_positions(size_t size, size_t step, size_t dense_from, size_t dense_to) {
  std::vector<size_t> cuts;
  for (size_t c = 0; c < size; c += step) cuts.push_back(c);
  for (size_t c = dense_from; c < std::min(dense_to, size); ++c) cuts.push_back(c);
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

TEST(Truncation, SnappyCutsGivePrefixes) {
  std::string file = read_file("gears.trace");
  expect_cuts_give_prefixes(file, cut_positions(file.size(), 211, file.size() - 1500, file.size()));
}

TEST(Truncation, SmallSnappyChunkCutsGivePrefixes) {
  // Chunk boundaries every 4 KiB, so cuts fall in lengths, preambles and chunk bodies alike.
  std::string file = snappy_container(snappy_stream(read_file("eglinfo.trace")), 4096);
  expect_cuts_give_prefixes(file, cut_positions(file.size(), 1, 0, 0));
}

TEST(Truncation, BrotliCutsGivePrefixes) {
  std::string file = read_file("gears.brotli.trace");
  expect_cuts_give_prefixes(file, cut_positions(file.size(), 97, file.size() - 800, file.size()));
}

TEST(Truncation, GzipCutsGivePrefixes) {
  std::string file = gzip_container(snappy_stream(read_file("eglinfo.trace")), 2);
  expect_cuts_give_prefixes(file, cut_positions(file.size(), 13, 0, 0));
}

// Random corruption never crashes or hangs; the reader ends with End or Error.
TEST(Corruption, RandomBytesNeverCrash) {
  std::mt19937 rng(12345);
  std::string stream = snappy_stream(read_file("eglinfo.trace"));
  std::string compressed = read_file("eglinfo.trace");
  for (int round = 0; round < 300; ++round) {
    std::string s = stream;
    std::string c = compressed;
    int flips = 1 + int(rng() % 8);
    for (int i = 0; i < flips; ++i) {
      s[rng() % s.size()] = char(rng());
      c[2 + rng() % (c.size() - 2)] = char(rng());
    }
    for (const std::string& file : {snappy_container(s, 1 + rng() % 5000), c, gzip_container(s)}) {
      std::string error;
      Status status = read_all(file, error);
      EXPECT_TRUE(status == Status::End || !error.empty());
    }
  }
}

// --- Value views --------------------------------------------------------------------------------

TEST(Value, NumericViewsConvertEveryNumericKind) {
  Value v;
  EXPECT_EQ(v.as_sint(), 0);
  v.kind = ValueKind::Bool;
  v.boolean = true;
  EXPECT_EQ(v.as_uint(), 1u);
  v.kind = ValueKind::SInt;
  v.sint = -3;
  EXPECT_EQ(v.as_double(), -3.0);
  EXPECT_EQ(v.as_uint(), uint64_t(-3));
  v.kind = ValueKind::Double;
  v.real = -2.75;
  EXPECT_EQ(v.as_sint(), -2);  // toward zero
  v.real = 1e300;
  EXPECT_EQ(v.as_sint(), INT64_MAX);
  EXPECT_EQ(v.as_uint(), UINT64_MAX);
  v.real = std::nan("");
  EXPECT_EQ(v.as_sint(), 0);
  v.kind = ValueKind::Pointer;
  v.uint = 0x1000;
  EXPECT_EQ(v.as_sint(), 0x1000);
  v.kind = ValueKind::String;
  v.bytes = "abc";
  EXPECT_EQ(v.as_sint(), 0);
  EXPECT_EQ(v.size(), 3u);
  EXPECT_EQ(std::string(static_cast<const char*>(v.data()), 3), "abc");
  v.kind = ValueKind::Array;
  EXPECT_EQ(v.data(), nullptr);
  EXPECT_EQ(v.size(), 0u);
}

}  // namespace
}  // namespace glpt::trace
