// EXT_texture_compression_s3tc through ARB_texture_compression's commands: DXT1 (RGB and RGBA),
// DXT3 and DXT5 blocks decoded as Mesa's llvmpipe decodes them (every block mode: DXT1's
// 3-colour mode with its transparent black, DXT5's 6- and 8-alpha modes), sampled with nearest
// and linear filters and mipmaps, updated by sub-images, of sizes that are not multiples of 4,
// on cube faces, compiled into display lists, and compressed from uncompressed data and from the
// framebuffer by Mesa's encoder. The blocks are pseudo-random (a fixed-seed generator) so that
// every colour and alpha interpolation shows up somewhere.
#include <algorithm>
#include <array>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

constexpr GLenum kDxt1Rgb = GL_COMPRESSED_RGB_S3TC_DXT1_EXT;
constexpr GLenum kDxt1Rgba = GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
constexpr GLenum kDxt3 = GL_COMPRESSED_RGBA_S3TC_DXT3_EXT;
constexpr GLenum kDxt5 = GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
constexpr std::array<GLenum, 4> kFormats = {kDxt1Rgb, kDxt1Rgba, kDxt3, kDxt5};

int block_bytes(GLenum format) { return format == kDxt1Rgb || format == kDxt1Rgba ? 8 : 16; }
int image_size(GLenum format, int w, int h) {
  return ((w + 3) / 4) * ((h + 3) / 4) * block_bytes(format);
}

// A fixed-seed linear congruential generator: the same bytes in both runners.
struct Lcg {
  uint32_t state;
  uint8_t next() {
    state = state * 1664525u + 1013904223u;
    return static_cast<uint8_t>(state >> 24);
  }
};

// One colour block. Block n alternates the modes: even blocks put the larger 5-6-5 word first
// (4-colour mode), odd ones the smaller (DXT1's 3-colour mode with index 3 transparent black;
// DXT3 and DXT5 decode 4 colours either way).
void colour_block(Lcg& rng, int n, uint8_t* out) {
  for (int k = 0; k < 8; ++k) out[k] = rng.next();
  const int c0 = out[0] | out[1] << 8, c1 = out[2] | out[3] << 8;
  if ((c0 > c1) != (n % 2 == 0)) {
    std::swap(out[0], out[2]);
    std::swap(out[1], out[3]);
  }
}

// One DXT5 alpha block: every third block in the 6-alpha mode (a0 <= a1, codes 6 and 7 are 0
// and 255), the others in the 8-alpha mode.
void dxt5_alpha_block(Lcg& rng, int n, uint8_t* out) {
  for (int k = 0; k < 8; ++k) out[k] = rng.next();
  if ((out[0] > out[1]) == (n % 3 == 0)) std::swap(out[0], out[1]);
}

// The blocks of a w x h image of `format`.
std::vector<uint8_t> blocks(GLenum format, int w, int h, uint32_t seed) {
  Lcg rng{seed};
  std::vector<uint8_t> data(static_cast<size_t>(image_size(format, w, h)));
  const int bytes = block_bytes(format);
  for (size_t n = 0; n * bytes < data.size(); ++n) {
    uint8_t* block = data.data() + n * bytes;
    if (bytes == 8) {
      colour_block(rng, static_cast<int>(n), block);
      continue;
    }
    if (format == kDxt5)
      dxt5_alpha_block(rng, static_cast<int>(n), block);
    else
      for (int k = 0; k < 8; ++k) block[k] = rng.next();
    colour_block(rng, static_cast<int>(n), block + 8);
  }
  return data;
}

void compressed_2d(GLenum target, GLint level, GLenum format, int w, int h, uint32_t seed) {
  const std::vector<uint8_t> data = blocks(format, w, h, seed);
  glCompressedTexImage2D(target, level, format, w, h, 0, static_cast<GLsizei>(data.size()),
                         data.data());
}

// A backdrop for the formats with alpha: a gradient the texels are blended over or cut out of.
void backdrop(int w, int h) {
  const float corners[4][4] = {
      {0.9f, 0.2f, 0.1f, 1}, {0.1f, 0.8f, 0.2f, 1}, {0.2f, 0.3f, 0.9f, 1}, {0.9f, 0.9f, 0.2f, 1}};
  coloured_quad(0, 0, static_cast<float>(w), static_cast<float>(h), corners);
}

