// Fixed-function state after command sequences (with errors), read back with glGetFloatv and
// glGetIntegerv, compared value for value with what real Mesa reports. The sequences are in
// mesa_reference/state_sequences.inc; OSMesa (Mesa 25.0.7) printed the expected values
// (mesa_reference/mesa_state_probe.c).
#include <cstring>
#include <string>

#include "gl_test_context.hpp"

namespace {

#include "mesa_reference/state_sequences.inc"

struct Expected {
  const char* name;
  int error_count;
  GLenum errors[MAX_NOTED_ERRORS];
  float floats[STATE_VALUES_READ];
  GLint integers[STATE_VALUES_READ];
  GLenum query_error;
};

const Expected kExpected[] = {
#include "mesa_reference/mesa_state_expected.inc"
};

static_assert(std::size(kExpected) == std::size(kStateSequences));

class MesaStateTest : public GlTest, public ::testing::WithParamInterface<size_t> {};

TEST_P(MesaStateTest, ReadsBackWhatMesaReports) {
  const size_t s = GetParam();
  const Expected& want = kExpected[s];
  ASSERT_STREQ(want.name, kStateSequences[s].name);
  NotedErrors errors{};
  if (kStateSequences[s].run) kStateSequences[s].run(&errors);
  ASSERT_EQ(errors.count, want.error_count);
  for (int i = 0; i < errors.count; ++i)
    EXPECT_EQ(errors.errors[i], want.errors[i]) << "error after step " << i;
  int k = 0;
  for (const auto& p : kStatePnames) {
    float f[4];
    GLint n[4];
    glGetFloatv(p.pname, f);
    glGetIntegerv(p.pname, n);
    for (int i = 0; i < p.count; ++i, ++k) {
      EXPECT_EQ(std::memcmp(&f[i], &want.floats[k], sizeof(float)), 0)
          << "pname 0x" << std::hex << p.pname << std::dec << "[" << i << "] float " << f[i]
          << ", Mesa " << want.floats[k];
      EXPECT_EQ(n[i], want.integers[k])
          << "pname 0x" << std::hex << p.pname << std::dec << "[" << i << "] integer";
    }
  }
  EXPECT_EQ(k, STATE_VALUES_READ);
  EXPECT_EQ(glGetError(), want.query_error);
}

INSTANTIATE_TEST_SUITE_P(Sequences, MesaStateTest,
                         ::testing::Range(size_t{0}, std::size(kStateSequences)),
                         [](const ::testing::TestParamInfo<size_t>& info) {
                           return std::string(kStateSequences[info.param].name);
                         });

}  // namespace
