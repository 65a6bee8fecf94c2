// The GL_FEEDBACK and GL_SELECT render modes (GL 1.5 5.2, 5.3) against real Mesa: the command
// sequences of mesa_reference/render_mode_sequences.inc run on glpt and must report what
// OSMesa (Mesa 25.0.7) reported for them (mesa_reference/mesa_render_mode_probe.c printed
// mesa_reference/mesa_render_mode_expected.inc), value for value and bit for bit.
#include <cmath>
#include <cstring>
#include <string>

#include "gl_shim/frame/headless_target.hpp"
#include "gl_test_context.hpp"

namespace {

#include "mesa_reference/render_mode_sequences.inc"

struct Expected {
  const char* name;
  int return_count;
  int returns[RM_MAX_RETURNS];
  int error_count;
  GLenum errors[RM_MAX_ERRORS];
  int value_count;
  unsigned values[RM_MAX_VALUES];
};

const Expected kExpected[] = {
#include "mesa_reference/mesa_render_mode_expected.inc"
};

static_assert(std::size(kExpected) == std::size(kRenderModeSequences));

// A context on a drawable of the probe's size (feedback y goes through the drawable height).
class RenderModeTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glpt::make_current_headless(ctx_, target_);
  }
  void TearDown() override {
    ctx_.target = nullptr;
    GlTest::TearDown();
  }
  glpt::HeadlessTarget target_{kRmWidth, kRmHeight};
};

class MesaRenderModeTest : public RenderModeTest, public ::testing::WithParamInterface<size_t> {};

// A logged value: a selection value as an integer, a feedback value as a float (bits too when
// `bits`). Small integers that are not float bit patterns print as integers.
std::string describe(unsigned value, bool is_float, bool bits = true) {
  if (!is_float && value < 0x01000000u) return std::to_string(value);
  float f;
  std::memcpy(&f, &value, sizeof f);
  char text[64];
  if (bits)
    std::snprintf(text, sizeof text, "%.9g (0x%08x)", double(f), value);
  else
    std::snprintf(text, sizeof text, "%.9g", double(f));
  return text;
}

TEST_P(MesaRenderModeTest, ReportsWhatMesaReports) {
  const size_t s = GetParam();
  const Expected& want = kExpected[s];
  ASSERT_STREQ(want.name, kRenderModeSequences[s].name);
  static RenderModeLog log;
  log = RenderModeLog{};
  kRenderModeSequences[s].run(&log);
  ASSERT_EQ(log.return_count, want.return_count);
  for (int i = 0; i < log.return_count; ++i)
    EXPECT_EQ(log.returns[i], want.returns[i]) << "glRenderMode / query result " << i;
  ASSERT_EQ(log.error_count, want.error_count);
  for (int i = 0; i < log.error_count; ++i)
    EXPECT_EQ(log.errors[i], want.errors[i]) << "error noted " << i;
  if (log.value_count != want.value_count) {
    std::string got, mesa;
    for (int i = 0; i < log.value_count; ++i)
      got += " " + describe(log.values[i], log.is_float[i], false);
    for (int i = 0; i < want.value_count; ++i)
      mesa += " " + describe(want.values[i], true, false);
    FAIL() << log.value_count << " values:" << got << "\nMesa's " << want.value_count
           << " values:" << mesa;
  }
  int mismatches = 0;
  for (int i = 0; i < log.value_count && mismatches < 20; ++i) {
    if (log.values[i] == want.values[i]) continue;
    ++mismatches;
    ADD_FAILURE() << "value " << i << ": " << describe(log.values[i], log.is_float[i])
                  << ", Mesa " << describe(want.values[i], log.is_float[i]);
  }
}

INSTANTIATE_TEST_SUITE_P(Sequences, MesaRenderModeTest,
                         ::testing::Range(size_t{0}, std::size(kRenderModeSequences)),
                         [](const ::testing::TestParamInfo<size_t>& info) {
                           return std::string(kRenderModeSequences[info.param].name);
                         });

}  // namespace