// The four formats side by side, each a 16x16 texture on a 30x30 quad (or 32x32 ones on 60x60
// quads for `large`), texture environment REPLACE, blended over the backdrop.
void four_formats(GLenum filter, int size, float quad) {
  const int w = static_cast<int>(2 * quad + 6);
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(w, w);
  backdrop(w, w);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int i = 0; i < 4; ++i) {
    new_texture(GL_TEXTURE_2D, filter, filter);
    compressed_2d(GL_TEXTURE_2D, 0, kFormats[i], size, size, 17u + static_cast<uint32_t>(i));
    const float x = 2 + static_cast<float>(i % 2) * (quad + 2);
    const float y = 2 + static_cast<float>(i / 2) * (quad + 2);
    textured_quad(x, y, x + quad, y + quad, 0, 0, 1, 1);
  }
}

// Every texel of each format at 2x2 pixels (no texel edge on a pixel centre): the decoded
// colours and alphas exactly, in every block mode.
GLPT_SCENE(texture_s3tc_formats_nearest, 134, 134) { four_formats(GL_NEAREST, 32, 64); }

// The same blocks magnified about 4x with GL_LINEAR: interpolation between decoded texels,
// across block edges.
GLPT_SCENE(texture_s3tc_formats_linear, 128, 128) { four_formats(GL_LINEAR, 16, 61); }

// DXT1 RGBA's transparent black cut out by the alpha test (and DXT1 RGB's opaque black next to
// it), over the backdrop: the 3-colour blocks' index 3 is alpha 0 only in the RGBA format.
GLPT_SCENE(texture_s3tc_dxt1_alpha_test, 80, 104) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(80, 104);
  backdrop(80, 104);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor4f(1, 1, 1, 1);
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  compressed_2d(GL_TEXTURE_2D, 0, kDxt1Rgba, 16, 16, 5);
  // 3 pixels per texel: no texel edge on a pixel centre.
  textured_quad(2, 2, 74, 50, 0, 0, 1.5f, 1);
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  compressed_2d(GL_TEXTURE_2D, 0, kDxt1Rgb, 16, 16, 5);
  textured_quad(2, 54, 74, 102, 0, 0, 1.5f, 1);
}

// Mip chains of compressed levels (32x32 down to the 2x2 and 1x1 levels, which are single
// partial blocks), each level its own blocks, trilinear on a receding floor.
void mipmapped_floor(GLenum format, GLenum min_filter) {
  clear(0.3f, 0.5f, 0.7f);
  new_texture(GL_TEXTURE_2D, min_filter, GL_LINEAR);
  for (int level = 0, size = 32; size >= 1; ++level, size /= 2)
    compressed_2d(GL_TEXTURE_2D, level, format, size, size, 100u + static_cast<uint32_t>(level));
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  receding_floor(4, 8);
}

GLPT_SCENE(texture_s3tc_dxt1_mipmaps_trilinear, 64, 64) {
  mipmapped_floor(kDxt1Rgb, GL_LINEAR_MIPMAP_LINEAR);
}
GLPT_SCENE(texture_s3tc_dxt5_mipmaps_nearest, 64, 64) {
  mipmapped_floor(kDxt5, GL_NEAREST_MIPMAP_NEAREST);
}

