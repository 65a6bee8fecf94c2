// Helpers shared by the conformance scenes: projections, tessellated shapes with normals and
// texture coordinates, and procedural textures. All deterministic: the same object code runs in
// both runners, so the vertex data is bit-identical for Mesa and glpt.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "../scene.hpp"

namespace glpt::conformance::util {

inline constexpr double kPi = 3.14159265358979323846;

struct Rgba8 {
  uint8_t r, g, b, a;
};

// Projection = glOrtho(0, width, 0, height, -1, 1), modelview = identity: one unit per pixel,
// origin at the bottom-left corner of the viewport.
void ortho_pixels(int width, int height);
// Projection = glFrustum for a vertical field of view (degrees), modelview = identity.
void perspective(double fovy_degrees, double aspect, double z_near, double z_far);
// The usual 3-D setup: the perspective above (near 1, far 20), depth test and lighting on, no
// light enabled yet.
void lit_perspective(double fovy_degrees, double aspect);
// lit_perspective with GL_LIGHT0 on: its default white, directional from the upper left
// (-1, 1, 1) in eye space.
void lit_perspective_light0(double fovy_degrees, double aspect);
// Clears colour (to the given colour) and depth (to 1).
void clear(float r, float g, float b, float a = 1.0f);

// A sphere centred on the origin, outward normals, texture coordinates (s around, t up), drawn
// as quad strips: `slices` around the z axis, `stacks` from pole to pole.
void sphere(float radius, int slices, int stacks);
// The square [x0,x1] x [y0,y1] at z = 0, facing +z (normal 0,0,1), cut into n x n quads
// (per-vertex lighting needs vertices inside the spot of a light), texture coordinates 0..1.
void grid(float x0, float y0, float x1, float y1, int n);
// An axis-aligned cube of half-size `h` with per-face normals and texture coordinates 0..1.
void cube(float h);
// A white floor receding from the viewer under a 60-degree perspective, texture coordinates
// (0, 0)..(s, t): magnified in front, minified towards the horizon.
void receding_floor(float s, float t);
// A single quad with texture coordinates 0..1 (counter-clockwise from the bottom-left).
void quad(float x0, float y0, float x1, float y1, float z = 0.0f);
// A quad of x0..x1, y0..y1 (z = 0) with texture coordinates s0..s1, t0..t1.
void textured_quad(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1);
// A triangle at z = 0 with a red, a green and a blue corner, smooth-shaded between them.
void rgb_triangle(float x0, float y0, float x1, float y1, float x2, float y2);
// A quad at z = 0 with its own RGBA colour at each corner: bottom-left, bottom-right, top-right,
// top-left.
void coloured_quad(float x0, float y0, float x1, float y1, const float (&corners)[4][4]);

// glLightfv, glMaterialfv, glLightModelfv, glFogfv(GL_FOG_COLOR) and
// glTexEnvfv(GL_TEXTURE_ENV_COLOR) with four values given inline.
void light4(GLenum light, GLenum pname, float x, float y, float z, float w);
void material4(GLenum face, GLenum pname, float r, float g, float b, float a = 1.0f);
void light_model4(GLenum pname, float r, float g, float b, float a = 1.0f);
void fog_colour(float r, float g, float b, float a = 1.0f);
void tex_env_colour(float r, float g, float b, float a = 1.0f);

// A width x height checkerboard of `cell`-pixel squares alternating `a` and `b`, rows bottom
// first, RGBA8.
std::vector<uint8_t> checker(int width, int height, int cell, Rgba8 a, Rgba8 b);
// A width x height image whose four corners are the given colours, bilinear in between (a
// gradient that makes filtering and coordinate mistakes visible), plus a 1-pixel dark grid
// every `grid` pixels when grid > 0.
std::vector<uint8_t> gradient(int width, int height, Rgba8 bottom_left, Rgba8 bottom_right,
                              Rgba8 top_left, Rgba8 top_right, int grid);
// Converts RGBA8 pixels to the components of `format` (GL_RGB, GL_LUMINANCE, GL_ALPHA, ...):
// luminance and intensity take red, alpha takes alpha.
std::vector<uint8_t> convert(const std::vector<uint8_t>& rgba, GLenum format);
// Binds texture object `name` (a new one from glGenTextures when 0) to `target` and sets its
// filters. Returns the name.
GLuint new_texture(GLenum target, GLenum min_filter, GLenum mag_filter, GLuint name = 0);
// Creates and binds a 2D texture of level 0 only from RGBA8 pixels, with the given internal
// format (pixels converted to the matching client format), filters and wrap modes. The texture
// object is `name`, or a new one from glGenTextures when `name` is 0.
GLuint texture_2d(GLenum internal_format, int width, int height, const std::vector<uint8_t>& rgba,
                  GLenum filter = GL_NEAREST, GLenum wrap = GL_REPEAT, GLuint name = 0);

// glBitmap text at the current raster position with a 5x7 font, advancing 6 pixels per
// character (GL_UNPACK_ALIGNMENT is set to 1). Knows A B C G K L O P T X 1 5 '.' and ' '; other
// characters draw nothing and do not advance.
void bitmap_text(const char* text);

// glActiveStencilFaceEXT (EXT_stencil_two_side), looked up by name: OSMesa exports only core
// commands, extension ones through OSMesaGetProcAddress.
void active_stencil_face(GLenum face);
// glBlitFramebufferEXT (EXT_framebuffer_blit), looked up by name as above.
void blit_framebuffer(GLint src_x0, GLint src_y0, GLint src_x1, GLint src_y1, GLint dst_x0,
                      GLint dst_y0, GLint dst_x1, GLint dst_y1, GLbitfield mask, GLenum filter);

}  // namespace glpt::conformance::util
