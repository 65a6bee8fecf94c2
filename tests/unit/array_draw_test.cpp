// Drawing from vertex arrays (GL 1.5 2.8): what glDrawArrays, glDrawElements,
// glDrawRangeElements, glMultiDraw* and glArrayElement record, Mesa's conversions of every
// component type (mesa_reference/mesa_array_expected.inc, printed by OSMesa), and the errors.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "array_test_util.hpp"

namespace {

using glpt::rec::Draw;
using glpt::rec::VertexData;

struct ConversionCase {
  GLenum type;
  long long value;
  double draw;     // the colour component glDrawArrays gives (llvmpipe's vertex fetch)
  double element;  // the current colour glArrayElement sets
};
const ConversionCase kConversions[] = {
#include "mesa_reference/mesa_array_expected.inc"
};

size_t type_size(GLenum type) {
  switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE:
      return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
      return 2;
    case GL_DOUBLE:
      return 8;
    default:
      return 4;
  }
}

// One element of `components` values of `type`, each `value` (truncated to the type).
std::vector<uint8_t> element_of(GLenum type, long long value, int components) {
  std::vector<uint8_t> out;
  for (int k = 0; k < components; ++k) {
    uint8_t bytes[8] = {};
    switch (type) {
      case GL_BYTE:
      case GL_UNSIGNED_BYTE:
        bytes[0] = uint8_t(value);
        break;
      case GL_SHORT:
      case GL_UNSIGNED_SHORT: {
        const uint16_t v = uint16_t(value);
        std::memcpy(bytes, &v, 2);
        break;
      }
      default: {
        const uint32_t v = uint32_t(value);
        std::memcpy(bytes, &v, 4);
        break;
      }
    }
    out.insert(out.end(), bytes, bytes + type_size(type));
  }
  return out;
}

class ArrayDrawTest : public GlTest {
 protected:
  std::vector<Draw> draws() { return recorded_draws(ctx_); }
  const VertexData& only_draw() {
    draws_ = draws();
    EXPECT_EQ(draws_.size(), 1u);
    if (draws_.empty()) {
      static const VertexData none;
      return none;
    }
    return *draws_.back().vertices;
  }
  std::vector<Draw> draws_;
};

