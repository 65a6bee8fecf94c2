// Data layouts shared by the C++ host code (rt_core) and the GLSL compute shaders.
//
// This header is compiled twice: as C++ (where vec4/uvec4/mat4 are glm types) and as GLSL (via
// GL_GOOGLE_include_directive). Every member is a 16-byte vec4/uvec4/ivec4 or a mat4, so std430
// (storage buffers), std140 (the uniform block) and the C++ layout are identical without any
// padding rules to get wrong; the C++ side checks the sizes with static_assert.
#ifndef GLPT_SHADERS_SHARED_TYPES_H
#define GLPT_SHADERS_SHARED_TYPES_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace glpt::rt::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
#endif

// ---- descriptor bindings ---------------------------------------------------------------------
// path_trace.comp, set 0
#define GLPT_PT_BINDING_SCENE 0      // accelerationStructureEXT (TLAS)
#define GLPT_PT_BINDING_INSTANCES 1  // GpuInstance[], indexed by instanceCustomIndex
#define GLPT_PT_BINDING_LIGHTS 2     // GpuLight[]
#define GLPT_PT_BINDING_EMITTERS 3   // GpuEmitter[]: the frame's emissive triangles
#define GLPT_PT_BINDING_COUNTERS 4   // GpuCounters
#define GLPT_PT_BINDING_FRAME 5      // uniform FrameUniforms
#define GLPT_PT_BINDING_STATES 6     // GpuTraceState[], one per record state
#define GLPT_PT_BINDING_GBUFFER 7    // 4 storage images (gbuffer_layout.h), bindings 7..10
#define GLPT_PT_BINDING_TEXTURES 14  // sampler2D[GLPT_TRACE_TEXTURES]: traced draws' 2-D textures
#define GLPT_PT_BINDING_CLIP_PLANES 15    // GpuClipPlanes[]: the user clip planes of traced draws
#define GLPT_PT_BINDING_TEXTURES_1D 16    // sampler1D[GLPT_TRACE_TEXTURES_OTHER]
#define GLPT_PT_BINDING_TEXTURES_3D 17    // sampler3D[GLPT_TRACE_TEXTURES_OTHER]
#define GLPT_PT_BINDING_TEXTURES_CUBE 18  // samplerCube[GLPT_TRACE_TEXTURES_OTHER]
// The denoiser's tile list (GLPT_DN_BINDING_TILES), filled under GLPT_OPTION_DENOISE_TILES.
#define GLPT_PT_BINDING_DENOISE_TILES 19
// uint[64 x 64]: the blue-noise masks that offset each pixel's sample points (trace/rng.h)
#define GLPT_PT_BINDING_BLUE_NOISE 20
#define GLPT_BLUE_NOISE_SIZE 64

// Emissive triangles next-event estimation samples in one frame (docs/light-transport.md); the
// emission of instances beyond them is found by bounces only.
#define GLPT_MAX_EMITTERS 65536u

// Distinct textures the trace pass can sample in one frame, per target: 2-D ones (most), and
// 1-D, 3-D and cube maps. A unit whose texture finds its table full is traced untextured.
#define GLPT_TRACE_TEXTURES 64
#define GLPT_TRACE_TEXTURES_OTHER 16

// A traced texture unit packed into one uint (GpuInstance.units): bits 0..7 the slot + 1 in its
// target's table (0: the unit is off for rays), bits 8..9 the target, bits 10..12 which of s, t, r
// GL_CLAMP clamps to [0, 1] before a linear lookup (no Vulkan address mode does), bits 16..31
// GL_TEXTURE_ENV_MODE.
#define GLPT_TRACE_TARGET_2D 0u
#define GLPT_TRACE_TARGET_1D 1u
#define GLPT_TRACE_TARGET_3D 2u
#define GLPT_TRACE_TARGET_CUBE 3u
#define GLPT_TRACE_UNITS 4

// path_trace.comp's push constant: which pixels a dispatch traces. GLPT_SCALE below 1 dispatches
// the grid pass over the coarse grid, then the fill pass over the window.
#define GLPT_TRACE_PASS_ALL 0u   // every pixel
#define GLPT_TRACE_PASS_GRID 1u  // one pixel per cell of the coarse grid (trace_grid)
#define GLPT_TRACE_PASS_FILL 2u  // the others: from traced neighbours, or traced where none fits

