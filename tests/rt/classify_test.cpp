// Classification and identity of draws (rt_core/scene/classify.hpp, draw_identity.hpp), on
// records built by hand: each test is a GL technique and the class GL state makes it.
#include "rt_core/scene/classify.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <string>
#include <vector>

#include "record_builder.hpp"
#include "rt_core/scene/classify_log.hpp"
#include "rt_core/scene/draw_identity.hpp"
#include "rt_core/scene/scene_builder.hpp"

namespace glpt::rt {
namespace {

using test::RecordBuilder;

// The kinds (by name) and ids of a record's drawing commands, in order.
struct Labels {
  std::vector<std::string> kinds;
  std::vector<uint64_t> ids;
};
Labels classify(const RecordBuilder& b, DrawIdentities* identities) {
  FrameClassification c;
  classify_frame(b.record, b.drawable, identities, c);
  if (identities != nullptr) identities->end_frame();
  Labels out;
  for (const CommandLabel& label : c.labels) {
    if (label.kind == DrawKind::kNone) continue;
    out.kinds.push_back(draw_kind_name(label.kind));
    out.ids.push_back(label.id);
  }
  return out;
}

std::vector<std::string> repeat(const std::string& kind, size_t n) {
  return std::vector<std::string>(n, kind);
}

RecordBuilder scene_builder() {
  RecordBuilder b(64, 64);
  b.transform.projection = glm::perspective(1.0f, 1.0f, 0.5f, 100.0f);
  b.raster.ops.depth_test = true;
  return b;
}

// A unit cube's six faces as one draw, under the current modelview.
void cube(RecordBuilder& b, glm::vec4 color = glm::vec4(1)) {
  std::vector<glm::vec3> p;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-0.5f, 0.5f}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (auto [a, c] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        glm::vec3 q;
        q[axis] = side;
        q[u] = a ? 0.5f : -0.5f;
        q[v] = c ? 0.5f : -0.5f;
        p.push_back(q);
      }
    }
  b.draw(GL_QUADS, p, {0, 0, 1}, color);
}

glm::mat4 camera_at(glm::vec3 eye) {
  return glm::lookAt(eye, glm::vec3(0, 0, -10), glm::vec3(0, 1, 0));
}

TEST(DrawIdentity, AStaticWorldUnderAMovingCameraStaysStaticWithItsIds) {
  DrawIdentities identities;
  std::vector<uint64_t> first_ids;
  for (int frame = 0; frame < 4; ++frame) {
    RecordBuilder b = scene_builder();
    const glm::mat4 view = camera_at(glm::vec3(0.3f * frame, 0.1f * frame, 0.0f));
    for (int object = 0; object < 5; ++object) {
      b.transform.modelview =
          glm::translate(view, glm::vec3(object * 2.0f - 4.0f, 0.0f, -10.0f - object));
      cube(b);
    }
    const Labels labels = classify(b, &identities);
    EXPECT_EQ(labels.kinds, repeat("static", 5)) << "frame " << frame;
    if (frame == 0) first_ids = labels.ids;
    EXPECT_EQ(labels.ids, first_ids) << "frame " << frame;
  }
  EXPECT_EQ(std::set<uint64_t>(first_ids.begin(), first_ids.end()).size(), 5u);
}

TEST(DrawIdentity, ALoneObjectTurningBeforeAStillCameraMoves) {
  DrawIdentities identities;
  for (int frame = 0; frame < 3; ++frame) {
    RecordBuilder b = scene_builder();
    b.transform.modelview = glm::rotate(glm::translate(glm::mat4(1), glm::vec3(0, 0, -5)),
                                        0.2f * frame, glm::vec3(0, 1, 0));
    cube(b);
    EXPECT_EQ(classify(b, &identities).kinds, repeat(frame == 0 ? "static" : "moving", 1))
        << "frame " << frame;
  }
}

TEST(DrawIdentity, AMovingObjectInAStaticWorldUnderAMovingCamera) {
  DrawIdentities identities;
  for (int frame = 0; frame < 3; ++frame) {
    RecordBuilder b = scene_builder();
    const glm::mat4 view = camera_at(glm::vec3(0.5f * frame, 0.0f, 0.0f));
    for (int object = 0; object < 4; ++object) {
      b.transform.modelview = glm::translate(view, glm::vec3(object * 2.0f - 3.0f, -2, -12));
      cube(b);
    }
    b.transform.modelview = glm::translate(view, glm::vec3(0, 0.3f * frame, -8));
    cube(b, glm::vec4(1, 0, 0, 1));
    std::vector<std::string> want = repeat("static", 4);
    want.push_back(frame == 0 ? "static" : "moving");
    EXPECT_EQ(classify(b, &identities).kinds, want) << "frame " << frame;
  }
}

