#include "gl_shim/glx/x11_window_target.hpp"

#include <xcb/xcb.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace glpt {

std::unique_ptr<X11WindowTarget> X11WindowTarget::create(const std::string& display_name,
                                                         uint32_t window, std::string* error) {
  xcb_connection_t* c = xcb_connect(display_name.empty() ? nullptr : display_name.c_str(), nullptr);
  if (xcb_connection_has_error(c)) {
    xcb_disconnect(c);
    *error = "cannot open X display '" + display_name + "' for presenting";
    return nullptr;
  }
  return std::unique_ptr<X11WindowTarget>(new X11WindowTarget(c, window));
}

X11WindowTarget::X11WindowTarget(xcb_connection_t* connection, uint32_t window)
    : connection_(connection), window_(window) {}

X11WindowTarget::~X11WindowTarget() {
  if (gc_ != 0) xcb_free_gc(connection_, gc_);
  xcb_disconnect(connection_);
}

bool X11WindowTarget::query_size(uint32_t* width, uint32_t* height) {
  xcb_generic_error_t* err = nullptr;
  xcb_get_geometry_reply_t* g =
      xcb_get_geometry_reply(connection_, xcb_get_geometry(connection_, window_), &err);
  free(err);
  if (g == nullptr) return false;
  *width = g->width;
  *height = g->height;
  depth_ = g->depth;
  free(g);
  return true;
}

bool X11WindowTarget::prepare() {
  if (prepared_) return gc_ != 0;
  prepared_ = true;
  xcb_generic_error_t* err = nullptr;
  xcb_get_window_attributes_reply_t* attrs = xcb_get_window_attributes_reply(
      connection_, xcb_get_window_attributes(connection_, window_), &err);
  free(err);
  if (attrs == nullptr) return false;
  const xcb_visualid_t visual = attrs->visual;
  free(attrs);
  const xcb_setup_t* setup = xcb_get_setup(connection_);
  lsb_first_ = setup->image_byte_order == XCB_IMAGE_ORDER_LSB_FIRST;
  for (auto s = xcb_setup_roots_iterator(setup); s.rem; xcb_screen_next(&s))
    for (auto d = xcb_screen_allowed_depths_iterator(s.data); d.rem; xcb_depth_next(&d))
      for (auto v = xcb_depth_visuals_iterator(d.data); v.rem; xcb_visualtype_next(&v))
        if (v.data->visual_id == visual) {
          red_shift_ = std::countr_zero(v.data->red_mask);
          green_shift_ = std::countr_zero(v.data->green_mask);
          blue_shift_ = std::countr_zero(v.data->blue_mask);
          depth_ = d.data->depth;
        }
  if (depth_ != 24 && depth_ != 32) {
    std::fprintf(stderr, "glpt: cannot present to a window of depth %u (need 24 or 32)\n", depth_);
    return false;
  }
  gc_ = xcb_generate_id(connection_);
  xcb_create_gc(connection_, gc_, window_, 0, nullptr);
  return true;
}

void X11WindowTarget::present(const uint8_t* rgba, uint32_t width, uint32_t height) {
  if (!prepare()) return;
  // GL rows run bottom to top, X rows top to bottom; pixels become 32-bit words in the
  // visual's channel layout.
  converted_.resize(size_t{width} * height);
  // The usual visual (0xRRGGBB words, little-endian server, as on x86 hosts) takes a word-wise
  // swap of R and B that the compiler vectorizes; any other layout goes channel by channel.
  const bool rgb_words = red_shift_ == 16 && green_shift_ == 8 && blue_shift_ == 0 && lsb_first_ &&
                         std::endian::native == std::endian::little;
  for (uint32_t y = 0; y < height; ++y) {
    const uint8_t* src = rgba + size_t{height - 1 - y} * width * 4;
    uint32_t* dst = converted_.data() + size_t{y} * width;
    if (rgb_words) {
      std::memcpy(dst, src, size_t{width} * 4);
      for (uint32_t x = 0; x < width; ++x) {
        const uint32_t w = dst[x];  // 0xAABBGGRR
        dst[x] = ((w & 0xFFu) << 16) | (w & 0xFF00u) | ((w >> 16) & 0xFFu);
      }
      continue;
    }
    for (uint32_t x = 0; x < width; ++x, src += 4) {
      uint32_t p = (uint32_t{src[0]} << red_shift_) | (uint32_t{src[1]} << green_shift_) |
                   (uint32_t{src[2]} << blue_shift_);
      if (!lsb_first_) p = __builtin_bswap32(p);
      dst[x] = p;
    }
  }
  // One PutImage request is limited in size: send strips of rows.
  const uint64_t max_bytes = uint64_t{xcb_get_maximum_request_length(connection_)} * 4 - 64;
  const uint32_t rows_per_request =
      std::max<uint32_t>(1, static_cast<uint32_t>(max_bytes / (uint64_t{width} * 4)));
  for (uint32_t y = 0; y < height; y += rows_per_request) {
    const uint32_t rows = std::min(rows_per_request, height - y);
    xcb_put_image(connection_, XCB_IMAGE_FORMAT_Z_PIXMAP, window_, gc_,
                  static_cast<uint16_t>(width), static_cast<uint16_t>(rows), 0,
                  static_cast<int16_t>(y), 0, depth_, rows * width * 4,
                  reinterpret_cast<const uint8_t*>(converted_.data() + size_t{y} * width));
  }
  // Round trip so the image is on screen when the swap returns (and errors are collected).
  free(xcb_get_input_focus_reply(connection_, xcb_get_input_focus(connection_), nullptr));
  // Errors (a window destroyed under us) arrive as events on this connection; nobody else reads it.
  while (xcb_generic_event_t* e = xcb_poll_for_event(connection_)) free(e);
}

}  // namespace glpt
