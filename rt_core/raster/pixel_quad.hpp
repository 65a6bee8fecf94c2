// Which image group each fragment of a zoomed pixel rectangle takes, exactly as Mesa decides it.
//
// Mesa draws glDrawPixels / glCopyPixels images as a textured quad (st_cb_drawpixels.c,
// draw_textured_quad and st_draw_quad: a triangle fan over the zoomed rectangle, normalized
// texture coordinates 0..1) into its y-inverted window buffer, and llvmpipe interpolates the
// coordinates with plane equations anchored at the framebuffer origin (lp_state_setup.c), then
// looks the image up with NEAREST filtering. Where a fragment centre lies exactly on the edge
// between two groups (fractional zooms: 0.5, 1.5, 2.5 ...), the rounding of that arithmetic
// picks the group; this reproduces it: the plane coefficients are computed here in float the way
// llvmpipe's setup computes them for Mesa's vertices and evaluated the way its interpolator does
// (with fused multiply-adds). The consumer tabulates the result per window column and row
// (rt_core/raster/pixel_commands.cpp), so shaders need no particular float arithmetic.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

namespace glpt::rt {

struct PixelQuad {
  // Per triangle of the fan: a0, da/dx, da/dy (w unused) of the coordinates s and t, for Mesa's
  // pixel (x, y) with y counted from the top row.
  std::array<glm::vec4, 2> s{}, t{};
  // a * x + b * y + c >= 0 (window coordinates) inside the first triangle; w: the framebuffer
  // height.
  glm::vec4 diagonal{0.0f};
};

// The quad of an image whose group (0, 0) corner is at p0 and whose opposite corner is at p1
// (window coordinates; p1 = p0 + size * zoom), in a framebuffer of the given size. Copies
// (rows_from_top) have t running down, as Mesa reads its source into the texture.
PixelQuad mesa_pixel_quad(glm::vec2 p0, glm::vec2 p1, uint32_t framebuffer_width,
                          uint32_t framebuffer_height, bool rows_from_top);

// Which of the fan's two triangles Mesa rasterizes the fragment centred at `centre` (window
// coordinates) in.
int mesa_pixel_triangle(const PixelQuad& quad, glm::vec2 centre);

// The image column a fragment in window column x takes inside `triangle`, of an image `width`
// groups wide; the image row a fragment in window row y takes, of an image `height` groups high.
// In an axis-aligned quad s depends on x only and t on y only (their other gradient is exactly
// zero), so each is a function of one window coordinate per triangle.
int mesa_pixel_column(const PixelQuad& quad, int triangle, int x, uint32_t width);
int mesa_pixel_row(const PixelQuad& quad, int triangle, int y, uint32_t height, bool rows_from_top);

}  // namespace glpt::rt
