// Blending, logic ops, colour masks and clears (GL 1.5 4.1.8-4.2.3).
#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// The lower-left corner of panel i in a 4x4 grid of 32x32 panels (128x128 scene).
float grid_x(int i) { return 32.0f * static_cast<float>(i % 4); }
float grid_y(int i) { return 96.0f - 32.0f * static_cast<float>(i / 4); }

// The destination of a blend panel: a horizontal gradient in colour and alpha, drawn unblended.
void destination(float x, float y) {
  static const float kCorners[4][4] = {{0.9f, 0.2f, 0.1f, 1.0f},
                                       {0.1f, 0.3f, 0.9f, 0.0f},
                                       {0.2f, 0.9f, 0.4f, 0.3f},
                                       {0.8f, 0.8f, 0.2f, 0.7f}};
  glDisable(GL_BLEND);
  coloured_quad(x + 1, y + 1, x + 31, y + 31, kCorners);
}

// The source of a blend panel: a vertical gradient in colour and alpha, inset.
void source(float x, float y) {
  static const float kCorners[4][4] = {{1.0f, 0.9f, 0.2f, 0.1f},
                                       {0.2f, 1.0f, 1.0f, 0.4f},
                                       {1.0f, 0.3f, 0.8f, 0.9f},
                                       {0.4f, 0.4f, 1.0f, 0.6f}};
  coloured_quad(x + 5, y + 5, x + 27, y + 27, kCorners);
}

// Fifteen blend factors (GL 1.5 tables 4.1, 4.2), and blending off in the last panel.
const GLenum kFactors[15] = {GL_ZERO,
                             GL_ONE,
                             GL_SRC_COLOR,
                             GL_ONE_MINUS_SRC_COLOR,
                             GL_DST_COLOR,
                             GL_ONE_MINUS_DST_COLOR,
                             GL_SRC_ALPHA,
                             GL_ONE_MINUS_SRC_ALPHA,
                             GL_DST_ALPHA,
                             GL_ONE_MINUS_DST_ALPHA,
                             GL_CONSTANT_COLOR,
                             GL_ONE_MINUS_CONSTANT_COLOR,
                             GL_CONSTANT_ALPHA,
                             GL_ONE_MINUS_CONSTANT_ALPHA,
                             GL_SRC_ALPHA_SATURATE};

// Each panel isolates one factor: the source factor with destination factor ZERO (result =
// source x factor), or the destination factor with source factor ZERO (destination x factor).
// SRC_ALPHA_SATURATE is a source factor only.
void factor_scene(bool source_factors) {
  clear(0.1f, 0.1f, 0.1f, 1.0f);
  ortho_pixels(128, 128);
  glBlendColor(0.2f, 0.5f, 0.8f, 0.6f);
  const int count = source_factors ? 15 : 14;
  for (int i = 0; i < 16; ++i) {
    destination(grid_x(i), grid_y(i));
    if (i < count) {
      glEnable(GL_BLEND);
      if (source_factors) {
        glBlendFunc(kFactors[i], GL_ZERO);
      } else {
        glBlendFunc(GL_ZERO, kFactors[i]);
      }
    }
    source(grid_x(i), grid_y(i));
  }
}

GLPT_SCENE(blend_source_factors, 128, 128) { factor_scene(true); }
GLPT_SCENE(blend_destination_factors, 128, 128) { factor_scene(false); }

// The usual translucency, SRC_ALPHA / ONE_MINUS_SRC_ALPHA, of overlapping smooth triangles
// drawn back to front.
GLPT_SCENE(blend_translucent_overlap, 64, 64) {
  clear(0.9f, 0.9f, 0.9f, 1.0f);
  ortho_pixels(64, 64);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const float centres[3][2] = {{24, 26}, {40, 26}, {32, 40}};
  const float colours[3][3] = {{1, 0, 0}, {0, 0.8f, 0}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i) {
    glBegin(GL_TRIANGLES);
    glColor4f(colours[i][0], colours[i][1], colours[i][2], 0.7f);
    glVertex2f(centres[i][0], centres[i][1] + 22);
    glColor4f(colours[i][0], colours[i][1], colours[i][2], 0.2f);
    glVertex2f(centres[i][0] - 20, centres[i][1] - 14);
    glColor4f(colours[i][0], colours[i][1], colours[i][2], 0.5f);
    glVertex2f(centres[i][0] + 20, centres[i][1] - 14);
    glEnd();
  }
}

