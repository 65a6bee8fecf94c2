// rt_core's public entry point: executes frame records (record/frame_record.hpp) on a drawable's
// buffers, in raster mode (Vulkan pipelines emulating GL fixed function) or path-traced mode.
//
// The drawable's buffers (colour front and back, depth, stencil, accumulation) persist between
// records as GL's do; a record only applies its commands to them. Reads answer from them.
//
// A Renderer holds what a share group's contexts share on the GPU (textures, pipelines,
// acceleration structures, the path tracer's history); the device under it is the process's
// (one per process). Its methods may be called from several threads (contexts of one share
// group current on different threads): they are serialized. No exception leaves this API;
// failures come back as nullptr / false with a message.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rt_core/frame_stats.hpp"
#include "rt_core/record/frame_record.hpp"
#include "rt_core/render_settings.hpp"

namespace glpt::rt {

// Host memory a window shows from directly (an X MIT-SHM segment): 32-bit pixels 0xAARRGGBB
// (bytes B, G, R, A), rows top to bottom, width * height * 4 bytes, page aligned.
struct HostImage {
  uint8_t* pixels = nullptr;
  uint32_t width = 0, height = 0;
  // A new value from new_host_image_generation() whenever `pixels` is (re)allocated: renderers
  // import the memory once per generation, and present to several windows.
  uint64_t generation = 0;
};
uint64_t new_host_image_generation();  // unique in the process

// What happens at the end of a frame, in the same submission as the record's commands (one
// round trip into the Vulkan queue per frame).
struct FrameEnd {
  bool swap = false;                           // double-buffered swap: back -> front
  std::vector<uint8_t>* front_rgba = nullptr;  // read the front buffer (RGBA8, bottom row first)
  const HostImage* present_to = nullptr;       // copy the front buffer there for the window
  // The caller shows present_to later, after Renderer::wait_for_frame(Renderer::frame_ticket()):
  // where the window's memory is imported and the frame is rasterized (raster mode, or a frame
  // with nothing traced is not enough: path-traced mode always waits), execute returns once the
  // frame is submitted, so the program records its next frame while this one renders.
  bool present_later = false;
  // present_to receives the rows bottom to top (GL's order), for the caller to flip: one copy
  // region where lavapipe pays per region (300 row regions cost 3x one at 300x300).
  bool present_bottom_up = false;
  // Where the front image is readable in place (raster mode, a device with linear colour
  // attachments), a frame presented later is not copied by the renderer at all: execute fills
  // this in with the front image's rows (bottom to top, row_pitch apart) for the caller to copy
  // into present_to once Renderer::wait_for_frame returned, and a token that stands for the
  // read: every later write to the image, and replacing it, waits until the token is released.
  struct FrontPixels {
    const uint8_t* rows = nullptr;
    size_t row_pitch = 0;
    std::shared_ptr<void> reading;
  };
  FrontPixels* front_pixels = nullptr;
};

// The samples one execute counted for an occlusion query (rec::BeginQuery .. rec::EndQuery): those
// of the record's commands while the query was active that passed the depth and stencil tests.
struct QuerySamples {
  uint64_t id = 0;
  uint64_t samples = 0;
};

// A rectangle of pixels that replaces what the buffers hold there, past every fragment operation
// (glBlitFramebuffer's destination). Each of colour, depth and stencil is written where it is not
// empty: width * height values, rows bottom to top. The rectangle lies inside the drawable.
struct PixelWrite {
  int32_t x = 0, y = 0;
  uint32_t width = 0, height = 0;
  uint32_t draw_buffer = 0;   // the GL draw buffer `rgba` goes to (GL_BACK, GL_NONE, ...)
  std::vector<uint8_t> rgba;  // RGBA8
  std::vector<float> depth;   // window z in [0, 1]
  std::vector<uint8_t> stencil;
};

// The buffers of one GL drawable (colour front and back, depth/stencil, accumulation; see
// raster/drawable_buffers.hpp). They belong to the drawable: every context drawing to it (with
// any renderer of the process) draws into and reads the same buffers. Created empty; the first
// execute on them allocates them. Not thread-safe: the caller serializes uses of one drawable.
struct DrawableBuffers;
std::shared_ptr<DrawableBuffers> create_drawable_buffers();

class Renderer {
 public:
  // nullptr + one clear message in *error when no usable Vulkan device exists (it names what is
  // missing and how to install it). A device without ray queries gives raster mode, with a
  // message in *notice. GLPT_VK_DEVICE=substring selects the device by name.
  static std::unique_ptr<Renderer> create(const RenderSettings& settings, std::string* error,
                                          std::string* notice = nullptr);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  RenderMode mode() const;
  const std::string& device_name() const;

