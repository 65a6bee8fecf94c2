// Builds frame records by hand, the way the GL front end would record them, for tests and
// benchmarks of rt_core without the front end: current state blocks to edit, snapshots taken at
// each draw or clear, quads and triangle lists as draws.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "rt_core/record/frame_record.hpp"

namespace glpt::rt::test {

class RecordBuilder {
 public:
  RecordBuilder(uint32_t width, uint32_t height) {
    drawable.width = width;
    drawable.height = height;
    drawable.double_buffered = false;
    transform.viewport = {0, 0, static_cast<int32_t>(width), static_cast<int32_t>(height)};
    raster.ops.draw_buffer = raster.ops.read_buffer = GL_FRONT;
    raster.ops.scissor_box = transform.viewport;
  }

  // The state the next command records (edit freely between commands).
  rec::TransformState transform;
  rec::LightingState lighting;
  rec::TexturingState texturing;
  rec::RasterState raster;
  rec::PixelTransferState pixel_transfer;
  rec::DrawableConfig drawable;
  rec::FrameRecord record;

  // Lighting on with GL_LIGHT0 only, set to a directional light towards `towards_light`.
  void directional_light(int light, glm::vec3 towards_light, glm::vec4 diffuse = glm::vec4(1)) {
    lighting.enabled = true;
    lighting.light_mask |= static_cast<uint8_t>(1u << light);
    lighting.lights[light].position = glm::vec4(glm::normalize(towards_light), 0.0f);
    lighting.lights[light].diffuse = diffuse;
  }

  void clear(glm::vec4 color, uint32_t mask = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT) {
    rec::Clear c;
    c.state = snapshot();
    c.mask = mask;
    c.color = color;
    record.commands.push_back(c);
  }

  // A draw of `mode` with per-vertex positions (w = 1), one normal and one colour for all.
  void draw(uint32_t mode, const std::vector<glm::vec3>& positions, glm::vec3 normal,
            glm::vec4 color) {
    auto v = std::make_shared<rec::VertexData>();
    v->mode = mode;
    for (const glm::vec3& p : positions) v->position.push_back(glm::vec4(p, 1.0f));
    v->normal = {normal};
    v->color = {color};
    v->primitives.push_back({0, static_cast<uint32_t>(positions.size())});
    draw(std::move(v));
  }

  // A draw of prepared vertex data (its keys are hashed when a consumer asks).
  void draw(std::shared_ptr<rec::VertexData> v) {
    rec::Draw d;
    d.state = snapshot();
    d.vertices = std::move(v);
    record.commands.push_back(d);
  }

  // A parallelogram from `corner` spanned by u and v (counter-clockwise seen from cross(u, v)).
  void quad(glm::vec3 corner, glm::vec3 u, glm::vec3 v, glm::vec4 color,
            glm::vec3 normal = glm::vec3(0.0f)) {
    if (normal == glm::vec3(0.0f)) normal = glm::normalize(glm::cross(u, v));
    draw(GL_QUADS, {corner, corner + u, corner + u + v, corner + v}, normal, color);
  }

  // A new record with the same current state (the next frame).
  void next_frame() { record.clear(); }

 private:
  // A snapshot of the current blocks; blocks equal to the previous snapshot's are shared, as the
  // front end shares unchanged blocks.
  rec::StateId snapshot() {
    transform.modelview_projection = transform.projection * transform.modelview;
    transform.modelview_inverse = glm::inverse(transform.modelview);
    rec::StateSnapshot s;
    s.transform = share(transform, last_transform_);
    s.lighting = share(lighting, last_lighting_);
    s.texturing = share(texturing, last_texturing_);
    s.raster = share(raster, last_raster_);
    s.pixel_transfer = share(pixel_transfer, last_pixel_transfer_);
    record.states.push_back(s);
    return static_cast<rec::StateId>(record.states.size() - 1);
  }
  template <typename Block>
  static std::shared_ptr<const Block> share(const Block& current,
                                            std::shared_ptr<const Block>& last) {
    if (!last || !(*last == current)) last = std::make_shared<const Block>(current);
    return last;
  }
  std::shared_ptr<const rec::TransformState> last_transform_;
  std::shared_ptr<const rec::LightingState> last_lighting_;
  std::shared_ptr<const rec::TexturingState> last_texturing_;
  std::shared_ptr<const rec::RasterState> last_raster_;
  std::shared_ptr<const rec::PixelTransferState> last_pixel_transfer_;
};

}  // namespace glpt::rt::test
