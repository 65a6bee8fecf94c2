// Rasterization, fog and per-fragment state: every setter's round trip through the glGet*
// queries (with the spec's type conversions), every error GL 1.5 names, and the initial values
// and implementation limits, which are Mesa llvmpipe's (read through OSMesa, Mesa 25.0.7).
#include <cmath>
#include <limits>
#include <vector>

#include "gl_test_context.hpp"

namespace {

constexpr GLint kIntMax = std::numeric_limits<GLint>::max();
// GL 2.0 enums, which GL 1.5 does not accept.
constexpr GLenum kMaxDrawBuffers = 0x8824;  // GL 2.0 draw buffers: glpt has one
constexpr GLenum kCurrentProgram = 0x8B8D;  // GL 2.0 shader state: glpt has none

std::vector<float> floats(GLenum pname, int n) {
  std::vector<float> v(16, -777.0f);
  glGetFloatv(pname, v.data());
  v.resize(static_cast<size_t>(n));
  return v;
}
float float1(GLenum pname) { return floats(pname, 1)[0]; }

std::vector<GLint> ints(GLenum pname, int n) {
  std::vector<GLint> v(16, -777);
  glGetIntegerv(pname, v.data());
  v.resize(static_cast<size_t>(n));
  return v;
}
GLint int1(GLenum pname) { return ints(pname, 1)[0]; }

bool bool1(GLenum pname) {
  GLboolean b = 77;
  glGetBooleanv(pname, &b);
  return b == GL_TRUE;
}

GLenum error() { return glGetError(); }

struct InitialValue {
  GLenum pname;
  std::vector<float> values;
};

// glGetFloatv of a fresh OSMesa context (Mesa 25.0.7, llvmpipe).
const InitialValue kMesaInitialValues[] = {
    {GL_ALIASED_POINT_SIZE_RANGE, {1, 256}},
    {GL_SMOOTH_POINT_SIZE_RANGE, {1, 256}},
    {GL_POINT_SIZE_GRANULARITY, {0.1f}},
    {GL_ALIASED_LINE_WIDTH_RANGE, {1, 255}},
    {GL_SMOOTH_LINE_WIDTH_RANGE, {1, 255}},
    {GL_SMOOTH_LINE_WIDTH_GRANULARITY, {0.1f}},
    {GL_MAX_MODELVIEW_STACK_DEPTH, {32}},
    {GL_MAX_PROJECTION_STACK_DEPTH, {32}},
    {GL_MAX_TEXTURE_STACK_DEPTH, {10}},
    {GL_SUBPIXEL_BITS, {8}},
    {GL_POINT_SIZE, {1}},
    {GL_POINT_SIZE_MIN, {0}},
    {GL_POINT_SIZE_MAX, {256}},
    {GL_POINT_FADE_THRESHOLD_SIZE, {1}},
    {GL_POINT_DISTANCE_ATTENUATION, {1, 0, 0}},
    {GL_LINE_WIDTH, {1}},
    {GL_LINE_STIPPLE_PATTERN, {65535}},
    {GL_LINE_STIPPLE_REPEAT, {1}},
    {GL_POLYGON_MODE, {GL_FILL, GL_FILL}},
    {GL_POLYGON_OFFSET_FACTOR, {0}},
    {GL_POLYGON_OFFSET_UNITS, {0}},
    {GL_FOG_MODE, {GL_EXP}},
    {GL_FOG_DENSITY, {1}},
    {GL_FOG_START, {0}},
    {GL_FOG_END, {1}},
    {GL_FOG_INDEX, {0}},
    {GL_FOG_COLOR, {0, 0, 0, 0}},
    {GL_FOG_COORDINATE_SOURCE, {GL_FRAGMENT_DEPTH}},
    {GL_ALPHA_TEST_FUNC, {GL_ALWAYS}},
    {GL_ALPHA_TEST_REF, {0}},
    {GL_STENCIL_FUNC, {GL_ALWAYS}},
    {GL_STENCIL_REF, {0}},
    {GL_STENCIL_VALUE_MASK, {255}},
    {GL_STENCIL_WRITEMASK, {255}},
    {GL_STENCIL_FAIL, {GL_KEEP}},
    {GL_STENCIL_PASS_DEPTH_FAIL, {GL_KEEP}},
    {GL_STENCIL_PASS_DEPTH_PASS, {GL_KEEP}},
    {GL_BLEND_SRC, {GL_ONE}},
    {GL_BLEND_DST, {GL_ZERO}},
    {GL_BLEND_SRC_RGB, {GL_ONE}},
    {GL_BLEND_DST_RGB, {GL_ZERO}},
    {GL_BLEND_SRC_ALPHA, {GL_ONE}},
    {GL_BLEND_DST_ALPHA, {GL_ZERO}},
    {GL_BLEND_EQUATION, {GL_FUNC_ADD}},
    {GL_BLEND_COLOR, {0, 0, 0, 0}},
    {GL_LOGIC_OP_MODE, {GL_COPY}},
    {GL_COLOR_WRITEMASK, {1, 1, 1, 1}},
    {GL_DEPTH_WRITEMASK, {1}},
    {GL_INDEX_WRITEMASK, {-1}},
    {GL_INDEX_CLEAR_VALUE, {0}},
    {GL_CURRENT_INDEX, {1}},
    {GL_ACCUM_CLEAR_VALUE, {0, 0, 0, 0}},
    {GL_CURRENT_SECONDARY_COLOR, {0, 0, 0, 1}},
    {GL_CURRENT_FOG_COORD, {0}},
    {GL_EDGE_FLAG, {1}},
    {GL_LIGHT_MODEL_COLOR_CONTROL, {GL_SINGLE_COLOR}},
};

TEST_F(GlTest, InitialStateAndLimitsAreMesas) {
  for (const InitialValue& want : kMesaInitialValues) {
    EXPECT_EQ(floats(want.pname, static_cast<int>(want.values.size())), want.values)
        << "pname 0x" << std::hex << want.pname;
    EXPECT_EQ(error(), GLenum{GL_NO_ERROR}) << "pname 0x" << std::hex << want.pname;
  }
  // Integer forms where they differ from the float one.
  EXPECT_EQ(int1(GL_INDEX_WRITEMASK), -1);
  EXPECT_EQ(int1(GL_SMOOTH_LINE_WIDTH_GRANULARITY), 0);  // 0.1 rounds to 0
  EXPECT_EQ(int1(GL_MAX_CLIP_PLANES), 6);                // the spec's minimum (Mesa: 8)
}

TEST_F(GlTest, UnknownPnameIsInvalidEnumAndWritesNothing) {
  GLint i = 5;
  GLfloat f = 5;
  GLboolean b = 5;
  GLdouble d = 5;
  glGetIntegerv(0x1234, &i);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glGetFloatv(kMaxDrawBuffers, &f);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glGetBooleanv(kCurrentProgram, &b);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glGetDoublev(0, &d);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(i, 5);
  EXPECT_EQ(f, 5.0f);
  EXPECT_EQ(b, 5);
  EXPECT_EQ(d, 5.0);
}

// ---- blending, logic op ------------------------------------------------------------------------

TEST_F(GlTest, BlendFuncSetsColourAndAlphaFactors) {
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(int1(GL_BLEND_SRC), GL_SRC_ALPHA);
  EXPECT_EQ(int1(GL_BLEND_DST), GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(int1(GL_BLEND_SRC_ALPHA), GL_SRC_ALPHA);
  EXPECT_EQ(int1(GL_BLEND_DST_ALPHA), GL_ONE_MINUS_SRC_ALPHA);
  // GL 1.4: source colour factors as source, destination ones as destination, constants.
  glBlendFunc(GL_SRC_COLOR, GL_DST_COLOR);
  EXPECT_EQ(int1(GL_BLEND_SRC_RGB), GL_SRC_COLOR);
  EXPECT_EQ(int1(GL_BLEND_DST_RGB), GL_DST_COLOR);
  glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_COLOR);
  EXPECT_EQ(ctx_.raster.ops.blend_src_rgb, uint32_t{GL_CONSTANT_ALPHA});
  EXPECT_EQ(ctx_.raster.ops.blend_dst_alpha, uint32_t{GL_ONE_MINUS_CONSTANT_COLOR});
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, BlendFuncSeparateAndFactorErrors) {
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
  EXPECT_EQ(ints(GL_BLEND_SRC_RGB, 1)[0], GL_SRC_ALPHA);
  EXPECT_EQ(ints(GL_BLEND_DST_RGB, 1)[0], GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(ints(GL_BLEND_SRC_ALPHA, 1)[0], GL_ONE);
  EXPECT_EQ(ints(GL_BLEND_DST_ALPHA, 1)[0], GL_ZERO);
  // Any invalid factor: GL_INVALID_ENUM and nothing changes.
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, 0x1234);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(int1(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
  glBlendFunc(GL_ZERO, GL_SRC_ALPHA_SATURATE);  // a source factor only in GL 1.5
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(int1(GL_BLEND_SRC), GL_SRC_ALPHA_SATURATE);
  glBlendFuncSeparateEXT(GL_ZERO, GL_ZERO, GL_ZERO, GL_ZERO);  // the EXT alias
  EXPECT_EQ(int1(GL_BLEND_SRC), GL_ZERO);
}

TEST_F(GlTest, BlendEquationSetsBothEquations) {
  for (GLenum mode : {GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX, GL_FUNC_ADD}) {
    glBlendEquation(mode);
    EXPECT_EQ(int1(GL_BLEND_EQUATION), static_cast<GLint>(mode));
    EXPECT_EQ(ctx_.raster.ops.blend_equation_rgb, mode);
    EXPECT_EQ(ctx_.raster.ops.blend_equation_alpha, mode);
  }
  glBlendEquation(GL_LOGIC_OP);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(int1(GL_BLEND_EQUATION), GL_FUNC_ADD);
}

TEST_F(GlTest, BlendEquationSeparateSetsEachEquationAndChecksBoth) {
  glBlendEquationSeparateEXT(GL_FUNC_SUBTRACT, GL_MAX);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(int1(GL_BLEND_EQUATION_RGB_EXT), GL_FUNC_SUBTRACT);
  EXPECT_EQ(int1(GL_BLEND_EQUATION_ALPHA_EXT), GL_MAX);
  // One invalid mode: GL_INVALID_ENUM and neither changes.
  glBlendEquationSeparateEXT(GL_FUNC_ADD, GL_LOGIC_OP);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glBlendEquationSeparateEXT(GL_ZERO, GL_FUNC_ADD);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(int1(GL_BLEND_EQUATION), GL_FUNC_SUBTRACT);
  EXPECT_EQ(int1(GL_BLEND_EQUATION_ALPHA_EXT), GL_MAX);
  glBlendEquation(GL_MIN);  // sets both
  EXPECT_EQ(int1(GL_BLEND_EQUATION_ALPHA_EXT), GL_MIN);
}

// EXT_stencil_two_side, as Mesa keeps it: the selected face takes glStencilFunc/Op/Mask and is the
// one queried; the selector is compiled into display lists and saved with the stencil group.
TEST_F(GlTest, StencilTwoSideSelectsTheFaceThatIsSetAndQueried) {
  EXPECT_EQ(int1(GL_ACTIVE_STENCIL_FACE_EXT), GL_FRONT);
  EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST_TWO_SIDE_EXT));
  glActiveStencilFaceEXT(GL_BACK);
  glStencilFunc(GL_LESS, 7, 0x3C);
  glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT);
  glStencilMask(0x0F);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(int1(GL_ACTIVE_STENCIL_FACE_EXT), GL_BACK);
  EXPECT_EQ(int1(GL_STENCIL_FUNC), GL_LESS);
  EXPECT_EQ(int1(GL_STENCIL_REF), 7);
  EXPECT_EQ(int1(GL_STENCIL_VALUE_MASK), 0x3C);
  EXPECT_EQ(int1(GL_STENCIL_FAIL), GL_INCR_WRAP);
  EXPECT_EQ(int1(GL_STENCIL_PASS_DEPTH_FAIL), GL_DECR_WRAP);
  EXPECT_EQ(int1(GL_STENCIL_PASS_DEPTH_PASS), GL_INVERT);
  EXPECT_EQ(int1(GL_STENCIL_WRITEMASK), 0x0F);
  glActiveStencilFaceEXT(GL_FRONT);  // the front face kept its initial state
  EXPECT_EQ(int1(GL_STENCIL_FUNC), GL_ALWAYS);
  EXPECT_EQ(int1(GL_STENCIL_WRITEMASK), 0xFF);
  glActiveStencilFaceEXT(GL_FRONT_AND_BACK);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(int1(GL_ACTIVE_STENCIL_FACE_EXT), GL_FRONT);

