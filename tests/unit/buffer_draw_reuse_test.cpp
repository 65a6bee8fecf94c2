// Draws from unchanged buffer objects are recorded once and drawn again from the same vertices
// (gl_shim/arrays/buffer_draw_cache.hpp), which raster mode keeps on the GPU after their second
// frame (rt_core/raster/resident_geometry.hpp). Every change a draw's vertices depend on records
// new ones, and the pixels of a reused draw equal those of the same draw recorded afresh.
#include <cstdint>
#include <cstring>
#include <vector>

#include "array_test_util.hpp"
#include "gl_shim/frame/headless_target.hpp"

namespace {

const void* offset(uintptr_t bytes) { return reinterpret_cast<const void*>(bytes); }

struct Vertex {
  float position[3];
  uint8_t color[4];
};

// `triangles` small triangles (two pixels wide on a 64x64 window) in a grid over the viewport,
// rows repeating, coloured by number.
std::vector<Vertex> grid_triangles(uint32_t triangles) {
  std::vector<Vertex> v;
  const uint32_t per_row = 32;
  for (uint32_t t = 0; t < triangles; ++t) {
    const float x = -1.0f + 2.0f * float(t % per_row) / per_row;
    const float y = -1.0f + 2.0f * float((t / per_row) % per_row) / per_row;
    const float s = 2.0f / per_row;
    const uint8_t r = uint8_t(t * 7), g = uint8_t(t * 13), b = uint8_t(255 - t % 256);
    v.push_back({{x, y, 0.0f}, {r, g, b, 255}});
    v.push_back({{x + s, y, 0.0f}, {r, g, b, 255}});
    v.push_back({{x, y + s, 0.0f}, {r, g, b, 255}});
  }
  return v;
}

class BufferDrawReuseTest : public GlTest {
 protected:
  // Vertices and indices in buffer objects, positions and colours enabled.
  void set_up_buffers(const std::vector<Vertex>& vertices) {
    glGenBuffers(2, buffers_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
                 GL_STATIC_DRAW);
    std::vector<GLuint> indices(vertices.size());
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = GLuint(i);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(GLuint)),
                 indices.data(), GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), offset(offsetof(Vertex, position)));
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), offset(offsetof(Vertex, color)));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    count_ = GLsizei(vertices.size());
  }
  // One glDrawElements in a record of its own: the vertices it recorded.
  std::shared_ptr<const glpt::rec::VertexData> draw_in_new_record() {
    next_record();
    glDrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, offset(0));
    EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
    const auto draws = recorded_draws(ctx_);
    return draws.size() == 1 ? draws[0].vertices : nullptr;
  }
  // What ending a record does to the recorder and the cache (no drawable here).
  void next_record() {
    ctx_.recorder.clear();
    ctx_.buffer_draws.record_cleared();
  }
  GLuint buffers_[2] = {};
  GLsizei count_ = 0;
};

TEST_F(BufferDrawReuseTest, UnchangedBuffersRecordTheSameVerticesAgain) {
  set_up_buffers(grid_triangles(10));
  const auto first = draw_in_new_record();
  ASSERT_TRUE(first);
  const auto second = draw_in_new_record();
  EXPECT_EQ(second, first);
  EXPECT_EQ(second->content_id(), first->content_id());
  // Also a glDrawArrays of the same buffers, cached under its own key.
  next_record();
  glDrawArrays(GL_TRIANGLES, 0, count_);
  glDrawArrays(GL_TRIANGLES, 0, count_);
  const auto draws = recorded_draws(ctx_);
  ASSERT_EQ(draws.size(), 2u);
  EXPECT_EQ(draws[0].vertices, draws[1].vertices);
  EXPECT_NE(draws[0].vertices, first);  // arrays and elements are recorded differently
  EXPECT_EQ(draws[0].vertices->source, glpt::rec::PrimitiveSource::kArrays);
}

