// Evaluators (GL 1.5 5.1): the vertices glEvalCoord/glEvalPoint/glEvalMesh put into the frame
// record, compared bit for bit with what real Mesa makes of the same command sequences
// (mesa_reference/evaluator_sequences.inc, printed by OSMesa through feedback:
// mesa_reference/mesa_evaluator_probe.c), the errors and state queries, glGetMap, display lists,
// the attribute stack, and bad input.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "array_test_util.hpp"
#include "gl_shim/context.hpp"
#include "rt_core/record/decompose.hpp"

namespace {

#include "mesa_reference/evaluator_sequences.inc"

struct ExpectedVertex {
  int kind;  // 0 point, 1 line, 2 triangle
  float position[4], color[4], tex_coord[4], normal[3];
};

struct Expected {
  const char* name;
  std::vector<GLenum> errors;
  std::vector<float> floats;
  std::vector<GLint> ints;
  std::vector<ExpectedVertex> vertices;
};

const Expected kExpected[] = {
#include "mesa_reference/mesa_evaluator_expected.inc"
};

static_assert(std::size(kExpected) == std::size(kEvalSequences));

// The vertices of the frame record, primitive by primitive, in the form feedback gives them.
std::vector<ExpectedVertex> recorded_vertices(glpt::Context& ctx) {
  std::vector<ExpectedVertex> out;
  for (const glpt::rec::Draw& draw : recorded_draws(ctx)) {
    const glpt::rec::VertexData& d = *draw.vertices;
    glpt::rec::Decomposed parts;
    glpt::rec::decompose(d, parts);
    auto add = [&](int kind, uint32_t v) {
      ExpectedVertex e{};
      e.kind = kind;
      const glm::vec4 p = d.position.at(v);
      const glm::vec4 c = at(d.color, v);
      const glm::vec4 t = d.tex_coord[0].empty() ? glm::vec4(-99) : at(d.tex_coord[0], v);
      const glm::vec3 n = at(d.normal, v);
      for (int k = 0; k < 4; ++k) {
        e.position[k] = p[k];
        e.color[k] = c[k];
        e.tex_coord[k] = t[k];
      }
      for (int k = 0; k < 3; ++k) e.normal[k] = n[k];
      out.push_back(e);
    };
    for (uint32_t v : parts.points) add(0, v);
    for (const auto& l : parts.lines)
      for (uint32_t v : l.v) add(1, v);
    for (const auto& t : parts.triangles)
      for (uint32_t v : t.v) add(2, v);
  }
  return out;
}

// Exact equality, except that feedback cannot tell -0 from +0 (its texgen adds zeros).
void expect_same(const float* got, const float* want, int n, const std::string& what) {
  for (int k = 0; k < n; ++k)
    EXPECT_EQ(got[k], want[k]) << what << "[" << k << "] " << std::hexfloat << got[k] << ", Mesa "
                               << want[k];
}

class MesaEvaluatorTest : public GlTest, public ::testing::WithParamInterface<size_t> {};

TEST_P(MesaEvaluatorTest, VerticesErrorsAndStateAreMesas) {
  const size_t s = GetParam();
  const Expected& want = kExpected[s];
  ASSERT_STREQ(want.name, kEvalSequences[s].name);
  evaluator_probe_setup();
  NotedEvalErrors errors{};
  kEvalSequences[s].run(&errors);
  ASSERT_EQ(size_t(errors.count), want.errors.size());
  for (int i = 0; i < errors.count; ++i)
    EXPECT_EQ(errors.errors[i], want.errors[size_t(i)]) << "error after step " << i;

  GLfloat floats[EVAL_STATE_VALUES];
  GLint ints[EVAL_STATE_VALUES];
  read_eval_state(floats, ints);
  ASSERT_EQ(want.floats.size(), size_t(EVAL_STATE_VALUES));
  for (int i = 0; i < EVAL_STATE_VALUES; ++i) {
    EXPECT_EQ(std::memcmp(&floats[i], &want.floats[size_t(i)], sizeof(float)), 0)
        << "state value " << i << ": " << floats[i] << ", Mesa " << want.floats[size_t(i)];
    EXPECT_EQ(ints[i], want.ints[size_t(i)]) << "state value " << i << " as integer";
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  const std::vector<ExpectedVertex> got = recorded_vertices(ctx_);
  ASSERT_EQ(got.size(), want.vertices.size());
  for (size_t v = 0; v < got.size(); ++v) {
    const ExpectedVertex& g = got[v];
    const ExpectedVertex& w = want.vertices[v];
    const std::string at = "vertex " + std::to_string(v) + " ";
    ASSERT_EQ(g.kind, w.kind) << at;
    expect_same(g.position, w.position, 4, at + "position");
    expect_same(g.color, w.color, 4, at + "colour");
    expect_same(g.tex_coord, w.tex_coord, 4, at + "texture coordinates");
    expect_same(g.normal, w.normal, 3, at + "normal");
  }
}

INSTANTIATE_TEST_SUITE_P(Sequences, MesaEvaluatorTest,
                         ::testing::Range(size_t{0}, std::size(kEvalSequences)),
                         [](const ::testing::TestParamInfo<size_t>& info) {
                           return std::string(kEvalSequences[info.param].name);
                         });

// ---- hand-derived cases ------------------------------------------------------------------------

class EvaluatorTest : public GlTest {
 protected:
  // A linear 1-D vertex map from (1, 2, 3) to (5, 6, 7) over u in [0, 2]: exact values.
  void linear_curve() {
    const GLfloat p[6] = {1, 2, 3, 5, 6, 7};
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 2.0f, 3, 2, p);
    glEnable(GL_MAP1_VERTEX_3);
  }
  std::vector<glm::vec4> positions() {
    std::vector<glm::vec4> out;
    for (const auto& d : recorded_draws(ctx_))
      out.insert(out.end(), d.vertices->position.begin(), d.vertices->position.end());
    return out;
  }
};

TEST_F(EvaluatorTest, EvalCoordIsAVertexOfTheEvaluatedMap) {
  linear_curve();
  glBegin(GL_LINES);
  glEvalCoord1f(1.0f);
  glEvalCoord1d(2.0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const auto p = positions();
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0], glm::vec4(3, 4, 5, 1));
  EXPECT_EQ(p[1], glm::vec4(5, 6, 7, 1));
}

