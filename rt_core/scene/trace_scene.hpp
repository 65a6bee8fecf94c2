// The path tracer's scene, derived from a frame record by scene_builder.cpp: the traced draws'
// triangles as geometry (the BLASes, for shadow, bounce and AO rays; primary visibility comes
// from the G-buffer the raster pipelines draw), GL's lights per record state, and per-state data
// the trace pass needs. Everything is in GL eye space: each instance carries the modelview it
// was drawn with, so a moving camera only changes instance transforms, never geometry.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "gl/gl_enums.h"
#include "rt_core/record/gl_state.hpp"
#include "rt_core/record/texture.hpp"

namespace glpt::rt {

// How a material takes the per-vertex colour (GL_COLOR_MATERIAL, or lighting disabled).
enum class ColorSource : uint32_t {
  kNone = 0,               // material values as given
  kAmbientAndDiffuse = 1,  // vertex colour replaces ambient and diffuse
  kDiffuse = 2,
  kAmbient = 3,
  kEmission = 4,
  kSpecular = 5,
};

struct Material {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
  glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  glm::vec4 specular{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;  // GL Blinn-Phong exponent, 0..128
  // false: GL_LIGHTING was disabled; at bounce hits the surface reflects as a diffuse surface of
  // its vertex colour (see docs/architecture.md, "unlit policy").
  bool lit = true;
  ColorSource color_source = ColorSource::kNone;
  // Two-sided lighting: the index (in the geometry's table) of the material of faces seen from
  // behind; kSameForBack: this one.
  static constexpr uint32_t kSameForBack = ~0u;
  uint32_t back = kSameForBack;

  bool operator==(const Material&) const = default;
};

// A triangle soup. Triangle t uses vertices 3t, 3t+1, 3t+2; GL_FLAT is already resolved (the
// provoking vertex's normal and colour are on all three vertices). Positions are in object space,
// or in eye space for draws under a projective modelview (the TLAS cannot hold a projective
// transform), whose instance transform is then the identity.
struct Geometry {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // not necessarily unit length
  std::vector<glm::vec4> colors;   // current colour per vertex (used per color_source)
  // Each texture unit's coordinates per vertex after texgen and the texture matrix (empty when
  // the geometry's draws have no texture on that unit).
  std::array<std::vector<glm::vec4>, rec::kMaxTextureUnits> texcoords;
  std::vector<uint32_t> material_ids;  // one per triangle, index into `materials`
  std::vector<Material> materials;
  // Identity of the shape (positions, triangle order): geometries with equal shape hashes share
  // one acceleration structure, so recolouring (new colours, normals, materials) never rebuilds
  // a BLAS.
  uint64_t shape_hash = 0;
  // Identity of the shading data (normals, colours, materials) of that shape.
  uint64_t shading_hash = 0;
  // The stable identities of the draws it is made of (draw_identity.hpp), hashed; 0 when one of
  // them has none. The same object in the previous frame had the same lineage, so a deformed
  // shape (a new shape_hash, the same triangle count) refits that frame's BLAS instead of
  // building one (BlasCache::prepare).
  uint64_t lineage = 0;
  // The arrays are left empty because the tracer holds this shape and shading already (found by
  // their hashes, scene_builder.hpp: KnownGeometry).
  bool resident = false;

  size_t triangle_count() const { return positions.size() / 3; }
};

// A texture unit as rays see it: its texture (any target) and environment.
struct TracedUnit {
  // The texture the unit samples (GL_TEXTURE_1D, _2D, _3D or _CUBE_MAP); null: none, or a depth
  // texture with comparison on, which rays do not sample.
  std::shared_ptr<const rec::TextureObjectSnapshot> texture;
  float lod_bias = 0.0f;            // the unit's GL_TEXTURE_LOD_BIAS
  uint32_t env_mode = GL_MODULATE;  // GL_TEXTURE_ENV_MODE

  bool operator==(const TracedUnit&) const = default;
};

// What rays see of a traced draw besides its triangles (docs/light-transport.md, "Textures in
// the tracer"): its texture units (a base texture, a lightmap or detail texture, an environment
// map: the multitexture of GL 1.x programs), the alpha test and the user clip planes. Draws that
// differ in it are separate instances.
struct TracedSurface {
  static constexpr size_t kUnits = rec::kMaxTextureUnits;
  std::array<TracedUnit, kUnits> units;
  uint32_t alpha_func = 0;  // GL alpha test function, 0 when the alpha test is off
  float alpha_ref = 0.0f;
  // The enabled GL_CLIP_PLANEi in eye space, packed (the first clip_plane_count are used, the
  // rest stay zero so equal clipping compares equal).
  static constexpr size_t kMaxClipPlanes = 6;
  uint32_t clip_plane_count = 0;
  std::array<glm::vec4, kMaxClipPlanes> clip_planes{};

  // GL's face culling as rays see it (docs/light-transport.md, "Culled faces"): the side of
  // its triangles GL discards, named by the object-space winding the triangle shows from that
  // side (counter-clockwise: the side its right-handed normal (p1 - p0) x (p2 - p0) points to).
  // The modelview's and the projection's mirrors and glFrontFace are folded in, so it is the
  // side the camera never sees. Rays looking out from a surface (bounces, ambient occlusion) see
  // only the other side; shadow rays, which stand for light arriving, are blocked only by faces
  // that light meets on their drawn side.
  enum class CulledSide : uint8_t { kNone, kCounterClockwise, kClockwise };
  CulledSide culled_side = CulledSide::kNone;