TEST(DrawIdentity, IdenticalMeshesInShuffledOrderKeepTheirIdsAndOneJumpsFar) {
  DrawIdentities identities;
  const std::vector<glm::vec3> places = {{-4, 0, -10}, {-2, 0, -10}, {0, 0, -10}, {2, 0, -10}};
  std::vector<uint64_t> id_of_place(places.size(), 0);
  const std::vector<std::vector<int>> orders = {
      {0, 1, 2, 3}, {2, 0, 3, 1}, {3, 2, 1, 0}, {1, 3, 0, 2}};
  for (size_t frame = 0; frame < orders.size(); ++frame) {
    RecordBuilder b = scene_builder();
    for (int place : orders[frame]) {
      glm::vec3 at = places[place];
      if (place == 3 && frame >= 2) at = glm::vec3(40, 0, -60);  // jumps far at frame 2
      b.transform.modelview = glm::translate(glm::mat4(1), at);
      cube(b);
    }
    const Labels labels = classify(b, &identities);
    for (size_t k = 0; k < orders[frame].size(); ++k) {
      const int place = orders[frame][k];
      if (frame == 0) id_of_place[place] = labels.ids[k];
      EXPECT_EQ(labels.ids[k], id_of_place[place]) << "frame " << frame << " place " << place;
      const bool jumped = place == 3 && frame == 2;
      EXPECT_EQ(labels.kinds[k], jumped ? "moving" : "static")
          << "frame " << frame << " place " << place;
    }
  }
}

TEST(DrawIdentity, ADeformingMeshKeepsItsIdAndAMeshDrawnTwiceHasTwo) {
  DrawIdentities identities;
  uint64_t wave_id = 0;
  for (int frame = 0; frame < 3; ++frame) {
    RecordBuilder b = scene_builder();
    b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6));
    std::vector<glm::vec3> grid;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (auto [di, dj] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
          grid.push_back({(i + di) * 0.5f - 1.0f, (j + dj) * 0.5f - 1.0f,
                          0.2f * std::sin(float(i + di + frame))});
    b.draw(GL_QUADS, grid, {0, 0, 1}, glm::vec4(1));
    b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(-3, 0, -8));
    cube(b);
    b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(3, 0, -8));
    cube(b);
    const Labels labels = classify(b, &identities);
    EXPECT_EQ(labels.kinds[0], frame == 0 ? "static" : "deforming");
    EXPECT_EQ(labels.kinds[1], "static");
    EXPECT_EQ(labels.kinds[2], "static");
    EXPECT_NE(labels.ids[1], labels.ids[2]);
    if (frame == 0) wave_id = labels.ids[0];
    EXPECT_EQ(labels.ids[0], wave_id);
  }
}

TEST(DrawIdentity, ADrawCulledForFramesComesBackWithItsId) {
  DrawIdentities identities;
  uint64_t id = 0;
  for (int frame = 0; frame < 6; ++frame) {
    RecordBuilder b = scene_builder();
    b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(-2, 0, -8));
    cube(b);
    if (frame == 0 || frame >= 4) {
      b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(2, 0, -8));
      cube(b, glm::vec4(0, 1, 0, 1));
      const Labels labels = classify(b, &identities);
      ASSERT_EQ(labels.ids.size(), 2u);
      if (frame == 0) id = labels.ids[1];
      EXPECT_EQ(labels.ids[1], id) << "frame " << frame;
      EXPECT_EQ(labels.kinds[1], "static");
    } else {
      classify(b, &identities);
    }
  }
}

TEST(DrawIdentity, LostDrawsAreBounded) {
  DrawIdentities identities(DrawIdentities::Limits{10, 32});
  for (int frame = 0; frame < 50; ++frame) {
    RecordBuilder b = scene_builder();
    for (int k = 0; k < 8; ++k) {  // new geometry every frame: nothing comes back
      b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(k, frame, -10));
      b.quad({0, 0, 0}, {1.0f + frame, 0, 0}, {0, 1.0f + k, 0}, glm::vec4(1));
    }
    classify(b, &identities);
  }
  EXPECT_LE(identities.tracked(), 8u + 32u);
}

