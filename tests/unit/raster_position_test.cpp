// glRasterPos / glWindowPos (GL 1.5 2.13) and the raster position queries. Expected values are
// what Mesa 25.0.7 (OSMesa) reports for the same calls (printed with %.9g), or derived by hand
// where the comment says so.
#include <gtest/gtest.h>

#include "gl_test_context.hpp"

namespace {

struct Raster {
  GLboolean valid = 0;
  float position[4] = {}, color[4] = {}, secondary[4] = {}, tex[4] = {}, distance = 0;
};

Raster query() {
  Raster r;
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &r.valid);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, r.position);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, r.color);
  glGetFloatv(0x845F /* GL_CURRENT_RASTER_SECONDARY_COLOR */, r.secondary);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, r.tex);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &r.distance);
  return r;
}

void expect4(const float* got, float a, float b, float c, float d, float tolerance = 2e-6f) {
  EXPECT_NEAR(got[0], a, tolerance);
  EXPECT_NEAR(got[1], b, tolerance);
  EXPECT_NEAR(got[2], c, tolerance);
  EXPECT_NEAR(got[3], d, tolerance);
}

class RasterPositionTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glViewport(0, 0, 64, 64);
  }
};

TEST_F(RasterPositionTest, InitialState) {
  const Raster r = query();
  EXPECT_TRUE(r.valid);
  expect4(r.position, 0, 0, 0, 1);
  expect4(r.color, 1, 1, 1, 1);
  expect4(r.secondary, 0, 0, 0, 1);
  expect4(r.tex, 0, 0, 0, 1);
  EXPECT_EQ(r.distance, 0.0f);
  GLint index = 0;
  glGetIntegerv(GL_CURRENT_RASTER_INDEX, &index);
  EXPECT_EQ(index, 1);
  GLint color[4];
  glGetIntegerv(GL_CURRENT_RASTER_COLOR, color);
  EXPECT_EQ(color[0], 2147483647);
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

TEST_F(RasterPositionTest, UnlitKeepsCurrentValuesUnclamped) {
  glColor4f(2.0f, -0.5f, 0.25f, 1.5f);
  ctx_.current.secondary_color = glm::vec4(0.5f, 2.0f, -1.0f, 1.0f);  // glSecondaryColor3f
  glTexCoord4f(1, 2, 3, 4);
  glRasterPos2f(0.5f, 0.25f);
  const Raster r = query();
  EXPECT_TRUE(r.valid);
  // By hand: (0.5 * 32 + 32, 0.25 * 32 + 32), z = 0 -> 0.5, w = 1.
  expect4(r.position, 48, 40, 0.5f, 1);
  expect4(r.color, 2, -0.5f, 0.25f, 1.5f);
  expect4(r.secondary, 0.5f, 2, -1, 1);
  expect4(r.tex, 1, 2, 3, 4);
  EXPECT_NEAR(r.distance, 0.559017003f, 1e-7f);  // |(0.5, 0.25, 0)|
}

TEST_F(RasterPositionTest, WindowPosUsesDepthRangeAndClampsColours) {
  glColor4f(2.0f, -0.5f, 0.25f, 1.5f);
  ctx_.current.secondary_color = glm::vec4(0.5f, 2.0f, -1.0f, 1.0f);  // glSecondaryColor3f
  glWindowPos2f(3.5f, 7.25f);
  Raster r = query();
  EXPECT_TRUE(r.valid);
  expect4(r.position, 3.5f, 7.25f, 0, 1);
  expect4(r.color, 1, 0, 0.25f, 1);
  expect4(r.secondary, 0.5f, 1, 0, 1);
  EXPECT_EQ(r.distance, 0.0f);
  glDepthRange(0.2, 0.6);
  glWindowPos3f(3, 4, 0.5f);
  r = query();
  expect4(r.position, 3, 4, 0.400000036f, 1, 0);  // Mesa, bit for bit
  glWindowPos3f(3, 4, 2.0f);                      // z clamped to 1 first
  r = query();
  expect4(r.position, 3, 4, 0.600000024f, 1, 0);
}

TEST_F(RasterPositionTest, OutsideTheViewVolumeIsInvalidAndKeepsTheRest) {
  glWindowPos3f(3, 4, 1.0f);
  glRasterPos3f(2.0f, 0, 0);  // x > w
  Raster r = query();
  EXPECT_FALSE(r.valid);
  expect4(r.position, 3, 4, 1, 1);  // Mesa leaves the previous position
  glRasterPos3f(0, 0, -1.5f);       // behind the near plane
  EXPECT_FALSE(query().valid);
  glRasterPos2f(0, 0);
  EXPECT_TRUE(query().valid);
}

TEST_F(RasterPositionTest, HomogeneousAndPerspective) {
  glRasterPos4f(0.5f, 0.5f, 0.5f, 2.0f);
  Raster r = query();
  expect4(r.position, 40, 40, 0.625f, 2);  // by hand: ndc (0.25, 0.25, 0.25)
  EXPECT_NEAR(r.distance, 0.866025388f, 1e-7f);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos3f(0.3f, 0.2f, -3.0f);
  r = query();
  EXPECT_TRUE(r.valid);
  expect4(r.position, 35.2000008f, 34.1333351f, 0.740740716f, 3, 4e-6f);
  EXPECT_NEAR(r.distance, 3.02158904f, 1e-6f);
}

TEST_F(RasterPositionTest, UserClipPlanes) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  ctx_.transform.clip_planes[0] = glm::vec4(1, 0, 0, 0);  // eye space: keep x >= 0
  ctx_.transform.clip_plane_mask = 1;
  glRasterPos3f(-0.3f, 0.2f, -3.0f);
  EXPECT_FALSE(query().valid);
  glRasterPos3f(0.0f, 0.2f, -3.0f);
  const Raster r = query();
  EXPECT_TRUE(r.valid);
  expect4(r.position, 32, 34.1333351f, 0.740740716f, 3, 4e-6f);
}

