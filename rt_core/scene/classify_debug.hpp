// GLPT_CLASSIFY_DEBUG=1: each draw tinted by its class, so a user sees what glpt took every draw
// for. The tint is GL's own fog, made constant: linear fog from -1e18 to 1e18 leaves every
// fragment half its colour and half the class's (kClassTint), through both modes' fog paths.
// Palette: docs/classification.md.
#pragma once

#include <glm/glm.hpp>

#include "rt_core/record/frame_record.hpp"
#include "rt_core/scene/classify.hpp"

namespace glpt::rt {

glm::vec4 class_tint(DrawKind kind);

// `out`: `record` with every classified command's state fogged in its class's colour.
void tint_by_class(const rec::FrameRecord& record, const FrameClassification& classification,
                   rec::FrameRecord& out);

}  // namespace glpt::rt