// Sizes that are not multiples of 4 (13x7, 5x3, 2x2, 1x1: the edge blocks' outer texels are not
// part of the image) and glCompressedTexSubImage2D on them: aligned blocks inside, and the
// partial blocks at the right and top edges, which the extension lets a sub-image cover. The
// unpack modes set here do not apply to compressed data (GL 1.x has no compressed pack state).
GLPT_SCENE(texture_s3tc_sub_images_odd_sizes, 128, 64) {
  clear(0.1f, 0.1f, 0.2f);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  ortho_pixels(128, 64);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const int sizes[4][2] = {{13, 7}, {5, 3}, {2, 2}, {1, 1}};
  for (int i = 0; i < 4; ++i) {
    new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
    const GLenum format = kFormats[static_cast<size_t>(3 - i)];
    const int w = sizes[i][0], h = sizes[i][1];
    compressed_2d(GL_TEXTURE_2D, 0, format, w, h, 40u + static_cast<uint32_t>(i));
    // The top-right (partial) block replaced, then for the 13x7 image an inner block and the
    // last column of blocks (1 texel wide).
    const int bx = (w - 1) / 4 * 4, by = (h - 1) / 4 * 4;
    const std::vector<uint8_t> patch =
        blocks(format, w - bx, h - by, 90u + static_cast<uint32_t>(i));
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, bx, by, w - bx, h - by, format,
                              static_cast<GLsizei>(patch.size()), patch.data());
    if (w == 13) {
      const std::vector<uint8_t> inner = blocks(format, 4, 4, 77);
      glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 4, 4, format,
                                static_cast<GLsizei>(inner.size()), inner.data());
      const std::vector<uint8_t> column = blocks(format, 1, 7, 78);
      glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 12, 0, 1, 7, format,
                                static_cast<GLsizei>(column.size()), column.data());
    }
    // Quads of 5 pixels per texel wide and high: no texel edge on a pixel centre.
    const float x = std::array<float, 4>{2, 70, 98, 112}[static_cast<size_t>(i)];
    textured_quad(x, 2, x + 5.0f * static_cast<float>(w), 2 + 5.0f * static_cast<float>(h), 0, 0, 1,
                  1);
  }
}

// Uncompressed data into S3TC formats: Mesa compresses it (libtxc_dxtn's encoder), and so does
// glpt, byte for byte: glTexImage2D of a gradient with a grid, glTexSubImage2D of a checker into
// one block-aligned part (re-compressed there only), and glCopyTexImage2D from the framebuffer.
GLPT_SCENE(texture_s3tc_compressed_by_driver, 128, 128) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(128, 128);
  backdrop(128, 128);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const std::vector<uint8_t> image =
      gradient(24, 24, Rgba8{250, 30, 30, 255}, Rgba8{30, 250, 60, 40}, Rgba8{40, 60, 250, 200},
               Rgba8{250, 250, 250, 0}, 5);
  const std::vector<uint8_t> patch =
      checker(8, 8, 2, Rgba8{255, 255, 0, 255}, Rgba8{0, 0, 128, 60});
  // Copied from the backdrop before anything else is drawn over it.
  const GLuint copied = new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 10, 20, 24, 24, 0);
  glEnable(GL_TEXTURE_2D);
  for (int i = 0; i < 4; ++i) {
    new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(kFormats[static_cast<size_t>(i)]), 24, 24, 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 12, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, patch.data());
    const float x = 4 + static_cast<float>(i % 2) * 50;
    const float y = 4 + static_cast<float>(i / 2) * 50;
    textured_quad(x, y, x + 48, y + 48, 0, 0, 1, 1);
  }
  glDisable(GL_BLEND);
  glBindTexture(GL_TEXTURE_2D, copied);
  textured_quad(104, 4, 128, 124, 0, 0, 1, 1);
}