  // Rays must test candidate hits on it (alpha test, clip planes): not an opaque TLAS instance.
  bool tests_candidates() const { return alpha_func != 0 || clip_plane_count != 0; }
  bool operator==(const TracedSurface&) const = default;
};

struct Instance {
  std::shared_ptr<const Geometry> geometry;
  glm::mat4 modelview{1.0f};  // object -> eye space at draw time
  // The record state whose lights light this geometry where bounce rays hit it.
  uint32_t state = 0;
  TracedSurface surface;
  // The sky (DrawClass::kSky): not seen by the world's rays, only looked up, from the eye, by
  // rays that miss the world (the sky is drawn around the camera).
  bool sky = false;
  // The record states of its draws, ascending (several where draws of other states were merged
  // into one geometry): the G-buffer's pixels of this geometry carry one of them.
  std::vector<uint32_t> draw_states;
};

// A GL light in eye space, with its GL parameters (already transformed by the modelview that was
// current when glLight(GL_POSITION / GL_SPOT_DIRECTION) was called, as GL specifies).
struct Light {
  glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f};  // w == 0: directional (towards the light)
  glm::vec4 ambient{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 diffuse{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec4 specular{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec3 spot_direction{0.0f, 0.0f, -1.0f};
  float spot_exponent = 0.0f;
  float spot_cutoff = 180.0f;  // degrees; 180 = not a spot light
  float constant_attenuation = 1.0f;
  float linear_attenuation = 0.0f;
  float quadratic_attenuation = 0.0f;

  bool operator==(const Light&) const = default;
};

// What the trace pass needs of one record state (pixels of the G-buffer and instances refer to
// record states by index).
struct TraceState {
  glm::vec4 global_ambient{0.2f, 0.2f, 0.2f, 1.0f};  // GL_LIGHT_MODEL_AMBIENT
  std::vector<uint32_t> lights;                      // indices into TraceScene::lights
  // Where the viewer is in eye space, for the side secondary rays leave a surface from and for
  // the specular term: a point (w = 1, the centre of a perspective projection) or a direction
  // towards the viewer (w = 0, parallel projections: GL's infinite viewer, +Z).
  glm::vec4 viewer{0.0f, 0.0f, 0.0f, 1.0f};
  uint32_t fog_mode = 0;  // 0 off, 1 linear, 2 exp, 3 exp2 (lit pixels; unlit ones are fogged)
  glm::vec4 fog_color{0.0f};
  glm::vec4 fog_params{0.0f};  // density, start, end, 1 / (end - start)
  uint32_t targets = 0;        // colour buffers its draws write: bit 0 front, bit 1 back
  bool local_viewer = false;   // GL_LIGHT_MODEL_LOCAL_VIEWER (the GL-parity evaluation)
  bool two_side = false;       // GL_LIGHT_MODEL_TWO_SIDE
  // GL_LIGHT_MODEL_COLOR_CONTROL is GL_SEPARATE_SPECULAR_COLOR: specular is added after
  // texturing (GL_SINGLE_COLOR: the texture environment applies to it too).
  bool separate_specular = false;
  // Its material reflects specularly: a specular colour on either face, or GL_COLOR_MATERIAL
  // tracking the specular colour (a texture may still make a texel's specular ~0).
  bool specular_material = false;
  // What the denoiser needs to find the state's pixels in the previous frame
  // (shaders/svgf_temporal.comp), from the identity of its first traced draw: history_id names
  // the object (a history is only taken from pixels of the same id); 0 for states with no traced
  // draw. With has_previous, to_previous_eye maps this frame's eye space to the previous frame's
  // (previous modelview x inverse of this one: a static object under a moving camera follows the
  // camera, a moving object its own motion), where previous_projection and viewport place it on
  // screen.
  uint32_t history_id = 0;
  bool has_previous = false;
  glm::mat4 to_previous_eye{1.0f};
  glm::mat4 previous_projection{1.0f};
  std::array<int32_t, 4> viewport{0, 0, 0, 0};
};

struct TraceScene {
  uint32_t width = 0, height = 0;  // drawable size in pixels
  // Distinct enabled GL lights of the traced draws' states (a lit scene without any: none, or the
  // default light if asked for), shared by the states that list them.
  std::vector<Light> lights;
  std::vector<TraceState> states;  // one per record state
  std::vector<Instance> instances;
  // Colour buffers to write where a pixel was traced in earlier samples but not in this frame's
  // G-buffer (the first traced draw's).
  uint32_t default_targets = 1;
  // The colour of the frame's last colour clear before its first traced draw (the background
  // GLPT_ENVIRONMENT=clear gives rays that miss).
  glm::vec4 clear_color{0.0f};
  // The angle one pixel spans at the main camera (0 for parallel projections): the spread of the
  // ray cones that choose texture levels at bounce hits.
  float pixel_spread = 0.0f;
  // The size of one pixel in eye-space units under a parallel main camera (0 for perspective):
  // the denoiser's depth tolerance.
  float pixel_size_parallel = 0.0f;
  // The main camera (classify.hpp: MainCamera) as found, for GLPT_DUMP_SCENE
  // (scene_dump_capture.hpp); the tracer itself does not use it.
  glm::mat4 camera_projection{1.0f};
  std::array<int32_t, 4> camera_viewport{0, 0, 0, 0};
  bool camera_valid = false;
};

}  // namespace glpt::rt
