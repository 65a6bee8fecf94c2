// The raster renderer's texture images: a program that replaces its textures at every frame
// (piglit streaming-texture-leak) must not keep them all on the device.
#include "rt_core/raster/texture_cache.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {
namespace {

// A 2D RGBA8 texture of `side` x `side` texels with a content version of its own.
std::shared_ptr<rec::TextureObjectSnapshot> texture(uint64_t version, uint32_t side) {
  auto image = std::make_shared<rec::TextureImage>();
  image->width = image->height = side;
  image->internal_format = GL_RGBA8;
  image->texels.assign(size_t{side} * side * 4, 0x80);
  auto t = std::make_shared<rec::TextureObjectSnapshot>();
  t->content_version = version;
  t->faces = {{image}};
  t->sampler.min_filter = GL_NEAREST;
  return t;
}

TEST(TextureCacheTest, KeepsTheImagesOfTwoFramesAndDropsOldOnesBeyondTheBudget) {
  std::unique_ptr<VulkanDevice> device;
  try {
    device = VulkanDevice::create({});
  } catch (const DeviceUnavailable& e) {
    FAIL() << e.what();
  }
  TextureCache cache(*device);
  constexpr uint32_t kSide = 1024;  // 4 MiB each
  constexpr size_t kBytes = size_t{kSide} * kSide * 4;
  const size_t per_frame = TextureCache::kMemoryBudgetBytes / kBytes / 2 + 1;  // > half budget
  uint64_t version = 1;
  std::vector<std::shared_ptr<rec::TextureObjectSnapshot>> previous, before_previous;
  for (uint64_t frame = 1; frame <= 4; ++frame) {
    std::vector<std::shared_ptr<rec::TextureObjectSnapshot>> owned;
    std::vector<const rec::TextureObjectSnapshot*> textures;
    for (size_t i = 0; i < per_frame; ++i) {
      owned.push_back(texture(version++, kSide));
      textures.push_back(owned.back().get());
    }
    cache.prepare(textures, frame);
    cache.evict_unused(frame);
    // Every texture of this frame keeps its image, even past the budget, and so does every
    // texture of the frame before (a frame presented later may still sample them) ...
    for (const auto* t : textures) EXPECT_NE(cache.view(*t), VK_NULL_HANDLE) << frame;
    for (const auto& t : previous) EXPECT_NE(cache.view(*t), VK_NULL_HANDLE) << frame;
    // ... and the older frames' images beyond the budget are gone.
    for (const auto& t : before_previous) EXPECT_EQ(cache.view(*t), VK_NULL_HANDLE) << frame;
    const size_t kept_frames = frame == 1 ? 1 : 2;
    EXPECT_LE(cache.image_bytes(),
              std::max(TextureCache::kMemoryBudgetBytes, kept_frames * per_frame * kBytes));
    EXPECT_GE(cache.image_bytes(), kept_frames * per_frame * kBytes);
    before_previous = std::move(previous);
    previous = std::move(owned);
  }
  // A texture prepared again keeps its image (no re-upload) and counts as used.
  std::vector<std::shared_ptr<rec::TextureObjectSnapshot>> last{texture(version - 1, kSide)};
  cache.prepare({last[0].get()}, 5);
  EXPECT_NE(cache.view(*last[0]), VK_NULL_HANDLE);
}

}  // namespace
}  // namespace glpt::rt