// composite.comp, set 0
#define GLPT_CO_BINDING_FRAME 0         // uniform FrameUniforms
#define GLPT_CO_BINDING_STATES 1        // GpuTraceState[]
#define GLPT_CO_BINDING_GBUFFER 3       // the G-buffer, bindings 3..6
#define GLPT_CO_BINDING_FRONT 10        // colour buffers: storage images, read and written
#define GLPT_CO_BINDING_BACK 11
#define GLPT_CO_BINDING_DENOISE 13   // uniform DenoiseUniforms (its work slots' address)

// svgf_temporal.comp and svgf_atrous.comp (rt_core/passes/svgf_denoiser.hpp), set 0. Per pixel
// p (row-major, GL window rows: row 0 at the bottom):
#define GLPT_DN_BINDING_UNIFORMS 0  // uniform DenoiseUniforms
#define GLPT_DN_BINDING_STATES 1    // GpuStateHistory[], one per record state
#define GLPT_DN_BINDING_POSITION 2  // G-buffer POSITION
#define GLPT_DN_BINDING_SURFACE 3   // G-buffer SURFACE
#define GLPT_DN_BINDING_SCENE 7      // the frame's TLAS (deformed surfaces' triangles)
#define GLPT_DN_BINDING_INSTANCES 8  // GpuInstance[] (GLPT_PT_BINDING_INSTANCES' table)
// The tiles (GLPT_IMAGE_TILE_WIDTH x GLPT_IMAGE_TILE_HEIGHT pixels, the passes' workgroups) with a
// pixel the denoiser filters, listed by the trace pass as it shades them
// (GLPT_OPTION_DENOISE_TILES); the temporal pass and the a-trous iterations are dispatched over
// them alone (vkCmdDispatchIndirect). uint[]: [0..2] the dispatch (x: the number of such tiles,
// 1, 1), [3] unused, then per tile a flag (1 once listed), then the list. Pixels of tiles not
// listed keep their guides of an earlier frame: a guide's frame stamp (DenoiseGuide) tells.
#define GLPT_DN_BINDING_TILES 9
//
// The denoiser's own per-pixel data lives in buffers reached by device address
// (DenoiseUniforms), not in storage images: lavapipe calls a function for every image access and
// stores an image texel lane by lane and component by component, while a buffer reference is
// a vector gather or scatter in the shader itself (an image store measured 0.3 ms a pass over
// glxgears' 320x240 frame on a 2-core Xeon, a buffer store too little to tell from noise:
// docs/denoiser.md, "Cost"). Each is an array of texels (16 bytes) in layers of one texel per
// pixel, layer-major: texel (layer * width * height + p) (pixel_buffers.h, layer_texel).
// - Guides (DenoiseUniforms::guides: this frame's, the previous frame's): DenoiseGuide[], one per
//   pixel.
// - Fast histories (::histories): vec4, GLPT_DN_HISTORY_LAYERS layers, one per channel: a short
//   exponential average of the raw colour (rgb; a unused), the clamp against stale light. The
//   colour history lives in the work slots (slots 3 and 4).
// - Work slots (::buffers.xy): vec4, per slot a layer per channel (GLPT_DN_WORK_LAYERS): slot 0
//   the temporally integrated colour, 1 and 2 the a-trous iterations' ping-pong, 3 and 4 the
//   colour history of alternate frames (DenoiseUniforms::slots): the temporally filtered colour,
//   which the a-trous filter's first iteration writes (the history fed back as in the SVGF
//   paper, and the second iteration's input), or the temporal pass where there is no iteration.
//   Layer GLPT_DN_WORK_LAYERS * slot + c holds channel c's rgb radiance and its luminance
//   variance. Floats, not half floats two channels a texel as when these were images: a pack or
//   unpack of halves costs lavapipe more than gathering or scattering the bytes it saves.
// - Moments (::moments): vec4, GLPT_DN_MOMENT_LAYERS layers: layer 0 the first and second
//   luminance moments of channel 0 (xy) and 1 (zw), layer 1 those of channel 2 (xy). In float:
//   the variance is a difference of them.
// - Motion (::buffers.zw): uvec4, where each pixel the temporal pass filtered shows its point in
//   the previous frame, for the temporal anti-aliasing pass: xy the previous frame's pixel
//   position (float bits; centres at whole numbers, as the history taps are read), z this
//   frame's stamp (DenoiseGuide's) << 8 | the denoiser's history length (1: disoccluded or no
//   identity; short after a clamp against stale light), w the depth (-eye z, float bits). A texel
//   with another stamp (an earlier frame's, a tile not listed) is no motion of this frame.
#define GLPT_DN_TILES_HEADER 4u
#define GLPT_DN_SLOTS 3
#define GLPT_DN_WORK_LAYERS 3u   // per slot
#define GLPT_DN_HISTORY_SLOTS 2  // slots GLPT_DN_SLOTS and GLPT_DN_SLOTS + 1
#define GLPT_DN_HISTORY_LAYERS 3u
#define GLPT_DN_MOMENT_LAYERS 2u
#define GLPT_DN_SLOT_NONE 254u  // an a-trous iteration's second output: none
// DenoiseUniforms::image.z flags
#define GLPT_DN_HISTORY_VALID 1u  // the previous frame's guide and history belong to this size
#define GLPT_DN_UNLIT_AO 2u       // unlit pixels carry AO in the indirect channel: denoise it
#define GLPT_DN_ACTIVE 4u         // composite: the denoiser ran this frame, show its result
// No traced surface reflects specularly this frame (every material's specular is black): the
// specular channel is zero, neither pass filters it and the composite takes it raw.
#define GLPT_DN_NO_SPECULAR 8u
// The previous frame filtered no specular channel: its history has none (the temporal pass
// stores no zeros for a channel it leaves out), so this frame's specular starts afresh.
#define GLPT_DN_PREVIOUS_NO_SPECULAR 16u
// The a-trous filter takes the variance of the integrated colour, not of one sample (the 2017
// paper's): GLPT_DENOISE_MEAN_VARIANCE.
#define GLPT_DN_MEAN_VARIANCE 32u
// The temporal anti-aliasing pass runs after this frame: store the motion (::buffers.zw).
#define GLPT_DN_MOTION 64u

