// rec::record_access: what a record needs of the records before it (glpt-replay's shards hold
// skipped frames while later frames overwrite everything they left; gl_shim/frame/
// deferred_frames.hpp). Records are built by hand, as the front end records them.
#include "rt_core/record/record_dependencies.hpp"

#include <gtest/gtest.h>

#include "gl/gl_enums.h"
#include "record_builder.hpp"

namespace glpt::rec {
namespace {

using rt::test::RecordBuilder;

RecordBuilder double_buffered() {
  RecordBuilder b(32, 32);
  b.drawable.double_buffered = true;
  b.raster.ops.draw_buffer = b.raster.ops.read_buffer = GL_BACK;
  b.raster.ops.depth_test = true;
  return b;
}

void draw_quad(RecordBuilder& b) { b.quad({-1, -1, -2}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1)); }

TEST(RecordAccess, AFrameThatClearsEverythingFirstDependsOnNothing) {
  RecordBuilder b = double_buffered();
  b.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  draw_quad(b);
  const RecordAccess access = record_access(b.record, b.drawable, /*swaps=*/true);
  EXPECT_EQ(access.depends, 0);
  EXPECT_EQ(access.overwrites, kBackColor | kDepthBuffer | kFrontColor);
  EXPECT_EQ(access.writes, kBackColor | kDepthBuffer | kFrontColor);
  // Without the swap, the front buffer is left as it was.
  EXPECT_EQ(record_access(b.record, b.drawable, false).overwrites, kBackColor | kDepthBuffer);
}

TEST(RecordAccess, DrawingBeforeOrWithoutAClearDependsOnWhatWasThere) {
  RecordBuilder b = double_buffered();
  draw_quad(b);
  EXPECT_EQ(record_access(b.record, b.drawable, true).depends, kBackColor | kDepthBuffer);
  RecordBuilder no_depth_test = double_buffered();
  no_depth_test.raster.ops.depth_test = false;
  draw_quad(no_depth_test);
  EXPECT_EQ(record_access(no_depth_test.record, b.drawable, true).depends, kBackColor);
  // Colour cleared, depth not: the draw's depth test reads the old depth.
  RecordBuilder colour_only = double_buffered();
  colour_only.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT);
  draw_quad(colour_only);
  EXPECT_EQ(record_access(colour_only.record, b.drawable, true).depends, kDepthBuffer);
}

TEST(RecordAccess, PartialClearsAndMaskedClearsOverwriteNothing) {
  RecordBuilder scissored = double_buffered();
  scissored.raster.ops.scissor_test = true;
  scissored.raster.ops.scissor_box = {0, 0, 16, 32};
  scissored.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  EXPECT_EQ(record_access(scissored.record, scissored.drawable, false).overwrites, 0);
  EXPECT_EQ(record_access(scissored.record, scissored.drawable, false).depends,
            kBackColor | kDepthBuffer);
  // A scissor box holding the whole drawable clears it whole.
  RecordBuilder whole = double_buffered();
  whole.raster.ops.scissor_test = true;
  whole.raster.ops.scissor_box = {0, 0, 32, 32};
  whole.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(record_access(whole.record, whole.drawable, false).overwrites, kBackColor);
  RecordBuilder masked = double_buffered();
  masked.raster.ops.color_write = {true, true, true, false};
  masked.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(record_access(masked.record, masked.drawable, false).overwrites, 0);
  EXPECT_EQ(record_access(masked.record, masked.drawable, false).depends, kBackColor);
}

TEST(RecordAccess, TheFrontBufferStencilAndAccumulationBuffer) {
  // Drawing into the front buffer of a double-buffered drawable after clearing the back.
  RecordBuilder front = double_buffered();
  front.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  front.raster.ops.draw_buffer = GL_FRONT;
  draw_quad(front);
  EXPECT_EQ(record_access(front.record, front.drawable, true).depends, kFrontColor);
  // A stencil test reads the stencil buffer; GL_INCR writes it.
  RecordBuilder stencil = double_buffered();
  stencil.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  stencil.raster.ops.stencil_test = true;
  stencil.raster.ops.stencil_depth_pass = GL_INCR;
  draw_quad(stencil);
  const RecordAccess s = record_access(stencil.record, stencil.drawable, true);
  EXPECT_EQ(s.depends, kStencilBuffer);
  EXPECT_NE(s.writes & kStencilBuffer, 0);
  // glAccum reads and writes the accumulation buffer, which outlives frames.
  RecordBuilder accum = double_buffered();
  accum.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  Accum a;
  a.op = GL_ACCUM;
  a.value = 0.5f;
  a.state = static_cast<StateId>(accum.record.states.size() - 1);
  accum.record.commands.push_back(a);
  const RecordAccess acc = record_access(accum.record, accum.drawable, true);
  EXPECT_EQ(acc.depends, kAccumBuffer);
  EXPECT_NE(acc.writes & kAccumBuffer, 0);
}

TEST(RecordAccess, ASingleBufferedDrawableHasOneColourBuffer) {
  RecordBuilder b(32, 32);             // single-buffered, drawing to GL_FRONT
  b.raster.ops.draw_buffer = GL_BACK;  // names the one buffer too
  b.clear(glm::vec4(0), GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  draw_quad(b);
  const RecordAccess access = record_access(b.record, b.drawable, false);
  EXPECT_EQ(access.depends, 0);
  EXPECT_EQ(access.overwrites, kFrontColor | kDepthBuffer);
}

}  // namespace
}  // namespace glpt::rec
