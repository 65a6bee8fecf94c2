// glBitmap, glDrawPixels, glCopyPixels, glAccum, glClearAccum, glPixelZoom as the front end
// records them (GL 1.5 3.6-3.7, 4.2.3-4.2.4, 4.3.3): their errors, where the pixels land, the
// image as unpacked, and the state snapshot they are drawn with. Expected values by hand from the
// spec, and from Mesa's rules where the comment says so.
#include <cmath>
#include <limits>
#include <variant>

#include "gl_test_context.hpp"

namespace {

using glpt::rec::PixelKind;

class PixelCommandTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, 64, 0, 64, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  template <typename T>
  std::vector<const T*> commands() {
    ctx_.recorder.seal();
    std::vector<const T*> out;
    for (const auto& c : ctx_.recorder.record().commands)
      if (const auto* t = std::get_if<T>(&c)) out.push_back(t);
    return out;
  }
  const glpt::rec::StateSnapshot& state(glpt::rec::StateId id) {
    return ctx_.recorder.record().states.at(id);
  }
  float raster_x() {
    float p[4];
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
    return p[0];
  }
};

TEST_F(PixelCommandTest, BitmapLandsAtTheFlooredOriginAndMoves) {
  glColor3f(1, 0.5f, 0.25f);
  glRasterPos2f(10.99995f, 20.3f);             // Mesa: floor(x + 1e-4 - xorig)
  const GLubyte rows[3] = {0x80, 0x40, 0xA0};  // bottom row first: bits 1..., .1.., 1.1.
  glBitmap(3, 3, 1.0f, -2.0f, 4.5f, -1.0f, rows);
  const auto b = commands<glpt::rec::Bitmap>();
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0]->origin, glm::vec2(10, 22));  // floor(11.00005 - 1), floor(20.3001 + 2)
  EXPECT_EQ(b[0]->width, 3u);
  EXPECT_EQ(b[0]->bits, (std::vector<uint8_t>{1, 0, 0, 0, 1, 0, 1, 0, 1}));
  EXPECT_EQ(b[0]->raster.color, glm::vec4(1, 0.5f, 0.25f, 1));
  EXPECT_FLOAT_EQ(raster_x(), 10.99995f + 4.5f);
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

TEST_F(PixelCommandTest, BitmapUnpackModes) {
  // Row length 16 bits (2 bytes), skip 1 row and 3 pixels, LSB first, alignment 2.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 16);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  const GLubyte data[6] = {0xFF, 0xFF, 0x08 | 0x20, 0x01, 0x10, 0x00};
  glRasterPos2i(0, 0);
  glBitmap(6, 2, 0, 0, 0, 0, data);
  const auto b = commands<glpt::rec::Bitmap>();
  ASSERT_EQ(b.size(), 1u);
  // Row 0 is bytes 2-3: bits 3..8 (LSB first) of 0x28, 0x01 -> 1 0 1 0 0 1; row 1: 0x10 -> bit 4.
  EXPECT_EQ(b[0]->bits, (std::vector<uint8_t>{1, 0, 1, 0, 0, 1, 0, 1, 0, 0, 0, 0}));
}

TEST_F(PixelCommandTest, BitmapErrorsAndNoOps) {
  glBitmap(-1, 2, 0, 0, 1, 1, nullptr);
  EXPECT_EQ(glGetError(), GL_INVALID_VALUE);
  glRasterPos2i(5, 5);
  glBitmap(4, 4, 0, 0, 3, 0, nullptr);  // no image: nothing drawn, still moves
  EXPECT_FLOAT_EQ(raster_x(), 8.0f);
  glRasterPos2i(500, 5);  // outside the view volume: invalid
  const GLubyte rows[1] = {0xFF};
  glBitmap(8, 1, 0, 0, 3, 0, rows);
  EXPECT_FLOAT_EQ(raster_x(), 8.0f);  // not moved (Mesa)
  EXPECT_TRUE(commands<glpt::rec::Bitmap>().empty());
  glBegin(GL_POINTS);
  glBitmap(8, 1, 0, 0, 3, 0, rows);
  glEnd();
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
}