// GL_GENERATE_MIPMAP on compressed base levels: Mesa builds the levels in software from the base
// level as its CPU decoder decodes it (2x2 boxes, truncated) and compresses each with its
// encoder. A 32x32 DXT1 image of random blocks and a 48x24 DXT5 image compressed from a gradient,
// each drawn at 1/2, 1/4, 1/8 and 1/16 of its size (one level each, texel centres on pixel
// centres), alpha kept in the image.
GLPT_SCENE(texture_s3tc_generated_mipmaps, 128, 64) {
  clear(0.1f, 0.1f, 0.2f, 0.5f);
  ortho_pixels(128, 64);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const GLuint random = new_texture(GL_TEXTURE_2D, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  compressed_2d(GL_TEXTURE_2D, 0, kDxt1Rgb, 32, 32, 3);
  const GLuint smooth = new_texture(GL_TEXTURE_2D, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const std::vector<uint8_t> image =
      gradient(48, 24, Rgba8{250, 30, 30, 255}, Rgba8{30, 250, 60, 40}, Rgba8{40, 60, 250, 200},
               Rgba8{250, 250, 250, 0}, 7);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(kDxt5), 48, 24, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.data());
  float x = 2;
  for (int k = 1; k <= 4; ++k) {
    const float s = static_cast<float>(32 >> k);
    glBindTexture(GL_TEXTURE_2D, random);
    textured_quad(x, 2, x + s, 2 + s, 0, 0, 1, 1);
    glBindTexture(GL_TEXTURE_2D, smooth);
    textured_quad(x, 24, x + 1.5f * s, 24 + 0.75f * s, 0, 0, 1, 1);
    x += 1.5f * s + 3;
  }
}

// Cube map faces of DXT1 blocks (one format: faces of different formats leave the cube
// incomplete), looked up by direction (texture coordinates are the directions to the six faces'
// centres and edges).
GLPT_SCENE(texture_s3tc_cube_map, 96, 96) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(96, 96);
  new_texture(GL_TEXTURE_CUBE_MAP, GL_LINEAR, GL_NEAREST);
  for (int face = 0; face < 6; ++face)
    compressed_2d(GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face), 0, kDxt1Rgb, 8, 8,
                  60u + static_cast<uint32_t>(face));
  glEnable(GL_TEXTURE_CUBE_MAP);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const float dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    // A quad spanning the face: the major axis fixed, the other two from -0.9 to 0.9.
    const int major = f / 2;
    const int u = (major + 1) % 3, v = (major + 2) % 3;
    const float x = 2 + static_cast<float>(f % 3) * 31, y = 2 + static_cast<float>(f / 3) * 46;
    glBegin(GL_QUADS);
    const float corners[4][2] = {{-0.9f, -0.9f}, {0.9f, -0.9f}, {0.9f, 0.9f}, {-0.9f, 0.9f}};
    for (const auto& c : corners) {
      float dir[3] = {dirs[f][0], dirs[f][1], dirs[f][2]};
      dir[u] = c[0];
      dir[v] = c[1];
      glTexCoord3fv(dir);
      glVertex2f(x + (c[0] + 0.9f) / 1.8f * 29, y + (c[1] + 0.9f) / 1.8f * 44);
    }
    glEnd();
  }
}

// glCompressedTexImage2D and glCompressedTexSubImage2D compiled into a display list copy their
// data at compile time: the client's array is overwritten before the list runs.
GLPT_SCENE(texture_s3tc_display_list, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  std::vector<uint8_t> data = blocks(kDxt3, 16, 16, 31);
  std::vector<uint8_t> patch = blocks(kDxt3, 4, 4, 32);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt3, 16, 16, 0, static_cast<GLsizei>(data.size()),
                         data.data());
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 8, 4, 4, 4, kDxt3, static_cast<GLsizei>(patch.size()),
                            patch.data());
  glEndList();
  data = blocks(kDxt3, 16, 16, 99);
  patch = blocks(kDxt3, 4, 4, 98);
  glCallList(list);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  textured_quad(0, 0, 64, 64, 0, 0, 1, 1);
}

