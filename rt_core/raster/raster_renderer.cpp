#include "rt_core/raster/raster_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <unordered_set>

#include "common/stopwatch.hpp"
#include "raster_types.h"
#include "rt_core/raster/depth_clear.hpp"
#include "rt_core/raster/draw_merging.hpp"
#include "rt_core/raster/raster_recording.hpp"
#include "rt_core/raster/state_uniforms.hpp"
#include "rt_core/raster/vertex_streams.hpp"
#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

// Two keys set the same per-draw blend state (RasterPipelines::set_blend_state).
bool same_blend(const PipelineKey& a, const PipelineKey& b) {
  if (a.framebuffer_ops != b.framebuffer_ops) return false;
  // Blending in the shader: the pipeline's blend state is off and the same for every key.
  if (a.framebuffer_ops)
    return a.attachments == b.attachments && a.color_write_mask == b.color_write_mask;
  return a.gbuffer == b.gbuffer && a.attachments == b.attachments && a.blend == b.blend &&
         a.blend_src_rgb == b.blend_src_rgb && a.blend_dst_rgb == b.blend_dst_rgb &&
         a.blend_src_alpha == b.blend_src_alpha && a.blend_dst_alpha == b.blend_dst_alpha &&
         a.blend_op_rgb == b.blend_op_rgb && a.blend_op_alpha == b.blend_op_alpha &&
         a.logic_op_enable == b.logic_op_enable && a.logic_op == b.logic_op &&
         a.color_write_mask == b.color_write_mask;
}

constexpr uint32_t kRestartIndex = 0xFFFFFFFFu;

template <typename T>
T load_device_function(const VulkanDevice& device, const char* name) {
  auto f = reinterpret_cast<T>(vkGetDeviceProcAddr(device.handle(), name));
  if (f == nullptr) throw VulkanError(std::string("vkGetDeviceProcAddr(") + name + ") failed");
  return f;
}

bool finite_matrix(const glm::mat4& m) {
  return finite(m[0]) && finite(m[1]) && finite(m[2]) && finite(m[3]);
}

// Whether Mesa's triangles of `v` are its elements in order, three by three, all of them, with
// finite positions: then the draw's own indices (or ascending ones) serve as the index list.
bool in_vertex_order(const rec::VertexData& v, const std::vector<rec::DecomposedTriangle>& tris) {
  const bool indexed = !v.indices.empty();
  if (tris.empty() || (indexed ? v.indices.size() : v.vertex_count()) != 3 * tris.size())
    return false;
  for (size_t t = 0; t < tris.size(); ++t) {
    for (uint32_t k = 0; k < 3; ++k) {
      const size_t element = 3 * t + k;
      const uint32_t vertex = tris[t].v[k];
      if (vertex != (indexed ? v.indices[element] : element)) return false;
      if (!finite(v.position[vertex])) return false;
    }
  }
  return true;
}

// The depth-stencil buffer: how it is made and what the single-target render pass's
// framebuffers declare (the two must agree; kColorUsage likewise).
constexpr VkImageUsageFlags kDepthStencilUsage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                 VK_IMAGE_USAGE_TRANSFER_DST_BIT;

}  // namespace

RasterRenderer::RasterRenderer(std::shared_ptr<VulkanDevice> device)
    : device_(std::move(device)),
      pipelines_(*device_),
      textures_(*device_),
      descriptor_sets_(*device_, pipelines_.set_layout(), pipelines_.set_descriptor_counts()) {
  set_line_stipple_ =
      load_device_function<PFN_vkCmdSetLineStippleEXT>(*device_, "vkCmdSetLineStippleEXT");
  host_readable_color_ = GpuImage::linear_supported(*device_, kColorFormat, kColorUsage);
}

void RasterRenderer::ensure_buffers(DrawableBuffers& buffers, const rec::DrawableConfig& drawable) {
  buffers_ = &buffers;  // the buffers every helper of this call works on
  if (drawable == buffers.config && buffers.front && buffers.device == device_) return;
  device_->wait_all();  // pending submissions may still draw into the buffers replaced here
  buffers.host_reads->wait(VK_NULL_HANDLE);  // and a presenting thread read the front
  buffers.device = device_;
  buffers.config = drawable;
  buffers.front = GpuImage();
  buffers.back = GpuImage();
  buffers.depth_stencil = GpuImage();
  buffers.back_is_front = false;
  if (drawable.width == 0 || drawable.height == 0) return;
  GpuImageInfo color;
  color.format = kColorFormat;
  color.extent = {drawable.width, drawable.height, 1};
  color.usage = kColorUsage;
  color.host_readable = host_readable_color_;
  buffers.front = GpuImage::create(*device_, color);
  buffers.back = GpuImage::create(*device_, color);
  GpuImageInfo depth = color;
  depth.host_readable = false;
  depth.format = kDepthStencilFormat;
  depth.usage = kDepthStencilUsage;
  depth.aspect = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
  buffers.depth_stencil = GpuImage::create(*device_, depth);
  buffers.accum.resize(drawable.accum_bits > 0 ? drawable.width : 0,
                       drawable.accum_bits > 0 ? drawable.height : 0);
  // GL leaves a new drawable's contents undefined; glpt starts from transparent black, depth 1
  // and stencil 0, like a freshly cleared Mesa drawable. A drawable without alpha holds alpha 1
  // from the start and never writes it (GL 1.5 4.1.8: its alpha reads as 1).
  device_->submit_and_wait([&](VkCommandBuffer cmd) {
    const VkClearColorValue black{{0.0f, 0.0f, 0.0f, drawable.has_alpha ? 0.0f : 1.0f}};
    const VkImageSubresourceRange color_range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    for (const GpuImage* image : {&buffers.front, &buffers.back}) {
      image->initial_barrier(cmd);
      vkCmdClearColorImage(cmd, image->handle(), VK_IMAGE_LAYOUT_GENERAL, &black, 1, &color_range);
    }
    buffers.depth_stencil.initial_barrier(cmd);
    const VkClearDepthStencilValue far{1.0f, 0};
    const VkImageSubresourceRange ds_range{VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT,
                                           0, 1, 0, 1};
    vkCmdClearDepthStencilImage(cmd, buffers.depth_stencil.handle(), VK_IMAGE_LAYOUT_GENERAL, &far,
                                1, &ds_range);
  });
}

