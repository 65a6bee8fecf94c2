// Texture parameters, environments, coordinate generation, completeness and the snapshot the draw
// recorder takes. Defaults, conversions and error codes are Mesa 25's where GL 1.5 leaves room
// (measured with OSMesa).
#include <vector>

#include "gl_shim/textures/texture_snapshot.hpp"
#include "gl_test_context.hpp"

namespace {

class TexStateTest : public GlTest {
 protected:
  GLint param_i(GLenum pname, GLenum target = GL_TEXTURE_2D) {
    GLint v[4] = {-7, -7, -7, -7};
    glGetTexParameteriv(target, pname, v);
    return v[0];
  }
  GLfloat param_f(GLenum pname, GLenum target = GL_TEXTURE_2D) {
    GLfloat v[4] = {-7, -7, -7, -7};
    glGetTexParameterfv(target, pname, v);
    return v[0];
  }
  GLint env_i(GLenum pname) {
    GLint v[4] = {-7, -7, -7, -7};
    glGetTexEnviv(GL_TEXTURE_ENV, pname, v);
    return v[0];
  }
  glpt::rec::TexturingState snapshot() {
    glpt::rec::TexturingState s;
    glpt::snapshot_texturing(ctx_, s);
    return s;
  }
  // A complete, mipmapped 4x4 RGBA 2D texture (3 levels) bound to unit 0.
  void define_mipmapped_2d() {
    const std::vector<GLubyte> texels(4 * 4 * 4, 128);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
};

// ---- glTexParameter --------------------------------------------------------------------------

TEST_F(TexStateTest, TextureParameterDefaultsAreGls) {
  EXPECT_EQ(param_i(GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  EXPECT_EQ(param_i(GL_TEXTURE_MAG_FILTER), GL_LINEAR);
  EXPECT_EQ(param_i(GL_TEXTURE_WRAP_S), GL_REPEAT);
  EXPECT_EQ(param_i(GL_TEXTURE_WRAP_R), GL_REPEAT);
  EXPECT_EQ(param_i(GL_TEXTURE_PRIORITY), 2147483647);  // 1.0 as a colour
  EXPECT_EQ(param_i(GL_TEXTURE_RESIDENT), 1);
  EXPECT_FLOAT_EQ(param_f(GL_TEXTURE_MIN_LOD), -1000.0f);
  EXPECT_FLOAT_EQ(param_f(GL_TEXTURE_MAX_LOD), 1000.0f);
  EXPECT_EQ(param_i(GL_TEXTURE_BASE_LEVEL), 0);
  EXPECT_EQ(param_i(GL_TEXTURE_MAX_LEVEL), 1000);
  EXPECT_EQ(param_i(GL_DEPTH_TEXTURE_MODE), GL_LUMINANCE);
  EXPECT_EQ(param_i(GL_TEXTURE_COMPARE_MODE), GL_NONE);
  EXPECT_EQ(param_i(GL_TEXTURE_COMPARE_FUNC), GL_LEQUAL);
  EXPECT_EQ(param_i(GL_GENERATE_MIPMAP), 0);
  EXPECT_FLOAT_EQ(param_f(GL_TEXTURE_MAX_ANISOTROPY_EXT), 1.0f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(TexStateTest, TextureParametersRoundTripWithMesasConversions) {
  const GLfloat border[4] = {-0.5f, 0.5f, 1.5f, 0.25f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  GLfloat f[4];
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, f);
  EXPECT_EQ(std::vector<float>(f, f + 4), (std::vector<float>{0.0f, 0.5f, 1.0f, 0.25f}));
  GLint i[4];
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, i);
  EXPECT_EQ(std::vector<int>(i, i + 4), (std::vector<int>{0, 1073741823, 2147483647, 536870911}));
  const GLint iborder[4] = {2147483647, 0, -2147483647, 1073741823};
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, iborder);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, f);
  EXPECT_FLOAT_EQ(f[0], 1.0f);
  EXPECT_FLOAT_EQ(f[1], 1.0f / 4294967295.0f);  // (2c + 1) / (2^32 - 1)
  EXPECT_FLOAT_EQ(f[2], 0.0f);
  EXPECT_FLOAT_EQ(f[3], 0.5f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 1);  // an integer, not a colour
  EXPECT_FLOAT_EQ(param_f(GL_TEXTURE_PRIORITY), 1.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0.5f);
  EXPECT_EQ(param_i(GL_TEXTURE_PRIORITY), 1073741823);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 2.7f);
  EXPECT_EQ(param_i(GL_TEXTURE_MIN_LOD), 3);  // rounded
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, -2.7f);
  EXPECT_EQ(param_i(GL_TEXTURE_LOD_BIAS), -3);
  EXPECT_FLOAT_EQ(param_f(GL_TEXTURE_LOD_BIAS), -2.7f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1.7f);
  EXPECT_EQ(param_i(GL_TEXTURE_BASE_LEVEL), 2);  // rounded
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 100.0f);
  EXPECT_FLOAT_EQ(param_f(GL_TEXTURE_MAX_ANISOTROPY_EXT), 16.0f);  // clamped to the maximum
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 5);
  EXPECT_EQ(param_i(GL_GENERATE_MIPMAP), 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_NEVER);  // GL 1.5 adds all eight
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  EXPECT_EQ(param_i(GL_TEXTURE_WRAP_T), GL_MIRRORED_REPEAT);
  EXPECT_EQ(param_i(GL_TEXTURE_COMPARE_FUNC), GL_NEVER);
  EXPECT_EQ(param_i(GL_DEPTH_TEXTURE_MODE), GL_INTENSITY);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  // Parameters belong to the object bound to the target.
  glBindTexture(GL_TEXTURE_2D, 3);
  EXPECT_EQ(param_i(GL_TEXTURE_WRAP_T), GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
  EXPECT_EQ(param_i(GL_TEXTURE_WRAP_T), GL_MIRRORED_REPEAT);
}