TEST_F(EvaluatorTest, NothingWithoutAnEnabledVertexMapOrOutsideBeginEnd) {
  linear_curve();
  glEvalCoord1f(1.0f);  // outside glBegin/glEnd: no vertex, no error
  glDisable(GL_MAP1_VERTEX_3);
  glBegin(GL_POINTS);
  glEvalCoord1f(1.0f);
  glEvalPoint1(0);
  glEnd();
  glEvalMesh1(GL_POINT, 0, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_TRUE(positions().empty());
}

// GL 1.5 5.1: the evaluated colour, normal and texture coordinates belong to the evaluated
// vertex; the current values stay, and apply to the next plain vertex.
TEST_F(EvaluatorTest, CurrentAttributesAreNotChanged) {
  linear_curve();
  const GLfloat c[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  const GLfloat n[6] = {1, 0, 0, 0, 1, 0};
  const GLfloat t[4] = {0, 0, 1, 1};
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 2.0f, 4, 2, c);
  glMap1f(GL_MAP1_NORMAL, 0.0f, 2.0f, 3, 2, n);
  glMap1f(GL_MAP1_TEXTURE_COORD_2, 0.0f, 2.0f, 2, 2, t);
  glEnable(GL_MAP1_COLOR_4);
  glEnable(GL_MAP1_NORMAL);
  glEnable(GL_MAP1_TEXTURE_COORD_2);
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  glNormal3f(0, 0, -1);
  glTexCoord2f(3, 4);
  glBegin(GL_POINTS);
  glEvalCoord1f(1.0f);
  glVertex3f(9, 9, 9);
  glEnd();
  GLfloat v[4];
  glGetFloatv(GL_CURRENT_COLOR, v);
  EXPECT_EQ(glm::vec4(v[0], v[1], v[2], v[3]), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  glGetFloatv(GL_CURRENT_NORMAL, v);
  EXPECT_EQ(glm::vec3(v[0], v[1], v[2]), glm::vec3(0, 0, -1));
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, v);
  EXPECT_EQ(glm::vec4(v[0], v[1], v[2], v[3]), glm::vec4(3, 4, 0, 1));
  const auto draws = recorded_draws(ctx_);
  ASSERT_EQ(draws.size(), 1u);
  const glpt::rec::VertexData& d = *draws[0].vertices;
  ASSERT_EQ(d.vertex_count(), 2u);
  EXPECT_EQ(at(d.color, 0), glm::vec4(0.5f));
  EXPECT_EQ(at(d.normal, 0), glm::vec3(0.5f, 0.5f, 0));
  EXPECT_EQ(at(d.color, 1), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  EXPECT_EQ(at(d.normal, 1), glm::vec3(0, 0, -1));
  // An evaluated colour is a colour given per vertex (it decides Mesa's flat-shaded quads).
  EXPECT_EQ(d.per_vertex & glpt::rec::kPerVertexColor, glpt::rec::kPerVertexColor);
}

TEST_F(EvaluatorTest, GetMapReadsThePackedControlPoints) {
  // Stride 5 for 3 components; doubles converted to floats.
  const GLdouble p[10] = {1.5, 2.5, 3.5, -1, -1, 0.1, 0.2, 0.3, -1, -1};
  glMap1d(GL_MAP1_VERTEX_3, 0.5, 4.25, 5, 2, p);
  GLfloat f[8] = {};
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, f);
  const GLfloat want[6] = {1.5f, 2.5f, 3.5f, 0.1f, 0.2f, 0.3f};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(f[i], want[i]) << i;
  GLdouble d[8] = {};
  glGetMapdv(GL_MAP1_VERTEX_3, GL_COEFF, d);
  EXPECT_EQ(d[3], double(0.1f));
  glGetMapdv(GL_MAP1_VERTEX_3, GL_DOMAIN, d);
  EXPECT_EQ(d[0], 0.5);
  EXPECT_EQ(d[1], 4.25);
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 2);

  // A 2 x 3 map given with v along the first index: read back u-major.
  GLfloat q[2 * 3];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 2; ++i) q[j * 2 + i] = float(10 * i + j);
  glMap2f(GL_MAP2_TEXTURE_COORD_1, 0, 1, 1, 2, 0, 1, 2, 3, q);
  glGetMapfv(GL_MAP2_TEXTURE_COORD_1, GL_COEFF, f);
  const GLfloat want2[6] = {0, 1, 2, 10, 11, 12};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(f[i], want2[i]) << i;
  GLint orders[2] = {};
  glGetMapiv(GL_MAP2_TEXTURE_COORD_1, GL_ORDER, orders);
  EXPECT_EQ(orders[0], 2);
  EXPECT_EQ(orders[1], 3);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// glGetMapiv converts as Mesa does (lroundf, then the long narrowed to GLint; measured with