void RasterRenderer::execute(const rec::FrameRecord& record, DrawableBuffers& buffers,
                             const rec::DrawableConfig& drawable, FrameStats& stats,
                             const std::vector<size_t>* commands, const FrameEnd* end,
                             const GBufferTargets* gbuffer, std::vector<QuerySamples>* queries,
                             const std::vector<uint8_t>* split_by_alpha) {
  const Stopwatch timer;
  ++frame_;
  ensure_buffers(buffers, drawable);
  std::vector<size_t> all;
  if (commands == nullptr) {
    all.resize(record.commands.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = i;
    commands = &all;
  }
  // A presenting thread may still be copying an earlier frame out of a colour image: the back
  // is drawn into by any execute, the front only by front-buffer drawing.
  wait_for_host_reads(may_write_front(record, *commands));
  queries_.begin_record(record, buffers_->front ? *commands : std::vector<size_t>{});
  if (!buffers_->front) {
    if (end && end->front_rgba) end->front_rgba->clear();
    if (queries) queries_.collect(*queries);  // nothing drawn: no samples
    return;
  }

  // ---- per-record data: state uniforms, textures, vertices and indices, into the upload set the
  // previous execute did not use (its submissions may still be reading theirs)
  std::swap(states_, spare_uploads_.states);
  std::swap(vertices_, spare_uploads_.vertices);
  std::swap(pixels_, spare_uploads_.pixels);
  std::swap(uploads_ticket_, spare_uploads_.ticket);
  device_->wait(uploads_ticket_);
  const size_t state_count = record.states.size();
  size_t quad_clears = 0;
  for (size_t i : *commands)
    if (std::holds_alternative<rec::Clear>(record.commands[i])) ++quad_clears;
  const size_t pixel_states = begin_pixel_commands(record, *commands);
  std::vector<gpu::RasterState> states(state_count + quad_clears + pixel_states + 1);
  // Only the states this execute's commands use (path-traced mode's pass after the trace draws a
  // few overlays of a record of thousands of states).
  std::vector<uint8_t> used(state_count, commands->size() == record.commands.size() ? 1 : 0);
  if (commands->size() != record.commands.size())
    for (size_t i : *commands)
      std::visit(
          [&](const auto& command) {
            if constexpr (requires { command.state; })
              if (command.state < state_count) used[command.state] = 1;
          },
          record.commands[i]);
  for (size_t i = 0; i < state_count; ++i) {
    if (!used[i]) continue;
    pack_state_uniforms(record.states[i], states[i]);
    states[i].drawable = glm::uvec4(drawable.width, drawable.height, 0, 0);
  }

  std::vector<const rec::TextureObjectSnapshot*> textures;
  for (const rec::StateSnapshot& s : record.states)
    for (const rec::TextureUnitState& unit : s.texturing->units)
      if (unit.target != 0 && unit.texture) textures.push_back(unit.texture.get());
  stats.upload_bytes += textures_.prepare(textures, frame_);

  descriptor_sets_.reclaim();
  Recording r;
  r.record = &record;
  r.stats = &stats;
  r.gbuffer = gbuffer;
  r.split_by_alpha = split_by_alpha;
  r.geometry.resize(record.commands.size());
  r.clear_state.assign(record.commands.size(), 0);
  r.pixels.resize(record.commands.size());
  Arena arena(upload_);
  // Attributes a draw lacks read one default value (stride 0): GL's initial current values.
  const glm::vec4 defaults[] = {glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 1, 0), glm::vec4(1.0f),
                                glm::vec4(0, 0, 0, 1), glm::vec4(0.0f)};
  const VkDeviceSize default_offset = arena.add(defaults, std::size(defaults));
  // Clears drawn as a quad: one triangle covering the viewport, in clip space.
  const glm::vec4 clear_triangle[] = {glm::vec4(-1, -1, 0, 1), glm::vec4(3, -1, 0, 1),
                                      glm::vec4(-1, 3, 0, 1)};
  const uint32_t clear_indices[] = {0, 1, 2};
  r.clear_geometry.offsets.fill(default_offset);
  r.clear_geometry.offsets[GLPT_RASTER_ATTR_POSITION] = arena.add(clear_triangle, 3);
  r.clear_geometry.strides[GLPT_RASTER_ATTR_POSITION] = sizeof(glm::vec4);
  r.clear_geometry.index_offset = arena.add(clear_indices, 3);
  r.clear_geometry.index_count = 3;
  // The small draws' vertices go into shared streams (vertex_streams.hpp): sized first.
  VertexStreams streams;
  r.streamed.assign(record.commands.size(), 0);
  for (size_t i : *commands)
    if (const auto* draw = std::get_if<rec::Draw>(&record.commands[i]);
        draw != nullptr && draw->vertices && VertexStreams::takes(*draw->vertices)) {
      streams.count(*draw->vertices);
      r.streamed[i] = 1;
    }
  if (!streams.reserve(arena)) r.streamed.assign(record.commands.size(), 0);
  const auto* default_bytes = reinterpret_cast<const uint8_t*>(defaults);
  std::vector<uint32_t>& indices = indices_;
  std::vector<uint8_t>& edge_masks = edge_masks_;
  std::vector<gpu::RasterMaterial> materials;
  size_t next_clear_state = state_count;
  for (size_t position = 0; position < commands->size(); ++position) {
    const size_t i = (*commands)[position];
    const rec::Command& command = record.commands[i];
    if (const auto* clear = std::get_if<rec::Clear>(&command)) {
      gpu::RasterState& s = states[next_clear_state];
      s = states[clear->state];
      s.mvp = glm::mat4(1.0f);
      s.clear_color = glm::clamp(clear->color, 0.0f, 1.0f);
      r.clear_state[i] = static_cast<uint32_t>(next_clear_state++);
      continue;
    }
    if (prepare_pixels(r, i, arena, states, next_clear_state)) continue;
    const auto* draw = std::get_if<rec::Draw>(&command);
    if (draw == nullptr || !draw->vertices) continue;
    if (gbuffer == nullptr && r.streamed[i]) {
      const size_t merged =
          merge_draws(r, *commands, position, arena, streams, default_bytes, default_offset);
      if (merged > 0) {
        position += merged - 1;
        continue;
      }
    }
    const rec::VertexData& v = *draw->vertices;
    DrawGeometry& g = r.geometry[i];
    ResidentGeometry::Entry* resident = resident_.use(*device_, v, frame_);
    if (resident != nullptr) ++stats.resident_draws;
    // (Streamed draws are below ResidentGeometry::kMinBytes: never resident.)
    if (r.streamed[i] && streams.fits(v.vertex_count())) {
      g.vertex_offset = streams.add(v, arena, default_bytes);
      streams.locate(default_offset, g.offsets, g.strides);
    } else {
      for_each_attribute(v, [&](uint32_t location, const auto& values, VkDeviceSize default_at) {
        using T = typename std::decay_t<decltype(values)>::value_type;
        if (values.empty()) {
          g.offsets[location] = default_offset + default_at;
          g.strides[location] = 0;
          return;
        }
        if (resident != nullptr) {
          g.buffers[location] = resident->buffer.handle();
          g.offsets[location] = resident->offsets[location];
        } else {
          g.offsets[location] = arena.add_external(values.data(), values.size());
        }
        g.strides[location] = values.size() == 1 ? 0 : sizeof(T);
      });
    }
    // The draw's own indices, wherever its attributes are.
    auto own_indices = [&] {
      if (resident != nullptr) {
        g.index_buffer = resident->buffer.handle();
        g.index_offset = resident->index_offset;
      } else {
        g.index_offset = arena.add_external(v.indices.data(), v.indices.size());
      }
    };
    // Materials given between glBegin and glEnd: front and back per vertex (or one pair).
    if (v.material.size() == 1 || (!v.material.empty() && v.material.size() == v.vertex_count())) {
      materials.clear();
      for (const auto& pair : v.material)
        materials.insert(materials.end(), {pack_material(pair[0]), pack_material(pair[1])});
      const uint32_t per_vertex = v.material.size() == 1 ? 0u : 2u * GLPT_RASTER_MATERIAL_VEC4S;
      g.materials = glm::uvec4(arena.add(materials.data(), materials.size()) / sizeof(glm::vec4),
                               per_vertex, 1u, 0u);
    }

    // Indices in GL's assembly order. Primitives with a non-finite vertex are dropped (GL
    // accepts such vertices; what they draw is undefined, and glpt draws nothing).
    indices.clear();
    const rec::PrimitiveClass cls = rec::primitive_class(v.mode);
    auto ok = [&](uint32_t vertex) { return finite(v.position[vertex]); };
    const rec::StateSnapshot& state = record.states[draw->state];
    if (!finite_matrix(state.transform->modelview_projection)) ++stats.non_finite_draws;
    // Strips stay strips (one stipple pattern along each) unless Mesa draws them segment by
    // segment (display lists).
    if (cls == rec::PrimitiveClass::kLines && v.mode != GL_LINES &&
        !rec::mesa_draws_strips_as_lines(v)) {
      g.topology = RasterTopology::kLineStrip;
      for (const rec::PrimitiveRange& range : v.primitives) {
        if (range.count < 2) continue;
        const bool indexed = !v.indices.empty();
        if (uint64_t{range.first} + range.count > (indexed ? v.indices.size() : v.vertex_count()))
          continue;
        auto element = [&](uint32_t k) {
          return indexed ? v.indices[range.first + k] : range.first + k;
        };
        bool good = true;
        for (uint32_t k = 0; k < range.count; ++k)
          good = good && element(k) < v.vertex_count() && ok(element(k));
        if (!good) {
          ++stats.non_finite_primitives;
          continue;
        }
        if (!indices.empty()) indices.push_back(kRestartIndex);
        for (uint32_t k = 0; k < range.count; ++k) indices.push_back(element(k));
        if (v.mode == GL_LINE_LOOP) indices.push_back(element(0));
      }
    } else {
      const rec::AssemblyState assembly = rec::assembly_state(state, v);
      const rec::PrimitiveState& p = state.raster->primitive;
      const bool unfilled = p.polygon_mode_front != GL_FILL || p.polygon_mode_back != GL_FILL;
      // Triangles drawn in the draw's own order: its indices as they are, or ascending ones (no
      // index list is made and uploaded per draw; lavapipe still draws indexed, as every other
      // draw).
      auto own_order = [&](uint32_t index_count) {
        g.topology = RasterTopology::kTriangles;
        g.index_count = index_count;
        if (v.indices.empty()) {
          g.ascending_indices = true;
          ensure_ascending_indices(g.index_count);
        } else {
          own_indices();
        }
      };
      // Known from an earlier record (resident geometry).
      uint32_t known_count = 0;
      if (cls == rec::PrimitiveClass::kTriangles && !unfilled && resident != nullptr &&
          resident->in_vertex_order(assembly, &known_count)) {
        own_order(known_count);
        continue;
      }
      // The common case told without decomposing: a triangle list in element order.
      if (cls == rec::PrimitiveClass::kTriangles && !unfilled &&
          rec::triangles_in_element_order(v, assembly) &&
          std::all_of(v.position.begin(), v.position.end(),
                      [](const glm::vec4& p) { return finite(p); })) {
        const uint32_t count = static_cast<uint32_t>(v.primitives[0].count);
        if (resident != nullptr) resident->found_in_vertex_order(count, false, assembly);
        own_order(count);
        continue;
      }
      decomposed_.clear();
      // Mesa's exact triangles and vertex order (decompose.hpp): they decide interpolation and
      // edge ties.
      rec::decompose(v, assembly, decomposed_);
      if (cls == rec::PrimitiveClass::kPoints) {
        g.topology = RasterTopology::kPoints;
        for (uint32_t p : decomposed_.points) {
          if (ok(p))
            indices.push_back(p);
          else
            ++stats.non_finite_primitives;
        }
      } else if (cls == rec::PrimitiveClass::kLines) {
        g.topology = RasterTopology::kLines;
        for (const auto& l : decomposed_.lines) {
          if (ok(l.v[0]) && ok(l.v[1]))
            indices.insert(indices.end(), {l.v[0], l.v[1]});
          else
            ++stats.non_finite_primitives;
        }
      } else {
        g.topology = RasterTopology::kTriangles;
        if (!unfilled && in_vertex_order(v, decomposed_.triangles)) {
          const auto count = static_cast<uint32_t>(3 * decomposed_.triangles.size());
          if (resident != nullptr)
            resident->found_in_vertex_order(count, decomposed_.assembly_consulted, assembly);
          own_order(count);
          continue;
        }
        edge_masks.clear();
        for (const auto& t : decomposed_.triangles) {
          if (!ok(t.v[0]) || !ok(t.v[1]) || !ok(t.v[2])) {
            ++stats.non_finite_primitives;
            continue;
          }
          indices.insert(indices.end(), {t.v[0], t.v[1], t.v[2]});
          edge_masks.push_back(t.boundary_edges);
        }
        // The geometry shader of unfilled polygons reads each triangle's boundary edges.
        if (unfilled) {
          edge_masks.resize((edge_masks.size() + 3) & ~size_t{3}, 0);
          g.edge_offset = arena.add(edge_masks.data(), edge_masks.size());
        }
      }
    }
    g.index_offset = arena.add(indices.data(), indices.size());
    g.index_count = static_cast<uint32_t>(indices.size());
  }

  const size_t states_bytes = states.size() * sizeof(gpu::RasterState);
  ensure_capacity(*device_, states_, states_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  states_.write(states.data(), states_bytes);
  ensure_capacity(*device_, vertices_, arena.size(),
                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  arena.write_to(static_cast<uint8_t*>(vertices_.mapped()));
  upload_pixels();
  stats.upload_bytes += states_bytes + arena.size() + pixel_words_.size() * sizeof(uint32_t) +
                        resident_.take_uploaded_bytes();
  stats.upload_ms += timer.elapsed_ms();

  present_ = end && end->present_to ? imported_host_image(*end->present_to) : nullptr;
  if (end && (end->front_rgba || (end->present_to && !present_)))
    ensure_capacity(*device_, readback_,
                    size_t{buffers_->config.width} * buffers_->config.height * 4,
                    VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);

  // ---- record and run: one submission, or one more after each glAccum that reads or writes
  // colour (the accumulation buffer is updated on the CPU, as Mesa does); the frame end goes with
  // the last. Nothing waits for the device unless the host reads what it produced (the
  // accumulation buffer, query results, read-back pixels): the renderer waits at the frame's end.
  // After a swap exchanged the colour images, the back takes the front's pixels first unless
  // the record starts by clearing all of it (most frames: glClear, then draws).
  // The upside-down copy of a colour buffer (mesa_orientation.cpp) is made in the submission
  // that needs it; one of another drawable's size goes first, once what may use it completed.
  if (mesa_image_ && (mesa_image_.info().extent.width != buffers_->config.width ||
                      mesa_image_.info().extent.height != buffers_->config.height)) {
    device_->wait_all();
    mesa_image_ = GpuImage();
  }
  const bool restore_back_first =
      buffers_->back_is_front && !begins_with_whole_back_clear(record, *commands);
  if (!restore_back_first) buffers_->back_is_front = false;  // the first clear replaces it
  size_t position = 0;
  VulkanDevice::Ticket ticket = 0;
  do {
    ticket = device_->submit([&](VkCommandBuffer cmd) {
      if (position == 0 && restore_back_first) record_restore_back(cmd);
      r.cmd = cmd;
      r.rendering = false;
      r.mesa_target = ColorTargets::kNone;
      r.bound_pipeline = VK_NULL_HANDLE;
      r.descriptors_pushed = false;
      r.written_sets.clear();  // an earlier submission's sets may be reused by now
      r.dynamic_valid = false;
      r.blend_valid = false;
      r.geometry_bound = false;
      r.push_valid = false;
      r.state_index_valid = false;
      if (position == 0) queries_.reset_slots(cmd);
      if (gbuffer && position == 0) {
        // Nothing is traced where no traced draw lands: the SURFACE attachment starts at 0.
        const VkClearColorValue zero{};
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cmd, gbuffer->images[GLPT_GBUFFER_SURFACE], VK_IMAGE_LAYOUT_GENERAL,
                             &zero, 1, &range);
        auto barrier = make_info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.dstAccessMask =
            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0, 1, &barrier, 0,
                             nullptr, 0, nullptr);
      }
      for (; position < commands->size(); ++position) {
        const size_t i = (*commands)[position];
        const rec::Command& command = record.commands[i];
        r.counting = queries_.query_of(i);
        if (r.counting == 0) queries_.stop(cmd);  // nothing else counts (clears in particular)
        // Only draws go to a colour buffer upside down (record_draw_pass decides each).
        if (!std::holds_alternative<rec::Draw>(command))
          use_mesa_orientation(r, ColorTargets::kNone);
        if (const auto* clear = std::get_if<rec::Clear>(&command)) {
          record_clear(r, *clear, r.clear_state[i]);
        } else if (const auto* draw = std::get_if<rec::Draw>(&command)) {
          const bool to_gbuffer = gbuffer && gbuffer->traced && i < gbuffer->traced->size() &&
                                  (*gbuffer->traced)[i] != 0;
          const uint32_t part = !r.split(i)  ? 0u
                                : to_gbuffer ? GLPT_FS_OPAQUE_PART
                                             : GLPT_FS_TRANSLUCENT_PART;
          record_draw(r, *draw, r.geometry[i], to_gbuffer, part);
        } else if (const auto* accum = std::get_if<rec::Accum>(&command)) {
          if (accumulation_touches_color(*accum)) break;
          execute_accum(record, *accum);
        } else if (!std::holds_alternative<rec::Read>(command) &&
                   !std::holds_alternative<rec::BeginQuery>(command) &&
                   !std::holds_alternative<rec::EndQuery>(command)) {
          record_pixels(r, i);
        }
      }
      use_mesa_orientation(r, ColorTargets::kNone);
      end_rendering(r);
      if (end && position == commands->size()) record_frame_end(cmd, *end);
    });
    descriptor_sets_.retire(ticket);
    unreported_.push_back(ticket);
    if (position < commands->size()) {
      device_->wait(ticket);
      execute_accum(record, std::get<rec::Accum>(record.commands[(*commands)[position++]]));
    }
  } while (position < commands->size());
  uploads_ticket_ = ticket;
  // The host reads query results only where a draw counted into a query (the shim always asks
  // for them), and the frame's pixels only where it copies them itself.
  // A frame presented later (FrameEnd::present_later) reaches the window's imported memory
  // inside the submission: the caller waits for it before showing it.
  if ((queries && queries_.counted_any()) ||
      (end && (end->front_rgba || (end->present_to && !(end->present_later && present_)))))
    device_->wait(ticket);
  if (queries) queries_.collect(*queries);
  const size_t pixel_count = size_t{buffers_->config.width} * buffers_->config.height;
  if (end && end->front_rgba) {
    end->front_rgba->resize(pixel_count * 4);
    std::memcpy(end->front_rgba->data(), readback_.mapped(), pixel_count * 4);
    swap_red_and_blue(end->front_rgba->data(), pixel_count);
  }
  // Without an imported buffer the window's memory is filled here, rows flipped.
  if (end && end->present_to && !present_ && end->present_to->width == buffers_->config.width &&
      end->present_to->height == buffers_->config.height) {
    const size_t row = size_t{buffers_->config.width} * 4;
    const auto* src = static_cast<const uint8_t*>(readback_.mapped());
    for (uint32_t y = 0; y < buffers_->config.height; ++y) {
      const uint32_t to = end->present_bottom_up ? y : buffers_->config.height - 1 - y;
      std::memcpy(end->present_to->pixels + to * row, src + y * row, row);
    }
  }
}

