// The frame record as the GL front end builds it: commands in GL's order, primitives as GL
// assembled them, and the state snapshot each draw refers to.
#include <variant>

#include "gl_test_context.hpp"

namespace {

class RecordTest : public GlTest {
 protected:
  const glpt::rec::FrameRecord& record() {
    ctx_.recorder.seal();
    return ctx_.recorder.record();
  }
  std::vector<const glpt::rec::Draw*> draws() {
    std::vector<const glpt::rec::Draw*> out;
    for (const auto& c : record().commands)
      if (const auto* d = std::get_if<glpt::rec::Draw>(&c)) out.push_back(d);
    return out;
  }
  const glpt::rec::StateSnapshot& state_of(const glpt::rec::Draw& d) {
    return record().states.at(d.state);
  }
};

void triangle(float z = 0.0f) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex4f(0, 0, z, 1);
  glColor3f(0, 1, 0);
  glVertex4f(2, 0, z, 2);  // homogeneous: kept as given
  glVertex3f(0, 1, z);
  glEnd();
}

TEST_F(RecordTest, ABeginEndBecomesOneDrawWithItsVertices) {
  glNormal3f(0, 1, 0);
  triangle();
  const auto d = draws();
  ASSERT_EQ(d.size(), 1u);
  const glpt::rec::VertexData& v = *d[0]->vertices;
  EXPECT_EQ(v.mode, GLenum{GL_TRIANGLES});
  ASSERT_EQ(v.vertex_count(), 3u);
  EXPECT_EQ(v.position[1], glm::vec4(2, 0, 0, 2));
  ASSERT_EQ(v.color.size(), 3u);  // colours changed between vertices
  EXPECT_EQ(v.color[2], glm::vec4(0, 1, 0, 1));
  ASSERT_EQ(v.normal.size(), 1u);  // the normal did not: one shared value
  EXPECT_EQ(v.normal[0], glm::vec3(0, 1, 0));
  ASSERT_EQ(v.primitives.size(), 1u);
  EXPECT_EQ(v.primitives[0].count, 3u);
}

TEST_F(RecordTest, PrimitivesWithOneStateBatchIntoOneDraw) {
  for (int i = 0; i < 40; ++i) triangle();
  ASSERT_EQ(draws().size(), 1u);
  EXPECT_EQ(draws()[0]->vertices->primitives.size(), 40u);
  EXPECT_EQ(draws()[0]->vertices->primitives[39].first, 117u);
}

TEST_F(RecordTest, AStateChangeStartsANewDrawAndSnapshot) {
  triangle();
  glTranslatef(1, 0, 0);
  triangle();
  triangle();
  const auto d = draws();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NE(d[0]->state, d[1]->state);
  const auto& a = state_of(*d[0]);
  const auto& b = state_of(*d[1]);
  EXPECT_NE(a.transform->modelview, b.transform->modelview);
  // Blocks that did not change are shared, not copied.
  EXPECT_EQ(a.lighting, b.lighting);
  EXPECT_EQ(a.raster, b.raster);
}

TEST_F(RecordTest, EachDrawKeepsTheLightsItWasDrawnWith) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  triangle();
  glDisable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  triangle();
  const auto d = draws();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(state_of(*d[0]).lighting->light_mask, 1u);
  EXPECT_EQ(state_of(*d[1]).lighting->light_mask, 2u);
}

TEST_F(RecordTest, ProjectionAndViewportMayChangeWithinAFrame) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  triangle(-2);
  glLoadIdentity();
  glOrtho(0, 100, 0, 100, -1, 1);
  glViewport(0, 0, 50, 50);
  triangle();
  const auto d = draws();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NE(state_of(*d[0]).transform->projection, state_of(*d[1]).transform->projection);
  EXPECT_EQ(state_of(*d[1]).transform->viewport, (std::array<int32_t, 4>{0, 0, 50, 50}));
}

TEST_F(RecordTest, ClearsAreCommandsInDrawOrder) {
  triangle();
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  triangle();
  const auto& commands = record().commands;
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<glpt::rec::Draw>(commands[0]));
  const auto* clear = std::get_if<glpt::rec::Clear>(&commands[1]);
  ASSERT_NE(clear, nullptr);
  EXPECT_EQ(clear->mask, GLbitfield{GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT});
  EXPECT_EQ(clear->color, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  EXPECT_TRUE(std::holds_alternative<glpt::rec::Draw>(commands[2]));
}

