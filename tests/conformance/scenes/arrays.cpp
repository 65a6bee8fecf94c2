// Vertex arrays and buffer objects beyond the misc_ scenes: glDrawElements with each index
// type, glMultiDrawArrays/glMultiDrawElements, arrays and indices sourced from buffer objects
// (written by glBufferData, glBufferSubData and through glMapBuffer), array draws compiled into
// a display list, and the normalized component types (Mesa converts them in its vertex fetch).
// Mesa splits quads differently depending on the command that specified them
// (arrays_quads_by_command); the other scenes use triangles, strips, fans and lines.
#include <cmath>
#include <cstring>
#include <vector>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// A ring of n vertices around (cx, cy): positions (2 floats) and colours (4 ubytes).
struct Ring {
  std::vector<GLfloat> positions;
  std::vector<GLubyte> colours;
};

Ring ring(int n, float cx, float cy, float r) {
  Ring out;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;
    out.positions.push_back(static_cast<float>(cx + r * std::cos(a)));
    out.positions.push_back(static_cast<float>(cy + r * std::sin(a)));
    out.colours.insert(out.colours.end(), {static_cast<GLubyte>(128 + 127 * std::cos(a)),
                                           static_cast<GLubyte>(128 + 127 * std::sin(a)),
                                           static_cast<GLubyte>(i * 255 / n), 255});
  }
  return out;
}

void use_ring(const Ring& r) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, r.positions.data());
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, r.colours.data());
}

// glDrawElements with GL_UNSIGNED_BYTE, _SHORT and _INT indices into one ring of 12 vertices:
// a fan (bottom left), a strip (bottom right) and a triangle list (top), smooth-shaded.
GLPT_SCENE(arrays_draw_elements_index_types, 64, 64) {
  clear(0.1f, 0.1f, 0.15f);
  ortho_pixels(64, 64);
  const Ring r = ring(12, 16, 16, 14);
  use_ring(r);
  const GLubyte fan[8] = {0, 1, 3, 5, 6, 8, 10, 11};
  glDrawElements(GL_TRIANGLE_FAN, 8, GL_UNSIGNED_BYTE, fan);
  glTranslatef(32, 0, 0);
  const GLushort strip[8] = {0, 1, 11, 2, 10, 3, 9, 4};
  glDrawElements(GL_TRIANGLE_STRIP, 8, GL_UNSIGNED_SHORT, strip);
  glTranslatef(-16, 32, 0);
  const GLuint triangles[9] = {0, 4, 8, 1, 5, 9, 2, 6, 10};
  glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_INT, triangles);
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(1, 1, 1);
  glDrawElements(GL_LINE_LOOP, 8, GL_UNSIGNED_BYTE, fan);
}

