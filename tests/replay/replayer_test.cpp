// The replayer on hand-built calls (call_builder.hpp), through both backends: glpt's front end
// in raster mode and real Mesa (OSMesa). The expected pixels and values follow from the GL
// calls themselves (a red triangle over a blue clear, values given and read back).
#include "replay/replayer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <map>

#include "gl/gl_enums.h"
#include "gl/glx_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "replay/backend.hpp"
#include "replay/frame_selection.hpp"
#include "tests/replay/call_builder.hpp"

namespace {

using namespace glpt_test;
using glpt::replay::Backend;
using glpt::replay::FrameImage;
using glpt::replay::Replayer;

constexpr uint32_t kWidth = 64, kHeight = 48;
constexpr uint64_t kDisplay = 0x5500, kVisual = 0x5600, kContext = 0x1000, kWindow = 0x400001;

// A backend and a replayer that keeps every rendered frame.
class Session {
 public:
  // `want`: the frames rendered (all without it); `write`: those of them kept in `frames` (all
  // rendered ones without it); `history_window`: Backend::set_history_window.
  explicit Session(const std::string& backend, Replayer::WantFrame want = nullptr,
                   Replayer::WantFrame write = nullptr, uint32_t history_window = 1) {
    std::string error;
    backend_ = backend == "mesa" ? glpt::replay::create_mesa_backend(&error)
                                 : glpt::replay::create_glpt_backend(&error);
    EXPECT_TRUE(backend_) << error;
    if (!backend_) return;
    backend_->set_history_window(history_window);
    if (!want) want = [](uint64_t) { return true; };
    replayer_ = std::make_unique<Replayer>(
        *backend_, std::move(want),
        [this](uint64_t frame, const FrameImage& image, std::string*) {
          frames[frame] = image;
          return true;
        },
        std::move(write));
  }
  void replay(const trace::Call& call) {
    std::string error;
    ASSERT_TRUE(replayer_->replay(call, &error)) << call.sig->name << ": " << error;
  }
  template <typename F>
  F gl(const char* name) {
    return reinterpret_cast<F>(backend_->resolve(name));
  }
  Replayer& replayer() { return *replayer_; }
  Backend& backend() { return *backend_; }

  std::map<uint64_t, FrameImage> frames;

 private:
  std::unique_ptr<Backend> backend_;
  std::unique_ptr<Replayer> replayer_;
};

// RGBA of pixel (x, y), y from the bottom.
std::array<uint8_t, 4> pixel(const FrameImage& image, uint32_t x, uint32_t y) {
  const size_t i = (size_t{y} * image.width + x) * 4;
  return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2], image.rgba[i + 3]};
}
constexpr std::array<uint8_t, 4> kRed{255, 0, 0, 255}, kBlue{0, 0, 255, 255};

class ReplayBackends : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { setenv("GLPT_MODE", "raster", 1); }

  // glXChooseVisual + glXCreateContext + glXMakeCurrent + glViewport, as a GLX program starts.
  void open_window(Session& s, bool double_buffered = true) {
    trace::Value attribs = double_buffered
                               ? ints({GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1, 0})
                               : ints({GLX_RGBA, GLX_DEPTH_SIZE, 1, 0});
    s.replay(b.call("XOpenDisplay", {null()}, pointer(kDisplay)));
    s.replay(b.call("glXChooseVisual", {pointer(kDisplay), sint(0), attribs}, pointer(kVisual)));
    s.replay(b.call("glXCreateContext", {pointer(kDisplay), pointer(kVisual), pointer(0), sint(1)},
                    pointer(kContext)));
    s.replay(
        b.call("glXMakeCurrent", {pointer(kDisplay), uintv(kWindow), pointer(kContext)}, sint(1)));
    s.replay(b.call("glViewport", {sint(0), sint(0), sint(kWidth), sint(kHeight)}));
  }
  void clear_blue(Session& s) {
    s.replay(b.call("glClearColor", {real(0), real(0), real(1), real(1)}));
    s.replay(b.call("glClear", {uintv(GL_COLOR_BUFFER_BIT)}));
    s.replay(b.call("glColor3f", {real(1), real(0), real(0)}));
  }
  void swap(Session& s) { s.replay(b.call("glXSwapBuffers", {pointer(kDisplay), uintv(kWindow)})); }
  // The frame shows the red triangle over the centre and blue in the top corners.
  static void expect_triangle(const Session& s, uint64_t frame) {
    ASSERT_EQ(s.frames.count(frame), 1u);
    const FrameImage& image = s.frames.at(frame);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    EXPECT_EQ(pixel(image, kWidth / 2, kHeight / 2), kRed);
    EXPECT_EQ(pixel(image, 1, kHeight - 2), kBlue);
    EXPECT_EQ(pixel(image, kWidth - 2, kHeight - 2), kBlue);
  }

  CallBuilder b;
};