TEST(ClassifyKinds, FakeShadowsAreShadowsAndNotDrawnInPathTracedMode) {
  RecordBuilder b = scene_builder();
  b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6));
  b.quad({-3, -1, -3}, {6, 0, 0}, {0, 0, 6}, glm::vec4(1));  // the ground: static
  // A planar shadow: the point-light shadow matrix onto y = -1 (projective), dark, blended.
  const glm::vec4 light(0, 5, 0, 1), plane(0, 1, 0, 1);
  glm::mat4 shadow = glm::dot(plane, light) * glm::mat4(1.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) shadow[c][r] -= light[r] * plane[c];
  b.transform.modelview = b.transform.modelview * shadow;
  b.raster.ops.blend = true;
  b.raster.ops.blend_src_rgb = GL_SRC_ALPHA;
  b.raster.ops.blend_dst_rgb = GL_ONE_MINUS_SRC_ALPHA;
  cube(b, glm::vec4(0, 0, 0, 0.5f));
  b.raster.ops.blend = false;
  // A stencil shadow volume pass and the darkening quad.
  b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6));
  b.raster.ops.color_write = {false, false, false, false};
  b.raster.ops.depth_write = false;
  b.raster.ops.stencil_test = true;
  b.raster.ops.stencil_depth_pass = GL_INCR;
  cube(b);
  b.raster.ops.color_write = {true, true, true, true};
  b.raster.ops.stencil_depth_pass = GL_KEEP;
  b.raster.ops.stencil_func = GL_NOTEQUAL;
  b.raster.ops.blend = true;
  b.raster.ops.depth_test = false;
  b.transform.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f);
  b.transform.modelview = glm::mat4(1);
  b.quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::vec4(0, 0, 0, 0.5f));
  FrameClassification c;
  classify_frame(b.record, b.drawable, nullptr, c);
  std::vector<std::string> kinds;
  std::vector<DrawClass> classes;
  for (size_t i = 0; i < c.labels.size(); ++i) {
    kinds.push_back(draw_kind_name(c.labels[i].kind));
    classes.push_back(c.classes[i]);
  }
  EXPECT_EQ(kinds, (std::vector<std::string>{"static", "shadow", "shadow", "shadow"}));
  EXPECT_EQ(classes, (std::vector<DrawClass>{DrawClass::kTraced, DrawClass::kShadow,
                                             DrawClass::kShadow, DrawClass::kShadow}));
}

// EXT_stencil_two_side: a z-fail volume drawn in one pass whose back faces alone count (the
// front faces keep) is a shadow volume; the same pass without two-sided stencil counts nothing and
// is only a colourless draw.
TEST(ClassifyKinds, ATwoSidedStencilVolumeIsAShadowWhicheverFaceCounts) {
  RecordBuilder b = scene_builder();
  b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6));
  b.quad({-3, -1, -3}, {6, 0, 0}, {0, 0, 6}, glm::vec4(1));
  b.raster.ops.color_write = {false, false, false, false};
  b.raster.ops.depth_write = false;
  b.raster.ops.stencil_test = true;
  b.raster.ops.stencil_two_side = true;
  b.raster.ops.back_stencil.depth_fail = GL_INCR_WRAP;
  cube(b);
  b.raster.ops.stencil_two_side = false;
  cube(b);
  FrameClassification c;
  classify_frame(b.record, b.drawable, nullptr, c);
  std::vector<std::string> kinds;
  for (const auto& label : c.labels) kinds.push_back(draw_kind_name(label.kind));
  EXPECT_EQ(kinds, (std::vector<std::string>{"static", "shadow", "hidden"}));
}