TEST_F(RasterPositionTest, FogCoordinateSourceGivesTheDistance) {
  ctx_.raster.fog.coord_source = GL_FOG_COORDINATE;
  ctx_.current.fog_coord = 3.5f;  // glFogCoordf
  glRasterPos3f(0.3f, 0.2f, 0.0f);
  EXPECT_EQ(query().distance, 3.5f);
  glWindowPos2f(1, 1);
  EXPECT_EQ(query().distance, 3.5f);
}

TEST_F(RasterPositionTest, LitByTheDefaultLight) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glRasterPos3f(0.2f, 0.3f, 0.0f);
  // By hand: 0.2 * 0.2 (scene ambient x material ambient) + 1 * 0.8 (diffuse), alpha 1.
  expect4(query().color, 0.84f, 0.84f, 0.84f, 1);
}

// Mesa lights the raster position with the object-space vertex even when lighting runs in eye
// space (positional light under a translation): the colour differs from a vertex's.
class LitRasterPositionTest : public RasterPositionTest {
 protected:
  void SetUp() override {
    RasterPositionTest::SetUp();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    const float position[4] = {2, 3, 1, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glTranslatef(0.5f, -0.25f, -5.0f);
    glNormal3f(0.2f, 0.4f, 0.9f);
  }
};

TEST_F(LitRasterPositionTest, PositionalLight) {
  glRasterPos3f(0.3f, 0.1f, 0.5f);
  const Raster r = query();
  expect4(r.position, 37.6888885f, 30.9333324f, 0.818713427f, 4.5f, 4e-6f);
  expect4(r.color, 0.499022096f, 0.499022096f, 0.499022096f, 1);
  EXPECT_NEAR(r.distance, 4.57301855f, 1e-6f);
}

TEST_F(LitRasterPositionTest, SpotAndAttenuation) {
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60.0f);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 3.0f);
  const float direction[3] = {0, -0.5f, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1f);
  glRasterPos3f(0.3f, 0.1f, 0.5f);
  expect4(query().color, 0.0863065422f, 0.0863065422f, 0.0863065422f, 1);
}

TEST_F(LitRasterPositionTest, SeparateSpecularAndLocalViewerWithColorMaterial) {
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60.0f);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 3.0f);
  const float direction[3] = {0, -0.5f, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1f);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  const float specular[4] = {0.9f, 0.8f, 0.7f, 1};
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 10.0f);
  glEnable(GL_LIGHT1);
  const float white[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT1, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT1, GL_SPECULAR, white);
  const float direction1[4] = {-0.3f, 0.5f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT1, GL_POSITION, direction1);
  glRasterPos3f(0.3f, 0.1f, 0.5f);
  Raster r = query();
  expect4(r.color, 0.805045009f, 0.805045009f, 0.805045009f, 1);
  expect4(r.secondary, 0.511573136f, 0.454731703f, 0.39789024f, 1);

  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  glColor4f(0.1f, 0.6f, 0.3f, 0.7f);
  const float ambient[4] = {0.3f, 0.2f, 0.1f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glRasterPos3f(0.3f, 0.1f, 0.5f);
  r = query();
  expect4(r.color, 0.125630632f, 0.69378382f, 0.316891909f, 0.699999988f);
  expect4(r.secondary, 0, 0, 0, 1);
}

