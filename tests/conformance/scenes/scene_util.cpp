#include "scene_util.hpp"

#include <dlfcn.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace glpt::conformance::util {
namespace {

GLenum client_format(GLenum internal_format) {
  switch (internal_format) {
    case GL_RGB:
    case GL_RGB8:
      return GL_RGB;
    case GL_LUMINANCE:
    case GL_LUMINANCE8:
      return GL_LUMINANCE;
    case GL_LUMINANCE_ALPHA:
    case GL_LUMINANCE8_ALPHA8:
      return GL_LUMINANCE_ALPHA;
    case GL_ALPHA:
    case GL_ALPHA8:
      return GL_ALPHA;
    case GL_INTENSITY:
    case GL_INTENSITY8:
      // Intensity textures take their one component from LUMINANCE client data.
      return GL_LUMINANCE;
    default:
      return GL_RGBA;
  }
}

}  // namespace

void ortho_pixels(int width, int height) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, 0, height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void perspective(double fovy_degrees, double aspect, double z_near, double z_far) {
  const double top = z_near * std::tan(fovy_degrees * kPi / 360.0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-top * aspect, top * aspect, -top, top, z_near, z_far);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void lit_perspective(double fovy_degrees, double aspect) {
  perspective(fovy_degrees, aspect, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
}

void lit_perspective_light0(double fovy_degrees, double aspect) {
  lit_perspective(fovy_degrees, aspect);
  light4(GL_LIGHT0, GL_POSITION, -1, 1, 1, 0);
  glEnable(GL_LIGHT0);
}

void clear(float r, float g, float b, float a) {
  glClearColor(r, g, b, a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void sphere(float radius, int slices, int stacks) {
  for (int i = 0; i < stacks; ++i) {
    const double phi0 = kPi * i / stacks - kPi / 2, phi1 = kPi * (i + 1) / stacks - kPi / 2;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const double theta = 2 * kPi * j / slices;
      // Lower vertex first: counter-clockwise quads seen from outside (front faces).
      for (const double phi : {phi0, phi1}) {
        const float x = static_cast<float>(std::cos(phi) * std::cos(theta));
        const float y = static_cast<float>(std::sin(phi));
        const float z = static_cast<float>(std::cos(phi) * std::sin(theta));
        glTexCoord2f(static_cast<float>(j) / slices, static_cast<float>(phi / kPi + 0.5));
        glNormal3f(x, y, z);
        glVertex3f(radius * x, radius * y, radius * z);
      }
    }
    glEnd();
  }
}

void grid(float x0, float y0, float x1, float y1, int n) {
  glNormal3f(0, 0, 1);
  for (int i = 0; i < n; ++i) {
    const float t0 = static_cast<float>(i) / n, t1 = static_cast<float>(i + 1) / n;
    glBegin(GL_QUAD_STRIP);  // upper vertex first: counter-clockwise quads seen from +z
    for (int j = 0; j <= n; ++j) {
      const float s = static_cast<float>(j) / n;
      const float x = x0 + (x1 - x0) * s;
      glTexCoord2f(s, t1);
      glVertex3f(x, y0 + (y1 - y0) * t1, 0);
      glTexCoord2f(s, t0);
      glVertex3f(x, y0 + (y1 - y0) * t0, 0);
    }
    glEnd();
  }
}

void cube(float h) {
  // Per face: normal, then the four corners counter-clockwise seen from outside.
  static const float kFaces[6][3][3] = {
      // normal, "right" axis, "up" axis
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
  };
  static const float kCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  glBegin(GL_QUADS);
  for (const auto& f : kFaces) {
    glNormal3fv(f[0]);
    for (const auto& c : kCorners) {
      glTexCoord2f((c[0] + 1) / 2, (c[1] + 1) / 2);
      glVertex3f(h * (f[0][0] + c[0] * f[1][0] + c[1] * f[2][0]),
                 h * (f[0][1] + c[0] * f[1][1] + c[1] * f[2][1]),
                 h * (f[0][2] + c[0] * f[1][2] + c[1] * f[2][2]));
    }
  }
  glEnd();
}

void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(x0, y0, z);
  glTexCoord2f(1, 0);
  glVertex3f(x1, y0, z);
  glTexCoord2f(1, 1);
  glVertex3f(x1, y1, z);
  glTexCoord2f(0, 1);
  glVertex3f(x0, y1, z);
  glEnd();
}

void receding_floor(float s, float t) {
  perspective(60.0, 1.0, 0.3, 30.0);
  glTranslatef(0, -0.6f, -1.0f);
  glRotatef(-75, 1, 0, 0);
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1);
  glTexCoord2f(0, 0);
  glVertex3f(-2, -0.5f, 0);
  glTexCoord2f(s, 0);
  glVertex3f(2, -0.5f, 0);
  glTexCoord2f(s, t);
  glVertex3f(2, 12, 0);
  glTexCoord2f(0, t);
  glVertex3f(-2, 12, 0);
  glEnd();
}

void textured_quad(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0);
  glVertex2f(x0, y0);
  glTexCoord2f(s1, t0);
  glVertex2f(x1, y0);
  glTexCoord2f(s1, t1);
  glVertex2f(x1, y1);
  glTexCoord2f(s0, t1);
  glVertex2f(x0, y1);
  glEnd();
}

