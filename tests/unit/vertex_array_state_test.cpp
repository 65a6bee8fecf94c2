// Client vertex array state (GL 1.5 2.8, tables 6.6-6.8): the *Pointer commands, client state
// enables, glInterleavedArrays, glLockArraysEXT and glGetPointerv, with their errors.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "array_test_util.hpp"
#include "gl_shim/dispatch.hpp"

namespace {

// Types GL 1.5 does not have for arrays (GL 3.0's half float, ES's fixed point).
constexpr GLenum kHalfFloat = 0x140B, kFixed = 0x140C;

const void* ptr(uintptr_t address) { return reinterpret_cast<const void*>(address); }

void* pointer_of(GLenum pname) {
  void* p = reinterpret_cast<void*>(uintptr_t{0xdead});
  glGetPointerv(pname, &p);
  return p;
}

TEST_F(GlTest, ArrayStateStartsAsTheSpecSays) {
  // GL 1.5 tables 6.6-6.7: disabled, GL_FLOAT, stride 0, null, the largest size.
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_SIZE), 4);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_STRIDE), 0);
  EXPECT_EQ(get_integer(GL_NORMAL_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_integer(GL_COLOR_ARRAY_SIZE), 4);
  EXPECT_EQ(get_integer(GL_SECONDARY_COLOR_ARRAY_SIZE), 3);
  EXPECT_EQ(get_integer(GL_FOG_COORD_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_integer(GL_INDEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_SIZE), 4);
  EXPECT_EQ(get_integer(GL_EDGE_FLAG_ARRAY_STRIDE), 0);
  for (GLenum cap :
       {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY,
        GL_FOG_COORD_ARRAY, GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY, GL_TEXTURE_COORD_ARRAY})
    EXPECT_FALSE(glIsEnabled(cap)) << cap;
  EXPECT_EQ(pointer_of(GL_VERTEX_ARRAY_POINTER), nullptr);
  EXPECT_EQ(get_integer(GL_MAX_ELEMENTS_VERTICES), 3000);  // Mesa's
  EXPECT_EQ(get_integer(GL_MAX_ELEMENTS_INDICES), 3000);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, PointerCommandsSetTheirArray) {
  glVertexPointer(3, GL_SHORT, 12, ptr(0x100));
  glNormalPointer(GL_BYTE, 4, ptr(0x200));
  glColorPointer(3, GL_UNSIGNED_INT, 16, ptr(0x300));
  glSecondaryColorPointer(3, GL_UNSIGNED_SHORT, 8, ptr(0x400));
  glFogCoordPointer(GL_DOUBLE, 24, ptr(0x500));
  glIndexPointer(GL_UNSIGNED_BYTE, 2, ptr(0x600));
  glEdgeFlagPointer(7, ptr(0x700));
  glTexCoordPointer(1, GL_INT, 0, ptr(0x800));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_STRIDE), 12);
  EXPECT_EQ(get_integer(GL_NORMAL_ARRAY_TYPE), GL_BYTE);
  EXPECT_EQ(get_integer(GL_NORMAL_ARRAY_STRIDE), 4);
  EXPECT_EQ(get_integer(GL_COLOR_ARRAY_SIZE), 3);
  EXPECT_EQ(get_integer(GL_COLOR_ARRAY_TYPE), GL_UNSIGNED_INT);
  EXPECT_EQ(get_integer(GL_SECONDARY_COLOR_ARRAY_TYPE), GL_UNSIGNED_SHORT);
  EXPECT_EQ(get_integer(GL_SECONDARY_COLOR_ARRAY_STRIDE), 8);
  EXPECT_EQ(get_integer(GL_FOG_COORD_ARRAY_TYPE), GL_DOUBLE);
  EXPECT_EQ(get_integer(GL_FOG_COORD_ARRAY_STRIDE), 24);
  EXPECT_EQ(get_integer(GL_INDEX_ARRAY_TYPE), GL_UNSIGNED_BYTE);
  EXPECT_EQ(get_integer(GL_EDGE_FLAG_ARRAY_STRIDE), 7);
  EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_SIZE), 1);
  EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_TYPE), GL_INT);
  EXPECT_EQ(pointer_of(GL_VERTEX_ARRAY_POINTER), ptr(0x100));
  EXPECT_EQ(pointer_of(GL_NORMAL_ARRAY_POINTER), ptr(0x200));
  EXPECT_EQ(pointer_of(GL_COLOR_ARRAY_POINTER), ptr(0x300));
  EXPECT_EQ(pointer_of(GL_SECONDARY_COLOR_ARRAY_POINTER), ptr(0x400));
  EXPECT_EQ(pointer_of(GL_FOG_COORD_ARRAY_POINTER), ptr(0x500));
  EXPECT_EQ(pointer_of(GL_INDEX_ARRAY_POINTER), ptr(0x600));
  EXPECT_EQ(pointer_of(GL_EDGE_FLAG_ARRAY_POINTER), ptr(0x700));
  EXPECT_EQ(pointer_of(GL_TEXTURE_COORD_ARRAY_POINTER), ptr(0x800));
}