TEST_P(ReplayBackends, ImmediateModeTriangleReachesTheImage) {
  Session s(GetParam());
  open_window(s);
  clear_blue(s);
  s.replay(b.call("glBegin", {enumv(GL_TRIANGLES)}));
  s.replay(b.call("glVertex2f", {real(-1), real(-1)}));
  s.replay(b.call("glVertex2f", {real(1), real(-1)}));
  s.replay(b.call("glVertex2f", {real(0), real(1)}));
  s.replay(b.call("glEnd", {}));
  swap(s);
  EXPECT_EQ(s.replayer().counts().frames, 1u);
  expect_triangle(s, 0);
}

// apitrace records a client array's pointer as an opaque address and, at the draw, a fake
// gl*Pointer call with the memory the draw reads as a blob.
TEST_P(ReplayBackends, ClientArraysFromTheTracersBlobsDraw) {
  Session s(GetParam());
  open_window(s);
  clear_blue(s);
  const float vertices[] = {-1, -1, 1, -1, 0, 1};
  const uint8_t indices[] = {0, 1, 2};
  s.replay(b.call("glVertexPointer", {sint(2), enumv(GL_FLOAT), sint(0), pointer(0x7fff1000)}));
  s.replay(b.call("glEnableClientState", {enumv(GL_VERTEX_ARRAY)}));
  s.replay(b.call("glVertexPointer",
                  {sint(2), enumv(GL_FLOAT), sint(0), blob(vertices, sizeof vertices)}));
  s.replay(b.call("glDrawElements", {enumv(GL_TRIANGLES), sint(3), enumv(GL_UNSIGNED_BYTE),
                                     blob(indices, sizeof indices)}));
  swap(s);
  expect_triangle(s, 0);
}

// With a buffer object bound, the recorded pointer is an offset into it.
TEST_P(ReplayBackends, ArrayPointersIntoABufferObjectStayOffsets) {
  Session s(GetParam());
  open_window(s);
  clear_blue(s);
  const float data[] = {9, 9, -1, -1, 1, -1, 0, 1};  // two floats before the vertices
  s.replay(b.call("glGenBuffers", {sint(1), ints({31})}));
  s.replay(b.call("glBindBuffer", {enumv(GL_ARRAY_BUFFER), uintv(31)}));
  s.replay(b.call("glBufferData", {enumv(GL_ARRAY_BUFFER), sint(sizeof data),
                                   blob(data, sizeof data), enumv(GL_STATIC_DRAW)}));
  s.replay(b.call("glVertexPointer", {sint(2), enumv(GL_FLOAT), sint(0), pointer(8)}));
  s.replay(b.call("glEnableClientState", {enumv(GL_VERTEX_ARRAY)}));
  s.replay(b.call("glDrawArrays", {enumv(GL_TRIANGLES), sint(0), sint(3)}));
  swap(s);
  expect_triangle(s, 0);
}

TEST_P(ReplayBackends, RecordedArraysBecomeTypedArrays) {
  Session s(GetParam());
  open_window(s);
  s.replay(
      b.call("glLightfv", {enumv(GL_LIGHT1), enumv(GL_DIFFUSE), reals({0.25, 0.5, 0.75, 0.125})}));
  s.replay(b.call("glLoadMatrixd", {reals({2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 5, 6, 7, 1})}));
  float diffuse[4] = {};
  s.gl<void (*)(GLenum, GLenum, float*)>("glGetLightfv")(GL_LIGHT1, GL_DIFFUSE, diffuse);
  EXPECT_EQ(diffuse[0], 0.25f);
  EXPECT_EQ(diffuse[1], 0.5f);
  EXPECT_EQ(diffuse[2], 0.75f);
  EXPECT_EQ(diffuse[3], 0.125f);
  double m[16] = {};
  s.gl<void (*)(GLenum, double*)>("glGetDoublev")(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[5], 3.0);
  EXPECT_EQ(m[12], 5.0);
}

