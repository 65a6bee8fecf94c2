#include "rt_core/scene/frame_signature.hpp"

#include <cstring>

namespace glpt::rt {
namespace {

// Blocks equal by value, or bit for bit: a block holding a NaN (a matrix or light a program set
// to NaN, which GL accepts) is never equal to itself by value, and a still frame drawn with it
// would start its accumulation over every frame (tests/extremes). Equal bits are the same
// state: members that point elsewhere (textures) are then the same pointers.
template <typename Block>
bool same_block(const std::shared_ptr<const Block>& a, const std::shared_ptr<const Block>& b) {
  return a == b || (a && b && (*a == *b || std::memcmp(a.get(), b.get(), sizeof(Block)) == 0));
}

const rec::StateSnapshot* state_of(const rec::FrameRecord& record, const rec::Command& command) {
  const rec::StateId id = std::visit(
      [](const auto& c) -> rec::StateId {
        if constexpr (requires { c.state; })
          return c.state;
        else
          return ~rec::StateId{0};
      },
      command);
  return id < record.states.size() ? &record.states[id] : nullptr;
}

}  // namespace

FrameSignature::FrameSignature(const rec::FrameRecord& record, std::span<const size_t> commands,
                               const rec::DrawableConfig& drawable)
    : valid_(true), drawable_(drawable) {
  entries_.reserve(commands.size());
  for (size_t i : commands) {
    const rec::Command& command = record.commands[i];
    Entry& e = entries_.emplace_back();
    e.kind = static_cast<uint32_t>(command.index());
    if (const rec::StateSnapshot* state = state_of(record, command)) e.state = *state;
    if (const auto* draw = std::get_if<rec::Draw>(&command); draw && draw->vertices) {
      const rec::VertexKeys& keys = draw->vertices->keys();
      e.geometry_key = keys.geometry;
      e.attribute_key = keys.attributes;
    } else if (const auto* clear = std::get_if<rec::Clear>(&command)) {
      e.clear[0] = clear->mask;
      std::memcpy(&e.clear[1], &clear->color, sizeof clear->color);
      std::memcpy(&e.clear[5], &clear->depth, sizeof clear->depth);
      static_assert(sizeof clear->depth == 8);
      e.clear[7] = static_cast<uint32_t>(clear->stencil);
    }
  }
}

bool FrameSignature::same(const Entry& a, const Entry& b) {
  return a.kind == b.kind && a.geometry_key == b.geometry_key &&
         a.attribute_key == b.attribute_key && std::memcmp(a.clear, b.clear, sizeof a.clear) == 0 &&
         same_block(a.state.transform, b.state.transform) &&
         same_block(a.state.lighting, b.state.lighting) &&
         same_block(a.state.texturing, b.state.texturing) &&
         same_block(a.state.raster, b.state.raster) &&
         same_block(a.state.pixel_transfer, b.state.pixel_transfer);
}

bool FrameSignature::operator==(const FrameSignature& other) const {
  if (!valid_ || !other.valid_ || drawable_ != other.drawable_ ||
      entries_.size() != other.entries_.size())
    return false;
  for (size_t i = 0; i < entries_.size(); ++i)
    if (!same(entries_[i], other.entries_[i])) return false;
  return true;
}

}  // namespace glpt::rt