// The errors of the compressed commands, each shown as the colour of one 6x6 square (GL_NO_ERROR
// grey, GL_INVALID_ENUM red, GL_INVALID_VALUE green, GL_INVALID_OPERATION blue), and the
// GL_TEXTURE_COMPRESSED_IMAGE_SIZE answers as grey levels; a failed command leaves the texture
// as it was, which the textured quad at the top shows. The state dump then compares the bound
// textures' internal formats and GL_TEXTURE_COMPRESSED.
GLPT_SCENE(texture_s3tc_errors, 96, 96) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(96, 96);
  int square = 0;
  const auto show = [&square](float r, float g, float b) {
    glColor3f(r, g, b);
    const float x = static_cast<float>(square % 12) * 8, y = static_cast<float>(square / 12) * 8;
    quad(x, y, x + 6, y + 6);
    ++square;
  };
  const auto check = [&show] {
    switch (glGetError()) {
      case GL_NO_ERROR:
        return show(0.5f, 0.5f, 0.5f);
      case GL_INVALID_ENUM:
        return show(1, 0, 0);
      case GL_INVALID_VALUE:
        return show(0, 1, 0);
      case GL_INVALID_OPERATION:
        return show(0, 0, 1);
      default:
        return show(1, 1, 1);
    }
  };
  const std::vector<uint8_t> data = blocks(kDxt5, 16, 16, 7);
  const std::vector<uint8_t> odd = blocks(kDxt1Rgb, 13, 7, 8);
  std::vector<uint8_t> out(4096);
  const GLuint tex = new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt5, 16, 16, 0, 256, data.data());
  check();
  // glCompressedTexImage2D: imageSize one short and one long, a border, a negative width, bad
  // levels, a generic and an uncompressed format, 1-D and cube-map targets, a non-square face.
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt5, 16, 16, 0, 255, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt5, 16, 16, 0, 257, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt5, 16, 16, 1, 256, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt5, -4, 16, 0, 256, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_2D, -1, kDxt5, 16, 16, 0, 256, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_2D, 20, kDxt5, 16, 16, 0, 256, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 16, 16, 0, 256, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, 256, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_1D, 0, kDxt5, 16, 16, 0, 256, data.data());
  check();
  glCompressedTexImage1D(GL_TEXTURE_1D, 0, kDxt1Rgb, 16, 0, 32, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP, 0, kDxt5, 16, 16, 0, 256, data.data());
  check();
  glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, kDxt5, 16, 8, 0, 128, data.data());
  check();
  // glCompressedTexSubImage2D: aligned (fine), offset and size not on block edges, a partial
  // block not at the image's edge, beyond the image, imageSize wrong, another S3TC format, an
  // uncompressed and a generic format, an undefined level, a 1-D target.
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 8, 8, 4, kDxt5, 32, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, kDxt5, 16, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 6, 4, 4, kDxt5, 16, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 6, 4, kDxt5, 32, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 12, 12, 8, 4, kDxt5, 32, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, kDxt5, 15, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, kDxt3, 16, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, 16, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_COMPRESSED_RGBA, 16, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 4, 4, kDxt5, 16, data.data());
  check();
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -4, 4, kDxt5, 16, data.data());
  check();
  glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, kDxt5, 16, data.data());
  check();
  // glTexSubImage2D and glCopyTexSubImage2D into the compressed image: block edges only.
  glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  check();
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 5, 0, 0, 4, 4);
  check();
  glTexImage1D(GL_TEXTURE_1D, 0, static_cast<GLint>(kDxt1Rgb), 8, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               out.data());
  check();
  glTexImage2D(GL_TEXTURE_2D, 1, static_cast<GLint>(kDxt1Rgb), 8, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE,
               out.data());
  check();
  glCopyTexImage2D(GL_TEXTURE_2D, 1, kDxt1Rgb, 0, 0, 8, 8, 1);
  check();
  // glGetCompressedTexImage: the image (fine), an undefined level, a proxy, bad levels.
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, out.data());
  check();
  glGetCompressedTexImage(GL_TEXTURE_2D, 3, out.data());
  check();
  glGetCompressedTexImage(GL_PROXY_TEXTURE_2D, 0, out.data());
  check();
  glGetCompressedTexImage(GL_TEXTURE_2D, -1, out.data());
  check();
  // The blocks came back as given but for the 8x4 sub-image.
  // (Blocks 9 and 10, bytes 144-175, hold the sub-image.)
  show(std::equal(out.begin(), out.begin() + 144, data.begin()) ? 1.0f : 0.0f,
       std::equal(out.begin() + 176, out.begin() + 256, data.begin() + 176) ? 1.0f : 0.0f, 0);
  // GL_TEXTURE_COMPRESSED_IMAGE_SIZE: 256; an undefined level and a proxy: errors.
  GLint size = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
  show(static_cast<float>(size) / 512.0f, 0, 0);
  check();
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
  check();
  glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, kDxt1Rgb, 13, 7, 0, 64, nullptr);
  check();
  GLint compressed = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
  show(static_cast<float>(compressed), 0, 0);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
  check();
  // An uncompressed texture: sub-images and reads of compressed data are errors.
  const GLuint plain = new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, kDxt5, 16, data.data());
  check();
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, out.data());
  check();
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
  check();
  glDeleteTextures(1, &plain);
  // A 13x7 DXT1 image on unit 1 for the state dump, its size as a grey level.
  glActiveTexture(GL_TEXTURE1);
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1Rgb, 13, 7, 0, 64, odd.data());
  check();
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
  show(0, static_cast<float>(size) / 128.0f, 0);
  glActiveTexture(GL_TEXTURE0);
  // What the failed commands left: the texture with the one sub-image.
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  textured_quad(16, 46, 80, 94, 0, 0, 1, 1);  // 4 x 3 pixels per texel
  glDisable(GL_TEXTURE_2D);
}

}  // namespace