  // Applies the record's commands to the drawable's `buffers`. They are (re)created when the
  // drawable's configuration changes; their contents are then undefined, as after a resize.
  // `queries` (may be null) receives one entry per occlusion query the record counts into
  // (active at its start or begun in it), zero samples included.
  bool execute(const rec::FrameRecord& record, DrawableBuffers& buffers,
               const rec::DrawableConfig& drawable, FrameStats& stats, std::string* error,
               const FrameEnd* end = nullptr, std::vector<QuerySamples>* queries = nullptr);

  // A rectangle of a colour buffer (GL_FRONT*, GL_BACK*: the resolved read buffer) as RGBA8,
  // rows bottom to top; pixels outside the drawable are zero. False before the first execute.
  bool read_color(DrawableBuffers& buffers, uint32_t buffer, int32_t x, int32_t y, uint32_t width,
                  uint32_t height, std::vector<uint8_t>& rgba, std::string* error);
  // Window depth in [0, 1] and stencil values of the rectangle; false if the drawable has none.
  bool read_depth(DrawableBuffers& buffers, int32_t x, int32_t y, uint32_t width, uint32_t height,
                  std::vector<float>& depth, std::string* error);
  bool read_stencil(DrawableBuffers& buffers, int32_t x, int32_t y, uint32_t width, uint32_t height,
                    std::vector<uint8_t>& stencil, std::string* error);

  // Replaces the front colour buffer of `buffers` (created for `drawable` if need be) with
  // `rgba` (RGBA8, rows bottom to top, the drawable's size): a framebuffer object's target takes
  // the image of the texture attached to it.
  bool write_color(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                   const std::vector<uint8_t>& rgba, std::string* error);
  // Replaces the depth buffer with `depth` (window z, rows bottom to top, the drawable's size):
  // a framebuffer object's target takes the depth texture attached to it.
  bool write_depth(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                   const std::vector<float>& depth, std::string* error);

  // Writes `pixels` into `buffers` (created for `drawable` if need be).
  bool write_pixels(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                    const PixelWrite& pixels, std::string* error);

  // What wait_for_frame() takes to wait for everything submitted so far (the frame an execute
  // with FrameEnd::present_later just submitted included).
  uint64_t frame_ticket() const;
  // Blocks until the submissions up to `ticket` have completed. Any thread may call it, also
  // while another executes: it holds no lock of the renderer while it waits.
  void wait_for_frame(uint64_t ticket) const;

  // glXSwapBuffers of a double-buffered drawable: the front buffer takes the back buffer's
  // contents, and the back buffer keeps them (Mesa's software swap does the same).
  bool swap_buffers(DrawableBuffers& buffers, std::string* error);

  // glpt-replay's frame `frame_index` starts: path tracing seeds its random sequence by the index
  // and keeps its history (denoiser, accumulation) only from the frame before it within the same
  // window of `history_window` frames (PathTracer::start_independent_frame), so the frame's
  // pixels depend only on the frames of its window before it. Raster mode has no such state.
  void start_independent_frame(uint64_t frame_index, uint32_t history_window);

 private:
  class Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace glpt::rt