const float kSquare[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

TEST_F(ArrayDrawTest, ColourConversionsAreMesasForEveryType) {
  static const float position[3] = {0, 0, 0};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, position);
  glEnableClientState(GL_COLOR_ARRAY);
  for (const ConversionCase& c : kConversions) {
    SCOPED_TRACE(::testing::Message() << "type " << c.type << " value " << c.value);
    const std::vector<uint8_t> element = element_of(c.type, c.value, 4);
    glColorPointer(4, c.type, 0, element.data());
    ctx_.recorder.clear();
    glDrawArrays(GL_POINTS, 0, 1);
    const VertexData& d = only_draw();
    ASSERT_EQ(d.color.size(), 1u);
    EXPECT_EQ(d.color[0].r, float(c.draw));
    EXPECT_EQ(d.color[0].a, float(c.draw));
    glArrayElement(0);
    GLfloat current[4];
    glGetFloatv(GL_CURRENT_COLOR, current);
    EXPECT_EQ(current[0], float(c.element));
  }
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(ArrayDrawTest, DrawArraysRecordsTheArraysAndTheCurrentValues) {
  const GLubyte colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
  glColor4f(0.25f, 0.5f, 0.75f, 1);
  glNormal3f(0, 1, 0);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  glDrawArrays(GL_QUADS, 0, 4);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, colours);
  glDrawArrays(GL_TRIANGLE_FAN, 1, 3);
  const auto d = draws();
  ASSERT_EQ(d.size(), 2u);
  const VertexData& a = *d[0].vertices;
  EXPECT_EQ(a.mode, GLenum{GL_QUADS});
  ASSERT_EQ(a.vertex_count(), 4u);
  EXPECT_EQ(a.position[2], glm::vec4(1, 1, 0, 1));  // size 2: z 0, w 1
  ASSERT_EQ(a.color.size(), 1u);                    // disabled: the current value, once
  EXPECT_EQ(a.color[0], glm::vec4(0.25f, 0.5f, 0.75f, 1));
  EXPECT_EQ(a.normal.at(0), glm::vec3(0, 1, 0));
  ASSERT_EQ(a.primitives.size(), 1u);
  EXPECT_EQ(a.primitives[0].count, 4u);
  EXPECT_TRUE(a.indices.empty());
  const VertexData& b = *d[1].vertices;
  ASSERT_EQ(b.vertex_count(), 3u);  // vertices 1, 2, 3
  EXPECT_EQ(b.position[0], glm::vec4(1, 0, 0, 1));
  ASSERT_EQ(b.color.size(), 3u);
  EXPECT_EQ(b.color[0], glm::vec4(0, 1, 0, 1));  // size 3: alpha 1
  EXPECT_EQ(b.color[2], glm::vec4(1, 1, 1, 1));
  // Mesa leaves the current values of array attributes unchanged after a draw.
  GLfloat current[4];
  glGetFloatv(GL_CURRENT_COLOR, current);
  EXPECT_EQ(current[1], 0.5f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(ArrayDrawTest, EveryAttributeArrayIsRecorded) {
  struct Vertex {
    GLdouble position[4];
    GLshort normal[3];
    GLushort colour[4];
    GLbyte secondary[3];
    GLfloat fog;
    GLint tex0[2];
    GLdouble tex1[3];
    GLboolean edge;
  };
  Vertex v[2] = {};
  for (int i = 0; i < 2; ++i) {
    v[i] = Vertex{{1.5 + i, 2, 3, 4}, {32767, 0, -32768}, {65535, 0, 32768, 65535},
                  {127, 0, -128},     0.5f + i,           {7, -8},
                  {0.25, 0.5, 0.75},  GLboolean(i)};
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(4, GL_DOUBLE, sizeof(Vertex), &v[0].position);
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_SHORT, sizeof(Vertex), &v[0].normal);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_UNSIGNED_SHORT, sizeof(Vertex), &v[0].colour);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glSecondaryColorPointer(3, GL_BYTE, sizeof(Vertex), &v[0].secondary);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glFogCoordPointer(GL_FLOAT, sizeof(Vertex), &v[0].fog);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_INT, sizeof(Vertex), &v[0].tex0);
  glClientActiveTexture(GL_TEXTURE1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(3, GL_DOUBLE, sizeof(Vertex), &v[0].tex1);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glEdgeFlagPointer(sizeof(Vertex), &v[0].edge);
  // Texture coordinates are recorded for units that sample a texture.
  const GLubyte texel[4] = {255, 255, 255, 255};
  for (GLenum unit : {GL_TEXTURE0, GL_TEXTURE1}) {
    glActiveTexture(unit);
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  }
  glDrawArrays(GL_LINES, 0, 2);
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const VertexData& d = only_draw();
  ASSERT_EQ(d.vertex_count(), 2u);
  EXPECT_EQ(d.position[1], glm::vec4(2.5f, 2, 3, 4));
  // Normalized through the vertex fetch: c / (2^(b-1) - 1), clamped to -1; c / (2^b - 1).
  EXPECT_EQ(at(d.normal, 0), glm::vec3(1, 0, -1));
  EXPECT_EQ(at(d.color, 0), glm::vec4(1, 0, 32768.0f * (1.0f / 65535.0f), 1));
  EXPECT_EQ(glm::vec3(at(d.secondary_color, 0)), glm::vec3(1, 0, -1));
  EXPECT_EQ(d.fog_coord.at(1), 1.5f);
  EXPECT_EQ(at(d.tex_coord[0], 1), glm::vec4(7, -8, 0, 1));
  EXPECT_EQ(at(d.tex_coord[1], 0), glm::vec4(0.25f, 0.5f, 0.75f, 1));
  EXPECT_TRUE(d.tex_coord[2].empty());
  ASSERT_EQ(d.edge_flag.size(), 2u);
  EXPECT_EQ(d.edge_flag[0], 0);
  EXPECT_EQ(d.edge_flag[1], 1);
}

TEST_F(ArrayDrawTest, StridesStepThroughPaddedData) {
  // Positions every 20 bytes, colours packed; the disabled normal array is ignored.
  std::vector<uint8_t> data(3 * 20, 0xff);
  for (int i = 0; i < 3; ++i) {
    const float p[3] = {float(i), float(10 * i), 0};
    std::memcpy(data.data() + 20 * i, p, sizeof p);
  }
  const GLfloat colours[3][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 0.5f}};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 20, data.data());
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_FLOAT, 0, colours);
  glNormalPointer(GL_FLOAT, 0, nullptr);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const VertexData& d = only_draw();
  ASSERT_EQ(d.vertex_count(), 3u);
  EXPECT_EQ(d.position[2], glm::vec4(2, 20, 0, 1));
  EXPECT_EQ(d.color.at(2), glm::vec4(0, 0, 1, 0.5f));
}