void RasterRenderer::end_frame(FrameStats& stats) {
  // The frame's submissions have completed (the caller waited), or, for a frame presented
  // later, those of the execute before the previous one (execute waits for them before reusing
  // their upload set). What is released here was last used before that: geometry after
  // ResidentGeometry::kKeepExecutes executes, textures after TextureCache's frames (the previous
  // execute's are kept).
  for (VulkanDevice::Ticket ticket : unreported_)
    stats.raster_ms += device_->take_device_ms(ticket);
  unreported_.clear();
  textures_.evict_unused(frame_);
  resident_.release_unused(frame_);
}

GpuBuffer* RasterRenderer::imported_host_image(const HostImage& image) {
  auto it = std::find_if(imported_.begin(), imported_.end(), [&](const ImportedHostImage& i) {
    return i.generation == image.generation;
  });
  if (it == imported_.end()) {
    // A share group's renderer presents to each of its contexts' windows (two segments each,
    // X11WindowTarget): those of a few windows are kept.
    constexpr size_t kMaxImported = 8;
    if (imported_.size() >= kMaxImported) {
      device_->wait_all();  // a frame presented later may still copy into the oldest
      imported_.erase(imported_.begin());
    }
    const VkDeviceSize alignment = device_->host_pointer_alignment();
    const size_t bytes =
        (size_t{image.width} * image.height * 4 + alignment - 1) & ~(alignment - 1);
    imported_.push_back(
        {image.generation,
         GpuBuffer::import_host(*device_, image.pixels, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT)});
  } else {
    std::rotate(it, it + 1, imported_.end());  // the most recently used last
  }
  GpuBuffer& buffer = imported_.back().buffer;
  return buffer ? &buffer : nullptr;
}

bool RasterRenderer::shader_blends(const PipelineKey& key) {
  // Blending in the shader costs no compile but each blended pixel reads the colour buffer and
  // blends in shader arithmetic (3-4x llvmpipe's own blending per pixel, docs/performance.md);
  // the pipeline's blending is fast per pixel but llvmpipe compiles a fragment shader variant
  // for each new blend state. So a state blends in the shader in the first records that use it
  // (a program walking through many states, each drawn once or twice, never compiles one) and
  // in the pipeline from then on (a program's steady states are fast once compiled).
  constexpr uint32_t kShaderBlendRecords = 4;
  constexpr size_t kTrackedStates = 16384;  // beyond: forgotten, so new again (correct either way)
  const uint64_t state = uint64_t{key.blend_src_rgb} | uint64_t{key.blend_dst_rgb} << 8 |
                         uint64_t{key.blend_src_alpha} << 16 | uint64_t{key.blend_dst_alpha} << 24 |
                         uint64_t{key.blend_op_rgb} << 32 | uint64_t{key.blend_op_alpha} << 40 |
                         uint64_t{key.logic_op} << 48 | uint64_t{key.logic_op_enable} << 56 |
                         uint64_t{key.blend} << 57;
  if (blend_state_uses_.size() >= kTrackedStates && !blend_state_uses_.count(state))
    blend_state_uses_.clear();
  BlendStateUse& use = blend_state_uses_[state];
  if (use.records == 0 || use.last_record != frame_) {
    ++use.records;
    use.last_record = frame_;
  }
  return use.records <= kShaderBlendRecords;
}