TEST_F(BufferDrawReuseTest, EveryChangeTheVerticesDependOnRecordsNewOnes) {
  std::vector<Vertex> vertices = grid_triangles(10);
  set_up_buffers(vertices);
  auto last = draw_in_new_record();
  ASSERT_TRUE(last);
  auto expect_new = [&](const char* change) {
    const auto now = draw_in_new_record();
    ASSERT_TRUE(now) << change;
    EXPECT_NE(now, last) << change;
    EXPECT_NE(now->content_id(), last->content_id()) << change;
    last = now;
  };
  // glBufferSubData of the vertices: the new position is recorded.
  const float moved[3] = {0.5f, 0.25f, 0.0f};
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof moved, moved);
  expect_new("glBufferSubData");
  EXPECT_EQ(last->position.at(0), glm::vec4(0.5f, 0.25f, 0.0f, 1.0f));
  // Written through a mapping.
  auto* mapped = static_cast<Vertex*>(glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY));
  ASSERT_NE(mapped, nullptr);
  mapped[1].position[0] = -0.75f;
  EXPECT_TRUE(glUnmapBuffer(GL_ARRAY_BUFFER));
  expect_new("glMapBuffer");
  EXPECT_EQ(last->position.at(1).x, -0.75f);
  // The indices.
  const GLuint swapped[3] = {2, 1, 0};
  glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, sizeof swapped, swapped);
  expect_new("element buffer");
  EXPECT_EQ(last->indices.at(0), 2u);
  // A whole new store.
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
               GL_STATIC_DRAW);
  expect_new("glBufferData");
  // The pointer (offset, stride, type).
  glColorPointer(3, GL_UNSIGNED_BYTE, sizeof(Vertex), offset(offsetof(Vertex, color)));
  expect_new("glColorPointer");
  glColorPointer(4, GL_UNSIGNED_SHORT, sizeof(Vertex), offset(offsetof(Vertex, color)));
  expect_new("type");
  glColorPointer(4, GL_UNSIGNED_SHORT, 2 * sizeof(Vertex), offset(offsetof(Vertex, color)));
  expect_new("stride");
  // A current value the draw falls back to, once its array is disabled; -0.0 is not 0.0.
  glDisableClientState(GL_COLOR_ARRAY);
  expect_new("colour array disabled");
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  expect_new("glColor");
  EXPECT_EQ(at(last->color, 0), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  glNormal3f(0.0f, 0.0f, 1.0f);
  EXPECT_EQ(draw_in_new_record(), last);  // the current normal it already had
  glNormal3f(-0.0f, 0.0f, 1.0f);
  expect_new("glNormal -0.0");
  // The same draw again after all that: reused.
  EXPECT_EQ(draw_in_new_record(), last);
}

TEST_F(BufferDrawReuseTest, ClientArraysAreNeverReused) {
  std::vector<Vertex> vertices = grid_triangles(4);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glVertexPointer(3, GL_FLOAT, sizeof(Vertex), &vertices[0].position);
  glEnableClientState(GL_VERTEX_ARRAY);
  next_record();
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
  const auto first = recorded_draws(ctx_);
  next_record();
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
  const auto second = recorded_draws(ctx_);
  ASSERT_EQ(first.size(), 1u);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_NE(first[0].vertices->content_id(), second[0].vertices->content_id());
  EXPECT_EQ(ctx_.buffer_draws.size(), 0u);
  // Buffer-object vertices with client-memory indices: not cached either.
  std::vector<GLuint> indices = {0, 1, 2};
  set_up_buffers(vertices);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, indices.data());
  EXPECT_EQ(ctx_.buffer_draws.size(), 0u);
}

