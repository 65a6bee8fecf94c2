// Path-traced mode through glpt's GL front end: GL scenes drawn by the exported gl* entry points
// on a headless drawable, read back with glReadPixels. Each test is a defect of the first,
// primary-ray path tracer (one projection per frame, one light set per frame, projective
// modelviews flattened, draw order, depth test and culling ignored, lit faces under parallel
// projections shadowing themselves) and asserts what GL requires instead, often by comparing
// with raster mode's image of the same scene (raster mode draws what Mesa draws).
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <memory>
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/gl_entry_decls.h"
#include "../common/headless_gl_render.hpp"

namespace {

constexpr int kSize = 64;

struct Rgba {
  int r, g, b, a;
  bool operator==(const Rgba&) const = default;
};

std::ostream& operator<<(std::ostream& out, const Rgba& c) {
  return out << "(" << c.r << "," << c.g << "," << c.b << "," << c.a << ")";
}

struct Image {
  std::vector<uint8_t> rgba;
  Rgba at(int x, int y) const {  // GL window coordinates: y = 0 is the bottom row
    const uint8_t* p = &rgba[(size_t(y) * kSize + size_t(x)) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
  int count(const std::function<bool(Rgba)>& match) const {
    int n = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) n += match(at(x, y)) ? 1 : 0;
    return n;
  }
};

// Draws `scene` with GL on a fresh context in GLPT_MODE `mode` ("path" or "raster") and reads
// the frame back: `frames` times the same frame, the last one read.
Image render(const char* mode, const std::function<void()>& scene, int frames = 1) {
  return Image{glpt::test::render_headless(kSize, {{"GLPT_MODE", mode}}, scene, frames, mode)};
}

// A 3-D camera (60 degree frustum, near 1, far 20), depth test on, cleared to dark blue.
void camera_3d() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.577, 0.577, -0.577, 0.577, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
}

void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glNormal3f(0, 0, 1);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

void light(GLenum light, float r, float g, float b) {
  const float position[] = {0, 0, 1, 0};
  const float diffuse[] = {r, g, b, 1};
  glLightfv(light, GL_POSITION, position);
  glLightfv(light, GL_DIFFUSE, diffuse);
}

// Where eye-space (x, y, z) lands with camera_3d()'s projection.
int pixel_of(float coordinate, float z) {
  return static_cast<int>((coordinate / (-z * 0.577f) * 0.5f + 0.5f) * kSize);
}

TEST(PathTracedGl, EachDrawIsLitByItsOwnLights) {
  // Left quad: GL_LIGHT0 (red) only. Right quad: GL_LIGHT1 (green) only. One light set for the
  // frame (the first lit draw's) would light both red.
  Image image = render("path", [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    light(GL_LIGHT0, 1, 0, 0);
    light(GL_LIGHT1, 0, 1, 0);
    glEnable(GL_LIGHT0);
    quad(-2.2f, -1, -0.2f, 1, -5);
    glDisable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    quad(0.2f, -1, 2.2f, 1, -5);
  });
  const Rgba left = image.at(pixel_of(-1.2f, -5), kSize / 2);
  const Rgba right = image.at(pixel_of(1.2f, -5), kSize / 2);
  EXPECT_GT(left.r, 150) << left;  // 0.8 * red + ambient
  EXPECT_LT(left.g, 40) << left;
  EXPECT_GT(right.g, 150) << right;
  EXPECT_LT(right.r, 40) << right;
}

TEST(PathTracedGl, HudAndSceneBothAppear) {
  // A lit 3-D quad under a perspective projection, then a 2-D HUD under glOrtho: both show.
  auto scene = [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    quad(-1, -1, 1, 1, -4);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kSize, 0, kSize, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1, 1, 0);
    quad(0, 0, 16, 16, 0);    // a corner of the HUD
    quad(28, 40, 36, 48, 0);  // over the 3-D quad
  };
  Image traced = render("path", scene), rasterized = render("raster", scene);
  EXPECT_EQ(traced.at(8, 8), (Rgba{255, 255, 0, 255}));
  EXPECT_EQ(traced.at(32, 44), (Rgba{255, 255, 0, 255}));
  const Rgba centre = traced.at(32, 30);
  EXPECT_GT(centre.r, 150) << centre;  // the lit quad (Mesa: 0.84 -> 214)
  EXPECT_NEAR(centre.r, rasterized.at(32, 30).r, 16) << centre << " vs " << rasterized.at(32, 30);
  EXPECT_EQ(traced.at(60, 4), (Rgba{0, 0, 64, 255}));  // the clear colour
}