TEST_P(ReplayBackends, GeneratedNamesAreMappedToTheReplaysOwn) {
  Session s(GetParam());
  open_window(s);
  s.replay(b.call("glGenTextures", {sint(1), ints({77})}));
  s.replay(b.call("glBindTexture", {enumv(GL_TEXTURE_2D), uintv(77)}));
  GLint bound = 0;
  s.gl<void (*)(GLenum, GLint*)>("glGetIntegerv")(GL_TEXTURE_BINDING_2D, &bound);
  EXPECT_NE(bound, 77);  // a fresh context's first generated name is small
  EXPECT_NE(bound, 0);
  s.replay(b.call("glGenLists", {sint(2)}, uintv(500)));
  s.replay(b.call("glNewList", {uintv(501), enumv(GL_COMPILE)}));
  s.replay(b.call("glEndList", {}));
  const GLuint first = s.gl<GLuint (*)(GLsizei)>("glGenLists")(1);
  EXPECT_EQ(first, 3u) << "lists 1 and 2 were generated by the replay (501 -> 2)";
  EXPECT_TRUE(s.gl<GLboolean (*)(GLuint)>("glIsList")(2));
}

// apitrace writes what a program stores into mapped memory as fake memcpy calls to the address
// glMapBuffer returned when recording.
TEST_P(ReplayBackends, MappedBuffersTakeTheTracersMemcpy) {
  Session s(GetParam());
  open_window(s);
  s.replay(b.call("glGenBuffers", {sint(1), ints({9})}));
  s.replay(b.call("glBindBuffer", {enumv(GL_ARRAY_BUFFER), uintv(9)}));
  s.replay(
      b.call("glBufferData", {enumv(GL_ARRAY_BUFFER), sint(8), null(), enumv(GL_STATIC_DRAW)}));
  s.replay(
      b.call("glMapBuffer", {enumv(GL_ARRAY_BUFFER), enumv(GL_WRITE_ONLY)}, pointer(0xabc000)));
  s.replay(b.call("memcpy", {pointer(0xabc004), blob("wxyz", 4), uintv(4)}));
  s.replay(b.call("glUnmapBuffer", {enumv(GL_ARRAY_BUFFER)}, sint(1)));
  char bytes[5] = {};
  s.gl<void (*)(GLenum, GLintptr, GLsizeiptr, void*)>("glGetBufferSubData")(GL_ARRAY_BUFFER, 4, 4,
                                                                            bytes);
  EXPECT_STREQ(bytes, "wxyz");
  EXPECT_EQ(s.replayer().counts().memcpy_outside_mappings, 0u);
}

// apitrace's frame markers: on a single-buffered drawable glFlush ends the frame.
TEST_P(ReplayBackends, GlFlushEndsAFrameOfASingleBufferedWindow) {
  Session s(GetParam());
  open_window(s, /*double_buffered=*/false);
  clear_blue(s);
  s.replay(b.call("glRectf", {real(-1), real(-1), real(1), real(0.5)}));
  s.replay(b.call("glFlush", {}));
  ASSERT_EQ(s.replayer().counts().frames, 1u);
  ASSERT_EQ(s.frames.count(0), 1u);
  EXPECT_EQ(pixel(s.frames[0], kWidth / 2, kHeight / 2), kRed);
  EXPECT_EQ(pixel(s.frames[0], kWidth / 2, kHeight - 2), kBlue);
}

// A trace whose image blob is shorter than the image GL reads: the rest reads as zeros.
TEST_P(ReplayBackends, ShortImageBlobsArePaddedWithZeros) {
  Session s(GetParam());
  open_window(s);
  clear_blue(s);
  const uint8_t red[4] = {255, 0, 0, 255};
  s.replay(b.call("glWindowPos2i", {sint(0), sint(0)}));
  s.replay(b.call("glDrawPixels", {sint(3), sint(1), enumv(GL_RGBA), enumv(GL_UNSIGNED_BYTE),
                                   blob(red, sizeof red)}));
  swap(s);
  ASSERT_EQ(s.frames.count(0), 1u);
  EXPECT_EQ(pixel(s.frames[0], 0, 0), kRed);
  EXPECT_EQ(pixel(s.frames[0], 1, 0), (std::array<uint8_t, 4>{0, 0, 0, 255}));
  EXPECT_EQ(pixel(s.frames[0], 2, 0), (std::array<uint8_t, 4>{0, 0, 0, 255}));
  EXPECT_EQ(pixel(s.frames[0], 3, 0), kBlue);
}