TEST_F(BufferDrawReuseTest, OnlyStaticBuffersAreCached) {
  const std::vector<Vertex> vertices = grid_triangles(4);
  set_up_buffers(vertices);
  const auto first = draw_in_new_record();
  EXPECT_EQ(ctx_.buffer_draws.size(), 1u);
  EXPECT_GT(ctx_.buffer_draws.bytes(), vertices.size() * sizeof(glm::vec4));
  // The same contents declared dynamic (or stream): recorded anew every time, nothing kept.
  for (GLenum usage : {GLenum(GL_DYNAMIC_DRAW), GLenum(GL_STREAM_DRAW)}) {
    for (uint64_t i = 0; i <= glpt::BufferDrawCache::kKeepRecords; ++i) next_record();
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
                 usage);
    const auto a = draw_in_new_record();
    const auto b = draw_in_new_record();
    ASSERT_TRUE(a && b);
    EXPECT_NE(a->content_id(), b->content_id());
    EXPECT_EQ(ctx_.buffer_draws.size(), 0u);
    EXPECT_EQ(ctx_.buffer_draws.bytes(), 0u);
  }
  // A static vertex buffer with dynamic indices: not cached either.
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
               GL_STATIC_DRAW);
  std::vector<GLuint> indices(vertices.size());
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = GLuint(i);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(GLuint)), indices.data(),
               GL_DYNAMIC_DRAW);
  draw_in_new_record();
  EXPECT_EQ(ctx_.buffer_draws.size(), 0u);
}

TEST_F(BufferDrawReuseTest, EntriesNotDrawnForSomeRecordsAreDropped) {
  set_up_buffers(grid_triangles(4));
  const auto first = draw_in_new_record();
  EXPECT_EQ(ctx_.buffer_draws.size(), 1u);
  for (uint64_t i = 0; i <= glpt::BufferDrawCache::kKeepRecords; ++i) next_record();
  EXPECT_EQ(ctx_.buffer_draws.size(), 0u);
  EXPECT_EQ(ctx_.buffer_draws.bytes(), 0u);
  EXPECT_NE(draw_in_new_record(), first);
}

TEST_F(BufferDrawReuseTest, FeedbackAndCompiledDrawsAreNotCached) {
  set_up_buffers(grid_triangles(2));
  GLfloat feedback[256];
  glFeedbackBuffer(256, GL_2D, feedback);
  glRenderMode(GL_FEEDBACK);
  glDrawArrays(GL_TRIANGLES, 0, count_);
  EXPECT_GT(glRenderMode(GL_RENDER), 0);
  EXPECT_EQ(ctx_.buffer_draws.size(), 0u);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glDrawArrays(GL_TRIANGLES, 0, count_);
  glEndList();
  EXPECT_EQ(ctx_.buffer_draws.size(), 0u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

// Raster mode: a large VBO (above ResidentGeometry::kMinBytes) drawn for several frames is
// uploaded once, from its second frame on, and its pixels stay those of the first frame; after a
// change of the buffer the pixels follow the change.
class ResidentDrawTest : public BufferDrawReuseTest {
 protected:
  void SetUp() override {
    BufferDrawReuseTest::SetUp();
    glpt::make_current_headless(ctx_, target_);
  }
  void TearDown() override {
    ctx_.target = nullptr;
    BufferDrawReuseTest::TearDown();
  }
  // Draws a frame (cleared to grey), swaps: the front buffer's pixels and the frame's statistics.
  // `indices`: an offset into the element buffer, or client memory.
  std::vector<uint8_t> frame(glpt::rt::FrameStats* stats, const void* indices = nullptr) {
    glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawElements(mode_, count_, GL_UNSIGNED_INT, indices);
    glpt::end_frame(ctx_, true);
    EXPECT_TRUE(ctx_.output);
    if (ctx_.output) *stats = ctx_.output->last_frame_stats();
    std::vector<uint8_t> rgba(size_t{kSize} * kSize * 4);
    glReadBuffer(GL_FRONT);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
    return rgba;
  }
  // The same draw of `vertices` from client memory (never reused): its pixels.
  std::vector<uint8_t> client_frame(const std::vector<Vertex>& vertices) {
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), &vertices[0].position);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), &vertices[0].color);
    std::vector<GLuint> indices(vertices.size());
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = GLuint(i);
    glpt::rt::FrameStats stats;
    std::vector<uint8_t> pixels = frame(&stats, indices.data());
    EXPECT_EQ(stats.resident_draws, 0u);
    return pixels;
  }
  static constexpr uint32_t kSize = 64;
  GLenum mode_ = GL_TRIANGLES;
  glpt_test::RasterMode raster_mode_;
  glpt::HeadlessTarget target_{kSize, kSize};
};

