// Random calls through the generated dispatch: every command with arguments of random kinds and
// values (NULL, short arrays and blobs, huge and negative counts, NaN), into glpt's front end.
// Nothing may crash: conversions pad what GL reads, and GL validates the rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "gl/gl_enums.h"
#include "replay/backend.hpp"
#include "replay/replayer.hpp"
#include "tests/replay/call_builder.hpp"

namespace {

using namespace glpt_test;

trace::Value random_value(std::mt19937& rng, int depth = 0) {
  static const int64_t kInteresting[] = {
      0, 1, 2, 3, 4, -1, GL_TEXTURE_2D, GL_RGBA, GL_FLOAT, 64, 255, 1 << 20, INT32_MAX, -65536};
  switch (rng() % (depth > 0 ? 5 : 7)) {
    case 0:
      return null();
    case 1:
      return sint(kInteresting[rng() % std::size(kInteresting)]);
    case 2:
      return uintv(rng() % 0x10000);
    case 3:
      return real(rng() % 4 == 0 ? std::nan("") : static_cast<double>(rng() % 200) - 100.0);
    case 4: {
      std::string bytes(rng() % 40, '\0');
      for (char& c : bytes) c = static_cast<char>(rng());
      return blob(bytes.data(), bytes.size());
    }
    case 5: {
      trace::Value a = array({});
      const size_t n = rng() % 20;
      for (size_t i = 0; i < n; ++i) a.elements.push_back(random_value(rng, depth + 1));
      return a;
    }
    default:
      return pointer(rng() % 64);
  }
}

TEST(ReplayRandomCalls, NeverCrash) {
  setenv("GLPT_MODE", "raster", 1);
  std::string error;
  auto backend = glpt::replay::create_glpt_backend(&error);
  ASSERT_TRUE(backend) << error;
  glpt::replay::Replayer replayer(
      *backend, [](uint64_t) { return true; },
      [](uint64_t, const glpt::replay::FrameImage&, std::string*) { return true; });
  CallBuilder b;
  auto replay = [&](const trace::Call& call) { ASSERT_TRUE(replayer.replay(call, &error)); };
  replay(b.call("glXCreateContext", {pointer(1), pointer(2), pointer(0), sint(1)}, pointer(3)));
  replay(b.call("glXMakeCurrent", {pointer(1), uintv(4), pointer(3)}, sint(1)));
  replay(b.call("glViewport", {sint(0), sint(0), sint(32), sint(32)}));
  std::mt19937 rng(12345);
  for (int i = 0; i < 20000; ++i) {
    const auto& entry = glpt::replay::kDispatchTable[rng() % glpt::replay::kDispatchTableSize];
    const std::string name = entry.name;
    // The surface grows with glViewport (to 2^25 pixels): not what this test is about.
    if (name == "glViewport") continue;
    std::vector<trace::Value> args;
    const size_t n = rng() % 12;
    for (size_t a = 0; a < n; ++a) args.push_back(random_value(rng));
    SCOPED_TRACE(name);
    if (std::getenv("RANDOM_CALLS_TRACE")) std::fprintf(stderr, "%d %s\n", i, name.c_str());
    replay(b.call(name, std::move(args), sint(static_cast<int64_t>(rng() % 8))));
    if (i % 500 == 0) replay(b.call("glXSwapBuffers", {pointer(1), uintv(4)}));
  }
}

}  // namespace