TEST(PathTracedGl, WithoutDepthTestALaterQuadCoversAnEarlierOne) {
  // The far green quad is drawn after the near red one with the depth test off: GL shows it.
  Image image = render("path", [] {
    camera_3d();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(1, 0, 0);
    quad(-1, -1, 1, 1, -3);
    glColor3f(0, 1, 0);
    quad(-1, -1, 1, 1, -6);
  });
  // (Dim: in the path tracer the near quad does shadow the far one from the light.)
  const Rgba overlap = image.at(kSize / 2, kSize / 2);
  EXPECT_GT(overlap.g, 40) << overlap;
  EXPECT_LT(overlap.r, 10) << overlap;
  const Rgba near_only = image.at(pixel_of(0.8f, -3), kSize / 2);  // outside the far quad
  EXPECT_GT(near_only.r, 150) << near_only;
}

TEST(PathTracedGl, CulledFacesAreAbsent) {
  Image image = render("path", [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    quad(-2.2f, -1, -0.2f, 1, -5);  // counter-clockwise: front, drawn
    glBegin(GL_QUADS);              // clockwise: back, culled
    glNormal3f(0, 0, 1);
    glVertex3f(0.2f, -1, -5);
    glVertex3f(0.2f, 1, -5);
    glVertex3f(2.2f, 1, -5);
    glVertex3f(2.2f, -1, -5);
    glEnd();
  });
  EXPECT_GT(image.at(pixel_of(-1.2f, -5), kSize / 2).r, 150);
  EXPECT_EQ(image.at(pixel_of(1.2f, -5), kSize / 2), (Rgba{0, 0, 64, 255}));
}

TEST(PathTracedGl, MaterialsSetBetweenBeginAndEndColourTheTracedSurface) {
  // glMaterial between glBegin and glEnd gives each vertex its own material (GL 1.5 2.14.3;
  // xscreensaver's squirtorus shades its mounds so). The G-buffer took the draw state's material
  // (here green, and in squirtorus whatever the frame before last set: one mound came out in
  // its stars' yellow): the surface must be lit with the vertices' red, left to right darker as
  // their diffuse falls, as raster mode (Mesa) lights it.
  auto scene = [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light(GL_LIGHT0, 1, 1, 1);
    const float green[] = {0, 0.8f, 0, 1}, bright[] = {0.9f, 0, 0, 1}, dim[] = {0.3f, 0, 0, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, green);
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, bright);
    glVertex3f(-2, -2, -4);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, dim);
    glVertex3f(2, -2, -4);
    glVertex3f(2, 2, -4);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, bright);
    glVertex3f(-2, 2, -4);
    glEnd();
  };
  Image traced = render("path", scene), rasterized = render("raster", scene);
  for (float x : {-1.5f, 0.0f, 1.5f}) {
    const int px = pixel_of(x, -4);
    const Rgba mesa = rasterized.at(px, kSize / 2), glpt = traced.at(px, kSize / 2);
    EXPECT_LT(glpt.g, 8) << "x " << x << ": " << glpt;
    // GL clamps each vertex's lit colour before interpolating; the tracer interpolates the
    // materials: up to 17 levels apart where the bright vertices saturate.
    EXPECT_NEAR(glpt.r, mesa.r, 24) << "x " << x << ": " << glpt << " Mesa " << mesa;
  }
  EXPECT_GT(traced.at(pixel_of(-1.5f, -4), kSize / 2).r,
            traced.at(pixel_of(1.5f, -4), kSize / 2).r + 60);
}