// Long draws read each array in one pass per draw (and the non-vec4 attributes in chunks of a few
// hundred elements): every element must still be its own, from a range, from a sparse index list,
// and where part of a buffer object's array lies beyond its store (those elements read
// (0, 0, 0, 1), as element by element).
TEST_F(ArrayDrawTest, LongDrawsReadEveryElement) {
  constexpr int kVertices = 1500;
  struct Vertex {
    GLshort position[2];
    GLubyte colour[3];
    GLubyte pad;
    GLfloat normal[3];
  };
  std::vector<Vertex> v(kVertices);
  std::vector<GLfloat> fog(kVertices);
  for (int i = 0; i < kVertices; ++i) {
    v[i] = {{GLshort(i), GLshort(-i)},
            {GLubyte(i % 2 ? 255 : 0), GLubyte(i % 3 ? 255 : 0), 255},
            0,
            {float(i), 0.5f, -float(i)}};
    fog[i] = 0.25f * float(i);
  }
  auto expect_vertex = [&](const VertexData& d, uint32_t at, int i) {
    SCOPED_TRACE(::testing::Message() << "vertex " << i);
    EXPECT_EQ(d.position.at(at), glm::vec4(float(i), float(-i), 0, 1));
    EXPECT_EQ(d.color.at(at), glm::vec4(i % 2 ? 1 : 0, i % 3 ? 1 : 0, 1, 1));
    EXPECT_EQ(d.normal.at(at), glm::vec3(float(i), 0.5f, -float(i)));
    EXPECT_EQ(d.fog_coord.at(at), 0.25f * float(i));
  };
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_SHORT, sizeof(Vertex), &v[0].position);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_UNSIGNED_BYTE, sizeof(Vertex), &v[0].colour);
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_FLOAT, sizeof(Vertex), &v[0].normal);
  glEnableClientState(GL_FOG_COORDINATE_ARRAY);
  glFogCoordPointer(GL_FLOAT, 0, fog.data());

  glDrawArrays(GL_POINTS, 7, kVertices - 7);
  {
    const VertexData& d = only_draw();
    ASSERT_EQ(d.vertex_count(), uint32_t(kVertices - 7));
    for (int i = 7; i < kVertices; ++i) expect_vertex(d, uint32_t(i - 7), i);
  }

  // Sparse indices (a span far beyond twice their count): a list of vertices, not a range.
  std::vector<GLuint> indices;
  for (int i = kVertices - 1; i >= 0; i -= 7) indices.push_back(GLuint(i));
  indices.push_back(3);
  ctx_.recorder.clear();
  glDrawElements(GL_POINTS, GLsizei(indices.size()), GL_UNSIGNED_INT, indices.data());
  {
    const VertexData& d = only_draw();
    ASSERT_EQ(d.indices.size(), indices.size());
    for (size_t k = 0; k < indices.size(); ++k) expect_vertex(d, d.indices[k], int(indices[k]));
  }

  // Colours from a buffer object holding only the first 1000 elements: the rest read
  // (0, 0, 0, 1) while the in-store ones are converted as usual.
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(1000 * sizeof(Vertex)), v.data(), GL_STATIC_DRAW);
  glColorPointer(3, GL_UNSIGNED_BYTE, sizeof(Vertex),
                 reinterpret_cast<const void*>(offsetof(Vertex, colour)));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glVertexPointer(2, GL_SHORT, sizeof(Vertex), &v[0].position);
  ctx_.recorder.clear();
  glDrawArrays(GL_POINTS, 0, kVertices);
  {
    const VertexData& d = only_draw();
    ASSERT_EQ(d.color.size(), size_t(kVertices));
    for (int i = 0; i < kVertices; ++i) {
      const glm::vec4 expected =
          i < 1000 ? glm::vec4(i % 2 ? 1 : 0, i % 3 ? 1 : 0, 1, 1) : glm::vec4(0, 0, 0, 1);
      EXPECT_EQ(d.color[size_t(i)], expected) << "vertex " << i;
    }
  }
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

