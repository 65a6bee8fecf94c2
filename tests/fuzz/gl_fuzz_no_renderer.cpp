// The GL call fuzzer links the front end without rt_core's Vulkan renderer (compiling it with
// the sanitizers would cost minutes of CI, and rendering an input would cost far more than
// recording it). These definitions stand in for the renderer's entry points the front end
// references: no renderer can be created, so a context takes the clear-colour fallback
// (gl_call_fuzz.cpp marks it so from the start), and nothing else here is ever reached.
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "common/image_io.hpp"
#include "rt_core/render_settings.hpp"
#include "rt_core/renderer.hpp"
#include "rt_core/scene/classify.hpp"

namespace glpt {

bool write_png_rgba8(const std::string&, uint32_t, uint32_t, const uint8_t*, bool,
                     std::string* error) {
  if (error != nullptr) *error = "the GL fuzzer writes no PNG";
  return false;
}

namespace rt {

// Never constructed: its only member is a pointer to this.
class Renderer::Impl {};
struct DrawableBuffers {};

std::shared_ptr<DrawableBuffers> create_drawable_buffers() {
  return std::make_shared<DrawableBuffers>();
}
RenderSettings RenderSettings::from_environment() { return RenderSettings(); }
const char* draw_kind_name(DrawKind) { return "none"; }

std::unique_ptr<Renderer> Renderer::create(const RenderSettings&, std::string* error,
                                           std::string*) {
  if (error != nullptr) *error = "the GL fuzzer links no renderer";
  return nullptr;
}
Renderer::~Renderer() = default;
bool Renderer::execute(const rec::FrameRecord&, DrawableBuffers&, const rec::DrawableConfig&,
                       FrameStats&, std::string*, const FrameEnd*, std::vector<QuerySamples>*) {
  std::abort();
}
bool Renderer::read_color(DrawableBuffers&, uint32_t, int32_t, int32_t, uint32_t, uint32_t,
                          std::vector<uint8_t>&, std::string*) {
  std::abort();
}
bool Renderer::read_depth(DrawableBuffers&, int32_t, int32_t, uint32_t, uint32_t,
                          std::vector<float>&, std::string*) {
  std::abort();
}
bool Renderer::read_stencil(DrawableBuffers&, int32_t, int32_t, uint32_t, uint32_t,
                            std::vector<uint8_t>&, std::string*) {
  std::abort();
}
bool Renderer::write_color(DrawableBuffers&, const rec::DrawableConfig&,
                           const std::vector<uint8_t>&, std::string*) {
  std::abort();
}
bool Renderer::write_depth(DrawableBuffers&, const rec::DrawableConfig&, const std::vector<float>&,
                           std::string*) {
  std::abort();
}
bool Renderer::write_pixels(DrawableBuffers&, const rec::DrawableConfig&, const PixelWrite&,
                            std::string*) {
  std::abort();
}
void Renderer::start_independent_frame(uint64_t, uint32_t) { std::abort(); }
uint64_t Renderer::frame_ticket() const { std::abort(); }
void Renderer::wait_for_frame(uint64_t) const { std::abort(); }
bool process_exiting() { return false; }

}  // namespace rt
}  // namespace glpt
