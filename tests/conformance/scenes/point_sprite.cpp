// GL_ARB_point_sprite (GL 2.0 3.3.1): points drawn as squares whose texture coordinates run
// from 0 to 1 across the square on units with GL_COORD_REPLACE, the sprite origin GL 2.0 added
// (GL_POINT_SPRITE_COORD_ORIGIN), with the point parameters' distance attenuation, mipmaps and
// blending as particle systems use them, and the state as point state (GL_POINT_BIT).
#include <cmath>
#include <vector>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// An 8x8 texture with every texel distinct (red across, green up, a blue checker), so a wrong
// origin, a flipped axis or a texel off by one shows. GL_NEAREST on unit 0, GL_MODULATE.
void sprite_texture() {
  std::vector<uint8_t> texels(8 * 8 * 4);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      uint8_t* t = &texels[size_t(y * 8 + x) * 4];
      t[0] = uint8_t(20 + 33 * x);
      t[1] = uint8_t(20 + 33 * y);
      t[2] = (x + y) % 2 == 0 ? 230 : 40;
      t[3] = 255;
    }
  }
  texture_2d(GL_RGBA, 8, 8, texels, GL_NEAREST, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
}

// A row of sprites of sizes 3 to 24, integer and not, at sub-pixel offsets, each with its own
// vertex colour and a vertex texture coordinate that GL_COORD_REPLACE must override.
void sprite_rows(float y0) {
  const float sizes[7] = {3.0f, 4.5f, 7.0f, 8.0f, 12.5f, 16.0f, 23.7f};
  float x = 4.0f;
  for (int i = 0; i < 7; ++i) {
    glPointSize(sizes[i]);
    glBegin(GL_POINTS);
    glColor3f(1.0f, 1.0f - 0.08f * i, 0.7f + 0.04f * i);
    glTexCoord2f(0.3f, 0.6f);
    glVertex2f(x + sizes[i] * 0.5f + 0.3f * i, y0 + 12.0f + 0.17f * i);
    glEnd();
    x += sizes[i] + 3.0f;
  }
}

void sprite_scene(GLenum origin) {
  clear(0.05f, 0.05f, 0.1f);
  ortho_pixels(128, 32);
  sprite_texture();
  glEnable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  if (origin != 0) glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GLint(origin));
  sprite_rows(0.0f);
}

// The default origin, GL_UPPER_LEFT: t = 0 at the top of each sprite.
GLPT_SCENE(point_sprite_coord_replace, 128, 32) { sprite_scene(0); }

// GL_LOWER_LEFT: t = 0 at the bottom.
GLPT_SCENE(point_sprite_origin_lower_left, 128, 32) { sprite_scene(GL_LOWER_LEFT); }

// Sprites without GL_COORD_REPLACE: squares of the unrounded size, textured with the vertex's
// coordinates (constant across each); GL_POINT_SMOOTH is ignored for sprites. The lower row is
// the same points without sprites: round, rounded sizes.
GLPT_SCENE(point_sprite_without_coord_replace, 128, 64) {
  clear(0.05f, 0.05f, 0.1f);
  ortho_pixels(128, 64);
  sprite_texture();
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_POINT_SPRITE);
  sprite_rows(32.0f);
  glDisable(GL_POINT_SPRITE);
  glDisable(GL_POINT_SMOOTH);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);  // no effect without sprites
  sprite_rows(0.0f);
}

// Polygons in GL_POINT mode: their vertices are sprites too (GL 2.0 3.3.1, as Mesa draws them),
// of an unrounded size, front and back faces alike.
GLPT_SCENE(point_sprite_polygon_mode, 64, 64) {
  clear(0.05f, 0.05f, 0.1f);
  ortho_pixels(64, 64);
  sprite_texture();
  glEnable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(11.5f);
  glColor3f(1.0f, 0.9f, 0.8f);
  glBegin(GL_QUADS);
  glVertex2f(10.3f, 10.2f);
  glVertex2f(30.6f, 10.2f);
  glVertex2f(30.6f, 28.7f);
  glVertex2f(10.3f, 28.7f);
  glEnd();
  glPointSize(16.0f);
  glBegin(GL_TRIANGLES);  // clockwise: a back face
  glVertex2f(40.2f, 40.4f);
  glVertex2f(52.7f, 52.3f);
  glVertex2f(52.7f, 40.4f);
  glEnd();
}