TEST(PathTracedGl, ClearsAfterTheTracedDrawsKeepTheirPlaceAmongTheLaterOnes) {
  // xscreensaver glplanet's passes: the lit world (traced), an alpha-only clear (here with one
  // more traced draw after it, so that it clears in the G-buffer pass), a depth clear,
  // an alpha-only mask nearer than the world, a depth clear, a blended pass behind the mask.
  // The alpha-only clear erased the traced surfaces (the planet was gone), and both depth clears
  // ran in the G-buffer pass, before the mask, so the blended pass failed the depth test
  // against the mask's depth. GL: the world red, the blended green added over it.
  auto scene = [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light(GL_LIGHT0, 1, 0, 0);
    quad(-2, -2, 2, 2, -5);
    glDisable(GL_LIGHTING);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_LIGHTING);
    quad(2.2f, -0.5f, 2.8f, 0.5f, -5);  // a traced draw after the alpha-only clear
    glDisable(GL_LIGHTING);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glColor4f(0, 0, 0, 1);
    quad(-2, -2, 2, 2, -3);
    glClear(GL_DEPTH_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glColor4f(0, 0.5f, 0, 1);
    quad(-1, -1, 1, 1, -4);
    glDisable(GL_BLEND);
  };
  Image traced = render("path", scene), rasterized = render("raster", scene);
  const Rgba mesa = rasterized.at(kSize / 2, kSize / 2), glpt = traced.at(kSize / 2, kSize / 2);
  EXPECT_GT(mesa.r, 150) << mesa;
  EXPECT_NEAR(mesa.g, 138, 3) << mesa;  // 0.5 added to GL's ambient 0.2 x 0.2
  EXPECT_NEAR(glpt.r, mesa.r, 30) << glpt << " Mesa " << mesa;  // the red world, traced
  EXPECT_NEAR(glpt.g, mesa.g, 8) << glpt << " Mesa " << mesa;   // the green pass over it
  // Outside the green quad the world alone.
  const Rgba world = traced.at(pixel_of(1.5f, -5), kSize / 2);
  EXPECT_GT(world.r, 120) << world;
  EXPECT_LT(world.g, 20) << world;
}

// A 40 x 40 wall at z = 2, behind camera_3d()'s camera and out of its view, normal +Z, its
// vertices counter-clockwise seen from +Z (`ccw_from_plus_z`) or from -Z.
void wall_behind_camera(bool ccw_from_plus_z) {
  const float x[4] = {-20, 20, 20, -20}, y[4] = {-20, -20, 20, 20};  // counter-clockwise from +Z
  glBegin(GL_QUADS);
  glNormal3f(0, 0, 1);
  for (int k = 0; k < 4; ++k) {
    const int i = ccw_from_plus_z ? k : 3 - k;
    glVertex3f(x[i], y[i], 2);
  }
  glEnd();
}

// A wall facing the camera at z = -6, lit by a directional light from the camera's side (+Z),
// and wall_behind_camera() between it and the light, after `setup` (its vertices
// counter-clockwise seen from +Z when `ccw_towards_light`). Returns the lit wall's centre.
Rgba wall_behind_occluder(const std::function<void()>& setup, bool ccw_towards_light,
                          const std::function<void()>& projection = {}) {
  Image image = render("path", [&] {
    camera_3d();
    if (projection) {
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      projection();
      glMatrixMode(GL_MODELVIEW);
    }
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light(GL_LIGHT0, 1, 1, 1);
    quad(-8, -8, 8, 8, -6);
    glPushMatrix();
    setup();
    wall_behind_camera(ccw_towards_light);
    glPopMatrix();
  });
  return image.at(kSize / 2, kSize / 2);
}

