// Pixel rectangles and the accumulation buffer in raster mode, for states the GL front end cannot
// set on its own yet (stencil functions and masks, blending, the alpha test, colour masks, pixel
// transfer): each test draws the same thing twice, with real Mesa (OSMesa, GL calls) and as a
// frame record built by hand executed by rt::Renderer, and compares the buffers.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <memory>
#include <string>

#include "osmesa_context.hpp"
#include "rt_core/raster/accumulation.hpp"
#include "rt_core/raster/pixel_quad.hpp"
#include "rt_core/renderer.hpp"

namespace glpt::rt {
namespace {

constexpr int kSize = 48;

// The current state of a record being built, snapshotted into the record on demand.
struct RecordBuilder {
  rec::FrameRecord record;
  rec::TransformState transform;
  rec::LightingState lighting;
  rec::TexturingState texturing;
  rec::RasterState raster;
  rec::PixelTransferState transfer;

  RecordBuilder() {
    transform.viewport = {0, 0, kSize, kSize};
    raster.ops.scissor_box = {0, 0, kSize, kSize};
    raster.ops.draw_buffer = GL_FRONT;  // a single-buffered drawable, as OSMesa's
    raster.ops.read_buffer = GL_FRONT;
  }
  rec::StateId state() {
    record.states.push_back({std::make_shared<rec::TransformState>(transform),
                             std::make_shared<rec::LightingState>(lighting),
                             std::make_shared<rec::TexturingState>(texturing),
                             std::make_shared<rec::RasterState>(raster),
                             std::make_shared<rec::PixelTransferState>(transfer)});
    return static_cast<rec::StateId>(record.states.size() - 1);
  }
  void clear(uint32_t mask, glm::vec4 color, int32_t stencil = 0, glm::vec4 accum = {}) {
    rec::Clear c;
    c.state = state();
    c.mask = mask;
    c.color = color;
    c.stencil = stencil;
    c.accum = accum;
    record.commands.push_back(c);
  }
  static rec::RasterPosition at(float x, float y, glm::vec4 color = glm::vec4(1.0f)) {
    rec::RasterPosition p;
    p.window = glm::vec4(x, y, 0.5f, 1.0f);
    p.color = color;
    p.tex_coord.fill(glm::vec4(0, 0, 0, 1));
    return p;
  }
  void draw_color(float x, float y, uint32_t w, uint32_t h, const std::vector<uint8_t>& rgba) {
    rec::DrawPixels d;
    d.state = state();
    d.raster = at(x, y);
    d.width = w;
    d.height = h;
    for (size_t i = 0; i < size_t{w} * h; ++i)
      d.color.push_back(glm::vec4(rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2], rgba[i * 4 + 3]) /
                        255.0f);
    record.commands.push_back(d);
  }
  void draw_stencil(float x, float y, uint32_t w, uint32_t h, const std::vector<uint8_t>& values) {
    rec::DrawPixels d;
    d.state = state();
    d.raster = at(x, y);
    d.kind = rec::PixelKind::kStencil;
    d.width = w;
    d.height = h;
    d.stencil.assign(values.begin(), values.end());
    record.commands.push_back(d);
  }
  void copy(rec::PixelKind kind, float to_x, float to_y, int32_t x, int32_t y, uint32_t w,
            uint32_t h) {
    rec::CopyPixels c;
    c.state = state();
    c.raster = at(to_x, to_y);
    c.kind = kind;
    c.x = x;
    c.y = y;
    c.width = w;
    c.height = h;
    record.commands.push_back(c);
  }
  void accum(uint32_t op, float value) {
    rec::Accum a;
    a.state = state();
    a.op = op;
    a.value = value;
    record.commands.push_back(a);
  }
};

std::vector<uint8_t> test_image(uint32_t w, uint32_t h) {
  std::vector<uint8_t> p(size_t{w} * h * 4);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      uint8_t* q = &p[(size_t{y} * w + x) * 4];
      q[0] = uint8_t(30 + 25 * x);
      q[1] = uint8_t(220 - 20 * y);
      q[2] = uint8_t((x + y) % 2 ? 200 : 40);
      q[3] = uint8_t(40 + 23 * ((x * 3 + y) % 10));
    }
  return p;
}