VkFramebuffer RasterRenderer::single_target_framebuffer(uint32_t width, uint32_t height) {
  for (const SizedFramebuffer& f : framebuffers_)
    if (f.width == width && f.height == height) return f.framebuffer.get();
  // Imageless: the views come with each vkCmdBeginRenderPass, so one framebuffer per size
  // serves the front and the back buffer of every drawable of that size.
  std::array<VkFramebufferAttachmentImageInfo, 2> images{};
  const VkFormat color_format = kColorFormat, depth_format = kDepthStencilFormat;
  for (VkFramebufferAttachmentImageInfo& image : images) {
    image = make_info<VkFramebufferAttachmentImageInfo>(
        VK_STRUCTURE_TYPE_FRAMEBUFFER_ATTACHMENT_IMAGE_INFO);
    image.width = width;
    image.height = height;
    image.layerCount = 1;
    image.viewFormatCount = 1;
  }
  images[0].usage = kColorUsage;
  images[0].pViewFormats = &color_format;
  images[1].usage = kDepthStencilUsage;
  images[1].pViewFormats = &depth_format;
  auto attachments = make_info<VkFramebufferAttachmentsCreateInfo>(
      VK_STRUCTURE_TYPE_FRAMEBUFFER_ATTACHMENTS_CREATE_INFO);
  attachments.attachmentImageInfoCount = static_cast<uint32_t>(images.size());
  attachments.pAttachmentImageInfos = images.data();
  auto info =
      make_info<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO, &attachments);
  info.flags = VK_FRAMEBUFFER_CREATE_IMAGELESS_BIT;
  info.renderPass = pipelines_.render_pass();
  info.attachmentCount = static_cast<uint32_t>(images.size());
  info.width = width;
  info.height = height;
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateFramebuffer(device_->handle(), &info, nullptr, &framebuffer));
  // A few sizes are kept (a share group's windows, a resize). Submitted frames may still use
  // the oldest, so it goes once they completed; the recording under way is of this size.
  constexpr size_t kMaxFramebuffers = 4;
  if (framebuffers_.size() >= kMaxFramebuffers) {
    device_->wait_all();
    framebuffers_.erase(framebuffers_.begin());
  }
  framebuffers_.push_back({width, height, vk::Framebuffer(framebuffer, {device_->handle()})});
  return framebuffer;
}

void RasterRenderer::begin_rendering(Recording& r, ColorTargets targets, RenderingKind kind) {
  // GL_NONE still writes depth and stencil: render to the back (or front) buffer with a colour
  // write mask of zero (the pipeline key has it).
  if (targets == ColorTargets::kNone)
    targets = buffers_->config.double_buffered ? ColorTargets::kBack : ColorTargets::kFront;
  if (r.rendering && r.targets == targets &&
      (kind == RenderingKind::kAny || r.in_render_pass == (kind == RenderingKind::kRenderPass)))
    return;
  end_rendering(r);
  if (kind == RenderingKind::kRenderPass) {
    // A draw blending in the shader: the render pass whose colour attachment the fragment shader
    // reads (RasterPipelines::render_pass; only keys with framebuffer_ops, one colour target).
    const std::array<VkImageView, 2> views{
        color_view(r, targets == ColorTargets::kFront ? ColorTargets::kFront : ColorTargets::kBack),
        buffers_->depth_stencil.view()};
    auto attachments = make_info<VkRenderPassAttachmentBeginInfo>(
        VK_STRUCTURE_TYPE_RENDER_PASS_ATTACHMENT_BEGIN_INFO);
    attachments.attachmentCount = static_cast<uint32_t>(views.size());
    attachments.pAttachments = views.data();
    auto info =
        make_info<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO, &attachments);
    info.renderPass = pipelines_.render_pass();
    info.framebuffer = single_target_framebuffer(buffers_->config.width, buffers_->config.height);
    info.renderArea = {{0, 0}, {buffers_->config.width, buffers_->config.height}};
    vkCmdBeginRenderPass(r.cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
    r.rendering = true;
    r.in_render_pass = true;
    r.targets = targets;
    r.bound_pipeline = VK_NULL_HANDLE;
    return;
  }
  std::array<VkRenderingAttachmentInfo, GLPT_GBUFFER_ATTACHMENTS> colors{};
  uint32_t count = 0;
  auto add_color = [&](VkImageView view) {
    VkRenderingAttachmentInfo& a = colors[count++];
    a = make_info<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    a.imageView = view;
    a.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
    a.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  };
  if (targets == ColorTargets::kFront || targets == ColorTargets::kFrontAndBack)
    add_color(color_view(r, ColorTargets::kFront));
  if (targets == ColorTargets::kBack || targets == ColorTargets::kFrontAndBack)
    add_color(color_view(r, ColorTargets::kBack));
  if (targets == ColorTargets::kGBuffer)
    for (VkImageView view : r.gbuffer->views) add_color(view);
  auto depth = make_info<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  depth.imageView = buffers_->depth_stencil.view();
  depth.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  auto info = make_info<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  info.renderArea = {{0, 0}, {buffers_->config.width, buffers_->config.height}};
  info.layerCount = 1;
  info.colorAttachmentCount = count;
  info.pColorAttachments = colors.data();
  info.pDepthAttachment = &depth;
  info.pStencilAttachment = &depth;
  vkCmdBeginRendering(r.cmd, &info);
  r.rendering = true;
  r.targets = targets;
  r.bound_pipeline = VK_NULL_HANDLE;
}

void RasterRenderer::end_rendering(Recording& r) {
  if (!r.rendering) return;
  queries_.stop(r.cmd);  // a Vulkan query ends inside the rendering instance it began in
  if (r.in_render_pass)
    vkCmdEndRenderPass(r.cmd);
  else
    vkCmdEndRendering(r.cmd);
  r.rendering = false;
  r.in_render_pass = false;
}

