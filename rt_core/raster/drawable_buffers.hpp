// The buffers of one GL drawable (a window, pixmap or pbuffer): colour front and back,
// depth/stencil and accumulation. They belong to the drawable, not to a context: GLX and EGL let
// several contexts draw to one drawable (one after another, or from several threads), and each
// must draw into and read what the others left (GL 1.5 2.1: the framebuffer is the window
// system's). The raster renderer (re)creates them when the drawable's configuration changes.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <vector>

#include "rt_core/raster/accumulation.hpp"
#include "rt_core/record/frame_record.hpp"
#include "rt_core/vk/gpu_image.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

// The host's reads of colour images in flight: a presenting thread that copies a finished frame
// out of the front image (FrameEnd::front_pixels) while the program goes on. Whatever writes an
// image, or replaces it, first waits for its reads (RasterRenderer). Thread-safe.
class HostImageReads {
 public:
  void begin(VkImage image) {
    std::lock_guard lock(mutex_);
    reading_.push_back({image, getpid()});
  }
  void end(VkImage image) {
    {
      std::lock_guard lock(mutex_);
      const auto found = std::find_if(reading_.begin(), reading_.end(),
                                      [&](const Read& r) { return r.image == image; });
      if (found != reading_.end()) reading_.erase(found);
    }
    done_.notify_all();
  }
  // Until no read of `image` is in flight (VK_NULL_HANDLE: of any image).
  void wait(VkImage image) {
    std::unique_lock lock(mutex_);
    // A forked child inherits the entries but not the threads that would end them.
    const pid_t self = getpid();
    std::erase_if(reading_, [&](const Read& r) { return r.process != self; });
    done_.wait(lock, [&] {
      return std::none_of(reading_.begin(), reading_.end(), [&](const Read& r) {
        return image == VK_NULL_HANDLE || r.image == image;
      });
    });
  }

 private:
  struct Read {
    VkImage image;
    pid_t process;
  };
  std::mutex mutex_;
  std::condition_variable done_;
  std::vector<Read> reading_;  // one entry per read in flight
};

struct DrawableBuffers {
  // The device the images live on (the process's); declared first, so it outlives them.
  std::shared_ptr<VulkanDevice> device;
  rec::DrawableConfig config{0, 0};
  GpuImage front, back, depth_stencil;
  // A swap exchanges the colour images instead of copying the back into the front (GL keeps the
  // back buffer's contents across a swap, as Mesa's software swap does): the back buffer's pixels
  // are then the front's until the raster renderer copies them over, which it does only when the
  // back is used before a clear replaces it (RasterRenderer::restore_back).
  bool back_is_front = false;
  AccumulationBuffer accum;
  // Shared with the reads' threads, which may finish after the buffers are gone.
  std::shared_ptr<HostImageReads> host_reads = std::make_shared<HostImageReads>();
};

}  // namespace glpt::rt
