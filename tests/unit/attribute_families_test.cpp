#include <variant>
// The current attributes beyond colour, normal and texture coordinates (secondary colour, fog
// coordinate, edge flag, colour index), the integer conversions shared with glColor/glNormal
// (Mesa's rounding: expected values read from OSMesa, Mesa 25.0.7), and glRect.
#include <vector>

#include "gl_test_context.hpp"

namespace {

std::vector<float> floats(GLenum pname, int n) {
  std::vector<float> v(4, -777.0f);
  glGetFloatv(pname, v.data());
  v.resize(static_cast<size_t>(n));
  return v;
}

using V = std::vector<float>;

TEST_F(GlTest, SecondaryColourVariantsConvertAsMesaAndKeepAlphaOne) {
  glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
  glSecondaryColor3f(0.5f, 0.6f, 0.7f);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 4), (V{0.5f, 0.6f, 0.7f, 1.0f}));
  EXPECT_EQ(ctx_.current.secondary_color, glm::vec4(0.5f, 0.6f, 0.7f, 1.0f));
  EXPECT_EQ(floats(GL_CURRENT_COLOR, 4), (V{0.1f, 0.2f, 0.3f, 0.4f}));  // untouched
  glSecondaryColor3b(-128, 127, 5);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 4), (V{-1.0f, 1.0f, 0x1.616162p-5f, 1.0f}));
  glSecondaryColor3s(-32768, 32767, 1234);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 3), (V{-1.0f, 1.0f, 0x1.34a134p-5f}));
  glSecondaryColor3i(-2147483647 - 1, 2147483647, 16777217);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 3), (V{-1.0f, 1.0f, 0x1p-7f}));
  glSecondaryColor3ub(255, 0, 51);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 3), (V{1.0f, 0.0f, 0x1.99999ap-3f}));
  glSecondaryColor3us(65535, 0, 4660);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 3), (V{1.0f, 0.0f, 0x1.234124p-4f}));
  glSecondaryColor3ui(4294967295u, 0, 16777217);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 3), (V{1.0f, 0.0f, 0x1.000002p-8f}));
  const GLshort sv[3] = {-2, 3, 100};
  glSecondaryColor3sv(sv);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 3),
            (V{-0x1.80018p-15f, 0x1.c001cp-14f, 0x1.920192p-9f}));
  const GLdouble dv[3] = {0.25, 1e300, -1e-50};
  glSecondaryColor3dv(dv);
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 3)[0], 0.25f);
  EXPECT_TRUE(std::isinf(floats(GL_CURRENT_SECONDARY_COLOR, 3)[1]));
  glSecondaryColor3fEXT(0.0f, 0.5f, 1.0f);  // the EXT alias
  EXPECT_EQ(floats(GL_CURRENT_SECONDARY_COLOR, 3), (V{0.0f, 0.5f, 1.0f}));
  glSecondaryColor3ubv(nullptr);  // ignored, no crash
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, ColourAndNormalIntegersRoundAsMesa) {
  glColor3b(-1, 0, 64);
  EXPECT_EQ(floats(GL_CURRENT_COLOR, 4), (V{-0x1.010102p-8f, 0x1.010102p-8f, 0x1.030304p-1f, 1}));
  glColor4us(1, 2, 3, 40000);
  EXPECT_EQ(floats(GL_CURRENT_COLOR, 4),
            (V{0x1.0001p-16f, 0x1.0001p-15f, 0x1.80018p-15f, 0x1.388138p-1f}));
  glNormal3s(-1, 0, 20000);
  EXPECT_EQ(floats(GL_CURRENT_NORMAL, 3), (V{-0x1.0001p-16f, 0x1.0001p-16f, 0x1.388338p-1f}));
  glNormal3i(5, -5, 123456789);
  EXPECT_EQ(floats(GL_CURRENT_NORMAL, 3), (V{0x1.6p-29f, -0x1.2p-29f, 0x1.d6f346p-5f}));
}

// Every unsigned byte colour component is c / 255.0f (GL 1.5 table 2.9; Mesa's UBYTE_TO_FLOAT
// table holds the same quotients), divided here at run time.
TEST_F(GlTest, EveryUnsignedByteColourIsItsQuotient) {
  volatile float divisor = 255.0f;
  for (int c = 0; c < 256; ++c) {
    const GLubyte component = GLubyte(c);
    glColor4ub(component, component, component, component);
    const float expected = float(c) / divisor;
    EXPECT_EQ(floats(GL_CURRENT_COLOR, 4), (V{expected, expected, expected, expected})) << c;
  }
}

