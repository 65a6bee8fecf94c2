#include "rt_core/raster/raster_pipelines.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "raster_ff_clip_vert_spv.h"
#include "raster_ff_clip_vert_v0_spv.h"
#include "raster_ff_clip_vert_v12_spv.h"
#include "raster_ff_clip_vert_v4_spv.h"
#include "raster_ff_clip_vert_v8_spv.h"
#include "raster_ff_flat_fbops_frag_v0_spv.h"
#include "raster_ff_flat_fbops_frag_v12_spv.h"
#include "raster_ff_flat_fbops_frag_v31_spv.h"
#include "raster_ff_flat_fbops_frag_v4_spv.h"
#include "raster_ff_flat_fbops_frag_v8_spv.h"
#include "raster_ff_flat_frag_spv.h"
#include "raster_ff_flat_frag_v0_spv.h"
#include "raster_ff_flat_frag_v12_spv.h"
#include "raster_ff_flat_frag_v4_spv.h"
#include "raster_ff_flat_frag_v8_spv.h"
#include "raster_ff_pixels_depth_frag_spv.h"
#include "raster_ff_pixels_frag_spv.h"
#include "raster_ff_smooth_fbops_frag_v0_spv.h"
#include "raster_ff_smooth_fbops_frag_v12_spv.h"
#include "raster_ff_smooth_fbops_frag_v31_spv.h"
#include "raster_ff_smooth_fbops_frag_v4_spv.h"
#include "raster_ff_smooth_fbops_frag_v8_spv.h"
#include "raster_ff_smooth_frag_spv.h"
#include "raster_ff_smooth_frag_v0_spv.h"
#include "raster_ff_smooth_frag_v12_spv.h"
#include "raster_ff_smooth_frag_v4_spv.h"
#include "raster_ff_smooth_frag_v8_spv.h"
#include "raster_ff_vert_spv.h"
#include "raster_ff_vert_v0_spv.h"
#include "raster_ff_vert_v12_spv.h"
#include "raster_ff_vert_v4_spv.h"
#include "raster_ff_vert_v8_spv.h"
#include "raster_gbuffer_clip_geom_spv.h"
#include "raster_gbuffer_clip_vert_spv.h"
#include "raster_gbuffer_flat_frag_spv.h"
#include "raster_gbuffer_geom_spv.h"
#include "raster_gbuffer_smooth_frag_spv.h"
#include "raster_gbuffer_vert_spv.h"
#include "raster_types.h"
#include "raster_unfilled_lines_geom_spv.h"
#include "raster_unfilled_points_geom_spv.h"
#include "rt_core/raster/gbuffer_targets.hpp"
#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

vk::ShaderModule make_module(VkDevice device, std::span<const uint32_t> spirv) {
  auto info = make_info<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
  return vk::ShaderModule(module, {device});
}

}  // namespace