  glPushAttrib(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST_TWO_SIDE_EXT);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glActiveStencilFaceEXT(GL_BACK);
  glEndList();
  EXPECT_EQ(int1(GL_ACTIVE_STENCIL_FACE_EXT), GL_FRONT);
  glCallList(list);
  EXPECT_EQ(int1(GL_ACTIVE_STENCIL_FACE_EXT), GL_BACK);
  EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST_TWO_SIDE_EXT));
  glPopAttrib();
  EXPECT_EQ(int1(GL_ACTIVE_STENCIL_FACE_EXT), GL_FRONT);
  EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST_TWO_SIDE_EXT));
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, BlendColorIsClampedAndReadsAsColourIntegers) {
  glBlendColor(2.0f, -1.0f, 0.5f, 0.2f);
  EXPECT_EQ(floats(GL_BLEND_COLOR, 4), (std::vector<float>{1.0f, 0.0f, 0.5f, 0.2f}));
  // Colours as integers: 1 -> 2^31 - 1, and (2^31 - 1) * c truncated in between (Mesa's values).
  EXPECT_EQ(ints(GL_BLEND_COLOR, 4), (std::vector<GLint>{kIntMax, 0, 1073741823, 429496735}));
}

TEST_F(GlTest, LogicOpAcceptsTheSixteenOps) {
  for (GLenum op = GL_CLEAR; op <= GL_SET; ++op) {
    glLogicOp(op);
    EXPECT_EQ(int1(GL_LOGIC_OP_MODE), static_cast<GLint>(op));
  }
  glLogicOp(GL_SET + 1);
  glLogicOp(GL_ZERO);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(int1(GL_LOGIC_OP_MODE), GL_SET);
}