// OSMesa): halves away from zero, out-of-range values wrap or read 0.
TEST_F(EvaluatorTest, GetMapivRoundsAsMesa) {
  const GLfloat p[8] = {2.5f,        -2.5f, 1e10f, std::numeric_limits<float>::quiet_NaN(),
                        0.49999997f, 3e9f,  -0.5f, std::numeric_limits<float>::infinity()};
  glMap1f(GL_MAP1_TEXTURE_COORD_1, -1.5f, 2.5f, 1, 8, p);
  GLint v[8];
  glGetMapiv(GL_MAP1_TEXTURE_COORD_1, GL_COEFF, v);
  const GLint want[8] = {3, -3, 1410065408, 0, 0, -1294967296, -1, 0};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(v[i], want[i]) << i;
  glGetMapiv(GL_MAP1_TEXTURE_COORD_1, GL_DOMAIN, v);
  EXPECT_EQ(v[0], -2);
  EXPECT_EQ(v[1], 3);
}

TEST_F(EvaluatorTest, InitialMapsAndGrid) {
  GLfloat f[4] = {-1, -1, -1, -1};
  glGetMapfv(GL_MAP2_NORMAL, GL_COEFF, f);
  EXPECT_EQ(glm::vec4(f[0], f[1], f[2], f[3]), glm::vec4(0, 0, 1, -1));
  glGetMapfv(GL_MAP1_COLOR_4, GL_COEFF, f);
  EXPECT_EQ(glm::vec4(f[0], f[1], f[2], f[3]), glm::vec4(1));
  glGetFloatv(GL_MAP2_GRID_DOMAIN, f);
  EXPECT_EQ(glm::vec4(f[0], f[1], f[2], f[3]), glm::vec4(0, 1, 0, 1));
  GLint n[2];
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, n);
  EXPECT_EQ(n[0], 1);
  EXPECT_EQ(n[1], 1);
  glGetIntegerv(GL_MAX_EVAL_ORDER, n);
  EXPECT_EQ(n[0], 30);
}

