// The GL_SELECT and GL_FEEDBACK render modes (GL 1.5 5.2, 5.3): glRenderMode, the selection
// name stack and buffer, the feedback buffer (render_mode_commands.cpp), and the primitive
// pipeline that reports primitives instead of drawing them (primitive_pipeline.cpp).
//
// While the render mode is not GL_RENDER nothing reaches the frame record: primitives are
// transformed, lit, clipped, culled and polygon-mode'd on the CPU as Mesa 25's gallium draw
// module does it for st/mesa (st_cb_feedback.c: a private draw context whose last stage writes
// feedback tokens or selection hits), and pixel rectangles report their raster position.
// Mesa's behaviour, measured with OSMesa (tests/unit/mesa_reference/mesa_render_mode_probe.c), is
// reproduced where the spec leaves room, including its defects; see primitive_pipeline.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "gl_shim/gl_types.h"
#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;
struct VertexAssembly;

inline constexpr uint32_t kMaxNameStackDepth = 64;  // Mesa's MAX_NAME_STACK_DEPTH

// glSelectBuffer and the name stack (GL 1.5 5.2).
struct SelectionState {
  GLuint* buffer = nullptr;  // the program's; may be null with a nonzero size (Mesa allows it)
  GLsizei size = 0;
  uint64_t count = 0;  // values written, and past `size` the ones that did not fit
  uint32_t hits = 0;   // hit records written
  std::array<GLuint, kMaxNameStackDepth> names{};
  uint32_t depth = 0;
  // A primitive (or raster position) hit since the name stack last changed, and the window z
  // range of what hit (Mesa's HitFlag, HitMinZ, HitMaxZ).
  bool hit = false;
  float min_z = 1.0f, max_z = 0.0f;
};

// glFeedbackBuffer (GL 1.5 5.3).
struct FeedbackState {
  GLfloat* buffer = nullptr;
  GLsizei size = 0;
  GLenum type = GL_2D;
  uint64_t count = 0;  // values written, and past `size` the ones that did not fit
};

// What Mesa's draw module keeps from one draw to the next and shows through feedback:
// - its feedback stage remembers a line-stipple reset until the next line it reports (so the
//   first line reported after an unfilled polygon whose edges were all hidden is a
//   GL_LINE_RESET_TOKEN, whatever primitive it comes from);
// - its clip stage reuses temporary vertices whose flat-shaded colours it never writes when it
//   creates them (a flat-shaded clipped polygon reports, at a new vertex, whatever colour that
//   temporary last held: zero when it never held one).
struct DrawModuleMemory {
  static constexpr int kClipTemporaries = 2 * (6 + 8) + 2;  // MAX_CLIPPED_VERTICES + 1
  bool line_reset_pending = false;
  struct Colors {
    glm::vec4 front{0.0f}, back{0.0f};
  };
  std::array<Colors, kClipTemporaries> clip_temporaries{};
};

// Mesa's immediate-mode vertex layout, as far as edge flags go (measured with OSMesa). Immediate
// primitives are stored until a flush (a state change, an array draw, glCallList, a raster
// position or pixel rectangle, a name stack command in selection mode, glPassThrough in feedback
// mode, glRenderMode), which also empties the layout. An edge flag joins the layout when
// glEdgeFlag comes inside glBegin/glEnd before a vertex, or outside while primitives are stored;
// the primitives drawn while it is in the layout have per-vertex edge flags. glpt sees a state
// change as a different state snapshot at the next primitive (a change undone before it goes
// unseen).
struct ImmediateLayout {
  bool edge_flag = false;
  bool vertices_stored = false;
  rec::StateId stored_state = 0;  // the snapshot of the last stored primitive
};

struct RenderModeState {
  GLenum mode = GL_RENDER;
  SelectionState selection;
  FeedbackState feedback;
  DrawModuleMemory draw_module;
  // The drawable's height when selection or feedback began (Mesa's window-system buffers are
  // y-inverted; feedback y is computed through that inversion, which decides its last bit).
  float drawable_height = 0.0f;
  ImmediateLayout immediate;
};

// An array draw while the render mode is GL_SELECT or GL_FEEDBACK: reported instead of recorded.
// `state`: the snapshot it was assembled with. `edge_flag_array`: edge flags come per vertex.
void render_mode_array_draw(Context& ctx, const rec::StateSnapshot& state,
                            const rec::VertexData& vertices, bool edge_flag_array);

// glEnd outside GL_RENDER: the primitive assembled since glBegin, reported instead of recorded.
void render_mode_assembled_primitive(Context& ctx, const VertexAssembly& assembly);

// Every glEdgeFlag, after the assembly noted it (the immediate-mode layout may take it in).
void render_mode_edge_flag(Context& ctx);

// Commands after which Mesa's immediate-mode vertex layout starts anew (see ImmediateLayout).
void render_mode_flush_vertices(Context& ctx);

// glBitmap, glDrawPixels, glCopyPixels with a valid raster position outside GL_RENDER: in
// feedback mode the token and the raster position (GL 1.5 5.3); nothing in selection mode.
void render_mode_pixel_rectangle(Context& ctx, GLenum token);

// glRasterPos / glWindowPos set a valid raster position: in selection mode it is a hit at its
// window z (Mesa's rastpos.c).
void render_mode_raster_position(Context& ctx);

// Selection: a primitive vertex at window depth `z` hit (Mesa's _mesa_update_hitflag).
void selection_hit(SelectionState& selection, float z);
// Feedback: one value into the buffer (Mesa's _mesa_feedback_token).
void feedback_value(FeedbackState& feedback, float value);
// Feedback: one vertex as the buffer type asks for it (Mesa's _mesa_feedback_vertex).
void feedback_vertex(FeedbackState& feedback, const glm::vec4& window, const glm::vec4& color,
                     const glm::vec4& tex_coord);

}  // namespace glpt