TEST(ClassifyKinds, PassesDecalsParticlesOverlaysAndViewModels) {
  RecordBuilder b = scene_builder();
  b.clear(glm::vec4(0));
  b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6));
  b.quad({-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, glm::vec4(1));  // wall: static
  // A lightmap pass over the same wall: GL_EQUAL, no depth writes, modulating.
  b.raster.ops.depth_write = false;
  b.raster.ops.depth_func = GL_EQUAL;
  b.raster.ops.blend = true;
  b.raster.ops.blend_src_rgb = GL_DST_COLOR;
  b.raster.ops.blend_dst_rgb = GL_ZERO;
  b.quad({-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, glm::vec4(0.5f));  // multipass
  // A dynamic light on half of it: GL_LEQUAL, additive, its own vertices among the wall's.
  b.raster.ops.depth_func = GL_LEQUAL;
  b.raster.ops.blend_src_rgb = GL_ONE;
  b.raster.ops.blend_dst_rgb = GL_ONE;
  b.draw(GL_TRIANGLES, {{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}}, {0, 0, 1}, glm::vec4(0.3f));
  // A blended decal with polygon offset, and one without depth writes (a small other quad).
  b.raster.ops.blend_src_rgb = GL_SRC_ALPHA;
  b.raster.ops.blend_dst_rgb = GL_ONE_MINUS_SRC_ALPHA;
  b.raster.primitive.offset_fill = true;
  b.raster.primitive.offset_factor = b.raster.primitive.offset_units = -1.0f;
  b.quad({0, 0, 0}, {0.3f, 0, 0}, {0, 0.3f, 0}, glm::vec4(0, 0, 0, 0.7f));
  b.raster.primitive.offset_fill = false;
  b.quad({-1, 0, 0}, {0.3f, 0, 0}, {0, 0.3f, 0}, glm::vec4(0, 0, 0, 0.7f));
  // A glass pane in front: blended, depth writes on.
  b.raster.ops.depth_write = true;
  b.quad({-1, -1, 2}, {2, 0, 0}, {0, 2, 0}, glm::vec4(0.5f, 0.5f, 1, 0.3f));
  // Particles: one draw of twelve small quads facing the camera, additive, no depth writes.
  b.raster.ops.depth_write = false;
  b.raster.ops.blend_src_rgb = GL_ONE;
  b.raster.ops.blend_dst_rgb = GL_ONE;
  std::vector<glm::vec3> sparks;
  for (int k = 0; k < 12; ++k) {
    const glm::vec3 c(-1.5f + 0.25f * k, 0.1f * k, 1.0f);
    for (glm::vec3 d : {glm::vec3(0, 0, 0), {0.1f, 0, 0}, {0.1f, 0.1f, 0}, {0, 0.1f, 0}})
      sparks.push_back(c + d);
  }
  b.draw(GL_QUADS, sparks, {0, 0, 1}, glm::vec4(1, 0.6f, 0.2f, 1));
  b.raster.ops.blend = false;
  b.raster.ops.depth_write = true;
  // A view model in its own depth range, then a crosshair drawn without the depth test.
  b.transform.depth_far = 0.1f;
  b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0.3f, -0.3f, -1));
  cube(b);
  b.transform.depth_far = 1.0f;
  b.raster.ops.depth_test = false;
  b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -2));
  b.quad({-0.02f, -0.02f, 0}, {0.04f, 0, 0}, {0, 0.04f, 0}, glm::vec4(1));
  // A HUD bar in glOrtho.
  b.transform.projection = glm::ortho(0.0f, 64.0f, 0.0f, 64.0f, -1.0f, 1.0f);
  b.transform.modelview = glm::mat4(1);
  b.quad({0, 0, 0}, {64, 0, 0}, {0, 8, 0}, glm::vec4(0, 1, 0, 1));
  const Labels labels = classify(b, nullptr);
  EXPECT_EQ(labels.kinds,
            (std::vector<std::string>{"static", "multipass", "multipass", "decal", "decal",
                                      "blended", "particles", "viewmodel", "overlay", "overlay"}));
}

TEST(ClassifyKinds, TheWorldIsTheMainCameraNotTheViewModelOrAMenuModel) {
  RecordBuilder b = scene_builder();
  b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6));
  cube(b);  // the world: 24 vertices
  b.clear(glm::vec4(0), GL_DEPTH_BUFFER_BIT);
  // A view model with its own projection and more vertices than the world.
  b.transform.projection = glm::perspective(0.6f, 1.0f, 0.05f, 10.0f);
  for (int k = 0; k < 3; ++k) {
    b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0.3f, -0.3f, -1.0f - k));
    cube(b);
  }
  FrameClassification c;
  classify_frame(b.record, b.drawable, nullptr, c);
  EXPECT_EQ(c.classes[0], DrawClass::kTraced);
  EXPECT_EQ(c.labels[2].kind, DrawKind::kViewmodel);
  EXPECT_EQ(c.camera.projection, glm::perspective(1.0f, 1.0f, 0.5f, 100.0f));
}

}  // namespace
}  // namespace glpt::rt