TEST_F(ResidentDrawTest, ReusedVerticesDrawTheSamePixelsAndFollowChanges) {
  // 4096 triangles: 12288 vertices, ~400 KB of position and colour floats.
  std::vector<Vertex> vertices = grid_triangles(4096);
  set_up_buffers(vertices);
  glpt::rt::FrameStats stats;
  const std::vector<uint8_t> first = frame(&stats);
  EXPECT_EQ(stats.draws, 1u);
  EXPECT_EQ(stats.resident_draws, 0u);  // first sight: the upload buffer
  size_t drawn = 0;
  for (size_t i = 0; i < first.size(); i += 4) drawn += first[i] != 128 || first[i + 1] != 128;
  EXPECT_GT(drawn, first.size() / 4 / 8);  // the triangles cover a good part of the window
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(frame(&stats), first) << "frame " << i + 2;
    EXPECT_EQ(stats.resident_draws, 1u) << "frame " << i + 2;
  }
  // Every triangle recoloured: the pixels follow, and equal a fresh recording's.
  for (Vertex& v : vertices) v.color[0] = uint8_t(255 - v.color[0]);
  glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(vertices.size() * sizeof(Vertex)),
                  vertices.data());
  const std::vector<uint8_t> changed = frame(&stats);
  EXPECT_NE(changed, first);
  EXPECT_EQ(stats.resident_draws, 0u);
  EXPECT_EQ(frame(&stats), changed);
  EXPECT_EQ(stats.resident_draws, 1u);
  // The same vertices from client memory draw the same pixels.
  EXPECT_EQ(client_frame(vertices), changed);
}

TEST_F(ResidentDrawTest, ResidentQuadsAreSplitPerFrameByTheTransform) {
  // GL_QUADS decompose by Mesa's path, which the transform decides (a quad with a vertex outside
  // the view volume is split along the other diagonal): a resident draw keeps its vertices, its
  // indices are made per frame. Quads in and out of the view volume, a colour per corner.
  std::vector<Vertex> vertices;
  for (uint32_t q = 0; q < 4096; ++q) {
    const float x = -1.2f + 2.4f * float(q % 64) / 64, y = -1.2f + 2.4f * float(q / 64) / 64;
    const float s = 2.4f / 64;
    const uint8_t c = uint8_t(q * 11);
    vertices.push_back({{x, y, 0.0f}, {c, 0, 0, 255}});
    vertices.push_back({{x + s, y, 0.0f}, {0, c, 0, 255}});
    vertices.push_back({{x + s, y + s, 0.0f}, {0, 0, c, 255}});
    vertices.push_back({{x, y + s, 0.0f}, {c, c, 0, 255}});
  }
  set_up_buffers(vertices);
  mode_ = GL_QUADS;
  glpt::rt::FrameStats stats;
  std::vector<uint8_t> last;
  glMatrixMode(GL_MODELVIEW);
  for (int i = 0; i < 4; ++i) {
    glLoadIdentity();
    glRotatef(float(i) * 7.0f, 0, 0, 1);
    last = frame(&stats);
  }
  EXPECT_EQ(stats.resident_draws, 1u);
  // The last frame again, recorded afresh from client memory: the same pixels.
  EXPECT_EQ(client_frame(vertices), last);
}

}  // namespace