class PixelCommandsVsMesa : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    RenderSettings settings = RenderSettings::from_environment();  // GLPT_VALIDATION
    settings.mode = RenderMode::kRaster;
    renderer_ = Renderer::create(settings, &error_);
  }
  static void TearDownTestSuite() { renderer_.reset(); }
  void SetUp() override { ASSERT_NE(renderer_, nullptr) << error_; }

  struct Buffers {
    std::vector<uint8_t> color, stencil;
  };

  // Mesa: a fresh single-buffered RGBA8 / depth 24 / stencil 8 / accum 16 context.
  static Buffers mesa(const std::function<void()>& draw) {
    test::OSMesaScope context(kSize, kSize);
    EXPECT_TRUE(context.ok());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    draw();
    Buffers b;
    b.color.resize(size_t{kSize} * kSize * 4);
    b.stencil.resize(size_t{kSize} * kSize);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, b.color.data());
    glReadPixels(0, 0, kSize, kSize, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, b.stencil.data());
    EXPECT_EQ(glGetError(), GL_NO_ERROR);
    return b;
  }

  static Buffers glpt(const RecordBuilder& builder, FrameStats* stats_out = nullptr) {
    rec::DrawableConfig drawable;
    drawable.width = drawable.height = kSize;
    drawable.double_buffered = false;
    FrameStats stats;
    std::string error;
    Buffers b;
    const std::shared_ptr<DrawableBuffers> buffers = create_drawable_buffers();
    EXPECT_TRUE(renderer_->execute(builder.record, *buffers, drawable, stats, &error)) << error;
    EXPECT_TRUE(renderer_->read_color(*buffers, GL_FRONT, 0, 0, kSize, kSize, b.color, &error))
        << error;
    EXPECT_TRUE(renderer_->read_stencil(*buffers, 0, 0, kSize, kSize, b.stencil, &error)) << error;
    if (stats_out != nullptr) *stats_out = stats;
    return b;
  }

  // Every pixel equal; the first differences are reported.
  static void expect_equal(const std::vector<uint8_t>& mesa, const std::vector<uint8_t>& glpt,
                           int channels, const char* what) {
    ASSERT_EQ(mesa.size(), glpt.size());
    int reported = 0;
    for (size_t i = 0; i < mesa.size(); ++i) {
      if (mesa[i] == glpt[i]) continue;
      const size_t pixel = i / size_t(channels);
      ADD_FAILURE() << what << " differs at (" << pixel % kSize << ", " << pixel / kSize
                    << ") channel " << i % size_t(channels) << ": Mesa " << int(mesa[i])
                    << ", glpt " << int(glpt[i]);
      if (++reported == 5) return;
    }
  }

  static std::unique_ptr<Renderer> renderer_;
  static std::string error_;
};
std::unique_ptr<Renderer> PixelCommandsVsMesa::renderer_;
std::string PixelCommandsVsMesa::error_;

std::vector<uint8_t> stencil_image(uint32_t w, uint32_t h) {
  std::vector<uint8_t> s(size_t{w} * h);
  for (size_t i = 0; i < s.size(); ++i) s[i] = uint8_t(i * 37 + 5);
  return s;
}

