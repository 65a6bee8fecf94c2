// glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib (GL 1.5 6.1.14): every
// attribute group restores exactly its state (GL 1.5 tables 6.5-6.33), the stacks' limits and
// errors, and Mesa's behaviour where the spec leaves room.
#include <map>
#include <string>
#include <vector>

#include "array_test_util.hpp"

namespace {

// The state of the groups, read back through glGet*, keyed by what was read.
using Reading = std::map<std::string, std::vector<float>>;

void get(Reading& r, GLenum pname, int n) {
  std::vector<float> v(16, -999.0f);
  glGetFloatv(pname, v.data());
  v.resize(size_t(n));
  r["get " + std::to_string(pname)] = v;
}

void enabled(Reading& r, GLenum cap) {
  r["enabled " + std::to_string(cap)] = {glIsEnabled(cap) ? 1.0f : 0.0f};
}

// Per texture unit (leaves unit 0 active).
void for_units(Reading& r, void (*read_unit)(Reading&, const std::string& unit)) {
  for (int u = 0; u < 4; ++u) {
    glActiveTexture(GLenum(GL_TEXTURE0 + u));
    read_unit(r, "unit " + std::to_string(u) + " ");
  }
  glActiveTexture(GL_TEXTURE0);
}

struct Group {
  const char* name;
  GLbitfield bit;
  void (*set)();           // changes every state of the group from its initial value
  void (*read)(Reading&);  // reads every state of the group
};

const GLenum kLights[] = {GL_LIGHT0, GL_LIGHT1, GL_LIGHT7};

const Group kGroups[] = {
    {"current", GL_CURRENT_BIT,
     [] {
       glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
       glSecondaryColor3f(0.5f, 0.6f, 0.7f);
       glNormal3f(1, 0, 0);
       glMultiTexCoord4f(GL_TEXTURE0, 1, 2, 3, 4);
       glMultiTexCoord4f(GL_TEXTURE3, 5, 6, 7, 8);
       glFogCoordf(3);
       glIndexf(9);
       glEdgeFlag(GL_FALSE);
       glWindowPos3f(5, 6, 0.25f);
     },
     [](Reading& r) {
       get(r, GL_CURRENT_COLOR, 4);
       get(r, GL_CURRENT_SECONDARY_COLOR, 4);
       get(r, GL_CURRENT_NORMAL, 3);
       get(r, GL_CURRENT_FOG_COORD, 1);
       get(r, GL_CURRENT_INDEX, 1);
       get(r, GL_EDGE_FLAG, 1);
       get(r, GL_CURRENT_RASTER_POSITION, 4);
       get(r, GL_CURRENT_RASTER_COLOR, 4);
       get(r, GL_CURRENT_RASTER_DISTANCE, 1);
       get(r, GL_CURRENT_RASTER_POSITION_VALID, 1);
       for_units(r, [](Reading& r, const std::string& u) {
         std::vector<float> v(4);
         glGetFloatv(GL_CURRENT_TEXTURE_COORDS, v.data());
         r[u + "texcoord"] = v;
       });
     }},
    {"point", GL_POINT_BIT,
     [] {
       glPointSize(5);
       glEnable(GL_POINT_SMOOTH);
       glPointParameterf(GL_POINT_SIZE_MIN, 2);
       glPointParameterf(GL_POINT_SIZE_MAX, 20);
       glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 3);
       const GLfloat attenuation[3] = {1, 2, 3};
       glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
     },
     [](Reading& r) {
       get(r, GL_POINT_SIZE, 1);
       enabled(r, GL_POINT_SMOOTH);
       get(r, GL_POINT_SIZE_MIN, 1);
       get(r, GL_POINT_SIZE_MAX, 1);
       get(r, GL_POINT_FADE_THRESHOLD_SIZE, 1);
       get(r, GL_POINT_DISTANCE_ATTENUATION, 3);
     }},
    {"line", GL_LINE_BIT,
     [] {
       glLineWidth(3);
       glEnable(GL_LINE_SMOOTH);
       glEnable(GL_LINE_STIPPLE);
       glLineStipple(3, 0xf0f0);
     },
     [](Reading& r) {
       get(r, GL_LINE_WIDTH, 1);
       enabled(r, GL_LINE_SMOOTH);
       enabled(r, GL_LINE_STIPPLE);
       get(r, GL_LINE_STIPPLE_PATTERN, 1);
       get(r, GL_LINE_STIPPLE_REPEAT, 1);
     }},
    {"polygon", GL_POLYGON_BIT,
     [] {
       glCullFace(GL_FRONT);
       glFrontFace(GL_CW);
       glPolygonMode(GL_FRONT, GL_LINE);
       glPolygonMode(GL_BACK, GL_POINT);
       glPolygonOffset(2, 3);
       for (GLenum cap : {GL_CULL_FACE, GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE,
                          GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT})
         glEnable(cap);
     },
     [](Reading& r) {
       get(r, GL_CULL_FACE_MODE, 1);
       get(r, GL_FRONT_FACE, 1);
       get(r, GL_POLYGON_MODE, 2);
       get(r, GL_POLYGON_OFFSET_FACTOR, 1);
       get(r, GL_POLYGON_OFFSET_UNITS, 1);
       for (GLenum cap : {GL_CULL_FACE, GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE,
                          GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT})
         enabled(r, cap);
     }},
    {"polygon stipple", GL_POLYGON_STIPPLE_BIT,
     [] {
       GLubyte mask[128];
       for (int i = 0; i < 128; ++i) mask[i] = GLubyte(i * 7);
       glPolygonStipple(mask);
     },
     [](Reading& r) {
       GLubyte mask[128] = {};
       glGetPolygonStipple(mask);
       r["stipple"] = std::vector<float>(mask, mask + 128);
     }},
    {"pixel mode", GL_PIXEL_MODE_BIT,
     [] {
       glPixelTransferf(GL_RED_SCALE, 2);
       glPixelTransferf(GL_ALPHA_BIAS, 0.5f);
       glPixelTransferf(GL_DEPTH_SCALE, 3);
       glPixelTransferi(GL_INDEX_SHIFT, 2);
       glPixelTransferi(GL_INDEX_OFFSET, 4);
       glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
       glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
       glPixelZoom(2, 3);
       glReadBuffer(GL_FRONT);
     },
     [](Reading& r) {
       for (GLenum p :
            {GL_RED_SCALE, GL_ALPHA_BIAS, GL_DEPTH_SCALE, GL_INDEX_SHIFT, GL_INDEX_OFFSET,
             GL_MAP_COLOR, GL_MAP_STENCIL, GL_ZOOM_X, GL_ZOOM_Y, GL_READ_BUFFER})
         get(r, p, 1);
     }},
    {"lighting", GL_LIGHTING_BIT,
     [] {
       glEnable(GL_LIGHTING);
       glEnable(GL_LIGHT1);
       glDisable(GL_LIGHT0);
       const GLfloat colour[4] = {0.1f, 0.2f, 0.3f, 0.4f};
       glLightfv(GL_LIGHT1, GL_DIFFUSE, colour);
       glLightf(GL_LIGHT7, GL_SPOT_CUTOFF, 30);
       glLightModelfv(GL_LIGHT_MODEL_AMBIENT, colour);
       glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
       glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
       glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
       glShadeModel(GL_FLAT);
       glColorMaterial(GL_BACK, GL_SPECULAR);
       glEnable(GL_COLOR_MATERIAL);
       glMaterialfv(GL_FRONT, GL_EMISSION, colour);
       glMaterialf(GL_BACK, GL_SHININESS, 50);
     },
     [](Reading& r) {
       enabled(r, GL_LIGHTING);
       enabled(r, GL_COLOR_MATERIAL);
       get(r, GL_LIGHT_MODEL_AMBIENT, 4);
       get(r, GL_LIGHT_MODEL_TWO_SIDE, 1);
       get(r, GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
       get(r, GL_LIGHT_MODEL_COLOR_CONTROL, 1);
       get(r, GL_SHADE_MODEL, 1);
       get(r, GL_COLOR_MATERIAL_FACE, 1);
       get(r, GL_COLOR_MATERIAL_PARAMETER, 1);
       for (GLenum light : kLights) {
         enabled(r, light);
         std::vector<float> v(4);
         glGetLightfv(light, GL_DIFFUSE, v.data());
         r["light diffuse " + std::to_string(light)] = v;
         glGetLightfv(light, GL_SPOT_CUTOFF, v.data());
         r["light cutoff " + std::to_string(light)] = {v[0]};
       }
       for (GLenum face : {GL_FRONT, GL_BACK}) {
         std::vector<float> v(4);
         glGetMaterialfv(face, GL_EMISSION, v.data());
         r["emission " + std::to_string(face)] = v;
         glGetMaterialfv(face, GL_SHININESS, v.data());
         r["shininess " + std::to_string(face)] = {v[0]};
       }
     }},
    {"fog", GL_FOG_BIT,
     [] {
       glEnable(GL_FOG);
       glEnable(GL_COLOR_SUM);
       glFogi(GL_FOG_MODE, GL_LINEAR);
       glFogf(GL_FOG_DENSITY, 0.5f);
       glFogf(GL_FOG_START, 2);
       glFogf(GL_FOG_END, 3);
       glFogf(GL_FOG_INDEX, 4);
       const GLfloat colour[4] = {0.1f, 0.2f, 0.3f, 0.4f};
       glFogfv(GL_FOG_COLOR, colour);
       glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
     },
     [](Reading& r) {
       enabled(r, GL_FOG);
       enabled(r, GL_COLOR_SUM);
       for (GLenum p :
            {GL_FOG_MODE, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_INDEX, GL_FOG_COORD_SRC})
         get(r, p, 1);
       get(r, GL_FOG_COLOR, 4);
     }},
    {"depth buffer", GL_DEPTH_BUFFER_BIT,
     [] {
       glEnable(GL_DEPTH_TEST);
       glDepthFunc(GL_GREATER);
       glDepthMask(GL_FALSE);
       glClearDepth(0.25);
     },
     [](Reading& r) {
       enabled(r, GL_DEPTH_TEST);
       get(r, GL_DEPTH_FUNC, 1);
       get(r, GL_DEPTH_WRITEMASK, 1);
       get(r, GL_DEPTH_CLEAR_VALUE, 1);
     }},
    {"accum buffer", GL_ACCUM_BUFFER_BIT, [] { glClearAccum(0.1f, 0.2f, 0.3f, 0.4f); },
     [](Reading& r) { get(r, GL_ACCUM_CLEAR_VALUE, 4); }},
    {"stencil buffer", GL_STENCIL_BUFFER_BIT,
     [] {
       glEnable(GL_STENCIL_TEST);
       glStencilFunc(GL_EQUAL, 3, 0x0f);
       glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
       glStencilMask(0x3c);
       glClearStencil(5);
     },
     [](Reading& r) {
       enabled(r, GL_STENCIL_TEST);
       for (GLenum p : {GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL,
                        GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS,
                        GL_STENCIL_WRITEMASK, GL_STENCIL_CLEAR_VALUE})
         get(r, p, 1);
     }},
    {"viewport", GL_VIEWPORT_BIT,
     [] {
       glViewport(1, 2, 30, 40);
       glDepthRange(0.25, 0.75);
     },
     [](Reading& r) {
       get(r, GL_VIEWPORT, 4);
       get(r, GL_DEPTH_RANGE, 2);
     }},
    {"transform", GL_TRANSFORM_BIT,
     [] {
       const GLdouble plane[4] = {1, 2, 3, 4};
       glClipPlane(GL_CLIP_PLANE2, plane);
       glEnable(GL_CLIP_PLANE2);
       glEnable(GL_NORMALIZE);
       glEnable(GL_RESCALE_NORMAL);
       glMatrixMode(GL_TEXTURE);
     },
     [](Reading& r) {
       get(r, GL_MATRIX_MODE, 1);
       enabled(r, GL_CLIP_PLANE2);
       enabled(r, GL_NORMALIZE);
       enabled(r, GL_RESCALE_NORMAL);
       GLdouble plane[4];
       glGetClipPlane(GL_CLIP_PLANE2, plane);
       r["clip plane 2"] = {float(plane[0]), float(plane[1]), float(plane[2]), float(plane[3])};
     }},
    {"color buffer", GL_COLOR_BUFFER_BIT,
     [] {
       glEnable(GL_ALPHA_TEST);
       glAlphaFunc(GL_GREATER, 0.5f);
       glEnable(GL_BLEND);
       glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_ZERO, GL_DST_COLOR);
       glBlendEquation(GL_FUNC_SUBTRACT);
       glBlendColor(0.1f, 0.2f, 0.3f, 0.4f);
       glDisable(GL_DITHER);
       glEnable(GL_COLOR_LOGIC_OP);
       glEnable(GL_INDEX_LOGIC_OP);
       glLogicOp(GL_XOR);
       glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
       glIndexMask(0x0f);
       glClearColor(0.5f, 0.6f, 0.7f, 0.8f);
       glClearIndex(3);
       glDrawBuffer(GL_FRONT);
     },
     [](Reading& r) {
       for (GLenum cap : {GL_ALPHA_TEST, GL_BLEND, GL_DITHER, GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP})
         enabled(r, cap);
       for (GLenum p : {GL_ALPHA_TEST_FUNC, GL_ALPHA_TEST_REF, GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB,
                        GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA, GL_BLEND_EQUATION, GL_LOGIC_OP_MODE,
                        GL_INDEX_WRITEMASK, GL_INDEX_CLEAR_VALUE, GL_DRAW_BUFFER})
         get(r, p, 1);
       get(r, GL_BLEND_COLOR, 4);
       get(r, GL_COLOR_WRITEMASK, 4);
       get(r, GL_COLOR_CLEAR_VALUE, 4);
     }},
    {"hint", GL_HINT_BIT,
     [] {
       glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
       glHint(GL_POINT_SMOOTH_HINT, GL_FASTEST);
       glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
       glHint(GL_POLYGON_SMOOTH_HINT, GL_FASTEST);
       glHint(GL_FOG_HINT, GL_NICEST);
       glHint(GL_TEXTURE_COMPRESSION_HINT, GL_FASTEST);
       glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
     },
     [](Reading& r) {
       for (GLenum p : {GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT,
                        GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT, GL_TEXTURE_COMPRESSION_HINT,
                        GL_GENERATE_MIPMAP_HINT})
         get(r, p, 1);
     }},
    {"eval", GL_EVAL_BIT,
     [] {
       glEnable(GL_MAP1_VERTEX_3);
       glEnable(GL_MAP2_TEXTURE_COORD_2);
       glEnable(GL_AUTO_NORMAL);
       glMapGrid1f(7, 0.25f, 3.5f);
       glMapGrid2f(3, -1.0f, 2.0f, 9, 0.5f, 0.75f);
     },
     [](Reading& r) {
       enabled(r, GL_MAP1_VERTEX_3);
       enabled(r, GL_MAP2_TEXTURE_COORD_2);
       enabled(r, GL_AUTO_NORMAL);
       get(r, GL_MAP1_GRID_DOMAIN, 2);
       get(r, GL_MAP1_GRID_SEGMENTS, 1);
       get(r, GL_MAP2_GRID_DOMAIN, 4);
       get(r, GL_MAP2_GRID_SEGMENTS, 2);
     }},
    {"list", GL_LIST_BIT, [] { glListBase(7); }, [](Reading& r) { get(r, GL_LIST_BASE, 1); }},
    {"texture", GL_TEXTURE_BIT,
     [] {
       glActiveTexture(GL_TEXTURE1);
       glEnable(GL_TEXTURE_2D);
       glEnable(GL_TEXTURE_GEN_S);
       glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
       glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
       const GLfloat plane[4] = {1, 2, 3, 4};
       glTexGenfv(GL_T, GL_OBJECT_PLANE, plane);
       glBindTexture(GL_TEXTURE_2D, 5);
       glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
       glActiveTexture(GL_TEXTURE3);
       glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP);  // texture 0 of 3-D
     },
     [](Reading& r) {
       get(r, GL_ACTIVE_TEXTURE, 1);
       for_units(r, [](Reading& r, const std::string& u) {
         for (GLenum cap : {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
                            GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T})
           r[u + "enabled " + std::to_string(cap)] = {glIsEnabled(cap) ? 1.0f : 0.0f};
         GLint v[4] = {};
         glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, v);
         r[u + "env mode"] = {float(v[0])};
         glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, v);
         r[u + "gen mode s"] = {float(v[0])};
         GLfloat plane[4] = {};
         glGetTexGenfv(GL_T, GL_OBJECT_PLANE, plane);
         r[u + "object plane t"] = std::vector<float>(plane, plane + 4);
         glGetIntegerv(GL_TEXTURE_BINDING_2D, v);
         r[u + "binding 2d"] = {float(v[0])};
         glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, v);
         r[u + "min filter"] = {float(v[0])};
         glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, v);
         r[u + "wrap r 3d"] = {float(v[0])};
       });
     }},
    {"scissor", GL_SCISSOR_BIT,
     [] {
       glEnable(GL_SCISSOR_TEST);
       glScissor(1, 2, 3, 4);
     },
     [](Reading& r) {
       enabled(r, GL_SCISSOR_TEST);
       get(r, GL_SCISSOR_BOX, 4);
     }},
    {"multisample", GL_MULTISAMPLE_BIT,
     [] {
       glDisable(GL_MULTISAMPLE);
       glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
       glEnable(GL_SAMPLE_ALPHA_TO_ONE);
       glEnable(GL_SAMPLE_COVERAGE);
       glSampleCoverage(0.5f, GL_TRUE);
     },
     [](Reading& r) {
       for (GLenum cap : {GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
                          GL_SAMPLE_COVERAGE})
         enabled(r, cap);
       get(r, GL_SAMPLE_COVERAGE_VALUE, 1);
       get(r, GL_SAMPLE_COVERAGE_INVERT, 1);
     }},
};