// glMultiDrawArrays (three strips of one array, one empty) and glMultiDrawElements (two line
// strips), both with a colour array.
GLPT_SCENE(arrays_multi_draw, 64, 64) {
  clear(0.15f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  std::vector<GLfloat> positions;
  std::vector<GLfloat> colours;
  for (int strip = 0; strip < 3; ++strip) {
    for (int i = 0; i < 8; ++i) {
      positions.push_back(4.0f + 8.0f * static_cast<float>(i));
      positions.push_back(4.0f + 18.0f * static_cast<float>(strip) + (i % 2 == 0 ? 0.0f : 12.0f));
      colours.insert(colours.end(), {i / 7.0f, strip / 2.0f, 1.0f - i / 7.0f});
    }
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions.data());
  glColorPointer(3, GL_FLOAT, 0, colours.data());
  const GLint first[4] = {0, 8, 16, 3};
  const GLsizei count[4] = {8, 6, 7, 0};
  glMultiDrawArrays(GL_TRIANGLE_STRIP, first, count, 4);
  glTranslatef(0.5f, 8.5f, 0);
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(1, 1, 0.3f);
  const GLushort top[4] = {0, 3, 4, 7};
  const GLushort middle[3] = {8, 12, 15};
  const void* lists[2] = {top, middle};
  const GLsizei list_counts[2] = {4, 3};
  glMultiDrawElements(GL_LINE_STRIP, list_counts, GL_UNSIGNED_SHORT, lists, 2);
}

// Positions and colours interleaved in one buffer object, indices in another; part of the data
// replaced by glBufferSubData, part written through glMapBuffer; glDrawRangeElements from an
// offset into the element buffer; the client-side pointers are garbage offsets that must not be
// read once the buffers are unbound... they are not used: the arrays keep their buffer.
GLPT_SCENE(arrays_buffer_objects, 64, 64) {
  clear(0.1f, 0.15f, 0.1f);
  ortho_pixels(64, 64);
  struct Vertex {
    GLfloat x, y;
    GLubyte r, g, b, a;
  };
  std::vector<Vertex> vertices;
  for (int row = 0; row < 5; ++row) {
    for (int col = 0; col < 5; ++col) {
      vertices.push_back({6.0f + 13.0f * static_cast<float>(col),
                          6.0f + 13.0f * static_cast<float>(row), static_cast<GLubyte>(col * 60),
                          static_cast<GLubyte>(row * 60), static_cast<GLubyte>(255 - col * 50),
                          255});
    }
  }
  std::vector<GLushort> indices;
  for (int row = 0; row + 1 < 5; ++row) {
    for (int col = 0; col + 1 < 5; ++col) {
      const GLushort i = static_cast<GLushort>(row * 5 + col);
      indices.insert(indices.end(),
                     {i, static_cast<GLushort>(i + 1), static_cast<GLushort>(i + 6), i,
                      static_cast<GLushort>(i + 6), static_cast<GLushort>(i + 5)});
    }
  }
  GLuint buffers[2];
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
  // The middle vertex moves up and turns white.
  const Vertex centre = {32, 38, 255, 255, 255, 255};
  glBufferSubData(GL_ARRAY_BUFFER, 12 * sizeof(Vertex), sizeof centre, &centre);
  // The top-right vertex turns red through a mapping.
  auto* mapped = static_cast<Vertex*>(glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY));
  if (mapped != nullptr) {
    mapped[24].r = 255;
    mapped[24].g = mapped[24].b = 0;
  }
  glUnmapBuffer(GL_ARRAY_BUFFER);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLushort)),
               indices.data(), GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, sizeof(Vertex), nullptr);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), reinterpret_cast<const void*>(8));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  // All but the first row of cells: 12 cells from index 24 on.
  glDrawRangeElements(GL_TRIANGLES, 5, 24, 72, GL_UNSIGNED_SHORT,
                      reinterpret_cast<const void*>(24 * sizeof(GLushort)));
  // The first row as points, from the same vertex buffer without indices.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glPointSize(3);
  glDrawArrays(GL_POINTS, 0, 5);
  glDeleteBuffers(2, buffers);
}

// glDrawArrays and glDrawElements compiled into a display list: the list is called three times
// after the client arrays were overwritten and partly disabled, under different modelviews.
GLPT_SCENE(arrays_draw_arrays_display_list, 64, 64) {
  clear(0.12f, 0.12f, 0.12f);
  ortho_pixels(64, 64);
  Ring r = ring(10, 0, 0, 9);
  use_ring(r);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawArrays(GL_POLYGON, 0, 10);
  const GLubyte star[5] = {0, 4, 8, 2, 6};
  glDrawElements(GL_LINE_LOOP, 5, GL_UNSIGNED_BYTE, star);
  glEndList();
  // None of this changes the list.
  std::memset(r.positions.data(), 0, r.positions.size() * sizeof(GLfloat));
  std::memset(r.colours.data(), 255, r.colours.size());
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(0, 0, 0);
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(12.0f + 20.0f * static_cast<float>(i), 14.0f + 16.0f * static_cast<float>(i), 0);
    glRotatef(25.0f * static_cast<float>(i), 0, 0, 1);
    glCallList(list);
    glPopMatrix();
  }
  glDeleteLists(list, 1);
}