// ---- alpha, stencil, depth, masks -------------------------------------------------------------

TEST_F(GlTest, AlphaFuncClampsTheReference) {
  glAlphaFunc(GL_GEQUAL, 0.3f);
  EXPECT_EQ(int1(GL_ALPHA_TEST_FUNC), GL_GEQUAL);
  EXPECT_EQ(float1(GL_ALPHA_TEST_REF), 0.3f);
  EXPECT_EQ(int1(GL_ALPHA_TEST_REF), 644245119);  // a colour for integer queries (as Mesa)
  glAlphaFunc(GL_LESS, 1.5f);
  EXPECT_EQ(float1(GL_ALPHA_TEST_REF), 1.0f);
  glAlphaFunc(GL_LESS, -0.5f);
  EXPECT_EQ(float1(GL_ALPHA_TEST_REF), 0.0f);
  EXPECT_FALSE(bool1(GL_ALPHA_TEST_REF));
  glAlphaFunc(GL_ZERO, 0.5f);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(int1(GL_ALPHA_TEST_FUNC), GL_LESS);
  EXPECT_EQ(float1(GL_ALPHA_TEST_REF), 0.0f);
}

TEST_F(GlTest, StencilFuncOpAndMask) {
  glStencilFunc(GL_NOTEQUAL, 3, 0x0F);
  EXPECT_EQ(int1(GL_STENCIL_FUNC), GL_NOTEQUAL);
  EXPECT_EQ(int1(GL_STENCIL_REF), 3);
  EXPECT_EQ(int1(GL_STENCIL_VALUE_MASK), 0x0F);
  // The reference reads back clamped to the 8-bit stencil buffer's range; masks are unsigned
  // and saturate as integers (Mesa: 255, 0, 2147483647, 4294967295.0).
  glStencilFunc(GL_LESS, 300, 0xFFFFFFFFu);
  EXPECT_EQ(int1(GL_STENCIL_REF), 255);
  EXPECT_EQ(ctx_.raster.ops.stencil_ref, 300);
  EXPECT_EQ(int1(GL_STENCIL_VALUE_MASK), kIntMax);
  EXPECT_EQ(float1(GL_STENCIL_VALUE_MASK), 4294967295.0f);
  glStencilFunc(GL_LESS, -5, 1);
  EXPECT_EQ(int1(GL_STENCIL_REF), 0);
  glStencilFunc(GL_NEVER - 1, 1, 1);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});

  glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT);  // GL 1.4 wrapping ops
  EXPECT_EQ(ints(GL_STENCIL_FAIL, 1)[0], GL_INCR_WRAP);
  EXPECT_EQ(ints(GL_STENCIL_PASS_DEPTH_FAIL, 1)[0], GL_DECR_WRAP);
  EXPECT_EQ(ints(GL_STENCIL_PASS_DEPTH_PASS, 1)[0], GL_INVERT);
  glStencilOp(GL_KEEP, GL_ZERO, GL_ONE);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(int1(GL_STENCIL_FAIL), GL_INCR_WRAP);

  glStencilMask(0x1FF);
  EXPECT_EQ(int1(GL_STENCIL_WRITEMASK), 0x1FF);
  EXPECT_EQ(ctx_.raster.ops.stencil_write_mask, 0x1FFu);
}