void RasterRenderer::bind(Recording& r, const PipelineKey& key,
                          const rec::StateSnapshot* textures_of) {
  bool created = false;
  VkPipeline pipeline = pipelines_.get(key, &created);
  if (created) ++r.stats->pipelines_created;
  if (pipeline != r.bound_pipeline) {
    vkCmdBindPipeline(r.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    r.bound_pipeline = pipeline;
    // Pushed again after a pipeline change: lavapipe hands push constants to the stages bound
    // when they are pushed, so a geometry shader bound later read none (polygon mode
    // GL_FILL front, GL_POINT back: the back faces' points were lost).
    r.push_valid = false;
    r.state_index_valid = false;
  }
  if (pipelines_.blend_is_dynamic() && (!r.blend_valid || !same_blend(key, r.blend_key))) {
    pipelines_.set_blend_state(r.cmd, key);
    r.blend_key = key;
    r.blend_valid = true;
  }
  // Descriptors: the states buffer and, per unit, the texture of the unit's target (every other
  // binding holds a dummy). Pushed only when they change.
  std::array<VkImageView, 4 * GLPT_RASTER_MAX_UNITS> views{};
  std::array<VkSampler, 4 * GLPT_RASTER_MAX_UNITS> samplers{};
  for (uint32_t b = 0; b < views.size(); ++b) {
    views[b] = textures_.dummy_view(b % 4);
    samplers[b] = textures_.dummy_sampler();
  }
  if (textures_of != nullptr) {
    for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
      const rec::TextureUnitState& unit = textures_of->texturing->units[u];
      if (unit.target == 0 || !unit.texture) continue;
      const uint32_t kind = unit.target == GL_TEXTURE_1D         ? GLPT_RASTER_TEXTURE_1D
                            : unit.target == GL_TEXTURE_3D       ? GLPT_RASTER_TEXTURE_3D
                            : unit.target == GL_TEXTURE_CUBE_MAP ? GLPT_RASTER_TEXTURE_CUBE
                                                                 : GLPT_RASTER_TEXTURE_2D;
      if (VkImageView view = textures_.view(*unit.texture)) {
        views[u * 4 + kind] = view;
        samplers[u * 4 + kind] = textures_.sampler(*unit.texture, unit.env.lod_bias);
      }
    }
  }
  // The colour buffer a fragment shader that blends reads: the render pass's target (any colour
  // buffer elsewhere: no pipeline outside the render pass reads it).
  const VkImageView framebuffer =
      !pipelines_.blends_in_shader()
          ? VK_NULL_HANDLE
          : color_view(
                r, r.targets == ColorTargets::kFront ? ColorTargets::kFront : ColorTargets::kBack);
  if (r.descriptors_pushed && views == r.bound_views && samplers == r.bound_samplers &&
      framebuffer == r.bound_framebuffer)
    return;
  r.bound_views = views;
  r.bound_samplers = samplers;
  r.bound_framebuffer = framebuffer;
  r.descriptors_pushed = true;
  for (const Recording::WrittenSet& written : r.written_sets) {
    if (written.views != views || written.samplers != samplers ||
        written.framebuffer != framebuffer)
      continue;
    vkCmdBindDescriptorSets(r.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout(), 0, 1,
                            &written.set, 0, nullptr);
    return;
  }
  std::array<VkDescriptorImageInfo, 4 * GLPT_RASTER_MAX_UNITS> images{};
  std::array<VkWriteDescriptorSet, 3 + 4 * GLPT_RASTER_MAX_UNITS> writes{};
  VkDescriptorBufferInfo states{states_.handle(), 0, VK_WHOLE_SIZE};
  writes[0] = make_info<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  writes[0].dstBinding = GLPT_RASTER_BINDING_STATES;
  writes[0].descriptorCount = 1;
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  writes[0].pBufferInfo = &states;
  // The shaders read edge flags and per-vertex materials through this binding, not the
  // positions: the binding may not exceed maxStorageBufferRange (lavapipe: 128 MiB) even when a
  // frame's vertices do (a million triangles: 144 MB). Edge-flag and material words placed past
  // the limit in such a frame are out of the binding's reach and are not drawn right (known
  // limitation; the million-triangle extreme has neither).
  const VkDeviceSize edge_range =
      std::min<VkDeviceSize>(vertices_.size(), device_->limits().maxStorageBufferRange);
  VkDescriptorBufferInfo edges{vertices_.handle(), 0, edge_range};
  writes[1] = writes[0];
  writes[1].dstBinding = GLPT_RASTER_BINDING_EDGES;
  writes[1].pBufferInfo = &edges;
  const VkDescriptorSet set = descriptor_sets_.acquire();
  for (VkWriteDescriptorSet& w : writes) w.dstSet = set;  // (the loop below sets its own)
  for (uint32_t b = 0; b < images.size(); ++b) {
    images[b] = {samplers[b], views[b], VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet& w = writes[2 + b];
    w = make_info<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w.dstSet = set;
    w.dstBinding = GLPT_RASTER_BINDING_TEXTURES + b;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &images[b];
  }
  // The pixel rectangles' images (pixel_commands.cpp); the buffer always exists.
  VkDescriptorBufferInfo pixels{pixels_.handle(), 0, VK_WHOLE_SIZE};
  writes.back() = writes[0];
  writes.back().dstBinding = GLPT_RASTER_BINDING_PIXELS;
  writes.back().pBufferInfo = &pixels;
  uint32_t write_count = static_cast<uint32_t>(writes.size());
  std::array<VkWriteDescriptorSet, std::tuple_size_v<decltype(writes)> + 1> all_writes{};
  std::copy(writes.begin(), writes.end(), all_writes.begin());
  const VkDescriptorImageInfo framebuffer_info{VK_NULL_HANDLE, framebuffer,
                                               VK_IMAGE_LAYOUT_GENERAL};
  if (framebuffer != VK_NULL_HANDLE) {
    VkWriteDescriptorSet& w = all_writes[write_count++];
    w = make_info<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w.dstSet = set;
    w.dstBinding = GLPT_RASTER_BINDING_FRAMEBUFFER;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
    w.pImageInfo = &framebuffer_info;
  }
  vkUpdateDescriptorSets(device_->handle(), write_count, all_writes.data(), 0, nullptr);
  vkCmdBindDescriptorSets(r.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout(), 0, 1, &set,
                          0, nullptr);
  // A linear search: a frame binds few distinct texture sets; past this many, new ones are not
  // remembered (they still work, each writes a set of its own).
  constexpr size_t kRememberedSets = 64;
  if (r.written_sets.size() < kRememberedSets)
    r.written_sets.push_back({views, samplers, framebuffer, set});
}

void RasterRenderer::set_dynamic_state(Recording& r, const DynamicDrawState& d,
                                       const VkViewport& viewport, const VkRect2D& scissor) {
  if (r.mesa_target != ColorTargets::kNone) {
    // Upside down (mesa_orientation.cpp): the viewport and scissor mirrored, and the winding
    // that faces the viewer with them.
    const float height = static_cast<float>(buffers_->config.height);
    VkViewport flipped = viewport;
    flipped.y = height - viewport.y;
    flipped.height = -viewport.height;
    VkRect2D mirrored = scissor;
    mirrored.offset.y = static_cast<int32_t>(buffers_->config.height) -
                        (scissor.offset.y + static_cast<int32_t>(scissor.extent.height));
    DynamicDrawState turned = d;
    turned.front_face = d.front_face == VK_FRONT_FACE_CLOCKWISE ? VK_FRONT_FACE_COUNTER_CLOCKWISE
                                                                : VK_FRONT_FACE_CLOCKWISE;
    return set_oriented_dynamic_state(r, turned, flipped, mirrored);
  }
  set_oriented_dynamic_state(r, d, viewport, scissor);
}

void RasterRenderer::set_oriented_dynamic_state(Recording& r, const DynamicDrawState& d,
                                                const VkViewport& viewport,
                                                const VkRect2D& scissor) {
  // Only what changed since the last draw of this command buffer: lavapipe turns dynamic state
  // changes into new gallium state objects, which cost more than the draw of a small primitive.
  VkCommandBuffer cmd = r.cmd;
  const bool all = !r.dynamic_valid;
  const DynamicDrawState& o = r.dynamic;
  if (all || std::memcmp(&viewport, &r.viewport, sizeof viewport) != 0)
    vkCmdSetViewport(cmd, 0, 1, &viewport);
  if (all || std::memcmp(&scissor, &r.scissor, sizeof scissor) != 0)
    vkCmdSetScissor(cmd, 0, 1, &scissor);
  if (all || d.cull != o.cull) vkCmdSetCullMode(cmd, d.cull);
  if (all || d.front_face != o.front_face) vkCmdSetFrontFace(cmd, d.front_face);
  if (all || d.depth_test != o.depth_test) vkCmdSetDepthTestEnable(cmd, d.depth_test);
  if (all || d.depth_write != o.depth_write) vkCmdSetDepthWriteEnable(cmd, d.depth_write);
  if (all || d.depth_compare != o.depth_compare) vkCmdSetDepthCompareOp(cmd, d.depth_compare);
  if (all || d.stencil_test != o.stencil_test) vkCmdSetStencilTestEnable(cmd, d.stencil_test);
  // Both faces at once unless EXT_stencil_two_side gives back faces their own state; a change
  // between the two sets the front face's state on both again.
  const bool split = d.separate_back_stencil;
  const bool split_changed = all || split != o.separate_back_stencil;
  const auto set_stencil_face = [&](VkStencilFaceFlags face, const StencilFaceOps& now,
                                    const StencilFaceOps& before) {
    if (split_changed || now.fail != before.fail || now.pass != before.pass ||
        now.depth_fail != before.depth_fail || now.compare != before.compare)
      vkCmdSetStencilOp(cmd, face, now.fail, now.pass, now.depth_fail, now.compare);
    if (split_changed || now.compare_mask != before.compare_mask)
      vkCmdSetStencilCompareMask(cmd, face, now.compare_mask);
    if (split_changed || now.write_mask != before.write_mask)
      vkCmdSetStencilWriteMask(cmd, face, now.write_mask);
    if (split_changed || now.reference != before.reference)
      vkCmdSetStencilReference(cmd, face, now.reference);
  };
  set_stencil_face(split ? VK_STENCIL_FACE_FRONT_BIT : VK_STENCIL_FACE_FRONT_AND_BACK,
                   d.front_stencil(), o.front_stencil());
  if (split) set_stencil_face(VK_STENCIL_FACE_BACK_BIT, d.back_stencil, o.back_stencil);
  if (all || d.depth_bias != o.depth_bias) vkCmdSetDepthBiasEnable(cmd, d.depth_bias);
  if (all || d.depth_bias_constant != o.depth_bias_constant ||
      d.depth_bias_slope != o.depth_bias_slope)
    vkCmdSetDepthBias(cmd, d.depth_bias_constant, 0.0f, d.depth_bias_slope);
  if (all || d.line_width != o.line_width) vkCmdSetLineWidth(cmd, d.line_width);
  if (all || d.line_stipple_factor != o.line_stipple_factor ||
      d.line_stipple_pattern != o.line_stipple_pattern)
    set_line_stipple_(cmd, d.line_stipple_factor, d.line_stipple_pattern);
  if (all || d.blend_constant != o.blend_constant) {
    const float blend[4] = {d.blend_constant.r, d.blend_constant.g, d.blend_constant.b,
                            d.blend_constant.a};
    vkCmdSetBlendConstants(cmd, blend);
  }
  r.dynamic = d;
  r.viewport = viewport;
  r.scissor = scissor;
  r.dynamic_valid = true;
}

void RasterRenderer::record_clear(Recording& r, const rec::Clear& clear, uint32_t state_index) {
  const rec::FragmentOpsState& ops = r.record->states[clear.state].raster->ops;
  const VkRect2D rect = scissor_of(ops, buffers_->config);
  if (rect.extent.width == 0 || rect.extent.height == 0) return;
  const ColorTargets targets =
      resolve_draw_buffer(ops.draw_buffer, buffers_->config.double_buffered);
  // Without alpha, clearing alpha to 1 leaves it as it is: the plain clear serves.
  const bool all_channels = ops.color_write[0] && ops.color_write[1] && ops.color_write[2] &&
                            (ops.color_write[3] || !buffers_->config.has_alpha);
  const bool color =
      (clear.mask & GL_COLOR_BUFFER_BIT) && targets != ColorTargets::kNone &&
      (ops.color_write[0] || ops.color_write[1] || ops.color_write[2] || ops.color_write[3]);
  const bool depth =
      (clear.mask & GL_DEPTH_BUFFER_BIT) && ops.depth_write && buffers_->config.depth_bits;
  const uint32_t stencil_mask = ops.stencil_write_mask & 0xFFu;
  const bool stencil =
      (clear.mask & GL_STENCIL_BUFFER_BIT) && stencil_mask != 0 && buffers_->config.stencil_bits;
  if (clear.mask & GL_ACCUM_BUFFER_BIT) clear_accum(*r.record, clear);  // on the CPU, now
  if (!color && !depth && !stencil) return;
  // A traced surface is its pixels' colour: a clear replaces it only where it writes the colour
  // (red, green and blue). One that writes alpha alone (xscreensaver glplanet clears alpha
  // between its day and night passes) leaves the traced colour GL keeps.
  const bool clears_surface =
      color && r.gbuffer && ops.color_write[0] && ops.color_write[1] && ops.color_write[2];
  begin_rendering(r, color ? targets : ColorTargets::kNone, RenderingKind::kAny);
  // The depth Mesa writes: its whole-buffer clear and its quad clear round differently.
  const bool whole_buffer = rect.offset.x == 0 && rect.offset.y == 0 &&
                            rect.extent.width == buffers_->config.width &&
                            rect.extent.height == buffers_->config.height;
  const uint32_t z24 =
      mesa_clear_z24(clear.depth, whole_buffer && (!stencil || stencil_mask == 0xFFu));

  // Full masks: a plain attachment clear. Partial colour or stencil masks: a quad through a
  // pipeline whose write masks are GL's (GL 1.5 4.2.3: only the scissor, dithering and the
  // write masks affect glClear).
  if ((!color || all_channels) && (!stencil || stencil_mask == 0xFFu)) {
    std::array<VkClearAttachment, 3> attachments{};
    uint32_t n = 0;
    if (color) {
      const uint32_t color_count = r.targets == ColorTargets::kFrontAndBack ? 2 : 1;
      for (uint32_t c = 0; c < color_count; ++c) {
        VkClearAttachment& a = attachments[n++];
        a.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
        a.colorAttachment = c;
        const glm::vec4 v = glm::clamp(clear.color, 0.0f, 1.0f);
        a.clearValue.color = {{v.r, v.g, v.b, buffers_->config.has_alpha ? v.a : 1.0f}};
      }
    }
    if (depth || stencil) {
      VkClearAttachment& a = attachments[n++];
      // A drawable without stencil bits still has the packed depth/stencil image: its stencil
      // is never read, so a depth clear takes it along (value 0). lavapipe then fills whole
      // words (rep stos) instead of keeping each pixel's stencil byte with a mask, a scalar
      // loop on its queue thread (5 % of all CPU samples of glxgears at 300x300).
      const bool stencil_aspect = stencil || (depth && buffers_->config.stencil_bits == 0);
      a.aspectMask = (depth ? VK_IMAGE_ASPECT_DEPTH_BIT : 0) |
                     (stencil_aspect ? VK_IMAGE_ASPECT_STENCIL_BIT : 0);
      a.clearValue.depthStencil = {attachment_clear_depth(z24),
                                   stencil ? static_cast<uint32_t>(clear.stencil) & 0xFFu : 0u};
    }
    const VkClearRect clear_rect{rect, 0, 1};
    vkCmdClearAttachments(r.cmd, n, attachments.data(), 1, &clear_rect);
    if (clears_surface) clear_gbuffer_surface(r, rect);
    return;
  }
  begin_rendering(r, color ? targets : ColorTargets::kNone);  // a pipeline's instance
  PipelineKey key;
  key.constants[GLPT_SC_FS_FLAGS] = GLPT_FS_CLEAR;
  key.topology = static_cast<uint8_t>(RasterTopology::kTriangles);
  key.polygon_mode = VK_POLYGON_MODE_FILL;
  key.line_mode = VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT;
  key.logic_op = VK_LOGIC_OP_COPY;
  uint8_t mask = 0;
  if (color) {
    for (int c = 0; c < 4; ++c)
      if (ops.color_write[c] && (c < 3 || buffers_->config.has_alpha))
        mask |= static_cast<uint8_t>(1u << c);
  }
  key.color_write_mask = mask;
  key.attachments = r.targets == ColorTargets::kFrontAndBack ? 2 : 1;
  bind(r, key, nullptr);
  DynamicDrawState d;
  d.depth_test = depth;
  d.depth_write = depth;
  d.depth_compare = VK_COMPARE_OP_ALWAYS;
  d.stencil_test = stencil;
  d.stencil_fail = d.stencil_depth_fail = d.stencil_pass = VK_STENCIL_OP_REPLACE;
  d.stencil_compare = VK_COMPARE_OP_ALWAYS;
  d.stencil_write_mask = stencil_mask;
  d.stencil_reference = static_cast<uint32_t>(clear.stencil) & 0xFFu;
  // The whole drawable at the clear depth: a viewport whose depth range is that one value.
  const float z = fragment_depth(z24);
  const VkViewport viewport{0.0f,
                            0.0f,
                            static_cast<float>(buffers_->config.width),
                            static_cast<float>(buffers_->config.height),
                            z,
                            z};
  set_dynamic_state(r, d, viewport, rect);
  push_constants(r, gpu::RasterPushConstants{glm::uvec4(0u), glm::uvec4(0u), glm::uvec4(0u)});
  draw_geometry(r, r.clear_geometry, state_index);
  if (clears_surface) clear_gbuffer_surface(r, rect);
}

size_t RasterRenderer::merge_draws(Recording& r, const std::vector<size_t>& commands,
                                   size_t position, Arena& arena, VertexStreams& streams,
                                   const uint8_t* defaults, VkDeviceSize default_offset) {
  const rec::FrameRecord& record = *r.record;
  const auto draw_at = [&](size_t p) {
    return std::get_if<rec::Draw>(&record.commands[commands[p]]);
  };
  const rec::Draw& lead = *draw_at(position);
  if (!mergeable_draw(record, lead, r.streamed[commands[position]])) return 0;
  // The run of draws after it under the same state, counting into the same occlusion query.
  const uint64_t query = queries_.query_of(commands[position]);
  uint64_t vertices = lead.vertices->vertex_count();
  size_t end = position + 1;
  for (; end < commands.size(); ++end) {
    const rec::Draw* next = draw_at(end);
    if (next == nullptr || next->state != lead.state ||
        r.split(commands[end]) != r.split(commands[position]) ||
        !mergeable_draw(record, *next, r.streamed[commands[end]]) ||
        queries_.query_of(commands[end]) != query ||
        vertices + next->vertices->vertex_count() > kMaxMergedVertices)
      break;
    vertices += next->vertices->vertex_count();
  }
  if (end - position < 2 || !streams.fits(vertices)) return 0;

  std::vector<uint32_t>& indices = indices_;
  indices.clear();
  const rec::StateSnapshot& state = record.states[lead.state];
  if (!finite_matrix(state.transform->modelview_projection))
    r.stats->non_finite_draws += static_cast<uint32_t>(end - position);
  DrawGeometry& g = r.geometry[commands[position]];
  uint32_t base = 0;  // the run's vertices follow each other in the streams
  for (size_t p = position; p < end; ++p) {
    const rec::VertexData& v = *draw_at(p)->vertices;
    const int32_t first = streams.add(v, arena, defaults);
    if (p == position) g.vertex_offset = first;
    r.stats->non_finite_primitives +=
        append_filled_triangles(v, rec::assembly_state(state, v), base, decomposed_, indices);
    base += v.vertex_count();
  }
  streams.locate(default_offset, g.offsets, g.strides);
  g.topology = RasterTopology::kTriangles;
  g.index_offset = arena.add(indices.data(), indices.size());
  g.index_count = static_cast<uint32_t>(indices.size());
  g.merged_draws = static_cast<uint32_t>(end - position - 1);
  return end - position;
}

void RasterRenderer::record_draw(Recording& r, const rec::Draw& draw, const DrawGeometry& g,
                                 bool to_gbuffer, uint32_t fs_flags) {
  if (g.index_count == 0) return;
  r.stats->draws += 1 + g.merged_draws;
  r.stats->merged_draws += g.merged_draws;
  record_draw_pass(r, draw, g, VK_CULL_MODE_NONE, to_gbuffer, fs_flags);
}

void RasterRenderer::clear_gbuffer_surface(Recording& r, const VkRect2D& rect) {
  begin_rendering(r, ColorTargets::kGBuffer);
  VkClearAttachment attachment{};
  attachment.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
  attachment.colorAttachment = GLPT_GBUFFER_SURFACE;
  const VkClearRect clear_rect{rect, 0, 1};
  vkCmdClearAttachments(r.cmd, 1, &attachment, 1, &clear_rect);
}

void RasterRenderer::record_draw_pass(Recording& r, const rec::Draw& draw, const DrawGeometry& g,
                                      VkCullModeFlags face_pass, bool to_gbuffer,
                                      uint32_t fs_flags) {
  const rec::StateSnapshot& state = r.record->states[draw.state];
  const rec::TransformState& t = *state.transform;
  DrawContext context;
  context.topology = g.topology;
  context.targets =
      resolve_draw_buffer(state.raster->ops.draw_buffer, buffers_->config.double_buffered);
  context.drawable_has_alpha = buffers_->config.has_alpha;
  context.stencil_bits = buffers_->config.stencil_bits;
  context.face_pass = face_pass;
  DrawSetup setup = make_draw_setup(state, context);
  if (setup.skip) return;
  if (setup.split_faces) {
    // GL draws front faces with the front polygon mode and back faces with the back one.
    record_draw_pass(r, draw, g, VK_CULL_MODE_BACK_BIT, to_gbuffer, fs_flags);
    record_draw_pass(r, draw, g, VK_CULL_MODE_FRONT_BIT, to_gbuffer, fs_flags);
    return;
  }
  setup.key.constants[GLPT_SC_FS_FLAGS] |= fs_flags;
  if (to_gbuffer) {
    // The same pipeline with the G-buffer's shaders and attachments (written unblended).
    context.targets = ColorTargets::kGBuffer;
    setup.key.gbuffer = 1;
    setup.key.attachments = GLPT_GBUFFER_ATTACHMENTS;
    setup.key.color_write_mask = 0xF;
    setup.key.blend = 0;
    setup.key.blend_src_rgb = setup.key.blend_dst_rgb = 0;
    setup.key.blend_src_alpha = setup.key.blend_dst_alpha = 0;
    setup.key.blend_op_rgb = setup.key.blend_op_alpha = 0;
    setup.key.logic_op_enable = 0;
    setup.key.logic_op = VK_LOGIC_OP_COPY;
  }
  if (setup.approximated) ++r.stats->inexpressible;
  if (t.viewport[2] <= 0 || t.viewport[3] <= 0) return;  // GL draws nothing in an empty viewport
  const VkRect2D scissor = scissor_of(state.raster->ops, buffers_->config);
  if (scissor.extent.width == 0 || scissor.extent.height == 0) return;
  DynamicDrawState d = setup.dynamic;
  if (buffers_->config.depth_bits == 0) d.depth_test = d.depth_write = false;
  // Rasterized upside down where the anisotropic filter needs Mesa's interpolation to the bit
  // (mesa_orientation.cpp); every other draw ends such a run.
  const bool mesa_oriented =
      !to_gbuffer && draws_in_mesa_orientation(setup.key, d, context.targets);
  use_mesa_orientation(r, mesa_oriented ? context.targets : ColorTargets::kNone);
  if (mesa_oriented) setup.key.constants[GLPT_SC_FS_FLAGS] |= GLPT_FS_MESA_ORIENTED;
  // Blending and logic ops in the fragment shader where it can read the colour buffer (one
  // colour target, not pixel rectangles) while the blend state is new (shader_blends()).
  setup.key.framebuffer_ops = pipelines_.blends_in_shader() && !to_gbuffer &&
                              setup.key.attachments == 1 && !setup.key.pixels &&
                              (setup.key.blend || setup.key.logic_op_enable) &&
                              shader_blends(setup.key);
  begin_rendering(r, context.targets,
                  setup.key.framebuffer_ops ? RenderingKind::kRenderPass : RenderingKind::kDynamic);
  bind(r, setup.key, &state);
  const VkViewport viewport{static_cast<float>(t.viewport[0]),
                            static_cast<float>(t.viewport[1]),
                            static_cast<float>(t.viewport[2]),
                            static_cast<float>(t.viewport[3]),
                            t.depth_near,
                            t.depth_far};
  set_dynamic_state(r, d, viewport, scissor);
  glm::uvec2 jitter(0u);
  if (to_gbuffer) std::memcpy(&jitter, &r.gbuffer->jitter, sizeof jitter);
  push_constants(
      r, gpu::RasterPushConstants{
             glm::uvec4(0u, static_cast<uint32_t>(g.edge_offset / 4), jitter), g.materials,
             setup.key.framebuffer_ops ? framebuffer_ops_constants(setup.key, d.blend_constant)
                                       : glm::uvec4(0u)});
  queries_.before_draw(r.cmd, r.counting);
  draw_geometry(r, g, draw.state);
}

void RasterRenderer::push_constants(Recording& r, const gpu::RasterPushConstants& push) {
  // Only when they change: lavapipe uploads a stage's push constants again at its next draw and
  // llvmpipe renews the stage's state (for the fragment stage, its per-draw state in the scene).
  // The state index (indices.x) is pushed by draw_geometry.
  constexpr uint32_t skip = RasterPipelines::kStateIndexPushBytes;
  const auto* bytes = reinterpret_cast<const std::byte*>(&push);
  if (r.push_valid &&
      std::memcmp(bytes + skip, reinterpret_cast<const std::byte*>(&r.pushed) + skip,
                  sizeof push - skip) == 0)
    return;
  vkCmdPushConstants(r.cmd, pipelines_.layout(), pipelines_.push_constant_stages(), skip,
                     sizeof push - skip, bytes + skip);
  r.pushed = push;
  r.push_valid = true;
}

void RasterRenderer::draw_geometry(Recording& r, const DrawGeometry& g, uint32_t state_index) {
  // Bindings only where they change: draws from the shared vertex streams bind nothing.
  std::array<VkBuffer, GLPT_RASTER_ATTR_COUNT> buffers;
  for (size_t a = 0; a < buffers.size(); ++a)
    buffers[a] = g.buffers[a] != VK_NULL_HANDLE ? g.buffers[a] : vertices_.handle();
  if (!r.geometry_bound || buffers != r.bound_buffers || g.offsets != r.bound_offsets ||
      g.strides != r.bound_strides) {
    vkCmdBindVertexBuffers2(r.cmd, 0, GLPT_RASTER_ATTR_COUNT, buffers.data(), g.offsets.data(),
                            nullptr, g.strides.data());
    r.bound_buffers = buffers;
    r.bound_offsets = g.offsets;
    r.bound_strides = g.strides;
  }
  // The whole buffer, the draw's indices found by firstIndex (every index list starts at a
  // multiple of 4 bytes: the upload buffer's pieces and resident entries are 16-byte aligned).
  const VkBuffer indices = g.ascending_indices                ? ascending_.handle()
                           : g.index_buffer != VK_NULL_HANDLE ? g.index_buffer
                                                              : vertices_.handle();
  if (!r.geometry_bound || indices != r.bound_index_buffer)
    vkCmdBindIndexBuffer(r.cmd, indices, 0, VK_INDEX_TYPE_UINT32);
  r.bound_index_buffer = indices;
  r.geometry_bound = true;
  // The state index for the vertex stage alone (raster_types.h, GLPT_RASTER_VARYING_STATE).
  if (!r.state_index_valid || state_index != r.pushed_state_index) {
    vkCmdPushConstants(r.cmd, pipelines_.layout(), VK_SHADER_STAGE_VERTEX_BIT, 0,
                       RasterPipelines::kStateIndexPushBytes, &state_index);
    r.pushed_state_index = state_index;
    r.state_index_valid = true;
  }
  vkCmdDrawIndexed(r.cmd, g.index_count, 1, static_cast<uint32_t>(g.index_offset / 4),
                   g.vertex_offset, 0);
}

void RasterRenderer::ensure_ascending_indices(uint32_t count) {
  if (ascending_ && ascending_.size() >= VkDeviceSize{count} * sizeof(uint32_t)) return;
  device_->wait_all();  // pending submissions may still read the buffer replaced here
  ensure_capacity(*device_, ascending_, VkDeviceSize{count} * sizeof(uint32_t),
                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  auto* indices = static_cast<uint32_t*>(ascending_.mapped());
  const size_t capacity = ascending_.size() / sizeof(uint32_t);
  for (size_t i = 0; i < capacity; ++i) indices[i] = static_cast<uint32_t>(i);
}

void RasterRenderer::wait_for_host_reads(bool front_too) {
  buffers_->host_reads->wait(front_too ? VK_NULL_HANDLE : buffers_->back.handle());
}

bool RasterRenderer::may_write_front(const rec::FrameRecord& record,
                                     const std::vector<size_t>& commands) const {
  const bool double_buffered = buffers_->config.double_buffered;
  for (size_t i : commands) {
    bool front = false;
    std::visit(
        [&](const auto& command) {
          if constexpr (requires { command.state; }) {
            if (command.state >= record.states.size()) return;
            const rec::StateSnapshot& state = record.states[command.state];
            if (!state.raster) return;
            const ColorTargets targets =
                resolve_draw_buffer(state.raster->ops.draw_buffer, double_buffered);
            front = targets == ColorTargets::kFront || targets == ColorTargets::kFrontAndBack;
          }
        },
        record.commands[i]);
    if (front) return true;
  }
  return false;
}

void RasterRenderer::record_frame_end(VkCommandBuffer cmd, const FrameEnd& end) {
  auto barrier = make_info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  auto wait_for_previous = [&] {
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                         VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier, 0, nullptr, 0,
                         nullptr);
  };
  // The swap: the back becomes the front, and the old front the back, whose pixels are the
  // front's until restored (DrawableBuffers::back_is_front). A back that already is the front
  // (nothing drew into it since the last swap) leaves the images as they are.
  if (end.swap && buffers_->config.double_buffered && !buffers_->back_is_front) {
    std::swap(buffers_->front, buffers_->back);
    buffers_->back_is_front = true;
  }
  const bool to_window = end.present_to && end.present_to->width == buffers_->config.width &&
                         end.present_to->height == buffers_->config.height;
  if (end.front_rgba || (to_window && !present_)) {
    wait_for_previous();
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {buffers_->config.width, buffers_->config.height, 1};
    vkCmdCopyImageToBuffer(cmd, buffers_->front.handle(), VK_IMAGE_LAYOUT_GENERAL,
                           readback_.handle(), 1, &copy);
  }
  if (to_window && end.present_later && end.present_bottom_up && end.front_pixels != nullptr &&
      buffers_->front.pixels() != nullptr) {
    // Nothing to copy: the caller reads the front image in place once the frame is done, and
    // whatever writes the image next waits until it has (wait_for_host_reads).
    FrameEnd::FrontPixels& out = *end.front_pixels;
    out.rows = buffers_->front.pixels();
    out.row_pitch = buffers_->front.pixel_row_pitch();
    const VkImage image = buffers_->front.handle();
    std::shared_ptr<HostImageReads> reads = buffers_->host_reads;
    reads->begin(image);
    out.reading = std::shared_ptr<void>(reads.get(), [reads, image](void*) { reads->end(image); });
  } else if (to_window && present_ && end.present_bottom_up) {
    // Straight into the window's memory as one region, rows bottom to top: the caller flips.
    wait_for_previous();
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {buffers_->config.width, buffers_->config.height, 1};
    vkCmdCopyImageToBuffer(cmd, buffers_->front.handle(), VK_IMAGE_LAYOUT_GENERAL,
                           present_->handle(), 1, &copy);
  } else if (to_window && present_) {
    // Straight into the window's memory, one region per row: X rows run top to bottom.
    wait_for_previous();
    std::vector<VkBufferImageCopy> rows(buffers_->config.height);
    for (uint32_t y = 0; y < buffers_->config.height; ++y) {
      VkBufferImageCopy& copy = rows[y];
      copy = {};
      copy.bufferOffset =
          VkDeviceSize{buffers_->config.height - 1 - y} * buffers_->config.width * 4;
      copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      copy.imageOffset = {0, static_cast<int32_t>(y), 0};
      copy.imageExtent = {buffers_->config.width, 1, 1};
    }
    vkCmdCopyImageToBuffer(cmd, buffers_->front.handle(), VK_IMAGE_LAYOUT_GENERAL,
                           present_->handle(), static_cast<uint32_t>(rows.size()), rows.data());
  }
}

bool RasterRenderer::read_image(const GpuImage& image, VkImageAspectFlags aspect,
                                uint32_t texel_bytes, int32_t x, int32_t y, uint32_t width,
                                uint32_t height, std::vector<uint8_t>& out) {
  out.assign(size_t{width} * height * texel_bytes, 0);
  if (!image) return false;
  const VkRect2D inside = intersect_with_framebuffer(
      x, y, static_cast<int32_t>(width), static_cast<int32_t>(height), buffers_->config);
  if (inside.extent.width == 0 || inside.extent.height == 0) return true;
  const VkDeviceSize bytes = VkDeviceSize{inside.extent.width} * inside.extent.height * texel_bytes;
  ensure_capacity(*device_, readback_, bytes,
                  VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  device_->submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {aspect, 0, 0, 1};
    copy.imageOffset = {inside.offset.x, inside.offset.y, 0};
    copy.imageExtent = {inside.extent.width, inside.extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_GENERAL, readback_.handle(), 1,
                           &copy);
  });
  const auto* src = static_cast<const uint8_t*>(readback_.mapped());
  const size_t row_bytes = size_t{inside.extent.width} * texel_bytes;
  for (uint32_t j = 0; j < inside.extent.height; ++j) {
    const size_t dst_row = static_cast<size_t>(inside.offset.y - y + static_cast<int32_t>(j));
    const size_t dst_col = static_cast<size_t>(inside.offset.x - x);
    std::memcpy(&out[(dst_row * width + dst_col) * texel_bytes], src + j * row_bytes, row_bytes);
  }
  return true;
}

