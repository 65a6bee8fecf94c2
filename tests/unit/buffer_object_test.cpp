// Buffer objects (GL 1.5 2.9): names, data stores, mapping rules, parameters and their errors as
// GL 1.5 and Mesa have them; arrays and indices sourced from buffers; sharing in a share group.
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "array_test_util.hpp"
#include "gl_shim/dispatch.hpp"

namespace {

GLint buffer_param(GLenum target, GLenum pname) {
  GLint v = -12345;
  glGetBufferParameteriv(target, pname, &v);
  return v;
}

const void* offset(uintptr_t bytes) { return reinterpret_cast<const void*>(bytes); }

TEST_F(GlTest, BufferNamesAreObjectsOnceBound) {
  GLuint b[3] = {};
  glGenBuffers(3, b);
  EXPECT_NE(b[0], 0u);
  EXPECT_NE(b[0], b[1]);
  EXPECT_FALSE(glIsBuffer(b[0]));  // generated only (as in Mesa)
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  EXPECT_TRUE(glIsBuffer(b[0]));
  EXPECT_EQ(get_integer(GL_ARRAY_BUFFER_BINDING), GLint(b[0]));
  // A name glGenBuffers did not return becomes a buffer when bound (compatibility contexts).
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 777);
  EXPECT_TRUE(glIsBuffer(777));
  EXPECT_EQ(get_integer(GL_ELEMENT_ARRAY_BUFFER_BINDING), 777);
  EXPECT_FALSE(glIsBuffer(0));
  GLuint more[2] = {};
  glGenBuffers(2, more);  // never a name in use
  for (GLuint n : more) EXPECT_TRUE(n != b[0] && n != b[1] && n != b[2] && n != 777u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glGenBuffers(-1, b);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glDeleteBuffers(-1, b);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glBindBuffer(GL_TEXTURE_2D, b[0]);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGenBuffers(1, nullptr);
  glDeleteBuffers(1, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, DeletingABufferUnbindsItEverywhereInThisContext) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, 64, nullptr, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 8, offset(8));
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, offset(16));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_BUFFER_BINDING), GLint(b));
  glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
  const GLuint names[2] = {b, 12345};  // an unknown name is ignored
  glDeleteBuffers(2, names);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_FALSE(glIsBuffer(b));
  EXPECT_EQ(get_integer(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(get_integer(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(get_integer(GL_COLOR_ARRAY_BUFFER_BINDING), 0);
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, offset(8));  // the pointer stays (Mesa's too)
  // Drawing from the orphaned offset reads nothing instead of client address 8.
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_POINTS, 0, 3);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto d = recorded_draws(ctx_);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].vertices->position.at(2), glm::vec4(0, 0, 0, 1));
}

TEST_F(GlTest, BufferDataSubDataAndReadBack) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 0);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), GL_STATIC_DRAW);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_READ_WRITE);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  const uint8_t bytes[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  glBufferData(GL_ARRAY_BUFFER, 8, bytes, GL_DYNAMIC_COPY);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 8);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), GL_DYNAMIC_COPY);
  const uint8_t patch[3] = {30, 40, 50};
  glBufferSubData(GL_ARRAY_BUFFER, 2, 3, patch);
  uint8_t out[8] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 8, out);
  EXPECT_EQ(std::vector<uint8_t>(out, out + 8), (std::vector<uint8_t>{1, 2, 30, 40, 50, 6, 7, 8}));
  // Null data: a store of the size, contents undefined (glpt: zeros).
  glBufferData(GL_ARRAY_BUFFER, 4, nullptr, GL_STREAM_DRAW);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, out);
  EXPECT_EQ(out[0], 0);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, BufferDataErrorsInMesasOrder) {
  const uint8_t bytes[4] = {};
  glBufferData(GL_ARRAY_BUFFER, -1, bytes, 0);  // nothing bound comes first
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glBufferData(GL_TEXTURE_2D, 4, bytes, GL_STATIC_DRAW);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, -1, bytes, 0);  // then the size, then the usage
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glBufferData(GL_ARRAY_BUFFER, 4, bytes, GL_STATIC_DRAW + 100);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  // A store too large to allocate (glpt's limit is 2 GiB) is GL_OUT_OF_MEMORY.
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr{1} << 40, nullptr, GL_STATIC_DRAW);
  EXPECT_EQ(glGetError(), GLenum{GL_OUT_OF_MEMORY});
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), 0);
  glBufferData(GL_ARRAY_BUFFER, 4, bytes, GL_STATIC_DRAW);
  glBufferSubData(GL_ARRAY_BUFFER, 2, 4, bytes);  // past the end
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glBufferSubData(GL_ARRAY_BUFFER, -1, 1, bytes);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 5, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glBufferSubData(GL_ARRAY_BUFFER, 4, 0, nullptr);  // empty at the end: fine
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLint value = 0;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &value);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glBufferSubData(GL_ARRAY_BUFFER, 0, 1, bytes);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