TEST_F(RecordTest, PointsAndLinesAreRecorded) {
  glBegin(GL_POINTS);
  glVertex2f(0, 0);
  glEnd();
  glBegin(GL_LINE_LOOP);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(1, 1);
  glEnd();
  const auto d = draws();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0]->vertices->mode, GLenum{GL_POINTS});
  EXPECT_EQ(d[1]->vertices->mode, GLenum{GL_LINE_LOOP});
}

TEST_F(RecordTest, RecolouringKeepsTheGeometryKey) {
  triangle();
  glColor3f(0, 0, 1);
  glBegin(GL_TRIANGLES);
  glVertex4f(0, 0, 0, 1);
  glVertex4f(2, 0, 0, 2);
  glVertex3f(0, 1, 0);
  glEnd();
  glTranslatef(0, 0, 0.5f);  // a separate draw
  glBegin(GL_TRIANGLES);
  glVertex4f(0, 0, 0, 1);
  glVertex4f(2, 0, 0, 2);
  glVertex3f(0, 1, 0);
  glEnd();
  // The first two triangles share a draw; compare the last draw with a fresh one of the same
  // positions and colours.
  const auto d = draws();
  ASSERT_EQ(d.size(), 2u);
  glpt::rec::VertexData recoloured = *d[1]->vertices;
  recoloured.color = {glm::vec4(1, 1, 0, 1)};
  glpt::finish_vertex_data(recoloured);
  EXPECT_EQ(recoloured.keys().geometry, d[1]->vertices->keys().geometry);
  EXPECT_NE(recoloured.keys().attributes, d[1]->vertices->keys().attributes);
}

// Keys are hashed on first use and cached; a copy does not carry the cache, so changing the copy
// changes its keys (and only the changed one).
TEST(VertexKeysTest, ACopyIsHashedAgain) {
  glpt::rec::VertexData original;
  original.mode = GL_TRIANGLES;
  original.position = {glm::vec4(0, 0, 0, 1), glm::vec4(1, 0, 0, 1), glm::vec4(0, 1, 0, 1)};
  original.color = {glm::vec4(1, 0, 0, 1)};
  original.primitives = {{0, 3}};
  const glpt::rec::VertexKeys keys = original.keys();
  glpt::rec::VertexData copy = original;
  copy.color = {glm::vec4(0, 1, 0, 1)};
  EXPECT_EQ(copy.keys().geometry, keys.geometry);
  EXPECT_NE(copy.keys().attributes, keys.attributes);
  glpt::rec::VertexData moved = std::move(copy);
  moved.position[2].y = 2.0f;
  EXPECT_NE(moved.keys().geometry, keys.geometry);
  // Changed in place after asking: forget_keys() makes it hash again.
  original.indices = {0, 1, 2};
  original.forget_keys();
  EXPECT_NE(original.keys().geometry, keys.geometry);
}

TEST_F(RecordTest, DisablingColorMaterialKeepsTheColourItWrote) {
  glEnable(GL_LIGHTING);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
  glDisable(GL_COLOR_MATERIAL);
  glColor4f(1, 1, 1, 1);  // no longer tracked
  GLfloat diffuse[4];
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  EXPECT_FLOAT_EQ(diffuse[0], 0.1f);
  EXPECT_FLOAT_EQ(diffuse[3], 0.4f);
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, diffuse);
  EXPECT_FLOAT_EQ(diffuse[0], 0.8f);  // the back was not tracked
  triangle();
  EXPECT_EQ(state_of(*draws()[0]).lighting->material[0].diffuse, glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
}

TEST_F(RecordTest, EnablingColorMaterialAppliesTheCurrentColourAtOnce) {
  glColor3f(0.5f, 0.25f, 0.125f);
  glColorMaterial(GL_FRONT_AND_BACK, GL_EMISSION);
  glEnable(GL_COLOR_MATERIAL);
  GLfloat emission[4];
  glGetMaterialfv(GL_BACK, GL_EMISSION, emission);
  EXPECT_FLOAT_EQ(emission[1], 0.25f);
}

