// glXUseXFont (GLX 1.4 3.3.11): display lists that draw an X font's glyphs with glBitmap, made the
// way Mesa's src/glx/xfont.c makes them (and its glXUseXFont(3) page says): each glyph is drawn
// by the X server into a 1-bit pixmap, read back with XGetImage and turned upside down;
// glBitmap(width, height, -lbearing, descent - 1, advance, 0). A code point the font lacks gets a
// list with an empty glBitmap that advances by the font's widest glyph.
#include <X11/Xlib.h>

#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/glx/glx_api.hpp"
#include "gl_shim/glx/glx_display.hpp"

// The exported GL entry points: list compilation goes through them like the program's own calls.
extern "C" {
GLPT_EXPORT void glNewList(GLuint list, GLenum mode);
GLPT_EXPORT void glEndList(void);
GLPT_EXPORT void glBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig,
                          GLfloat xmove, GLfloat ymove, const GLubyte* bitmap);
GLPT_EXPORT void glGetIntegerv(GLenum pname, GLint* data);
GLPT_EXPORT void glPixelStorei(GLenum pname, GLint param);
}

namespace {

// The glyph metrics of code point `c`, nullptr if the font has no such glyph (as Mesa's isvalid:
// one-row fonts index by the code point, matrix fonts by its two bytes).
const XCharStruct* glyph_metrics(const XFontStruct* fs, unsigned c) {
  const unsigned rows = fs->max_byte1 - fs->min_byte1 + 1;
  const unsigned columns = fs->max_char_or_byte2 - fs->min_char_or_byte2 + 1;
  unsigned index = 0;
  if (rows == 1) {
    if (c < fs->min_char_or_byte2 || c > fs->max_char_or_byte2) return nullptr;
    index = c - fs->min_char_or_byte2;
  } else {
    const unsigned byte1 = c >> 8, byte2 = c & 0xFF;
    if (byte2 < fs->min_char_or_byte2 || byte2 > fs->max_char_or_byte2 || byte1 < fs->min_byte1 ||
        byte1 > fs->max_byte1)
      return nullptr;
    index = (byte1 - fs->min_byte1) * columns + (byte2 - fs->min_char_or_byte2);
  }
  return fs->per_char ? &fs->per_char[index] : &fs->min_bounds;
}

// The glyph as a GL bitmap: rows bottom to top, `row_bytes` per row, most significant bit first.
std::vector<GLubyte> glyph_bitmap(Display* dpy, Window root, GC gc, unsigned c, int row_bytes,
                                  int height, int x, int y) {
  std::vector<GLubyte> bits(static_cast<size_t>(row_bytes) * height, 0);
  const unsigned width = static_cast<unsigned>(row_bytes) * 8;
  Pixmap pixmap = XCreatePixmap(dpy, root, width, static_cast<unsigned>(height), 1);
  XSetForeground(dpy, gc, 0);
  XFillRectangle(dpy, pixmap, gc, 0, 0, width, static_cast<unsigned>(height));
  XSetForeground(dpy, gc, 1);
  XChar2b glyph{static_cast<unsigned char>((c >> 8) & 0xFF), static_cast<unsigned char>(c & 0xFF)};
  XDrawString16(dpy, pixmap, gc, x, y, &glyph, 1);
  if (XImage* image =
          XGetImage(dpy, pixmap, 0, 0, width, static_cast<unsigned>(height), 1, XYPixmap)) {
    for (int row = 0; row < height; ++row)
      for (unsigned col = 0; col < width; ++col)
        if (XGetPixel(image, static_cast<int>(col), row))
          bits[static_cast<size_t>(height - 1 - row) * row_bytes + col / 8] |=
              static_cast<GLubyte>(0x80u >> (col % 8));
    XDestroyImage(image);
  }
  XFreePixmap(dpy, pixmap);
  return bits;
}

void use_x_font(Font font, int first, int count, int list_base) {
  glpt::Context* gl = glpt::current_context();
  if (gl == nullptr || gl->window_system != glpt::WindowSystem::kGlx) return;
  Display* dpy = glXGetCurrentDisplay();
  if (dpy == nullptr) return;
  if (count < 0) return glpt::record_error(*gl, GL_INVALID_VALUE);
  XFontStruct* fs = XQueryFont(dpy, font);
  if (fs == nullptr) return glpt::record_error(*gl, GL_INVALID_VALUE);  // as Mesa

  // The lists are made with the default unpacking, byte-aligned; the program's is restored, the
  // font and GC freed and an open list closed, also when an allocation fails on the way.
  static constexpr GLenum kUnpack[] = {GL_UNPACK_SWAP_BYTES,  GL_UNPACK_LSB_FIRST,
                                       GL_UNPACK_ROW_LENGTH,  GL_UNPACK_SKIP_ROWS,
                                       GL_UNPACK_SKIP_PIXELS, GL_UNPACK_ALIGNMENT};
  struct Restore {
    Display* dpy;
    XFontStruct* fs;
    GC gc = nullptr;
    GLint saved[6] = {};
    GLint program_list = 0;  // a list the program is compiling (then glNewList fails here)
    ~Restore() {
      // A list of ours left open by a failure (also one inside glNewList or glEndList, which
      // catch it themselves) is closed, or the program's commands would go into it.
      GLint open_list = 0;
      glGetIntegerv(GL_LIST_INDEX, &open_list);
      if (open_list != program_list) glEndList();
      if (gc != nullptr) XFreeGC(dpy, gc);
      XFreeFontInfo(nullptr, fs, 1);
      for (int i = 0; i < 6; ++i) glPixelStorei(kUnpack[i], saved[i]);
    }
  } restore{dpy, fs};
  glGetIntegerv(GL_LIST_INDEX, &restore.program_list);
  for (int i = 0; i < 6; ++i) glGetIntegerv(kUnpack[i], &restore.saved[i]);
  for (int i = 0; i < 5; ++i) glPixelStorei(kUnpack[i], 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  const int screen = DefaultScreen(dpy);
  const Window root = RootWindow(dpy, screen);
  Pixmap scratch = XCreatePixmap(dpy, root, 8, 8, 1);
  XGCValues values{};
  values.font = fs->fid;
  GC gc = XCreateGC(dpy, scratch, GCFont, &values);
  restore.gc = gc;
  XFreePixmap(dpy, scratch);

  for (int i = 0; i < count; ++i) {
    const unsigned c = static_cast<unsigned>(first + i);
    const XCharStruct* ch = glyph_metrics(fs, c);
    const bool valid = ch != nullptr;
    if (!valid) ch = &fs->max_bounds;
    const int width = ch->rbearing - ch->lbearing;
    const int height = ch->ascent + ch->descent;
    const int row_bytes = (width + 7) / 8;
    glNewList(static_cast<GLuint>(list_base + i), GL_COMPILE);
    if (valid && row_bytes > 0 && height > 0) {
      const std::vector<GLubyte> bits =
          glyph_bitmap(dpy, root, gc, c, row_bytes, height, -ch->lbearing, ch->ascent);
      glBitmap(width, height, static_cast<GLfloat>(-ch->lbearing),
               static_cast<GLfloat>(ch->descent - 1), static_cast<GLfloat>(ch->width), 0,
               bits.data());
    } else {
      glBitmap(0, 0, 0, 0, static_cast<GLfloat>(ch->width), 0, nullptr);
    }
    glEndList();
  }
}

}  // namespace

// An allocation failure (a glyph's bitmap) is GL_OUT_OF_MEMORY, as in the GL commands it makes
// the lists with.
extern "C" GLPT_EXPORT void glXUseXFont(Font font, int first, int count, int list_base) {
  glpt::glx::gl_work_entry([&] { use_x_font(font, first, count, list_base); });
}