TEST_F(TexStateTest, TextureParameterErrorsMatchMesa) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0.5f);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR + 0.7f);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S,
                  0x8742 /* GL_MIRROR_CLAMP_EXT */);  // not in GL 1.5
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RED);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1);  // vector only
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexParameteri(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  GLint v;
  glGetTexParameteriv(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(param_i(GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);  // untouched
}

// ---- glTexEnv --------------------------------------------------------------------------------

TEST_F(TexStateTest, TextureEnvironmentDefaultsAndRoundTrips) {
  EXPECT_EQ(env_i(GL_TEXTURE_ENV_MODE), GL_MODULATE);
  EXPECT_EQ(env_i(GL_COMBINE_RGB), GL_MODULATE);
  EXPECT_EQ(env_i(GL_SOURCE2_RGB), GL_CONSTANT);
  EXPECT_EQ(env_i(GL_OPERAND2_RGB), GL_SRC_ALPHA);
  EXPECT_EQ(env_i(GL_RGB_SCALE), 1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_ADD_SIGNED);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE3);  // crossbar (GL 1.4)
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, GL_PRIMARY_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_ONE_MINUS_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
  glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 100.0f);  // stored unclamped (Mesa)
  const GLfloat color[4] = {-1.0f, 0.5f, 2.0f, 0.25f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, color);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const glpt::rec::TexEnv& env = ctx_.textures.units[0].env;
  EXPECT_EQ(env.mode, GLenum{GL_COMBINE});
  EXPECT_EQ(env.combine_rgb, GLenum{GL_DOT3_RGBA});
  EXPECT_EQ(env.combine_alpha, GLenum{GL_ADD_SIGNED});
  EXPECT_EQ(env.source_rgb[1], GLenum{GL_TEXTURE3});
  EXPECT_EQ(env.source_alpha[2], GLenum{GL_PRIMARY_COLOR});
  EXPECT_EQ(env.operand_rgb[0], GLenum{GL_ONE_MINUS_SRC_COLOR});
  EXPECT_EQ(env.operand_alpha[1], GLenum{GL_ONE_MINUS_SRC_ALPHA});
  EXPECT_FLOAT_EQ(env.rgb_scale, 2.0f);
  EXPECT_FLOAT_EQ(env.alpha_scale, 4.0f);
  EXPECT_FLOAT_EQ(env.lod_bias, 100.0f);
  GLfloat f[4];
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
  EXPECT_EQ(std::vector<float>(f, f + 4), (std::vector<float>{0.0f, 0.5f, 1.0f, 0.25f}));
  GLint i[4];
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, i);  // Mesa: 0 1073741823 2147483647 ...
  EXPECT_EQ(std::vector<int>(i, i + 4), (std::vector<int>{0, 1073741823, 2147483647, 536870911}));
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, f);
  EXPECT_FLOAT_EQ(f[0], 100.0f);
  EXPECT_EQ(env_i(GL_OPERAND0_RGB), GL_ONE_MINUS_SRC_COLOR);
  // The environment is per unit.
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(env_i(GL_TEXTURE_ENV_MODE), GL_MODULATE);
}