void light4(GLenum light, GLenum pname, float x, float y, float z, float w) {
  const float v[4] = {x, y, z, w};
  glLightfv(light, pname, v);
}

void material4(GLenum face, GLenum pname, float r, float g, float b, float a) {
  const float v[4] = {r, g, b, a};
  glMaterialfv(face, pname, v);
}

void light_model4(GLenum pname, float r, float g, float b, float a) {
  const float v[4] = {r, g, b, a};
  glLightModelfv(pname, v);
}

void fog_colour(float r, float g, float b, float a) {
  const float v[4] = {r, g, b, a};
  glFogfv(GL_FOG_COLOR, v);
}

void tex_env_colour(float r, float g, float b, float a) {
  const float v[4] = {r, g, b, a};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v);
}

void rgb_triangle(float x0, float y0, float x1, float y1, float x2, float y2) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(x0, y0);
  glColor3f(0, 1, 0);
  glVertex2f(x1, y1);
  glColor3f(0, 0, 1);
  glVertex2f(x2, y2);
  glEnd();
}

void coloured_quad(float x0, float y0, float x1, float y1, const float (&corners)[4][4]) {
  const float xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    glColor4fv(corners[i]);
    glVertex2f(xs[i], ys[i]);
  }
  glEnd();
}

std::vector<uint8_t> checker(int width, int height, int cell, Rgba8 a, Rgba8 b) {
  std::vector<uint8_t> out(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Rgba8 c = ((x / cell + y / cell) % 2 == 0) ? a : b;
      uint8_t* p = &out[(static_cast<size_t>(y) * width + x) * 4];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
      p[3] = c.a;
    }
  }
  return out;
}

std::vector<uint8_t> gradient(int width, int height, Rgba8 bl, Rgba8 br, Rgba8 tl, Rgba8 tr,
                              int grid) {
  std::vector<uint8_t> out(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int u = width > 1 ? x * 255 / (width - 1) : 0;
      const int v = height > 1 ? y * 255 / (height - 1) : 0;
      const uint8_t* corner[4] = {&bl.r, &br.r, &tl.r, &tr.r};
      uint8_t* p = &out[(static_cast<size_t>(y) * width + x) * 4];
      for (int c = 0; c < 4; ++c) {
        const int bottom = corner[0][c] * (255 - u) + corner[1][c] * u;
        const int top = corner[2][c] * (255 - u) + corner[3][c] * u;
        p[c] = static_cast<uint8_t>((bottom * (255 - v) + top * v) / (255 * 255));
      }
      if (grid > 0 && (x % grid == 0 || y % grid == 0)) {
        p[0] = static_cast<uint8_t>(p[0] / 4);
        p[1] = static_cast<uint8_t>(p[1] / 4);
        p[2] = static_cast<uint8_t>(p[2] / 4);
      }
    }
  }
  return out;
}

std::vector<uint8_t> convert(const std::vector<uint8_t>& rgba, GLenum format) {
  std::vector<uint8_t> out;
  out.reserve(rgba.size());
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    switch (format) {
      case GL_RGB:
        out.insert(out.end(), {rgba[i], rgba[i + 1], rgba[i + 2]});
        break;
      case GL_LUMINANCE:
        out.push_back(rgba[i]);
        break;
      case GL_ALPHA:
        out.push_back(rgba[i + 3]);
        break;
      case GL_LUMINANCE_ALPHA:
        out.insert(out.end(), {rgba[i], rgba[i + 3]});
        break;
      default:
        out.insert(out.end(), {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]});
        break;
    }
  }
  return out;
}