template <typename Index>
void draw_with_indices(GLenum type) {
  const Index indices[6] = {3, 2, 1, 3, 1, 0};
  glDrawElements(GL_TRIANGLES, 6, type, indices);
}

TEST_F(ArrayDrawTest, DrawElementsKeepsIndicesOfEveryType) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  draw_with_indices<GLubyte>(GL_UNSIGNED_BYTE);
  draw_with_indices<GLushort>(GL_UNSIGNED_SHORT);
  draw_with_indices<GLuint>(GL_UNSIGNED_INT);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto d = draws();
  ASSERT_EQ(d.size(), 3u);
  for (const Draw& draw : d) {
    const VertexData& v = *draw.vertices;
    ASSERT_EQ(v.vertex_count(), 4u);
    EXPECT_EQ(v.indices, (std::vector<uint32_t>{3, 2, 1, 3, 1, 0}));
    EXPECT_EQ(v.position[v.indices[0]], glm::vec4(0, 1, 0, 1));
    ASSERT_EQ(v.primitives.size(), 1u);
    EXPECT_EQ(v.primitives[0].count, 6u);
  }
}

TEST_F(ArrayDrawTest, DrawElementsReadsOnlyTheVerticesItUses) {
  // Two far-apart vertices of a large array: only they are converted, the indices renumbered.
  std::vector<GLfloat> positions(2 * 100000, 0.0f);
  positions[2 * 5] = 5;
  positions[2 * 99999] = 99999;
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions.data());
  const GLuint indices[3] = {99999, 5, 99999};
  glDrawRangeElements(GL_LINE_STRIP, 5, 99999, 3, GL_UNSIGNED_INT, indices);
  const VertexData& d = only_draw();
  ASSERT_EQ(d.vertex_count(), 2u);
  ASSERT_EQ(d.indices.size(), 3u);
  EXPECT_EQ(d.position[d.indices[0]].x, 99999.0f);
  EXPECT_EQ(d.position[d.indices[1]].x, 5.0f);
  EXPECT_EQ(d.indices[0], d.indices[2]);
}

TEST_F(ArrayDrawTest, MultiDrawsRecordOneRangePerDraw) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  const GLint first[3] = {0, 1, 2};
  const GLsizei count[3] = {3, 0, 2};
  glMultiDrawArrays(GL_LINE_STRIP, first, count, 3);
  const GLubyte a[2] = {3, 0}, b[3] = {1, 2, 3};
  const void* indices[2] = {a, b};
  const GLsizei index_counts[2] = {2, 3};
  glMultiDrawElements(GL_LINES, index_counts, GL_UNSIGNED_BYTE, indices, 2);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto d = draws();
  ASSERT_EQ(d.size(), 2u);
  const VertexData& arrays = *d[0].vertices;
  ASSERT_EQ(arrays.primitives.size(), 2u);  // the empty draw is skipped
  EXPECT_EQ(arrays.primitives[1].first, 3u);
  EXPECT_EQ(arrays.primitives[1].count, 2u);
  EXPECT_EQ(arrays.position[3], glm::vec4(1, 1, 0, 1));  // first[2] = 2
  const VertexData& elements = *d[1].vertices;
  ASSERT_EQ(elements.primitives.size(), 2u);
  EXPECT_EQ(elements.primitives[1].first, 2u);
  ASSERT_EQ(elements.indices.size(), 5u);
  EXPECT_EQ(elements.position[elements.indices[1]], glm::vec4(0, 0, 0, 1));
}