TEST(PathTracedGl, CulledFacesBlockLightOnlyOnTheSideGlDraws) {
  // A draw GL culls has one side: light passes its culled side, so an open or inside-out object
  // (xscreensaver's lavalite draws its lamp from the inside, the near wall culled) does not
  // shadow what GL shows lit. Light meets the occluder from +Z; the checks cover each input to
  // "which side GL culls": glCullFace, glFrontFace, a mirroring modelview and projection.
  auto cull = [](GLenum face, GLenum front) {
    return [=] {
      glEnable(GL_CULL_FACE);
      glCullFace(face);
      glFrontFace(front);
    };
  };
  auto lit = [](Rgba c) { return c.r > 120; };
  auto shadowed = [](Rgba c) { return c.r < 60; };
  // Culling off: solid from both sides, as before.
  const Rgba solid = wall_behind_occluder([] { glDisable(GL_CULL_FACE); }, false);
  EXPECT_PRED1(shadowed, solid) << solid;
  // Its front towards the light: light meets the drawn side.
  const Rgba front = wall_behind_occluder(cull(GL_BACK, GL_CCW), true);
  EXPECT_PRED1(shadowed, front) << front;
  // Its back towards the light: light meets the culled side and passes.
  const Rgba back = wall_behind_occluder(cull(GL_BACK, GL_CCW), false);
  EXPECT_PRED1(lit, back) << back;
  // The same winding with glFrontFace(GL_CW), or culling GL_FRONT: the side towards the light is
  // drawn again.
  const Rgba clockwise = wall_behind_occluder(cull(GL_BACK, GL_CW), false);
  EXPECT_PRED1(shadowed, clockwise) << clockwise;
  const Rgba front_culled = wall_behind_occluder(cull(GL_FRONT, GL_CCW), false);
  EXPECT_PRED1(shadowed, front_culled) << front_culled;
  // A mirroring modelview reverses the window winding: the vertices given counter-clockwise
  // towards the light are clockwise after glScalef(-1, 1, 1), so light meets the culled side.
  const Rgba mirrored = wall_behind_occluder(
      [&] {
        cull(GL_BACK, GL_CCW)();
        glScalef(-1, 1, 1);
      },
      true);
  EXPECT_PRED1(lit, mirrored) << mirrored;
  // So does a mirroring projection (left and right swapped).
  const Rgba mirrored_projection = wall_behind_occluder(
      cull(GL_BACK, GL_CCW), true, [] { glFrustum(0.577, -0.577, -0.577, 0.577, 1.0, 20.0); });
  EXPECT_PRED1(lit, mirrored_projection) << mirrored_projection;
}

TEST(PathTracedGl, AnEmitterGivesNoLightFromTheFaceGlCulls) {
  // The only light is GL emission: a large emissive wall behind the camera (out of view), facing
  // a diffuse wall in view; no GL light, no ambient. Both faces emit where the draw does not cull;
  // where it culls, the culled face is seen by no bounce ray, and next-event estimation must not
  // find it either (before: it did, MIS-weighted against a bounce that never could).
  auto lit_wall = [](const std::function<void()>& cull, bool front_towards_wall) {
    Image image = render(
        "path",
        [&] {
          camera_3d();
          glEnable(GL_LIGHTING);
          const float black[] = {0, 0, 0, 1}, white[] = {0.5f, 0.5f, 0.5f, 1};
          glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
          glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);  // (the frame before set white)
          glDisable(GL_CULL_FACE);
          quad(-8, -8, 8, 8, -6);
          cull();
          glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, white);
          wall_behind_camera(!front_towards_wall);  // front towards the lit wall: ccw from -Z
        },
        4);
    int sum = 0;
    for (int y = kSize / 2 - 2; y <= kSize / 2 + 2; ++y)
      for (int x = kSize / 2 - 2; x <= kSize / 2 + 2; ++x) sum += image.at(x, y).r;
    return sum / 25;
  };
  auto culling = [] {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
  };
  const int both_faces = lit_wall([] { glDisable(GL_CULL_FACE); }, false);
  const int drawn_face = lit_wall(culling, true);
  const int culled_face = lit_wall(culling, false);
  EXPECT_GT(both_faces, 60);
  EXPECT_GT(drawn_face, 60);
  EXPECT_NEAR(drawn_face, both_faces, 0.2 * both_faces);
  EXPECT_LT(culled_face, 8) << "drawn face " << drawn_face;
}