namespace glpt::rt {
namespace {

std::shared_ptr<rec::TextureObjectSnapshot> texture_of_version(uint64_t version) {
  auto t = std::make_shared<rec::TextureObjectSnapshot>();
  t->target = GL_TEXTURE_2D;
  t->content_version = version;
  return t;
}

// A wall with per-vertex texture coordinates `st` on unit 0.
std::shared_ptr<rec::VertexData> textured_wall(float s_scale) {
  auto v = std::make_shared<rec::VertexData>();
  v->mode = GL_QUADS;
  for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
    v->position.push_back(glm::vec4(c.x * 4 - 2, c.y * 4 - 2, 0, 1));
    v->tex_coord[0].push_back(glm::vec4(c.x * s_scale, c.y, 0, 1));
  }
  v->normal = {glm::vec3(0, 0, 1)};
  v->color = {glm::vec4(1)};
  v->primitives.push_back({0, 4});
  return v;
}

// A 2 x 1 RGBA texture: an opaque texel and one of alpha `alpha`.
std::shared_ptr<rec::TextureObjectSnapshot> half_see_through_texture(uint8_t alpha) {
  auto image = std::make_shared<rec::TextureImage>();
  image->width = 2;
  image->height = 1;
  image->internal_format = GL_RGBA8;
  image->texels = {255, 255, 255, 255, 255, 255, 255, alpha};
  auto t = std::make_shared<rec::TextureObjectSnapshot>();
  t->content_version = 100u + alpha;
  t->faces = {{image}};
  t->sampler.min_filter = GL_NEAREST;
  return t;
}

TEST(ClassifyKinds, ABlendedSolidWithSeeThroughTexelsIsSplitByAlpha) {
  // GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA with depth writes, a texture with a see-through texel:
  // traced where opaque (into the G-buffer pass and the TLAS, whose rays test alpha >= 254.5 /
  // 255) and drawn again after the trace for the rest. Not split: without depth writes (a glass
  // pane, a particle), with a vertex alpha below 1, with additive blending, with an alpha test
  // that opaque fragments fail.
  struct Case {
    const char* what;
    bool depth_write = true;
    float vertex_alpha = 1.0f;
    uint32_t blend_dst = GL_ONE_MINUS_SRC_ALPHA;
    uint32_t alpha_func = 0;  // 0: no alpha test
    bool split = true;
  };
  for (const Case& c :
       {Case{"split"}, Case{"no depth writes", false, 1.0f, GL_ONE_MINUS_SRC_ALPHA, 0, false},
        Case{"vertex alpha 0.5", true, 0.5f, GL_ONE_MINUS_SRC_ALPHA, 0, false},
        Case{"additive", true, 1.0f, GL_ONE, 0, false},
        Case{"alpha test GL_GREATER 0.5", true, 1.0f, GL_ONE_MINUS_SRC_ALPHA, GL_GREATER, true},
        Case{"alpha test GL_LESS 0.5", true, 1.0f, GL_ONE_MINUS_SRC_ALPHA, GL_LESS, false}}) {
    RecordBuilder b = scene_builder();
    b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6));
    b.draw(textured_wall(1.0f));  // an opaque wall behind: the world
    b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -4));
    b.texturing.units[0].target = GL_TEXTURE_2D;
    b.texturing.units[0].texture = half_see_through_texture(128);
    b.raster.ops.depth_write = c.depth_write;
    b.raster.ops.blend = true;
    b.raster.ops.blend_src_rgb = b.raster.ops.blend_src_alpha = GL_SRC_ALPHA;
    b.raster.ops.blend_dst_rgb = b.raster.ops.blend_dst_alpha = c.blend_dst;
    b.raster.ops.alpha_test = c.alpha_func != 0;
    b.raster.ops.alpha_func = c.alpha_func != 0 ? c.alpha_func : GL_ALWAYS;
    b.raster.ops.alpha_ref = 0.5f;
    std::shared_ptr<rec::VertexData> quad = textured_wall(1.0f);
    quad->color = {glm::vec4(1, 1, 1, c.vertex_alpha)};
    b.draw(quad);
    SceneBuild build;
    build_trace_scene(b.record, b.drawable, build);
    SCOPED_TRACE(c.what);
    EXPECT_EQ(build.classes[1], c.split ? DrawClass::kSplitByAlpha : DrawClass::kBlended);
    EXPECT_EQ(build.split_by_alpha[1], c.split ? 1 : 0);
    EXPECT_EQ(build.traced[1], c.split ? 1 : 0);
    const bool in_gbuffer_pass =
        std::count(build.gbuffer_pass.begin(), build.gbuffer_pass.end(), size_t{1}) == 1;
    EXPECT_EQ(in_gbuffer_pass, c.split);
    EXPECT_EQ(std::count(build.after_trace.begin(), build.after_trace.end(), size_t{1}), 1);
    ASSERT_EQ(build.scene.instances.size(), c.split ? 2u : 1u);
    if (c.split) {
      EXPECT_EQ(build.scene.instances[1].surface.alpha_func, uint32_t{GL_GEQUAL});
      EXPECT_FLOAT_EQ(build.scene.instances[1].surface.alpha_ref, 254.5f / 255.0f);
    }
    // GLPT_CLASSIFY_LOG says which blended draws are split.
    FrameClassification classification;
    classify_frame(b.record, b.drawable, nullptr, classification);
    char path[] = "/tmp/glpt_classify_log_XXXXXX";
    const int fd = ::mkstemp(path);
    ASSERT_GE(fd, 0);
    ::close(fd);
    {
      std::string error;
      ClassifyLog log(path, &error);
      ASSERT_TRUE(error.empty()) << error;
      log.write(classification);
    }
    std::ifstream in(path);
    std::string wall, blended;
    std::getline(in, wall);
    std::getline(in, blended);
    ::unlink(path);
    EXPECT_EQ(wall.find("split_by_alpha"), std::string::npos) << wall;
    EXPECT_NE(blended.find("\"class\": \"blended\""), std::string::npos) << blended;
    EXPECT_EQ(blended.find("\"split_by_alpha\": true") != std::string::npos, c.split) << blended;
  }
}