// EGL: a pbuffer has its recorded size (a glViewport does not grow it); eglSwapBuffers ends the
// frame.
TEST_P(ReplayBackends, EglPbufferHasItsRecordedSize) {
  Session s(GetParam());
  constexpr int64_t kEglWidth = 0x3057, kEglHeight = 0x3056, kEglNone = 0x3038;
  s.replay(b.call("eglGetDisplay", {pointer(0)}, pointer(kDisplay)));
  s.replay(b.call("eglCreatePbufferSurface",
                  {pointer(kDisplay), pointer(7), ints({kEglWidth, 40, kEglHeight, 24, kEglNone})},
                  pointer(0x3000)));
  s.replay(b.call("eglCreateContext", {pointer(kDisplay), pointer(7), pointer(0), ints({kEglNone})},
                  pointer(0x4000)));
  s.replay(b.call("eglMakeCurrent",
                  {pointer(kDisplay), pointer(0x3000), pointer(0x3000), pointer(0x4000)},
                  uintv(1)));
  s.replay(b.call("glViewport", {sint(0), sint(0), sint(400), sint(300)}));
  s.replay(b.call("glViewport", {sint(0), sint(0), sint(40), sint(24)}));
  clear_blue(s);
  s.replay(b.call("glRectf", {real(-0.5), real(-0.5), real(0.5), real(0.5)}));
  s.replay(b.call("eglSwapBuffers", {pointer(kDisplay), pointer(0x3000)}, uintv(1)));
  ASSERT_EQ(s.frames.count(0), 1u);
  const FrameImage& image = s.frames[0];
  EXPECT_EQ(image.width, 40u);
  EXPECT_EQ(image.height, 24u);
  EXPECT_EQ(pixel(image, 20, 12), kRed);
  EXPECT_EQ(pixel(image, 1, 1), kBlue);
}

// Two recording threads, each with its context current: every call goes to its own thread's
// context, however the trace interleaves them.
TEST_P(ReplayBackends, EachRecordingThreadKeepsItsCurrentContext) {
  Session s(GetParam());
  open_window(s);  // thread 0
  auto on_thread = [](trace::Call call, uint32_t thread) {
    call.thread = thread;
    return call;
  };
  s.replay(
      on_thread(b.call("glXCreateContext",
                       {pointer(kDisplay), pointer(kVisual), pointer(0), sint(1)}, pointer(0x2000)),
                1));
  s.replay(on_thread(
      b.call("glXMakeCurrent", {pointer(kDisplay), uintv(0x400002), pointer(0x2000)}, sint(1)), 1));
  s.replay(on_thread(b.call("glClearColor", {real(0), real(1), real(0), real(1)}), 1));
  clear_blue(s);  // thread 0 again: its own context's clear colour
  float color[4] = {};
  s.gl<void (*)(GLenum, float*)>("glGetFloatv")(GL_COLOR_CLEAR_VALUE, color);
  EXPECT_EQ(color[2], 1.0f) << "thread 0's context is current";
  s.replay(on_thread(b.call("glFinish", {}), 1));
  s.gl<void (*)(GLenum, float*)>("glGetFloatv")(GL_COLOR_CLEAR_VALUE, color);
  EXPECT_EQ(color[1], 1.0f) << "thread 1's context is current";
}

INSTANTIATE_TEST_SUITE_P(, ReplayBackends, ::testing::Values("glpt", "mesa"),
                         [](const auto& info) { return info.param; });

TEST(Replayer, UnknownCallsAreCountedAndNotReplayed) {
  setenv("GLPT_MODE", "raster", 1);
  CallBuilder b;
  Session s("glpt");
  s.replay(b.call("glFrobnicateXYZ", {sint(1)}));
  s.replay(b.call("glFrobnicateXYZ", {sint(2)}));
  s.replay(b.call("vkCreateInstance", {}));
  s.replay(b.call("glGetFloatv", {enumv(GL_CURRENT_COLOR), reals({1, 2, 3, 4})}));
  const auto& counts = s.replayer().counts();
  EXPECT_EQ(counts.unknown.at("glFrobnicateXYZ"), 2u);
  EXPECT_EQ(counts.unknown.at("vkCreateInstance"), 1u);
  EXPECT_EQ(counts.unknown.count("glGetFloatv"), 0u);
  EXPECT_EQ(counts.skipped_queries, 1u);
}