// GL's planar projection of everything onto `plane` from the light at `light` (homogeneous),
// as OpenGL demos build it, column-major for glMultMatrixf.
void shadow_matrix(const float plane[4], const float light[4], float m[16]) {
  const float dot =
      plane[0] * light[0] + plane[1] * light[1] + plane[2] * light[2] + plane[3] * light[3];
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      m[column * 4 + row] = (row == column ? dot : 0.0f) - light[row] * plane[column];
}

TEST(PathTracedGl, AFakePlanarShadowGivesWayToTheTracedOne) {
  // A floor, a small quad above it, and its planar shadow: the same quad drawn under the planar
  // shadow matrix (projective, singular) in black, over the floor. It is a fake shadow (class
  // `shadow`, docs/classification.md): path-traced mode does not draw it, and the traced shadow
  // darkens the floor where raster mode (Mesa) draws the black one.
  auto scene = [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    const float light_position[] = {1.0f, 4.0f, -3.0f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glBegin(GL_QUADS);  // the floor, y = -1
    glNormal3f(0, 1, 0);
    glVertex3f(-3, -1, -2);
    glVertex3f(3, -1, -2);
    glVertex3f(3, -1, -9);
    glVertex3f(-3, -1, -9);
    glEnd();
    auto occluder = [] {
      glBegin(GL_QUADS);
      glNormal3f(0, 1, 0);
      glVertex3f(-1.5f, 0.5f, -4.5f);
      glVertex3f(0.5f, 0.5f, -4.5f);
      glVertex3f(0.5f, 0.5f, -6.5f);
      glVertex3f(-1.5f, 0.5f, -6.5f);
      glEnd();
    };
    occluder();
    const float floor_plane[] = {0, 1, 0, 1};
    float m[16];
    shadow_matrix(floor_plane, light_position, m);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glColor3f(0, 0, 0);
    glPushMatrix();
    glMultMatrixf(m);
    occluder();
    glPopMatrix();
  };
  // The traced shadow of the quad lies there too, lit by GL's ambient alone; without ambient
  // occlusion (whose one sample per pixel can find the quad above and leave a pixel black) that
  // is a dark grey, not black.
  ::setenv("GLPT_AO", "0", 1);
  Image traced = render("path", scene);
  ::unsetenv("GLPT_AO");
  Image rasterized = render("raster", scene);
  auto black = [](Rgba c) { return c.r == 0 && c.g == 0 && c.b == 0; };
  const int shadow_pixels = rasterized.count(black);
  ASSERT_GT(shadow_pixels, 20);
  EXPECT_EQ(traced.count(black), 0) << "the fake shadow is not drawn";
  // The floor's pixels (what raster mode draws grey-lit, away from the quad) and the shadow's:
  // the traced shadow, lit by GL's ambient alone, is less than half as bright as the lit floor.
  double in_shadow = 0, lit = 0;
  int lit_count = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Rgba r = rasterized.at(x, y), t = traced.at(x, y);
      if (black(r)) {
        in_shadow += t.r + t.g + t.b;
      } else if (y < kSize / 3 && r.r > 0 && r.r == r.g && r.g == r.b) {
        lit += t.r + t.g + t.b;
        ++lit_count;
      }
    }
  ASSERT_GT(lit_count, 20);
  EXPECT_LT(in_shadow / shadow_pixels, 0.5 * lit / lit_count);
}

