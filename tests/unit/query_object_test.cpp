// Occlusion query objects in the front end (GL 1.5 4.1.6, 6.1.12): names, errors and state as
// Mesa reports them (the scenes of mesa_reference/query_scenes.inc that draw nothing, compared
// with what OSMesa logged), contexts of a share group, bad input, the ARB names, and what the
// queries put in the frame record. Sample counts are occlusion_query_render_test.cpp's subject.
#include <cstring>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "gl_shim/frame/headless_target.hpp"
#include "gl_test_context.hpp"

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

const ExpectedLog& expected_log(const std::string& scene) {
  for (const ExpectedLog& e : kExpected)
    if (scene == e.scene) return e;
  ADD_FAILURE() << "no expected log for " << scene;
  static const ExpectedLog none{"", 0, {}};
  return none;
}

using QueryObjectTest = GlTest;

// Without a drawable nothing counts samples: results are 0 as soon as they are asked for, which
// is what the scenes that draw nothing get from Mesa too.
TEST_F(QueryObjectTest, ScenesWithoutDrawingLogWhatMesaLogs) {
  for (const QueryScene& scene : kQueryScenes) {
    if (scene.draws) continue;
    SCOPED_TRACE(scene.name);
    glpt::Context context(nullptr);
    glpt::set_current_context(&context);
    QueryLog log{};
    scene.run(&log);
    const ExpectedLog& expected = expected_log(scene.name);
    ASSERT_EQ(log.count, expected.count);
    EXPECT_EQ(std::vector<long long>(log.values, log.values + log.count), expected.values);
  }
  glpt::set_current_context(&ctx_);
}

TEST_F(QueryObjectTest, QueryObjectsBelongToTheirContextNotTheShareGroup) {
  // What OSMesa does (mesa_query_expected.inc's last line): the other context neither sees the
  // query nor avoids its name.
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glEndQuery(GL_SAMPLES_PASSED);
  ASSERT_EQ(glIsQuery(q), GLboolean{1});
  glpt::Context sharing(&ctx_);
  glpt::set_current_context(&sharing);
  EXPECT_EQ(glIsQuery(q), GLboolean{0});
  GLint value = -7;
  glGetQueryObjectiv(q, GL_QUERY_RESULT, &value);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(value, -7);
  GLuint other = 0;
  glGenQueries(1, &other);
  EXPECT_EQ(other, q);
  // A query active in one context is not active in the other.
  glBeginQuery(GL_SAMPLES_PASSED, other);
  glpt::set_current_context(&ctx_);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &value);
  EXPECT_EQ(value, 0);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glEndQuery(GL_SAMPLES_PASSED);
  glpt::set_current_context(&sharing);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &value);
  EXPECT_EQ(value, GLint(other));
  glpt::set_current_context(&ctx_);
}

TEST_F(QueryObjectTest, ArbNamesAreTheSameCommands) {
  GLuint q[2] = {};
  glGenQueriesARB(2, q);
  EXPECT_EQ(q[0], 1u);
  EXPECT_EQ(q[1], 2u);
  glBeginQueryARB(GL_SAMPLES_PASSED_ARB, q[1]);
  EXPECT_EQ(glIsQueryARB(q[1]), GLboolean{1});
  GLint value = 0;
  glGetQueryivARB(GL_SAMPLES_PASSED_ARB, GL_CURRENT_QUERY_ARB, &value);
  EXPECT_EQ(value, 2);
  glGetQueryivARB(GL_SAMPLES_PASSED_ARB, GL_QUERY_COUNTER_BITS_ARB, &value);
  EXPECT_EQ(value, 64);
  glEndQueryARB(GL_SAMPLES_PASSED_ARB);
  GLuint result = 7;
  glGetQueryObjectuivARB(q[1], GL_QUERY_RESULT_ARB, &result);
  EXPECT_EQ(result, 0u);  // nothing drawn (and no drawable)
  glGetQueryObjectivARB(q[1], GL_QUERY_RESULT_AVAILABLE_ARB, &value);
  EXPECT_EQ(value, 1);
  glDeleteQueriesARB(2, q);
  EXPECT_EQ(glIsQueryARB(q[1]), GLboolean{0});
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(QueryObjectTest, NotAllowedBetweenBeginAndEnd) {
  GLuint q = 0;
  glGenQueries(1, &q);
  glBegin(GL_TRIANGLES);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glBegin(GL_TRIANGLES);
  EXPECT_EQ(glIsQuery(q), GLboolean{0});
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  GLint value = 0;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &value);
  EXPECT_EQ(value, 0);
}

