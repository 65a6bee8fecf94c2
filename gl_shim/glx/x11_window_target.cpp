#include "gl_shim/glx/x11_window_target.hpp"

#include <sys/ipc.h>
#include <sys/shm.h>
#include <xcb/shm.h>
#include <xcb/xcb.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "rt_core/vk/vk_device.hpp"

namespace glpt {

std::unique_ptr<X11WindowTarget> X11WindowTarget::create(const std::string& display_name,
                                                         uint32_t window,
                                                         rec::DrawableConfig config,
                                                         std::string* error) {
  xcb_connection_t* c = xcb_connect(display_name.empty() ? nullptr : display_name.c_str(), nullptr);
  if (xcb_connection_has_error(c)) {
    xcb_disconnect(c);
    *error = "cannot open X display '" + display_name + "' for presenting";
    return nullptr;
  }
  return std::unique_ptr<X11WindowTarget>(new X11WindowTarget(c, window, config));
}

X11WindowTarget::X11WindowTarget(xcb_connection_t* connection, uint32_t window,
                                 rec::DrawableConfig config)
    : connection_(connection), window_(window), config_(config) {}

X11WindowTarget::~X11WindowTarget() {
  if (!owner_.is_this_process()) {  // a forked child's exit (process_owner.hpp)
    (void)presenter_.release();     // the thread is the parent's: nothing of it runs here
    return;
  }
  if (presenter_) {
    {
      std::lock_guard lock(present_mutex_);
      presenter_stop_ = true;  // after the frames it holds
    }
    present_changed_.notify_all();
    presenter_->join();
  }
  release_shm();
  if (gc_ != 0) xcb_free_gc(connection_, gc_);
  xcb_disconnect(connection_);
}

void X11WindowTarget::round_trip() {
  // The server has processed (and, for SHM, read) everything sent before the reply; errors of
  // earlier requests arrive as events on this connection, which nobody else reads. They came
  // before the reply, so reading the reply queued them: draining the queue needs no read of the
  // socket (xcb_poll_for_event's would be one more system call per frame, finding nothing).
  free(xcb_get_input_focus_reply(connection_, xcb_get_input_focus(connection_), nullptr));
  while (xcb_generic_event_t* e = xcb_poll_for_queued_event(connection_)) free(e);
}

void X11WindowTarget::release_shm() {
  wait_presented();
  for (ShmSegment& segment : shm_) {
    if (segment.id != 0) {
      xcb_shm_detach(connection_, segment.id);
      round_trip();  // the server lets go of the segment before it is unmapped here
      segment.id = 0;
    }
    if (segment.image.pixels != nullptr) shmdt(segment.image.pixels);
    segment.image = rt::HostImage();
  }
  shm_next_ = 0;
}

bool X11WindowTarget::attach_shm(ShmSegment& segment, uint32_t width, uint32_t height) {
  const size_t bytes = (size_t{width} * height * 4 + 4095) & ~size_t{4095};
  const int id = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
  if (id < 0) return false;
  void* memory = shmat(id, nullptr, 0);
  segment.id = xcb_generate_id(connection_);
  xcb_void_cookie_t cookie = xcb_shm_attach_checked(connection_, segment.id, id, 0);
  xcb_generic_error_t* error = xcb_request_check(connection_, cookie);
  // Marked for removal now: the segment disappears once both sides have detached.
  shmctl(id, IPC_RMID, nullptr);
  if (memory == reinterpret_cast<void*>(-1) || error != nullptr) {
    free(error);
    if (memory != reinterpret_cast<void*>(-1)) shmdt(memory);
    segment.id = 0;
    return false;  // e.g. a server on another host
  }
  segment.image = {static_cast<uint8_t*>(memory), width, height, rt::new_host_image_generation()};
  return true;
}

const rt::HostImage* X11WindowTarget::host_image(uint32_t width, uint32_t height) {
  if (!prepare()) return nullptr;
  if (!shm_checked_) {
    shm_checked_ = true;
    xcb_shm_query_version_reply_t* v =
        xcb_shm_query_version_reply(connection_, xcb_shm_query_version(connection_), nullptr);
    // Only the pixel layout the renderer writes (BGRA bytes = 0x..RRGGBB little-endian words).
    shm_available_ =
        v != nullptr && red_shift_ == 16 && green_shift_ == 8 && blue_shift_ == 0 && lsb_first_;
    free(v);
  }
  // At exit (rt::process_exiting) frames are not shown: no segment, no waiting for one.
  if (!shm_available_ || width == 0 || height == 0 || rt::process_exiting()) return nullptr;
  const ShmSegment& other = shm_[shm_next_ ^ 1];
  if (other.image.pixels != nullptr && (other.image.width != width || other.image.height != height))
    release_shm();  // a new size: both segments go
  {
    // The segment's last frame must be on screen before the renderer writes the next into it.
    std::unique_lock lock(present_mutex_);
    present_changed_.wait(lock, [&] { return !shm_busy_[shm_next_]; });
  }
  ShmSegment& segment = shm_[shm_next_];
  if (segment.image.pixels != nullptr && segment.image.width == width &&
      segment.image.height == height)
    return &segment.image;
  if (segment.image.pixels != nullptr) release_shm();
  if (!attach_shm(shm_[shm_next_], width, height)) {
    shm_available_ = false;
    release_shm();
    return nullptr;
  }
  return &shm_[shm_next_].image;
}

void X11WindowTarget::put_shm(const ShmSegment& segment) {
  const uint16_t w = static_cast<uint16_t>(segment.image.width);
  const uint16_t h = static_cast<uint16_t>(segment.image.height);
  xcb_shm_put_image(connection_, window_, gc_, w, h, 0, 0, w, h, 0, 0, depth_,
                    XCB_IMAGE_FORMAT_Z_PIXMAP, 0, segment.id, 0);
  // The segment may be written again once the server has read it, and the frame is on screen.
  round_trip();
}

void X11WindowTarget::present_host_image() {
  wait_presented();  // frames keep their order on screen
  const ShmSegment& segment = shm_[shm_next_];
  if (segment.id == 0 || segment.image.pixels == nullptr) return;
  put_shm(segment);
}

void X11WindowTarget::present_host_image_later(std::function<void()> ready) {
  if (shm_[shm_next_].id == 0 || shm_[shm_next_].image.pixels == nullptr) {
    ready();  // nothing to show; the renderer's work still completes before this returns
    return;
  }
  {
    std::lock_guard lock(present_mutex_);
    if (!presenter_) {
      try {
        presenter_ = std::make_unique<std::thread>([this] { run_presenter(); });
      } catch (const std::exception&) {  // no thread: present here, as before
        presenter_.reset();
      }
    }
    if (presenter_) {
      shm_busy_[shm_next_] = true;
      present_jobs_.push_back({shm_next_, std::move(ready)});
    }
  }
  if (!presenter_) {
    ready();
    put_shm(shm_[shm_next_]);
    return;
  }
  present_changed_.notify_all();
  shm_next_ ^= 1;
}

void X11WindowTarget::run_presenter() {
  for (;;) {
    PresentJob* job = nullptr;
    {
      std::unique_lock lock(present_mutex_);
      present_changed_.wait(lock, [&] { return presenter_stop_ || !present_jobs_.empty(); });
      if (present_jobs_.empty()) return;  // stopped, every frame shown
      job = &present_jobs_.front();       // stays in the queue (wait_presented) until shown
    }
    // The job and its segment are not touched by the program's thread until it leaves the
    // queue: host_image() and release_shm() wait for that.
    job->ready();
    if (!rt::process_exiting()) put_shm(shm_[job->segment]);
    {
      std::lock_guard lock(present_mutex_);
      shm_busy_[job->segment] = false;
      present_jobs_.pop_front();
    }
    present_changed_.notify_all();
  }
}

void X11WindowTarget::wait_presented() {
  // From an exit handler nothing is shown any more (the presenting thread skips its requests):
  // flushes at exit do not wait for it.
  if (rt::process_exiting()) return;
  std::unique_lock lock(present_mutex_);
  present_changed_.wait(lock, [&] { return present_jobs_.empty(); });
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

bool X11WindowTarget::known_size(uint32_t* width, uint32_t* height) {
  const uint64_t known = known_size_;
  if (known != kSizeUnknown) {
    *width = static_cast<uint32_t>(known >> 32);
    *height = static_cast<uint32_t>(known);
    return true;
  }
  if (!query_size(width, height)) return false;
  known_size_ = uint64_t{*width} << 32 | *height;
  return true;
}

bool X11WindowTarget::prepare() {
  if (prepared_) return gc_ != 0;
  prepared_ = true;
  xcb_generic_error_t* err = nullptr;
  xcb_get_window_attributes_reply_t* attrs = xcb_get_window_attributes_reply(
      connection_, xcb_get_window_attributes(connection_, window_), &err);
  free(err);
  // A pixmap has no visual: its pixels are laid out as the TrueColor visuals of its depth.
  xcb_visualid_t visual = 0;
  uint8_t pixmap_depth = 0;
  if (attrs != nullptr) {
    visual = attrs->visual;
    free(attrs);
  } else {
    xcb_get_geometry_reply_t* g =
        xcb_get_geometry_reply(connection_, xcb_get_geometry(connection_, window_), nullptr);
    if (g == nullptr) return false;
    pixmap_depth = g->depth;
    free(g);
  }
  const xcb_setup_t* setup = xcb_get_setup(connection_);
  lsb_first_ = setup->image_byte_order == XCB_IMAGE_ORDER_LSB_FIRST;
  for (auto s = xcb_setup_roots_iterator(setup); s.rem; xcb_screen_next(&s))
    for (auto d = xcb_screen_allowed_depths_iterator(s.data); d.rem; xcb_depth_next(&d))
      for (auto v = xcb_depth_visuals_iterator(d.data); v.rem; xcb_visualtype_next(&v))
        if (v.data->visual_id == visual || (visual == 0 && d.data->depth == pixmap_depth &&
                                            v.data->_class == XCB_VISUAL_CLASS_TRUE_COLOR)) {
          visual = v.data->visual_id;
          red_shift_ = std::countr_zero(v.data->red_mask);
          green_shift_ = std::countr_zero(v.data->green_mask);
          blue_shift_ = std::countr_zero(v.data->blue_mask);
          depth_ = d.data->depth;
        }
  if (depth_ != 24 && depth_ != 32) {
    std::fprintf(stderr, "glpt: cannot present to a window of depth %u (need 24 or 32)\n",
                 depth_.load());
    return false;
  }
  gc_ = xcb_generate_id(connection_);
  xcb_create_gc(connection_, gc_, window_, 0, nullptr);
  return true;
}

void X11WindowTarget::present(const uint8_t* rgba, uint32_t width, uint32_t height) {
  if (!prepare()) return;
  wait_presented();  // frames keep their order on screen
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
  round_trip();
}

}  // namespace glpt