// A constant blend colour: a textured quad faded to 35% with CONSTANT_ALPHA, and one tinted
// with CONSTANT_COLOR.
GLPT_SCENE(blend_constant_colour, 64, 64) {
  clear(0.1f, 0.2f, 0.3f, 1.0f);
  ortho_pixels(64, 64);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGB, 8, 8, checker(8, 8, 2, Rgba8{250, 250, 250, 255}, Rgba8{250, 100, 20, 255}));
  glColor3f(1, 1, 1);
  glEnable(GL_BLEND);
  glBlendColor(0.2f, 1.0f, 0.4f, 0.35f);
  glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
  quad(4, 4, 44, 44);
  glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR);
  quad(20, 20, 60, 60);
}

// Each blend equation (ADD, SUBTRACT, REVERSE_SUBTRACT, MIN, MAX) with factors ONE, ONE; MIN and
// MAX ignore the factors. The last three panels repeat ADD, SUBTRACT and MAX with other factors.
GLPT_SCENE(blend_equations, 128, 64) {
  clear(0.1f, 0.1f, 0.1f, 1.0f);
  ortho_pixels(128, 64);
  const GLenum equations[8] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN,
                               GL_MAX,      GL_FUNC_ADD,      GL_FUNC_SUBTRACT,         GL_MAX};
  for (int i = 0; i < 8; ++i) {
    const float x = 32.0f * static_cast<float>(i % 4), y = i < 4 ? 32.0f : 0.0f;
    destination(x, y);
    glEnable(GL_BLEND);
    glBlendEquation(equations[i]);
    if (i < 5) {
      glBlendFunc(GL_ONE, GL_ONE);
    } else {
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    source(x, y);
  }
}

// Separate RGB and alpha factors (GL 1.4 BlendFuncSeparate): RGB blends by source alpha while
// alpha keeps the destination's (left) or takes the source's (right). Alpha is in the image.
GLPT_SCENE(blend_func_separate, 64, 64) {
  clear(0.1f, 0.1f, 0.1f, 1.0f);
  ortho_pixels(64, 64);
  for (int i = 0; i < 2; ++i) {
    const float x = 32.0f * i;
    destination(x, 16);
    glEnable(GL_BLEND);
    if (i == 0) {
      glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    } else {
      glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    }
    source(x, 16);
  }
}

// Separate RGB and alpha equations (EXT_blend_equation_separate): each panel blends colour with
// one equation and alpha with another, factors ONE, ONE; alpha is in the image. The last panel
// sets an invalid pair, which changes nothing (GL_INVALID_ENUM).
GLPT_SCENE(blend_equation_separate, 128, 64) {
  clear(0.1f, 0.1f, 0.1f, 1.0f);
  ortho_pixels(128, 64);
  const GLenum pairs[8][2] = {{GL_FUNC_ADD, GL_FUNC_SUBTRACT},
                              {GL_FUNC_SUBTRACT, GL_FUNC_ADD},
                              {GL_FUNC_ADD, GL_FUNC_REVERSE_SUBTRACT},
                              {GL_FUNC_REVERSE_SUBTRACT, GL_MAX},
                              {GL_MIN, GL_FUNC_ADD},
                              {GL_MAX, GL_MIN},
                              {GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT},
                              {GL_FUNC_ADD, GL_ZERO}};
  for (int i = 0; i < 8; ++i) {
    const float x = 32.0f * static_cast<float>(i % 4), y = i < 4 ? 32.0f : 0.0f;
    destination(x, y);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquationSeparate(pairs[i][0], pairs[i][1]);  // the EXT entry point's GL 2.0 name
    source(x, y);
  }
}