// Mesa's bitmap cache (st_cb_bitmap.c): bitmaps that fit a 512 x 32 cache with the same raster
// colour become one bitmap, drawn with the state of the last glBitmap call.
TEST_F(PixelCommandTest, CachedBitmapsMergeAndTakeTheLastState) {
  const GLubyte rows[2] = {0xC0, 0x80};  // bottom row 11, top row 1.
  glRasterPos2i(10, 10);
  glBitmap(2, 2, 0, 0, 1, 0, rows);  // overlaps the next: one fragment per pixel
  glEnable(GL_BLEND);
  glBitmap(2, 2, 0, 0, 0, 1, rows);
  auto b = commands<glpt::rec::Bitmap>();
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0]->origin, glm::vec2(10, 10));
  EXPECT_EQ(b[0]->width, 3u);
  EXPECT_EQ(b[0]->height, 2u);
  EXPECT_EQ(b[0]->bits, (std::vector<uint8_t>{1, 1, 1, 1, 1, 0}));
  EXPECT_TRUE(state(b[0]->state).raster->ops.blend);  // validated at the second call
  // Another colour flushes the cache, with the state validated by the call that flushed it.
  glColor3f(1, 0, 0);
  glRasterPos2i(10, 12);
  glBlendFunc(GL_ONE, GL_ONE);
  glBitmap(2, 2, 0, 0, 0, 0, rows);
  b = commands<glpt::rec::Bitmap>();
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0]->state, b[1]->state);
  EXPECT_EQ(state(b[0]->state).raster->ops.blend_src_rgb, GLenum{GL_ONE});
}

TEST_F(PixelCommandTest, BitmapCacheKeepsItsProgramAndScissorEnable) {
  const GLubyte rows[1] = {0xFF};
  glRasterPos2i(10, 10);
  glBitmap(8, 1, 0, 0, 0, 0, rows);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_FOG);
  glEnable(GL_DEPTH_TEST);
  glBitmap(8, 1, 0, 0, 0, 0, rows);  // another program and scissor enable: flushes the cache
  const auto b = commands<glpt::rec::Bitmap>();
  ASSERT_EQ(b.size(), 2u);
  const glpt::rec::RasterState& first = *state(b[0]->state).raster;
  EXPECT_TRUE(first.ops.depth_test);
  EXPECT_FALSE(first.ops.scissor_test);
  EXPECT_FALSE(first.fog.enabled);
  EXPECT_TRUE(state(b[1]->state).raster->ops.scissor_test);
}

TEST_F(PixelCommandTest, LargeBitmapsAndAccumulationGoBeforeTheCache) {
  const GLubyte rows[40] = {};
  glRasterPos2i(10, 10);
  glBitmap(8, 1, 0, 0, 0, 0, rows);
  glBitmap(8, 40, 0, 0, 0, 0, rows);  // taller than the cache: drawn at once
  glAccum(GL_LOAD, 1.0f);             // does not flush the cache
  glBitmap(8, 1, 0, 0, 0, 0, rows);   // joins the cache
  glFlush();                          // flushes it
  glBitmap(8, 1, 0, 0, 0, 0, rows);
  ctx_.recorder.seal();
  const auto& c = ctx_.recorder.record().commands;
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(std::get<glpt::rec::Bitmap>(c[0]).height, 40u);
  EXPECT_TRUE(std::holds_alternative<glpt::rec::Accum>(c[1]));
  EXPECT_EQ(std::get<glpt::rec::Bitmap>(c[2]).height, 1u);
  EXPECT_TRUE(std::holds_alternative<glpt::rec::Bitmap>(c[3]));
}

// Mesa textures pixel rectangles with current coordinates, not the raster position's: images
// with unit 0's at the call, copies and bitmaps with those current at the last glRasterPos.
TEST_F(PixelCommandTest, PixelRectanglesTakeMesasTextureCoordinates) {
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0, 0);  // moves the raster position's coordinates only
  glMatrixMode(GL_MODELVIEW);
  glTexCoord2f(0.1f, 0.2f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.3f, 0.4f);
  glRasterPos2i(1, 1);
  glTexCoord2f(0.7f, 0.8f);  // after the raster position
  const GLubyte pixel[4] = {1, 2, 3, 4};
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  const GLubyte bit = 0x80;
  glBitmap(1, 1, 0, 0, 0, 0, &bit);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);  // glDrawPixels flushed the current values
  const auto c = commands<glpt::rec::CopyPixels>();
  const auto b = commands<glpt::rec::Bitmap>();
  const auto d = commands<glpt::rec::DrawPixels>();
  ASSERT_EQ(c.size(), 2u);
  ASSERT_EQ(b.size(), 1u);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(c[0]->raster.tex_coord[0], glm::vec4(0.1f, 0.2f, 0, 1));
  EXPECT_EQ(c[0]->raster.tex_coord[1], glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(b[0]->raster.tex_coord[0], glm::vec4(0.1f, 0.2f, 0, 1));
  EXPECT_EQ(b[0]->raster.tex_coord[1], glm::vec4(0.3f, 0.4f, 0, 1));
  EXPECT_EQ(d[0]->raster.tex_coord[0], glm::vec4(0.7f, 0.8f, 0, 1));
  EXPECT_EQ(c[1]->raster.tex_coord[0], glm::vec4(0.7f, 0.8f, 0, 1));
  GLfloat raster[4];
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, raster);
  EXPECT_FLOAT_EQ(raster[0], 0.6f);  // the raster position's own, transformed
}

