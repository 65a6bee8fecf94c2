// Occlusion queries in raster mode (rec::BeginQuery .. rec::EndQuery, GL 1.5 4.1.6): the samples
// of the record's commands between a BeginQuery and its EndQuery that pass the depth and stencil
// tests, counted by Vulkan occlusion queries (VK_QUERY_CONTROL_PRECISE_BIT).
//
// A Vulkan query must begin and end inside one rendering instance of one command buffer, and
// must not see what GL does not count (clears drawn as quads, the extra passes of stencil
// images), whereas a GL query spans any commands, render targets and submissions. So the counted
// draw calls are split into stretches, each counted in a slot of its own: a stretch begins at the
// first draw call of a counted command and ends at a draw call that counts for another query or
// none, at a command that makes no fragments (a clear), and when rendering ends (a change of
// render targets, a copy, the end of a submission). The slots' results are summed per GL query
// after the submissions. Every counted command starts at most one stretch, so a record needs at
// most as many slots as it has counted commands.
#pragma once

#include <cstdint>
#include <vector>

#include "rt_core/record/frame_record.hpp"
#include "rt_core/renderer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

class OcclusionQueries {
 public:
  explicit OcclusionQueries(VulkanDevice& device) : device_(device) {}

  // Starts an execute of `commands` (indices into `record`): finds the query each command counts
  // into, in the record's order (the order the commands are executed in may differ: path-traced
  // mode's passes), and makes room for their slots.
  void begin_record(const rec::FrameRecord& record, const std::vector<size_t>& commands);
  // The query command `index` counts into; 0 when none is active or it makes no fragments.
  uint64_t query_of(size_t index) const {
    return index < query_of_command_.size() ? query_of_command_[index] : 0;
  }
  // In the first command buffer of the execute, outside rendering: makes its slots usable.
  void reset_slots(VkCommandBuffer cmd);
  // Before a draw call inside a rendering instance: `query` is what it counts into (0: nothing).
  void before_draw(VkCommandBuffer cmd, uint64_t query);
  // Stops counting (before vkCmdEndRendering, and before what must not count).
  void stop(VkCommandBuffer cmd);
  // After the execute's last submission completed: adds each query's samples to `out` (one
  // entry per query, those without samples included).
  void collect(std::vector<QuerySamples>& out);
  // Whether this execute's submissions count into any query slot (collect must wait for them).
  bool counted_any() const { return !slot_query_.empty(); }

 private:
  VulkanDevice& device_;
  vk::QueryPool pool_;
  uint32_t capacity_ = 0;
  std::vector<uint64_t> query_of_command_;  // per command index of the record
  std::vector<uint64_t> queries_;           // the record's queries, in order
  std::vector<uint64_t> slot_query_;        // the query each used slot counted
  uint32_t slots_reserved_ = 0;             // slots reset for this execute
  bool active_ = false;                     // a slot is counting
};

}  // namespace glpt::rt
