#include "gl_shim/pixels/bitmap_cache.hpp"

#include <cmath>
#include <memory>
#include <utility>
#include <variant>

#include "gl_shim/context.hpp"

namespace glpt {
namespace {

// st_cb_bitmap.c: BITMAP_CACHE_WIDTH, BITMAP_CACHE_HEIGHT, Z_EPSILON.
constexpr int64_t kCacheWidth = 512;
constexpr int64_t kCacheHeight = 32;
constexpr float kZEpsilon = 1e-6f;
// Bitmaps further out than this from the origin are never cached (keeps the arithmetic exact).
constexpr float kMaxCachedPosition = 1 << 30;

BitmapFragmentKey key_of(const rec::StateSnapshot& s) {
  BitmapFragmentKey k;
  k.fog = s.raster->fog.enabled;
  k.fog_mode = k.fog ? s.raster->fog.mode : 0;
  k.color_sum = s.raster->ops.color_sum;
  k.lighting = s.lighting->enabled;
  k.separate_specular = k.lighting && s.lighting->separate_specular;
  for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
    const rec::TextureUnitState& unit = s.texturing->units[u];
    k.texture_target[u] = unit.target;
    if (unit.target == 0) continue;
    k.texture_env[u] = unit.env;
    k.texture_env[u].color = glm::vec4(0.0f);  // constants of the program, not its key
    k.texture_env[u].lod_bias = 0.0f;
  }
  k.scissor_test = s.raster->ops.scissor_test;
  k.draw_buffer = s.raster->ops.draw_buffer;
  return k;
}

bool cache_open(const Context& ctx) {
  return ctx.bitmap_cache.open && ctx.bitmap_cache.recorder_events == ctx.recorder.events();
}

rec::Bitmap& cached_bitmaps(Context& ctx) {
  return std::get<rec::Bitmap>(ctx.recorder.record().commands[ctx.bitmap_cache.command]);
}

// Mesa validated `state` while the cache was open: the cache's quad will be drawn with its
// fragment operations, but with the cache's own fragment program and scissor enable. Of those,
// glpt can put back the fog mode, colour sum and scissor enables; when texturing, lighting or
// the draw buffer differ, the cache keeps the state it had (an approximation: Mesa's mix of the
// two has no snapshot).
void revalidate(Context& ctx, rec::StateId state) {
  rec::FrameRecord& record = ctx.recorder.record();
  const BitmapCache& cache = ctx.bitmap_cache;
  rec::Bitmap& cached = cached_bitmaps(ctx);
  BitmapFragmentKey key = key_of(record.states[state]);
  if (key == cache.key) {
    cached.state = state;
    return;
  }
  key.fog = cache.key.fog;
  key.fog_mode = cache.key.fog_mode;
  key.color_sum = cache.key.color_sum;
  key.scissor_test = cache.key.scissor_test;
  if (!(key == cache.key)) return;
  rec::StateSnapshot mixed = record.states[state];
  auto raster = std::make_shared<rec::RasterState>(*mixed.raster);
  raster->fog.enabled = cache.key.fog;
  if (cache.key.fog) raster->fog.mode = cache.key.fog_mode;
  raster->ops.color_sum = cache.key.color_sum;
  raster->ops.scissor_test = cache.key.scissor_test;
  mixed.raster = std::move(raster);
  record.states.push_back(std::move(mixed));
  cached.state = static_cast<rec::StateId>(record.states.size() - 1);
}

// ORs `b` into the cache's bitmap, growing it to the union of both rectangles.
void merge(rec::Bitmap& into, const rec::Bitmap& b) {
  const int64_t x0 = std::min<int64_t>(int64_t(into.origin.x), int64_t(b.origin.x));
  const int64_t y0 = std::min<int64_t>(int64_t(into.origin.y), int64_t(b.origin.y));
  const int64_t x1 =
      std::max<int64_t>(int64_t(into.origin.x) + into.width, int64_t(b.origin.x) + b.width);
  const int64_t y1 =
      std::max<int64_t>(int64_t(into.origin.y) + into.height, int64_t(b.origin.y) + b.height);
  const auto width = static_cast<uint32_t>(x1 - x0);
  const auto height = static_cast<uint32_t>(y1 - y0);
  if (width != into.width || height != into.height) {
    std::vector<uint8_t> bits(size_t{width} * height, 0);
    const int64_t dx = int64_t(into.origin.x) - x0, dy = int64_t(into.origin.y) - y0;
    for (uint32_t r = 0; r < into.height; ++r)
      for (uint32_t c = 0; c < into.width; ++c)
        bits[size_t(dy + r) * width + size_t(dx + c)] = into.bits[size_t{r} * into.width + c];
    into.bits = std::move(bits);
    into.origin = glm::vec2(float(x0), float(y0));
    into.width = width;
    into.height = height;
  }
  const int64_t dx = int64_t(b.origin.x) - x0, dy = int64_t(b.origin.y) - y0;
  for (uint32_t r = 0; r < b.height; ++r)
    for (uint32_t c = 0; c < b.width; ++c)
      into.bits[size_t(dy + r) * width + size_t(dx + c)] |= b.bits[size_t{r} * b.width + c];
  into.calls += b.calls;
}

}  // namespace