TEST_F(ArrayDrawTest, ArrayElementInsideBeginEndAssemblesAPrimitive) {
  const GLfloat colours[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  const GLbyte normals[4][3] = {{0, 0, 127}, {0, 127, 0}, {127, 0, 0}, {0, 0, -128}};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_FLOAT, 0, colours);
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_BYTE, 0, normals);
  glBegin(GL_TRIANGLES);
  glArrayElement(3);
  glArrayElement(1);
  glVertex2f(5, 5);  // the current values the last glArrayElement left
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const VertexData& d = only_draw();
  ASSERT_EQ(d.vertex_count(), 3u);
  EXPECT_EQ(d.position[0], glm::vec4(0, 1, 0, 1));
  EXPECT_EQ(at(d.color, 2), glm::vec4(0, 1, 0, 1));
  // glNormal3bv's conversion: (2c + 1) / 255.
  EXPECT_EQ(at(d.normal, 0).z, (2.0f * -128 + 1) / 255.0f);
  EXPECT_EQ(at(d.normal, 1).y, 1.0f);
  // Outside glBegin/glEnd it sets the current values only.
  glArrayElement(2);
  GLfloat current[4];
  glGetFloatv(GL_CURRENT_COLOR, current);
  EXPECT_EQ(current[2], 1.0f);
  EXPECT_EQ(draws().size(), 1u);
  // A negative element reads nothing.
  glArrayElement(-1);
  glGetFloatv(GL_CURRENT_COLOR, current);
  EXPECT_EQ(current[2], 1.0f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(ArrayDrawTest, WithoutAVertexArrayNothingIsDrawn) {
  const GLfloat colours[2][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}};
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_FLOAT, 0, colours);
  glDrawArrays(GL_POINTS, 0, 2);
  const GLubyte indices[2] = {0, 1};
  glDrawElements(GL_POINTS, 2, GL_UNSIGNED_BYTE, indices);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_TRUE(draws().empty());
}

TEST_F(ArrayDrawTest, ErrorsAreMesasAndDrawNothing) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  const GLubyte indices[3] = {0, 1, 2};
  struct Case {
    const char* what;
    void (*call)(const GLubyte*);
    GLenum error;
  };
  const Case cases[] = {
      {"count < 0", [](const GLubyte*) { glDrawArrays(GL_POINTS, 0, -1); }, GL_INVALID_VALUE},
      {"bad mode", [](const GLubyte*) { glDrawArrays(GL_POLYGON + 1, 0, 3); }, GL_INVALID_ENUM},
      {"count first", [](const GLubyte*) { glDrawArrays(GL_POLYGON + 1, 0, -1); },
       GL_INVALID_VALUE},
      {"elements count",
       [](const GLubyte* i) { glDrawElements(GL_POINTS, -2, GL_UNSIGNED_BYTE, i); },
       GL_INVALID_VALUE},
      {"elements mode", [](const GLubyte* i) { glDrawElements(0x20, 3, GL_UNSIGNED_BYTE, i); },
       GL_INVALID_ENUM},
      {"elements type", [](const GLubyte* i) { glDrawElements(GL_POINTS, 3, GL_BYTE, i); },
       GL_INVALID_ENUM},
      {"elements float", [](const GLubyte* i) { glDrawElements(GL_POINTS, 3, GL_FLOAT, i); },
       GL_INVALID_ENUM},
      {"range end < start",
       [](const GLubyte* i) { glDrawRangeElements(GL_POINTS, 2, 1, 3, GL_UNSIGNED_BYTE, i); },
       GL_INVALID_VALUE},
      {"multi count < 0",
       [](const GLubyte*) {
         const GLint first[2] = {0, 0};
         const GLsizei count[2] = {3, -1};
         glMultiDrawArrays(GL_POINTS, first, count, 2);
       },
       GL_INVALID_VALUE},
      {"multi drawcount < 0",
       [](const GLubyte*) { glMultiDrawArrays(GL_POINTS, nullptr, nullptr, -1); },
       GL_INVALID_VALUE},
      {"multi elements type",
       [](const GLubyte* i) {
         const GLsizei count[1] = {3};
         const void* list[1] = {i};
         glMultiDrawElements(GL_POINTS, count, GL_SHORT, list, 1);
       },
       GL_INVALID_ENUM},
  };
  for (const Case& c : cases) {
    c.call(indices);
    EXPECT_EQ(glGetError(), c.error) << c.what;
  }
  EXPECT_TRUE(draws().empty());
  // Inside glBegin/glEnd every draw is an error; glArrayElement is allowed.
  // (glGetError itself is not allowed there.)
  glBegin(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, 1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glBegin(GL_POINTS);
  glDrawElements(GL_POINTS, 1, GL_UNSIGNED_BYTE, indices);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glBegin(GL_POINTS);
  glArrayElement(0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(draws().size(), 1u);  // the point glArrayElement gave
}

TEST_F(ArrayDrawTest, BadInputNeverCrashes) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  // Null pointers: nothing to read, no error (Mesa crashes on the first two).
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, nullptr);
  glMultiDrawElements(GL_TRIANGLES, nullptr, GL_UNSIGNED_INT, nullptr, 4);
  glMultiDrawArrays(GL_TRIANGLES, nullptr, nullptr, 4);
  const GLsizei counts[1] = {3};
  const void* no_indices[1] = {nullptr};
  glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_INT, no_indices, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // A negative first draws nothing (Mesa raises no error).
  glDrawArrays(GL_POINTS, -5, 3);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // More vertices than one draw may assemble: GL_OUT_OF_MEMORY, nothing read.
  glDrawArrays(GL_POINTS, 0, std::numeric_limits<GLsizei>::max());
  EXPECT_EQ(glGetError(), GLenum{GL_OUT_OF_MEMORY});
  glDrawElements(GL_POINTS, std::numeric_limits<GLsizei>::max(), GL_UNSIGNED_INT, kSquare);
  EXPECT_EQ(glGetError(), GLenum{GL_OUT_OF_MEMORY});
  // A null vertex pointer reads (0, 0, 0, 1).
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glDrawArrays(GL_POINTS, 0, 2);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto d = draws();
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].vertices->position.at(1), glm::vec4(0, 0, 0, 1));
}

