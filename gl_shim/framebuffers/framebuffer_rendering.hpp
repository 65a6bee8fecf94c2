// Drawing into framebuffer objects (EXT_framebuffer_object; docs/framebuffer-objects-plan.md).
//
// A framebuffer object has a frame record of its own and a target of its attachments' size (a
// headless drawable: single-buffered, depth and stencil as attached). While it is bound, the
// context's recorder, snapshots, drawable configuration and draw and read buffers are the
// object's (swapped in by enter_framebuffer, out by leave_framebuffer), so every command records
// into it unchanged; the context's window stays ctx.target. Leaving renders what was recorded on
// the target and writes the colour (and a depth texture's depth) back into the attached texture
// images, as glCopyTexSubImage would without pixel transfer; entering (and the first draw after
// a texture command) loads the attached colour texture and a depth texture into the target when
// their contents changed since (or the target is new). One context at
// a time may have an object bound: its bundle is the object's (two contexts of a share group
// drawing into one object at once are not supported).
#pragma once

#include <cstdint>
#include <memory>

#include "common/stopwatch.hpp"
#include "gl_shim/frame/frame_recorder.hpp"
#include "gl_shim/frame/framebuffer_access.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/frame/state_snapshot.hpp"
#include "gl_shim/gl_types.h"
#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;
class TextureObject;
class WindowTarget;
struct FramebufferObject;

// What the context records into: its own while the window is bound, the object's while one is.
struct RecordingBundle {
  FrameRecorder recorder;
  StateSnapshotter snapshots;
  Stopwatch recording_since;
  rec::DrawableConfig drawable;  // what GL_DOUBLEBUFFER, GL_*_BITS report
  uint32_t draw_buffer = 0, read_buffer = 0;
};

struct FramebufferRendering {
  // The object's bundle while it is not bound; the window's while it is.
  RecordingBundle parked;
  std::unique_ptr<HeadlessTarget> target;  // null while the object is incomplete
  // A record was executed on the target since it was entered: its contents go to the textures.
  bool drawn = false;
  // The texture image the target's colour buffer holds and the texture's content version then.
  const TextureObject* loaded_texture = nullptr;
  GLenum loaded_target = 0;
  int loaded_level = -1;
  int loaded_zoffset = 0;
  // The same for the depth texture attachment's image in the target's depth buffer.
  const TextureObject* loaded_depth_texture = nullptr;
  uint64_t loaded_depth_version = 0;
  uint64_t loaded_version = 0;
};

// The object's rendering state, created (draw and read buffer GL_COLOR_ATTACHMENT0_EXT) when
// first needed.
FramebufferRendering& rendering_of(FramebufferObject& fb);

// After `fb` became the bound framebuffer object (ctx.framebuffers.framebuffer).
void enter_framebuffer(Context& ctx);
// Before the bound framebuffer object stops being bound (or its attachments change): renders
// what was recorded into it, writes the result back into its attached textures, and gives the
// context its window's bundle again.
void leave_framebuffer(Context& ctx);
// Its attachments changed while bound: leave and enter again (a new target size or image).
void refresh_framebuffer(Context& ctx);
// GL_NO_ERROR when drawing, clearing or reading may proceed: the window is bound, or a complete
// framebuffer object; else GL_INVALID_FRAMEBUFFER_OPERATION_EXT (which draws, clears and reads
// raise; glDrawPixels, glCopyPixels and glBitmap raise GL_INVALID_OPERATION instead, as Mesa).
// Completeness is judged again each time: an attached image defined, resized or redefined while
// the object is bound gives it a new target (what was drawn so far is written back first).
GLenum framebuffer_error(Context& ctx);
// Before a command reads or writes texture images while a framebuffer object is bound: what was
// drawn into it so far is rendered and written into its attached textures, so that a read sees
// it and a write is not overwritten by it later (the next draw loads what the write left).
void sync_framebuffer_textures(Context& ctx);
// Colour reads of the bound framebuffer object (glReadPixels, glCopyTex*Image, glCopyPixels) see
// what the read attachment stores, as Mesa's do: its format's components quantized to their
// bits, luminance and intensity in red, absent colour components 0 and absent alpha 1. The
// target holds 8-bit RGBA; `out` (read from it) is converted here. An attachment other than the
// drawn one is read from its texture (read_other_attachment returns true and fills `out`).
void show_stored_components(const Context& ctx, uint32_t read_buffer, FramebufferPixels& out);
bool read_other_attachment(Context& ctx, uint32_t read_buffer, int32_t x, int32_t y, uint32_t width,
                           uint32_t height, FramebufferPixels& out);
// What the context's record renders to: the bound framebuffer object's target, else the window.
WindowTarget* render_target(Context& ctx);

// EXT_framebuffer_blit's read framebuffer, for the commands that read pixels. While a scope
// lives, the context has entered its read framebuffer (that framebuffer's record, drawable, read
// buffer and completeness are the context's), so reads take their source from it; the scope's
// end enters the draw framebuffer again. Nothing happens when both bindings are one framebuffer
// (the usual case). Entering a framebuffer object renders what was drawn into the one left and
// writes it to its textures (reads are flush points anyway).
class ReadFramebufferScope {
 public:
  explicit ReadFramebufferScope(Context& ctx);
  ~ReadFramebufferScope();
  ReadFramebufferScope(const ReadFramebufferScope&) = delete;
  ReadFramebufferScope& operator=(const ReadFramebufferScope&) = delete;

 private:
  Context& ctx_;
  bool swapped_ = false;
  std::shared_ptr<FramebufferObject> draw_;
};

// The draw and read buffers of `fb` (null: the window) as its bundle holds them, wherever that
// bundle is now (the context's while entered, else parked).
struct FramebufferBuffers {
  uint32_t draw_buffer = 0, read_buffer = 0;
};
FramebufferBuffers buffers_of(const Context& ctx, const FramebufferObject* fb);
// The window's configuration (GLX visual or EGL config), wherever its bundle is now.
const rec::DrawableConfig& window_drawable(const Context& ctx);

// EXT_framebuffer_object: the width x height rectangle at the origin of the render target's front
// colour (or depth) buffer becomes the texels of `object`'s image at `texture_target` (a cube
// face for cube maps), `level` and `zoffset` (a 3-D texture's slice): no pixel transfer (drawing
// is not a copy).
// (gl_shim/textures/texture_image_commands.cpp)
void write_back_framebuffer_image(Context& ctx, TextureObject& object, GLenum texture_target,
                                  int level, int zoffset, uint32_t width, uint32_t height,
                                  bool depth);

}  // namespace glpt