// GL 1.5 table 2.4 (and Mesa's secondary colour size 4); errors in Mesa's order: negative stride
// (GL_INVALID_VALUE), type (GL_INVALID_ENUM), size (GL_INVALID_VALUE). A rejected command
// changes nothing.
struct PointerCase {
  const char* what;
  void (*call)(GLint size, GLenum type, GLsizei stride);
  std::array<GLint, 2> sizes;  // smallest and largest accepted
  std::vector<GLenum> types;
  GLenum size_pname;  // 0: the command has no size
  GLenum type_pname;
};

const GLenum kAllTypes[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                            GL_INT,  GL_UNSIGNED_INT,  GL_FLOAT, GL_DOUBLE};

const PointerCase kPointerCases[] = {
    {"vertex",
     [](GLint s, GLenum t, GLsizei st) { glVertexPointer(s, t, st, nullptr); },
     {2, 4},
     {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE},
     GL_VERTEX_ARRAY_SIZE,
     GL_VERTEX_ARRAY_TYPE},
    {"normal",
     [](GLint, GLenum t, GLsizei st) { glNormalPointer(t, st, nullptr); },
     {3, 3},
     {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE},
     0,
     GL_NORMAL_ARRAY_TYPE},
    {"color",
     [](GLint s, GLenum t, GLsizei st) { glColorPointer(s, t, st, nullptr); },
     {3, 4},
     {std::begin(kAllTypes), std::end(kAllTypes)},
     GL_COLOR_ARRAY_SIZE,
     GL_COLOR_ARRAY_TYPE},
    {"secondary color",
     [](GLint s, GLenum t, GLsizei st) { glSecondaryColorPointer(s, t, st, nullptr); },
     {3, 4},
     {std::begin(kAllTypes), std::end(kAllTypes)},
     GL_SECONDARY_COLOR_ARRAY_SIZE,
     GL_SECONDARY_COLOR_ARRAY_TYPE},
    {"fog coord",
     [](GLint, GLenum t, GLsizei st) { glFogCoordPointer(t, st, nullptr); },
     {1, 1},
     {GL_FLOAT, GL_DOUBLE},
     0,
     GL_FOG_COORD_ARRAY_TYPE},
    {"index",
     [](GLint, GLenum t, GLsizei st) { glIndexPointer(t, st, nullptr); },
     {1, 1},
     {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE},
     0,
     GL_INDEX_ARRAY_TYPE},
    {"tex coord",
     [](GLint s, GLenum t, GLsizei st) { glTexCoordPointer(s, t, st, nullptr); },
     {1, 4},
     {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE},
     GL_TEXTURE_COORD_ARRAY_SIZE,
     GL_TEXTURE_COORD_ARRAY_TYPE},
};