// Stencil images write only stencil, through the scissor and the stencil write mask, zoomed.
TEST_F(PixelCommandsVsMesa, StencilImageUnderWriteMaskScissorAndZoom) {
  const std::vector<uint8_t> s = stencil_image(8, 6);
  const Buffers m = mesa([&] {
    glClearStencil(0x0F);
    glClearColor(0.2f, 0.3f, 0.4f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 40, 48);
    glStencilMask(0x5A);
    glPixelZoom(1.5f, 2.0f);
    glWindowPos2i(5, 7);
    glDrawPixels(8, 6, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s.data());
    glPixelZoom(-1, 1);
    glWindowPos2i(44, 30);
    glDrawPixels(8, 6, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s.data());
  });
  RecordBuilder r;
  r.clear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, {0.2f, 0.3f, 0.4f, 1}, 0x0F);
  r.raster.ops.scissor_test = true;
  r.raster.ops.scissor_box = {0, 0, 40, 48};
  r.raster.ops.stencil_write_mask = 0x5A;
  r.transfer.zoom_x = 1.5f;
  r.transfer.zoom_y = 2.0f;
  r.draw_stencil(5, 7, 8, 6, s);
  r.transfer.zoom_x = -1;
  r.transfer.zoom_y = 1;
  r.draw_stencil(44, 30, 8, 6, s);
  const Buffers g = glpt(r);
  expect_equal(m.stencil, g.stencil, 1, "stencil");
  expect_equal(m.color, g.color, 4, "colour");
}

// A colour image through the stencil test, blending, the alpha test and a colour mask.
TEST_F(PixelCommandsVsMesa, ColorImageThroughFragmentOperations) {
  const std::vector<uint8_t> s = stencil_image(12, 10);
  const std::vector<uint8_t> image = test_image(12, 10);
  const Buffers m = mesa([&] {
    glClearColor(0.2f, 0.5f, 0.1f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glWindowPos2i(4, 4);
    glDrawPixels(12, 10, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s.data());
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 1, 0x3);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.3f);
    glColorMask(1, 0, 1, 1);
    glPixelZoom(2, 2);
    glWindowPos2i(2, 2);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  });
  RecordBuilder r;
  r.clear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, {0.2f, 0.5f, 0.1f, 0.6f});
  r.draw_stencil(4, 4, 12, 10, s);
  rec::FragmentOpsState& ops = r.raster.ops;
  ops.stencil_test = true;
  ops.stencil_func = GL_EQUAL;
  ops.stencil_ref = 1;
  ops.stencil_value_mask = 0x3;
  ops.stencil_depth_pass = GL_INCR;
  ops.blend = true;
  ops.blend_src_rgb = ops.blend_src_alpha = GL_SRC_ALPHA;
  ops.blend_dst_rgb = ops.blend_dst_alpha = GL_ONE_MINUS_SRC_ALPHA;
  ops.alpha_test = true;
  ops.alpha_func = GL_GREATER;
  ops.alpha_ref = 0.3f;
  ops.color_write = {true, false, true, true};
  r.transfer.zoom_x = r.transfer.zoom_y = 2;
  r.draw_color(2, 2, 12, 10, image);
  const Buffers g = glpt(r);
  expect_equal(m.color, g.color, 4, "colour");
  expect_equal(m.stencil, g.stencil, 1, "stencil");
}