// Colours of every normalized integer type through glDrawArrays: Mesa converts them in its vertex
// fetch (signed components c / (2^(b-1) - 1), not GL 1.5's (2c + 1) / (2^b - 1)). Each type's
// strip is drawn six times, blended additively, so that a conversion off by a fraction of a
// colour step adds up to several steps; the components are small ramps, flat-shaded (no
// interpolation, so no rounding ties). The last strip has byte normals, lit and smooth.
GLPT_SCENE(arrays_normalized_types, 64, 64) {
  clear(0, 0, 0);
  ortho_pixels(64, 64);
  const GLenum types[6] = {GL_BYTE,           GL_UNSIGNED_BYTE, GL_SHORT,
                           GL_UNSIGNED_SHORT, GL_INT,           GL_UNSIGNED_INT};
  // Bits of each type's positive range below its top bit.
  const int magnitude_bits[6] = {7, 8, 15, 16, 31, 32};
  std::vector<GLfloat> positions;
  for (int i = 0; i < 16; ++i) {
    positions.push_back(2.0f + 4.0f * static_cast<float>(i / 2));
    positions.push_back(i % 2 == 0 ? 0.0f : 8.0f);
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions.data());
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glShadeModel(GL_FLAT);
  for (int t = 0; t < 6; ++t) {
    // Component c of vertex i: a ramp up to 1/16 of the range (about 16/255), different per
    // channel.
    std::vector<uint8_t> colours;
    const size_t size = magnitude_bits[t] <= 8 ? 1 : magnitude_bits[t] <= 16 ? 2 : 4;
    for (int i = 0; i < 16; ++i) {
      for (int c = 0; c < 3; ++c) {
        const double f = ((i * 5 + c * 7) % 16) / 256.0;
        const uint64_t v =
            static_cast<uint64_t>(f * static_cast<double>((uint64_t{1} << magnitude_bits[t]) - 1));
        uint8_t bytes[8];
        std::memcpy(bytes, &v, 8);  // little-endian: the low `size` bytes
        colours.insert(colours.end(), bytes, bytes + size);
      }
    }
    glColorPointer(3, types[t], 0, colours.data());
    glPushMatrix();
    glTranslatef(0, 2.0f + 10.0f * static_cast<float>(t), 0);
    for (int pass = 0; pass < 6; ++pass) glDrawArrays(GL_TRIANGLE_STRIP, 0, 16);
    glPopMatrix();
  }
  glDisable(GL_BLEND);
  glShadeModel(GL_SMOOTH);
  glDisableClientState(GL_COLOR_ARRAY);
  // Byte normals, lit (each vertex's normal tilts a little further).
  std::vector<GLbyte> normals;
  for (int i = 0; i < 16; ++i)
    normals.insert(normals.end(), {static_cast<GLbyte>(-60 + 8 * i), static_cast<GLbyte>(30),
                                   static_cast<GLbyte>(100)});
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_BYTE, 0, normals.data());
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.9f, 0.8f, 0.3f);
  glTranslatef(0, 56, 0);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 16);
}

// Smooth quads with four different corner colours: the diagonal Mesa splits them along depends
// on how they were specified (glDrawArrays: 0-2, glDrawElements and display lists: 1-3). Left
// column glDrawArrays, middle glDrawElements, right a compiled glDrawArrays; the top row has the
// colours rotated by one corner.
GLPT_SCENE(arrays_quads_by_command, 96, 64) {
  clear(0, 0, 0);
  ortho_pixels(96, 64);
  const GLfloat positions[8] = {2, 2, 30, 6, 28, 30, 4, 26};
  const GLubyte colours[20] = {255, 0,   0,   255, 0,   255, 0,   255, 0, 0,
                               255, 255, 255, 255, 255, 255, 255, 0,   0, 255};
  const GLubyte indices[4] = {0, 1, 2, 3};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  for (int row = 0; row < 2; ++row) {
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colours + 4 * row);
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glDrawArrays(GL_QUADS, 0, 4);
    glEndList();
    glPushMatrix();
    glTranslatef(0, 32.0f * static_cast<float>(row), 0);
    glDrawArrays(GL_QUADS, 0, 4);
    glTranslatef(32, 0, 0);
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, indices);
    glTranslatef(32, 0, 0);
    glCallList(list);
    glPopMatrix();
    glDeleteLists(list, 1);
  }
}

}  // namespace