TEST_F(GlTest, DepthAndColourWriteMasks) {
  glDepthMask(GL_FALSE);
  EXPECT_FALSE(bool1(GL_DEPTH_WRITEMASK));
  EXPECT_FALSE(ctx_.raster.ops.depth_write);
  glDepthMask(5);  // any nonzero GLboolean is true
  EXPECT_EQ(int1(GL_DEPTH_WRITEMASK), 1);
  glColorMask(2, 0, 1, 0);
  GLboolean b[4];
  glGetBooleanv(GL_COLOR_WRITEMASK, b);
  EXPECT_EQ(b[0], GL_TRUE);
  EXPECT_EQ(b[1], GL_FALSE);
  EXPECT_EQ(b[2], GL_TRUE);
  EXPECT_EQ(b[3], GL_FALSE);
  EXPECT_EQ(floats(GL_COLOR_WRITEMASK, 4), (std::vector<float>{1, 0, 1, 0}));
  EXPECT_EQ(ctx_.raster.ops.color_write, (std::array<bool, 4>{true, false, true, false}));
}

TEST_F(GlTest, ColourIndexStateIsKeptForQueries) {
  glIndexMask(0x5);
  EXPECT_EQ(int1(GL_INDEX_WRITEMASK), 5);
  glClearIndex(2.7f);  // truncated to an integer, as Mesa stores it
  EXPECT_EQ(int1(GL_INDEX_CLEAR_VALUE), 2);
  glClearIndex(-2.7f);
  EXPECT_EQ(float1(GL_INDEX_CLEAR_VALUE), -2.0f);
  glClearIndex(NAN);
  EXPECT_EQ(int1(GL_INDEX_CLEAR_VALUE), 0);
  glIndexf(2.5f);
  EXPECT_EQ(float1(GL_CURRENT_INDEX), 2.5f);
  EXPECT_EQ(int1(GL_CURRENT_INDEX), 3);
  glIndexub(200);
  EXPECT_EQ(float1(GL_CURRENT_INDEX), 200.0f);
  glIndexs(-7);
  EXPECT_EQ(float1(GL_CURRENT_INDEX), -7.0f);
  const GLdouble d = 2.75;
  glIndexdv(&d);
  EXPECT_EQ(float1(GL_CURRENT_INDEX), 2.75f);
  glFogf(GL_FOG_INDEX, 3.7f);
  EXPECT_EQ(float1(GL_FOG_INDEX), 3.7f);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, ClearAccumIsClampedToPlusMinusOne) {
  glClearAccum(2.0f, -2.0f, 0.5f, 0.001f);
  EXPECT_EQ(floats(GL_ACCUM_CLEAR_VALUE, 4), (std::vector<float>{1.0f, -1.0f, 0.5f, 0.001f}));
  EXPECT_EQ(ctx_.framebuffer.clear_accum, glm::vec4(1.0f, -1.0f, 0.5f, 0.001f));
  // Mesa's mapping: -1 is -(2^31 - 1), not the spec's -2^31.
  EXPECT_EQ(ints(GL_ACCUM_CLEAR_VALUE, 4),
            (std::vector<GLint>{kIntMax, -kIntMax, 1073741823, 2147483}));
}