TEST_F(TexStateTest, TextureEnvironmentErrors) {
  glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 3);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0.5f);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE4);  // glpt has 4 units
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_ZERO);  // ATI_texture_env_combine3, not GL 1.5
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE + 1);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexEnvi(0x1234, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexEnvi(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  GLint v;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, &v);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  // Mesa: the scalar form of GL_TEXTURE_ENV_COLOR is no error and sets (param, 0, 0, 0).
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 0.5f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(ctx_.textures.units[0].env.color, glm::vec4(0.5f, 0.0f, 0.0f, 0.0f));
  EXPECT_EQ(ctx_.textures.units[0].env.mode, GLenum{GL_MODULATE});
  // The EXT_texture_env_dot3 functions are accepted for RGB as Mesa does.
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB_EXT);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

// ---- glTexGen --------------------------------------------------------------------------------

TEST_F(TexStateTest, TexGenDefaultsModesAndErrors) {
  GLint mode = 0;
  glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_EYE_LINEAR);
  GLfloat plane[4];
  glGetTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  EXPECT_EQ(std::vector<float>(plane, plane + 4), (std::vector<float>{1, 0, 0, 0}));
  glGetTexGenfv(GL_T, GL_EYE_PLANE, plane);
  EXPECT_EQ(std::vector<float>(plane, plane + 4), (std::vector<float>{0, 1, 0, 0}));
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGend(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glTexGenf(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLdouble d = 0;
  glGetTexGendv(GL_R, GL_TEXTURE_GEN_MODE, &d);
  EXPECT_EQ(d, double(GL_REFLECTION_MAP));
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glTexGeni(GL_S + 4, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  glGetTexGeniv(GL_S, GL_TEXTURE_ENV_MODE, &mode);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(ctx_.textures.units[0].texgen[0].mode, GLenum{GL_SPHERE_MAP});
  EXPECT_EQ(ctx_.textures.units[0].texgen[3].mode, GLenum{GL_OBJECT_LINEAR});
  // Enables live in the unit too.
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_Q);
  EXPECT_EQ(ctx_.textures.units[0].texgen_mask, 0x9);
}

TEST_F(TexStateTest, EyePlanesAreStoredInEyeSpace) {
  // Mesa: with modelview T(1,2,3) S(2), the plane (1,2,3,4) becomes (0.5, 1, 1.5, -3).
  glTranslatef(1, 2, 3);
  glScalef(2, 2, 2);
  const GLfloat p[4] = {1, 2, 3, 4};
  glTexGenfv(GL_S, GL_EYE_PLANE, p);
  GLfloat f[4];
  glGetTexGenfv(GL_S, GL_EYE_PLANE, f);
  EXPECT_FLOAT_EQ(f[0], 0.5f);
  EXPECT_FLOAT_EQ(f[1], 1.0f);
  EXPECT_FLOAT_EQ(f[2], 1.5f);
  EXPECT_FLOAT_EQ(f[3], -3.0f);
  GLint i[4];
  glGetTexGeniv(GL_S, GL_EYE_PLANE, i);  // truncated, as Mesa
  EXPECT_EQ(std::vector<int>(i, i + 4), (std::vector<int>{0, 1, 1, -3}));
  // Object planes are stored as given.
  const GLdouble o[4] = {0.6, -0.6, 1.5, -1.5};
  glTexGendv(GL_T, GL_OBJECT_PLANE, o);
  glGetTexGeniv(GL_T, GL_OBJECT_PLANE, i);
  EXPECT_EQ(std::vector<int>(i, i + 4), (std::vector<int>{0, 0, 1, -1}));
}

// ---- completeness and snapshots -------------------------------------------------------------

TEST_F(TexStateTest, TexturingIsOffUntilATargetIsEnabledWithACompleteTexture) {
  EXPECT_EQ(snapshot().units[0].target, 0u);
  glEnable(GL_TEXTURE_2D);
  EXPECT_EQ(snapshot().units[0].target, 0u);  // texture 0 has no image
  const GLubyte texel[4] = {1, 2, 3, 4};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  // A 1x1 image is a complete mipmap chain by itself.
  glpt::rec::TexturingState s = snapshot();
  EXPECT_EQ(s.units[0].target, GLenum{GL_TEXTURE_2D});
  ASSERT_NE(s.units[0].texture, nullptr);
  EXPECT_EQ(s.units[0].texture->base_format, GLenum{GL_RGBA});
  EXPECT_EQ(s.units[0].texture->texel_format, glpt::rec::TexelFormat::kRgba8);
  EXPECT_EQ(s.units[0].texture->last_level, 0);
  EXPECT_EQ(s.units[1].target, 0u);
}

TEST_F(TexStateTest, MipmapCompletenessFollowsTheFilterAndTheLevels) {
  const std::vector<GLubyte> texels(4 * 4 * 4, 128);
  glEnable(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(snapshot().units[0].target, 0u);  // the default filter needs mipmaps
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  EXPECT_EQ(snapshot().units[0].target, GLenum{GL_TEXTURE_2D});
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(snapshot().units[0].target, 0u);  // level 2 missing
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGB, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(snapshot().units[0].target, 0u);  // another internal format
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glpt::rec::TexturingState s = snapshot();
  EXPECT_EQ(s.units[0].target, GLenum{GL_TEXTURE_2D});
  EXPECT_EQ(s.units[0].texture->last_level, 2);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(snapshot().units[0].target, 0u);  // wrong size
  // GL_TEXTURE_MAX_LEVEL limits the chain GL requires.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  s = snapshot();
  EXPECT_EQ(s.units[0].target, GLenum{GL_TEXTURE_2D});
  EXPECT_EQ(s.units[0].texture->last_level, 0);
  // A base level above the max level is incomplete.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  EXPECT_EQ(snapshot().units[0].target, 0u);
  // Base level 2 (1x1) with max level 1000: complete by itself.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  EXPECT_EQ(snapshot().units[0].target, GLenum{GL_TEXTURE_2D});
}

TEST_F(TexStateTest, CubeMapsMustBeCubeComplete) {
  glEnable(GL_TEXTURE_CUBE_MAP);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  const std::vector<GLubyte> texels(2 * 2 * 4, 50);
  for (int f = 0; f < 5; ++f) {
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels.data());
  }
  EXPECT_EQ(snapshot().units[0].target, 0u);  // -Z missing
  glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGB, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texels.data());
  EXPECT_EQ(snapshot().units[0].target, 0u);  // another format
  glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texels.data());
  const glpt::rec::TexturingState s = snapshot();
  EXPECT_EQ(s.units[0].target, GLenum{GL_TEXTURE_CUBE_MAP});
  ASSERT_EQ(s.units[0].texture->faces.size(), 6u);
  EXPECT_EQ(s.units[0].texture->faces[5][0]->width, 2u);
}