// The push saves the grid with its step: glEvalMesh1 on the initial grid (step 0, Mesa's) puts
// every point at u1 again after the pop.
TEST_F(EvaluatorTest, EvalBitSavesTheGrids) {
  linear_curve();
  glPushAttrib(GL_EVAL_BIT);
  glMapGrid1f(4, 0.0f, 2.0f);
  glMapGrid2f(3, 1.0f, 2.0f, 5, 3.0f, 4.0f);
  glEnable(GL_AUTO_NORMAL);
  glDisable(GL_MAP1_VERTEX_3);
  glPopAttrib();
  GLfloat f[4];
  glGetFloatv(GL_MAP1_GRID_DOMAIN, f);
  EXPECT_EQ(f[0], 0.0f);
  EXPECT_EQ(f[1], 1.0f);
  glGetFloatv(GL_MAP2_GRID_DOMAIN, f);
  EXPECT_EQ(glm::vec4(f[0], f[1], f[2], f[3]), glm::vec4(0, 1, 0, 1));
  EXPECT_FALSE(glIsEnabled(GL_AUTO_NORMAL));
  EXPECT_TRUE(glIsEnabled(GL_MAP1_VERTEX_3));
  glEvalMesh1(GL_POINT, 0, 2);
  const auto p = positions();
  ASSERT_EQ(p.size(), 3u);
  for (const auto& v : p) EXPECT_EQ(v, glm::vec4(1, 2, 3, 1));
}