// temporal_aa.comp (rt_core/passes/temporal_aa_pass.hpp), set 0: the last stage of the SVGF
// pipeline, over the colour buffer the composite pass wrote.
#define GLPT_TAA_BINDING_UNIFORMS 0          // uniform TemporalAaUniforms
#define GLPT_TAA_BINDING_COLOUR 1            // the colour buffer (BGRA8 storage image)
#define GLPT_TAA_BINDING_TILES 2  // the denoiser's tile list (GLPT_DN_BINDING_TILES): its flags
#define GLPT_TAA_BINDING_SURFACE 3  // G-buffer SURFACE
// The pass's history, this frame's and the previous frame's, lives in buffers reached by device
// address (TemporalAaUniforms::buffers.zw, histories), as the denoiser's data does (lavapipe
// stores an image texel lane by lane): per pixel p (row-major, pixel_buffers.h) a vec4, rgb
// colour and a length (floats: half floats measured slower, docs/denoiser.md "Cost").
// TemporalAaUniforms::image.z flags
#define GLPT_TAA_HISTORY_VALID 1u  // the previous frame's history belongs to this drawable and size
// The composite showed an accumulated average (a still scene): it is the image, already
// anti-aliased; the history takes it as it is, so that a motion continues from it.
#define GLPT_TAA_TAKE_CURRENT 2u
// temporal_aa.comp's push constant: its two dispatches.
#define GLPT_TAA_RESOLVE 0u     // blend the colour with the reprojected history into the history
#define GLPT_TAA_WRITE_BACK 1u  // the history into the colour buffer