// The enable group: every capability any group above reads (and the texture targets of every
// unit), GL 1.5's "enable" attribute.
void read_enables(Reading& r) {
  Reading all;
  for (const Group& g : kGroups) g.read(all);
  for (auto& [key, value] : all)
    if (key.find("enabled") != std::string::npos) r[key] = value;
}

void set_everything() {
  for (const Group& g : kGroups) g.set();
  glActiveTexture(GL_TEXTURE0);
  glMatrixMode(GL_MODELVIEW);
}

Reading read_everything() {
  Reading r;
  for (const Group& g : kGroups) g.read(r);
  return r;
}

class AttribStackTest : public GlTest, public ::testing::WithParamInterface<size_t> {};

// Push one group, change the state of every group, pop: the group's state is back, the others
// keep their changes.
TEST_P(AttribStackTest, PoppingAGroupRestoresItAndNothingElse) {
  const bool enable_group = GetParam() == std::size(kGroups);
  const Group enable{"enable", GL_ENABLE_BIT, nullptr, read_enables};
  const Group& g = enable_group ? enable : kGroups[GetParam()];
  SCOPED_TRACE(g.name);
  Reading group_before;
  g.read(group_before);
  glPushAttrib(g.bit);
  set_everything();
  ASSERT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const Reading changed = read_everything();
  Reading group_changed;
  g.read(group_changed);
  EXPECT_NE(group_changed, group_before) << "the setters do not change this group";
  glPopAttrib();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  Reading group_after;
  g.read(group_after);
  for (const auto& [key, value] : group_before) EXPECT_EQ(group_after.at(key), value) << key;
  for (const auto& [key, value] : read_everything()) {
    if (group_before.count(key) == 0) {
      EXPECT_EQ(value, changed.at(key)) << key;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryGroup, AttribStackTest,
                         ::testing::Range(size_t{0}, std::size(kGroups) + 1));

TEST_F(GlTest, AllAttribBitsRestoresEveryGroup) {
  const Reading before = read_everything();
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  set_everything();
  glPopAttrib();
  EXPECT_EQ(read_everything(), before);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, AttribStacksOverflowAndUnderflowAtMesasDepths) {
  EXPECT_EQ(get_integer(GL_MAX_ATTRIB_STACK_DEPTH), 16);
  EXPECT_EQ(get_integer(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH), 16);
  glPopAttrib();
  EXPECT_EQ(glGetError(), GLenum{GL_STACK_UNDERFLOW});
  glPopClientAttrib();
  EXPECT_EQ(glGetError(), GLenum{GL_STACK_UNDERFLOW});
  for (int i = 0; i < 16; ++i) {
    glPushAttrib(GL_CURRENT_BIT);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  }
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(get_integer(GL_ATTRIB_STACK_DEPTH), 16);
  EXPECT_EQ(get_integer(GL_CLIENT_ATTRIB_STACK_DEPTH), 16);
  glColor3f(1, 0, 0);
  glPushAttrib(GL_CURRENT_BIT);
  EXPECT_EQ(glGetError(), GLenum{GL_STACK_OVERFLOW});
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  EXPECT_EQ(glGetError(), GLenum{GL_STACK_OVERFLOW});
  EXPECT_EQ(get_integer(GL_ATTRIB_STACK_DEPTH), 16);
  glPopAttrib();  // the 16th push, not the refused one
  GLfloat colour[4];
  glGetFloatv(GL_CURRENT_COLOR, colour);
  EXPECT_EQ(colour[1], 1.0f);
  EXPECT_EQ(get_integer(GL_ATTRIB_STACK_DEPTH), 15);
  // Any mask is accepted, unknown bits included (as in Mesa).
  glPushAttrib(0x12345678);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, PushAttribIsCompiledAndNotAllowedInsideBeginEnd) {
  glNewList(1, GL_COMPILE);
  glPushAttrib(GL_CURRENT_BIT);
  glColor3f(1, 0, 0);
  glPopAttrib();
  glEndList();
  EXPECT_EQ(get_integer(GL_ATTRIB_STACK_DEPTH), 0);
  glColor3f(0, 0, 1);
  glCallList(1);
  GLfloat colour[4];
  glGetFloatv(GL_CURRENT_COLOR, colour);
  EXPECT_EQ(colour[2], 1.0f);
  glBegin(GL_POINTS);
  glPushAttrib(GL_CURRENT_BIT);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_OPERATION});
  EXPECT_EQ(get_integer(GL_ATTRIB_STACK_DEPTH), 0);
}

