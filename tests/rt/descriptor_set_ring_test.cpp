// The raster pipelines' set 0 comes from a DescriptorSetRing (descriptor_set_ring.hpp): a set is
// handed out again only once the submission that read it has completed. Here the submission is
// held pending on a device event the test sets itself, so "not yet" and "now" are both certain.
#include "rt_core/raster/descriptor_set_ring.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <vector>

#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

class DescriptorSetRingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      device_ = VulkanDevice::create({});
    } catch (const DeviceUnavailable& e) {
      GTEST_FAIL() << e.what();
    }
    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                               VK_SHADER_STAGE_ALL, nullptr};
    auto layout_info = make_info<VkDescriptorSetLayoutCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    layout_info.bindingCount = 1;
    layout_info.pBindings = &binding;
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    GLPT_VK_CHECK(vkCreateDescriptorSetLayout(device_->handle(), &layout_info, nullptr, &layout));
    layout_ = vk::DescriptorSetLayout(layout, {device_->handle()});
    auto event_info = make_info<VkEventCreateInfo>(VK_STRUCTURE_TYPE_EVENT_CREATE_INFO);
    GLPT_VK_CHECK(vkCreateEvent(device_->handle(), &event_info, nullptr, &event_));
  }
  void TearDown() override {
    if (!device_) return;
    if (event_ != VK_NULL_HANDLE) {
      vkSetEvent(device_->handle(), event_);  // nothing may stay pending on it
      device_->wait_all();
      vkDestroyEvent(device_->handle(), event_, nullptr);
    }
    layout_ = {};
  }

  // A submission that completes only once the test sets the event.
  VulkanDevice::Ticket pending_submission() {
    return device_->submit([&](VkCommandBuffer cmd) {
      vkCmdWaitEvents(cmd, 1, &event_, VK_PIPELINE_STAGE_HOST_BIT,
                      VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, nullptr, 0, nullptr, 0, nullptr);
    });
  }
  void complete(VulkanDevice::Ticket ticket) {
    GLPT_VK_CHECK(vkSetEvent(device_->handle(), event_));
    device_->wait(ticket);
  }
  DescriptorSetRing ring() {
    return DescriptorSetRing(*device_, layout_.get(), {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}});
  }

  std::unique_ptr<VulkanDevice> device_;
  vk::DescriptorSetLayout layout_;
  VkEvent event_ = VK_NULL_HANDLE;
};

// Acquires until every set of `wanted` has come back (true), or `limit` sets without (false).
bool comes_back(DescriptorSetRing& ring, const std::set<VkDescriptorSet>& wanted, int limit) {
  std::set<VkDescriptorSet> found;
  for (int i = 0; i < limit && found.size() < wanted.size(); ++i)
    if (VkDescriptorSet set = ring.acquire(); wanted.count(set)) found.insert(set);
  return found == wanted;
}

TEST_F(DescriptorSetRingTest, ASetReadByAPendingSubmissionIsNotHandedOutUntilItCompletes) {
  DescriptorSetRing sets = ring();
  std::set<VkDescriptorSet> read;
  for (int i = 0; i < 3; ++i) read.insert(sets.acquire());
  ASSERT_EQ(read.size(), 3u) << "sets of one recording must be distinct";
  const VulkanDevice::Ticket ticket = pending_submission();
  sets.retire(ticket);

  // While it is pending: more than a pool's worth of new sets (so pools are added), none of the
  // three, whatever reclaim() is asked.
  for (int i = 0; i < 100; ++i) {
    sets.reclaim();
    EXPECT_EQ(read.count(sets.acquire()), 0u) << "acquire " << i;
  }
  sets.retire(pending_submission());  // those 100 go with a second pending submission

  complete(ticket);
  sets.reclaim();
  EXPECT_TRUE(comes_back(sets, read, 1000)) << "completed sets must be reused, not leaked";
}

TEST_F(DescriptorSetRingTest, SetsOfARecordingNeverSubmittedGoWithTheNextSubmission) {
  DescriptorSetRing sets = ring();
  std::set<VkDescriptorSet> read;
  read.insert(sets.acquire());
  read.insert(sets.acquire());  // a recording abandoned: no retire
  read.insert(sets.acquire());  // the next one's
  ASSERT_EQ(read.size(), 3u);
  const VulkanDevice::Ticket ticket = pending_submission();
  sets.retire(ticket);
  for (int i = 0; i < 40; ++i) EXPECT_EQ(read.count(sets.acquire()), 0u) << "acquire " << i;
  sets.retire(pending_submission());
  complete(ticket);
  sets.reclaim();
  EXPECT_TRUE(comes_back(sets, read, 1000));
}

}  // namespace
}  // namespace glpt::rt