// ---- radiance channels -----------------------------------------------------------------------
// What the trace pass writes per pixel (a vec4 per channel, this frame's samples averaged; linear
// HDR radiance with the albedo divided out where the channel is diffuse), and the composite pass
// (or the denoiser before it) reads. Composite: albedo * (direct + indirect) + specular +
// emission. One buffer reached by device address (FrameUniforms::buffers.zw,
// DenoiseUniforms::channels.xy), layer-major as the denoiser's: channel c of pixel p (row-major)
// is texel c * width * height + p. Not storage images: lavapipe stores an image texel lane by
// lane through a function call, and the trace pass writes all three for every pixel.
#define GLPT_CHANNEL_DIRECT_DIFFUSE 0    // rgb: next-event estimation through the diffuse lobe
#define GLPT_CHANNEL_INDIRECT_DIFFUSE 1  // rgb: paths continuing from the diffuse lobe + ambient
#define GLPT_CHANNEL_SPECULAR 2          // rgb: everything reflected by the specular lobe
#define GLPT_CHANNELS 3
// The channels' alpha: DIRECT_DIFFUSE.a = samples traced this frame (0: none), INDIRECT.a and
// SPECULAR.a unused.

// The trace pass runs 8x8 pixel tiles: neighbouring rays stay coherent, which is what lavapipe's
// ray traversal (one SIMD lane per invocation) rewards.
#define GLPT_TILE_SIZE 8
// Specialization constant ids of a compute pass's workgroup size (its default: GLPT_TILE_SIZE).
#define GLPT_SPEC_TILE_WIDTH 100
#define GLPT_SPEC_TILE_HEIGHT 101
// The per-pixel image passes (denoiser, composite) run 32x8 tiles: a quarter of the workgroups,
// each of four whole 8-wide rows more (lavapipe runs a workgroup's rows as 8-lane vectors):
// glxgears 320x240 composite 3.0 -> 1.9 ms, denoiser about 17.5 -> 16.2 ms (16x16: 2.2, 16.3).
#define GLPT_IMAGE_TILE_WIDTH 32
#define GLPT_IMAGE_TILE_HEIGHT 8

// ---- ray masks -------------------------------------------------------------------------------
// Every world instance has GLPT_MASK_VISIBLE set; bits 0..5 say "casts shadows for light i"
// (lights 6+ share bit 5). Bounce rays use GLPT_MASK_VISIBLE, shadow rays the light's bit, so an
// instance can be visible yet not shadow a light (see light_setup.cpp: lamp markers). Sky
// instances have GLPT_MASK_SKY alone: only the sky lookup of rays that miss the world sees them.
#define GLPT_MASK_VISIBLE 0x80u
#define GLPT_MASK_SKY 0x40u
#define GLPT_MASK_SHADOW_BITS 6u

// ---- GpuMaterial::params.z flags and ColorSource values (same numbers as rt::ColorSource) ----
#define GLPT_COLOR_SOURCE_NONE 0u
#define GLPT_COLOR_SOURCE_AMBIENT_AND_DIFFUSE 1u
#define GLPT_COLOR_SOURCE_DIFFUSE 2u
#define GLPT_COLOR_SOURCE_AMBIENT 3u
#define GLPT_COLOR_SOURCE_EMISSION 4u
#define GLPT_COLOR_SOURCE_SPECULAR 5u

// Geometry of a BLAS, in its Morton-sorted triangle order: triangle p (the BLAS primitive index)
// uses vertices 3p..3p+2. The BLAS is built straight from these (stride 16 bytes); they depend on
// the shape only, so recolouring a shape reuses them and its BLAS.
struct GpuPosition {
  vec4 position;  // xyz: object-space position (eye space for projective modelviews), w: 0
};

// Shading data of one vertex, in the same order as the GpuPosition array of its shape. Colours
// stay full float so an unlit surface reproduces GL's 8-bit rounding of the same value exactly.
struct ShadingVertex {
  vec4 normal;  // xyz: normal as given (not necessarily unit length); w: material index (float)
  vec4 color;   // GL current colour
  // Each texture unit's coordinates after texgen and the texture matrix (s, t, r, q); (0, 0, 0, 1)
  // for units rays do not sample
  vec4 texcoords[GLPT_TRACE_UNITS];
};

struct GpuMaterial {
  vec4 ambient;
  vec4 diffuse;
  vec4 specular;
  vec4 emission;
  // x: floatBits(shininess), y: lit (0/1), z: GLPT_COLOR_SOURCE_*, w: index of the material of
  // back faces (itself unless two-sided lighting gives back faces their own)
  uvec4 params;
};