TEST_F(GlTest, SampleCoverageIsClampedAndReadsBack) {
  EXPECT_EQ(float1(GL_SAMPLE_COVERAGE_VALUE), 1.0f);
  EXPECT_FALSE(bool1(GL_SAMPLE_COVERAGE_INVERT));
  glSampleCoverage(0.25f, GL_TRUE);
  EXPECT_EQ(float1(GL_SAMPLE_COVERAGE_VALUE), 0.25f);
  EXPECT_TRUE(bool1(GL_SAMPLE_COVERAGE_INVERT));
  glSampleCoverage(7.0f, GL_FALSE);
  EXPECT_EQ(float1(GL_SAMPLE_COVERAGE_VALUE), 1.0f);
  EXPECT_EQ(int1(GL_SAMPLE_BUFFERS), 0);
  EXPECT_EQ(int1(GL_SAMPLES), 0);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

// ---- fog ----------------------------------------------------------------------------------------

TEST_F(GlTest, FogParametersRoundTrip) {
  glFogi(GL_FOG_MODE, GL_LINEAR);
  EXPECT_EQ(int1(GL_FOG_MODE), GL_LINEAR);
  glFogf(GL_FOG_MODE, static_cast<float>(GL_EXP2));
  EXPECT_EQ(int1(GL_FOG_MODE), GL_EXP2);
  glFogf(GL_FOG_MODE, 2048.4f);  // converted to an integer enum first, as Mesa does
  EXPECT_EQ(int1(GL_FOG_MODE), GL_EXP);
  glFogf(GL_FOG_DENSITY, 0.25f);
  EXPECT_EQ(float1(GL_FOG_DENSITY), 0.25f);
  EXPECT_TRUE(bool1(GL_FOG_DENSITY));
  glFogf(GL_FOG_START, -3.5f);
  EXPECT_EQ(float1(GL_FOG_START), -3.5f);
  EXPECT_EQ(int1(GL_FOG_START), -4);  // nearest, halfway away from zero
  const GLint end = 7;
  glFogiv(GL_FOG_END, &end);
  EXPECT_EQ(float1(GL_FOG_END), 7.0f);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  EXPECT_EQ(int1(GL_FOG_COORDINATE_SOURCE), GL_FOG_COORDINATE);
  EXPECT_EQ(ctx_.raster.fog.coord_source, uint32_t{GL_FOG_COORDINATE});
  EXPECT_EQ(ctx_.raster.fog.mode, uint32_t{GL_EXP});
  EXPECT_EQ(ctx_.raster.fog.end, 7.0f);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, FogErrorsLeaveStateUnchanged) {
  glFogf(GL_FOG_DENSITY, -1.0f);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glFogf(GL_FOG_DENSITY, NAN);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  EXPECT_EQ(float1(GL_FOG_DENSITY), 1.0f);
  glFogi(GL_FOG_MODE, GL_ZERO);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glFogf(GL_FOG_MODE, NAN);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(int1(GL_FOG_MODE), GL_EXP);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_ZERO);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glFogi(GL_FOG_HINT, GL_NICEST);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glFogfv(GL_FOG_COLOR, nullptr);  // ignored, no crash
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, FogColourIsClampedAndIntegerColoursAreNormalized) {
  const GLfloat f[4] = {2.0f, -1.0f, 0.5f, 0.2f};
  glFogfv(GL_FOG_COLOR, f);
  EXPECT_EQ(floats(GL_FOG_COLOR, 4), (std::vector<float>{1.0f, 0.0f, 0.5f, 0.2f}));
  // glFogiv maps integers linearly ([-2^31, 2^31 - 1] to [-1, 1]), then clamps. Mesa's values.
  const GLint i[4] = {16777217, 1073741823, 123, kIntMax};
  glFogiv(GL_FOG_COLOR, i);
  EXPECT_EQ(floats(GL_FOG_COLOR, 4), (std::vector<float>{0x1p-7f, 0x1p-1f, 0x1.eep-25f, 1.0f}));
  // The scalar forms take the value as the red component, the rest 0 (as Mesa); glFogi does not
  // normalize.
  glFogf(GL_FOG_COLOR, 0.5f);
  EXPECT_EQ(floats(GL_FOG_COLOR, 4), (std::vector<float>{0.5f, 0, 0, 0}));
  glFogi(GL_FOG_COLOR, 1073741823);
  EXPECT_EQ(floats(GL_FOG_COLOR, 4), (std::vector<float>{1, 0, 0, 0}));
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

// ---- points, lines, polygons ------------------------------------------------------------------

TEST_F(GlTest, PolygonModePerFaceAndErrors) {
  glPolygonMode(GL_FRONT, GL_LINE);
  EXPECT_EQ(ints(GL_POLYGON_MODE, 2), (std::vector<GLint>{GL_LINE, GL_FILL}));
  glPolygonMode(GL_BACK, GL_POINT);
  EXPECT_EQ(ints(GL_POLYGON_MODE, 2), (std::vector<GLint>{GL_LINE, GL_POINT}));
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  EXPECT_EQ(floats(GL_POLYGON_MODE, 2), (std::vector<float>{GL_FILL, GL_FILL}));
  glPolygonMode(GL_LEFT, GL_LINE);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glPolygonMode(GL_FRONT, GL_ZERO);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(ctx_.raster.primitive.polygon_mode_front, uint32_t{GL_FILL});
  EXPECT_EQ(ctx_.raster.primitive.polygon_mode_back, uint32_t{GL_FILL});
}

TEST_F(GlTest, PolygonOffsetRoundTrips) {
  glPolygonOffset(1.5f, -2.0f);
  EXPECT_EQ(float1(GL_POLYGON_OFFSET_FACTOR), 1.5f);
  EXPECT_EQ(float1(GL_POLYGON_OFFSET_UNITS), -2.0f);
  EXPECT_EQ(int1(GL_POLYGON_OFFSET_FACTOR), 2);
  EXPECT_EQ(ctx_.raster.primitive.offset_units, -2.0f);
}

TEST_F(GlTest, LineWidthAndStipple) {
  for (float bad : {0.0f, -1.0f, NAN}) {
    glLineWidth(bad);
    EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  }
  EXPECT_EQ(float1(GL_LINE_WIDTH), 1.0f);
  glLineWidth(1000.0f);  // stored as given; the range applies when drawing
  EXPECT_EQ(float1(GL_LINE_WIDTH), 1000.0f);
  glLineWidth(2.5f);
  EXPECT_EQ(int1(GL_LINE_WIDTH), 3);
  EXPECT_EQ(ctx_.raster.primitive.line_width, 2.5f);

  glLineStipple(0, 0x1234);  // the factor is clamped to [1, 256]
  EXPECT_EQ(int1(GL_LINE_STIPPLE_REPEAT), 1);
  EXPECT_EQ(int1(GL_LINE_STIPPLE_PATTERN), 0x1234);
  glLineStipple(300, 0xF0F0);
  EXPECT_EQ(int1(GL_LINE_STIPPLE_REPEAT), 256);
  EXPECT_EQ(float1(GL_LINE_STIPPLE_PATTERN), 61680.0f);
  glLineStipple(-5, 0xF0F0);
  EXPECT_EQ(int1(GL_LINE_STIPPLE_REPEAT), 1);
  glLineStipple(3, 0xAAAA);
  EXPECT_EQ(ctx_.raster.primitive.line_stipple_factor, 3);
  EXPECT_EQ(ctx_.raster.primitive.line_stipple_pattern, 0xAAAA);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, PointSizeAndParameters) {
  glPointSize(0.0f);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glPointSize(300.0f);
  EXPECT_EQ(float1(GL_POINT_SIZE), 300.0f);

  for (GLenum pname : {GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE}) {
    glPointParameterf(pname, -1.0f);
    EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE}) << pname;
    glPointParameteri(pname, -1);
    EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE}) << pname;
  }
  glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
  glPointParameterfARB(GL_POINT_SIZE_MAX, 1000.0f);  // the ARB alias
  glPointParameteri(GL_POINT_FADE_THRESHOLD_SIZE, 3);
  EXPECT_EQ(float1(GL_POINT_SIZE_MIN), 2.0f);
  EXPECT_EQ(float1(GL_POINT_SIZE_MAX), 1000.0f);
  EXPECT_EQ(float1(GL_POINT_FADE_THRESHOLD_SIZE), 3.0f);
  glPointParameteri(GL_POINT_SIZE_MAX, 0);  // zero is allowed
  EXPECT_EQ(float1(GL_POINT_SIZE_MAX), 0.0f);

  const GLfloat attenuation[3] = {-1.0f, 0.5f, -2.0f};  // any values
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
  EXPECT_EQ(floats(GL_POINT_DISTANCE_ATTENUATION, 3), (std::vector<float>{-1.0f, 0.5f, -2.0f}));
  const GLint iattenuation[3] = {3, 4, 5};
  glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, iattenuation);
  EXPECT_EQ(ctx_.raster.primitive.point_distance_attenuation, glm::vec3(3, 4, 5));
  glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 2.0f);  // (2, 0, 0), as Mesa
  EXPECT_EQ(floats(GL_POINT_DISTANCE_ATTENUATION, 3), (std::vector<float>{2, 0, 0}));
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});

  // ARB_point_sprite's origin, as GL 2.0 added it: two values, others GL_INVALID_VALUE (Mesa).
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(ctx_.raster.primitive.point_sprite_coord_origin, GLenum{GL_LOWER_LEFT});
  glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, 0x8CA3);  // GL_STENCIL_BACK_REF
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, std::nanf(""));
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  EXPECT_EQ(ctx_.raster.primitive.point_sprite_coord_origin, GLenum{GL_LOWER_LEFT});
  glPointParameterfv(GL_POINT_SIZE_MIN, nullptr);  // ignored, no crash
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, StateCommandsAreInvalidBetweenBeginAndEnd) {
  glBegin(GL_POINTS);
  glLineWidth(2.0f);
  glFogf(GL_FOG_DENSITY, 0.5f);
  glBlendFunc(GL_ONE, GL_ONE);
  glClipPlane(GL_CLIP_PLANE0, std::array<GLdouble, 4>{1, 0, 0, 0}.data());
  glEnd();
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(float1(GL_LINE_WIDTH), 1.0f);
  EXPECT_EQ(float1(GL_FOG_DENSITY), 1.0f);
  EXPECT_EQ(int1(GL_BLEND_SRC), GL_ONE);
  EXPECT_EQ(int1(GL_BLEND_DST), GL_ZERO);
}