// All sixteen logic ops (GL 1.5 4.1.10): destination stripes one way, source stripes the other,
// values with distinct bit patterns.
GLPT_SCENE(logic_op_all, 128, 128) {
  clear(0, 0, 0, 1);
  ortho_pixels(128, 128);
  const GLenum ops[16] = {GL_CLEAR,         GL_AND,         GL_AND_REVERSE, GL_COPY,
                          GL_AND_INVERTED,  GL_NOOP,        GL_XOR,         GL_OR,
                          GL_NOR,           GL_EQUIV,       GL_INVERT,      GL_OR_REVERSE,
                          GL_COPY_INVERTED, GL_OR_INVERTED, GL_NAND,        GL_SET};
  const GLubyte destination_colours[3][4] = {
      {0xF0, 0x33, 0x0F, 0xFF}, {0x55, 0xAA, 0xC3, 0x80}, {0x0F, 0xF0, 0x5A, 0x3C}};
  const GLubyte source_colours[3][4] = {
      {0xFF, 0x0F, 0x33, 0xFF}, {0x3C, 0x55, 0xF0, 0x0F}, {0xA5, 0xCC, 0x00, 0x99}};
  glShadeModel(GL_FLAT);
  for (int i = 0; i < 16; ++i) {
    const float x = grid_x(i), y = grid_y(i);
    glDisable(GL_COLOR_LOGIC_OP);
    for (int k = 0; k < 3; ++k) {
      glColor4ubv(destination_colours[k]);
      glRectf(x + 1, y + 1 + 10 * k, x + 31, y + 11 + 10 * k);
    }
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(ops[i]);
    for (int k = 0; k < 3; ++k) {
      glColor4ubv(source_colours[k]);
      glRectf(x + 3 + 9 * k, y + 3, x + 11 + 9 * k, y + 29);
    }
  }
}

// Colour write masks per channel, alpha included: the same white quad drawn through several
// masks over a coloured background.
GLPT_SCENE(colour_mask, 64, 64) {
  clear(0.2f, 0.4f, 0.6f, 0.5f);
  ortho_pixels(64, 64);
  const GLboolean masks[4][4] = {{GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE},
                                 {GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE},
                                 {GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE},
                                 {GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE}};
  for (int i = 0; i < 4; ++i) {
    glColorMask(masks[i][0], masks[i][1], masks[i][2], masks[i][3]);
    glColor4f(1, 0.9f, 0.8f, 1);
    const float x = 4.0f + 30.0f * static_cast<float>(i % 2),
                y = 4.0f + 30.0f * static_cast<float>(i / 2);
    glRectf(x, y, x + 26, y + 26);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// glClear obeys the scissor box and the write masks (GL 1.5 4.2.3): coloured clears of
// scissored regions through colour masks, a scissored depth clear that lets a far quad through
// only there, and a scissored stencil clear through a stencil mask.
GLPT_SCENE(clear_with_scissor_and_masks, 64, 64) {
  clear(0.1f, 0.1f, 0.1f, 1.0f);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 36, 24, 24);
  glClearColor(1, 0.5f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(16, 44, 40, 16);
  glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE);
  glClearColor(0.3f, 0.9f, 0.9f, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Depth: everything near (0), then a scissored far clear (1) where the far quad shows.
  glScissor(0, 0, 64, 64);
  glClearDepth(0.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glScissor(6, 6, 20, 24);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  // Stencil: a scissored clear to 0xFF through the mask 0x0F stores 0x0F.
  glScissor(30, 6, 28, 24);
  glStencilMask(0x0F);
  glClearStencil(0xFF);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilMask(0xFF);
  glDisable(GL_SCISSOR_TEST);
  ortho_pixels(64, 64);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.9f, 0.9f, 0.3f);
  glRectf(2, 2, 62, 32);  // z = 0: depth 0.5, passes only where depth was cleared to 1
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0x0F, 0xFF);
  glColor3f(0.8f, 0.3f, 1);
  glRectf(28, 2, 62, 26);
}

}  // namespace
