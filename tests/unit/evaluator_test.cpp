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

}  // namespace