// ---- query conversions
// ---------------------------------------------------------------------------

TEST_F(GlTest, DepthRangeSaturatesNanAndInfinityAsMesaDoes) {
  // OSMesa 25 reads back glDepthRange(NaN, Inf) as (0, 1) and (-Inf, NaN) as (0, 0): a NaN
  // never reaches the viewport (Vulkan requires minDepth and maxDepth in [0, 1]).
  GLdouble range[2] = {-1, -1};
  glDepthRange(std::nan(""), HUGE_VAL);
  glGetDoublev(GL_DEPTH_RANGE, range);
  EXPECT_EQ(range[0], 0.0);
  EXPECT_EQ(range[1], 1.0);
  glDepthRange(-HUGE_VAL, std::nan(""));
  glGetDoublev(GL_DEPTH_RANGE, range);
  EXPECT_EQ(range[0], 0.0);
  EXPECT_EQ(range[1], 0.0);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, QueriesConvertBetweenTypes) {
  // Colours (and normals, depth values) as integers: Mesa's mapping in (-1, 1].
  glClearColor(0.1f, 0.3f, 0.7f, 0.9f);
  EXPECT_EQ(ints(GL_COLOR_CLEAR_VALUE, 4),
            (std::vector<GLint>{214748367, 644245119, 1503238527, 1932735231}));
  glClearColor(0.0f, 1.0f, 0.0f, 0.0f);
  EXPECT_EQ(ints(GL_COLOR_CLEAR_VALUE, 2), (std::vector<GLint>{0, kIntMax}));
  glDepthRange(0.25, 0.8);
  EXPECT_EQ(ints(GL_DEPTH_RANGE, 2), (std::vector<GLint>{536870911, 1717986943}));
  glNormal3f(0.6f, -0.8f, 0.0f);
  EXPECT_EQ(ints(GL_CURRENT_NORMAL, 3), (std::vector<GLint>{1288490239, -1717986943, 0}));
  glSecondaryColor3f(2.0f, -1.0f, 0.5f);  // stored unclamped; integers saturate
  EXPECT_EQ(ints(GL_CURRENT_SECONDARY_COLOR, 4),
            (std::vector<GLint>{kIntMax, -kIntMax, 1073741823, kIntMax}));
  // Floats as booleans: nonzero is true.
  glFogf(GL_FOG_END, 0.0f);
  EXPECT_FALSE(bool1(GL_FOG_END));
  glFogf(GL_FOG_END, -0.001f);
  EXPECT_TRUE(bool1(GL_FOG_END));
  // Floats as integers: nearest, halfway away from zero.
  glFogf(GL_FOG_START, 2.5f);
  EXPECT_EQ(int1(GL_FOG_START), 3);
  glFogf(GL_FOG_START, -2.5f);
  EXPECT_EQ(int1(GL_FOG_START), -3);
  glFogf(GL_FOG_START, 0.49999997f);
  EXPECT_EQ(int1(GL_FOG_START), 0);
  glFogf(GL_FOG_START, 1e20f);
  EXPECT_EQ(int1(GL_FOG_START), kIntMax);
  // Doubles are exact; enums and booleans read as numbers.
  glFogf(GL_FOG_START, 0.1f);
  GLdouble d = 0;
  glGetDoublev(GL_FOG_START, &d);
  EXPECT_EQ(d, static_cast<double>(0.1f));
  glGetDoublev(GL_FOG_MODE, &d);
  EXPECT_EQ(d, double{GL_EXP});
  EXPECT_TRUE(bool1(GL_FOG_MODE));
  EXPECT_EQ(float1(GL_EDGE_FLAG), 1.0f);
  EXPECT_EQ(float1(GL_LINE_STIPPLE), 0.0f);  // a capability reads as a boolean
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, TransposedMatrixQueries) {
  const GLfloat m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  glLoadMatrixf(m);
  GLfloat t[16];
  glGetFloatv(GL_TRANSPOSE_MODELVIEW_MATRIX, t);
  const GLfloat want[16] = {1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 4, 8, 12, 16};
  for (int i = 0; i < 16; ++i) EXPECT_EQ(t[i], want[i]) << i;
  glMatrixMode(GL_PROJECTION);
  glLoadTransposeMatrixf(m);
  glGetFloatv(GL_TRANSPOSE_PROJECTION_MATRIX, t);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(t[i], m[i]) << i;
  glMatrixMode(GL_TEXTURE);
  glTranslatef(1, 2, 3);
  glGetFloatv(GL_TRANSPOSE_TEXTURE_MATRIX, t);
  EXPECT_EQ(t[3], 1.0f);
  EXPECT_EQ(t[7], 2.0f);
  EXPECT_EQ(t[11], 3.0f);
}

