// The buffers of one GL drawable (a window, pixmap or pbuffer): colour front and back,
// depth/stencil and accumulation. They belong to the drawable, not to a context: GLX and EGL let
// several contexts draw to one drawable (one after another, or from several threads), and each
// must draw into and read what the others left (GL 1.5 2.1: the framebuffer is the window
// system's). The raster renderer (re)creates them when the drawable's configuration changes.
#pragma once

#include <memory>

#include "rt_core/raster/accumulation.hpp"
#include "rt_core/record/frame_record.hpp"
#include "rt_core/vk/gpu_image.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

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
};

}  // namespace glpt::rt