bool RasterRenderer::read_color(DrawableBuffers& buffers, uint32_t buffer, int32_t x, int32_t y,
                                uint32_t width, uint32_t height, std::vector<uint8_t>& rgba) {
  buffers_ = &buffers;
  return read_current_color(buffer, x, y, width, height, rgba);
}

bool RasterRenderer::read_current_color(uint32_t buffer, int32_t x, int32_t y, uint32_t width,
                                        uint32_t height, std::vector<uint8_t>& rgba) {
  const bool front = buffer == GL_FRONT || buffer == GL_FRONT_LEFT || buffer == GL_LEFT ||
                     !buffers_->config.double_buffered;
  if (!front) restore_back();
  if (!read_image(front ? buffers_->front : buffers_->back, VK_IMAGE_ASPECT_COLOR_BIT, 4, x, y,
                  width, height, rgba))
    return false;
  swap_red_and_blue(rgba.data(), size_t{width} * height);
  return true;
}

bool RasterRenderer::read_depth(DrawableBuffers& buffers, int32_t x, int32_t y, uint32_t width,
                                uint32_t height, std::vector<float>& depth) {
  buffers_ = &buffers;
  std::vector<uint8_t> raw;
  if (!read_image(buffers_->depth_stencil, VK_IMAGE_ASPECT_DEPTH_BIT, 4, x, y, width, height, raw))
    return false;
  // The depth aspect of D24_UNORM_S8_UINT copies as 32-bit words holding 24 bits of depth.
  depth.resize(size_t{width} * height);
  for (size_t i = 0; i < depth.size(); ++i) {
    uint32_t word;
    std::memcpy(&word, &raw[i * 4], 4);
    depth[i] = static_cast<float>(static_cast<double>(word & 0xFFFFFFu) / 16777215.0);
  }
  return true;
}

