#include "rt_core/scene/classify_debug.hpp"

#include <map>
#include <memory>
#include <utility>
#include <variant>

namespace glpt::rt {

glm::vec4 class_tint(DrawKind kind) {
  switch (kind) {
    case DrawKind::kStatic:
      return {0.2f, 0.4f, 1.0f, 1.0f};  // blue
    case DrawKind::kMoving:
      return {0.0f, 1.0f, 0.0f, 1.0f};  // green
    case DrawKind::kDeforming:
      return {1.0f, 1.0f, 0.0f, 1.0f};  // yellow
    case DrawKind::kBlended:
      return {0.0f, 1.0f, 1.0f, 1.0f};  // cyan
    case DrawKind::kParticles:
      return {1.0f, 0.5f, 0.0f, 1.0f};  // orange
    case DrawKind::kMultipass:
      return {0.6f, 0.0f, 1.0f, 1.0f};  // purple
    case DrawKind::kDecal:
      return {1.0f, 0.0f, 1.0f, 1.0f};  // magenta
    case DrawKind::kOverlay:
      return {1.0f, 1.0f, 1.0f, 1.0f};  // white
    case DrawKind::kSky:
      return {0.6f, 0.85f, 1.0f, 1.0f};  // light blue
    case DrawKind::kShadow:
      return {0.3f, 0.3f, 0.3f, 1.0f};  // grey (drawn in raster mode only)
    case DrawKind::kViewmodel:
      return {1.0f, 0.0f, 0.0f, 1.0f};  // red
    case DrawKind::kLines:
      return {0.6f, 0.4f, 0.2f, 1.0f};  // brown
    case DrawKind::kHidden:
    case DrawKind::kNone:
      break;
  }
  return {0.0f, 0.0f, 0.0f, 1.0f};
}

void tint_by_class(const rec::FrameRecord& record, const FrameClassification& classification,
                   rec::FrameRecord& out) {
  out.clear();
  out.query_at_start = record.query_at_start;
  out.states = record.states;
  out.commands = record.commands;
  // One tinted state per (state, kind) pair.
  std::map<std::pair<rec::StateId, DrawKind>, rec::StateId> tinted;
  auto tint = [&](rec::StateId state, DrawKind kind) {
    auto [it, added] = tinted.try_emplace({state, kind}, 0);
    if (added) {
      rec::StateSnapshot snapshot = record.states[state];
      rec::RasterState raster = *snapshot.raster;
      raster.fog.enabled = true;
      raster.fog.mode = GL_LINEAR;
      raster.fog.start = -1e18f;
      raster.fog.end = 1e18f;
      raster.fog.coord_source = GL_FRAGMENT_DEPTH;
      raster.fog.color = class_tint(kind);
      snapshot.raster = std::make_shared<const rec::RasterState>(raster);
      out.states.push_back(std::move(snapshot));
      it->second = static_cast<rec::StateId>(out.states.size() - 1);
    }
    return it->second;
  };
  for (size_t i = 0; i < out.commands.size() && i < classification.labels.size(); ++i) {
    const DrawKind kind = classification.labels[i].kind;
    if (kind == DrawKind::kNone) continue;
    std::visit(
        [&](auto& command) {
          using T = std::decay_t<decltype(command)>;
          if constexpr (std::is_same_v<T, rec::Draw> || std::is_same_v<T, rec::Bitmap> ||
                        std::is_same_v<T, rec::DrawPixels> || std::is_same_v<T, rec::CopyPixels>)
            command.state = tint(command.state, kind);
        },
        out.commands[i]);
  }
}

}  // namespace glpt::rt
