// GL_ARB_texture_rectangle: the GL_TEXTURE_RECTANGLE_ARB target, its binding, enable, proxy,
// limits, initial parameters and errors. Expected values are the extension's, and Mesa 25's where
// it leaves room (measured with OSMesa: see the comments).
#include <cstring>
#include <string>
#include <vector>

#include "gl_shim/textures/texture_snapshot.hpp"
#include "gl_test_context.hpp"

namespace {

constexpr GLenum kRect = GL_TEXTURE_RECTANGLE_ARB;

class TexRectTest : public GlTest {
 protected:
  GLint param(GLenum pname) {
    GLint v[4] = {-7, -7, -7, -7};
    glGetTexParameteriv(kRect, pname, v);
    return v[0];
  }
  GLint level_param(GLenum target, GLenum pname) {
    GLint v = -7;
    glGetTexLevelParameteriv(target, 0, pname, &v);
    return v;
  }
  GLint integer(GLenum pname) {
    GLint v = -7;
    glGetIntegerv(pname, &v);
    return v;
  }
  GLenum error() { return glGetError(); }
  // A w x h RGBA rectangle image on the bound rectangle texture.
  void define(GLsizei w, GLsizei h) {
    const std::vector<GLubyte> texels(size_t(w * h * 4), 200);
    glTexImage2D(kRect, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  GLenum snapshot_target() {
    glpt::rec::TexturingState s;
    glpt::snapshot_texturing(ctx_, s);
    return s.units[0].target;
  }
};

TEST_F(TexRectTest, IsAdvertisedUnderMesasThreeNames) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_texture_rectangle "), std::string::npos);
  EXPECT_NE(ext.find("GL_EXT_texture_rectangle "), std::string::npos);
  EXPECT_NE(ext.find("GL_NV_texture_rectangle "), std::string::npos);
}

TEST_F(TexRectTest, EnableIsPerUnitAndQueryable) {
  EXPECT_FALSE(glIsEnabled(kRect));
  glEnable(kRect);
  EXPECT_TRUE(glIsEnabled(kRect));
  GLboolean b = GL_FALSE;
  glGetBooleanv(kRect, &b);
  EXPECT_TRUE(b);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_FALSE(glIsEnabled(kRect));
  glActiveTexture(GL_TEXTURE0);
  glDisable(kRect);
  EXPECT_FALSE(glIsEnabled(kRect));
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(TexRectTest, BindingAndLimitQueries) {
  EXPECT_EQ(integer(GL_TEXTURE_BINDING_RECTANGLE_ARB), 0);
  glBindTexture(kRect, 9);
  EXPECT_EQ(integer(GL_TEXTURE_BINDING_RECTANGLE_ARB), 9);
  EXPECT_EQ(integer(GL_TEXTURE_BINDING_2D), 0);
  // Mesa's limit equals GL_MAX_TEXTURE_SIZE (16384 both on llvmpipe); glpt's 2D limit is 4096.
  EXPECT_EQ(integer(GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB), integer(GL_MAX_TEXTURE_SIZE));
  EXPECT_EQ(integer(GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB), 4096);
  // A rectangle texture is bound to no other target, nor another texture to this one.
  glBindTexture(GL_TEXTURE_2D, 9);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glBindTexture(GL_TEXTURE_2D, 10);
  glBindTexture(kRect, 10);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(integer(GL_TEXTURE_BINDING_RECTANGLE_ARB), 9);
}

TEST_F(TexRectTest, InitialParametersClampToEdgeAndLinear) {
  // Texture 0 of the target, then a generated name once bound (ARB_texture_rectangle 3.8.8).
  for (int pass = 0; pass < 2; ++pass) {
    EXPECT_EQ(param(GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
    EXPECT_EQ(param(GL_TEXTURE_WRAP_T), GL_CLAMP_TO_EDGE);
    EXPECT_EQ(param(GL_TEXTURE_WRAP_R), GL_CLAMP_TO_EDGE);
    EXPECT_EQ(param(GL_TEXTURE_MIN_FILTER), GL_LINEAR);
    EXPECT_EQ(param(GL_TEXTURE_MAG_FILTER), GL_LINEAR);
    EXPECT_EQ(param(GL_TEXTURE_MAX_LEVEL), 1000);  // Mesa leaves it at GL's 1000
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(kRect, t);
  }
  // A 2D texture keeps GL's defaults.
  GLint wrap = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &wrap);
  EXPECT_EQ(wrap, GL_REPEAT);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(TexRectTest, RepeatingWrapModesAndMipmapFiltersAreInvalidEnum) {
  glBindTexture(kRect, 3);
  for (const GLenum pname : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
    for (const GLenum wrap : {GL_REPEAT, GL_MIRRORED_REPEAT}) {
      glTexParameteri(kRect, pname, GLint(wrap));
      EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
      EXPECT_EQ(param(pname), GL_CLAMP_TO_EDGE);
    }
    for (const GLenum wrap : {GL_CLAMP, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_EDGE}) {
      glTexParameteri(kRect, pname, GLint(wrap));
      EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
      EXPECT_EQ(param(pname), GLint(wrap));
    }
  }
  for (const GLenum filter : {GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                              GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR}) {
    glTexParameteri(kRect, GL_TEXTURE_MIN_FILTER, GLint(filter));
    EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  }
  EXPECT_EQ(param(GL_TEXTURE_MIN_FILTER), GL_LINEAR);
  glTexParameteri(kRect, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(param(GL_TEXTURE_MIN_FILTER), GL_NEAREST);
}

TEST_F(TexRectTest, LevelParametersOtherThanZeroAreErrors) {
  // Mesa (measured): base level != 0, negative included, is GL_INVALID_OPERATION; max level != 0
  // is GL_INVALID_VALUE.
  glTexParameteri(kRect, GL_TEXTURE_BASE_LEVEL, 1);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glTexParameteri(kRect, GL_TEXTURE_BASE_LEVEL, -1);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glTexParameteri(kRect, GL_TEXTURE_BASE_LEVEL, 0);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glTexParameteri(kRect, GL_TEXTURE_MAX_LEVEL, 5);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  EXPECT_EQ(param(GL_TEXTURE_MAX_LEVEL), 1000);
  glTexParameteri(kRect, GL_TEXTURE_MAX_LEVEL, 0);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(param(GL_TEXTURE_MAX_LEVEL), 0);
}

TEST_F(TexRectTest, ImageCommandsTakeLevelZeroWithoutBorderOnly) {
  const std::vector<GLubyte> texels(64, 0);
  glTexImage2D(kRect, 1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glTexImage2D(kRect, 0, GL_RGBA, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glCopyTexImage2D(kRect, 0, GL_RGBA, 0, 0, 4, 4, 1);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glCopyTexImage2D(kRect, 1, GL_RGBA, 0, 0, 2, 2, 0);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  define(5, 3);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glTexSubImage2D(kRect, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glCopyTexSubImage2D(kRect, 1, 0, 0, 0, 0, 1, 1);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  GLubyte out[64];
  glGetTexImage(kRect, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  GLint v = 0;
  glGetTexLevelParameteriv(kRect, 1, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  // Rectangle textures are two-dimensional only; proxies are neither read nor parameterized.
  glTexImage1D(kRect, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glTexImage3D(kRect, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glGetTexImage(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glGetTexParameteriv(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, &v);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
}

TEST_F(TexRectTest, ImagesOfAnySizeRoundTrip) {
  glBindTexture(kRect, 4);
  define(5, 3);
  EXPECT_EQ(level_param(kRect, GL_TEXTURE_WIDTH), 5);
  EXPECT_EQ(level_param(kRect, GL_TEXTURE_HEIGHT), 3);
  EXPECT_EQ(level_param(kRect, GL_TEXTURE_BORDER), 0);
  const GLubyte red[2 * 4] = {255, 0, 0, 255, 255, 0, 0, 255};
  glTexSubImage2D(kRect, 0, 3, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glTexSubImage2D(kRect, 0, 4, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);  // past the right edge
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  std::vector<GLubyte> out(5 * 3 * 4, 0);
  glGetTexImage(kRect, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  const size_t last_row = 2 * 5 * 4;
  EXPECT_EQ(out[last_row + 3 * 4 + 0], 255);  // (3, 2) and (4, 2) are red
  EXPECT_EQ(out[last_row + 4 * 4 + 1], 0);
  EXPECT_EQ(out[last_row + 2 * 4 + 0], 200);  // (2, 2) is not
  EXPECT_EQ(out[0], 200);
}

TEST_F(TexRectTest, ProxyAnswersUpToTheLimit) {
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WIDTH), 0);
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 4096, 4096, 0, GL_RGBA, GL_FLOAT,
               nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WIDTH), 4096);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_HEIGHT), 4096);
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 4097, 3, 0, GL_RGBA, GL_FLOAT, nullptr);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});  // a proxy too large is no error
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WIDTH), 0);
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 7, 3, 0, GL_RGBA, GL_FLOAT, nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WIDTH), 7);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_HEIGHT), 3);
  // The proxy does not touch the bound texture.
  EXPECT_EQ(level_param(kRect, GL_TEXTURE_WIDTH), 0);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(TexRectTest, TargetPriorityIsCubeThen3DThenRectangleThen2D) {
  // ARB_texture_rectangle 3.8.15 (Mesa's gl_texture_index order): cube map > 3D > rectangle >
  // 2D > 1D; an incomplete texture is passed over, as Mesa does.
  const std::vector<GLubyte> texel(4 * 6, 255);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glEnable(kRect);
  EXPECT_EQ(snapshot_target(), GLenum{GL_TEXTURE_2D});  // the rectangle texture has no image
  define(3, 2);
  EXPECT_EQ(snapshot_target(), GLenum{kRect});
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel.data());
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_3D);
  EXPECT_EQ(snapshot_target(), GLenum{GL_TEXTURE_3D});
  glDisable(GL_TEXTURE_3D);
  for (int f = 0; f < 6; ++f)
    glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA, 1, 1, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texel.data());
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_CUBE_MAP);
  EXPECT_EQ(snapshot_target(), GLenum{GL_TEXTURE_CUBE_MAP});
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

TEST_F(TexRectTest, TextureAndEnableBitsSaveTheRectangleState) {
  GLuint t[2] = {};
  glGenTextures(2, t);
  glBindTexture(kRect, t[0]);
  glEnable(kRect);
  glPushAttrib(GL_TEXTURE_BIT);
  glDisable(kRect);
  glTexParameteri(kRect, GL_TEXTURE_WRAP_S, GL_CLAMP);
  glBindTexture(kRect, t[1]);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(kRect));
  EXPECT_EQ(integer(GL_TEXTURE_BINDING_RECTANGLE_ARB), GLint(t[0]));
  EXPECT_EQ(param(GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(kRect);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(kRect));
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

}  // namespace