TEST_F(TexStateTest, TheHighestEnabledCompleteTargetWins) {
  const GLubyte texel[4] = {1, 2, 3, 4};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glEnable(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_2D);
  EXPECT_EQ(snapshot().units[0].target, GLenum{GL_TEXTURE_2D});
  // An enabled but incomplete 3D texture is skipped, as Mesa does.
  glEnable(GL_TEXTURE_3D);
  EXPECT_EQ(snapshot().units[0].target, GLenum{GL_TEXTURE_2D});
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(snapshot().units[0].target, GLenum{GL_TEXTURE_3D});
  glDisable(GL_TEXTURE_3D);
  glDisable(GL_TEXTURE_2D);
  EXPECT_EQ(snapshot().units[0].target, GLenum{GL_TEXTURE_1D});
}

TEST_F(TexStateTest, SnapshotCarriesEnvTexgenAndTheTextureMatrix) {
  glActiveTexture(GL_TEXTURE2);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glEnable(GL_TEXTURE_GEN_T);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glMatrixMode(GL_TEXTURE);
  glScalef(2, 3, 4);
  const glpt::rec::TexturingState s = snapshot();
  EXPECT_EQ(s.units[2].env.mode, GLenum{GL_DECAL});
  EXPECT_EQ(s.units[2].texgen_mask, 2);
  EXPECT_EQ(s.units[2].texgen[1].mode, GLenum{GL_OBJECT_LINEAR});
  EXPECT_FLOAT_EQ(s.units[2].matrix[1][1], 3.0f);
  EXPECT_FLOAT_EQ(s.units[0].matrix[1][1], 1.0f);
}