GLuint new_texture(GLenum target, GLenum min_filter, GLenum mag_filter, GLuint name) {
  if (name == 0) glGenTextures(1, &name);
  glBindTexture(target, name);
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min_filter));
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag_filter));
  return name;
}

GLuint texture_2d(GLenum internal_format, int width, int height, const std::vector<uint8_t>& rgba,
                  GLenum filter, GLenum wrap, GLuint name) {
  name = new_texture(GL_TEXTURE_2D, filter, filter, name);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLenum format = client_format(internal_format);
  const std::vector<uint8_t> data = convert(rgba, format);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format,
               GL_UNSIGNED_BYTE, data.data());
  return name;
}

void bitmap_text(const char* text) {
  // Rows top to bottom, bit 7 = left column.
  struct Glyph {
    char c;
    GLubyte rows[7];
  };
  static const Glyph kFont[] = {
      {'A', {0x70, 0x88, 0x88, 0xF8, 0x88, 0x88, 0x88}},
      {'B', {0xF0, 0x88, 0x88, 0xF0, 0x88, 0x88, 0xF0}},
      {'C', {0x70, 0x88, 0x80, 0x80, 0x80, 0x88, 0x70}},
      {'G', {0x70, 0x88, 0x80, 0xB8, 0x88, 0x88, 0x78}},
      {'K', {0x88, 0x90, 0xA0, 0xC0, 0xA0, 0x90, 0x88}},
      {'L', {0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0xF8}},
      {'O', {0x70, 0x88, 0x88, 0x88, 0x88, 0x88, 0x70}},
      {'P', {0xF0, 0x88, 0x88, 0xF0, 0x80, 0x80, 0x80}},
      {'T', {0xF8, 0x20, 0x20, 0x20, 0x20, 0x20, 0x20}},
      {'X', {0x88, 0x88, 0x50, 0x20, 0x50, 0x88, 0x88}},
      {'1', {0x20, 0x60, 0x20, 0x20, 0x20, 0x20, 0x70}},
      {'5', {0xF8, 0x80, 0xF0, 0x08, 0x08, 0x88, 0x70}},
      {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x60, 0x60}},
      {' ', {0, 0, 0, 0, 0, 0, 0}},
  };
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (const char* p = text; *p; ++p) {
    for (const Glyph& g : kFont) {
      if (g.c != *p) continue;
      GLubyte bottom_up[7];
      for (int r = 0; r < 7; ++r) bottom_up[r] = g.rows[6 - r];
      glBitmap(5, 7, 0, 0, 6, 0, bottom_up);
    }
  }
}

namespace {

// An extension command of the runner's GL. glpt's runner links glpt statically (the symbol is
// there, but not in the dynamic table: `linked`, a weak reference); Mesa's runner has OSMesa,
// whose library does not export extension commands but gives them through OSMesaGetProcAddress.
template <typename Fn>
Fn extension_command(Fn linked, const char* name) {
  if (linked != nullptr) return linked;
  using GetProc = void* (*)(const char*);
  if (void* osmesa = dlsym(RTLD_DEFAULT, "OSMesaGetProcAddress"))
    if (void* found = reinterpret_cast<GetProc>(osmesa)(name)) return reinterpret_cast<Fn>(found);
  std::fprintf(stderr, "scene: %s not found\n", name);
  std::abort();
}

}  // namespace

#pragma weak glActiveStencilFaceEXT
void active_stencil_face(GLenum face) {
  static const auto fn = extension_command(&glActiveStencilFaceEXT, "glActiveStencilFaceEXT");
  fn(face);
}

#pragma weak glBlitFramebufferEXT
void blit_framebuffer(GLint src_x0, GLint src_y0, GLint src_x1, GLint src_y1, GLint dst_x0,
                      GLint dst_y0, GLint dst_x1, GLint dst_y1, GLbitfield mask, GLenum filter) {
  static const auto fn = extension_command(&glBlitFramebufferEXT, "glBlitFramebufferEXT");
  fn(src_x0, src_y0, src_x1, src_y1, dst_x0, dst_y0, dst_x1, dst_y1, mask, filter);
}

}  // namespace glpt::conformance::util
