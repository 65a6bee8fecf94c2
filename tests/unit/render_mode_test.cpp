// The GL_FEEDBACK and GL_SELECT render modes (GL 1.5 5.2, 5.3) against real Mesa: the command
// sequences of mesa_reference/render_mode_sequences.inc run on glpt and must report what
// OSMesa (Mesa 25.0.7) reported for them (mesa_reference/mesa_render_mode_probe.c printed
// mesa_reference/mesa_render_mode_expected.inc), value for value and bit for bit.
#include <cmath>
#include <cstring>
#include <string>

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
class RenderModeTest : public HeadlessGlTest {
 protected:
  RenderModeTest() : HeadlessGlTest(kRmWidth, kRmHeight) {}
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
    // Appended, not `" " + describe(...)`: GCC 12 -O3 reports a false -Wrestrict there (GCC bug
    // 105329), which fails the Release build under -Werror.
    for (int i = 0; i < log.value_count; ++i)
      got.append(" ").append(describe(log.values[i], log.is_float[i], false));
    for (int i = 0; i < want.value_count; ++i)
      mesa.append(" ").append(describe(want.values[i], true, false));
    FAIL() << log.value_count << " values:" << got << "\nMesa's " << want.value_count
           << " values:" << mesa;
  }
  int mismatches = 0;
  for (int i = 0; i < log.value_count && mismatches < 20; ++i) {
    if (log.values[i] == want.values[i]) continue;
    ++mismatches;
    ADD_FAILURE() << "value " << i << ": " << describe(log.values[i], log.is_float[i]) << ", Mesa "
                  << describe(want.values[i], log.is_float[i]);
  }
}

// What selection and feedback draw goes nowhere near the frame record (GL 1.5 5.2, 5.3: no
// fragments are produced); back in GL_RENDER the same commands are recorded again.
void draw_everything() {
  static const float positions[] = {1, 1, 5, 1, 5, 5};
  // 8 rows of one byte, each padded to GL_UNPACK_ALIGNMENT's default 4.
  static const GLubyte bitmap[8 * 4] = {0xff, 0, 0, 0, 0x81, 0, 0, 0, 0x81, 0, 0, 0, 0x81, 0, 0, 0,
                                        0x81, 0, 0, 0, 0x81, 0, 0, 0, 0x81, 0, 0, 0, 0xff, 0, 0, 0};
  static const GLubyte pixels[4 * 4 * 4] = {};
  static const float control[] = {1, 1, 0, 5, 5, 0};
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(1, 1);
  glVertex2f(5, 1);
  glVertex2f(5, 5);
  glEnd();
  glRectf(2, 2, 8, 8);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisableClientState(GL_VERTEX_ARRAY);
  glCallList(1);
  glRasterPos2f(3, 3);
  glBitmap(8, 8, 0, 0, 1, 1, bitmap);
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, control);
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(4, 0, 1);
  glEvalMesh1(GL_LINE, 0, 4);
  glDisable(GL_MAP1_VERTEX_3);
}

TEST_F(RenderModeTest, SelectionAndFeedbackRecordNothing) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, kRmWidth, 0, kRmHeight, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glNewList(1, GL_COMPILE);
  glBegin(GL_POINTS);
  glVertex2f(4, 4);
  glEnd();
  glEndList();
  static GLfloat feedback[4096];
  static GLuint selection[64];
  glFeedbackBuffer(4096, GL_2D, feedback);
  glSelectBuffer(64, selection);
  auto& commands = ctx_.recorder.record().commands;
  commands.clear();
  glRenderMode(GL_FEEDBACK);
  draw_everything();
  const GLint values = glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  draw_everything();
  const GLint hits = glRenderMode(GL_RENDER);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_TRUE(commands.empty()) << commands.size() << " commands recorded";
  // Everything was reported instead: polygons, lines, points and the three pixel tokens.
  EXPECT_GT(values, 60);
  EXPECT_EQ(hits, 1);
  int pixel_tokens = 0;
  for (GLint i = 0; i < values; ++i)
    if (feedback[i] == float(GL_BITMAP_TOKEN) || feedback[i] == float(GL_DRAW_PIXEL_TOKEN) ||
        feedback[i] == float(GL_COPY_PIXEL_TOKEN))
      ++pixel_tokens;
  EXPECT_EQ(pixel_tokens, 3);
  draw_everything();
  EXPECT_GE(commands.size(), 8u);
}

INSTANTIATE_TEST_SUITE_P(Sequences, MesaRenderModeTest,
                         ::testing::Range(size_t{0}, std::size(kRenderModeSequences)),
                         [](const ::testing::TestParamInfo<size_t>& info) {
                           return std::string(kRenderModeSequences[info.param].name);
                         });

}  // namespace
