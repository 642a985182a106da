#include "runtime/scene_renderer.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <cstring>
#include <set>
#include <stdexcept>

#include "compiler/material_input_files.hpp"
#include "runtime/draw_order.hpp"
#include "runtime/frame_uniforms.hpp"
#include "runtime/scene/graph_path.hpp"
#include "runtime/weather/frame_weather.hpp"

namespace wg {

namespace {
// Lighting constants of the validation scenes (linear radiance).
constexpr glm::vec3 kSunColor{3.2f, 3.05f, 2.8f};  // a clear midday sun against the tone curve
constexpr glm::vec3 kSkyColor{0.45f, 0.55f, 0.72f};
constexpr float kAmbientIntensity = 0.8f;
constexpr float kToneExposure = 1.f;
constexpr float kNearPlane = 0.1f, kFarPlane = 600.f;
// Extra height above and below the scene for the top-down exposure camera (metres).
constexpr float kExposureMargin = 1.f;

glm::mat4 flipY(glm::mat4 projection) {
  projection[1][1] *= -1.f;  // Vulkan's clip y points down
  return projection;
}

struct PassKind {
  enum { Exposure, Shadow, Colour };
};
}  // namespace

struct SceneRenderer::Object {
  const scene::SceneObject* source = nullptr;
  vk::Buffer vertices, indices;
  std::uint32_t indexCount = 0;
};

SceneRenderer::SceneRenderer(vk::Context& ctx, scene::Scene scene, std::string graphsDirectory)
    : ctx_(ctx), scene_(std::move(scene)), graphsDirectory_(std::move(graphsDirectory)) {
  createPasses();
  linearClamp_ = createSampler(ctx_, "clamp", "linear");
  nearestClamp_ = createSampler(ctx_, "clamp", "nearest");
  // 1x1 stand-ins: "nothing above" for heights, "fully lit" for shadows, bound while
  // the real maps are being drawn.
  float lowest = -1e6f, lit = 1.f;
  placeholderHeight_ = vk::Image2D(ctx_, 1, 1, VK_FORMAT_R32_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  placeholderHeight_.upload(ctx_, &lowest, sizeof lowest);
  placeholderShadow_ = vk::Image2D(ctx_, 1, 1, VK_FORMAT_R32_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  placeholderShadow_.upload(ctx_, &lit, sizeof lit);
  const float undeformed[4] = {0.f, 0.f, 1.f, 0.f};  // no height offset, normal straight up
  placeholderDeformation_ = vk::Image2D(ctx_, 1, 1, VK_FORMAT_R32G32B32A32_SFLOAT,
                                        VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  placeholderDeformation_.upload(ctx_, undeformed, sizeof undeformed);
  linearRepeat_ = createSampler(ctx_, "repeat", "linear");
  shadowMap_ = vk::Image2D(ctx_, kShadowResolution, kShadowResolution, vk::kDepthFormat,
                           VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  uploadTerrain();
  VkQueryPoolCreateInfo query{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  query.queryType = VK_QUERY_TYPE_TIMESTAMP;
  query.queryCount = 2;
  VkQueryPool timestamps;
  vk::check(vkCreateQueryPool(ctx_.device(), &query, nullptr, &timestamps), "vkCreateQueryPool");
  timestamps_ = vk::UniqueQueryPool(ctx_.device(), timestamps);
  buildExposureMap();
}

SceneRenderer::~SceneRenderer() { vkDeviceWaitIdle(ctx_.device()); }

void SceneRenderer::createPasses() {
  // Colour pass: RGBA32F colour kept for read-back, depth kept for later passes.
  VkAttachmentDescription colour{};
  colour.format = vk::kColourFormat;
  colour.samples = VK_SAMPLE_COUNT_1_BIT;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  colour.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  colour.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentDescription depth = colour;
  depth.format = vk::kDepthFormat;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;  // soft particles read it afterwards
  depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colourRef;
  subpass.pDepthStencilAttachment = &depthRef;
  VkAttachmentDescription attachments[] = {colour, depth};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 2;
  info.pAttachments = attachments;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  VkRenderPass colourPass;
  vk::check(vkCreateRenderPass(ctx_.device(), &info, nullptr, &colourPass), "vkCreateRenderPass");
  colourPass_ = vk::UniqueRenderPass(ctx_.device(), colourPass);

  // Depth-only pass (shadow and sky-exposure maps): stored and left shader-readable.
  VkAttachmentDescription depthOnly = depth;
  depthOnly.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depthOnly.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkAttachmentReference depthOnlyRef{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription depthSubpass{};
  depthSubpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  depthSubpass.pDepthStencilAttachment = &depthOnlyRef;
  // The colour pass samples the map afterwards.
  VkSubpassDependency after{};
  after.srcSubpass = 0;
  after.dstSubpass = VK_SUBPASS_EXTERNAL;
  after.srcStageMask = VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  after.dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
  after.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo depthInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  depthInfo.attachmentCount = 1;
  depthInfo.pAttachments = &depthOnly;
  depthInfo.subpassCount = 1;
  depthInfo.pSubpasses = &depthSubpass;
  depthInfo.dependencyCount = 1;
  depthInfo.pDependencies = &after;
  VkRenderPass depthPass;
  vk::check(vkCreateRenderPass(ctx_.device(), &depthInfo, nullptr, &depthPass), "vkCreateRenderPass");
  depthPass_ = vk::UniqueRenderPass(ctx_.device(), depthPass);
}

vk::UniqueFramebuffer SceneRenderer::framebuffer(VkRenderPass pass, std::vector<VkImageView> views, std::uint32_t w, std::uint32_t h) {
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = pass;
  info.attachmentCount = static_cast<std::uint32_t>(views.size());
  info.pAttachments = views.data();
  info.width = w;
  info.height = h;
  info.layers = 1;
  VkFramebuffer fb;
  vk::check(vkCreateFramebuffer(ctx_.device(), &info, nullptr, &fb), "vkCreateFramebuffer");
  return vk::UniqueFramebuffer(ctx_.device(), fb);
}

void SceneRenderer::uploadTerrain() {
  int n = scene_.terrainHeightResolution;
  if (n <= 0 || scene_.terrainHeights.size() != static_cast<std::size_t>(n) * n) {
    float flat = 0.f;  // no terrain map: eq. 3.12's slope is zero
    terrainHeight_ = vk::Image2D(ctx_, 1, 1, VK_FORMAT_R32_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    terrainHeight_.upload(ctx_, &flat, sizeof flat);
    return;
  }
  terrainHeight_ = vk::Image2D(ctx_, static_cast<std::uint32_t>(n), static_cast<std::uint32_t>(n), VK_FORMAT_R32_SFLOAT,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  terrainHeight_.upload(ctx_, scene_.terrainHeights.data(), scene_.terrainHeights.size() * sizeof(float));
}

MaterialResources& SceneRenderer::material(const std::string& graph, const std::optional<std::string>& preset) {
  std::string key = graph + "|" + preset.value_or("");
  auto& slot = materials_[key];
  if (!slot) {
    CompileOptions options;
    options.weatherPreset = preset;
    slot = std::make_unique<MaterialResources>(ctx_, scene::graphFilePath(graph, graphsDirectory_), options);
  }
  return *slot;
}

namespace {
struct ClipRange {
  float nearPlane, farPlane;
};

// The fixed planes cover every bundled scene; a larger one (an imported model in
// millimetres) pushes the far plane out and the near plane with it, keeping their ratio.
ClipRange clipRange(const scene::Scene& scene, glm::vec3 eye) {
  glm::vec3 centre = 0.5f * (scene.boundsMin + scene.boundsMax);
  float reach = glm::distance(eye, centre) + 0.5f * glm::distance(scene.boundsMin, scene.boundsMax);
  float scale = std::max(1.f, 1.5f * reach / kFarPlane);
  return {kNearPlane * scale, kFarPlane * scale};
}

glm::mat4 cameraViewProjection(const scene::CameraPreset& camera, ClipRange clip, std::uint32_t width, std::uint32_t height) {
  glm::mat4 view = glm::lookAt(camera.eye, camera.target, glm::vec3(0.f, 1.f, 0.f));
  glm::mat4 projection =
      glm::perspective(glm::radians(camera.fovYDegrees), float(width) / float(height), clip.nearPlane, clip.farPlane);
  return flipY(projection) * view;
}
}  // namespace

glm::mat4 SceneRenderer::viewProjection(const std::string& camera, std::uint32_t width, std::uint32_t height) const {
  const scene::CameraPreset* preset = scene_.cameras.empty() ? nullptr : &scene_.cameras.front();
  for (const auto& c : scene_.cameras)
    if (c.name == camera) preset = &c;
  if (!preset) throw std::runtime_error("scene '" + scene_.name + "' has no cameras");
  return cameraViewProjection(*preset, clipRange(scene_, preset->eye), width, height);
}

std::size_t SceneRenderer::gpuMemoryBytes() const {
  std::size_t n = terrainHeight_.byteSize() + exposureMap_.byteSize() + shadowMap_.byteSize();
  for (const auto& o : objects_) n += o->vertices.size() + o->indices.size();
  for (const auto& [key, m] : materials_) n += m->textureBytes();
  return n;
}

std::vector<std::string> SceneRenderer::materialInputFiles() const {
  std::set<std::string> files;
  for (const auto& [key, m] : materials_) {
    files.insert(m->graphPath());
    for (auto& file : wg::materialInputFiles(m->compiled().ir)) files.insert(std::move(file));
  }
  return {files.begin(), files.end()};
}

namespace {

// Interleaves a mesh into the material's reflected vertex format.
std::vector<float> packVertices(const scene::Mesh& mesh, const vk::VertexLayout& layout) {
  std::vector<float> out;
  out.reserve(mesh.positions.size() * layout.stride / sizeof(float));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (const auto& name : layout.names) {
      if (name == "position") out.insert(out.end(), {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z});
      else if (name == "normal") out.insert(out.end(), {mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z});
      else if (name == "tangent")
        out.insert(out.end(), {mesh.tangents[i].x, mesh.tangents[i].y, mesh.tangents[i].z, mesh.tangents[i].w});
      else if (name == "texcoord") out.insert(out.end(), {mesh.texcoords[i].x, mesh.texcoords[i].y});
      else if (name == "texcoord1") {
        const glm::vec2 uv = mesh.texcoords1.empty() ? mesh.texcoords[i] : mesh.texcoords1[i];  // set 0 stands in
        out.insert(out.end(), {uv.x, uv.y});
      }
      else if (name == "color")
        out.insert(out.end(), {mesh.colors[i].r, mesh.colors[i].g, mesh.colors[i].b, mesh.colors[i].a});
      else throw std::runtime_error("reflection names an unknown vertex input '" + name + "'");
    }
  }
  return out;
}

struct DescriptorWriter {
  std::vector<VkWriteDescriptorSet> writes;
  std::vector<std::unique_ptr<VkDescriptorImageInfo>> images;
  std::vector<std::unique_ptr<VkDescriptorBufferInfo>> buffers;

  void buffer(VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type, VkBuffer buffer, VkDeviceSize range) {
    buffers.push_back(std::make_unique<VkDescriptorBufferInfo>(VkDescriptorBufferInfo{buffer, 0, range}));
    add(set, binding, type).pBufferInfo = buffers.back().get();
  }
  void image(VkDescriptorSet set, std::uint32_t binding, VkImageView view) {
    images.push_back(std::make_unique<VkDescriptorImageInfo>(
        VkDescriptorImageInfo{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}));
    add(set, binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE).pImageInfo = images.back().get();
  }
  void sampler(VkDescriptorSet set, std::uint32_t binding, VkSampler sampler) {
    images.push_back(std::make_unique<VkDescriptorImageInfo>(VkDescriptorImageInfo{sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED}));
    add(set, binding, VK_DESCRIPTOR_TYPE_SAMPLER).pImageInfo = images.back().get();
  }

 private:
  VkWriteDescriptorSet& add(VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    writes.push_back(w);
    return writes.back();
  }
};

// The images a pass binds for the shared maps.
struct SharedMaps {
  VkImageView terrainHeight, skyExposure, sunShadow, snowDeformation;
  VkSampler linear, nearest;  // depth formats need not be filterable; PCF filters
  VkSampler repeat;           // the toroidal snow deformation map
};

// Allocates one object's set 0 (frame slice and shared maps) and set 1 (material)
// and queues their writes.
std::array<VkDescriptorSet, 2> allocateMaterialSets(VkDevice device, VkDescriptorPool pool, const MaterialResources& material,
                                                    const vk::MaterialPipeline& pipeline, DescriptorWriter& writer,
                                                    VkBuffer frameBuffer, VkDeviceSize frameSize, const SharedMaps& maps) {
  VkDescriptorSetLayout layouts[2] = {pipeline.setLayout(0), pipeline.setLayout(1)};
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = 2;
  alloc.pSetLayouts = layouts;
  std::array<VkDescriptorSet, 2> sets{};
  vk::check(vkAllocateDescriptorSets(device, &alloc, sets.data()), "vkAllocateDescriptorSets");
  const auto& refl = material.reflection();
  writer.buffer(sets[0], refl.frame.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, frameBuffer, frameSize);
  for (const auto& map : refl.weatherMaps) {
    bool shadow = map.name == "sunShadow", deformation = map.name == "snowDeformation";
    writer.image(sets[0], map.binding,
                 map.name == "terrainHeight" ? maps.terrainHeight
                 : shadow                    ? maps.sunShadow
                 : deformation               ? maps.snowDeformation
                                             : maps.skyExposure);
    writer.sampler(sets[0], map.samplerBinding, shadow ? maps.nearest : deformation ? maps.repeat : maps.linear);
  }
  if (const vk::Buffer* params = material.parameterBuffer())
    writer.buffer(sets[1], refl.material.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params->handle(), refl.material.size);
  for (const auto& t : material.textures()) {
    writer.image(sets[1], t.reflected->binding, t.image.view());
    writer.sampler(sets[1], t.reflected->samplerBinding, t.sampler.get());
  }
  return sets;
}

void drawIndexed(VkCommandBuffer cmd, const vk::MaterialPipeline& pipeline, VkPipeline handle,
                 const std::array<VkDescriptorSet, 2>& sets, std::uint32_t frameOffset, VkBuffer vertices, VkBuffer indices,
                 std::uint32_t indexCount) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, handle);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 0, 2, sets.data(), 1, &frameOffset);
  VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
  vkCmdBindIndexBuffer(cmd, indices, 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, indexCount, 1, 0, 0, 0);
}

void setViewport(VkCommandBuffer cmd, std::uint32_t w, std::uint32_t h) {
  VkViewport viewport{0.f, 0.f, float(w), float(h), 0.f, 1.f};
  VkRect2D scissor{{0, 0}, {w, h}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

// What one depth or colour pass draws with.
struct PassSetup {
  int kind;
  glm::mat4 viewProjection;
  glm::vec3 eye;
  VkImageView exposureView, shadowView;
};

}  // namespace

RenderedFrame SceneRenderer::render(const RenderRequest& request) {
  ctx_.clearValidationMessages();
  // Materials and meshes for this request's preset and backend.
  const WeatherLevels& levels = request.weather.levels;
  bool neutral = levels.snow <= 0.f && levels.wetness <= 0.f && levels.moss <= 0.f && levels.frost <= 0.f && levels.puddles <= 0.f;
  std::optional<std::string> preset = request.weatherPreset;
  if (!preset && neutral && request.unweatheredVariantWhenNeutral) preset = "none";
  std::vector<MaterialResources*> mats;
  for (const auto& o : scene_.objects) mats.push_back(&material(o.graph, preset));
  if (objects_.empty()) {
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      auto& src = scene_.objects[i];
      auto obj = std::make_unique<Object>();
      obj->source = &src;
      auto layout = vk::vertexLayoutFrom(mats[i]->reflection());
      auto packed = packVertices(src.mesh, layout);
      obj->vertices = vk::Buffer(ctx_, packed.size() * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
      obj->vertices.write(packed.data(), packed.size() * sizeof(float));
      obj->indices = vk::Buffer(ctx_, src.mesh.indices.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
      obj->indices.write(src.mesh.indices.data(), src.mesh.indices.size() * sizeof(std::uint32_t));
      obj->indexCount = static_cast<std::uint32_t>(src.mesh.indices.size());
      objects_.push_back(std::move(obj));
    }
  }

  // Sun shadow camera: orthographic over the scene's bounds, looking along the light.
  glm::vec3 towardsSun = glm::normalize(glm::vec3(request.weather.conditions.sunDirection[0],
                                                  request.weather.conditions.sunDirection[1],
                                                  request.weather.conditions.sunDirection[2]));
  glm::vec3 centre = 0.5f * (scene_.boundsMin + scene_.boundsMax);
  float radius = 0.5f * glm::length(scene_.boundsMax - scene_.boundsMin);
  glm::vec3 up = std::abs(towardsSun.y) > 0.99f ? glm::vec3(0.f, 0.f, 1.f) : glm::vec3(0.f, 1.f, 0.f);
  glm::mat4 lightView = glm::lookAt(centre + towardsSun * (2.f * radius), centre, up);
  glm::mat4 light = flipY(glm::ortho(-radius, radius, -radius, radius, 0.01f, 4.f * radius)) * lightView;

  const scene::CameraPreset* camera = &scene_.cameras.front();
  for (const auto& c : scene_.cameras)
    if (c.name == request.camera) camera = &c;
  if (request.cameraPose) camera = &*request.cameraPose;
  std::vector<PassSetup> passes;
  if (request.shadows) passes.push_back({PassKind::Shadow, light, camera->eye, exposureMap_.view(), placeholderShadow_.view()});
  ClipRange clip = clipRange(scene_, camera->eye);
  passes.push_back({PassKind::Colour, cameraViewProjection(*camera, clip, request.width, request.height), camera->eye,
                    exposureMap_.view(), request.shadows ? shadowMap_.view() : placeholderShadow_.view()});

  RenderedFrame frame;
  frame.width = request.width;
  frame.height = request.height;
  // Later passes (request.afterColourPass) may write the colour in compute and sample the depth.
  VkImageUsageFlags later = request.afterColourPass ? VK_IMAGE_USAGE_STORAGE_BIT : 0;
  vk::Image2D colour(ctx_, request.width, request.height, vk::kColourFormat,
                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | later);
  vk::Image2D depth(ctx_, request.width, request.height, vk::kDepthFormat,
                    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | (request.afterColourPass ? VK_IMAGE_USAGE_SAMPLED_BIT : 0));
  vk::UniqueFramebuffer colourTarget = framebuffer(colourPass_.get(), {colour.view(), depth.view()}, request.width, request.height);
  vk::UniqueFramebuffer shadowTarget = framebuffer(depthPass_.get(), {shadowMap_.view()}, kShadowResolution, kShadowResolution);

  // Frame data: one dynamic slice per (pass, object).
  const vk::ReflectedBlock& frameBlock = mats.front()->reflection().frame;
  VkDeviceSize alignment = ctx_.properties().limits.minUniformBufferOffsetAlignment;
  VkDeviceSize slice = (frameBlock.size + alignment - 1) / alignment * alignment;
  vk::Buffer frameBuffer(ctx_, slice * passes.size() * objects_.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  auto modelOf = [&](std::size_t i) {
    auto moved = request.objectModels.find(objects_[i]->source->name);
    return moved != request.objectModels.end() ? moved->second : objects_[i]->source->model;
  };
  FrameState uniforms;  // the block's values; per pass and object only the matrices and eye change
  writeWeather(request.weather, uniforms);
  storeInto(uniforms.sunDirection, towardsSun);  // unit length, as the block requires
  storeInto(uniforms.lightViewProjection, light);
  storeInto(uniforms.skyExposureRegion, exposureRegion_);
  storeInto(uniforms.terrainRegion, scene_.terrainRegion);
  storeInto(uniforms.sunColor, kSunColor);
  uniforms.ambientIntensity = kAmbientIntensity;
  storeInto(uniforms.skyColor, kSkyColor);
  uniforms.exposure = kToneExposure;
  uniforms.debugView = request.debugView;
  uniforms.terrainHeightScale = scene_.terrainHeightScale;
  uniforms.shadowMapTexel = request.shadows ? 1.f / float(kShadowResolution) : 0.f;
  for (std::size_t p = 0; p < passes.size(); ++p)
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      glm::mat4 model = modelOf(i);
      storeInto(uniforms.model, model);
      storeInto(uniforms.viewProjection, passes[p].viewProjection);
      storeInto(uniforms.normalMatrix, glm::transpose(glm::inverse(model)));
      storeInto(uniforms.cameraPosition, passes[p].eye);
      FrameUniforms f(frameBlock);
      f.set(uniforms);
      frameBuffer.write(f.bytes().data(), f.bytes().size(), slice * (p * objects_.size() + i));
    }

  // Descriptor sets: set 0 and set 1 per (pass, object).
  std::size_t setCount = 2 * passes.size() * objects_.size();
  std::uint32_t imageDescriptors = 0;
  for (auto* m : mats) imageDescriptors += static_cast<std::uint32_t>(m->reflection().textures.size() + m->reflection().weatherMaps.size());
  imageDescriptors = (imageDescriptors + 1) * static_cast<std::uint32_t>(passes.size());
  VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, static_cast<std::uint32_t>(setCount)},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, static_cast<std::uint32_t>(setCount)},
      {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, imageDescriptors},
      {VK_DESCRIPTOR_TYPE_SAMPLER, imageDescriptors},
  };
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = static_cast<std::uint32_t>(setCount);
  poolInfo.poolSizeCount = 4;
  poolInfo.pPoolSizes = sizes;
  VkDescriptorPool rawPool;
  vk::check(vkCreateDescriptorPool(ctx_.device(), &poolInfo, nullptr, &rawPool), "vkCreateDescriptorPool");
  vk::UniqueDescriptorPool pool(ctx_.device(), rawPool);

  DescriptorWriter writer;
  std::vector<std::array<VkDescriptorSet, 2>> sets(passes.size() * objects_.size());
  for (std::size_t p = 0; p < passes.size(); ++p)
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      SharedMaps maps{terrainHeight_.view(), passes[p].exposureView, passes[p].shadowView,
                      (snowDeformation_ ? *snowDeformation_ : placeholderDeformation_).view(), linearClamp_.get(), nearestClamp_.get(),
                      linearRepeat_.get()};
      sets[p * objects_.size() + i] =
          allocateMaterialSets(ctx_.device(), pool.get(), *mats[i], mats[i]->pipeline(request.backend, colourPass_.get(), depthPass_.get()),
                               writer, frameBuffer.handle(), frameBlock.size, maps);
    }
  vkUpdateDescriptorSets(ctx_.device(), static_cast<std::uint32_t>(writer.writes.size()), writer.writes.data(), 0, nullptr);

  // Blended objects after the others, farthest first; AOVs draw them opaque.
  std::vector<DrawCandidate> candidates;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    bool blended = mats[i]->reflection().blended();
    candidates.push_back({blended, blended ? worldCentre(objects_[i]->source->mesh, modelOf(i)) : glm::vec3(0.f)});
  }
  const std::vector<std::size_t> drawOrder = colourDrawOrder(candidates, camera->eye);
  const bool aov = request.debugView != 0;

  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, timestamps_.get(), 0, 2);
    for (std::size_t p = 0; p < passes.size(); ++p) {
      bool colourPass = passes[p].kind == PassKind::Colour;
      std::uint32_t w = colourPass ? request.width : kShadowResolution;
      std::uint32_t h = colourPass ? request.height : kShadowResolution;
      VkClearValue clears[2];
      // AOVs clear to alpha 0, which no surface writes, so read-backs can tell sky
      // from surface.
      if (request.debugView == 0) clears[0].color = {{kSkyColor.r, kSkyColor.g, kSkyColor.b, 1.f}};
      else clears[0].color = {{0.f, 0.f, 0.f, 0.f}};
      clears[1].depthStencil = {1.f, 0};
      VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
      begin.renderPass = colourPass ? colourPass_.get() : depthPass_.get();
      begin.framebuffer = colourPass ? colourTarget.get() : shadowTarget.get();
      begin.renderArea = {{0, 0}, {w, h}};
      begin.clearValueCount = colourPass ? 2 : 1;
      begin.pClearValues = colourPass ? clears : &clears[1];
      if (colourPass) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps_.get(), 0);
      vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
      setViewport(cmd, w, h);
      for (std::size_t i : drawOrder) {
        if (!colourPass && !objects_[i]->source->castsShadow) continue;
        if (colourPass && !request.onlyObject.empty() && objects_[i]->source->name != request.onlyObject) continue;
        auto& pipeline = mats[i]->pipeline(request.backend, colourPass_.get(), depthPass_.get());
        drawIndexed(cmd, pipeline, colourPass ? pipeline.colourPipeline(aov) : pipeline.depthPipeline(), sets[p * objects_.size() + i],
                    static_cast<std::uint32_t>(slice * (p * objects_.size() + i)), objects_[i]->vertices.handle(),
                    objects_[i]->indices.handle(), objects_[i]->indexCount);
      }
      vkCmdEndRenderPass(cmd);
      if (colourPass) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_.get(), 1);
      if (colourPass && request.afterColourPass)
        request.afterColourPass({cmd, &colour, &depth, passes[p].viewProjection, passes[p].eye, clip.nearPlane, clip.farPlane});
    }
  });

  std::uint64_t ticks[2] = {0, 0};
  if (vkGetQueryPoolResults(ctx_.device(), timestamps_.get(), 0, 2, sizeof ticks, ticks, sizeof(std::uint64_t),
                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS && ticks[1] > ticks[0])
    frame.gpuMilliseconds = double(ticks[1] - ticks[0]) * ctx_.properties().limits.timestampPeriod * 1e-6;

  auto raw = colour.download(ctx_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  frame.rgba.resize(std::size_t(request.width) * request.height * 4);
  std::memcpy(frame.rgba.data(), raw.data(), frame.rgba.size() * sizeof(float));

  return frame;
}

void SceneRenderer::buildExposureMap() {
  // A top-down orthographic depth map of everything that keeps rain off (clip x, y
  // follow world x, z exactly as wg_sky_exposure_uv does; depth is height from the top).
  glm::vec3 lo = scene_.boundsMin - glm::vec3(kExposureMargin), hi = scene_.boundsMax + glm::vec3(kExposureMargin);
  float sizeX = hi.x - lo.x, sizeZ = hi.z - lo.z, top = hi.y, bottom = lo.y;
  glm::mat4 topDown(0.f);
  topDown[0][0] = 2.f / sizeX;
  topDown[3][0] = -2.f * lo.x / sizeX - 1.f;
  topDown[2][1] = 2.f / sizeZ;
  topDown[3][1] = -2.f * lo.z / sizeZ - 1.f;
  topDown[1][2] = -1.f / (top - bottom);
  topDown[3][2] = top / (top - bottom);
  topDown[3][3] = 1.f;
  exposureRegion_ = glm::vec4(lo.x, lo.z, 1.f / sizeX, 1.f / sizeZ);

  // Draw with unweathered materials: the map holds the scene's own geometry.
  RenderRequest request;
  request.weatherPreset = "none";
  request.shadows = false;
  std::vector<MaterialResources*> mats;
  for (const auto& o : scene_.objects) mats.push_back(&material(o.graph, request.weatherPreset));
  vk::Image2D depth(ctx_, kExposureResolution, kExposureResolution, vk::kDepthFormat,
                    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  vk::UniqueFramebuffer target = framebuffer(depthPass_.get(), {depth.view()}, kExposureResolution, kExposureResolution);
  const vk::ReflectedBlock& frameBlock = mats.front()->reflection().frame;
  VkDeviceSize alignment = ctx_.properties().limits.minUniformBufferOffsetAlignment;
  VkDeviceSize slice = (frameBlock.size + alignment - 1) / alignment * alignment;
  std::vector<std::size_t> drawn;
  for (std::size_t i = 0; i < scene_.objects.size(); ++i)
    if (scene_.objects[i].occludesSky) drawn.push_back(i);
  vk::Buffer frameBuffer(ctx_, slice * std::max<std::size_t>(drawn.size(), 1), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::vector<vk::Buffer> vertexBuffers, indexBuffers;
  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 64}, {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 64},
                                  {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 512}, {VK_DESCRIPTOR_TYPE_SAMPLER, 512}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = static_cast<std::uint32_t>(2 * drawn.size() + 2);
  poolInfo.poolSizeCount = 4;
  poolInfo.pPoolSizes = sizes;
  VkDescriptorPool rawPool;
  vk::check(vkCreateDescriptorPool(ctx_.device(), &poolInfo, nullptr, &rawPool), "vkCreateDescriptorPool");
  vk::UniqueDescriptorPool pool(ctx_.device(), rawPool);
  DescriptorWriter writer;
  std::vector<std::array<VkDescriptorSet, 2>> sets(drawn.size());
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    std::size_t i = drawn[k];
    FrameUniforms f(frameBlock);
    glm::mat4 model = scene_.objects[i].model;
    f.set("model", model);
    f.set("viewProjection", topDown);
    f.set("normalMatrix", glm::transpose(glm::inverse(model)));
    frameBuffer.write(f.bytes().data(), f.bytes().size(), slice * k);
    auto layout = vk::vertexLayoutFrom(mats[i]->reflection());
    auto packed = packVertices(scene_.objects[i].mesh, layout);
    vertexBuffers.emplace_back(ctx_, packed.size() * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    vertexBuffers.back().write(packed.data(), packed.size() * sizeof(float));
    const auto& indices = scene_.objects[i].mesh.indices;
    indexBuffers.emplace_back(ctx_, indices.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    indexBuffers.back().write(indices.data(), indices.size() * sizeof(std::uint32_t));
    SharedMaps maps{terrainHeight_.view(), placeholderHeight_.view(), placeholderShadow_.view(),
                    placeholderDeformation_.view(), linearClamp_.get(), nearestClamp_.get(), linearRepeat_.get()};
    sets[k] = allocateMaterialSets(ctx_.device(), pool.get(), *mats[i], mats[i]->pipeline(ShaderLanguage::Glsl, colourPass_.get(), depthPass_.get()),
                                   writer, frameBuffer.handle(), frameBlock.size, maps);
  }
  vkUpdateDescriptorSets(ctx_.device(), static_cast<std::uint32_t>(writer.writes.size()), writer.writes.data(), 0, nullptr);
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    VkClearValue clear;
    clear.depthStencil = {1.f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = depthPass_.get();
    begin.framebuffer = target.get();
    begin.renderArea = {{0, 0}, {kExposureResolution, kExposureResolution}};
    begin.clearValueCount = 1;
    begin.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    setViewport(cmd, kExposureResolution, kExposureResolution);
    for (std::size_t k = 0; k < drawn.size(); ++k) {
      auto& pipeline = mats[drawn[k]]->pipeline(ShaderLanguage::Glsl, colourPass_.get(), depthPass_.get());
      drawIndexed(cmd, pipeline, pipeline.depthPipeline(), sets[k], static_cast<std::uint32_t>(slice * k), vertexBuffers[k].handle(),
                  indexBuffers[k].handle(), static_cast<std::uint32_t>(scene_.objects[drawn[k]].mesh.indices.size()));
    }
    vkCmdEndRenderPass(cmd);
  });
  auto raw = depth.download(ctx_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  exposureHeights_.resize(std::size_t(kExposureResolution) * kExposureResolution);
  const auto* depths = reinterpret_cast<const float*>(raw.data());
  for (std::size_t k = 0; k < exposureHeights_.size(); ++k) exposureHeights_[k] = top - depths[k] * (top - bottom);
  exposureMap_ = vk::Image2D(ctx_, kExposureResolution, kExposureResolution, VK_FORMAT_R32_SFLOAT,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  exposureMap_.upload(ctx_, exposureHeights_.data(), exposureHeights_.size() * sizeof(float));
}

}  // namespace wg