TEST_F(PixelCommandTest, DrawPixelsUnpacksFormatsAndRoundsThePosition) {
  glRasterPos2f(2.5f, 3.49f);  // rounded half away from zero: (3, 3)
  const GLubyte rgb[2 * 2 * 3] = {255, 0, 51, 0, 255, 102, 10, 20, 30, 40, 50, 60};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);  // 6-byte rows padded to 8
  const GLubyte padded[16] = {255, 0, 51, 0, 255, 102, 0, 0, 10, 20, 30, 40, 50, 60, 0, 0};
  glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_BYTE, padded);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glDrawPixels(1, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, rgb);
  const GLfloat f[2] = {1.5f, -0.25f};
  glDrawPixels(2, 1, GL_ALPHA, GL_FLOAT, f);
  const GLshort s[3] = {-32768, 0, 16384};
  glDrawPixels(1, 1, GL_BGR, GL_SHORT, s);
  const auto d = commands<glpt::rec::DrawPixels>();
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0]->raster.window.x, 3.0f);
  EXPECT_EQ(d[0]->raster.window.y, 3.0f);
  EXPECT_EQ(d[0]->kind, PixelKind::kColor);
  ASSERT_EQ(d[0]->color.size(), 4u);
  // Mesa's unorm conversion: c * (1 / 255) in float.
  EXPECT_EQ(d[0]->color[0], glm::vec4(255, 0, 51, 255) * (1.0f / 255.0f));
  EXPECT_EQ(d[0]->color[2], glm::vec4(10, 20, 30, 255) * (1.0f / 255.0f));
  EXPECT_EQ(d[1]->color[0], glm::vec4(glm::vec3(1.0f), 0.0f));  // L = 255, A = 0
  EXPECT_EQ(d[2]->color[0], glm::vec4(0, 0, 0, 1));             // A clamped to 1, RGB 0
  EXPECT_EQ(d[2]->color[1], glm::vec4(0, 0, 0, 0));
  // Signed shorts: max(c * (1 / 32767), -1); BGR order.
  EXPECT_EQ(d[3]->color[0], glm::vec4(16384.0f * (1.0f / 32767.0f), 0, 0, 1));
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

TEST_F(PixelCommandTest, DrawPixelsDepthAndStencilImages) {
  glWindowPos3f(1, 2, 0.25f);
  const GLushort depth[2] = {0, 65535};
  glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, depth);
  const GLubyte stencil[3] = {7, 200, 255};
  glDrawPixels(3, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  const auto d = commands<glpt::rec::DrawPixels>();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0]->kind, PixelKind::kDepth);
  EXPECT_EQ(d[0]->depth, (std::vector<float>{0, 1}));
  EXPECT_EQ(d[0]->raster.window.z, 0.25f);
  EXPECT_EQ(d[1]->kind, PixelKind::kStencil);
  EXPECT_EQ(d[1]->stencil, (std::vector<uint32_t>{7, 200, 255}));
}

TEST_F(PixelCommandTest, DrawPixelsErrors) {
  const GLubyte data[16] = {};
  glDrawPixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);
  EXPECT_EQ(glGetError(), GL_INVALID_VALUE);
  glDrawPixels(1, 1, GL_RGBA, GL_DOUBLE, data);
  EXPECT_EQ(glGetError(), GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_INTENSITY, GL_UNSIGNED_BYTE, data);  // not a pixel format
  EXPECT_EQ(glGetError(), GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGBA, GL_BITMAP, data);
  EXPECT_EQ(glGetError(), GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, data);  // 3-component packed type
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_INT_8_8_8_8, data);
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE_3_3_2, data);
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
  glRasterPos2i(500, 0);  // invalid: no-op, not an error
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
  EXPECT_TRUE(commands<glpt::rec::DrawPixels>().empty());
}

TEST_F(PixelCommandTest, MissingBuffersAreInvalidOperations) {
  glpt::rec::DrawableConfig config;
  config.stencil_bits = 0;
  config.depth_bits = 0;
  config.accum_bits = 0;
  ctx_.drawable = config;
  const GLubyte data[4] = {};
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, data);
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, data);
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_STENCIL);
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
  glAccum(GL_ACCUM, 0.5f);
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
  GLint bits = -1;
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits);
  EXPECT_EQ(bits, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);  // colour is fine without the buffers
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

