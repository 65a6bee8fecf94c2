#include "rt_core/raster/pixel_quad.hpp"

#include <algorithm>
#include <cmath>

namespace glpt::rt {
namespace {

// Every step is one float operation, rounded, in llvmpipe's order (the front end is compiled
// without FMA contraction).
struct Vertex {
  float x, y, s, t;
};

// lp_state_setup.c, init_args and calc_coef4, for one attribute.
glm::vec4 plane(const Vertex (&v)[3], float Vertex::*attribute) {
  const float x0_center = v[0].x - 0.5f, y0_center = v[0].y - 0.5f;
  const float dx01 = v[0].x - v[1].x, dy01 = v[0].y - v[1].y;
  const float dx20 = v[2].x - v[0].x, dy20 = v[2].y - v[0].y;
  const float e = dx01 * dy20, f = dy01 * dx20;
  const float ooa = 1.0f / (e - f);
  const float dx20_ooa = dx20 * ooa, dy20_ooa = dy20 * ooa;
  const float dx01_ooa = dx01 * ooa, dy01_ooa = dy01 * ooa;
  const float da01 = v[0].*attribute - v[1].*attribute;
  const float da20 = v[2].*attribute - v[0].*attribute;
  const float dadx = da01 * dy20_ooa - da20 * dy01_ooa;
  const float dady = da20 * dx01_ooa - da01 * dx20_ooa;
  const float a0 = v[0].*attribute - (dadx * x0_center + dady * y0_center);
  return {a0, dadx, dady, 0.0f};
}

// llvmpipe's triangle setup takes a clockwise triangle as (v1, v0, v2) (triangle_both, with the
// last vertex provoking): the sign of its fixed-point area decides.
void orient(Vertex (&v)[3]) {
  auto fixed = [](float c) { return std::llround(double{c} * 256.0); };
  const int64_t dx01 = fixed(v[0].x) - fixed(v[1].x), dy01 = fixed(v[0].y) - fixed(v[1].y);
  const int64_t dx20 = fixed(v[2].x) - fixed(v[0].x), dy20 = fixed(v[2].y) - fixed(v[0].y);
  if (dx01 * dy20 - dx20 * dy01 < 0) std::swap(v[0], v[1]);
}

}  // namespace

PixelQuad mesa_pixel_quad(glm::vec2 p0, glm::vec2 p1, uint32_t framebuffer_width,
                          uint32_t framebuffer_height, bool rows_from_top) {
  const float w = static_cast<float>(framebuffer_width), h = static_cast<float>(framebuffer_height);
  // Window -> clip (draw_textured_quad) -> Mesa's window through its y-inverting viewport (the
  // draw module's viewport transform is a fused multiply-add).
  auto mesa_x = [&](float x) { return std::fma(x / w * 2.0f - 1.0f, w * 0.5f, 0.5f * w); };
  auto mesa_y = [&](float y) { return std::fma(y / h * 2.0f - 1.0f, h * -0.5f, 0.5f * h); };
  const float x0 = mesa_x(p0.x), x1 = mesa_x(p1.x), y0 = mesa_y(p0.y), y1 = mesa_y(p1.y);
  // st_draw_quad's fan, with t running up the image (glDrawPixels) or down it (copies).
  const float t_bottom = rows_from_top ? 1.0f : 0.0f, t_top = 1.0f - t_bottom;
  const Vertex quad[4] = {{x0, y1, 0.0f, t_top},
                          {x1, y1, 1.0f, t_top},
                          {x1, y0, 1.0f, t_bottom},
                          {x0, y0, 0.0f, t_bottom}};
  PixelQuad result;
  const int fan[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (int i = 0; i < 2; ++i) {
    Vertex v[3] = {quad[fan[i][0]], quad[fan[i][1]], quad[fan[i][2]]};
    orient(v);
    result.s[i] = plane(v, &Vertex::s);
    result.t[i] = plane(v, &Vertex::t);
  }
  // The shared diagonal, from the fan's first vertex (p0.x, p1.y) to its third (p1.x, p0.y), in
  // window coordinates, signed so that the first triangle's other corner (p1) is inside.
  float a = -(p0.y - p1.y), b = p1.x - p0.x;
  float c = -(a * p0.x + b * p1.y);
  if (a * p1.x + b * p1.y + c < 0.0f) {
    a = -a;
    b = -b;
    c = -c;
  }
  result.diagonal = glm::vec4(a, b, c, h);
  return result;
}

int mesa_pixel_triangle(const PixelQuad& quad, glm::vec2 centre) {
  const glm::vec4& d = quad.diagonal;
  return d.x * centre.x + d.y * centre.y + d.z >= 0.0f ? 0 : 1;
}

// lp_bld_interp.c: a0 + dadx * x + dady * y as two fused multiply-adds, at Mesa's integer pixel
// coordinates (y from the top); then the NEAREST texel of a normalized coordinate.
int mesa_pixel_column(const PixelQuad& quad, int triangle, int x, uint32_t width) {
  const glm::vec4& c = quad.s[size_t(triangle)];
  const float u = std::fma(c.z, 0.0f, std::fma(c.y, float(x), c.x));
  return std::clamp(int(std::floor(u * float(width))), 0, int(width) - 1);
}

int mesa_pixel_row(const PixelQuad& quad, int triangle, int y, uint32_t height,
                   bool rows_from_top) {
  const glm::vec4& c = quad.t[size_t(triangle)];
  const float mesa_y = quad.diagonal.w - 1.0f - float(y);
  const float v = std::fma(c.z, mesa_y, std::fma(c.y, 0.0f, c.x));
  const int row = std::clamp(int(std::floor(v * float(height))), 0, int(height) - 1);
  return rows_from_top ? int(height) - 1 - row : row;
}

}  // namespace glpt::rt
