// Matrix arithmetic, clip planes and light positions bit for bit as real Mesa computes them.
// The command sequences are in mesa_reference/matrix_sequences.inc; the expected values were
// printed by OSMesa (Mesa 25.0.7) running the same sequences (mesa_reference/mesa_matrix_probe.c).
#include <cstring>
#include <string>

#include "gl_test_context.hpp"

namespace {

#include "mesa_reference/matrix_sequences.inc"

struct Expected {
  const char* name;
  float modelview[16];
  float projection[16];
  float texture[16];
  float clip_planes[8];
  float light[7];  // GL_LIGHT1 position, spot direction
  bool no_error;
};

const Expected kExpected[] = {
#include "mesa_reference/mesa_matrix_expected.inc"
};

static_assert(std::size(kExpected) == std::size(kSequences));

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof(u));
  return u;
}

void expect_bits(const char* what, const float* got, const float* want, int n) {
  for (int i = 0; i < n; ++i)
    EXPECT_EQ(bits(got[i]), bits(want[i]))
        << what << "[" << i << "]: got " << got[i] << ", Mesa " << want[i];
}

class MesaMatrixTest : public GlTest, public ::testing::WithParamInterface<size_t> {};

TEST_P(MesaMatrixTest, MatchesMesaBitForBit) {
  const size_t i = GetParam();
  const Expected& want = kExpected[i];
  ASSERT_STREQ(want.name, kSequences[i].name);
  kSequences[i].run();
  float m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  expect_bits("modelview", m, want.modelview, 16);
  glGetFloatv(GL_PROJECTION_MATRIX, m);
  expect_bits("projection", m, want.projection, 16);
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  expect_bits("texture", m, want.texture, 16);
  float planes[8];
  for (int p = 0; p < 2; ++p) {
    GLdouble e[4];
    glGetClipPlane(GL_CLIP_PLANE0 + p, e);
    for (int k = 0; k < 4; ++k) planes[p * 4 + k] = static_cast<float>(e[k]);
  }
  expect_bits("clip planes", planes, want.clip_planes, 8);
  float light[7];
  glGetLightfv(GL_LIGHT1, GL_POSITION, light);
  glGetLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, light + 4);
  expect_bits("light", light, want.light, 7);
  EXPECT_EQ(glGetError() == GL_NO_ERROR, want.no_error);
}

INSTANTIATE_TEST_SUITE_P(Sequences, MesaMatrixTest,
                         ::testing::Range(size_t{0}, std::size(kSequences)),
                         [](const ::testing::TestParamInfo<size_t>& info) {
                           return std::string(kSequences[info.param].name);
                         });

}  // namespace