TEST_F(QueryObjectTest, BadInputIsAnErrorOrNothing) {
  glGenQueries(4, nullptr);
  glDeleteQueries(4, nullptr);
  glDeleteQueries(1 << 30, nullptr);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glGenQueries(-5, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glEndQuery(GL_SAMPLES_PASSED);
  glGetQueryObjectiv(q, GL_QUERY_RESULT, nullptr);
  glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // GL 1.5 names only GL_QUERY_RESULT and GL_QUERY_RESULT_AVAILABLE (Mesa also answers the
  // GL 4.x GL_QUERY_TARGET and GL_QUERY_RESULT_NO_WAIT).
  GLint value = -7;
  glGetQueryObjectiv(q, 0x82EA, &value);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetQueryObjectiv(q, 0x9194, &value);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(value, -7);
  // Targets of later versions and extensions glpt does not have.
  glBeginQuery(0x8C2F /* GL_ANY_SAMPLES_PASSED */, q);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetQueryiv(0x88BF /* GL_TIME_ELAPSED */, GL_QUERY_COUNTER_BITS, &value);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
}

TEST_F(QueryObjectTest, NamesNearTheLargestGoBackToTheFirstFreeRun) {
  // Mesa's _mesa_HashFindFreeKeyBlock: after the largest name used, unless that passes
  // 2^32 - 2; then the first run of free names from 1.
  GLuint q[3] = {};
  glGenQueries(2, q);  // 1, 2
  glBeginQuery(GL_SAMPLES_PASSED, 0xFFFFFFFDu);
  glEndQuery(GL_SAMPLES_PASSED);
  glGenQueries(1, q);
  EXPECT_EQ(q[0], 0xFFFFFFFEu);
  glGenQueries(2, q);
  EXPECT_EQ(q[0], 3u);
  EXPECT_EQ(q[1], 4u);
  glDeleteQueries(1, q);  // 3 is free again
  glGenQueries(1, q + 2);
  EXPECT_EQ(q[2], 3u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glBeginQuery(GL_SAMPLES_PASSED, 0xFFFFFFFFu);  // any non-zero name
  EXPECT_EQ(glIsQuery(0xFFFFFFFFu), GLboolean{1});
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(QueryObjectTest, ResultsSaturateToTheTypeAsked) {
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glEndQuery(GL_SAMPLES_PASSED);
  // The renderer reports more samples than 32 bits hold (a long query), in two records.
  const uint64_t id = ctx_.queries.objects.at(q).id;
  glpt::count_query_samples(ctx_.queries, {{id, 3'000'000'000ull}, {id + 1, 5}});
  glpt::count_query_samples(ctx_.queries, {{id, 2'000'000'000ull}});  // known: ignored
  GLint signed_result = 0;
  GLuint unsigned_result = 0;
  glGetQueryObjectiv(q, GL_QUERY_RESULT, &signed_result);
  glGetQueryObjectuiv(q, GL_QUERY_RESULT, &unsigned_result);
  EXPECT_EQ(signed_result, 0x7FFFFFFF);
  EXPECT_EQ(unsigned_result, 3'000'000'000u);
  glpt::count_query_samples(ctx_.queries, {});
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

// ---- what the frame record gets (a drawable, raster mode) ---------------------------------

class QueryRecordTest : public HeadlessGlTest {
 protected:
  QueryRecordTest() : HeadlessGlTest(8, 8) {}
  template <typename T>
  std::vector<size_t> positions() const {
    std::vector<size_t> at;
    const auto& commands = ctx_.recorder.record().commands;
    for (size_t i = 0; i < commands.size(); ++i)
      if (std::holds_alternative<T>(commands[i])) at.push_back(i);
    return at;
  }
  void triangle() {
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(-1, 1);
    glEnd();
  }
  glpt_test::RasterMode raster_mode_;
};

TEST_F(QueryRecordTest, BeginAndEndAreRecordedInOrderAndEndBatches) {
  GLuint q = 0;
  glGenQueries(1, &q);
  triangle();
  glBeginQuery(GL_SAMPLES_PASSED, q);
  triangle();  // same state and mode: batched with the first one if nothing came between
  glEndQuery(GL_SAMPLES_PASSED);
  triangle();
  ctx_.recorder.seal();
  const auto& commands = ctx_.recorder.record().commands;
  ASSERT_EQ(commands.size(), 5u);
  EXPECT_EQ(positions<glpt::rec::Draw>(), (std::vector<size_t>{0, 2, 4}));
  ASSERT_EQ(positions<glpt::rec::BeginQuery>(), std::vector<size_t>{1});
  ASSERT_EQ(positions<glpt::rec::EndQuery>(), std::vector<size_t>{3});
  const uint64_t id = std::get<glpt::rec::BeginQuery>(commands[1]).id;
  EXPECT_NE(id, 0u);
  EXPECT_EQ(std::get<glpt::rec::EndQuery>(commands[3]).id, id);
  // Each glBeginQuery has an id of its own, also for the same query object.
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_NE(std::get<glpt::rec::BeginQuery>(ctx_.recorder.record().commands[5]).id, id);
  EXPECT_EQ(ctx_.recorder.record().query_at_start, 0u);
}

TEST_F(QueryRecordTest, DeletingTheActiveQueryEndsIt) {
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glDeleteQueries(1, &q);
  ASSERT_EQ(positions<glpt::rec::EndQuery>(), std::vector<size_t>{1});
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

TEST_F(QueryRecordTest, ARecordStartedDuringAQueryNamesIt) {
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  const uint64_t id = std::get<glpt::rec::BeginQuery>(ctx_.recorder.record().commands[0]).id;
  GLubyte pixel[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);  // executes the record
  EXPECT_TRUE(ctx_.recorder.record().commands.empty());
  EXPECT_EQ(ctx_.recorder.record().query_at_start, id);
  glEndQuery(GL_SAMPLES_PASSED);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  EXPECT_EQ(ctx_.recorder.record().query_at_start, 0u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(QueryRecordTest, CachedBitmapsAreDrawnBeforeTheQueryBegins) {
  // Mesa flushes its bitmap cache at glBeginQuery and glEndQuery (queryobj.c): the cached
  // bitmap stays before the BeginQuery, and a bitmap after it is a new command.
  const GLubyte bits[8] = {0xFF, 0, 0, 0, 0xFF, 0, 0, 0};
  GLuint q = 0;
  glGenQueries(1, &q);
  glRasterPos2f(0, 0);
  glBitmap(8, 2, 0, 0, 1, 0, bits);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glBitmap(8, 2, 0, 0, 1, 0, bits);
  glEndQuery(GL_SAMPLES_PASSED);
  glBitmap(8, 2, 0, 0, 1, 0, bits);
  EXPECT_EQ(positions<glpt::rec::Bitmap>(), (std::vector<size_t>{0, 2, 4}));
  EXPECT_EQ(positions<glpt::rec::BeginQuery>(), std::vector<size_t>{1});
  EXPECT_EQ(positions<glpt::rec::EndQuery>(), std::vector<size_t>{3});
}

TEST_F(QueryRecordTest, AvailabilityIsFalseOnceThenTheRecordIsExecuted) {
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glRectf(-1, -1, 0, 0);  // the lower left 4 x 4 pixels of the 8 x 8 window
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint available = 7;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &available);
  EXPECT_EQ(available, 0u);
  EXPECT_FALSE(ctx_.recorder.record().commands.empty());  // nothing executed yet
  glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &available);
  EXPECT_EQ(available, 1u);
  EXPECT_TRUE(ctx_.recorder.record().commands.empty());
  GLuint samples = 0;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT, &samples);
  EXPECT_EQ(samples, 16u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(QueryRecordTest, TheEndOfAFrameMakesResultsAvailable) {
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glRectf(-1, -1, 1, 0);
  glEndQuery(GL_SAMPLES_PASSED);
  glpt::end_frame(ctx_, true);
  GLuint available = 7;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &available);
  EXPECT_EQ(available, 1u);
  GLuint samples = 0;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT, &samples);
  EXPECT_EQ(samples, 32u);
}

}  // namespace
