// Mesa's bitmap cache, reproduced in the frame record.
//
// Mesa (src/mesa/state_tracker/st_cb_bitmap.c) does not draw a small glBitmap at once: it ORs
// the bitmap into a 512 x 32 cache and draws the cache as one quad when it is flushed. Bitmaps
// join the cache while they fit in it (relative to where its first bitmap put it), have the same
// raster colour and depth (within 1e-6), the same fixed-function fragment program and the same
// scissor enable; any other draw, clear, pixel command or read (and glFlush, texture uploads)
// flushes it first. Its quad is drawn with the fragment operations Mesa validated last before
// the flush (blending, depth/stencil, alpha test, logic op, colour mask, scissor box): those of
// the last glBitmap call, or of the glBitmap that did not fit and caused the flush, which can
// be state set after the cached bitmaps were issued. Overlapping cached bitmaps make one
// fragment per pixel, not one per bitmap. Bitmaps too big for the cache (wider than 512 or
// taller than 32) and glAccum do not flush it: they are drawn before the cached bitmaps.
//
// glpt keeps the cache's bitmaps merged in one rec::Bitmap, the last command of the record while
// the cache is open, and re-points its state snapshot as Mesa's validation would.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;

// What decides Mesa's fixed-function fragment program for a bitmap (ff_fragment_shader.cpp's
// key, as far as glpt's state reaches), plus the scissor enable and draw buffer the cache keeps.
struct BitmapFragmentKey {
  bool fog = false;
  uint32_t fog_mode = 0;
  bool color_sum = false;  // GL_COLOR_SUM
  bool lighting = false;
  bool separate_specular = false;
  std::array<uint32_t, rec::kMaxTextureUnits> texture_target{};
  std::array<rec::TexEnv, rec::kMaxTextureUnits> texture_env{};  // constants zeroed
  bool scissor_test = false;
  uint32_t draw_buffer = 0;

  bool operator==(const BitmapFragmentKey&) const = default;
};

struct BitmapCache {
  bool open = false;
  uint64_t recorder_events = 0;  // FrameRecorder::events() after the cache's command was added
  size_t command = 0;            // index of the cache's rec::Bitmap in the record
  int64_t x = 0, y = 0;          // window position of the cache's lower-left corner
  float z = 0.0f;
  glm::vec4 color{0.0f};
  BitmapFragmentKey key;
};

// Records `bitmap` (its state not yet set) as Mesa draws it: into the open cache, or starting a
// new one, or (too big for the cache) drawn before the cached bitmaps.
void record_bitmap(Context& ctx, rec::Bitmap bitmap);

// Records `command` (state set) where Mesa executes it without flushing the bitmap cache:
// before the cached bitmaps when the cache is open (glAccum).
void record_before_bitmap_cache(Context& ctx, rec::Command command);

// Mesa flushes the cache (glFlush, texture uploads): later bitmaps start a new one.
void flush_bitmap_cache(Context& ctx);

}  // namespace glpt
