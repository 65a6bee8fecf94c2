// Texture objects (GL 1.5 3.8.12): names, binding, deletion, sharing between contexts, residency
// and priorities, and the EXT_texture_object entry points.
#include "gl_shim/dispatch.hpp"
#include "gl_test_context.hpp"

namespace {

TEST_F(GlTest, GeneratedNamesBecomeTexturesWhenFirstBound) {
  GLuint names[3] = {};
  glGenTextures(3, names);
  EXPECT_NE(names[0], 0u);
  EXPECT_NE(names[0], names[1]);
  EXPECT_NE(names[1], names[2]);
  EXPECT_FALSE(glIsTexture(names[0]));  // a name, not yet a texture
  glBindTexture(GL_TEXTURE_2D, names[0]);
  EXPECT_TRUE(glIsTexture(names[0]));
  EXPECT_FALSE(glIsTexture(0));
  GLint bound = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  EXPECT_EQ(GLuint(bound), names[0]);
  // An unused name can be bound without glGenTextures (GL 1.5), and is then taken.
  glBindTexture(GL_TEXTURE_1D, 500);
  EXPECT_TRUE(glIsTexture(500));
  GLuint more[2];
  glGenTextures(2, more);
  EXPECT_NE(more[0], 500u);
  EXPECT_NE(more[1], 500u);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, BindingATextureToAnotherTargetIsInvalidOperation) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glBindTexture(GL_TEXTURE_3D, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  GLint bound = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &bound);
  EXPECT_EQ(bound, 0);
  glBindTexture(GL_TEXTURE_CUBE_MAP_POSITIVE_X, t);  // a face is not a binding target
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glBindTexture(GL_PROXY_TEXTURE_2D, t);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
}

TEST_F(GlTest, DeletingATextureUnbindsItFromEveryUnit) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, t);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, t);
  const GLuint bad[3] = {0, 9999, t};  // 0 and unknown names are ignored
  glDeleteTextures(3, bad);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_FALSE(glIsTexture(t));
  GLint bound = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  EXPECT_EQ(bound, 0);
  glActiveTexture(GL_TEXTURE2);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  EXPECT_EQ(bound, 0);
  glDeleteTextures(-1, bad);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glGenTextures(-1, nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
}

TEST_F(GlTest, TexturesAreSharedWithTheShareGroupButBindingsAreNot) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  const GLubyte texel[4] = {10, 20, 30, 40};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);

  glpt::Context other(&ctx_);  // shares lists and textures
  glpt::Context stranger(nullptr);
  glpt::set_current_context(&other);
  EXPECT_TRUE(glIsTexture(t));
  GLint bound = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  EXPECT_EQ(bound, 0);  // bindings are per context
  glBindTexture(GL_TEXTURE_2D, t);
  GLubyte back[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[2], 30);
  // Deleted in one context, the object lives on where it is still bound (GL 1.5 D.1).
  glpt::set_current_context(&ctx_);
  glDeleteTextures(1, &t);
  glpt::set_current_context(&other);
  EXPECT_FALSE(glIsTexture(t));
  back[2] = 0;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[2], 30);

  glpt::set_current_context(&stranger);
  glBindTexture(GL_TEXTURE_2D, 1);
  GLuint name = 0;
  glGenTextures(1, &name);
  EXPECT_NE(name, 1u);
  glpt::set_current_context(&ctx_);
  EXPECT_FALSE(glIsTexture(1));  // another share group's texture
}

TEST_F(GlTest, AllTexturesAreResidentAndPrioritiesAreClamped) {
  GLuint t[2];
  glGenTextures(2, t);
  glBindTexture(GL_TEXTURE_2D, t[0]);
  GLboolean residences[2] = {7, 7};
  EXPECT_TRUE(glAreTexturesResident(2, t, residences));
  EXPECT_EQ(residences[0], 7);  // left unchanged when all are resident
  const GLuint with_zero[2] = {t[0], 0};
  EXPECT_FALSE(glAreTexturesResident(2, with_zero, residences));
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  const GLuint unknown[1] = {4242};
  EXPECT_FALSE(glAreTexturesResident(1, unknown, residences));
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glAreTexturesResident(-1, t, residences);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});

  const GLfloat priorities[2] = {1.5f, 0.25f};
  glPrioritizeTextures(2, t, priorities);
  GLfloat p = 0;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  EXPECT_FLOAT_EQ(p, 1.0f);
  glBindTexture(GL_TEXTURE_2D, t[1]);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  EXPECT_FLOAT_EQ(p, 0.25f);
  GLint resident = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, &resident);
  EXPECT_EQ(resident, 1);
  glPrioritizeTextures(-1, t, priorities);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
}

TEST_F(GlTest, TextureObjectExtensionNamesRunTheCoreCommands) {
  GLuint t = 0;
  glGenTexturesEXT(1, &t);
  glBindTextureEXT(GL_TEXTURE_2D, t);
  EXPECT_TRUE(glIsTextureEXT(t));
  GLboolean r[1];
  EXPECT_TRUE(glAreTexturesResidentEXT(1, &t, r));
  const GLclampf half = 0.5f;
  glPrioritizeTexturesEXT(1, &t, &half);
  GLfloat p = 0;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  EXPECT_FLOAT_EQ(p, 0.5f);
  glDeleteTexturesEXT(1, &t);
  EXPECT_FALSE(glIsTexture(t));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_NE(glpt::lookup_gl_proc("glGenTexturesEXT"), nullptr);
  EXPECT_NE(glpt::lookup_gl_proc("glTexImage3DEXT"), nullptr);
}

TEST_F(GlTest, ActiveAndClientActiveTextureSelectUnits) {
  glActiveTexture(GL_TEXTURE3);
  glClientActiveTexture(GL_TEXTURE1);
  GLint v = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE3);
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE1);
  glActiveTexture(GL_TEXTURE4);  // glpt has 4 units
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glClientActiveTexture(GL_TEXTURE0 - 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetIntegerv(GL_MAX_TEXTURE_UNITS, &v);
  EXPECT_EQ(v, 4);
  // The texture matrix stack follows the active unit.
  glMatrixMode(GL_TEXTURE);
  glTranslatef(1, 2, 3);
  EXPECT_FLOAT_EQ(ctx_.matrices.texture[3].top()[3][1], 2.0f);
  EXPECT_FLOAT_EQ(ctx_.matrices.texture[0].top()[3][1], 0.0f);
}

TEST_F(GlTest, TextureLimitsAreReported) {
  GLint v = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &v);
  EXPECT_EQ(v, glpt::kMaxTextureSize);
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &v);
  EXPECT_EQ(v, glpt::kMax3DTextureSize);
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &v);
  EXPECT_EQ(v, glpt::kMaxTextureSize);
  GLfloat f = 0;
  glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS, &f);
  EXPECT_FLOAT_EQ(f, 16.0f);  // Mesa's value
  glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &f);
  EXPECT_FLOAT_EQ(f, 16.0f);
  // The S3TC formats Mesa lists for desktop GL (it leaves out DXT1 RGBA), in Mesa's order.
  glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &v);
  EXPECT_EQ(v, 3);
  GLint formats[4] = {};
  glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, formats);
  EXPECT_EQ(formats[0], GL_COMPRESSED_RGB_S3TC_DXT1_EXT);
  EXPECT_EQ(formats[1], GL_COMPRESSED_RGBA_S3TC_DXT3_EXT);
  EXPECT_EQ(formats[2], GL_COMPRESSED_RGBA_S3TC_DXT5_EXT);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

}  // namespace