TEST_F(RecordTest, MaterialChangesInsideBeginEndArePerVertex) {
  const GLfloat red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glVertex3f(1, 0, 0);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
  glVertex3f(0, 1, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto& m = draws().at(0)->vertices->material;
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0][0].diffuse, glm::vec4(0.8f, 0.8f, 0.8f, 1.0f));  // before the first glMaterial
  EXPECT_EQ(m[1][0].diffuse, glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(m[2][0].diffuse, glm::vec4(0, 0, 1, 1));
}

// glColor inside glBegin/glEnd updates the GL_COLOR_MATERIAL fields once it matters (at glEnd,
// or when glMaterial is called): the material then is what it would have been after every glColor.
TEST_F(RecordTest, ColorMaterialInsideBeginEndTakesEffect) {
  const GLfloat shiny[4] = {0.5f, 0.5f, 0.5f, 1};
  glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex3f(0, 0, 0);
  glColor3f(0, 1, 0);
  glVertex3f(1, 0, 0);
  // From here every vertex carries its material: the one of the green glColor before it.
  glMaterialfv(GL_FRONT, GL_SPECULAR, shiny);
  glVertex3f(0, 1, 0);
  glColor3f(0, 0, 1);
  glVertex3f(0, 0, 1);
  glVertex3f(1, 0, 1);
  glVertex3f(0, 1, 1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto& m = draws().at(0)->vertices->material;
  ASSERT_EQ(m.size(), 6u);
  EXPECT_EQ(m[2][0].diffuse, glm::vec4(0, 1, 0, 1));
  EXPECT_EQ(m[2][0].specular, glm::vec4(0.5f, 0.5f, 0.5f, 1));
  EXPECT_EQ(m[3][0].diffuse, glm::vec4(0, 0, 1, 1));
  EXPECT_EQ(m[3][1].diffuse, glm::vec4(0, 0, 1, 1));
  GLfloat diffuse[4];
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, diffuse);
  EXPECT_EQ(diffuse[2], 1.0f);
  // Without glMaterial inside: the last colour's update, visible after glEnd.
  glBegin(GL_POINTS);
  glColor3f(1, 1, 0);
  glVertex3f(0, 0, 0);
  glColor3f(0, 1, 1);
  glEnd();
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  EXPECT_EQ(diffuse[0], 0.0f);
  EXPECT_EQ(diffuse[1], 1.0f);
  EXPECT_EQ(diffuse[2], 1.0f);
  // The next draw's snapshot holds it too.
  triangle();
  EXPECT_EQ(state_of(*draws().back()).lighting->material[0].diffuse, glm::vec4(0, 1, 1, 1));
}

TEST_F(RecordTest, ADisplayListDrawnTwiceGivesEqualKeys) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  triangle();
  glEndList();
  glCallList(list);
  glTranslatef(1, 0, 0);
  glCallList(list);
  const auto d = draws();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0]->vertices->keys().geometry, d[1]->vertices->keys().geometry);
  EXPECT_EQ(d[0]->vertices->keys().attributes, d[1]->vertices->keys().attributes);
}

TEST_F(RecordTest, EndListInsideBeginEndIsAnError) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_TRIANGLES);
  glEndList();  // GL_INVALID_OPERATION, and the list stays open
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_FALSE(glIsList(list));
  glEndList();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_TRUE(glIsList(list));
}

// How the primitives were given decides how Mesa splits them (rt_core/record/decompose.hpp):
// glBegin/glEnd replayed from a display list are indexed draws in Mesa; the execution of
// GL_COMPILE_AND_EXECUTE is immediate mode.
TEST_F(RecordTest, DrawsRecordWhetherADisplayListDrewThem) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  triangle();
  glEndList();
  triangle();
  glCallList(list);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glTranslatef(1, 0, 0);  // a new draw
  triangle();
  glEndList();
  const auto d = draws();
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0]->vertices->source, glpt::rec::PrimitiveSource::kImmediate);
  EXPECT_EQ(d[1]->vertices->source, glpt::rec::PrimitiveSource::kDisplayList);
  EXPECT_EQ(d[2]->vertices->source, glpt::rec::PrimitiveSource::kImmediate);
}

void quad(bool colour_inside) {
  glBegin(GL_QUADS);
  if (colour_inside) glColor3f(1, 0, 0);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(1, 1);
  glVertex2f(0, 1);
  glEnd();
}