TEST(Replayer, CommandsGlptDoesNotImplementAreListed) {
  setenv("GLPT_MODE", "raster", 1);
  CallBuilder b;
  Session s("glpt");
  s.replay(b.call("glXCreateContext", {pointer(1), pointer(2), pointer(0), sint(1)}, pointer(3)));
  s.replay(b.call("glXMakeCurrent", {pointer(1), uintv(4), pointer(3)}, sint(1)));
  // Any exported command glpt leaves unimplemented; the test looks one up rather than naming it.
  std::string unimplemented;
  size_t count = 0;
  const glpt::GlProcEntry* table = glpt::gl_proc_table(&count);
  for (size_t i = 0; i < count && unimplemented.empty(); ++i)
    if (!table[i].implemented && glpt::replay::find_dispatch_entry(table[i].name) != nullptr &&
        std::strncmp(table[i].name, "glGen", 5) != 0)
      unimplemented = table[i].name;
  if (unimplemented.empty()) GTEST_SKIP() << "glpt implements every command";
  s.replay(b.call(unimplemented, {sint(0), sint(0), sint(0), sint(0), sint(0), sint(0)}));
  bool listed = false;
  for (const auto& [name, n] : s.backend().unimplemented_calls())
    listed = listed || (name == unimplemented && n == 1);
  EXPECT_TRUE(listed) << unimplemented;
}

}  // namespace