TEST_F(LitRasterPositionTest, DirectionalLightUnderScaleAndRotation) {
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  glColor4f(0.1f, 0.6f, 0.3f, 0.7f);
  glDisable(GL_COLOR_MATERIAL);
  const float ambient[4] = {0.3f, 0.2f, 0.1f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glDisable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  const float white[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT1, GL_DIFFUSE, white);
  const float direction1[4] = {-0.3f, 0.5f, 1.0f, 0.0f};
  glLoadIdentity();
  glLightfv(GL_LIGHT1, GL_POSITION, direction1);
  glTranslatef(0, 0, -5);
  glScalef(2, 2, 2);  // not length preserving: Mesa lights in eye space
  glRasterPos3f(0.3f, 0.1f, 0.5f);
  expect4(query().color, 0.0749211609f, 0.389526963f, 0.16476348f, 0.699999988f);
  glLoadIdentity();
  glTranslatef(0, 0, -5);
  glRotatef(30, 1, 2, 3);  // length preserving: Mesa lights in object space
  glRasterPos3f(0.3f, 0.1f, 0.5f);
  const Raster r = query();
  expect4(r.position, 34.6045952f, 33.2469826f, 0.822617769f, 4.57638502f, 2e-5f);
  expect4(r.color, 0.115313619f, 0.631881714f, 0.285940856f, 0.699999988f, 4e-6f);
}

TEST_F(RasterPositionTest, TexGenAndTextureMatrix) {
  ctx_.textures.units[0].texgen_mask = 1;  // S: object linear
  ctx_.textures.units[0].texgen[0].mode = GL_OBJECT_LINEAR;
  ctx_.textures.units[0].texgen[0].object_plane = glm::vec4(1, 2, 0, 0.5f);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.25f, 0.5f, 0);
  glScalef(2, 1, 1);
  glMatrixMode(GL_MODELVIEW);
  glTexCoord4f(9, 8, 7, 1);
  glRasterPos3f(0.3f, 0.1f, 0.5f);
  // By hand: s = 0.3 + 0.2 + 0.5 = 1, then 2 * 1 + 0.25; t = 8 + 0.5.
  expect4(query().tex, 2.25f, 8.5f, 7, 1);
  ctx_.textures.units[0].texgen_mask = 3;  // T: eye linear (identity modelview)
  ctx_.textures.units[0].texgen[1].mode = GL_EYE_LINEAR;
  ctx_.textures.units[0].texgen[1].eye_plane = glm::vec4(0.1f, 0.2f, 0.3f, 0.4f);
  glRasterPos3f(0.3f, 0.1f, 0.5f);
  expect4(query().tex, 2.25f, 1.0999999f, 7, 1);  // by hand: .03 + .02 + .15 + .4 + .5
}

TEST_F(RasterPositionTest, BitmapMovesOnlyAValidPosition) {
  glRasterPos2f(0, 0);
  glBitmap(0, 0, 0, 0, 5.5f, 6.25f, nullptr);
  Raster r = query();
  expect4(r.position, 37.5f, 38.25f, 0.5f, 1);
  glBitmap(0, 0, 0, 0, 100, 100, nullptr);  // off-screen: still valid
  r = query();
  EXPECT_TRUE(r.valid);
  expect4(r.position, 137.5f, 138.25f, 0.5f, 1);
  glRasterPos3f(2.0f, 0, 0);
  glBitmap(0, 0, 0, 0, 5, 5, nullptr);
  r = query();
  EXPECT_FALSE(r.valid);
  expect4(r.position, 137.5f, 138.25f, 0.5f, 1);
  glBitmap(-1, 0, 0, 0, 0, 0, nullptr);
  EXPECT_EQ(glGetError(), GL_INVALID_VALUE);
}

TEST_F(RasterPositionTest, NullVectorsAreIgnoredAndVariantsConvert) {
  glRasterPos2i(1, 1);  // on the view volume's edge: still valid
  glRasterPos3fv(nullptr);
  glWindowPos2iv(nullptr);
  expect4(query().position, 64, 64, 0.5f, 1);
  const GLshort s[4] = {0, 0, 0, 2};
  glRasterPos4sv(s);
  expect4(query().position, 32, 32, 0.5f, 2);
  const GLdouble d[3] = {10, 20, 0.25};
  glWindowPos3dv(d);
  expect4(query().position, 10, 20, 0.25f, 1);
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

TEST_F(RasterPositionTest, NotAllowedBetweenBeginAndEnd) {
  glBegin(GL_POINTS);
  glRasterPos2f(0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GL_INVALID_OPERATION);
}

}  // namespace