// Mesa's fragment shader reads a colour given inside glBegin/glEnd per vertex, and one set only
// outside as a constant. Mesa's vertex layout keeps the colour once it has one, until the next
// state change; growing the layout ends its batch.
TEST_F(RecordTest, DrawsRecordWhichColoursWereGivenPerVertex) {
  glColor3f(0, 1, 0);
  glSecondaryColor3f(0, 0, 1);
  quad(false);
  quad(true);
  quad(false);  // continues the draw that has per-vertex colours
  glBegin(GL_QUADS);
  glSecondaryColor3f(1, 1, 0);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(1, 1);
  glVertex2f(0, 1);
  glEnd();
  const auto d = draws();
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0]->vertices->per_vertex, 0u);
  EXPECT_EQ(d[1]->vertices->per_vertex, glpt::rec::kPerVertexColor);
  EXPECT_EQ(d[1]->vertices->primitives.size(), 2u);
  EXPECT_EQ(d[2]->vertices->per_vertex,
            glpt::rec::kPerVertexColor | glpt::rec::kPerVertexSecondaryColor);
}

}  // namespace

// A program drawing the same large batch every frame reuses storage once a record was executed
// and cleared (no allocation, and no page faults, per frame), with this frame's vertices in it.
// glBegin/glEnd's scratch and the record exchange two sets of arrays: frame 3 records into the
// storage of frame 1.
TEST_F(RecordTest, AClearedRecordsBatchStorageIsReusedWithNewVertices) {
  triangle(0.25f);
  const float* first_storage = nullptr;
  {
    const auto d = draws();
    ASSERT_EQ(d.size(), 1u);
    first_storage = &d[0]->vertices->position[0].x;
  }
  ctx_.recorder.clear();
  triangle(0.75f);
  EXPECT_EQ(draws().size(), 1u);
  ctx_.recorder.clear();
  triangle(0.5f);
  const auto d = draws();
  ASSERT_EQ(d.size(), 1u);
  const glpt::rec::VertexData& v = *d[0]->vertices;
  EXPECT_EQ(&v.position[0].x, first_storage);
  ASSERT_EQ(v.vertex_count(), 3u);
  EXPECT_EQ(v.position[0], glm::vec4(0, 0, 0.5f, 1));
  EXPECT_EQ(v.position[1], glm::vec4(2, 0, 0.5f, 2));
  EXPECT_EQ(v.position[2], glm::vec4(0, 1, 0.5f, 1));
  ASSERT_EQ(v.primitives.size(), 1u);
  EXPECT_EQ(v.primitives[0].first, 0u);
  EXPECT_EQ(v.primitives[0].count, 3u);
}

// A draw a consumer still holds (the path tracer's scene) is never reused or changed.
TEST_F(RecordTest, ADrawStillHeldElsewhereIsNotReused) {
  triangle(0.25f);
  std::shared_ptr<const glpt::rec::VertexData> held = draws().at(0)->vertices;
  ctx_.recorder.clear();
  triangle(0.5f);
  EXPECT_NE(draws().at(0)->vertices.get(), held.get());
  EXPECT_NE(&draws().at(0)->vertices->position[0].x, &held->position[0].x);
  ASSERT_EQ(held->vertex_count(), 3u);
  EXPECT_EQ(held->position[0], glm::vec4(0, 0, 0.25f, 1));
}

// Array draws take the storage too, and record their own vertices in it.
TEST_F(RecordTest, ArrayDrawsReuseAClearedRecordsStorage) {
  triangle(0.25f);
  const float* first_storage = &draws().at(0)->vertices->position[0].x;
  ctx_.recorder.clear();
  const GLfloat positions[] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  glVertexPointer(3, GL_FLOAT, 0, positions);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const auto d = draws();
  ASSERT_EQ(d.size(), 1u);
  const glpt::rec::VertexData& v = *d[0]->vertices;
  EXPECT_EQ(&v.position[0].x, first_storage);
  ASSERT_EQ(v.vertex_count(), 3u);
  EXPECT_EQ(v.position[0], glm::vec4(1, 2, 3, 1));
  EXPECT_EQ(v.position[2], glm::vec4(7, 8, 9, 1));
  EXPECT_TRUE(v.indices.empty());
}