// Bitmaps take the raster colour plus the raster secondary colour with GL_COLOR_SUM, and fog
// with a fog coordinate of 0 (Mesa's), as do glDrawPixels colour images.
TEST_F(PixelCommandsVsMesa, BitmapColorSumAndFog) {
  std::vector<uint8_t> bits(16 * 16);
  for (size_t i = 0; i < bits.size(); ++i) bits[i] = (i * 7 % 5) < 3;
  GLubyte packed[16 * 2] = {};
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      if (bits[size_t(y) * 16 + x]) packed[y * 2 + x / 8] |= GLubyte(0x80 >> (x % 8));
  const std::vector<uint8_t> image = test_image(8, 8);
  const float fog_color[4] = {0.9f, 0.1f, 0.6f, 1};
  const Buffers m = mesa([&] {
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_COLOR_SUM);
    glSecondaryColor3f(0.0f, 0.3f, 0.5f);
    glColor3f(0.4f, 0.2f, 0.1f);
    glWindowPos2i(3, 3);
    glBitmap(16, 16, 0, 0, 20, 0, packed);
    glDisable(GL_COLOR_SUM);  // Mesa's glDrawPixels reads garbage with it on (not emulated)
    glWindowPos2i(30, 3);
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    glEnable(GL_COLOR_SUM);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 20);
    glFogf(GL_FOG_END, 10);  // at coordinate 0: (10 - 0) / (10 - 20) -> all fog
    glFogfv(GL_FOG_COLOR, fog_color);
    glWindowPos2i(3, 25);
    glBitmap(16, 16, 0, 0, 0, 0, packed);
    glDisable(GL_COLOR_SUM);
    glWindowPos2i(30, 25);
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  });
  RecordBuilder r;
  r.clear(GL_COLOR_BUFFER_BIT, glm::vec4(0.0f));
  r.raster.ops.color_sum = true;
  auto bitmap = [&](float x, float y) {
    rec::Bitmap b;
    b.state = r.state();
    b.raster = RecordBuilder::at(x, y, glm::vec4(0.4f, 0.2f, 0.1f, 1));
    b.raster.secondary_color = glm::vec4(0.0f, 0.3f, 0.5f, 1);
    b.origin = glm::vec2(x, y);
    b.width = b.height = 16;
    b.bits = bits;
    r.record.commands.push_back(b);
  };
  bitmap(3, 3);
  r.raster.ops.color_sum = false;
  r.draw_color(30, 3, 8, 8, image);
  r.raster.ops.color_sum = true;
  r.raster.fog.enabled = true;
  r.raster.fog.mode = GL_LINEAR;
  r.raster.fog.start = 20;
  r.raster.fog.end = 10;
  r.raster.fog.color = glm::vec4(0.9f, 0.1f, 0.6f, 1);
  bitmap(3, 25);
  r.raster.ops.color_sum = false;
  r.draw_color(30, 25, 8, 8, image);
  expect_equal(m.color, glpt(r).color, 4, "colour");
}