TEST_F(ArrayDrawTest, DrawsValidateStateAsMesaDoes) {
  // Every draw command analyses the matrices (Mesa's state validation, which decides later
  // arithmetic), even one whose arguments are then rejected, as glBegin does.
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  const GLubyte indices[1] = {0};
  const std::vector<void (*)(const GLubyte*)> draws = {
      [](const GLubyte*) { glDrawArrays(GL_POINTS, 0, 1); },
      [](const GLubyte*) { glDrawArrays(GL_POINTS, 0, -1); },
      [](const GLubyte* i) { glDrawElements(GL_POINTS, 1, GL_UNSIGNED_BYTE, i); },
      [](const GLubyte* i) { glDrawRangeElements(GL_POINTS, 1, 0, 1, GL_UNSIGNED_BYTE, i); },
      [](const GLubyte*) {
        const GLint first[1] = {0};
        const GLsizei count[1] = {1};
        glMultiDrawArrays(GL_POINTS, first, count, 1);
      },
  };
  glMatrixMode(GL_TEXTURE);
  for (auto draw : draws) {
    glRotatef(10, 0, 0, 1);
    ASSERT_TRUE(ctx_.matrices.texture[0].top_matrix().dirty());
    draw(indices);
    EXPECT_FALSE(ctx_.matrices.texture[0].top_matrix().dirty());
  }
  glGetError();
}

TEST_F(ArrayDrawTest, CompileAndExecuteDrawsLikeImmediateModeAndSetsCurrentValues) {
  // Mesa executes a draw compiled with GL_COMPILE_AND_EXECUTE as glBegin, glArrayElement per
  // vertex, glEnd: batched like immediate mode, and the current values follow the last vertex.
  const GLfloat colours[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_FLOAT, 0, colours);
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEndList();
  const auto d = draws();
  ASSERT_EQ(d.size(), 1u);  // two glBegin/glEnd primitives batched
  EXPECT_EQ(d[0].vertices->primitives.size(), 2u);
  GLfloat current[4];
  glGetFloatv(GL_CURRENT_COLOR, current);
  EXPECT_EQ(current[2], 1.0f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

// Mesa assembles draws by how they were specified (rt_core/record/decompose.hpp): each array
// draw says so, and which colours came per vertex from arrays.
TEST_F(ArrayDrawTest, DrawsSayHowTheyWereSpecified) {
  const GLfloat colours[4][3] = {};
  const GLubyte indices[4] = {0, 1, 2, 3};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  glDrawArrays(GL_QUADS, 0, 4);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_FLOAT, 0, colours);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, indices);
  glDisableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glSecondaryColorPointer(3, GL_FLOAT, 0, colours);
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_QUADS, 0, 4);
  glEndList();
  glCallList(1);
  const auto d = draws();
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].vertices->source, glpt::rec::PrimitiveSource::kArrays);
  EXPECT_EQ(d[0].vertices->per_vertex, 0);
  EXPECT_EQ(d[1].vertices->source, glpt::rec::PrimitiveSource::kElements);
  EXPECT_EQ(d[1].vertices->per_vertex, glpt::rec::kPerVertexColor);
  EXPECT_EQ(d[2].vertices->source, glpt::rec::PrimitiveSource::kDisplayList);
  EXPECT_EQ(d[2].vertices->per_vertex, glpt::rec::kPerVertexSecondaryColor);
}

}  // namespace
