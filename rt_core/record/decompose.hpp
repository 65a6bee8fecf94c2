// GL primitives -> points, lines and triangles, in exactly the order Mesa 25 (llvmpipe behind the
// gallium draw module) hands them to its rasterizer. The vertex order of each triangle decides
// how llvmpipe (and lavapipe, which shares its setup code) computes the plane equations, so a
// rotated triangle interpolates colours and depth differently in the last bits, and the choice
// of diagonal decides the whole interior of a non-planar quad. Mesa's order is not one rule:
//
// Which way a batch of vertices goes through Mesa (AssemblyPath):
//   arrays    non-indexed draws (immediate mode, glDrawArrays, GL_COMPILE_AND_EXECUTE's
//             execution) that need no primitive pipeline: llvmpipe's lp_setup_draw_arrays
//   elements  indexed draws (display lists, which Mesa compiles to indexed draws, glDrawElements)
//             that need no primitive pipeline: lp_setup_draw_elements
//   pipeline  the draw module decomposes the primitives itself (draw_decompose_tmp.h) when its
//             primitive pipeline runs: for every batch while polygons are unfilled or polygon
//             stipple is on, and for every batch that has a vertex to clip (outside the view
//             volume: llvmpipe clips triangles without a guard band; or outside a user plane)
//
// The order per path, GL's last-vertex convention (v[2] provokes):
//   triangles       (3i, 3i+1, 3i+2)                        every path
//   triangle strip  i even (i, i+1, i+2), i odd (i+1, i, i+2)  every path
//   triangle fan    (0, i+1, i+2)                           every path
//   polygon         (i+1, i+2, 0)                           every path (the first vertex provokes)
//   quads           arrays, no constant interpolation: (0, 1, 2), (0, 2, 3)
//                   otherwise:                          (0, 1, 3), (1, 2, 3)
//   quad strip      arrays and elements: (2i, 2i+1, 2i+3), (2i+2, 2i, 2i+3)
//                   pipeline:            (2i+2, 2i, 2i+3), (2i, 2i+1, 2i+3)
// "Constant interpolation": flat shading of a colour that Mesa's fragment shader reads as a
// per-vertex input (AssemblyState::constant_interpolation).
//
// A batch is what Mesa's draw module processes at once: in immediate mode, consecutive
// glBegin/glEnd of a mode Mesa merges (points, lines, triangles, quads, and strips/fans short
// enough to be one line or triangle) are one draw, cut every 4096 vertices (4095 for triangles);
// every other glBegin/glEnd, array draw and display-list primitive is its own batch. (Mesa also
// cuts where its 512 KiB immediate-mode vertex buffer fills up; that depends on the vertex
// layout and on all earlier draws and is not modelled.)
//
// One Mesa defect is reproduced: llvmpipe draws nothing of an arrays-path batch of exactly 9
// triangle-list vertices, smooth-interpolated, whose last three vertices have the same window y
// (lp_setup_analyse_triangles takes it for a Windows Aero window border).
//
// Display lists draw line strips that follow or precede another line strip or line list in the
// same compiled block as line lists, so the line stipple restarts at every segment
// (mesa_draws_strips_as_lines); within one draw that is every line strip when there are two or
// more.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "rt_core/record/frame_record.hpp"