// A colour copy without zoom and without fragment operations is a plain copy in Mesa, even
// under a colour mask; with blending on it is drawn, and the mask applies. Pixel transfer scale
// and bias apply to copies drawn as fragments.
TEST_F(PixelCommandsVsMesa, ColorCopiesBlitOrDraw) {
  const std::vector<uint8_t> image = test_image(10, 10);
  const Buffers m = mesa([&] {
    glClearColor(0.1f, 0.6f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glWindowPos2i(1, 1);
    glDrawPixels(10, 10, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    glColorMask(1, 0, 1, 1);
    glWindowPos2i(14, 1);
    glCopyPixels(1, 1, 10, 10, GL_COLOR);  // blit: the mask does not apply
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glWindowPos2i(27, 1);
    glCopyPixels(1, 1, 10, 10, GL_COLOR);  // drawn: the mask applies
    glDisable(GL_BLEND);
    glColorMask(1, 1, 1, 1);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glWindowPos2i(1, 20);
    glCopyPixels(1, 1, 10, 10, GL_COLOR);
    glPixelTransferf(GL_RED_SCALE, 1);
    glPixelTransferf(GL_GREEN_BIAS, 0);
    glWindowPos2i(5, 5);
    glCopyPixels(1, 1, 10, 10, GL_COLOR);  // overlapping its source: drawn from a copy
  });
  RecordBuilder r;
  r.clear(GL_COLOR_BUFFER_BIT, {0.1f, 0.6f, 0.3f, 1});
  r.draw_color(1, 1, 10, 10, image);
  r.raster.ops.color_write = {true, false, true, true};
  r.copy(rec::PixelKind::kColor, 14, 1, 1, 1, 10, 10);
  r.raster.ops.blend = true;
  r.copy(rec::PixelKind::kColor, 27, 1, 1, 1, 10, 10);
  r.raster.ops.blend = false;
  r.raster.ops.color_write = {true, true, true, true};
  r.transfer.scale.r = 0.5f;
  r.transfer.bias.g = 0.25f;
  r.copy(rec::PixelKind::kColor, 1, 20, 1, 1, 10, 10);
  r.transfer = rec::PixelTransferState{};
  r.copy(rec::PixelKind::kColor, 5, 5, 1, 1, 10, 10);
  expect_equal(m.color, glpt(r).color, 4, "colour");
}

// Stencil copies (drawn, with Mesa's stencil export) overlapping their source, under the write
// mask.
TEST_F(PixelCommandsVsMesa, StencilCopies) {
  const std::vector<uint8_t> s = stencil_image(12, 12);
  const Buffers m = mesa([&] {
    glClearStencil(0x81);
    glClear(GL_STENCIL_BUFFER_BIT);
    glWindowPos2i(2, 2);
    glDrawPixels(12, 12, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s.data());
    glWindowPos2i(6, 5);
    glCopyPixels(2, 2, 12, 12, GL_STENCIL);
    glStencilMask(0xF0);
    glPixelZoom(2, 1.5f);
    glWindowPos2i(20, 20);
    glCopyPixels(2, 2, 12, 12, GL_STENCIL);
  });
  RecordBuilder r;
  r.clear(GL_STENCIL_BUFFER_BIT, glm::vec4(0.0f), 0x81);
  r.draw_stencil(2, 2, 12, 12, s);
  r.copy(rec::PixelKind::kStencil, 6, 5, 2, 2, 12, 12);
  r.raster.ops.stencil_write_mask = 0xF0;
  r.transfer.zoom_x = 2;
  r.transfer.zoom_y = 1.5f;
  r.copy(rec::PixelKind::kStencil, 20, 20, 2, 2, 12, 12);
  expect_equal(m.stencil, glpt(r).stencil, 1, "stencil");
}

// GL_RETURN writes only the enabled components inside the scissor box; GL_ACCUM/GL_LOAD read the
// read buffer.
TEST_F(PixelCommandsVsMesa, AccumulationReturnUnderColorMaskAndScissor) {
  const std::vector<uint8_t> image = test_image(kSize, kSize);
  const Buffers m = mesa([&] {
    glWindowPos2i(0, 0);
    glDrawPixels(kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    glAccum(GL_LOAD, 0.8f);
    glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    glAccum(GL_ACCUM, -0.3f);
    glColorMask(1, 0, 1, 0);
    glEnable(GL_SCISSOR_TEST);
    glScissor(5, 7, 30, 33);
    glAccum(GL_RETURN, 1.2f);
  });
  RecordBuilder r;
  r.draw_color(0, 0, kSize, kSize, image);
  r.accum(GL_LOAD, 0.8f);
  r.clear(GL_COLOR_BUFFER_BIT, glm::vec4(0.5f));
  r.accum(GL_ACCUM, -0.3f);
  r.raster.ops.color_write = {true, false, true, false};
  r.raster.ops.scissor_test = true;
  r.raster.ops.scissor_box = {5, 7, 30, 33};
  r.accum(GL_RETURN, 1.2f);
  expect_equal(m.color, glpt(r).color, 4, "colour");
}

// ---- host-only: Mesa's arithmetic
// ----------------------------------------------------------------

// Values from Mesa 25.0.7 (OSMesa): the groups a 6 x 5 image at (2, 40), zoom 0.5, takes in a
// 96 x 96 window (columns 0, 2, 4: the viewport transform rounds x = 2 up, so pixel 2's
// coordinate falls just short of group 1), and in a 128 x 128 one (columns 1, 3, 5).
TEST(MesaPixelQuad, GroupsOnEdgesAsMesaPicksThem) {
  for (const auto& [size, first] : {std::pair{96u, 0}, std::pair{128u, 1}}) {
    const PixelQuad q = mesa_pixel_quad({2, 40}, {5, 42.5f}, size, size, false);
    for (int x = 2; x < 5; ++x) {
      const int triangle = mesa_pixel_triangle(q, {x + 0.5f, 40.5f});
      EXPECT_EQ(mesa_pixel_column(q, triangle, x, 6), first + 2 * (x - 2)) << size << " " << x;
      EXPECT_EQ(mesa_pixel_row(q, triangle, 40, 5, false), 1);
      EXPECT_EQ(mesa_pixel_row(q, mesa_pixel_triangle(q, {x + 0.5f, 41.5f}), 41, 5, false), 3);
    }
  }
  // Zoom (2.5, 1.5) at (20, 3), 96 x 96: window columns 22, 27 and 32 lie on group edges; Mesa
  // gives 1, 2 (not 3) and 4 (not 5).
  const PixelQuad q = mesa_pixel_quad({20, 3}, {35, 10.5f}, 96, 96, false);
  EXPECT_EQ(mesa_pixel_column(q, mesa_pixel_triangle(q, {22.5f, 5.5f}), 22, 6), 1);
  EXPECT_EQ(mesa_pixel_column(q, mesa_pixel_triangle(q, {27.5f, 5.5f}), 27, 6), 2);
  EXPECT_EQ(mesa_pixel_column(q, mesa_pixel_triangle(q, {32.5f, 5.5f}), 32, 6), 4);
}

// Mesa's accumulation arithmetic on values worked out by hand from src/mesa/main/accum.c.
TEST(AccumulationBuffer, MesaArithmetic) {
  AccumulationBuffer a;
  a.resize(2, 1);
  const PixelRect all{0, 0, 2, 1}, first{0, 0, 1, 1};
  a.clear(all, glm::vec4(1.0f, -1.0f, 0.5f, 0.0f));
  // FLOAT_TO_SHORT: ((int)(65535 * x) - 1) / 2 -> 32767, -32768, 16383, 0 (truncating division).
  EXPECT_EQ(a.at(0, 0, 0), 32767);
  EXPECT_EQ(a.at(0, 0, 1), -32768);
  EXPECT_EQ(a.at(0, 0, 2), 16383);
  EXPECT_EQ(a.at(0, 0, 3), 0);
  a.add(first, 0.5f);                // + (short)(0.5 * 32767) = 16383; the sums wrap in 16 bits
  EXPECT_EQ(a.at(0, 0, 0), -16386);  // 32767 + 16383 = 49150 wraps
  EXPECT_EQ(a.at(0, 0, 1), -16385);
  EXPECT_EQ(a.at(1, 0, 0), 32767);  // outside the rectangle
  a.multiply(all, 0.5f);            // truncated toward zero
  EXPECT_EQ(a.at(0, 0, 0), -8193);
  EXPECT_EQ(a.at(1, 0, 2), 8191);
  // GL_LOAD of colour 255 / 128 / 1 / 0 with value 1: (short)(c * (1/255) * 32767).
  a.accumulate(all, {255, 128, 1, 0, 255, 128, 1, 0}, 1.0f, true);
  EXPECT_EQ(a.at(1, 0, 0), 32767);
  EXPECT_EQ(a.at(1, 0, 1), 16447);  // 128 / 255 * 32767 = 16447.49
  EXPECT_EQ(a.at(1, 0, 2), 128);    // 128.498
  // GL_RETURN 1 under a mask of red and alpha: float_to_ubyte(v / 32767); green, blue kept.
  std::vector<uint8_t> rgba = {9, 9, 9, 9, 9, 9, 9, 9};
  a.return_to(all, 1.0f, {true, false, false, true}, rgba);
  EXPECT_EQ(rgba, (std::vector<uint8_t>{255, 9, 9, 0, 255, 9, 9, 0}));
  EXPECT_EQ(mesa_float_to_ubyte(0.5f), 128);  // 127.5 rounds to even
  EXPECT_EQ(mesa_float_to_ubyte(-0.1f), 0);
  EXPECT_EQ(mesa_float_to_ubyte(1.7f), 255);
}

}  // namespace
}  // namespace glpt::rt