TEST_F(EvaluatorTest, MeshesOfEveryShape) {
  const GLfloat p[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0};  // bilinear, u along x
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, p);
  glEnable(GL_MAP2_VERTEX_3);
  glMapGrid2f(2, 0, 1, 2, 0, 1);
  glEvalMesh2(GL_FILL, 0, 2, 0, 2);
  auto draws = recorded_draws(ctx_);
  ASSERT_EQ(draws.size(), 1u);
  const glpt::rec::VertexData& fill = *draws[0].vertices;
  EXPECT_EQ(fill.mode, GLenum(GL_TRIANGLE_STRIP));
  ASSERT_EQ(fill.primitives.size(), 2u);  // one strip per row
  EXPECT_EQ(fill.primitives[0].count, 6u);
  // (u, v), (u, v + dv), ...
  EXPECT_EQ(fill.position[0], glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(fill.position[1], glm::vec4(0, 0.5f, 0, 1));
  EXPECT_EQ(fill.position[2], glm::vec4(0.5f, 0, 0, 1));
  EXPECT_EQ(fill.source, glpt::rec::PrimitiveSource::kImmediate);

  ctx_.recorder.record().commands.clear();
  glEvalMesh2(GL_LINE, 0, 2, 1, 2);  // 2 rows of 3, then 3 columns of 2
  draws = recorded_draws(ctx_);
  ASSERT_EQ(draws.size(), 1u);
  const glpt::rec::VertexData& lines = *draws[0].vertices;
  EXPECT_EQ(lines.mode, GLenum(GL_LINE_STRIP));
  ASSERT_EQ(lines.primitives.size(), 5u);
  EXPECT_EQ(lines.primitives[0].count, 3u);
  EXPECT_EQ(lines.primitives[4].count, 2u);
  EXPECT_EQ(lines.position[3], glm::vec4(0, 1, 0, 1));  // the second row
  EXPECT_EQ(lines.position[7], glm::vec4(0, 1, 0, 1));  // the first column's end

  ctx_.recorder.record().commands.clear();
  glEvalMesh2(GL_FILL, 0, 2, 1, 1);   // a single row of points has no strip
  glEvalMesh2(GL_POINT, 2, 1, 0, 2);  // reversed range: nothing
  EXPECT_TRUE(recorded_draws(ctx_).empty());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(EvaluatorTest, HugeMeshesAreOutOfMemoryQuickly) {
  linear_curve();
  glEvalMesh1(GL_LINE, std::numeric_limits<GLint>::min(), std::numeric_limits<GLint>::max());
  EXPECT_EQ(glGetError(), GLenum(GL_OUT_OF_MEMORY));
  const GLfloat p[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, p);
  glEnable(GL_MAP2_VERTEX_3);
  glEvalMesh2(GL_FILL, 0, 100000, 0, 100000);
  EXPECT_EQ(glGetError(), GLenum(GL_OUT_OF_MEMORY));
  // Empty in one direction: no vertices at all, however long the other.
  glEvalMesh2(GL_LINE, 1, 0, std::numeric_limits<GLint>::min(), std::numeric_limits<GLint>::max());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_TRUE(positions().empty());
}

TEST_F(EvaluatorTest, BadInputNeverCrashes) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // A NaN domain is not equal to anything, so GL accepts it (as Mesa); evaluation gives NaN.
  const GLfloat p[6] = {1, 2, 3, nan, 5, 6};
  glMap1f(GL_MAP1_VERTEX_3, nan, 1.0f, 3, 2, p);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(3, nan, 1.0f);
  glBegin(GL_LINE_STRIP);
  glEvalCoord1f(nan);
  glEvalCoord1fv(nullptr);
  glEvalCoord1dv(nullptr);
  glEvalCoord2fv(nullptr);
  glEvalCoord2dv(nullptr);
  glEvalPoint1(std::numeric_limits<GLint>::max());
  glEnd();
  glEvalMesh1(GL_LINE, 0, 3);
  EXPECT_EQ(positions().size(), 6u);
  EXPECT_TRUE(std::isnan(positions()[0].x));
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, nullptr);
  glGetMapdv(GL_MAP1_VERTEX_3, GL_ORDER, nullptr);
  glGetMapiv(GL_MAP1_VERTEX_3, GL_DOMAIN, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, std::numeric_limits<GLint>::max(), p);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, std::numeric_limits<GLint>::min(), 2, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetMapfv(GL_MAP1_VERTEX_3, GL_ORDER, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// glMap2 with null points: accepted by Mesa (no error), the map keeps its order and domain but
// has no control points; glpt evaluates nothing from it (Mesa would crash).
TEST_F(EvaluatorTest, Map2WithoutPoints) {
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 16, 4, 2, 3, 4, 4, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint orders[2];
  glGetMapiv(GL_MAP2_VERTEX_4, GL_ORDER, orders);
  EXPECT_EQ(orders[0], 4);
  GLfloat f[4] = {-7, -7, -7, -7};
  glGetMapfv(GL_MAP2_VERTEX_4, GL_COEFF, f);
  EXPECT_EQ(f[0], -7.0f);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_AUTO_NORMAL);
  glBegin(GL_POINTS);
  glEvalCoord2f(0.5f, 2.5f);
  glEnd();
  glEvalMesh2(GL_FILL, 0, 1, 0, 1);
  EXPECT_TRUE(positions().empty());
}

// An order of 1 with GL_AUTO_NORMAL: Mesa reads past its control points; glpt gives the point
// and a zero normal (the derivative along the constant direction is zero).
TEST_F(EvaluatorTest, AutoNormalOfAnOrderOneDirection) {
  const GLfloat p[6] = {0, 0, 0, 2, 4, 6};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 1, 0, 1, 3, 2, p);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glBegin(GL_POINTS);
  glEvalCoord2f(0.25f, 0.5f);
  glEnd();
  const auto draws = recorded_draws(ctx_);
  ASSERT_EQ(draws.size(), 1u);
  EXPECT_EQ(draws[0].vertices->position[0], glm::vec4(1, 2, 3, 1));
  EXPECT_EQ(at(draws[0].vertices->normal, 0), glm::vec3(0));
}

