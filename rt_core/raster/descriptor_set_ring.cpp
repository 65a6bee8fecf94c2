#include "rt_core/raster/descriptor_set_ring.hpp"

#include <utility>

#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

// Sets per pool: a frame binds a new set only where its textures change, so most frames need a
// few; a frame of thousands of differently textured draws adds pools as it needs them.
constexpr uint32_t kSetsPerPool = 32;

}  // namespace

DescriptorSetRing::DescriptorSetRing(VulkanDevice& device, VkDescriptorSetLayout layout,
                                     std::vector<VkDescriptorPoolSize> pool_sizes)
    : device_(device), layout_(layout), pool_sizes_(std::move(pool_sizes)) {}

void DescriptorSetRing::add_pool() {
  std::vector<VkDescriptorPoolSize> sizes = pool_sizes_;
  for (VkDescriptorPoolSize& size : sizes) size.descriptorCount *= kSetsPerPool;
  auto pool_info =
      make_info<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool_info.maxSets = kSetsPerPool;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateDescriptorPool(device_.handle(), &pool_info, nullptr, &pool));
  vk::DescriptorPool owner(pool, {device_.handle()});
  std::vector<VkDescriptorSetLayout> layouts(kSetsPerPool, layout_);
  std::vector<VkDescriptorSet> sets(kSetsPerPool);
  auto set_info =
      make_info<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  set_info.descriptorPool = pool;
  set_info.descriptorSetCount = kSetsPerPool;
  set_info.pSetLayouts = layouts.data();
  GLPT_VK_CHECK(vkAllocateDescriptorSets(device_.handle(), &set_info, sets.data()));
  free_.reserve(free_.size() + sets.size());
  pools_.push_back(std::move(owner));
  free_.insert(free_.end(), sets.begin(), sets.end());
}

void DescriptorSetRing::reclaim() {
  if (in_flight_.empty()) return;
  const VulkanDevice::Ticket completed = device_.completed_ticket();
  while (!in_flight_.empty() && in_flight_.front().ticket <= completed) {
    free_.insert(free_.end(), in_flight_.front().sets.begin(), in_flight_.front().sets.end());
    in_flight_.pop_front();
  }
}

VkDescriptorSet DescriptorSetRing::acquire() {
  if (free_.empty()) add_pool();
  // Into acquired_ before leaving free_: a failed push_back loses no set.
  acquired_.push_back(free_.back());
  free_.pop_back();
  return acquired_.back();
}

void DescriptorSetRing::retire(VulkanDevice::Ticket ticket) {
  if (acquired_.empty()) return;
  in_flight_.push_back({ticket, std::move(acquired_)});
  acquired_.clear();
  reclaim();
}

}  // namespace glpt::rt