// One entry per TLAS instance (instanceCustomIndex indexes this table).
struct GpuInstance {
  // xy: device address of the shape's GpuPosition array, zw: of its ShadingVertex array
  // (GL_EXT_buffer_reference_uvec2 turns a uvec2 straight into a buffer reference). Normals are
  // transformed in the shader with the query's world-to-object matrix (the inverse-transpose GL
  // uses), so no matrix is stored here.
  uvec4 addresses;
  // xy: address of the GpuMaterial array, z: the record state whose lights light it, w:
  // floatBits(the instance's size: the diagonal of its eye-space bounds), which sets how far it
  // occludes ambient light (automatic AO radius, docs/light-transport.md)
  uvec4 materials;
  // The draw's texture units 0..3 as rays see them, one packed uint each (GLPT_TRACE_TARGET_*
  // above)
  uvec4 units;
  // x: GL alpha function (0: no alpha test), y: floatBits(alpha reference), zw: unused
  uvec4 surface;
  // Indices into the frame's other tables. x: in the emitter table (GLPT_PT_BINDING_EMITTERS),
  // of the emitter of BLAS primitive 0, + 1 (primitive p is emitter x - 1 + p); 0: not sampled
  // by next-event estimation. y: in the clip-plane table (GLPT_PT_BINDING_CLIP_PLANES) + 1; 0:
  // no clip plane. zw: device address of the shape's GpuPosition array as it was the frame
  // before, where the shape deformed since (its BLAS refit this frame: the same triangles in the
  // same order); 0: none. The denoiser's temporal pass reprojects through it.
  uvec4 tables;
};

// The enabled user clip planes of a draw (GL_CLIP_PLANEi, eye space): rays see only the part of
// it GL keeps, where every plane's dot(plane, (p, 1)) >= 0.
#define GLPT_MAX_CLIP_PLANES 6
struct GpuClipPlanes {
  vec4 planes[GLPT_MAX_CLIP_PLANES];
  uvec4 count;  // x: planes in use; yzw: unused
};

// An emissive triangle in eye space (one per BLAS primitive of an instance with GL emission).
// GL's emission is radiance leaving both faces; next-event estimation picks a triangle in
// proportion to its power (area x emitted luminance), then a point uniformly on it.
struct GpuEmitter {
  vec4 p0;         // w: the cumulative probability of the emitters up to and including this one
  vec4 p1;         // w: the probability of choosing this one
  vec4 p2;         // w: area
  // rgb: the emission at each vertex (interpolated over the triangle). emission0.a: the side
  // GL culls (TracedSurface::culled_side), which emits nothing: +1 the side the normal
  // (p1 - p0) x (p2 - p0) points to, -1 the other, 0 none (both faces emit).
  vec4 emission0;
  vec4 emission1;
  vec4 emission2;
};

// A GL light in eye space.
struct GpuLight {
  vec4 position;  // w == 0: directional (xyz = unit direction towards the light)
  vec4 ambient;
  vec4 diffuse;
  vec4 specular;
  vec4 spot;         // xyz: unit spot direction, w: cos(cutoff), or -2 for "not a spot light"
  vec4 attenuation;  // x: constant, y: linear, z: quadratic, w: spot exponent
  // x: shadow ray cull mask, y: floatBits(sphere radius; 0 = a point light), z: unused, w: unused
  uvec4 params;
};

// Per record state: the lighting of pixels (G-buffer) and bounce hits (instances) drawn with it.
struct GpuTraceState {
  vec4 global_ambient;  // GL_LIGHT_MODEL_AMBIENT
  vec4 viewer;          // eye-space viewer: a point (w = 1) or a direction towards it (w = 0)
  vec4 fog_color;
  vec4 fog_params;  // density, start, end, 1 / (end - start)
  // x: light count (<= 8), y: fog mode (0 off, 1 linear, 2 exp, 3 exp2), z: colour buffers
  // (bit 0 front, bit 1 back), w: GLPT_STATE_* flags
  uvec4 info;
  uvec4 lights[2];  // GpuLight indices, lights[i / 4][i % 4]
};