namespace {

// A lit scene the path tracer traces: a floor and a card above it (shadows, ambient occlusion
// and a bounce: every pixel's value depends on its random samples).
void lit_scene(Session& s, CallBuilder& b) {
  s.replay(b.call("glXCreateContext", {pointer(1), pointer(2), pointer(0), sint(1)}, pointer(3)));
  s.replay(b.call("glXMakeCurrent", {pointer(1), uintv(4), pointer(3)}, sint(1)));
  s.replay(b.call("glViewport", {sint(0), sint(0), sint(48), sint(48)}));
  s.replay(b.call("glMatrixMode", {enumv(GL_PROJECTION)}));
  s.replay(b.call("glFrustum", {real(-1), real(1), real(-1), real(1), real(1), real(20)}));
  s.replay(b.call("glMatrixMode", {enumv(GL_MODELVIEW)}));
  s.replay(b.call("glEnable", {enumv(GL_DEPTH_TEST)}));
  s.replay(b.call("glEnable", {enumv(GL_LIGHTING)}));
  s.replay(b.call("glEnable", {enumv(GL_LIGHT0)}));
  s.replay(b.call("glLightfv", {enumv(GL_LIGHT0), enumv(GL_POSITION), reals({1, 4, 0, 1})}));
}

// A read back and glFinish in the middle of a frame.
void s_read_and_finish(Session& s, CallBuilder& b) {
  static std::array<uint8_t, 4> sink;
  s.replay(b.call("glReadPixels", {sint(0), sint(0), sint(1), sint(1), enumv(GL_RGBA),
                                   enumv(GL_UNSIGNED_BYTE), blob(sink.data(), sink.size())}));
  s.replay(b.call("glFinish", {}));
}

void lit_frame(Session& s, CallBuilder& b) {
  s.replay(b.call("glClear", {uintv(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)}));
  s.replay(b.call("glBegin", {enumv(GL_QUADS)}));
  s.replay(b.call("glNormal3f", {real(0), real(1), real(0)}));
  for (const auto& [x, y, z] : std::vector<std::array<double, 3>>{{-4, -1, -2},
                                                                  {4, -1, -2},
                                                                  {4, -1, -9},
                                                                  {-4, -1, -9},  // floor
                                                                  {-0.5, 0, -3.5},
                                                                  {0.5, 0, -3.5},
                                                                  {0.5, 0, -4.5},
                                                                  {-0.5, 0, -4.5}})  // card
    s.replay(b.call("glVertex3f", {real(x), real(y), real(z)}));
  s.replay(b.call("glEnd", {}));
  s.replay(b.call("glXSwapBuffers", {pointer(1), uintv(4)}));
}

// Sharding: a frame's pixels must not depend on which frames were rendered before it.
TEST(ReplayShards, PathTracedFramesDoNotDependOnTheFramesRenderedBefore) {
  setenv("GLPT_MODE", "path", 1);
  setenv("GLPT_ACCUMULATE", "0", 1);  // as glpt-replay sets it
  CallBuilder whole_calls, shard_calls;
  Session whole("glpt");
  Session shard("glpt", [](uint64_t f) { return f % 2 == 1; });
  // One after the other: GL's current context is per thread.
  lit_scene(whole, whole_calls);
  for (int f = 0; f < 4; ++f) lit_frame(whole, whole_calls);
  lit_scene(shard, shard_calls);
  for (int f = 0; f < 4; ++f) lit_frame(shard, shard_calls);
  setenv("GLPT_MODE", "raster", 1);
  unsetenv("GLPT_ACCUMULATE");
  ASSERT_EQ(whole.frames.size(), 4u);
  ASSERT_EQ(shard.frames.size(), 2u);
  if (whole.frames[1].rgba == whole.frames[3].rgba)
    GTEST_SKIP() << "identical frames differ by nothing random: no path tracing here";
  EXPECT_TRUE(shard.frames[1].rgba == whole.frames[1].rgba);
  EXPECT_TRUE(shard.frames[3].rgba == whole.frames[3].rgba);
  EXPECT_EQ(shard.replayer().counts().frames_rendered, 2u);
}

// lit_frame with the card moved by `f` tenths of a unit: the denoiser reprojects its history.
void moving_lit_frame(Session& s, CallBuilder& b, int f) {
  s.replay(b.call("glClear", {uintv(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)}));
  s.replay(b.call("glBegin", {enumv(GL_QUADS)}));
  s.replay(b.call("glNormal3f", {real(0), real(1), real(0)}));
  const double x = 0.1 * f;
  for (const auto& [vx, vy, vz] : std::vector<std::array<double, 3>>{{-4, -1, -2},
                                                                     {4, -1, -2},
                                                                     {4, -1, -9},
                                                                     {-4, -1, -9},
                                                                     {x - 0.5, 0, -3.5},
                                                                     {x + 0.5, 0, -3.5},
                                                                     {x + 0.5, 0, -4.5},
                                                                     {x - 0.5, 0, -4.5}})
    s.replay(b.call("glVertex3f", {real(vx), real(vy), real(vz)}));
  s.replay(b.call("glEnd", {}));
  s.replay(b.call("glXSwapBuffers", {pointer(1), uintv(4)}));
}

// With a history window, a frame builds on the denoiser's history of the frames of its window
// before it: a shard takes whole windows and renders the frames of a written frame's window
// before it, and writes exactly the frames one whole replay writes.
TEST(ReplayShards, FramesBuildOnTheHistoryOfTheirWindowAndShardsStillEqualOneReplay) {
  setenv("GLPT_MODE", "path", 1);
  setenv("GLPT_ACCUMULATE", "0", 1);
  constexpr uint32_t kWindow = 4;
  glpt::replay::FrameSelection selection;
  std::string error;
  ASSERT_TRUE(selection.parse_shard("1/2", &error)) << error;
  ASSERT_TRUE(selection.parse_frames("2,6,9-10", &error)) << error;
  selection.set_history_window(kWindow);
  CallBuilder whole_calls, shard_calls, independent_calls;
  Session whole("glpt", nullptr, nullptr, kWindow);
  Session shard(
      "glpt", [&](uint64_t f) { return selection.rendered(f); },
      [&](uint64_t f) { return selection.written(f); }, kWindow);
  Session independent("glpt");  // a window of 1: every frame starts afresh
  for (Session* s : {&whole, &shard, &independent}) {
    CallBuilder& b = s == &whole ? whole_calls : s == &shard ? shard_calls : independent_calls;
    lit_scene(*s, b);
    for (int f = 0; f < 12; ++f) moving_lit_frame(*s, b, f);
  }
  setenv("GLPT_MODE", "raster", 1);
  unsetenv("GLPT_ACCUMULATE");
  ASSERT_EQ(whole.frames.size(), 12u);
  if (whole.frames[4].rgba == whole.frames[5].rgba)
    GTEST_SKIP() << "frames differ by nothing random: no path tracing here";
  // Shard 1 of 2 takes windows 1 (frames 4-7) and 3: it writes frame 6, rendering 4 and 5 for
  // its history; frames 2, 9 and 10 are shard 0's.
  ASSERT_EQ(shard.frames.size(), 1u);
  EXPECT_TRUE(shard.frames[6].rgba == whole.frames[6].rgba);
  EXPECT_EQ(shard.replayer().counts().frames_rendered, 3u);
  // The history shows: frame 6 after 4 and 5 is not frame 6 alone; a window's first frame is.
  EXPECT_FALSE(whole.frames[6].rgba == independent.frames[6].rgba);
  EXPECT_TRUE(whole.frames[4].rgba == independent.frames[4].rgba);
}

// A frame that draws one more quad over the last without clearing (a program that builds its
// image over frames), ending with glFinish before its swap as xscreensaver's hacks do.
void accumulating_frame(Session& s, CallBuilder& b, int f) {
  if (f == 0) {
    s.replay(b.call("glClearColor", {real(0), real(0), real(0.5), real(1)}));
    s.replay(b.call("glClear", {uintv(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)}));
  }
  s.replay(b.call("glColor3f", {real(0.2 * f), real(1 - 0.15 * f), real(0.3)}));
  s.replay(b.call("glBegin", {enumv(GL_QUADS)}));
  const double x = -3.5 + 1.1 * f, y = -1.0 + 0.3 * f;
  for (const auto& [dx, dy] :
       std::vector<std::array<double, 2>>{{0, 0}, {1.5, 0}, {1.5, 1.5}, {0, 1.5}})
    s.replay(b.call("glVertex3f", {real(x + dx), real(y + dy), real(-6)}));
  s.replay(b.call("glEnd", {}));
  s.replay(b.call("glFinish", {}));
  s.replay(b.call("glXSwapBuffers", {pointer(1), uintv(4)}));
}

// Shards skip the frames other shards write: frames a later frame builds on are rendered first,
// so a program that never clears still gets exactly the frames one whole replay gets.
TEST(ReplayShards, AProgramThatDoesNotClearGetsTheSkippedFramesItBuildsOn) {
  for (const char* mode : {"raster", "path"}) {
    SCOPED_TRACE(mode);
    setenv("GLPT_MODE", mode, 1);
    setenv("GLPT_ACCUMULATE", "0", 1);
    CallBuilder whole_calls, shard_calls;
    Session whole("glpt");
    Session shard("glpt", [](uint64_t f) { return f % 3 == 2; });
    lit_scene(whole, whole_calls);
    for (int f = 0; f < 6; ++f) accumulating_frame(whole, whole_calls, f);
    lit_scene(shard, shard_calls);
    for (int f = 0; f < 6; ++f) accumulating_frame(shard, shard_calls, f);
    ASSERT_EQ(whole.frames.size(), 6u);
    ASSERT_EQ(shard.frames.size(), 2u);
    EXPECT_TRUE(shard.frames[2].rgba == whole.frames[2].rgba);
    EXPECT_TRUE(shard.frames[5].rgba == whole.frames[5].rgba);
    // Every skipped frame was needed: rendered, none dropped.
    const glpt::Context* context = glpt::current_context();
    ASSERT_NE(context, nullptr);
    EXPECT_EQ(context->skipped_frames.rendered(), 4u);
    EXPECT_EQ(context->skipped_frames.dropped(), 0u);
  }
  setenv("GLPT_MODE", "raster", 1);
  unsetenv("GLPT_ACCUMULATE");
}

// Frames that a later frame clears away are never rendered: a shard costs their recording.
TEST(ReplayShards, SkippedFramesThatTheNextFrameClearsAwayAreNotRendered) {
  setenv("GLPT_MODE", "path", 1);
  setenv("GLPT_ACCUMULATE", "0", 1);
  CallBuilder calls;
  Session shard("glpt", [](uint64_t f) { return f == 5; });
  lit_scene(shard, calls);
  for (int f = 0; f < 6; ++f) {
    // glFinish and glReadPixels inside the frame: a replay has no reader to answer.
    s_read_and_finish(shard, calls);
    lit_frame(shard, calls);
  }
  setenv("GLPT_MODE", "raster", 1);
  unsetenv("GLPT_ACCUMULATE");
  ASSERT_EQ(shard.frames.size(), 1u);
  const glpt::Context* context = glpt::current_context();
  ASSERT_NE(context, nullptr);
  EXPECT_EQ(context->skipped_frames.rendered(), 0u);
  EXPECT_EQ(context->skipped_frames.dropped(), 5u);
  EXPECT_EQ(context->output->last_frame_stats().draws, 1u);  // frame 5's one glBegin/glEnd
}

}  // namespace