RasterPipelines::RasterPipelines(const VulkanDevice& device)
    : device_(device),
      cache_file_(PipelineCacheFile::default_path(device.name()), device.properties()) {
  VkDevice dev = device.handle();
  // Set 0: the per-state uniforms and one combined image sampler per unit and texture kind,
  // written where a draw's textures change (descriptor_set_ring.hpp: why not push descriptors).
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  bindings.push_back({GLPT_RASTER_BINDING_STATES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                      VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  for (uint32_t i = 0; i < 4 * GLPT_RASTER_MAX_UNITS; ++i)
    bindings.push_back({GLPT_RASTER_BINDING_TEXTURES + i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                        1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  const VkShaderStageFlags geometry =
      device.has_geometry_shader() ? VK_SHADER_STAGE_GEOMETRY_BIT : 0;
  // Fragment too: the G-buffer pass reads per-vertex materials there (raster_ff.frag).
  bindings.push_back({GLPT_RASTER_BINDING_EDGES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                      VK_SHADER_STAGE_VERTEX_BIT | geometry | VK_SHADER_STAGE_FRAGMENT_BIT,
                      nullptr});
  bindings[0].stageFlags |= geometry;
  bindings.push_back({GLPT_RASTER_BINDING_PIXELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                      VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  if (device.has_ordered_framebuffer_reads())
    bindings.push_back({GLPT_RASTER_BINDING_FRAMEBUFFER, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT, 1,
                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  auto set_info = make_info<VkDescriptorSetLayoutCreateInfo>(
      VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set_info.bindingCount = static_cast<uint32_t>(bindings.size());
  set_info.pBindings = bindings.data();
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateDescriptorSetLayout(dev, &set_info, nullptr, &set_layout));
  set_layout_ = vk::DescriptorSetLayout(set_layout, {dev});
  for (const VkDescriptorSetLayoutBinding& binding : bindings) {
    auto same = [&](const VkDescriptorPoolSize& s) { return s.type == binding.descriptorType; };
    auto found = std::find_if(set_counts_.begin(), set_counts_.end(), same);
    if (found == set_counts_.end())
      set_counts_.push_back({binding.descriptorType, binding.descriptorCount});
    else
      found->descriptorCount += binding.descriptorCount;
  }

  push_stages_ = VK_SHADER_STAGE_VERTEX_BIT | geometry | VK_SHADER_STAGE_FRAGMENT_BIT;
  // The vertex stage reads all of them; the other stages all but the state index (indices.x),
  // so pushing the index alone (with every draw) touches the vertex stage's alone, and the rest
  // (pushed when it changes) every stage's (raster_types.h). No stage may be in two ranges.
  const std::array<VkPushConstantRange, 2> push{
      VkPushConstantRange{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(gpu::RasterPushConstants)},
      VkPushConstantRange{push_stages_ & ~VkShaderStageFlags{VK_SHADER_STAGE_VERTEX_BIT},
                          kStateIndexPushBytes,
                          sizeof(gpu::RasterPushConstants) - kStateIndexPushBytes}};
  auto layout_info =
      make_info<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  layout_info.pushConstantRangeCount = static_cast<uint32_t>(push.size());
  layout_info.pPushConstantRanges = push.data();
  VkPipelineLayout layout = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreatePipelineLayout(dev, &layout_info, nullptr, &layout));
  layout_ = vk::PipelineLayout(layout, {dev});

  const bool framebuffer_reads = device.has_ordered_framebuffer_reads();
  auto add_set = [&](uint32_t varyings, std::span<const uint32_t> vertex,
                     std::span<const uint32_t> vertex_clip, std::span<const uint32_t> smooth,
                     std::span<const uint32_t> flat, std::span<const uint32_t> smooth_ops,
                     std::span<const uint32_t> flat_ops) {
    shader_sets_.push_back({varyings, make_module(dev, vertex), make_module(dev, vertex_clip),
                            make_module(dev, smooth), make_module(dev, flat),
                            framebuffer_reads ? make_module(dev, smooth_ops) : vk::ShaderModule(),
                            framebuffer_reads ? make_module(dev, flat_ops) : vk::ShaderModule()});
  };
  add_set(0, raster_ff_vert_v0_spv, raster_ff_clip_vert_v0_spv, raster_ff_smooth_frag_v0_spv,
          raster_ff_flat_frag_v0_spv, raster_ff_smooth_fbops_frag_v0_spv,
          raster_ff_flat_fbops_frag_v0_spv);
  add_set(GLPT_VARYING_FOG, raster_ff_vert_v4_spv, raster_ff_clip_vert_v4_spv,
          raster_ff_smooth_frag_v4_spv, raster_ff_flat_frag_v4_spv,
          raster_ff_smooth_fbops_frag_v4_spv, raster_ff_flat_fbops_frag_v4_spv);
  add_set(GLPT_VARYING_TEXCOORDS, raster_ff_vert_v8_spv, raster_ff_clip_vert_v8_spv,
          raster_ff_smooth_frag_v8_spv, raster_ff_flat_frag_v8_spv,
          raster_ff_smooth_fbops_frag_v8_spv, raster_ff_flat_fbops_frag_v8_spv);
  add_set(GLPT_VARYING_TEXCOORDS | GLPT_VARYING_FOG, raster_ff_vert_v12_spv,
          raster_ff_clip_vert_v12_spv, raster_ff_smooth_frag_v12_spv, raster_ff_flat_frag_v12_spv,
          raster_ff_smooth_fbops_frag_v12_spv, raster_ff_flat_fbops_frag_v12_spv);
  add_set(GLPT_VARYINGS_ALL, raster_ff_vert_spv, raster_ff_clip_vert_spv, raster_ff_smooth_frag_spv,
          raster_ff_flat_frag_spv, raster_ff_smooth_fbops_frag_v31_spv,
          raster_ff_flat_fbops_frag_v31_spv);
  if (framebuffer_reads) render_pass_ = create_single_target_render_pass(dev);
  fragment_pixels_ = make_module(dev, raster_ff_pixels_frag_spv);
  fragment_pixels_depth_ = make_module(dev, raster_ff_pixels_depth_frag_spv);
  if (device.has_geometry_shader()) {
    unfilled_lines_ = make_module(dev, raster_unfilled_lines_geom_spv);
    unfilled_points_ = make_module(dev, raster_unfilled_points_geom_spv);
    gbuffer_vertex_ = make_module(dev, raster_gbuffer_vert_spv);
    gbuffer_vertex_clip_ = make_module(dev, raster_gbuffer_clip_vert_spv);
    gbuffer_geometry_ = make_module(dev, raster_gbuffer_geom_spv);
    gbuffer_geometry_clip_ = make_module(dev, raster_gbuffer_clip_geom_spv);
    gbuffer_fragment_smooth_ = make_module(dev, raster_gbuffer_smooth_frag_spv);
    gbuffer_fragment_flat_ = make_module(dev, raster_gbuffer_flat_frag_spv);
  }

  std::string message;
  std::vector<char> data = cache_file_.load(&message);
  if (!message.empty()) std::fprintf(stderr, "glpt: %s\n", message.c_str());
  auto cache_info =
      make_info<VkPipelineCacheCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
  cache_info.initialDataSize = data.size();
  cache_info.pInitialData = data.empty() ? nullptr : data.data();
  VkPipelineCache cache = VK_NULL_HANDLE;
  // The file's header and hash were checked (pipeline_cache_file.hpp); should the driver still
  // refuse the data, start empty.
  if (vkCreatePipelineCache(dev, &cache_info, nullptr, &cache) != VK_SUCCESS) {
    cache_info.initialDataSize = 0;
    cache_info.pInitialData = nullptr;
    GLPT_VK_CHECK(vkCreatePipelineCache(dev, &cache_info, nullptr, &cache));
  }
  cache_ = vk::PipelineCache(cache, {dev});
}

RasterPipelines::~RasterPipelines() {
  if (cache_file_.path().empty() || !cache_) return;
  size_t size = 0;
  if (vkGetPipelineCacheData(device_.handle(), cache_.get(), &size, nullptr) != VK_SUCCESS) return;
  std::vector<char> data(size);
  if (vkGetPipelineCacheData(device_.handle(), cache_.get(), &size, data.data()) != VK_SUCCESS)
    return;
  data.resize(size);
  std::string message;
  if (!cache_file_.save(data, &message)) std::fprintf(stderr, "glpt: %s\n", message.c_str());
}

PipelineKey RasterPipelines::pipeline_of(const PipelineKey& key) const {
  if (key.framebuffer_ops) {
    // Push constants (framebuffer_ops_constants): one pipeline per colour mask, or one for all
    // where the mask is dynamic too.
    PipelineKey shared = key;
    shared.blend = 0;
    shared.blend_src_rgb = shared.blend_dst_rgb = shared.blend_src_alpha = 0;
    shared.blend_dst_alpha = shared.blend_op_rgb = shared.blend_op_alpha = 0;
    shared.logic_op_enable = shared.logic_op = 0;
    if (device_.dynamic_blend() != nullptr) shared.color_write_mask = 0;
    return shared;
  }
  if (device_.dynamic_blend() == nullptr) return key;
  // Set per draw (RasterRenderer::bind): no part of the pipeline.
  PipelineKey shared = key;
  shared.blend = 0;
  shared.blend_src_rgb = shared.blend_dst_rgb = shared.blend_src_alpha = shared.blend_dst_alpha = 0;
  shared.blend_op_rgb = shared.blend_op_alpha = 0;
  shared.logic_op_enable = shared.logic_op = 0;
  shared.color_write_mask = 0;
  return shared;
}

void RasterPipelines::set_blend_state(VkCommandBuffer cmd, const PipelineKey& key) const {
  const VulkanDevice::DynamicBlendFunctions* blend = device_.dynamic_blend();
  if (blend == nullptr) return;
  std::array<VkBool32, GLPT_GBUFFER_ATTACHMENTS> enables{};
  std::array<VkColorBlendEquationEXT, GLPT_GBUFFER_ATTACHMENTS> equations{};
  std::array<VkColorComponentFlags, GLPT_GBUFFER_ATTACHMENTS> masks{};
  // Blending in the shader: the pipeline's blending and logic op are off.
  const bool fixed_function = !key.gbuffer && !key.framebuffer_ops;
  for (size_t i = 0; i < GLPT_GBUFFER_ATTACHMENTS; ++i) {
    // The G-buffer's attachments are written whole, unblended (as create() makes them).
    enables[i] = fixed_function ? key.blend : VK_FALSE;
    equations[i] = {static_cast<VkBlendFactor>(key.blend_src_rgb),
                    static_cast<VkBlendFactor>(key.blend_dst_rgb),
                    static_cast<VkBlendOp>(key.blend_op_rgb),
                    static_cast<VkBlendFactor>(key.blend_src_alpha),
                    static_cast<VkBlendFactor>(key.blend_dst_alpha),
                    static_cast<VkBlendOp>(key.blend_op_alpha)};
    if (!fixed_function) equations[i] = {};
    masks[i] = key.gbuffer ? 0xFu : key.color_write_mask;
  }
  const uint32_t count = key.attachments;
  blend->set_enable(cmd, 0, count, enables.data());
  blend->set_equation(cmd, 0, count, equations.data());
  blend->set_write_mask(cmd, 0, count, masks.data());
  blend->set_logic_op_enable(cmd, key.logic_op_enable && fixed_function);
  blend->set_logic_op(cmd, static_cast<VkLogicOp>(key.logic_op));
}

VkPipeline RasterPipelines::get(const PipelineKey& full_key, bool* created) {
  const PipelineKey key = pipeline_of(full_key);
  auto it = pipelines_.find(key);
  if (it != pipelines_.end()) {
    if (created) *created = false;
    return it->second.get();
  }
  // GLPT_PIPELINE_LOG=1: each pipeline's state before its compile and the compile's time, to find
  // which state makes a program stall on a compile.
  const char* log = std::getenv("GLPT_PIPELINE_LOG");
  const bool logging = log != nullptr && *log == '1';
  if (logging) {
    std::string constants;
    for (uint32_t c : key.constants) constants += ' ' + std::to_string(c);
    std::fprintf(stderr,
                 "glpt: pipeline %zu: topology %u flat %u clip %u unfilled %u pixels %u gbuffer %u "
                 "blend %u framebuffer_ops %u attachments %u constants%s\n",
                 pipelines_.size() + 1, key.topology, key.flat, key.clip_variant, key.unfilled,
                 key.pixels, key.gbuffer, key.blend, key.framebuffer_ops, key.attachments,
                 constants.c_str());
  }
  const auto started = std::chrono::steady_clock::now();
  VkPipeline pipeline = create(key);
  pipelines_.emplace(key, vk::Pipeline(pipeline, {device_.handle()}));
  if (created) *created = true;
  if (logging)
    std::fprintf(
        stderr, "glpt: pipeline %zu compiled in %.1f ms\n", pipelines_.size(),
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count());
  return pipeline;
}

VkPipeline RasterPipelines::create(const PipelineKey& key) {
  std::array<VkSpecializationMapEntry, PipelineKey::kConstants> entries;
  for (uint32_t i = 0; i < PipelineKey::kConstants; ++i)
    entries[i] = {i, static_cast<uint32_t>(i * sizeof(uint32_t)), sizeof(uint32_t)};
  VkSpecializationInfo specialization{PipelineKey::kConstants, entries.data(), sizeof key.constants,
                                      key.constants};
  const uint32_t varyings = varyings_read(key);
  const ShaderSet* shaders = &shader_sets_.back();
  for (const ShaderSet& set : shader_sets_) {
    if ((set.varyings & varyings) == varyings) {
      shaders = &set;
      break;
    }
  }
  std::array<VkPipelineShaderStageCreateInfo, 3> stages{};
  stages[0] = make_info<VkPipelineShaderStageCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = key.clip_variant ? shaders->vertex_clip.get() : shaders->vertex.get();
  stages[0].pName = "main";
  stages[0].pSpecializationInfo = &specialization;
  stages[1] = stages[0];
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = key.pixels == 2       ? fragment_pixels_depth_.get()
                     : key.pixels          ? fragment_pixels_.get()
                     : key.framebuffer_ops ? (key.flat ? shaders->fragment_flat_ops.get()
                                                       : shaders->fragment_smooth_ops.get())
                     : key.flat            ? shaders->fragment_flat.get()
                                           : shaders->fragment_smooth.get();
  uint32_t stage_count = 2;
  if (key.unfilled != 0 && unfilled_lines_) {
    stages[2] = stages[0];
    stages[2].stage = VK_SHADER_STAGE_GEOMETRY_BIT;
    stages[2].module = key.unfilled == 1 ? unfilled_lines_.get() : unfilled_points_.get();
    stage_count = 3;
  }
  if (key.gbuffer) {
    if (!gbuffer_geometry_) throw VulkanError("the G-buffer pass needs geometry shaders");
    stages[0].module = key.clip_variant ? gbuffer_vertex_clip_.get() : gbuffer_vertex_.get();
    stages[1].module = key.flat ? gbuffer_fragment_flat_.get() : gbuffer_fragment_smooth_.get();
    stages[2] = stages[0];
    stages[2].stage = VK_SHADER_STAGE_GEOMETRY_BIT;
    stages[2].module = key.clip_variant ? gbuffer_geometry_clip_.get() : gbuffer_geometry_.get();
    stage_count = 3;
  }

  // One binding per attribute; strides are dynamic (0 for an attribute with one value).
  struct Attribute {
    uint32_t location;
    VkFormat format;
  };
  const Attribute attributes[] = {
      {GLPT_RASTER_ATTR_POSITION, VK_FORMAT_R32G32B32A32_SFLOAT},
      {GLPT_RASTER_ATTR_NORMAL, VK_FORMAT_R32G32B32_SFLOAT},
      {GLPT_RASTER_ATTR_COLOR, VK_FORMAT_R32G32B32A32_SFLOAT},
      {GLPT_RASTER_ATTR_SECONDARY, VK_FORMAT_R32G32B32A32_SFLOAT},
      {GLPT_RASTER_ATTR_FOG, VK_FORMAT_R32_SFLOAT},
      {GLPT_RASTER_ATTR_TEXCOORD0 + 0, VK_FORMAT_R32G32B32A32_SFLOAT},
      {GLPT_RASTER_ATTR_TEXCOORD0 + 1, VK_FORMAT_R32G32B32A32_SFLOAT},
      {GLPT_RASTER_ATTR_TEXCOORD0 + 2, VK_FORMAT_R32G32B32A32_SFLOAT},
      {GLPT_RASTER_ATTR_TEXCOORD0 + 3, VK_FORMAT_R32G32B32A32_SFLOAT},
  };
  std::vector<VkVertexInputBindingDescription> binding_descriptions;
  std::vector<VkVertexInputAttributeDescription> attribute_descriptions;
  for (const Attribute& a : attributes) {
    binding_descriptions.push_back({a.location, 16, VK_VERTEX_INPUT_RATE_VERTEX});
    attribute_descriptions.push_back({a.location, a.location, a.format, 0});
  }
  auto vertex_input = make_info<VkPipelineVertexInputStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  vertex_input.vertexBindingDescriptionCount = static_cast<uint32_t>(binding_descriptions.size());
  vertex_input.pVertexBindingDescriptions = binding_descriptions.data();
  vertex_input.vertexAttributeDescriptionCount =
      static_cast<uint32_t>(attribute_descriptions.size());
  vertex_input.pVertexAttributeDescriptions = attribute_descriptions.data();

  const auto topology = static_cast<RasterTopology>(key.topology);
  auto input_assembly = make_info<VkPipelineInputAssemblyStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  input_assembly.topology = topology == RasterTopology::kPoints  ? VK_PRIMITIVE_TOPOLOGY_POINT_LIST
                            : topology == RasterTopology::kLines ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST
                            : topology == RasterTopology::kLineStrip
                                ? VK_PRIMITIVE_TOPOLOGY_LINE_STRIP
                                : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  // Several GL line strips in one draw are separated by restart indices.
  input_assembly.primitiveRestartEnable = topology == RasterTopology::kLineStrip;

  // GL's clip-space depth is [-1, 1].
  auto depth_clip = make_info<VkPipelineViewportDepthClipControlCreateInfoEXT>(
      VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_DEPTH_CLIP_CONTROL_CREATE_INFO_EXT);
  depth_clip.negativeOneToOne = VK_TRUE;
  auto viewport = make_info<VkPipelineViewportStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO, &depth_clip);
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  // GL's provoking vertex is the last one (the decomposition orders triangles for it).
  auto provoking = make_info<VkPipelineRasterizationProvokingVertexStateCreateInfoEXT>(
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_PROVOKING_VERTEX_STATE_CREATE_INFO_EXT);
  provoking.provokingVertexMode = VK_PROVOKING_VERTEX_MODE_LAST_VERTEX_EXT;
  auto line_state = make_info<VkPipelineRasterizationLineStateCreateInfoEXT>(
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_LINE_STATE_CREATE_INFO_EXT, &provoking);
  line_state.lineRasterizationMode = static_cast<VkLineRasterizationModeEXT>(key.line_mode);
  if (line_state.lineRasterizationMode == VK_LINE_RASTERIZATION_MODE_RECTANGULAR_SMOOTH_EXT &&
      !device_.has_smooth_lines())
    line_state.lineRasterizationMode = VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT;
  line_state.stippledLineEnable = key.line_stipple;
  line_state.lineStippleFactor = 1;
  line_state.lineStipplePattern = 0xFFFF;
  auto rasterization = make_info<VkPipelineRasterizationStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO, &line_state);
  rasterization.polygonMode = static_cast<VkPolygonMode>(key.polygon_mode);
  rasterization.lineWidth = 1.0f;

  auto multisample = make_info<VkPipelineMultisampleStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

  auto depth_stencil = make_info<VkPipelineDepthStencilStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);

  VkPipelineColorBlendAttachmentState blend{};
  blend.blendEnable = key.blend;
  blend.srcColorBlendFactor = static_cast<VkBlendFactor>(key.blend_src_rgb);
  blend.dstColorBlendFactor = static_cast<VkBlendFactor>(key.blend_dst_rgb);
  blend.colorBlendOp = static_cast<VkBlendOp>(key.blend_op_rgb);
  blend.srcAlphaBlendFactor = static_cast<VkBlendFactor>(key.blend_src_alpha);
  blend.dstAlphaBlendFactor = static_cast<VkBlendFactor>(key.blend_dst_alpha);
  blend.alphaBlendOp = static_cast<VkBlendOp>(key.blend_op_alpha);
  blend.colorWriteMask = key.color_write_mask;
  std::array<VkPipelineColorBlendAttachmentState, GLPT_GBUFFER_ATTACHMENTS> blends{blend, blend};
  if (key.gbuffer) {
    VkPipelineColorBlendAttachmentState unblended{};
    unblended.colorWriteMask = 0xF;
    blends.fill(unblended);
  }
  // Blending in the shader: the render pass whose colour attachment is also its input
  // attachment, read in rasterization order (render_pass()); the others render dynamically.
  const bool in_render_pass = uses_render_pass(key);
  auto color_blend = make_info<VkPipelineColorBlendStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  if (in_render_pass)
    color_blend.flags =
        VK_PIPELINE_COLOR_BLEND_STATE_CREATE_RASTERIZATION_ORDER_ATTACHMENT_ACCESS_BIT_EXT;
  color_blend.logicOpEnable = key.logic_op_enable;
  color_blend.logicOp = static_cast<VkLogicOp>(key.logic_op);
  color_blend.attachmentCount = key.attachments;
  color_blend.pAttachments = blends.data();

  const bool blend_dynamic = device_.dynamic_blend() != nullptr;
  std::vector<VkDynamicState> dynamic_states = {
      VK_DYNAMIC_STATE_VIEWPORT,
      VK_DYNAMIC_STATE_SCISSOR,
      VK_DYNAMIC_STATE_LINE_WIDTH,
      VK_DYNAMIC_STATE_DEPTH_BIAS,
      VK_DYNAMIC_STATE_BLEND_CONSTANTS,
      VK_DYNAMIC_STATE_STENCIL_COMPARE_MASK,
      VK_DYNAMIC_STATE_STENCIL_WRITE_MASK,
      VK_DYNAMIC_STATE_STENCIL_REFERENCE,
      VK_DYNAMIC_STATE_CULL_MODE,
      VK_DYNAMIC_STATE_FRONT_FACE,
      VK_DYNAMIC_STATE_DEPTH_TEST_ENABLE,
      VK_DYNAMIC_STATE_DEPTH_WRITE_ENABLE,
      VK_DYNAMIC_STATE_DEPTH_COMPARE_OP,
      VK_DYNAMIC_STATE_STENCIL_TEST_ENABLE,
      VK_DYNAMIC_STATE_STENCIL_OP,
      VK_DYNAMIC_STATE_DEPTH_BIAS_ENABLE,
      VK_DYNAMIC_STATE_VERTEX_INPUT_BINDING_STRIDE,
      VK_DYNAMIC_STATE_LINE_STIPPLE_EXT,
  };
  if (blend_dynamic) {
    dynamic_states.insert(
        dynamic_states.end(),
        {VK_DYNAMIC_STATE_COLOR_BLEND_ENABLE_EXT, VK_DYNAMIC_STATE_COLOR_BLEND_EQUATION_EXT,
         VK_DYNAMIC_STATE_COLOR_WRITE_MASK_EXT, VK_DYNAMIC_STATE_LOGIC_OP_ENABLE_EXT,
         VK_DYNAMIC_STATE_LOGIC_OP_EXT});
  }
  auto dynamic = make_info<VkPipelineDynamicStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
  dynamic.dynamicStateCount = static_cast<uint32_t>(dynamic_states.size());
  dynamic.pDynamicStates = dynamic_states.data();

  const std::array<VkFormat, 2> color_formats{kColorFormat, kColorFormat};
  auto rendering =
      make_info<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
  rendering.colorAttachmentCount = key.attachments;
  rendering.pColorAttachmentFormats = key.gbuffer ? kGBufferFormats.data() : color_formats.data();
  rendering.depthAttachmentFormat = kDepthStencilFormat;
  rendering.stencilAttachmentFormat = kDepthStencilFormat;

  auto info = make_info<VkGraphicsPipelineCreateInfo>(
      VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, in_render_pass ? nullptr : &rendering);
  if (in_render_pass) {
    info.renderPass = render_pass_.get();
    info.subpass = 0;
  }
  info.stageCount = stage_count;
  info.pStages = stages.data();
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &input_assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &rasterization;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth_stencil;
  info.pColorBlendState = &color_blend;
  info.pDynamicState = &dynamic;
  info.layout = layout_.get();
  VkPipeline pipeline = VK_NULL_HANDLE;
  GLPT_VK_CHECK(
      vkCreateGraphicsPipelines(device_.handle(), cache_.get(), 1, &info, nullptr, &pipeline));
  return pipeline;
}

bool RasterPipelines::uses_render_pass(const PipelineKey& key) const {
  return render_pass_ && key.framebuffer_ops;
}

vk::RenderPass RasterPipelines::create_single_target_render_pass(VkDevice dev) {
  // Everything stays in GENERAL (as with dynamic rendering): no layout transitions.
  std::array<VkAttachmentDescription, 2> attachments{};
  for (VkAttachmentDescription& a : attachments) {
    a.samples = VK_SAMPLE_COUNT_1_BIT;
    a.loadOp = a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    a.storeOp = a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_STORE;
    a.initialLayout = a.finalLayout = VK_IMAGE_LAYOUT_GENERAL;
  }
  attachments[0].format = kColorFormat;
  attachments[1].format = kDepthStencilFormat;
  const VkAttachmentReference color{0, VK_IMAGE_LAYOUT_GENERAL};
  const VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_GENERAL};
  VkSubpassDescription subpass{};
  subpass.flags = VK_SUBPASS_DESCRIPTION_RASTERIZATION_ORDER_ATTACHMENT_COLOR_ACCESS_BIT_EXT;
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.inputAttachmentCount = 1;
  subpass.pInputAttachments = &color;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  subpass.pDepthStencilAttachment = &depth;
  auto info = make_info<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
  info.attachmentCount = static_cast<uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateRenderPass(dev, &info, nullptr, &render_pass));
  return vk::RenderPass(render_pass, {dev});
}

}  // namespace glpt::rt