bool RasterRenderer::read_stencil(DrawableBuffers& buffers, int32_t x, int32_t y, uint32_t width,
                                  uint32_t height, std::vector<uint8_t>& stencil) {
  buffers_ = &buffers;
  return read_image(buffers_->depth_stencil, VK_IMAGE_ASPECT_STENCIL_BIT, 1, x, y, width, height,
                    stencil);
}

void RasterRenderer::write_color(bool front, const std::vector<uint8_t>& rgba) {
  wait_for_host_reads(true);
  const bool to_front = front || !buffers_->config.double_buffered;
  if (!to_front) restore_back();  // (a whole image: the copy is cheap and keeps this simple)
  const GpuImage& image = to_front ? buffers_->front : buffers_->back;
  if (!image || rgba.size() != size_t{buffers_->config.width} * buffers_->config.height * 4) return;
  write_image(image, {{0, 0}, {buffers_->config.width, buffers_->config.height}}, rgba);
}

void RasterRenderer::write_front_color(DrawableBuffers& buffers,
                                       const rec::DrawableConfig& drawable,
                                       const std::vector<uint8_t>& rgba) {
  ensure_buffers(buffers, drawable);
  write_color(true, rgba);
}

void RasterRenderer::write_depth(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                                 const std::vector<float>& depth) {
  ensure_buffers(buffers, drawable);
  if (!buffers_->depth_stencil ||
      depth.size() != size_t{buffers_->config.width} * buffers_->config.height)
    return;
  // The depth aspect of D24_UNORM_S8_UINT copies as 32-bit words holding 24 bits of depth.
  std::vector<uint32_t> words(depth.size());
  for (size_t i = 0; i < depth.size(); ++i)
    words[i] = uint32_t(std::lround(double(std::clamp(depth[i], 0.0f, 1.0f)) * 16777215.0));
  write_depth_stencil(VK_IMAGE_ASPECT_DEPTH_BIT,
                      {{0, 0}, {buffers_->config.width, buffers_->config.height}}, words.data(),
                      words.size() * sizeof(uint32_t));
}

