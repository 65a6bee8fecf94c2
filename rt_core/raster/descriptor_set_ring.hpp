// Set 0 of the raster pipelines (uniforms, textures, edge flags, pixel images), taken from pools
// and reused once the submission that read it has completed.
//
// Why not push descriptors (vkCmdPushDescriptorSetKHR), which would need no bookkeeping: lavapipe
// turns each push into a new descriptor buffer that it maps (an mmap of the device memory's file)
// when the command buffer executes and unmaps after it: a system call pair and a TLB shootdown
// across the process's threads per bound set: 13 % of all CPU samples of a loop of small draws
// (bench/gl_readback.c, docs/performance.md). A pool's sets stay mapped for their lifetime.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

class DescriptorSetRing {
 public:
  // Sets of `layout`, whose bindings `pool_sizes` lists for one set.
  DescriptorSetRing(VulkanDevice& device, VkDescriptorSetLayout layout,
                    std::vector<VkDescriptorPoolSize> pool_sizes);

  // Returns the sets of completed submissions to the free ones. Not while recording inside
  // VulkanDevice::submit, which holds the lock that asking for completed submissions takes.
  void reclaim();
  // A set no pending submission reads, for the recording under way (its contents are the
  // caller's to write, all of them: a reused set holds what it held before). Never waits and
  // never asks the device: callable while recording.
  VkDescriptorSet acquire();
  // The sets acquired since the last call are read by submission `ticket`; they return once it
  // has completed (then reclaims). Sets of a recording never submitted go with the next one.
  void retire(VulkanDevice::Ticket ticket);

 private:
  void add_pool();

  VulkanDevice& device_;
  VkDescriptorSetLayout layout_;
  std::vector<VkDescriptorPoolSize> pool_sizes_;  // for one set
  std::vector<vk::DescriptorPool> pools_;
  std::vector<VkDescriptorSet> free_;
  std::vector<VkDescriptorSet> acquired_;  // by the recording under way
  struct InFlight {
    VulkanDevice::Ticket ticket;
    std::vector<VkDescriptorSet> sets;
  };
  std::deque<InFlight> in_flight_;  // in ticket order
};

}  // namespace glpt::rt