// A particle system as games of the time draw one: additive blending, no depth writes, a soft
// round mipmapped texture (GL_LINEAR_MIPMAP_LINEAR) on sprites whose size falls off with eye
// distance (point parameters), clamped to [2, 40], receding in perspective.
GLPT_SCENE(point_sprite_particles, 96, 96) {
  clear(0.0f, 0.0f, 0.05f);
  perspective(60.0, 1.0, 0.5, 40.0);
  const GLuint tex = new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  (void)tex;
  for (int level = 0, size = 32; size >= 1; ++level, size /= 2) {
    std::vector<uint8_t> texels(size_t(size * size) * 4);
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const float dx = (x + 0.5f) / float(size) - 0.5f, dy = (y + 0.5f) / float(size) - 0.5f;
        const float r2 = 4.0f * (dx * dx + dy * dy);
        const float a = r2 >= 1.0f ? 0.0f : (1.0f - r2) * (1.0f - r2);
        uint8_t* t = &texels[size_t(y * size + x) * 4];
        t[0] = uint8_t(255 * a);
        t[1] = uint8_t(200 * a * (0.5f + dx));
        t[2] = uint8_t(120 * a * (0.5f + dy));
        t[3] = uint8_t(255 * a);
      }
    }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels.data());
  }
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_POINT_SPRITE);
  glTexEnvf(GL_POINT_SPRITE, GL_COORD_REPLACE, 1.0f);
  const float attenuation[3] = {0.0f, 0.0f, 0.02f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
  glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 40.0f);
  glPointSize(30.0f);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glBegin(GL_POINTS);
  for (int i = 0; i < 40; ++i) {
    const float a = 0.7f * float(i);
    glColor4f(1.0f, 0.6f + 0.01f * i, 0.9f - 0.02f * i, 0.8f);
    glVertex3f(1.6f * std::cos(a) * (1.0f - 0.015f * i), 1.2f * std::sin(a) - 0.2f,
               -2.0f - 0.55f * float(i));
  }
  glEnd();
}

// Two units: unit 0 replaced by the sprite's coordinates, unit 1 keeping the vertex's (a 2x2
// tint texture, GL_MODULATE over unit 0). The centres are off the pixel grid: where a sprite
// coordinate falls exactly on an edge between GL_NEAREST texels, Mesa (which computes it in its
// y-down window coordinates) and glpt (in GL's y-up ones) may round it to different sides, one
// texel row apart; GL 2.0 3.3.1 specifies the coordinate, not its rounding.
GLPT_SCENE(point_sprite_two_units, 64, 32) {
  clear(0.05f, 0.05f, 0.1f);
  ortho_pixels(64, 32);
  glActiveTexture(GL_TEXTURE0);
  sprite_texture();
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glActiveTexture(GL_TEXTURE1);
  const std::vector<uint8_t> tint = checker(2, 2, 1, {255, 120, 120, 255}, {120, 255, 255, 255});
  texture_2d(GL_RGBA, 2, 2, tint, GL_NEAREST, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_POINT_SPRITE);
  glPointSize(14.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 4; ++i) {
    glColor3f(1, 1, 1);
    glMultiTexCoord2f(GL_TEXTURE1, 0.25f + 0.5f * float(i % 2), 0.25f + 0.5f * float(i / 2));
    glVertex2f(9.0f + 15.0f * i, 16.3f);
  }
  glEnd();
  glActiveTexture(GL_TEXTURE0);
}

// The state: GL_COORD_REPLACE is per unit and point state, saved and restored with
// GL_POINT_BIT (not GL_TEXTURE_BIT); GL_POINT_SPRITE with GL_ENABLE_BIT and GL_POINT_BIT; bad
// values are GL_INVALID_VALUE and bad names GL_INVALID_ENUM. The scene draws one sprite per
// check, green when the state read back is what GL says and red when not, and leaves state
// behind for the state dump to compare.
GLPT_SCENE(point_sprite_state, 64, 16) {
  clear(0.05f, 0.05f, 0.1f);
  ortho_pixels(64, 16);
  bool ok[6] = {};
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
  glPopAttrib();
  GLint replace = -1;
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace);
  ok[0] = replace == GL_FALSE;  // GL_TEXTURE_BIT does not hold it
  glPushAttrib(GL_POINT_BIT);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glEnable(GL_POINT_SPRITE);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  glPopAttrib();
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace);
  GLint origin = 0;
  glGetIntegerv(GL_POINT_SPRITE_COORD_ORIGIN, &origin);
  ok[1] = replace == GL_FALSE && !glIsEnabled(GL_POINT_SPRITE) && origin == GL_UPPER_LEFT;
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, 7);
  ok[2] = glGetError() == GL_INVALID_VALUE;
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_FRONT);
  ok[3] = glGetError() == GL_INVALID_VALUE;
  glTexEnvi(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  ok[4] = glGetError() == GL_INVALID_ENUM;
  glActiveTexture(GL_TEXTURE0);
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace);
  ok[5] = replace == GL_FALSE;  // per unit
  glPointSize(6.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 6; ++i) {
    glColor3f(ok[i] ? 0.1f : 1.0f, ok[i] ? 1.0f : 0.1f, 0.1f);
    glVertex2f(5.0f + 10.0f * i, 8.0f);
  }
  glEnd();
  // Left for the state dump: sprites on, unit 1 replaced, the lower-left origin.
  glEnable(GL_POINT_SPRITE);
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glActiveTexture(GL_TEXTURE0);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
}

}  // namespace