TEST_F(GlTest, MappingRules) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  // An empty store cannot be mapped (Mesa: GL_INVALID_OPERATION).
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE), nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  const float data[4] = {1, 2, 3, 4};
  glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY + 7), nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  auto* p = static_cast<float*>(glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY));
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p[2], 3.0f);
  p[2] = 30.0f;
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_TRUE);
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_WRITE_ONLY);
  void* q = nullptr;
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &q);
  EXPECT_EQ(q, p);
  // While mapped: no second map, no sub data in or out.
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glBufferSubData(GL_ARRAY_BUFFER, 0, 4, data);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  float out[4] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, out);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GLboolean{GL_TRUE});
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_READ_WRITE);  // as in Mesa
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &q);
  EXPECT_EQ(q, nullptr);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, sizeof out, out);
  EXPECT_EQ(out[2], 30.0f);  // written through the mapping
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GLboolean{GL_FALSE});
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  // glBufferData on a mapped buffer unmaps it (Mesa).
  glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
  glBufferData(GL_ARRAY_BUFFER, 8, nullptr, GL_STATIC_DRAW);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(buffer_param(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
}

TEST_F(GlTest, DrawsFromMappedBuffersAreInvalidOperations) {
  GLuint b[2] = {};
  glGenBuffers(2, b);
  const float positions[6] = {0, 0, 1, 0, 0, 1};
  const GLushort indices[3] = {0, 1, 2};
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof positions, positions, GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glBegin(GL_POINTS);
  glArrayElement(0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  // A disabled array does not count.
  glDisableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glEnableClientState(GL_VERTEX_ARRAY);
  glUnmapBuffer(GL_ARRAY_BUFFER);
  glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_ONLY);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glDrawArrays(GL_TRIANGLES, 0, 3);  // does not read the element buffer
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(recorded_draws(ctx_).size(), 1u);
}

TEST_F(GlTest, ArraysAndIndicesComeFromBuffers) {
  // Interleaved position (3 floats) and colour (4 ubytes) in one buffer, indices in another.
  struct Vertex {
    float x, y, z;
    uint8_t r, g, b, a;
  };
  const Vertex vertices[4] = {{0, 0, 0, 255, 0, 0, 255},
                              {1, 0, 0, 0, 255, 0, 255},
                              {1, 1, 0, 0, 0, 255, 255},
                              {0, 1, 0, 255, 255, 255, 0}};
  const GLubyte indices[6] = {0, 1, 2, 2, 3, 0};
  GLuint b[2] = {};
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof vertices, vertices, GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(Vertex), offset(0));
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), offset(12));
  glBindBuffer(GL_ARRAY_BUFFER, 0);  // the arrays keep their buffer
  EXPECT_EQ(get_integer(GL_COLOR_ARRAY_BUFFER_BINDING), GLint(b[0]));
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, offset(3));  // the second triangle
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto d = recorded_draws(ctx_);
  ASSERT_EQ(d.size(), 1u);
  const glpt::rec::VertexData& v = *d[0].vertices;
  ASSERT_EQ(v.indices.size(), 3u);
  EXPECT_EQ(v.position[v.indices[1]], glm::vec4(0, 1, 0, 1));
  EXPECT_EQ(at(v.color, v.indices[1]), glm::vec4(1, 1, 1, 0));
  EXPECT_EQ(at(v.color, v.indices[2]), glm::vec4(1, 0, 0, 1));
  // Changing the buffer later does not change what was recorded.
  const Vertex moved = {9, 9, 9, 0, 0, 0, 0};
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof moved, &moved);
  EXPECT_EQ(v.position[v.indices[2]], glm::vec4(0, 0, 0, 1));
}