TEST_F(GlTest, PointerCommandsAcceptTheSpecsTypesAndSizesOnly) {
  for (const PointerCase& c : kPointerCases) {
    SCOPED_TRACE(c.what);
    for (GLenum type : kAllTypes) {
      const bool legal = std::find(c.types.begin(), c.types.end(), type) != c.types.end();
      c.call(c.sizes[1], type, 0);
      EXPECT_EQ(glGetError(), legal ? GLenum{GL_NO_ERROR} : GLenum{GL_INVALID_ENUM}) << type;
      if (legal) {
        EXPECT_EQ(get_integer(c.type_pname), GLint(type));
      }
    }
    c.call(c.sizes[0], c.types.back(), 0);
    EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
    for (GLenum bad : {kHalfFloat, kFixed, GLenum{GL_BGRA}, GLenum{0}}) {
      c.call(c.sizes[0], bad, 0);
      EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM}) << bad;
    }
    if (c.size_pname != 0) {
      for (GLint size : {c.sizes[0] - 1, c.sizes[1] + 1, GLint{0}, GLint{-1}, GLint{GL_BGRA}}) {
        c.call(size, c.types.back(), 0);
        EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE}) << size;
        EXPECT_EQ(get_integer(c.size_pname), c.sizes[0]);
      }
      // A bad type is reported before a bad size.
      c.call(c.sizes[1] + 1, kHalfFloat, 0);
      EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
    }
    // A negative stride first of all; the array keeps its state.
    c.call(c.sizes[1] + 1, kHalfFloat, -4);
    EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
    EXPECT_EQ(get_integer(c.type_pname), GLint(c.types.back()));
  }
  glEdgeFlagPointer(-1, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  EXPECT_EQ(get_integer(GL_EDGE_FLAG_ARRAY_STRIDE), 0);
}

TEST_F(GlTest, PointerCommandsAreNotAllowedInsideBeginEnd) {
  glBegin(GL_POINTS);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_FALSE(glIsEnabled(GL_VERTEX_ARRAY));
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_SIZE), 4);
}

TEST_F(GlTest, ExtVertexArrayPointersIgnoreTheirCount) {
  glVertexPointerEXT(2, GL_INT, 8, 99, ptr(0x10));
  glNormalPointerEXT(GL_SHORT, 6, 99, ptr(0x20));
  glColorPointerEXT(3, GL_UNSIGNED_BYTE, 4, 99, ptr(0x30));
  glIndexPointerEXT(GL_INT, 4, 99, ptr(0x40));
  glTexCoordPointerEXT(2, GL_DOUBLE, 16, 99, ptr(0x50));
  const GLboolean flags[1] = {GL_TRUE};
  glEdgeFlagPointerEXT(1, 99, flags);
  glSecondaryColorPointerEXT(3, GL_BYTE, 3, ptr(0x60));
  glFogCoordPointerEXT(GL_FLOAT, 4, ptr(0x70));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_TYPE), GL_INT);
  EXPECT_EQ(get_integer(GL_NORMAL_ARRAY_STRIDE), 6);
  EXPECT_EQ(get_integer(GL_COLOR_ARRAY_TYPE), GL_UNSIGNED_BYTE);
  EXPECT_EQ(get_integer(GL_INDEX_ARRAY_TYPE), GL_INT);
  EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_TYPE), GL_DOUBLE);
  EXPECT_EQ(pointer_of(GL_EDGE_FLAG_ARRAY_POINTER), flags);
  EXPECT_EQ(get_integer(GL_SECONDARY_COLOR_ARRAY_TYPE), GL_BYTE);
  EXPECT_EQ(get_integer(GL_FOG_COORD_ARRAY_STRIDE), 4);
  void* p = nullptr;
  glGetPointervEXT(GL_COLOR_ARRAY_POINTER, &p);
  EXPECT_EQ(p, ptr(0x30));
  glVertexPointerEXT(1, GL_INT, 8, 99, ptr(0x10));
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
}

TEST_F(GlTest, ClientStateEnablesEachArray) {
  for (GLenum cap :
       {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY,
        GL_FOG_COORD_ARRAY, GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY, GL_TEXTURE_COORD_ARRAY}) {
    glEnableClientState(cap);
    EXPECT_TRUE(glIsEnabled(cap)) << cap;
    GLboolean b = GL_FALSE;
    glGetBooleanv(cap, &b);
    EXPECT_TRUE(b);
    glDisableClientState(cap);
    EXPECT_FALSE(glIsEnabled(cap)) << cap;
  }
  glEnableClientState(GL_LIGHTING);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glDisableClientState(0x1234);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  // Mesa also takes client arrays through glEnable/glDisable.
  glEnable(GL_NORMAL_ARRAY);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_TRUE(glIsEnabled(GL_NORMAL_ARRAY));
}

