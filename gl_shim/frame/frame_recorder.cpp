#include "gl_shim/frame/frame_recorder.hpp"

#include <algorithm>
#include <cstring>

namespace glpt {
namespace {

// Bitwise equality: the record keeps what GL was given, so -0.0 and 0.0 (or two NaNs) are
// different values only if their bits differ.
template <typename T>
bool all_equal(const std::vector<T>& values) {
  for (size_t i = 1; i < values.size(); ++i)
    if (std::memcmp(&values[i], &values[0], sizeof(T)) != 0) return false;
  return true;
}

// The storage is kept (capacity): a batch's arrays become the next frame's spare storage
// (FrameRecorder::clear), and immediate mode records every attribute per vertex, so releasing
// the secondary colour, fog coordinate and edge flags that one value holds would make them grow
// again, page by page, every frame.
template <typename T>
void compact(std::vector<T>& values) {
  // erase, not resize(1): the same, and GCC 12 at -O3 sees resize's growing path and reports a
  // false -Warray-bounds that fails the Release build under -Werror.
  if (values.size() > 1 && all_equal(values)) values.erase(values.begin() + 1, values.end());
}

template <typename T>
void append(std::vector<T>& to, std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

size_t bytes_per_vertex(const rec::VertexData& d) {
  size_t bytes = sizeof(glm::vec4) * 3 + sizeof(glm::vec3) + sizeof(float) + 1;
  for (const auto& t : d.tex_coord)
    if (!t.empty()) bytes += sizeof(glm::vec4);
  if (!d.material.empty()) bytes += sizeof(d.material[0]);
  return bytes;
}

}  // namespace

void clear_vertex_arrays(rec::VertexData& d) {
  d.position.clear();
  d.normal.clear();
  d.color.clear();
  d.secondary_color.clear();
  d.fog_coord.clear();
  for (auto& t : d.tex_coord) t.clear();
  d.edge_flag.clear();
  d.material.clear();
  d.indices.clear();
  d.primitives.clear();
  d.forget_keys();
}

void finish_vertex_data(rec::VertexData& d) {
  compact(d.normal);
  compact(d.color);
  compact(d.secondary_color);
  compact(d.fog_coord);
  for (auto& t : d.tex_coord) compact(t);
  compact(d.edge_flag);
  compact(d.material);

  d.forget_keys();  // hashed when a consumer asks (VertexData::keys)
}

void FrameRecorder::add_primitive(rec::StateId state, rec::VertexData& p) {
  if (p.position.empty() || p.primitives.size() != 1) return;
  ++events_;
  // Mesa's immediate-mode vertex layout keeps a per-vertex colour until the next state change,
  // so a primitive without one still has it; when the layout grows Mesa draws what it has
  // batched (a new draw here).
  if (open_ && open_state_ == state && open_->source == p.source) p.per_vertex |= open_->per_vertex;
  if (open_ && (open_state_ != state || open_->mode != p.mode || open_->source != p.source ||
                open_->per_vertex != p.per_vertex || open_->material.empty() != p.material.empty()))
    seal();
  vertex_bytes_ += p.position.size() * bytes_per_vertex(p);
  if (!open_) {
    if (spare_.empty()) {
      open_ = std::make_shared<rec::VertexData>(std::move(p));
    } else {
      open_ = std::move(spare_.back());
      spare_.pop_back();
      spare_bytes_ -= open_->capacity_bytes();
      // Exchanged, not copied: `p` (the caller's scratch, cleared before reuse) takes the spare's
      // storage for its next primitive.
      std::swap(*open_, p);
    }
    open_state_ = state;
    return;
  }
  rec::VertexData& d = *open_;
  const uint32_t base = d.vertex_count();
  const size_t count = p.position.size();
  d.primitives.push_back({base + p.primitives[0].first, p.primitives[0].count});
  append(d.position, p.position);
  // The attributes hold one value or one per vertex (rec::store_attribute).
  rec::append_attribute(d.normal, base, p.normal, count);
  rec::append_attribute(d.color, base, p.color, count);
  rec::append_attribute(d.secondary_color, base, p.secondary_color, count);
  rec::append_attribute(d.fog_coord, base, p.fog_coord, count);
  for (int u = 0; u < rec::kMaxTextureUnits; ++u)
    rec::append_attribute(d.tex_coord[u], base, p.tex_coord[u], count);
  rec::append_attribute(d.edge_flag, base, p.edge_flag, count);
  append(d.material, p.material);
}

std::shared_ptr<const rec::VertexData> FrameRecorder::add_draw(rec::StateId state,
                                                               rec::VertexData&& draw) {
  if (draw.position.empty() || draw.primitives.empty()) return nullptr;
  auto data = std::make_shared<rec::VertexData>(std::move(draw));
  finish_vertex_data(*data);
  add_recorded_draw(state, data);
  return data;
}

void FrameRecorder::add_recorded_draw(rec::StateId state,
                                      std::shared_ptr<const rec::VertexData> vertices) {
  if (!vertices) return;
  seal();
  vertex_bytes_ +=
      vertices->position.size() * bytes_per_vertex(*vertices) + vertices->indices.size() * 4;
  record_.commands.push_back(rec::Draw{state, std::move(vertices)});
}

rec::VertexData FrameRecorder::take_storage() {
  if (spare_.empty()) return {};
  spare_bytes_ -= spare_.back()->capacity_bytes();
  rec::VertexData storage = std::move(*spare_.back());
  spare_.pop_back();
  clear_vertex_arrays(storage);
  return storage;
}

void FrameRecorder::add(rec::Command command) {
  ++events_;
  seal();
  record_.commands.push_back(std::move(command));
}

void FrameRecorder::seal() {
  if (!open_) return;
  finish_vertex_data(*open_);
  record_.commands.push_back(
      rec::Draw{open_state_, std::shared_ptr<const rec::VertexData>(std::move(open_))});
  open_.reset();
}

void FrameRecorder::clear() {
  ++events_;
  // Enough spares for every batch of a frame of thousands of draws (glxgears has 18: with 4
  // kept, 14 batches a frame grew their arrays from nothing and were freed again, a seventh of
  // the program thread's time in malloc and free). The first few are kept whatever their size
  // (a program drawing megabytes a frame in one batch); the rest within a bound.
  constexpr size_t kMaxSpares = 4096, kSparesOfAnySize = 4;
  constexpr size_t kMaxSpareBytes = size_t{64} << 20;
  for (rec::Command& command : record_.commands) {
    auto* draw = std::get_if<rec::Draw>(&command);
    if (spare_.size() == kMaxSpares) break;
    // Only this record holds it (consumers that keep draws, as the path tracer's scene, share
    // them): the batches were created mutable, so taking const away is sound.
    if (!draw || !draw->vertices || draw->vertices.use_count() != 1) continue;
    const size_t bytes = draw->vertices->capacity_bytes();
    if (spare_.size() >= kSparesOfAnySize && spare_bytes_ + bytes > kMaxSpareBytes) continue;
    spare_bytes_ += bytes;
    spare_.push_back(std::const_pointer_cast<rec::VertexData>(std::move(draw->vertices)));
  }
  record_.clear();
  open_.reset();
  vertex_bytes_ = 0;
}

}  // namespace glpt
