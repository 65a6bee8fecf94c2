// Occlusion query results through the whole of glpt: the scenes of
// mesa_reference/query_scenes.inc (visible, occluded and partly visible quads, fragment tests,
// clears, reads and frame ends inside queries, points, lines, unfilled polygons, pixel
// rectangles) drawn on a headless drawable, in raster mode and in path-traced mode, must log
// exactly the sample counts, availability and errors real Mesa logged (mesa_query_expected.inc).
// Path-traced mode counts its traced draws where the G-buffer pass rasterizes them: the counts
// are raster mode's (every record here is the first of its accumulation, so nothing is
// jittered), except where path-traced mode draws in another order than GL (kPathOrder).
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/gl_entry_decls.h"

namespace {

#include "mesa_reference/query_scenes.inc"

struct ExpectedLog {
  const char* scene;
  int count;
  std::vector<long long> values;
};

const ExpectedLog kExpected[] = {
#include "mesa_reference/mesa_query_expected.inc"
};

// Path-traced mode draws the traced draws of a record (filled triangles under the main camera,
// unblended, all colour channels written) in its G-buffer pass and the other draws after its
// trace pass (docs/architecture.md): a draw that is not traced and comes before a traced one is
// drawn after it, and the depth and stencil tests see that order. In fragment_tests:
struct PathOrderCount {
  const char* scene;
  int index;  // into the log
  long long samples;
};
const PathOrderCount kPathOrder[] = {
    // q[1], the colour-masked (untraced) quad where stencil is 1, meets the depth 0.05 the
    // traced scissored quad drawn after it in GL wrote into 4 x 2 of its pixels: 1024 - 8.
    {"fragment_tests", 3, 1016},
    // q[7], the traced depth-GL_GREATER quad, does not yet see the depth 0.02 of the blended
    // (untraced) 10 x 10 quad GL drew before it: 2272 - 100.
    {"fragment_tests", 21, 2172},
};

// Runs `scene` on a fresh context drawing to a 64x64 single-buffered drawable with 24 depth
// and 8 stencil bits (OSMesa's), in GLPT_MODE `mode`.
QueryLog run_scene(const char* mode, const QueryScene& scene) {
  ::setenv("GLPT_MODE", mode, 1);  // read when the context creates its renderer
  glpt::rec::DrawableConfig config;
  config.double_buffered = false;
  config.accum_bits = 0;
  auto target = std::make_unique<glpt::HeadlessTarget>(64, 64, config);
  auto context = std::make_unique<glpt::Context>(nullptr);
  glpt::make_current_headless(*context, *target);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  QueryLog log{};
  scene.run(&log);
  glpt::set_current_context(nullptr);
  context.reset();
  ::unsetenv("GLPT_MODE");
  return log;
}

class OcclusionQueryRender : public ::testing::TestWithParam<const char*> {};

TEST_P(OcclusionQueryRender, ScenesCountWhatMesaCounts) {
  for (const QueryScene& scene : kQueryScenes) {
    SCOPED_TRACE(scene.name);
    const ExpectedLog* expected = nullptr;
    for (const ExpectedLog& e : kExpected)
      if (std::string(e.scene) == scene.name) expected = &e;
    ASSERT_NE(expected, nullptr);
    std::vector<long long> values = expected->values;
    if (std::string(GetParam()) == "path")
      for (const PathOrderCount& p : kPathOrder)
        if (std::string(p.scene) == scene.name) values.at(size_t(p.index)) = p.samples;
    const QueryLog log = run_scene(GetParam(), scene);
    ASSERT_EQ(log.count, expected->count);
    EXPECT_EQ(std::vector<long long>(log.values, log.values + log.count), values);
  }
}

// Polling needs no drawing to end: the first poll of an unknown result answers false (as
// llvmpipe's does while its rasterizer runs), the next one executes the frame record.
TEST_P(OcclusionQueryRender, PollingEndsWithoutDrawingMore) {
  const QueryScene scene = {"polling",
                            [](QueryLog* log) {
                              GLuint q = 0;
                              GLuint value = 0;
                              glGenQueries(1, &q);
                              window_projection();
                              glBeginQuery(GL_SAMPLES_PASSED, q);
                              quad(0, 0, 7, 9, 0.5f);
                              glEndQuery(GL_SAMPLES_PASSED);
                              for (int poll = 0; poll < 3; ++poll) {
                                glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &value);
                                qlog(log, value);
                              }
                              glGetQueryObjectuiv(q, GL_QUERY_RESULT, &value);
                              qlog(log, value);
                            },
                            1};
  const QueryLog log = run_scene(GetParam(), scene);
  EXPECT_EQ(std::vector<long long>(log.values, log.values + log.count),
            (std::vector<long long>{0, 1, 1, 63}));
}

INSTANTIATE_TEST_SUITE_P(Modes, OcclusionQueryRender, ::testing::Values("raster", "path"),
                         [](const auto& info) { return std::string(info.param); });

}  // namespace
