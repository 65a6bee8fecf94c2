// Presents frames into an X window through glpt's own XCB connection to the program's display.
//
// Why a connection of its own: the program's Display* is not thread-safe unless it called
// XInitThreads, and Xlib reports errors through a process-global handler that belongs to the
// program. XCB returns errors per request, so a window that vanished is just a failed present.
#pragma once

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "gl_shim/frame/frame_output.hpp"
#include "gl_shim/process_owner.hpp"

struct xcb_connection_t;

namespace glpt {

class X11WindowTarget final : public WindowTarget {
 public:
  // nullptr (and a message) if the display cannot be opened. `drawable` is a window or a pixmap;
  // `config` says what buffers its GLX config has (a pixmap of a double-buffered config has a
  // back buffer that is never swapped, as in Mesa).
  static std::unique_ptr<X11WindowTarget> create(const std::string& display_name, uint32_t drawable,
                                                 rec::DrawableConfig config, std::string* error);
  ~X11WindowTarget() override;

  uint32_t window() const { return window_; }
  bool query_size(uint32_t* width, uint32_t* height) override;
  bool known_size(uint32_t* width, uint32_t* height) override;
  void forget_size() override {
    if (!size_assumed_.exchange(false)) known_size_ = kSizeUnknown;
  }
  void assume_size(uint32_t width, uint32_t height) override {
    known_size_ = uint64_t{width} << 32 | height;
    size_assumed_ = true;
  }
  rec::DrawableConfig config() const override { return config_; }
  void present(const uint8_t* rgba, uint32_t width, uint32_t height) override;
  const rt::HostImage* host_image(uint32_t width, uint32_t height) override;
  void present_host_image() override;
  void present_host_image_later(std::function<void()> ready) override;
  void wait_presented() override;

 private:
  X11WindowTarget(xcb_connection_t* connection, uint32_t window, rec::DrawableConfig config);
  bool prepare();  // looks up the window's visual and creates the GC, once

  xcb_connection_t* connection_;
  uint32_t window_;
  ProcessOwner owner_;  // only the process that connected may send requests or disconnect
  rec::DrawableConfig config_;
  uint32_t gc_ = 0;
  std::atomic<uint8_t> depth_ = 0;  // written by query_size, which any thread may call
  // known_size(): width << 32 | height, or kSizeUnknown (any thread may ask or forget).
  static constexpr uint64_t kSizeUnknown = ~uint64_t{0};
  std::atomic<uint64_t> known_size_ = kSizeUnknown;
  std::atomic<bool> size_assumed_ = false;  // assume_size(): the next forget_size() keeps it
  int red_shift_ = 16, green_shift_ = 8, blue_shift_ = 0;
  bool prepared_ = false;
  bool lsb_first_ = true;  // server image byte order
  std::vector<uint32_t> converted_;
  // MIT-SHM: the frame is written straight into memory the X server reads (as Mesa's software
  // GLX presents). Unavailable over a network connection or with another pixel layout. Two
  // segments: the renderer writes the next frame into one while the other is being shown.
  struct ShmSegment {
    uint32_t id = 0;  // xcb_shm_seg_t, 0 when none is attached
    rt::HostImage image;
  };
  bool shm_checked_ = false, shm_available_ = false;
  std::array<ShmSegment, 2> shm_;
  size_t shm_next_ = 0;  // the segment host_image() hands out
  bool attach_shm(ShmSegment& segment, uint32_t width, uint32_t height);
  void release_shm();
  void put_shm(const ShmSegment& segment);
  void round_trip();

  // The presenting thread (present_host_image_later): it waits for each frame, then shows it.
  // shm_busy_[i]: segment i holds a frame not yet shown (host_image() waits for it).
  struct PresentJob {
    size_t segment;
    std::function<void()> ready;
  };
  std::mutex present_mutex_;
  std::condition_variable present_changed_;
  std::deque<PresentJob> present_jobs_;
  std::array<bool, 2> shm_busy_{};
  bool presenter_stop_ = false;
  std::unique_ptr<std::thread> presenter_;
  void run_presenter();
};

}  // namespace glpt
