// A GL rendering context: all GL 1.x state of one glXCreateContext / eglCreateContext, plus the
// frame being captured from it. The only global mutable state of glpt is which Context is
// current on each thread (GL's own model).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/stopwatch.hpp"
#include "gl_shim/arrays/buffer_draw_cache.hpp"
#include "gl_shim/arrays/vertex_arrays.hpp"
#include "gl_shim/buffers/buffer_objects.hpp"
#include "gl_shim/display_lists/display_lists.hpp"
#include "gl_shim/evaluators/evaluator_state.hpp"
#include "gl_shim/frame/clear_fallback.hpp"
#include "gl_shim/frame/deferred_frames.hpp"
#include "gl_shim/frame/frame_output.hpp"
#include "gl_shim/frame/frame_recorder.hpp"
#include "gl_shim/frame/state_snapshot.hpp"
#include "gl_shim/framebuffers/framebuffer_objects.hpp"
#include "gl_shim/geometry/vertex_assembly.hpp"
#include "gl_shim/gl_commands.hpp"
#include "gl_shim/pixels/bitmap_cache.hpp"
#include "gl_shim/pixels/raster_position.hpp"
#include "gl_shim/queries/query_objects.hpp"
#include "gl_shim/render_modes/render_modes.hpp"
#include "gl_shim/state/attrib_stack.hpp"
#include "gl_shim/state/color_index_state.hpp"
#include "gl_shim/state/current_attributes.hpp"
#include "gl_shim/state/enable_state.hpp"
#include "gl_shim/state/framebuffer_state.hpp"
#include "gl_shim/state/hints.hpp"
#include "gl_shim/state/implementation_limits.hpp"
#include "gl_shim/state/matrix_stack.hpp"
#include "gl_shim/state/transform_controls.hpp"
#include "gl_shim/textures/texture_units.hpp"
#include "rt_core/record/gl_state.hpp"

namespace glpt {

// The window-system API whose context wraps a Context (GLX and EGL contexts may both be current
// on different threads of one program).
enum class WindowSystem { kNone, kGlx, kEgl };

class Context {
 public:
  // `shared` (may be null): a context whose display lists, texture and buffer objects this one
  // shares
  // (GLX share_list).
  explicit Context(const Context* shared);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // --- what the generated entry points ask -------------------------------------------------
  bool inside_begin_end() const { return assembly.inside; }
  ListStream* list_being_compiled() { return lists.compiling() ? &lists.pending : nullptr; }
  bool list_executes_while_compiling() const;

  // --- state, one struct per concern ------------------------------------------------------------
  // The live state of the groups a draw snapshots is kept in the record's own block types
  // (rt_core/record/gl_state.hpp): snapshotting is a copy, and there is one source of truth.
  GLenum error = 0;  // GL_NO_ERROR
  MatrixState matrices;
  TransformControls transform;
  rec::LightingState lighting;
  TextureUnits textures;
  rec::RasterState raster = initial_raster_state();
  rec::PixelTransferState pixel_transfer;
  EnableState enables;  // capabilities without a field in the blocks above
  CurrentAttributes current;
  rec::RasterPosition raster_position = initial_raster_position();  // GL 1.5 2.13
  BitmapCache bitmap_cache;
  // The current texture coordinates as Mesa's GL state last saw them (its FLUSH_CURRENT: at
  // glRasterPos, glWindowPos, glDrawPixels): what its bitmaps and copies are textured with.
  std::array<glm::vec4, rec::kMaxTextureUnits> flushed_tex_coord =
      CurrentAttributes().tex_coord;  // Mesa's, reproduced in the record (pixels/bitmap_cache.hpp)
  FramebufferState framebuffer;
  ColorIndexState color_index;  // kept for queries only (glpt renders RGBA)
  HintState hints;
  VertexAssembly assembly;
  DisplayListState lists;
  VertexArrays arrays;           // client vertex arrays and buffer bindings (GL 1.5 2.8, 2.9)
  BufferDrawCache buffer_draws;  // draws from unchanged buffer objects, recorded once
  EvaluatorState evaluators;     // maps and grids (GL 1.5 5.1); their enables are in `enables`
  // Buffer objects of the share group (the constructor shares them with share_list).
  std::shared_ptr<BufferStore> buffers = std::make_shared<BufferStore>();
  AttribStacks attrib_stacks;   // glPushAttrib / glPushClientAttrib
  RenderModeState render_mode;  // GL_RENDER, GL_SELECT, GL_FEEDBACK (GL 1.5 5.2, 5.3)
  QueryState queries;           // occlusion queries: this context's own, never shared
  // EXT_framebuffer_object: the share group's objects and this context's bindings.
  FramebufferBindings framebuffers;

