// Display-list support for commands that read client memory (GL 1.5 5.4): what the generated
// recording code (gen_gl_api.py, CLIENT_IMAGES and CUSTOM_ARRAY_COUNTS) calls.
#pragma once

#include <cstdint>
#include <vector>

#include "gl_shim/gl_types.h"
#include "gl_shim/pixels/pixel_layout.hpp"
#include "gl_shim/state/framebuffer_state.hpp"

namespace glpt {

class Context;

// A client image as a display list keeps it: the same format and type, laid out with the
// default unpack modes (DefaultUnpackModes), so the list never sees later changes to the client's
// memory or to its pixel store modes.
struct ClientImageCopy {
  // False when there is nothing to read: a null pointer, a format/type pair GL rejects (the
  // command reports the error when the list runs), or an image too large to copy. Replay then
  // passes a null pointer.
  bool present = false;
  std::vector<uint8_t> bytes;
};

ClientImageCopy copy_client_image(const PixelStoreModes& modes, const ImageShape& shape,
                                  bool three_d, const void* data);

// The unpack modes of a copied image (Mesa's display lists use the same): alignment 1, nothing
// skipped, no byte swapping, most significant bit first.
PixelStoreModes default_unpack_modes();

// While alive, the context unpacks with default_unpack_modes(); restores its own modes after.
class DefaultUnpackModes {
 public:
  explicit DefaultUnpackModes(Context& ctx);
  ~DefaultUnpackModes();
  DefaultUnpackModes(const DefaultUnpackModes&) = delete;
  DefaultUnpackModes& operator=(const DefaultUnpackModes&) = delete;

 private:
  Context& ctx_;
  PixelStoreModes saved_;
};

// How many values of glPixelMap{fv,uiv,usv} to record: `mapsize` when GL accepts it, else none
// (the command reports GL_INVALID_VALUE when the list runs).
uint32_t pixel_map_values_to_record(GLsizei mapsize);

// GL_PROXY_TEXTURE_*: glTexImage with a proxy target is executed at once, never compiled.
bool is_proxy_texture_target(GLenum target);

}  // namespace glpt
