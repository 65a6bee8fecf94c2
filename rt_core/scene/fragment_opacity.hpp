// Whether a draw's fragments are opaque whatever blending is on: programs of the GL 1.x era
// often leave GL_BLEND enabled with GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA and draw opaque
// surfaces through it, with an alpha of 1 in every vertex colour, material and texel. Such a
// draw writes each fragment as it is, so path-traced mode traces it like an unblended one.
#pragma once

#include "rt_core/record/frame_record.hpp"
#include "rt_core/record/texture.hpp"
#include "raster_types.h"

namespace glpt::rt {

// Whether blending with `ops` writes a fragment of alpha 1 unchanged (colour and alpha): source
// factor GL_ONE or GL_SRC_ALPHA (GL_SRC_ALPHA_SATURATE too for alpha), destination factor GL_ZERO
// or GL_ONE_MINUS_SRC_ALPHA, equation GL_FUNC_ADD or GL_FUNC_SUBTRACT. Blending off: true.
bool blending_keeps_an_opaque_fragment(const rec::FragmentOpsState& ops);

// Whether every fragment `draw` produces has alpha 1 before blending: its primary alpha (vertex
// colours, or with lighting the materials' diffuse alpha or the tracked vertex colours) and what
// each enabled texture unit makes of it (the texture's texels, its environment). Conservative:
// false wherever it cannot tell (GL_BLEND and GL_INTENSITY environments, combine functions other
// than GL_REPLACE and GL_MODULATE, depth textures).
bool fragments_are_opaque(const rec::Draw& draw, const rec::StateSnapshot& state);

// The alpha from which a fragment counts as opaque where a draw is split by alpha (the raster
// shaders' GLPT_OPAQUE_ALPHA).
inline constexpr float kOpaqueAlpha = static_cast<float>(GLPT_OPAQUE_ALPHA);

// Whether a blended draw can be split by its fragments' alpha (path-traced mode,
// docs/classification.md): traced where its fragments are opaque, blended where they are not.
// Blending writes a fragment of alpha 1 unchanged (no logic op), the draw tests and writes depth
// (a solid object with see-through parts, not a particle or a glass pane drawn over the scene),
// its primary alpha is 1 (only textures make parts of it translucent), and an alpha test, if
// any, passes every opaque fragment (GL_GREATER, GL_GEQUAL or GL_NOTEQUAL below kOpaqueAlpha).
bool splits_by_alpha(const rec::Draw& draw, const rec::StateSnapshot& state);

// Whether every texel of levels base..last of every face of `texture` has alpha 1. Computed once
// per image and kept (images never change).
bool texels_are_opaque(const rec::TextureObjectSnapshot& texture);

}  // namespace glpt::rt
