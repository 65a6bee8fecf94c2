// The GLX config chooser without an X server: attribute-list parsing (both list styles), GLX 1.4
// table 3.4's match criteria and 3.3.3's order as Mesa's glxcmds.c implements them, and the
// buffers a config gives a drawable. Expected values come from the spec's tables and Mesa's code
// (the end-to-end comparison with Mesa is glx.mesa_oracle).
// gtest before the X headers: Xlib's macros (None, Bool, Status) break gtest's templates.
// clang-format off
#include <gtest/gtest.h>
#include "gl_shim/glx/glx_configs.hpp"
// clang-format on

#include <algorithm>
#include <vector>

#include "gl/glx_enums.h"

namespace {

using glpt::glx::Config;

Config rgb(int alpha, int depth, int stencil, bool db, int id) {
  Config c;
  c.fbconfig_id = id;
  c.visual_id = 0x21;
  c.visual_type = GLX_TRUE_COLOR;
  c.red = c.green = c.blue = 8;
  c.alpha = alpha;
  c.buffer_size = alpha ? 32 : 24;
  c.depth = depth;
  c.stencil = stencil;
  c.double_buffer = db;
  c.drawable_type = GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT;
  c.render_type = GLX_RGBA_BIT;
  c.x_renderable = 1;
  return c;
}

std::vector<int> choose(const std::vector<Config>& configs, std::vector<int> list) {
  list.push_back(None);
  const Config wanted = glpt::glx::chooser_template(list.data(), true);
  std::vector<const Config*> chosen;
  for (const Config& c : configs)
    if (glpt::glx::compatible(wanted, c)) chosen.push_back(&c);
  std::stable_sort(chosen.begin(), chosen.end(),
                   [](const Config* a, const Config* b) { return glpt::glx::compare(*a, *b) < 0; });
  std::vector<int> ids;
  for (const Config* c : chosen) ids.push_back(c->fbconfig_id);
  return ids;
}

const std::vector<Config> kConfigs = {
    rgb(8, 24, 8, true, 1),  rgb(8, 24, 0, true, 2), rgb(0, 24, 8, true, 3),
    rgb(0, 16, 0, false, 4), rgb(0, 0, 0, true, 5),  rgb(8, 0, 0, false, 6),
};

TEST(GlxConfigs, FBConfigListsHaveDefaultsOfTable34) {
  // Defaults: any buffering, RGBA, windows; minimums 0. Order: alpha 0 first ("larger or zero"),
  // then smaller buffer size, single before double, depth 0 first then larger, stencil smaller.
  EXPECT_EQ(choose(kConfigs, {}), (std::vector<int>{4, 5, 3, 6, 2, 1}));
  EXPECT_EQ(choose(kConfigs, {GLX_DOUBLEBUFFER, True}), (std::vector<int>{5, 3, 2, 1}));
  EXPECT_EQ(choose(kConfigs, {GLX_ALPHA_SIZE, 1}), (std::vector<int>{6, 2, 1}));
  EXPECT_EQ(choose(kConfigs, {GLX_DEPTH_SIZE, 1, GLX_STENCIL_SIZE, 1}), (std::vector<int>{3, 1}));
  EXPECT_EQ(choose(kConfigs, {GLX_DEPTH_SIZE, 17}), (std::vector<int>{3, 2, 1}));
  // Exact-match attributes, GLX_DONT_CARE, masks, an unknown attribute (skipped, as Mesa).
  EXPECT_EQ(choose(kConfigs, {GLX_FBCONFIG_ID, 2}), (std::vector<int>{2}));
  EXPECT_EQ(choose(kConfigs, {GLX_DOUBLEBUFFER, static_cast<int>(GLX_DONT_CARE)}).size(), 6u);
  EXPECT_TRUE(choose(kConfigs, {GLX_RENDER_TYPE, GLX_COLOR_INDEX_BIT}).empty());
  EXPECT_TRUE(choose(kConfigs, {GLX_LEVEL, 1}).empty());
  EXPECT_TRUE(choose(kConfigs, {GLX_ACCUM_RED_SIZE, 1}).empty());
  EXPECT_EQ(choose(kConfigs, {0x7777, 5, GLX_STENCIL_SIZE, 8}), (std::vector<int>{3, 1}));
}

TEST(GlxConfigs, VisualListsUseBooleanTokensAndSingleBufferDefault) {
  const int single[] = {GLX_RGBA, GLX_DEPTH_SIZE, 16, None};
  const Config s = glpt::glx::chooser_template(single, false);
  EXPECT_EQ(s.double_buffer, 0);  // glXChooseVisual: single-buffered unless asked
  EXPECT_EQ(s.render_type, GLX_RGBA_BIT);
  EXPECT_EQ(s.depth, 16);
  EXPECT_TRUE(glpt::glx::compatible(s, kConfigs[3]));
  EXPECT_FALSE(glpt::glx::compatible(s, kConfigs[2]));  // double-buffered
  const int dbl[] = {GLX_USE_GL, GLX_RGBA, GLX_DOUBLEBUFFER, GLX_STENCIL_SIZE, 1, None};
  const Config d = glpt::glx::chooser_template(dbl, false);
  EXPECT_EQ(d.double_buffer, 1);
  EXPECT_EQ(d.stencil, 1);
  EXPECT_TRUE(glpt::glx::compatible(d, kConfigs[0]));
  // No GLX_RGBA: Mesa 25 leaves the render type open, so RGBA visuals still match.
  const int no_rgba[] = {GLX_DOUBLEBUFFER, None};
  EXPECT_TRUE(glpt::glx::compatible(glpt::glx::chooser_template(no_rgba, false), kConfigs[0]));
}

TEST(GlxConfigs, AttributesAreAnsweredAsMesa) {
  const Config& c = kConfigs[2];
  int v = -1;
  EXPECT_TRUE(glpt::glx::config_attribute(c, GLX_BUFFER_SIZE, &v));
  EXPECT_EQ(v, 24);
  EXPECT_TRUE(glpt::glx::config_attribute(c, GLX_RGBA, &v));
  EXPECT_EQ(v, 1);
  EXPECT_TRUE(glpt::glx::config_attribute(c, GLX_MAX_PBUFFER_WIDTH, &v));
  EXPECT_EQ(v, 4096);  // Mesa's own limit, whatever the server said
  EXPECT_TRUE(glpt::glx::config_attribute(c, GLX_TRANSPARENT_RED_VALUE, &v));
  EXPECT_EQ(v, -1);                                          // GLX_DONT_CARE
  EXPECT_FALSE(glpt::glx::config_attribute(c, 0x8028, &v));  // GLX_VISUAL_SELECT_GROUP_SGIX
  EXPECT_FALSE(glpt::glx::config_attribute(c, 0x7777, &v));
}

TEST(GlxConfigs, DrawablesHaveTheConfigsBuffers) {
  const glpt::rec::DrawableConfig none = glpt::glx::drawable_config(kConfigs[5]);
  EXPECT_FALSE(none.double_buffered);
  EXPECT_TRUE(none.has_alpha);
  EXPECT_EQ(none.depth_bits, 0u);
  EXPECT_EQ(none.stencil_bits, 0u);
  EXPECT_EQ(none.accum_bits, 0u);
  const glpt::rec::DrawableConfig full = glpt::glx::drawable_config(kConfigs[2]);
  EXPECT_TRUE(full.double_buffered);
  EXPECT_FALSE(full.has_alpha);
  EXPECT_EQ(full.depth_bits, 24u);
  EXPECT_EQ(full.stencil_bits, 8u);
}

}  // namespace