namespace glpt::rec {

struct DecomposedTriangle {
  uint32_t v[3];  // vertex numbers (indices already resolved); v[2] is the provoking vertex
  // Bit k: the edge v[k] -> v[(k+1)%3] is a boundary edge (drawn in GL_LINE / GL_POINT polygon
  // mode): the structural edges of the GL primitive AND the edge flag of the vertex it starts at.
  // GL 1.5 2.6.2 applies edge flags to independent triangles, quads and polygons only; Mesa's
  // draw module keeps every vertex's flag, so they apply to strips and fans too (measured).
  uint8_t boundary_edges;
  // The draw module flags the triangle DRAW_PIPE_RESET_STIPPLE: every triangle of independent
  // triangles, strips and fans, the first of each quad, the first of a polygon. (Its unfilled
  // stage restarts the line stipple there; GL_FEEDBACK reports a GL_LINE_RESET_TOKEN.)
  bool reset_stipple = false;
};

struct DecomposedLine {
  uint32_t v[2];       // v[1] is the provoking vertex
  bool reset_stipple;  // GL restarts the line stipple here (each GL_LINES segment, each strip)
};

struct Decomposed {
  std::vector<uint32_t> points;
  std::vector<DecomposedLine> lines;
  std::vector<DecomposedTriangle> triangles;
  // Whether the AssemblyState decided anything (a batch whose order depends on Mesa's path:
  // quads, quad strips, the 9-vertex defect). When false, the same vertices decompose the same
  // under every AssemblyState (consumers keep the result across frames: rt_core's resident
  // geometry).
  bool assembly_consulted = false;
  void clear() {
    points.clear();
    lines.clear();
    triangles.clear();
    assembly_consulted = false;
  }
};

enum class AssemblyPath : uint8_t { kArrays, kElements, kPipeline };

// What decides Mesa's assembly of a draw besides its vertices (derived from the draw's state by
// assembly_state, or set directly by tests).
struct AssemblyState {
  // llvmpipe interpolates one of its fragment shader's inputs as a constant: flat shading of a
  // primary or secondary colour the fragment shader reads per vertex.
  bool constant_interpolation = false;
  // The draw module's primitive pipeline runs for every batch (triangles only: unfilled
  // polygons, polygon stipple).
  bool pipeline = false;
  // Vertex clip test, needed only when a batch's path matters: the clip-space position is
  // modelview_projection * position computed as the vertex shader does (c0*x + c1*y + c2*z +
  // c3*w); a vertex is outside when |x|, |y| or |z| exceeds w (llvmpipe has no guard band) or
  // when the eye-space position is behind an enabled user clip plane. Without a transform no
  // vertex is outside.
  bool clip_test = false;
  glm::mat4 modelview_projection{1.0f};
  glm::mat4 modelview{1.0f};
  uint8_t clip_plane_mask = 0;
  std::array<glm::vec4, kMaxClipPlanes> clip_planes{};
  // Window coordinates = ndc * viewport_scale + viewport_offset (for the 9-vertex defect).
  float viewport_scale_x = 1.0f, viewport_offset_x = 0.0f;
  float viewport_scale_y = 1.0f, viewport_offset_y = 0.0f;

  bool operator==(const AssemblyState&) const = default;
};

// Mesa's assembly state for drawing `vertices` with `state`.
AssemblyState assembly_state(const StateSnapshot& state, const VertexData& vertices);

// Whether Mesa's fixed-function fragment shader reads the primary colour, for this texturing
// state (texture environments chained from the primary colour; GL_REPLACE of a texture with its
// own alpha, or a GL_COMBINE that takes nothing from it, cut the chain).
bool fragment_reads_primary_color(const TexturingState& texturing);

// Display lists with two or more line strips in one draw: Mesa draws each strip as separate
// segments (a line list), which restarts the line stipple at every segment.
bool mesa_draws_strips_as_lines(const VertexData& vertices);

// Appends the primitives of `vertices` to `out` as Mesa assembles them. Incomplete trailing
// primitives are dropped as GL drops them; out-of-range indices drop the primitive they belong
// to.
void decompose(const VertexData& vertices, const AssemblyState& assembly, Decomposed& out);
// Whether decompose(vertices, assembly) gives exactly the draw's elements in order, three by
// three (element 3i, 3i+1, 3i+2 as triangle i), answered without decomposing: GL_TRIANGLES drawn
// as one range, every index naming a vertex, no batch whose order Mesa's path decides. False
// when it cannot tell so cheaply (decompose then answers). Positions are not looked at.
bool triangles_in_element_order(const VertexData& vertices, const AssemblyState& assembly);
// The same with a default AssemblyState (smooth, filled, nothing clipped): the decomposition
// for consumers that do not need Mesa's exact order (the path tracer).
void decompose(const VertexData& vertices, Decomposed& out);

// The basic primitive class a GL mode rasterizes as (before polygon mode).
enum class PrimitiveClass : uint8_t { kPoints, kLines, kTriangles };
PrimitiveClass primitive_class(uint32_t mode);

}  // namespace glpt::rec