void lit_face_under(const std::function<void()>& projection) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  projection();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);  // directional, towards +Z: GL lights the face with N.L = 1
  quad(-0.5f, -0.5f, 0.5f, 0.5f, 0.0f);
}

TEST(PathTracedGl, LitFaceUnderAnIdentityOrFlippedProjectionIsLit) {
  // Both look down +Z at the face (the identity projection keeps z, glOrtho with near and far
  // swapped too): seen from behind its normal. GL lights it as its normal says; the tracer must
  // not shadow it with itself.
  const std::function<void()> projections[] = {[] {}, [] { glOrtho(-1, 1, -1, 1, 1, -1); }};
  for (const auto& projection : projections) {
    auto scene = [&] { lit_face_under(projection); };
    Image traced = render("path", scene), rasterized = render("raster", scene);
    const Rgba mesa = rasterized.at(kSize / 2, kSize / 2), glpt = traced.at(kSize / 2, kSize / 2);
    EXPECT_EQ(mesa.r, 214);  // 0.8 + 0.2 * 0.2
    EXPECT_NEAR(glpt.r, mesa.r, 12) << glpt;
  }
}

TEST(PathTracedGl, ClipPlanesCutTracedSurfacesWhereMesaDoes) {
  auto scene = [] {
    camera_3d();
    const double plane[] = {1.0, 0.5, 0.0, 0.1};  // keeps x + y / 2 >= -0.1, in eye space
    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    quad(-1, -1, 1, 1, -4);
  };
  Image traced = render("path", scene), rasterized = render("raster", scene);
  auto background = [](Rgba c) { return c == Rgba{0, 0, 64, 255}; };
  const int uncovered = rasterized.count(background);
  EXPECT_GT(uncovered, kSize * kSize / 2);  // the plane removes part of the quad
  EXPECT_LT(uncovered, kSize * kSize - 100);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      ASSERT_EQ(background(traced.at(x, y)), background(rasterized.at(x, y))) << x << "," << y;
}

TEST(PathTracedGl, ClassifyDebugTintsEachDrawByItsClass) {
  // GLPT_CLASSIFY_DEBUG=1: half of each fragment is its class's colour (docs/classification.md):
  // a white unlit quad in the 3-D view is static (blue 0.2, 0.4, 1), a white HUD quad in glOrtho
  // is an overlay (white): (1 + 0.2) / 2 = 0.6, (1 + 0.4) / 2 = 0.7, 1.
  auto scene = [] {
    camera_3d();
    glColor3f(1, 1, 1);
    quad(-2, -2, 2, 2, -5);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kSize, 0, kSize, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glRecti(0, 0, 8, 8);
  };
  for (const char* mode : {"raster", "path"}) {
    ::setenv("GLPT_CLASSIFY_DEBUG", "1", 1);
    const Image tinted = render(mode, scene);
    ::unsetenv("GLPT_CLASSIFY_DEBUG");
    const Image plain = render(mode, scene);
    EXPECT_EQ(plain.at(32, 32), (Rgba{255, 255, 255, 255})) << mode;
    const Rgba quad_pixel = tinted.at(32, 32);
    EXPECT_NEAR(quad_pixel.r, 0.6 * 255, 3) << mode << " " << quad_pixel;
    EXPECT_NEAR(quad_pixel.g, 0.7 * 255, 3) << mode << " " << quad_pixel;
    EXPECT_EQ(quad_pixel.b, 255) << mode;
    EXPECT_EQ(tinted.at(4, 4), (Rgba{255, 255, 255, 255})) << mode << ": the HUD is white";
  }
}