TEST_F(GlTest, FogCoordinateEdgeFlagAndIndexVariants) {
  glFogCoordf(2.5f);
  EXPECT_EQ(floats(GL_CURRENT_FOG_COORD, 1), (V{2.5f}));
  glFogCoordd(0.1);
  EXPECT_EQ(floats(GL_CURRENT_FOG_COORD, 1), (V{0.1f}));
  const GLfloat f = -3.0f;
  glFogCoordfv(&f);
  EXPECT_EQ(ctx_.current.fog_coord, -3.0f);
  glFogCoorddEXT(4.0);
  EXPECT_EQ(ctx_.current.fog_coord, 4.0f);

  glEdgeFlag(GL_FALSE);
  GLboolean b = 7;
  glGetBooleanv(GL_EDGE_FLAG, &b);
  EXPECT_EQ(b, GL_FALSE);
  EXPECT_FALSE(ctx_.current.edge_flag);
  const GLboolean on = 2;  // any nonzero GLboolean is true
  glEdgeFlagv(&on);
  EXPECT_TRUE(ctx_.current.edge_flag);

  glIndexi(-3);
  EXPECT_EQ(floats(GL_CURRENT_INDEX, 1), (V{-3.0f}));
  const GLubyte ub = 200;
  glIndexubv(&ub);
  EXPECT_EQ(ctx_.current.index, 200.0f);
  glEdgeFlagv(nullptr);
  glFogCoorddv(nullptr);
  glIndexfv(nullptr);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, AttributeSettersAreAllowedBetweenBeginAndEnd) {
  glBegin(GL_POINTS);
  glSecondaryColor3f(0.25f, 0.5f, 0.75f);
  glFogCoordf(9.0f);
  glEdgeFlag(GL_FALSE);
  glIndexf(4.0f);
  glVertex2f(0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(ctx_.current.secondary_color, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  EXPECT_EQ(ctx_.current.fog_coord, 9.0f);
  EXPECT_FALSE(ctx_.current.edge_flag);
  EXPECT_EQ(ctx_.current.index, 4.0f);
}

std::vector<const glpt::rec::Draw*> recorded_draws(glpt::Context& ctx) {
  ctx.recorder.seal();
  std::vector<const glpt::rec::Draw*> out;
  for (const auto& c : ctx.recorder.record().commands)
    if (const auto* d = std::get_if<glpt::rec::Draw>(&c)) out.push_back(d);
  return out;
}

// glRect draws the quadrilateral Mesa draws for it: Begin(GL_QUADS), the four corners, End.
TEST_F(GlTest, RectIsRecordedLikeTheEquivalentQuad) {
  glRectf(-1.0f, -0.5f, 2.0f, 3.0f);
  glTranslatef(10, 0, 0);  // a new modelview: a separate recorded batch
  glBegin(GL_QUADS);
  glVertex2f(-1.0f, -0.5f);
  glVertex2f(2.0f, -0.5f);
  glVertex2f(2.0f, 3.0f);
  glVertex2f(-1.0f, 3.0f);
  glEnd();
  const auto d = recorded_draws(ctx_);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0]->vertices->mode, GLenum{GL_QUADS});
  EXPECT_EQ(d[0]->vertices->position, d[1]->vertices->position);
  EXPECT_EQ(d[0]->vertices->keys().geometry, d[1]->vertices->keys().geometry);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, RectVariantsConvertTheirCorners) {
  const GLshort a[2] = {1, 2}, b[2] = {3, 4};
  glRectsv(a, b);
  glRecti(1, 2, 3, 4);
  glRectd(1.0, 2.0, 3.0, 4.0);
  const GLdouble c[2] = {1.0, 2.0}, d[2] = {3.0, 4.0};
  glRectdv(c, d);
  glRectfv(nullptr, nullptr);  // ignored, no crash
  const auto draws = recorded_draws(ctx_);
  ASSERT_EQ(draws.size(), 1u);  // one state: one draw of four rectangles
  const auto& p = draws[0]->vertices->position;
  ASSERT_EQ(p.size(), 4u * 4u);
  EXPECT_EQ(draws[0]->vertices->primitives.size(), 4u);
  for (size_t rect = 1; rect < 4; ++rect)
    for (size_t k = 0; k < 4; ++k) EXPECT_EQ(p[rect * 4 + k], p[k]) << rect << " " << k;
  EXPECT_EQ(p[0], glm::vec4(1, 2, 0, 1));
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, RectIsInvalidBetweenBeginAndEnd) {
  glBegin(GL_TRIANGLES);
  glRectf(0, 0, 1, 1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_TRUE(recorded_draws(ctx_).empty());
}

}  // namespace