void record_bitmap(Context& ctx, rec::Bitmap b) {
  b.state = ctx.snapshots.capture(ctx, ctx.recorder.record());
  BitmapCache& cache = ctx.bitmap_cache;
  const bool open = cache_open(ctx);
  const bool cacheable = b.width <= kCacheWidth && b.height <= kCacheHeight &&
                         std::abs(b.origin.x) < kMaxCachedPosition &&
                         std::abs(b.origin.y) < kMaxCachedPosition;
  if (!cacheable) {
    // Drawn at once, validated: the cached bitmaps come later, with this state.
    const rec::StateId state = b.state;
    record_before_bitmap_cache(ctx, std::move(b));
    if (open) revalidate(ctx, state);
    return;
  }
  const auto x = static_cast<int64_t>(b.origin.x), y = static_cast<int64_t>(b.origin.y);
  const BitmapFragmentKey key = key_of(ctx.recorder.record().states[b.state]);
  if (open) {
    const int64_t px = x - cache.x, py = y - cache.y;
    const bool joins = px >= 0 && px + b.width <= kCacheWidth && py >= 0 &&
                       py + b.height <= kCacheHeight && b.raster.color == cache.color &&
                       key == cache.key && std::fabs(b.raster.window.z - cache.z) <= kZEpsilon;
    if (joins) {
      rec::Bitmap& cached = cached_bitmaps(ctx);
      merge(cached, b);
      cached.state = b.state;
      cached.raster.tex_coord = b.raster.tex_coord;  // Mesa's constants at the flush
      return;
    }
    revalidate(ctx, b.state);  // Mesa flushes the cache after validating this call's state
    cached_bitmaps(ctx).raster.tex_coord = b.raster.tex_coord;
  }
  cache.open = true;
  cache.x = x;
  cache.y = y - (kCacheHeight - int64_t{b.height}) / 2;
  cache.z = b.raster.window.z;
  cache.color = b.raster.color;
  cache.key = key;
  ctx.recorder.add(std::move(b));
  cache.command = ctx.recorder.record().commands.size() - 1;
  cache.recorder_events = ctx.recorder.events();
}

void record_before_bitmap_cache(Context& ctx, rec::Command command) {
  if (!cache_open(ctx)) return ctx.recorder.add(std::move(command));
  auto& commands = ctx.recorder.record().commands;
  commands.insert(commands.begin() + static_cast<std::ptrdiff_t>(ctx.bitmap_cache.command),
                  std::move(command));
  ++ctx.bitmap_cache.command;
}

void flush_bitmap_cache(Context& ctx) { ctx.bitmap_cache.open = false; }

}  // namespace glpt
