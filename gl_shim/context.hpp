// A GL rendering context: all GL 1.x state of one glXCreateContext / eglCreateContext, plus the
// frame being captured from it. The only global mutable state of glpt is which Context is
// current on each thread (GL's own model).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl_shim/display_lists/display_lists.hpp"
#include "gl_shim/frame/frame_capture.hpp"
#include "gl_shim/frame/frame_output.hpp"
#include "gl_shim/geometry/vertex_assembly.hpp"
#include "gl_shim/gl_commands.hpp"
#include "gl_shim/state/current_attributes.hpp"
#include "gl_shim/state/enable_state.hpp"
#include "gl_shim/state/framebuffer_state.hpp"
#include "gl_shim/state/matrix_stack.hpp"
#include "gl_shim/state/transform_controls.hpp"
#include "gl_shim/textures/texture_units.hpp"
#include "rt_core/record/gl_state.hpp"

namespace glpt {

class Context {
 public:
  // `shared` (may be null): a context whose display lists and texture objects this one shares
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
  rec::RasterState raster;
  rec::PixelTransferState pixel_transfer;
  EnableState enables;  // capabilities without a field in the blocks above
  CurrentAttributes current;
  FramebufferState framebuffer;
  VertexAssembly assembly;
  DisplayListState lists;

  // --- the frame --------------------------------------------------------------------------------
  FrameCapture capture;
  // The window this context draws to (set by glXMakeCurrent / eglMakeCurrent).
  WindowTarget* target = nullptr;
  std::unique_ptr<FrameOutput> output;    // created on the first frame
  bool renderer_unavailable = false;      // creation failed: reported once, never retried
  void* window_system_context = nullptr;  // the GLX/EGL context wrapping this one
  // Something was drawn or cleared since the image was last rendered.
  bool frame_dirty = false;
  rt::Frame pending;  // camera, lights and clear colour as last seen by a draw/clear

  // --- accounting -------------------------------------------------------------------------------
  std::vector<uint64_t> unimplemented_calls;  // per CommandId
  std::vector<bool> unimplemented_reported;
  uint64_t not_compilable_calls = 0;
};

Context* current_context();
void set_current_context(Context* ctx);

// Binds `target` to `ctx` and makes it current. On the context's first binding the viewport and
// scissor box become the target's size (GL 1.5 2.11.1, 4.1.2).
void bind_target_and_make_current(Context& ctx, WindowTarget* target);

// Renders what was drawn since the last render, if anything (a read, a swap or glFinish).
// Returns false if there is no image (no window, or the renderer failed).
bool render_pending_frame(Context& ctx);

}  // namespace glpt