void RasterRenderer::write_pixels(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                                  const PixelWrite& pixels) {
  ensure_buffers(buffers, drawable);
  wait_for_host_reads(true);
  const rec::DrawableConfig& config = buffers_->config;
  const size_t n = size_t{pixels.width} * pixels.height;
  if (n == 0 || pixels.x < 0 || pixels.y < 0 || pixels.x + int64_t{pixels.width} > config.width ||
      pixels.y + int64_t{pixels.height} > config.height)
    return;
  const VkRect2D rect{{pixels.x, pixels.y}, {pixels.width, pixels.height}};
  if (pixels.rgba.size() == n * 4) {
    const ColorTargets targets = resolve_draw_buffer(pixels.draw_buffer, config.double_buffered);
    if (targets == ColorTargets::kFront || targets == ColorTargets::kFrontAndBack)
      write_image(buffers_->front, rect, pixels.rgba);
    if (targets == ColorTargets::kBack || targets == ColorTargets::kFrontAndBack) {
      restore_back();
      write_image(buffers_->back, rect, pixels.rgba);
    }
  }
  if (!buffers_->depth_stencil) return;
  if (pixels.depth.size() == n) {
    std::vector<uint32_t> words(n);
    for (size_t i = 0; i < n; ++i)
      words[i] =
          uint32_t(std::lround(double(std::clamp(pixels.depth[i], 0.0f, 1.0f)) * 16777215.0));
    write_depth_stencil(VK_IMAGE_ASPECT_DEPTH_BIT, rect, words.data(), words.size() * 4);
  }
  if (pixels.stencil.size() == n)
    write_depth_stencil(VK_IMAGE_ASPECT_STENCIL_BIT, rect, pixels.stencil.data(), n);
}

void RasterRenderer::write_depth_stencil(VkImageAspectFlags aspect, const VkRect2D& rect,
                                         const void* bytes, size_t size) {
  ensure_capacity(*device_, readback_, size,
                  VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  readback_.write(bytes, size);
  device_->submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {aspect, 0, 0, 1};
    copy.imageOffset = {rect.offset.x, rect.offset.y, 0};
    copy.imageExtent = {rect.extent.width, rect.extent.height, 1};
    vkCmdCopyBufferToImage(cmd, readback_.handle(), buffers_->depth_stencil.handle(),
                           VK_IMAGE_LAYOUT_GENERAL, 1, &copy);
  });
}

void RasterRenderer::write_image(const GpuImage& image, const VkRect2D& rect,
                                 const std::vector<uint8_t>& rgba) {
  ensure_capacity(*device_, readback_, rgba.size(),
                  VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  readback_.write(rgba.data(), rgba.size());
  swap_red_and_blue(static_cast<uint8_t*>(readback_.mapped()), rgba.size() / 4);
  device_->submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageOffset = {rect.offset.x, rect.offset.y, 0};
    copy.imageExtent = {rect.extent.width, rect.extent.height, 1};
    vkCmdCopyBufferToImage(cmd, readback_.handle(), image.handle(), VK_IMAGE_LAYOUT_GENERAL, 1,
                           &copy);
  });
}

void RasterRenderer::swap_buffers(DrawableBuffers& buffers) {
  buffers_ = &buffers;
  if (!buffers_->front || !buffers_->config.double_buffered || buffers_->back_is_front) return;
  // (Submissions still pending use the images they recorded; later ones follow in queue order.)
  std::swap(buffers_->front, buffers_->back);
  buffers_->back_is_front = true;
}

void RasterRenderer::record_restore_back(VkCommandBuffer cmd) {
  if (!buffers_->back_is_front) return;
  buffers_->back_is_front = false;
  auto barrier = make_info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       0, 1, &barrier, 0, nullptr, 0, nullptr);
  VkImageCopy copy{};
  copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.dstSubresource = copy.srcSubresource;
  copy.extent = {buffers_->config.width, buffers_->config.height, 1};
  vkCmdCopyImage(cmd, buffers_->front.handle(), VK_IMAGE_LAYOUT_GENERAL, buffers_->back.handle(),
                 VK_IMAGE_LAYOUT_GENERAL, 1, &copy);
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void RasterRenderer::restore_back() {
  if (!buffers_->back_is_front || !buffers_->back) return;
  device_->submit_and_wait([&](VkCommandBuffer cmd) { record_restore_back(cmd); });
}

bool RasterRenderer::begins_with_whole_back_clear(const rec::FrameRecord& record,
                                                  const std::vector<size_t>& commands) const {
  for (size_t i : commands) {
    const rec::Command& command = record.commands[i];
    if (std::holds_alternative<rec::BeginQuery>(command) ||
        std::holds_alternative<rec::EndQuery>(command))
      continue;
    const auto* clear = std::get_if<rec::Clear>(&command);
    if (clear == nullptr) return false;  // a draw, read or pixel command: it may touch colour
    const rec::FragmentOpsState& ops = record.states[clear->state].raster->ops;
    const ColorTargets targets =
        resolve_draw_buffer(ops.draw_buffer, buffers_->config.double_buffered);
    const bool writes_color =
        (clear->mask & GL_COLOR_BUFFER_BIT) &&
        (ops.color_write[0] || ops.color_write[1] || ops.color_write[2] || ops.color_write[3]);
    // A clear of depth or stencil only, or of the front only, leaves colour as it is: look on.
    if (!writes_color || targets == ColorTargets::kNone || targets == ColorTargets::kFront)
      continue;
    if (targets != ColorTargets::kBack && targets != ColorTargets::kFrontAndBack) return false;
    const VkRect2D rect = scissor_of(ops, buffers_->config);
    const bool all_channels = ops.color_write[0] && ops.color_write[1] && ops.color_write[2] &&
                              (ops.color_write[3] || !buffers_->config.has_alpha);
    return all_channels && rect.offset.x == 0 && rect.offset.y == 0 &&
           rect.extent.width == buffers_->config.width &&
           rect.extent.height == buffers_->config.height;
  }
  return false;
}

}  // namespace glpt::rt