TEST_F(PixelCommandTest, AbsurdSizesAndPositionsAreSafe) {
  const GLubyte data[4] = {};
  glDrawPixels(100000, 100000, GL_RGBA, GL_UNSIGNED_BYTE, data);  // never read: too large
  EXPECT_EQ(glGetError(), GL_OUT_OF_MEMORY);
  glBitmap(1 << 20, 1 << 20, 0, 0, 0, 0, data);
  EXPECT_EQ(glGetError(), GL_OUT_OF_MEMORY);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  glWindowPos2f(nan, 3);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);
  glBitmap(1, 1, 0, 0, 1, 1, data);
  glCopyPixels(0, 0, 16384, 16384, GL_COLOR);
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
  const auto d = commands<glpt::rec::DrawPixels>();
  ASSERT_EQ(d.size(), 1u);
  EXPECT_TRUE(std::isnan(d[0]->raster.window.x));  // recorded as it is; drawn nowhere
}

TEST_F(PixelCommandTest, PixelZoomIsInTheSnapshot) {
  glPixelZoom(2.5f, -1.0f);
  glRasterPos2i(3, 4);
  const GLubyte data[4] = {1, 2, 3, 4};
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);
  glCopyPixels(1, 2, 3, 4, GL_COLOR);
  const auto d = commands<glpt::rec::DrawPixels>();
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(state(d[0]->state).pixel_transfer->zoom_x, 2.5f);
  EXPECT_EQ(state(d[0]->state).pixel_transfer->zoom_y, -1.0f);
  const auto c = commands<glpt::rec::CopyPixels>();
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0]->kind, PixelKind::kColor);
  EXPECT_EQ(c[0]->x, 1);
  EXPECT_EQ(c[0]->height, 4u);
  EXPECT_EQ(c[0]->raster.window.x, 3.0f);
}

TEST_F(PixelCommandTest, CopyPixelsErrorsAndNoOps) {
  glCopyPixels(0, 0, -1, 1, GL_COLOR);
  EXPECT_EQ(glGetError(), GL_INVALID_VALUE);
  glCopyPixels(0, 0, 1, 1, GL_RGBA);
  EXPECT_EQ(glGetError(), GL_INVALID_ENUM);
  glCopyPixels(0, 0, 0, 5, GL_DEPTH);  // empty: nothing recorded
  glRasterPos2i(-500, 0);
  glCopyPixels(0, 0, 4, 4, GL_STENCIL);  // invalid raster position: nothing recorded
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
  EXPECT_TRUE(commands<glpt::rec::CopyPixels>().empty());
}

TEST_F(PixelCommandTest, AccumulationCommandsAndClearValue) {
  glClearAccum(2.0f, -0.5f, 0.25f, -3.0f);  // clamped to [-1, 1]
  GLfloat value[4];
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, value);
  EXPECT_EQ(glm::vec4(value[0], value[1], value[2], value[3]), glm::vec4(1, -0.5f, 0.25f, -1));
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_MULT, 0.5f);
  glAccum(GL_RETURN, 2.0f);
  glAccum(GL_FLOAT, 1.0f);
  EXPECT_EQ(glGetError(), GL_INVALID_ENUM);
  const auto clears = commands<glpt::rec::Clear>();
  ASSERT_EQ(clears.size(), 1u);
  EXPECT_EQ(clears[0]->mask, GLbitfield{GL_ACCUM_BUFFER_BIT});
  EXPECT_EQ(clears[0]->accum, glm::vec4(1, -0.5f, 0.25f, -1));
  const auto a = commands<glpt::rec::Accum>();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0]->op, GLenum{GL_MULT});
  EXPECT_EQ(a[1]->op, GLenum{GL_RETURN});
  EXPECT_EQ(a[1]->value, 2.0f);
}

TEST_F(PixelCommandTest, AccumulationBitsFollowTheDrawable) {
  ctx_.drawable = glpt::rec::DrawableConfig{};  // 16 bits per component, as Mesa's buffer
  GLint bits[4];
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
  glGetIntegerv(GL_ACCUM_ALPHA_BITS, &bits[3]);
  EXPECT_EQ(bits[0], 16);
  EXPECT_EQ(bits[3], 16);
}

TEST_F(PixelCommandTest, RasterPositionCompilesIntoDisplayLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glWindowPos2i(7, 9);
  glEndList();
  glWindowPos2i(1, 1);
  glCallList(list);
  EXPECT_FLOAT_EQ(raster_x(), 7.0f);
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

}  // namespace