namespace {

// ARB_texture_compression's generic formats as Mesa stores them: GL_COMPRESSED_RGB and
// GL_COMPRESSED_RGBA become DXT1 and DXT5 (the texels its encoder leaves, which differ from the
// data) on 2-D, cube-map and rectangle images and from glCopyTexImage2D, and stay uncompressed on
// 1-D images; GL_COMPRESSED_ALPHA and GL_COMPRESSED_INTENSITY stay uncompressed. torcs uploads
// its track map as GL_COMPRESSED_RGBA from signed bytes. Each image is drawn with 2 pixels per
// texel (nearest); the answers of GL_TEXTURE_INTERNAL_FORMAT / GL_TEXTURE_COMPRESSED /
// GL_TEXTURE_COMPRESSED_IMAGE_SIZE show as the colours of the squares along the top, and the
// state dump compares the textures left bound on units 1 and 2.
GLPT_SCENE(texture_generic_compressed_formats, 160, 128) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(160, 128);
  backdrop(160, 128);
  const std::vector<uint8_t> image =
      gradient(24, 24, Rgba8{250, 30, 30, 255}, Rgba8{30, 250, 60, 40}, Rgba8{40, 60, 250, 200},
               Rgba8{250, 250, 250, 0}, 5);
  // Signed bytes: the gradient at half range, its alpha negative (0) in one corner.
  std::vector<int8_t> half(image.size());
  for (size_t i = 0; i < image.size(); ++i) half[i] = static_cast<int8_t>(image[i] / 2);
  half[3] = -100;
  int square = 0;
  const auto show = [&square](float r, float g, float b) {
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_BLEND);
    glColor3f(r, g, b);
    const float x = 2 + static_cast<float>(square) * 8;
    quad(x, 118, x + 6, 124);
    ++square;
  };
  const auto query = [&show](GLenum target) {
    GLint format = 0, compressed = 0, size = 0;
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_COMPRESSED, &compressed);
    if (compressed != 0)
      glGetTexLevelParameteriv(target, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
    show(format == GL_COMPRESSED_RGB_S3TC_DXT1_EXT    ? 1.0f
         : format == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT ? 0.5f
                                                      : static_cast<float>(format & 0xFF) / 255.0f,
         static_cast<float>(compressed), static_cast<float>(size) / 1024.0f);
    if (glGetError() != GL_NO_ERROR) show(1, 1, 1);
  };
  // Copied from the backdrop first: GL_COMPRESSED_RGBA from the framebuffer (unit 2, for the
  // state dump).
  glActiveTexture(GL_TEXTURE2);
  const GLuint copied = new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 10, 20, 24, 24, 0);
  query(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const auto draw = [](float x, float y) {
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    textured_quad(x, y, x + 48, y + 48, 0, 0, 1, 1);
  };
  const GLenum generic[] = {GL_COMPRESSED_RGB, GL_COMPRESSED_RGBA, GL_COMPRESSED_ALPHA,
                            GL_COMPRESSED_INTENSITY};
  for (int i = 0; i < 4; ++i) {
    new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(generic[i]), 24, 24, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, image.data());
    query(GL_TEXTURE_2D);
    draw(2 + static_cast<float>(i % 3) * 52, 2 + static_cast<float>(i / 3) * 52);
  }
  // torcs's way: signed bytes into GL_COMPRESSED_RGBA, with the compression hint at its nicest.
  glHint(GL_TEXTURE_COMPRESSION_HINT, GL_NICEST);
  glActiveTexture(GL_TEXTURE1);
  new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 24, 24, 0, GL_RGBA, GL_BYTE, half.data());
  query(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  draw(54, 54);
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  // A cube-map face and a 1-D image (uncompressed), both queried; the copy drawn last.
  new_texture(GL_TEXTURE_CUBE_MAP, GL_NEAREST, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_COMPRESSED_RGB, 24, 24, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, image.data());
  query(GL_TEXTURE_CUBE_MAP_POSITIVE_X);
  new_texture(GL_TEXTURE_1D, GL_NEAREST, GL_NEAREST);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_COMPRESSED_RGBA, 24, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.data());
  query(GL_TEXTURE_1D);
  glBindTexture(GL_TEXTURE_2D, copied);
  draw(106, 54);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_BLEND);
}

}  // namespace