// GpuTraceState::info.w
#define GLPT_STATE_LOCAL_VIEWER 1u       // GL_LIGHT_MODEL_LOCAL_VIEWER
#define GLPT_STATE_TWO_SIDE 2u           // GL_LIGHT_MODEL_TWO_SIDE
#define GLPT_STATE_SEPARATE_SPECULAR 4u  // GL_SEPARATE_SPECULAR_COLOR (specular not textured)
// The material reflects specularly (a specular colour, front or back, or GL_COLOR_MATERIAL
// tracking it): the trace pass estimates specular light even where a texel's is ~0
#define GLPT_STATE_SPECULAR_MATERIAL 8u

// FrameUniforms::options.x: what the trace pass models (render_settings.hpp)
#define GLPT_OPTION_SHADOWS 1u       // shadow rays (GLPT_SHADOWS)
#define GLPT_OPTION_AO 2u            // ambient light occluded by ray-traced AO (GLPT_AO)
#define GLPT_OPTION_GL_PARITY 4u     // GL's lighting equation per pixel (no shadows, AO, bounces)
#define GLPT_OPTION_UNLIT_AO 8u      // GLPT_UNLIT=ao: unlit pixels darkened by AO
#define GLPT_OPTION_UNLIT_EMIT 16u   // GLPT_UNLIT=emit: unlit surfaces light others
#define GLPT_OPTION_ENVIRONMENT 32u  // rays that miss see FrameUniforms::environment
#define GLPT_OPTION_SKY 64u          // the frame has sky instances (GLPT_MASK_SKY)
// The denoiser filters this frame: list the tiles it filters (GLPT_PT_BINDING_DENOISE_TILES)
#define GLPT_OPTION_DENOISE_TILES 128u
// Pixels share their sample points, offset by a blue-noise mask (trace/rng.h; GLPT_BLUE_NOISE)
#define GLPT_OPTION_BLUE_NOISE 256u
// FrameUniforms::options.y: how one light of a surface's lights is chosen per sample
#define GLPT_LIGHT_CHOICE_CONTRIBUTION 0u  // in proportion to its estimated contribution
#define GLPT_LIGHT_CHOICE_UNIFORM 1u       // uniformly (for comparison)
#define GLPT_LIGHT_CHOICE_ALL 2u           // every light, one shadow ray each

struct FrameUniforms {
  // x: image width, y: image height, z: colour buffers of pixels traced earlier but not in this
  // frame's G-buffer (bit 0 front, bit 1 back), w: random seed of this frame
  uvec4 image;
  // x: samples already accumulated before this frame (0 = overwrite), y: samples to trace this
  // frame, z: bounces, w: total samples after this frame
  uvec4 sampling;
  // x: ambient-occlusion radius (eye-space units; 0: each occluder's own size), y: cos(angular
  // radius of directional lights), z: 1 - y (computed without cancellation), w: the angle one
  // pixel spans at the main camera (ray cones' spread, for texture levels at bounce hits)
  vec4 params;
  // x: GLPT_OPTION_* bits, y: GLPT_LIGHT_CHOICE_*, z: emitters in the emitter table (0: none
  // emits), w: the Sobol sample number of this pass's first sample (trace/rng.h): the frame's
  // index times its samples, plus the samples of the same frame traced before (a reference)
  uvec4 options;
  vec4 environment;  // rgb: radiance of rays that miss (GLPT_OPTION_ENVIRONMENT), a: unused
  // GLPT_SCALE below 1 (path_trace.comp's grid and fill passes): x, y: the coarse grid's cells
  // per pixel (the scale), z, w: where in its cell this frame's traced pixel lies, [0, 1)
  vec4 trace_grid;
  // Device addresses (low word, high word): xy the composite's accumulation (composite.comp: vec4
  // texels, 3 layers of one per pixel), zw the radiance channels (GLPT_CHANNELS, below)
  uvec4 buffers;
};

// The denoiser's view of one record state (TraceState's history fields).
struct GpuStateHistory {
  mat4 to_previous_eye;      // this frame's eye space -> the previous frame's
  mat4 previous_projection;  // the previous frame's projection
  vec4 viewport;             // x, y, width, height (GL window pixels)
  // x: history id (0: no traced draw, 1: no identity), y: 1 when the matrices are valid, z: 1
  // when an instance of the state deformed (GpuInstance.tables.zw): the temporal pass finds
  // each pixel's triangle with a ray query and moves its point by the triangle's deformation
  uvec4 info;
};

