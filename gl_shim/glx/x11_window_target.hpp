// Presents frames into an X window through glpt's own XCB connection to the program's display.
//
// Why a connection of its own: the program's Display* is not thread-safe unless it called
// XInitThreads, and Xlib reports errors through a process-global handler that belongs to the
// program. XCB returns errors per request, so a window that vanished is just a failed present.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl_shim/frame/frame_output.hpp"

struct xcb_connection_t;

namespace glpt {

class X11WindowTarget final : public WindowTarget {
 public:
  // nullptr (and a message) if the display cannot be opened.
  static std::unique_ptr<X11WindowTarget> create(const std::string& display_name, uint32_t window,
                                                 std::string* error);
  ~X11WindowTarget() override;

  uint32_t window() const { return window_; }
  bool query_size(uint32_t* width, uint32_t* height) override;
  void present(const uint8_t* rgba, uint32_t width, uint32_t height) override;

 private:
  X11WindowTarget(xcb_connection_t* connection, uint32_t window);
  bool prepare();  // looks up the window's visual and creates the GC, once

  xcb_connection_t* connection_;
  uint32_t window_;
  uint32_t gc_ = 0;
  uint8_t depth_ = 0;
  int red_shift_ = 16, green_shift_ = 8, blue_shift_ = 0;
  bool prepared_ = false;
  bool lsb_first_ = true;  // server image byte order
  std::vector<uint32_t> converted_;
};

}  // namespace glpt