namespace {

using glpt::rec::append_attribute;
using glpt::rec::attribute_at;
using glpt::rec::store_attribute;

// Every vertex's value under the "one value or one per vertex" rule.
std::vector<float> expanded(const std::vector<float>& values, uint32_t count) {
  std::vector<float> out;
  for (uint32_t i = 0; i < count; ++i) out.push_back(attribute_at(values, i, -1.0f));
  return out;
}

TEST(AttributeRuleTest, StoringKeepsOneValueUntilAVertexDiffers) {
  std::vector<float> values;
  store_attribute(values, 2.0f, 0);
  store_attribute(values, 2.0f, 1);
  store_attribute(values, 2.0f, 2);
  EXPECT_EQ(values.size(), 1u);
  store_attribute(values, 5.0f, 3);  // the three before are filled in
  store_attribute(values, 5.0f, 4);
  EXPECT_EQ(values, (std::vector<float>{2, 2, 2, 5, 5}));
  std::vector<float> signs;
  store_attribute(signs, 0.0f, 0);
  store_attribute(signs, -0.0f, 1);  // bitwise: two values, as GL gave them
  EXPECT_EQ(signs.size(), 2u);
}

TEST(AttributeRuleTest, AppendingKeepsEveryVertexsValue) {
  struct Case {
    std::vector<float> to;
    uint32_t to_count;
    std::vector<float> from;
    uint32_t from_count;
  };
  const Case cases[] = {
      {{1}, 3, {1}, 2},        // one value both: stays one
      {{1}, 3, {2}, 2},        // two single values
      {{1}, 1, {2}, 4},        // a single vertex before
      {{1, 2, 3}, 3, {4}, 2},  // per vertex, then one value
      {{1}, 2, {4, 5, 6}, 3},  // one value, then per vertex
      {{1, 2}, 2, {3, 4}, 2},  // per vertex both
      {{1}, 2, {}, 3},         // an unused attribute appends nothing
  };
  for (const Case& c : cases) {
    std::vector<float> to = c.to;
    append_attribute(to, c.to_count, c.from, c.from_count);
    if (c.from.empty()) {
      EXPECT_EQ(to, c.to);
      continue;
    }
    std::vector<float> want = expanded(c.to, c.to_count);
    for (float v : expanded(c.from, c.from_count)) want.push_back(v);
    EXPECT_EQ(expanded(to, c.to_count + c.from_count), want);
    EXPECT_TRUE(to.size() == 1 || to.size() == c.to_count + c.from_count) << to.size();
  }
  std::vector<float> same{7};
  append_attribute(same, 3, std::vector<float>{7}, 2);
  EXPECT_EQ(same.size(), 1u);
}

TEST_F(RecordTest, AttributesChangingInAPrimitiveOrBetweenBatchedOnesKeepEachVertexsValue) {
  glBegin(GL_TRIANGLES);  // the normal changes at the third vertex, the fog coordinate never
  glNormal3f(0, 0, 1);
  glVertex3f(0, 0, 0);
  glVertex3f(1, 0, 0);
  glNormal3f(0, 1, 0);
  glVertex3f(0, 1, 0);
  glEnd();
  glBegin(GL_TRIANGLES);  // batched with the first: one normal for all its vertices
  glVertex3f(0, 0, 1);
  glVertex3f(1, 0, 1);
  glVertex3f(0, 1, 1);
  glEnd();
  glBegin(GL_TRIANGLES);  // and per vertex again
  glNormal3f(1, 0, 0);
  glVertex3f(0, 0, 2);
  glNormal3f(0, 0, -1);
  glVertex3f(1, 0, 2);
  glVertex3f(0, 1, 2);
  glEnd();
  const auto d = draws();
  ASSERT_EQ(d.size(), 1u);
  const glpt::rec::VertexData& v = *d[0]->vertices;
  ASSERT_EQ(v.vertex_count(), 9u);
  const glm::vec3 want[] = {{0, 0, 1}, {0, 0, 1}, {0, 1, 0},  {0, 1, 0}, {0, 1, 0},
                            {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {0, 0, -1}};
  ASSERT_EQ(v.normal.size(), 9u);
  for (uint32_t i = 0; i < 9; ++i) EXPECT_EQ(v.normal[i], want[i]) << "vertex " << i;
  EXPECT_EQ(v.fog_coord.size(), 1u);
  EXPECT_EQ(v.color.size(), 1u);
}

}  // namespace