// ---- clip planes ------------------------------------------------------------------------------

TEST_F(GlTest, ClipPlanesAreStoredInEyeSpace) {
  glTranslatef(0.0f, 0.0f, -5.0f);         // eye = object + (0, 0, -5)
  const GLdouble plane[4] = {0, 0, 1, 2};  // z >= -2 in object space
  glClipPlane(GL_CLIP_PLANE2, plane);
  GLdouble got[4];
  glGetClipPlane(GL_CLIP_PLANE2, got);
  // In eye space: z_eye + 5 >= -2, i.e. (0, 0, 1, 7).
  EXPECT_EQ(got[0], 0.0);
  EXPECT_EQ(got[1], 0.0);
  EXPECT_EQ(got[2], 1.0);
  EXPECT_EQ(got[3], 7.0);
  EXPECT_EQ(ctx_.transform.clip_planes[2], glm::vec4(0, 0, 1, 7));
  glEnable(GL_CLIP_PLANE2);
  EXPECT_TRUE(glIsEnabled(GL_CLIP_PLANE2));
  EXPECT_EQ(ctx_.transform.clip_plane_mask, 1u << 2);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, ClipPlaneErrors) {
  const GLdouble plane[4] = {1, 0, 0, 0};
  glClipPlane(GL_CLIP_PLANE0 + 6, plane);  // GL_MAX_CLIP_PLANES is 6
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glClipPlane(GL_CLIP_PLANE0 - 1, plane);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  GLdouble got[4] = {9, 9, 9, 9};
  glGetClipPlane(GL_CLIP_PLANE0 + 6, got);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(got[0], 9.0);
  glClipPlane(GL_CLIP_PLANE0, nullptr);  // ignored, no crash
  glGetClipPlane(GL_CLIP_PLANE0, nullptr);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

// ---- display lists ------------------------------------------------------------------------------

TEST_F(GlTest, StateCommandsCompileIntoDisplayLists) {
  const GLfloat fog_color[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  const GLfloat attenuation[3] = {1.0f, 0.5f, 0.25f};
  const GLdouble plane[4] = {1, 0, 0, 0};
  glNewList(1, GL_COMPILE);
  glFogfv(GL_FOG_COLOR, fog_color);
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glStencilOp(GL_ZERO, GL_INCR_WRAP, GL_REPLACE);
  glClipPlane(GL_CLIP_PLANE1, plane);
  glSecondaryColor3ub(255, 0, 0);
  glEndList();
  EXPECT_EQ(floats(GL_FOG_COLOR, 4), (std::vector<float>{0, 0, 0, 0}));  // not executed yet
  EXPECT_EQ(int1(GL_BLEND_SRC), GL_ONE);
  glCallList(1);
  EXPECT_EQ(floats(GL_FOG_COLOR, 4), (std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f}));
  EXPECT_EQ(floats(GL_POINT_DISTANCE_ATTENUATION, 3), (std::vector<float>{1.0f, 0.5f, 0.25f}));
  EXPECT_EQ(int1(GL_BLEND_SRC), GL_SRC_ALPHA);
  EXPECT_EQ(int1(GL_STENCIL_PASS_DEPTH_FAIL), GL_INCR_WRAP);
  EXPECT_EQ(ctx_.transform.clip_planes[1], glm::vec4(1, 0, 0, 0));
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 4), (std::vector<float>{1, 0, 0, 1}));
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

}  // namespace