// ---- display lists
// -------------------------------------------------------------------------------

TEST_F(EvaluatorTest, ListsCopyControlPointsWhenCompiled) {
  GLfloat p[8] = {1, 2, 3, -1, 5, 6, 7, -1};  // stride 4
  glNewList(1, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 2.0f, 4, 2, p);
  glEndList();
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 1);  // compiled, not executed
  p[0] = 100;
  glCallList(1);
  GLfloat f[8];
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, f);
  const GLfloat want[6] = {1, 2, 3, 5, 6, 7};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(f[i], want[i]) << i;

  const GLdouble q[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10.1, 11, 12};
  glNewList(2, GL_COMPILE_AND_EXECUTE);
  glMap2d(GL_MAP2_COLOR_4, 0.1, 0.2, 8, 1, 0.3, 0.4, 4, 2, q + 2);
  glEndList();
  glGetMapfv(GL_MAP2_COLOR_4, GL_COEFF, f);
  EXPECT_EQ(f[0], 3.0f);
  GLdouble domain[4];
  glGetMapdv(GL_MAP2_COLOR_4, GL_DOMAIN, domain);
  EXPECT_EQ(domain[0], double(0.1f));
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 1, 0, 1, 4, 1, f);
  glCallList(2);
  glGetMapfv(GL_MAP2_COLOR_4, GL_COEFF, f);
  EXPECT_EQ(f[7], 10.1f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(EvaluatorTest, CompiledMapsRaiseTheirErrorsWhenTheListRuns) {
  const GLfloat p[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  glNewList(1, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 1.0f, 1.0f, 3, 2, p);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  // Compiled with unit 1 active, run with unit 0 active: the unit at run time decides.
  glActiveTexture(GL_TEXTURE1);
  glNewList(2, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, p);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCallList(2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glActiveTexture(GL_TEXTURE0);
  glCallList(2);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // Mesa's quirk: a positive stride below the components is read as given when compiled, and the
  // list then loads the map without an error.
  glNewList(3, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 1, 2, p);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, nullptr);
  glEndList();
  glCallList(3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));  // from the null points only
  GLfloat f[6];
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, f);
  const GLfloat want[6] = {1, 2, 3, 2, 3, 4};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(f[i], want[i]) << i;
}

// piglit's dlist-fdo31590: glEvalCoord compiled between glBegin and glEnd.
TEST_F(EvaluatorTest, EvaluationsInAListLookLikeImmediateMode) {
  const GLfloat p[12] = {-4, -4, 0, -2, 4, 0, 2, -4, 0, 4, 4, 0};
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, p);
  glEnable(GL_MAP1_VERTEX_3);
  glNewList(5, GL_COMPILE);
  glBegin(GL_LINE_STRIP);
  glColor3f(1, 1, 0);
  for (int i = 0; i <= 30; ++i) glEvalCoord1f(float(i) / 30.0f);
  glEnd();
  glMapGrid1f(30, 0.0f, 1.0f);
  glEvalMesh1(GL_LINE, 0, 30);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glColor3f(1, 1, 1);
  glCallList(5);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const auto draws = recorded_draws(ctx_);
  ASSERT_EQ(draws.size(), 1u);
  const glpt::rec::VertexData& d = *draws[0].vertices;
  ASSERT_EQ(d.vertex_count(), 62u);
  EXPECT_EQ(d.source, glpt::rec::PrimitiveSource::kImmediate);  // Mesa's loopback
  EXPECT_EQ(at(d.color, 0), glm::vec4(1, 1, 0, 1));
  EXPECT_EQ(at(d.color, 61), glm::vec4(1, 1, 0, 1));  // glColor3f of the list is current
  // glEvalMesh1 steps u by adding du, so the same curve agrees only to rounding.
  for (uint32_t i = 0; i <= 30; ++i)
    EXPECT_LT(glm::length(d.position[i] - d.position[31 + i]), 1e-5f) << i;
  EXPECT_EQ(d.position[30], glm::vec4(4, 4, 0, 1));
}

}  // namespace