GLfloat diffuse(GLenum face) {
  GLfloat v[4] = {};
  glGetMaterialfv(face, GL_DIFFUSE, v);
  return v[0];
}

TEST_F(GlTest, LightingPopRestoresTheMaterialOnlyWithTheRestOfTheGroupAsMesaDoes) {
  // Mesa restores the lighting group only if a command changed it; glMaterial and colour
  // material tracking do not count (checked with OSMesa 25.0.7).
  glMaterialf(GL_FRONT, GL_SHININESS, 10);
  glPushAttrib(GL_LIGHTING_BIT);
  glMaterialf(GL_FRONT, GL_SHININESS, 50);
  glPopAttrib();
  GLfloat shininess = 0;
  glGetMaterialfv(GL_FRONT, GL_SHININESS, &shininess);
  EXPECT_EQ(shininess, 50.0f);
  // With another lighting change, the whole group comes back, the material included.
  glPushAttrib(GL_LIGHTING_BIT);
  glMaterialf(GL_FRONT, GL_SHININESS, 70);
  glShadeModel(GL_FLAT);
  glPopAttrib();
  glGetMaterialfv(GL_FRONT, GL_SHININESS, &shininess);
  EXPECT_EQ(shininess, 50.0f);
  // Colour material: the pushed diffuse is 0.5; glColor tracks into it; popping keeps 1.
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(0.5f, 0.25f, 0.125f);
  glPushAttrib(GL_LIGHTING_BIT);
  glColor3f(1, 1, 1);
  EXPECT_EQ(diffuse(GL_FRONT), 1.0f);
  glPopAttrib();
  EXPECT_EQ(diffuse(GL_FRONT), 1.0f);
  // Popping the current colour does not re-apply colour material.
  glPushAttrib(GL_CURRENT_BIT);
  glColor3f(0.25f, 0.25f, 0.25f);
  glPopAttrib();
  EXPECT_EQ(diffuse(GL_FRONT), 0.25f);
  GLfloat colour[4];
  glGetFloatv(GL_CURRENT_COLOR, colour);
  EXPECT_EQ(colour[0], 1.0f);
  // Enabling colour material inside, a lighting change: everything back, material included.
  glDisable(GL_COLOR_MATERIAL);
  glPushAttrib(GL_LIGHTING_BIT | GL_ENABLE_BIT);
  glEnable(GL_COLOR_MATERIAL);  // applies the current colour (1) to the material
  glColor3f(0.75f, 0.75f, 0.75f);
  glPopAttrib();
  EXPECT_FALSE(glIsEnabled(GL_COLOR_MATERIAL));
  EXPECT_EQ(diffuse(GL_FRONT), 0.25f);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, TexturePopRebindsByNameAndRestoresParameters) {
  GLuint t[2] = {};
  glGenTextures(2, t);
  glBindTexture(GL_TEXTURE_2D, t[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, t[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glPopAttrib();
  EXPECT_EQ(get_integer(GL_TEXTURE_BINDING_2D), GLint(t[0]));
  GLint filter = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
  EXPECT_EQ(filter, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, t[1]);  // was not bound at the push: keeps its parameters
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
  EXPECT_EQ(filter, GL_LINEAR);
  // A texture deleted while pushed is bound again by name (Mesa: a new object of that name).
  glPushAttrib(GL_TEXTURE_BIT);
  glDeleteTextures(1, &t[1]);
  EXPECT_EQ(get_integer(GL_TEXTURE_BINDING_2D), 0);
  glPopAttrib();
  EXPECT_EQ(get_integer(GL_TEXTURE_BINDING_2D), GLint(t[1]));
  EXPECT_TRUE(glIsTexture(t[1]));
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
  EXPECT_EQ(filter, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(GlTest, ClientPixelStoreRoundTrip) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 7);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glPixelStorei(GL_PACK_SKIP_IMAGES, 2);
  glEnableClientState(GL_VERTEX_ARRAY);  // not in the group
  glPopClientAttrib();
  EXPECT_EQ(get_integer(GL_UNPACK_ALIGNMENT), 2);
  EXPECT_EQ(get_integer(GL_PACK_ROW_LENGTH), 0);
  EXPECT_EQ(get_integer(GL_UNPACK_SWAP_BYTES), 0);
  EXPECT_EQ(get_integer(GL_PACK_SKIP_IMAGES), 0);
  EXPECT_TRUE(glIsEnabled(GL_VERTEX_ARRAY));
}

TEST_F(GlTest, ClientVertexArrayRoundTrip) {
  const float data[4] = {};
  GLuint b[2] = {};
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, 64, nullptr, GL_STATIC_DRAW);
  glVertexPointer(3, GL_SHORT, 6, reinterpret_cast<const void*>(8));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glEnableClientState(GL_VERTEX_ARRAY);
  glClientActiveTexture(GL_TEXTURE2);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glVertexPointer(2, GL_FLOAT, 0, data);
  glDisableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, b[1]);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glClientActiveTexture(GL_TEXTURE0);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glLockArraysEXT(0, 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);  // not in the group
  glDeleteBuffers(1, &b[0]);            // the pushed arrays keep their buffer
  glPopClientAttrib();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(get_integer(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE2);
  EXPECT_TRUE(glIsEnabled(GL_VERTEX_ARRAY));
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_COORD_ARRAY));
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_STRIDE), 6);
  EXPECT_EQ(get_integer(GL_VERTEX_ARRAY_BUFFER_BINDING), GLint(b[0]));
  EXPECT_EQ(get_integer(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(get_integer(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(get_integer(GL_ARRAY_ELEMENT_LOCK_COUNT_EXT), 0);
  EXPECT_EQ(get_integer(GL_PACK_ALIGNMENT), 1);
  glClientActiveTexture(GL_TEXTURE0);
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_COORD_ARRAY));
  // The restored array still reads its (deleted) buffer's store.
  glDrawArrays(GL_POINTS, 0, 2);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(recorded_draws(ctx_).size(), 1u);
}

}  // namespace