TEST(PathTracedGl, LinesAreDepthTestedAgainstTheTracedSurfaces) {
  // A lit quad at z = -5, a line in front of it and one behind it: only the front one shows.
  Image image = render("path", [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    quad(-1, -1, 1, 1, -5);
    glDisable(GL_LIGHTING);
    glColor3f(1, 0, 1);
    glBegin(GL_LINES);
    glVertex3f(-3, 0.25f, -4);  // in front
    glVertex3f(3, 0.25f, -4);
    glVertex3f(-3, -0.25f, -6);  // behind
    glVertex3f(3, -0.25f, -6);
    glEnd();
  });
  auto magenta = [](Rgba c) { return c.r == 255 && c.g == 0 && c.b == 255; };
  const int front_row = pixel_of(0.25f, -4), back_row = pixel_of(-0.25f, -6);
  int front = 0, back_over_quad = 0, back_outside = 0;
  for (int x = 0; x < kSize; ++x) {
    front += magenta(image.at(x, front_row)) ? 1 : 0;
    if (x > pixel_of(-0.9f, -5) && x < pixel_of(0.9f, -5))
      back_over_quad += magenta(image.at(x, back_row)) ? 1 : 0;
    else
      back_outside += magenta(image.at(x, back_row)) ? 1 : 0;
  }
  EXPECT_EQ(front, kSize);
  EXPECT_EQ(back_over_quad, 0);
  EXPECT_GT(back_outside, 10);
}

TEST(PathTracedGl, ClearsAndBackgroundsKeepTheirPlaceInTheRecord) {
  // A 2-D background drawn first stays behind the 3-D scene; a scissored clear after the scene
  // wipes it where it clears.
  Image image = render("path", [] {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kSize, 0, kSize, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(0, 0.6f, 0);
    quad(0, 0, kSize, kSize, 0);  // background, depth test off
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.577, 0.577, -0.577, 0.577, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    quad(-1, -1, 1, 1, -4);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 36, 36);
    glClearColor(1, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  });
  EXPECT_EQ(image.at(32, 32), (Rgba{255, 0, 255, 255}));   // scene, then cleared
  EXPECT_GT(image.at(40, 40).r, 150) << image.at(40, 40);  // scene
  EXPECT_EQ(image.at(60, 60), (Rgba{0, 153, 0, 255}));     // background
}

}  // namespace

namespace {

// The quad of quad() as an indexed draw from buffer objects (two triangles of a fan).
void buffer_quad(float x0, float y0, float x1, float y1, float z) {
  const float vertices[4][6] = {
      {x0, y0, z, 0, 0, 1}, {x1, y0, z, 0, 0, 1}, {x1, y1, z, 0, 0, 1}, {x0, y1, z, 0, 0, 1}};
  const GLushort indices[6] = {0, 1, 2, 0, 2, 3};
  GLuint buffers[2];
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof vertices, vertices, GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof vertices[0], nullptr);
  glNormalPointer(GL_FLOAT, sizeof vertices[0], reinterpret_cast<const void*>(3 * sizeof(float)));
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, nullptr);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDeleteBuffers(2, buffers);
}

}  // namespace

TEST(PathTracedGl, IndexedBufferDrawsAreTracedLikeTheirImmediateTwin) {
  // The same lit quad, once from glBegin/glEnd and once from glDrawElements over buffer
  // objects, side by side: the traced surfaces cover the same pixels and are lit alike.
  Image image = render("path", [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    quad(-2.2f, -1, -0.2f, 1, -5);
    buffer_quad(0.2f, -1, 2.2f, 1, -5);
  });
  for (int y = pixel_of(-0.8f, -5); y <= pixel_of(0.8f, -5); y += 4) {
    const Rgba left = image.at(pixel_of(-1.2f, -5), y);
    const Rgba right = image.at(pixel_of(1.2f, -5), y);
    EXPECT_GT(left.r, 100) << left;
    EXPECT_NEAR(right.r, left.r, 12) << "row " << y << ": " << right << " vs " << left;
  }
  const auto lit = [](Rgba c) { return c.r > 60; };
  Image left_only = render("path", [] {
    camera_3d();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    quad(-2.2f, -1, -0.2f, 1, -5);
  });
  EXPECT_NEAR(image.count(lit), 2 * left_only.count(lit), 8);
}