TEST_F(GlTest, ReadsBeyondABuffersStoreAreZerosOrNothing) {
  const float positions[4] = {1, 2, 3, 4};  // two vertices
  GLuint b[2] = {};
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof positions, positions, GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  const GLuint far[3] = {0, 1, 4000000000u};
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, far);
  glDrawArrays(GL_POINTS, 1, 4);
  // Indices beyond the element buffer: nothing is drawn.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, 4, far, GL_STATIC_DRAW);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, nullptr);
  glDrawElements(GL_TRIANGLES, 1, GL_UNSIGNED_INT, offset(1000));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const auto d = recorded_draws(ctx_);
  ASSERT_EQ(d.size(), 2u);
  const glpt::rec::VertexData& e = *d[0].vertices;
  EXPECT_EQ(e.position[e.indices[1]], glm::vec4(3, 4, 0, 1));
  EXPECT_EQ(e.position[e.indices[2]], glm::vec4(0, 0, 0, 1));
  const glpt::rec::VertexData& a = *d[1].vertices;
  ASSERT_EQ(a.vertex_count(), 4u);
  EXPECT_EQ(a.position[0], glm::vec4(3, 4, 0, 1));
  EXPECT_EQ(a.position[1], glm::vec4(0, 0, 0, 1));
}

TEST_F(GlTest, BuffersAreSharedByTheShareGroup) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  const uint8_t bytes[4] = {1, 2, 3, 4};
  glBufferData(GL_ARRAY_BUFFER, 4, bytes, GL_STATIC_DRAW);
  glpt::Context shared(&ctx_), alone(nullptr);
  glpt::set_current_context(&shared);
  EXPECT_TRUE(glIsBuffer(b));
  EXPECT_EQ(get_integer(GL_ARRAY_BUFFER_BINDING), 0);  // bindings are per context
  glBindBuffer(GL_ARRAY_BUFFER, b);
  uint8_t out[4] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, out);
  EXPECT_EQ(out[3], 4);
  glDeleteBuffers(1, &b);
  glpt::set_current_context(&alone);
  EXPECT_FALSE(glIsBuffer(b));
  glpt::set_current_context(&ctx_);
  // Deleted by the other context: the name is gone, but this context's binding keeps the object
  // (GL 1.5 2.9.1 resets bindings in the deleting context only).
  EXPECT_FALSE(glIsBuffer(b));
  EXPECT_EQ(get_integer(GL_ARRAY_BUFFER_BINDING), GLint(b));
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, out);
  EXPECT_EQ(out[0], 1);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, ArbAliasesAreTheCoreCommands) {
  for (const char* name :
       {"glGenBuffersARB", "glDeleteBuffersARB", "glIsBufferARB", "glBindBufferARB",
        "glBufferDataARB", "glBufferSubDataARB", "glGetBufferSubDataARB", "glMapBufferARB",
        "glUnmapBufferARB", "glGetBufferParameterivARB", "glGetBufferPointervARB", "glMapBuffer",
        "glBufferData"})
    EXPECT_NE(glpt::lookup_gl_proc(name), nullptr) << name;
  GLuint b = 0;
  glGenBuffersARB(1, &b);
  glBindBufferARB(GL_ARRAY_BUFFER, b);
  const float f = 2.5f;
  glBufferDataARB(GL_ARRAY_BUFFER, sizeof f, &f, GL_STATIC_DRAW);
  auto* p = static_cast<float*>(glMapBufferARB(GL_ARRAY_BUFFER, GL_READ_ONLY));
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(*p, 2.5f);
  EXPECT_TRUE(glUnmapBufferARB(GL_ARRAY_BUFFER));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

}  // namespace
