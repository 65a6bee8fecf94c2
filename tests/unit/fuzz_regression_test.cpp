// What the GL call fuzzer (tests/fuzz/gl_call_fuzz.cpp) found in the front end, one test each:
// undefined behaviour (UBSan fails these in the sanitizer build) or a crash, now the GL error the
// spec names.
#include <cmath>
#include <limits>

#include "gl_shim/frame/clear_fallback.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_test_context.hpp"

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// An enum given as a float that no GLint holds was converted to GLenum directly (undefined).
// Mesa converts (GLenum)(GLint) value: such a value names no enum.
TEST_F(GlTest, LightModelColorControlFromAnyFloatIsAnEnumOrInvalid) {
  for (float v : {-3.0f, kNaN, kInf, -kInf, 1e38f, 4.5e9f}) {
    glLightModelfv(GL_LIGHT_MODEL_COLOR_CONTROL, &v);
    EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM}) << v;
  }
  const float separate = float(GL_SEPARATE_SPECULAR_COLOR);
  glLightModelfv(GL_LIGHT_MODEL_COLOR_CONTROL, &separate);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLint control = 0;
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &control);
  EXPECT_EQ(control, GL_SEPARATE_SPECULAR_COLOR);
}

// A compiled array draw of no vertices was replayed with memcpy from and to null pointers
// (undefined even for zero bytes). It draws nothing, without an error.
TEST_F(GlTest, CompiledEmptyArrayDrawReplays) {
  const float vertices[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, vertices);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_FLOAT, 0, vertices);
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_TRIANGLES, 0, 0);
  glEndList();
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

// glCallLists with GL_FLOAT names converted any float to GLuint (undefined for negative ones,
// NaN, infinities). As Mesa: (GLint) name; those no GLint holds call no list.
TEST_F(GlTest, CallListsWithFloatNamesThatNoIntegerHolds) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glColor3f(0.25f, 0.5f, 0.75f);
  glEndList();
  const GLfloat names[] = {-1.0f, -1.7e38f, kNaN, kInf, 1e20f};
  glCallLists(5, GL_FLOAT, names);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLfloat color[4] = {};
  glGetFloatv(GL_CURRENT_COLOR, color);
  EXPECT_EQ(color[0], 1.0f);                // no list ran
  const GLfloat name = float(list) + 0.5f;  // truncated, as (GLint) does
  glCallLists(1, GL_FLOAT, &name);
  glGetFloatv(GL_CURRENT_COLOR, color);
  EXPECT_EQ(color[0], 0.25f);
}

// glClearColor keeps NaN; a context without a renderer converted it to a byte (undefined) when
// the frame ended. It clears to 0, as the renderer's Vulkan UNORM conversion makes it.
TEST(ClearFallbackFuzzRegression, NaNClearColourClearsToZero) {
  glpt::rec::FrameRecord record;
  glpt::rec::Clear clear;
  clear.mask = GL_COLOR_BUFFER_BIT;
  clear.color = {kNaN, 0.5f, -kNaN, 1.0f};
  record.commands.push_back(clear);
  glpt::ClearFallback fallback;
  glpt::HeadlessTarget target(2, 1);
  fallback.end_frame(record, 2, 1, &target);
  ASSERT_EQ(target.presented().size(), 8u);
  EXPECT_EQ(target.presented()[0], 0);
  EXPECT_EQ(target.presented()[1], 128);
  EXPECT_EQ(target.presented()[2], 0);
  EXPECT_EQ(target.presented()[3], 255);
  glpt::FramebufferPixels pixels;
  fallback.read(glpt::rec::PixelKind::kColor, 0, 0, 1, 1, 2, 1, pixels);
  ASSERT_EQ(pixels.color.size(), 1u);
  EXPECT_EQ(pixels.color[0].r, 0.0f);
}

}  // namespace