TEST_F(TexStateTest, SnapshotsAreCachedAndCopiedOnWrite) {
  glEnable(GL_TEXTURE_2D);
  define_mipmapped_2d();
  const glpt::rec::TexturingState first = snapshot();
  const auto& tex = first.units[0].texture;
  ASSERT_NE(tex, nullptr);
  // Nothing changed: the same snapshot, not a copy.
  EXPECT_EQ(snapshot().units[0].texture, tex);
  // A parameter change: a new snapshot with the same texel content.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const glpt::rec::TexturingState second = snapshot();
  EXPECT_NE(second.units[0].texture, tex);
  EXPECT_EQ(second.units[0].texture->content_version, tex->content_version);
  EXPECT_EQ(second.units[0].texture->sampler.mag_filter, GLenum{GL_NEAREST});
  EXPECT_EQ(tex->sampler.mag_filter, GLenum{GL_LINEAR});
  // Setting a parameter to the value it has keeps the snapshot.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  EXPECT_EQ(snapshot().units[0].texture, second.units[0].texture);
  // A sub-image: new content, new version, and the old snapshots keep their texels.
  const GLubyte red[4] = {255, 0, 0, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  const glpt::rec::TexturingState third = snapshot();
  EXPECT_GT(third.units[0].texture->content_version, tex->content_version);
  EXPECT_EQ(third.units[0].texture->faces[0][0]->texels[0], 255);
  EXPECT_EQ(tex->faces[0][0]->texels[0], 128);
  EXPECT_EQ(second.units[0].texture->faces[0][0]->texels[0], 128);
  // Untouched levels are shared, not copied.
  EXPECT_EQ(third.units[0].texture->faces[0][1], tex->faces[0][1]);
  // Redefining an image: the old snapshot is unchanged.
  const std::vector<GLubyte> green(16 * 4, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, green.data());
  EXPECT_EQ(third.units[0].texture->faces[0][0]->texels[0], 255);
  // A base level change changes which texels are used: a new version.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  const glpt::rec::TexturingState fourth = snapshot();
  EXPECT_NE(fourth.units[0].texture->content_version, third.units[0].texture->content_version);
}

TEST_F(TexStateTest, ContentVersionsAreUniqueAcrossTextures) {
  glEnable(GL_TEXTURE_2D);
  GLuint t[2];
  glGenTextures(2, t);
  glBindTexture(GL_TEXTURE_2D, t[0]);
  define_mipmapped_2d();
  const uint64_t a = snapshot().units[0].texture->content_version;
  glBindTexture(GL_TEXTURE_2D, t[1]);
  define_mipmapped_2d();  // the same texels, but another texture
  const uint64_t b = snapshot().units[0].texture->content_version;
  EXPECT_NE(a, b);
  glpt::Context other(nullptr);
  glpt::set_current_context(&other);
  glEnable(GL_TEXTURE_2D);
  define_mipmapped_2d();
  glpt::rec::TexturingState s;
  glpt::snapshot_texturing(other, s);
  EXPECT_NE(s.units[0].texture->content_version, a);
  EXPECT_NE(s.units[0].texture->content_version, b);
  glpt::set_current_context(&ctx_);
}

}  // namespace