// Per pixel of the denoiser's G-buffer copy: what the next frame's reprojection tests taps on.
// The shading normal is kept unpacked (n.x, n.y in meta.zw as float bits, n.z in eye.w): the
// a-trous filter reads it at every tap, and decoding the G-buffer's octahedral normal there took
// half of an iteration's time on lavapipe.
struct DenoiseGuide {
  vec4 eye;  // xyz: eye-space position; w: the normal's z
  // x: history id (0: no denoised surface here), y: history length in frames (bits 0-7) and the
  // stamp of the frame that wrote the guide (bits 8-31, never 0: DenoiseUniforms::slots.z; the
  // passes skip the tiles without a filtered pixel, whose guides stay as an earlier frame wrote
  // them), z, w: the normal's x and y (float bits)
  uvec4 meta;
};

struct DenoiseUniforms {
  // x, y: image size, z: GLPT_DN_* flags, w: a-trous iterations
  uvec4 image;
  // x: colour alpha, y: moments alpha, z: fast-history alpha, w: fast-clamp width in standard
  // deviations (0: off)
  vec4 temporal;
  // x: sigma depth, y: sigma normal (exponent), z: sigma luminance, w: a-trous kernel (0: four
  // taps, cross and diagonal in turn; 1: 3x3; 2: 5x5)
  vec4 sigmas;
  // x: angle one pixel spans (perspective main camera), y: pixel size in eye units (parallel),
  // z: history length a clamped history falls back to, w: composite: weight of the accumulated
  // mean against the denoised frame (1: accumulation alone)
  vec4 params;
  // xy: this frame's sub-pixel jitter (removed from the reprojection), z: 1 when the composite
  // reads the denoised colour, w: unused
  vec4 jitter;
  // x: the work slot of this frame's colour history, y: the previous frame's; z: this frame's
  // stamp, w: the previous frame's (DenoiseGuide::meta.y)
  uvec4 slots;
  // Device addresses (GL_EXT_buffer_reference_uvec2: low word, high word) of the per-pixel
  // buffers above: xy this frame's, zw the previous frame's guides, fast histories, moments;
  // buffers: xy the work slots, zw the motion. 0 where the denoiser does not run.
  uvec4 guides;
  uvec4 histories;
  uvec4 moments;
  uvec4 buffers;
  // xy: the trace pass's radiance channels (FrameUniforms::buffers.zw), zw: unused
  uvec4 channels;
};

struct TemporalAaUniforms {
  // x, y: image size, z: GLPT_TAA_* flags, w: this frame's denoiser stamp (its motion's)
  uvec4 image;
  // x: weight of a new frame at an edge (GLPT_TAA_ALPHA), y: clip box half-width in standard
  // deviations of the 3x3 neighbourhood (GLPT_TAA_GAMMA), zw: unused
  vec4 params;
  // Device addresses (low word, high word): xy the denoiser's motion (DenoiseUniforms::buffers.zw),
  // zw this frame's history
  uvec4 buffers;
  // xy: the previous frame's history, zw: unused
  uvec4 histories;
};

struct GpuCounters {
  // x: rays traced this frame (shadow + bounce + AO), y: non-finite samples dropped, zw: unused
  uvec4 rays;
};

#ifdef __cplusplus
static_assert(sizeof(GpuPosition) == 16);
static_assert(sizeof(ShadingVertex) == 96);
static_assert(sizeof(GpuMaterial) == 80);
static_assert(sizeof(GpuInstance) == 80);
static_assert(sizeof(GpuEmitter) == 96);
static_assert(sizeof(GpuClipPlanes) == 112);
static_assert(sizeof(GpuLight) == 112);
static_assert(sizeof(GpuTraceState) == 112);
static_assert(sizeof(FrameUniforms) == 112);
static_assert(sizeof(GpuCounters) == 16);
static_assert(sizeof(GpuStateHistory) == 160);
static_assert(sizeof(DenoiseGuide) == 32);
static_assert(sizeof(DenoiseUniforms) == 176);
static_assert(sizeof(TemporalAaUniforms) == 64);
}  // namespace glpt::rt::gpu
#endif

#endif  // GLPT_SHADERS_SHARED_TYPES_H