TEST(ClassifyKinds, ALightmapPassIsFoldedIntoTheSurfaceForRays) {
  RecordBuilder b = scene_builder();
  b.transform.modelview = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6));
  b.texturing.units[0].target = GL_TEXTURE_2D;
  b.texturing.units[0].texture = texture_of_version(1);  // the wall's texture
  b.draw(textured_wall(1.0f));
  b.texturing.units[0].texture = texture_of_version(2);  // the lightmap, its own coordinates
  b.raster.ops.depth_write = false;
  b.raster.ops.depth_func = GL_EQUAL;
  b.raster.ops.blend = true;
  b.raster.ops.blend_src_rgb = GL_DST_COLOR;
  b.raster.ops.blend_dst_rgb = GL_ZERO;
  b.draw(textured_wall(0.25f));
  SceneBuild build;
  build_trace_scene(b.record, b.drawable, build);
  EXPECT_EQ(build.classes[1], DrawClass::kBlended) << "the pass is still drawn over the trace";
  ASSERT_EQ(build.scene.instances.size(), 1u);
  const Instance& wall = build.scene.instances[0];
  ASSERT_TRUE(wall.surface.units[0].texture && wall.surface.units[1].texture);
  EXPECT_EQ(wall.surface.units[0].texture->content_version, 1u);
  EXPECT_EQ(wall.surface.units[1].texture->content_version, 2u);
  EXPECT_EQ(wall.surface.units[1].env_mode, uint32_t{GL_MODULATE});
  const Geometry& g = *wall.geometry;
  ASSERT_EQ(g.texcoords[1].size(), g.positions.size());
  for (size_t k = 0; k < g.positions.size(); ++k) {
    // The pass's coordinates follow the same vertices: s = (x + 2) / 4 * 0.25.
    EXPECT_FLOAT_EQ(g.texcoords[1][k].x, (g.positions[k].x + 2.0f) / 4.0f * 0.25f);
    EXPECT_FLOAT_EQ(g.texcoords[0][k].x, (g.positions[k].x + 2.0f) / 4.0f);
  }

  // An additive pass (light) and a pass over other triangles are not folded.
  RecordBuilder c = scene_builder();
  c.transform.modelview = b.transform.modelview;
  c.texturing = b.texturing;
  c.texturing.units[0].texture = texture_of_version(1);
  c.draw(textured_wall(1.0f));
  c.texturing.units[0].texture = texture_of_version(2);
  c.raster = b.raster;
  c.raster.ops.blend_src_rgb = GL_ONE;
  c.raster.ops.blend_dst_rgb = GL_ONE;
  c.draw(textured_wall(0.25f));
  SceneBuild unfolded;
  build_trace_scene(c.record, c.drawable, unfolded);
  ASSERT_EQ(unfolded.scene.instances.size(), 1u);
  EXPECT_FALSE(unfolded.scene.instances[0].surface.units[1].texture);
}

}  // namespace
}  // namespace glpt::rt
