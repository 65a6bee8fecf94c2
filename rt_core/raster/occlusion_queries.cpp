#include "rt_core/raster/occlusion_queries.hpp"

#include <algorithm>
#include <variant>

#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

// The commands whose fragments GL counts (Mesa draws all of them as primitives), once each.
bool makes_fragments(const rec::Command& command) {
  if (const auto* draw_pixels = std::get_if<rec::DrawPixels>(&command)) return draw_pixels->counted;
  if (const auto* copy_pixels = std::get_if<rec::CopyPixels>(&command)) return copy_pixels->counted;
  return std::holds_alternative<rec::Draw>(command) || std::holds_alternative<rec::Bitmap>(command);
}

}  // namespace

void OcclusionQueries::begin_record(const rec::FrameRecord& record,
                                    const std::vector<size_t>& commands) {
  query_of_command_.assign(record.commands.size(), 0);
  queries_.clear();
  slot_query_.clear();
  active_ = false;
  uint64_t active = record.query_at_start;
  if (active != 0) queries_.push_back(active);
  for (size_t i = 0; i < record.commands.size(); ++i) {
    const rec::Command& command = record.commands[i];
    if (const auto* begin = std::get_if<rec::BeginQuery>(&command)) {
      active = begin->id;
      queries_.push_back(begin->id);
    } else if (std::holds_alternative<rec::EndQuery>(command)) {
      active = 0;
    } else if (makes_fragments(command)) {
      query_of_command_[i] = active;
    }
  }
  slots_reserved_ = static_cast<uint32_t>(
      std::count_if(commands.begin(), commands.end(), [&](size_t i) { return query_of(i) != 0; }));
  if (slots_reserved_ <= capacity_) return;
  // Grown geometrically. An earlier execute's submission may still be using the old pool (the
  // passes of a frame are not waited for): it must be done before the pool goes.
  device_.wait_all();
  const uint32_t capacity = std::max({slots_reserved_, capacity_ * 2, 64u});
  auto info = make_info<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
  info.queryType = VK_QUERY_TYPE_OCCLUSION;
  info.queryCount = capacity;
  VkQueryPool pool = VK_NULL_HANDLE;
  pool_ = vk::QueryPool();
  capacity_ = 0;
  GLPT_VK_CHECK(vkCreateQueryPool(device_.handle(), &info, nullptr, &pool));
  pool_ = vk::QueryPool(pool, {device_.handle()});
  capacity_ = capacity;
}

void OcclusionQueries::reset_slots(VkCommandBuffer cmd) {
  if (slots_reserved_ > 0) vkCmdResetQueryPool(cmd, pool_.get(), 0, slots_reserved_);
}

void OcclusionQueries::before_draw(VkCommandBuffer cmd, uint64_t query) {
  if (active_ && slot_query_.back() == query) return;
  stop(cmd);
  if (query == 0 || slot_query_.size() >= slots_reserved_) return;
  const VkQueryControlFlags flags =
      device_.has_precise_occlusion_queries() ? VK_QUERY_CONTROL_PRECISE_BIT : 0;
  vkCmdBeginQuery(cmd, pool_.get(), static_cast<uint32_t>(slot_query_.size()), flags);
  slot_query_.push_back(query);
  active_ = true;
}

void OcclusionQueries::stop(VkCommandBuffer cmd) {
  if (!active_) return;
  vkCmdEndQuery(cmd, pool_.get(), static_cast<uint32_t>(slot_query_.size() - 1));
  active_ = false;
}

void OcclusionQueries::collect(std::vector<QuerySamples>& out) {
  std::vector<uint64_t> samples(slot_query_.size(), 0);
  if (!samples.empty())
    GLPT_VK_CHECK(vkGetQueryPoolResults(
        device_.handle(), pool_.get(), 0, static_cast<uint32_t>(samples.size()),
        samples.size() * sizeof(uint64_t), samples.data(), sizeof(uint64_t),
        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  for (uint64_t query : queries_) {
    auto entry =
        std::find_if(out.begin(), out.end(), [&](const QuerySamples& q) { return q.id == query; });
    if (entry == out.end()) entry = out.insert(out.end(), QuerySamples{query, 0});
    for (size_t slot = 0; slot < samples.size(); ++slot)
      if (slot_query_[slot] == query) entry->samples += samples[slot];
  }
  slot_query_.clear();
}

}  // namespace glpt::rt
