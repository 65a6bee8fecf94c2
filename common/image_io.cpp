#include "image_io.hpp"

#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

namespace glpt {
namespace {

void set_error(std::string* error, const std::string& message) {
  if (error) *error = message;
}

std::string errno_text(const char* what, const std::string& path) {
  return std::string(what) + " " + path + ": " + std::strerror(errno);
}

// libpng reports errors by calling a handler that must not return; it longjmps back into
// encode_png(). No C++ object with a destructor may live in a frame that longjmp skips, so the
// libpng work stays in this plain-C-style function and everything it touches is POD.
struct EncodeStatus {
  char message[256];
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* status = static_cast<EncodeStatus*>(png_get_error_ptr(png));
  std::snprintf(status->message, sizeof status->message, "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

bool encode_png(FILE* fp, uint32_t w, uint32_t h, const uint8_t* rgba, bool bottom_up,
                EncodeStatus* status) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, status, on_png_error, on_png_warning);
  if (!png) {
    std::snprintf(status->message, sizeof status->message, "png_create_write_struct failed");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(status->message, sizeof status->message, "png_create_info_struct failed");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, fp);
  // Frames are written once per frame from inside libGL: favour speed over size. Measured on a
  // 1280x1024 gears frame: zlib level 1 with the "up" filter takes 14 ms (63 KB) against 53 ms
  // (35 KB) for libpng's defaults (level 6, adaptive filters); with +-10 noise per channel, as a
  // path tracer leaves, 99 ms (3.2 MB) against 639 ms (2.8 MB).
  png_set_compression_level(png, 1);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const size_t stride = size_t{w} * 4;
  for (uint32_t y = 0; y < h; ++y) {
    const uint32_t row = bottom_up ? h - 1 - y : y;
    png_write_row(png, rgba + row * stride);
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

bool write_png_rgba8(const std::string& path, uint32_t w, uint32_t h, const uint8_t* rgba,
                     bool bottom_up, std::string* error) {
  // PNG allows up to 2^31-1; libpng's default user limit is 10^6 per side.
  if (w == 0 || h == 0 || w > 1000000 || h > 1000000) {
    set_error(error, "write_png_rgba8 " + path + ": invalid size " + std::to_string(w) + "x" +
                         std::to_string(h));
    return false;
  }
  if (!rgba) {
    set_error(error, "write_png_rgba8 " + path + ": no pixels");
    return false;
  }
  try {
    // A unique temporary name next to the target, so rename() is atomic (same file system) and
    // concurrent writers never share a temporary file.
    // The name ends in ".png.tmp" (ignored by git, not matched by "*.png" globs).
    std::string tmp = path + ".XXXXXX.png.tmp";
    const int fd = mkstemps(tmp.data(), 8);
    if (fd < 0) {
      set_error(error, errno_text("cannot create a temporary file for", path));
      return false;
    }
    fchmod(fd, 0644);  // mkstemps creates 0600; frames are ordinary output files
    FILE* fp = fdopen(fd, "wb");
    if (!fp) {
      set_error(error, errno_text("fdopen", tmp));
      close(fd);
      unlink(tmp.c_str());
      return false;
    }
    EncodeStatus status{};
    const bool encoded = encode_png(fp, w, h, rgba, bottom_up, &status);
    int write_errno = 0;
    if (std::fflush(fp) != 0 || std::ferror(fp)) write_errno = errno ? errno : EIO;
    if (std::fclose(fp) != 0 && write_errno == 0) write_errno = errno;
    if (!encoded || write_errno != 0) {
      if (!encoded) {
        set_error(error, "write_png_rgba8 " + tmp + ": " + status.message);
      } else {
        errno = write_errno;
        set_error(error, errno_text("write", tmp));
      }
      unlink(tmp.c_str());
      return false;
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
      set_error(error, errno_text(("rename " + tmp + " to").c_str(), path));
      unlink(tmp.c_str());
      return false;
    }
    return true;
  } catch (const std::exception& e) {  // std::bad_alloc from building the strings
    set_error(error, std::string("write_png_rgba8: ") + e.what());
    return false;
  }
}

bool read_png_rgba8(const std::string& path, ImageRGBA8* out, std::string* error) {
  if (!out) {
    set_error(error, "read_png_rgba8: no output image");
    return false;
  }
  // libpng's simplified API does every conversion (palette, grey, tRNS, 16-bit) and handles its
  // own longjmp internally.
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    set_error(error, "read_png_rgba8 " + path + ": " + image.message);
    return false;  // libpng has already freed `image`
  }
  image.format = PNG_FORMAT_RGBA;
  // 16-bit files without gAMA/sRGB: treat the values as sRGB-encoded (plain 16 -> 8 bit scaling)
  // rather than as linear light, which libpng would otherwise assume.
  image.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
  try {
    out->width = image.width;
    out->height = image.height;
    // PNG_IMAGE_SIZE computes in 32 bits; libpng limits each side to 10^6, so use size_t.
    out->pixels.assign(size_t{image.width} * image.height * 4, 0);
  } catch (const std::exception& e) {
    png_image_free(&image);
    set_error(error, "read_png_rgba8 " + path + ": " + e.what());
    return false;
  }
  if (!png_image_finish_read(&image, nullptr, out->pixels.data(), 0, nullptr)) {
    set_error(error, "read_png_rgba8 " + path + ": " + image.message);
    return false;
  }
  return true;
}

}  // namespace glpt