TEST_F(GlTest, TextureCoordinateArraysBelongToTheClientActiveUnit) {
  glClientActiveTexture(GL_TEXTURE2);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(3, GL_SHORT, 6, ptr(0x40));
  glClientActiveTexture(GL_TEXTURE0);
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_COORD_ARRAY));
  EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_SIZE), 4);
  EXPECT_EQ(pointer_of(GL_TEXTURE_COORD_ARRAY_POINTER), nullptr);
  glClientActiveTexture(GL_TEXTURE2);
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_COORD_ARRAY));
  EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_SIZE), 3);
  EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_STRIDE), 6);
  EXPECT_EQ(pointer_of(GL_TEXTURE_COORD_ARRAY_POINTER), ptr(0x40));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

// GL 1.5 table 2.5, by hand: enabled arrays, sizes, colour type, offsets and the default stride
// (f = 4 bytes, c = 4 bytes of colour).
struct Interleaved {
  GLenum format;
  GLint tex, color, vertex;
  bool normal;
  GLenum color_type;
  uintptr_t color_offset, normal_offset, vertex_offset;
  GLint stride;
};
const Interleaved kInterleaved[] = {
    {GL_V2F, 0, 0, 2, false, 0, 0, 0, 0, 8},
    {GL_V3F, 0, 0, 3, false, 0, 0, 0, 0, 12},
    {GL_C4UB_V2F, 0, 4, 2, false, GL_UNSIGNED_BYTE, 0, 0, 4, 12},
    {GL_C4UB_V3F, 0, 4, 3, false, GL_UNSIGNED_BYTE, 0, 0, 4, 16},
    {GL_C3F_V3F, 0, 3, 3, false, GL_FLOAT, 0, 0, 12, 24},
    {GL_N3F_V3F, 0, 0, 3, true, 0, 0, 0, 12, 24},
    {GL_C4F_N3F_V3F, 0, 4, 3, true, GL_FLOAT, 0, 16, 28, 40},
    {GL_T2F_V3F, 2, 0, 3, false, 0, 0, 0, 8, 20},
    {GL_T4F_V4F, 4, 0, 4, false, 0, 0, 0, 16, 32},
    {GL_T2F_C4UB_V3F, 2, 4, 3, false, GL_UNSIGNED_BYTE, 8, 0, 12, 24},
    {GL_T2F_C3F_V3F, 2, 3, 3, false, GL_FLOAT, 8, 0, 20, 32},
    {GL_T2F_N3F_V3F, 2, 0, 3, true, 0, 0, 8, 20, 32},
    {GL_T2F_C4F_N3F_V3F, 2, 4, 3, true, GL_FLOAT, 8, 24, 36, 48},
    {GL_T4F_C4F_N3F_V4F, 4, 4, 4, true, GL_FLOAT, 16, 32, 44, 60},
};