  // --- the frame --------------------------------------------------------------------------------
  // The frame being recorded (commands since the record was last executed) and the snapshots of
  // the state its commands refer to.
  FrameRecorder recorder;
  StateSnapshotter snapshots;
  Stopwatch recording_since;  // when the current record started (for GLPT_STATS)
  // The drawable this context draws to (set by glXMakeCurrent / eglMakeCurrent / headless).
  WindowTarget* target = nullptr;
  // The buffers of the drawable the context was first made current with (GLX visual / EGL config):
  // what GL_DOUBLEBUFFER, GL_*_BITS and the initial draw/read buffers report.
  rec::DrawableConfig drawable;
  // The renderer of the share group (shared with share_list, as the objects are).
  std::shared_ptr<RenderGroup> render_group = std::make_shared<RenderGroup>();
  std::unique_ptr<FrameOutput> output;    // created when the first record is executed
  bool renderer_unavailable = false;      // creation failed: reported once, never retried
  void* window_system_context = nullptr;  // the GLX/EGL context wrapping this one
  WindowSystem window_system = WindowSystem::kNone;  // which API window_system_context is of
  // Replayed by glpt-replay: what the program reads back goes nowhere (the trace holds what it
  // did next), so glReadPixels renders and answers nothing and glFinish waits for nothing.
  bool replayed = false;
  // false: a frame's end renders nothing (glpt-replay's shards replay every frame's state but
  // render only their own frames): its record is held in skipped_frames, rendered only when a
  // later frame builds on its pixels.
  bool render_frame_ends = true;
  DeferredFrames skipped_frames;
  uint64_t replay_frame = 0;  // glpt-replay's index of the frame being replayed
  // glpt-replay's history window: a frame builds on the path tracer's history of the frames
  // before it in its window of this many frames (rt::Renderer::start_independent_frame).
  uint32_t replay_history_window = 1;
  // Without a renderer (renderer_unavailable): frames show the last clear colour.
  std::unique_ptr<ClearFallback> clear_fallback;

  // --- accounting -------------------------------------------------------------------------------
  std::vector<uint64_t> unimplemented_calls;  // per CommandId
  std::vector<bool> unimplemented_reported;
  uint64_t not_compilable_calls = 0;
  uint64_t errors_recorded = 0;  // every GL error raised, also those after the first is pending
};

// The one piece of global mutable state glpt has: GL's current context, per thread. Every GL
// command reads it, so it is initial-exec TLS read inline, as Mesa's own current context: the
// general-dynamic model of a shared library costs a __tls_get_addr call per command (~2 ms per
// frame of 300 000 immediate-mode vertices). A libGL loaded by dlopen takes its 8 bytes from
// glibc's static TLS surplus, which exists for this.
extern constinit thread_local Context* t_current_context __attribute__((tls_model("initial-exec")));
inline Context* current_context() { return t_current_context; }
void set_current_context(Context* ctx);

// Binds `target` to `ctx` and makes it current. On the context's first binding the viewport and
// scissor box become the target's size (GL 1.5 2.11.1, 4.1.2). A context moving to another
// drawable is flushed first (flush_before_release).
void bind_target_and_make_current(Context& ctx, WindowTarget* target);

// `ctx` stops being current (or leaves its drawable): GLX 1.4 3.3.7 and EGL 1.5 3.7.3 flush it,
// so what it drew is executed on the drawable it was drawn for, where other contexts drawing to
// that drawable see it (piglit glx-multi-context-single-window, glx-make-glxdrawable-current).
void flush_before_release(Context& ctx);

// Executes the frame record (everything recorded since it was last executed) on the drawable's
// buffers: at a swap, a read, glFinish/glFlush. Returns false if there is nothing to execute on
// (no drawable, or no renderer).
bool execute_record(Context& ctx);
// Drops what was recorded since the record was last executed (an incomplete framebuffer object's
// drawing, which GL does not do).
void discard_record(Context& ctx);
// Creates the frame output (the renderer) on first use; false when there is nothing to render to
// or no renderer.
bool ensure_output(Context& ctx);
// The configuration and current size of what the context's record renders to (render_target,
// which must exist).
rec::DrawableConfig current_drawable(Context& ctx);

// A primitive or pixel command was recorded: keeps a frame that never ends from growing without
// bound by executing it early (invisible in raster mode).
void note_frame_content(Context& ctx);

// The end of a frame (swap, or glFlush/glFinish on a single-buffered drawable): executes the
// record, then presents and writes PNG/stats (FrameOutput::end_frame). With
// ctx.render_frame_ends false, holds the record in ctx.skipped_frames instead (nothing is
// presented).
void end_frame(Context& ctx, bool swap);

}  // namespace glpt