TEST_F(GlTest, InterleavedArraysSetUpEveryFormatAsTable25Says) {
  const uintptr_t base = 0x1000;
  for (const Interleaved& f : kInterleaved) {
    SCOPED_TRACE(f.format);
    for (GLsizei stride : {GLsizei{0}, GLsizei{100}}) {
      glEnableClientState(GL_EDGE_FLAG_ARRAY);
      glEnableClientState(GL_INDEX_ARRAY);
      glEnableClientState(GL_COLOR_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glEnableClientState(GL_TEXTURE_COORD_ARRAY);
      glInterleavedArrays(f.format, stride, ptr(base));
      ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
      const GLint want_stride = stride == 0 ? f.stride : stride;
      EXPECT_FALSE(glIsEnabled(GL_EDGE_FLAG_ARRAY));
      EXPECT_FALSE(glIsEnabled(GL_INDEX_ARRAY));
      EXPECT_TRUE(glIsEnabled(GL_VERTEX_ARRAY));
      EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_SIZE), f.vertex);
      EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_TYPE), GL_FLOAT);
      EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_STRIDE), want_stride);
      EXPECT_EQ(pointer_of(GL_VERTEX_ARRAY_POINTER), ptr(base + f.vertex_offset));
      EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), f.tex != 0);
      if (f.tex != 0) {
        EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_SIZE), f.tex);
        EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_STRIDE), want_stride);
        EXPECT_EQ(pointer_of(GL_TEXTURE_COORD_ARRAY_POINTER), ptr(base));
      }
      EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), f.color != 0);
      if (f.color != 0) {
        EXPECT_EQ(get_integer(GL_COLOR_ARRAY_SIZE), f.color);
        EXPECT_EQ(get_integer(GL_COLOR_ARRAY_TYPE), GLint(f.color_type));
        EXPECT_EQ(get_integer(GL_COLOR_ARRAY_STRIDE), want_stride);
        EXPECT_EQ(pointer_of(GL_COLOR_ARRAY_POINTER), ptr(base + f.color_offset));
      }
      EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), f.normal);
      if (f.normal) {
        EXPECT_EQ(get_integer(GL_NORMAL_ARRAY_STRIDE), want_stride);
        EXPECT_EQ(pointer_of(GL_NORMAL_ARRAY_POINTER), ptr(base + f.normal_offset));
      }
    }
  }
}

TEST_F(GlTest, InterleavedArraysLeaveOtherUnitsAndSecondaryArraysAlone) {
  // As in Mesa: the secondary colour and fog coordinate arrays keep their enables, and only the
  // client active unit's texture coordinates are set.
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE0);
  glInterleavedArrays(GL_T2F_V3F, 0, ptr(0x10));
  EXPECT_TRUE(glIsEnabled(GL_SECONDARY_COLOR_ARRAY));
  EXPECT_TRUE(glIsEnabled(GL_FOG_COORD_ARRAY));
  glClientActiveTexture(GL_TEXTURE1);
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_COORD_ARRAY));
  EXPECT_EQ(get_integer(GL_TEXTURE_COORD_ARRAY_STRIDE), 0);
}

TEST_F(GlTest, InterleavedArraysRejectBadArguments) {
  glInterleavedArrays(GL_V2F, -1, ptr(0x10));
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glInterleavedArrays(GL_RGBA, 0, ptr(0x10));
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_FALSE(glIsEnabled(GL_VERTEX_ARRAY));
}

TEST_F(GlTest, LockArraysFollowsMesasRules) {
  glLockArraysEXT(0, 0);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glLockArraysEXT(-1, 3);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glUnlockArraysEXT();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glLockArraysEXT(2, 5);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(get_integer(GL_ARRAY_ELEMENT_LOCK_FIRST_EXT), 2);
  EXPECT_EQ(get_integer(GL_ARRAY_ELEMENT_LOCK_COUNT_EXT), 5);
  glLockArraysEXT(0, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  glUnlockArraysEXT();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(get_integer(GL_ARRAY_ELEMENT_LOCK_COUNT_EXT), 0);
}

TEST_F(GlTest, GetPointervRejectsOtherNamesAndToleratesNull) {
  glGetPointerv(GL_VERTEX_ARRAY_SIZE, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(pointer_of(GL_FEEDBACK_BUFFER_POINTER), nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, ArrayCommandsAreFoundByName) {
  for (const char* name :
       {"glVertexPointer", "glDrawArrays", "glDrawElements", "glDrawRangeElements",
        "glMultiDrawArrays", "glMultiDrawElements", "glArrayElement", "glInterleavedArrays",
        "glLockArraysEXT", "glUnlockArraysEXT", "glGetPointerv", "glVertexPointerEXT",
        "glDrawArraysEXT", "glMultiDrawArraysEXT", "glDrawRangeElementsEXT",
        "glSecondaryColorPointerEXT", "glFogCoordPointerEXT", "glPushClientAttrib", "glPopAttrib"})
    EXPECT_NE(glpt::lookup_gl_proc(name), nullptr) << name;
}

}  // namespace
