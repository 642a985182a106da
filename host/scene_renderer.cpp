#include "host/scene_renderer.hpp"

#include <algorithm>
#include <cstring>
#include <set>
#include <stdexcept>

#include <glm/gtc/packing.hpp>

#include "compiler/material_input_files.hpp"
#include "nodes/pbr_shading.hpp"
#include "nodes/weather_noise.hpp"
#include "host/descriptor_sets.hpp"
#include "host/distance_haze_pass.hpp"
#include "host/draw_order.hpp"
#include "host/frame_recording.hpp"
#include "host/frame_slices.hpp"
#include "host/pass_cameras.hpp"
#include "host/precipitation_pass.hpp"
#include "host/render_passes.hpp"
#include "host/sky_light_builder.hpp"
#include "vulkan/texture_sampler.hpp"
#include "host/scene/graph_path.hpp"
#include "weather/frame_weather.hpp"

namespace wg {

namespace {
// Lighting constants of the validation scenes (linear radiance).
constexpr glm::vec3 kSunColor{3.2f, 3.05f, 2.8f};  // a clear midday sun against the tone curve
constexpr glm::vec3 kSkyColor{0.45f, 0.55f, 0.72f};
constexpr float kAmbientIntensity = 0.8f;
constexpr float kToneExposure = 1.f;
// Where, as a fraction of the far plane, distance haze starts rising to all sky: the
// ground ahead fades out over its last 65 %, so the horizon is soft, not a line.
constexpr float kHazeHorizonFrom = 0.35f;

// Lit frames of a scene with haze fade into the sky with distance; AOVs never do.
bool drawsHaze(const scene::Scene& s, const RenderRequest& r) { return s.hazeDistance > 0.f && r.debugView == 0; }

// Lit frames asked for precipitation draw it when something falls.
bool drawsPrecipitation(const RenderRequest& r) {
  return r.precipitation && r.debugView == 0 && precipitationField(r.weather.conditions).total() > 0;
}
}  // namespace

struct SceneRenderer::Object {
  const scene::SceneObject* source = nullptr;
  UploadedMesh mesh;
};

// One depth or colour pass of a frame and the maps it samples.
struct SceneRenderer::Pass {
  bool colour = false;
  glm::mat4 viewProjection{1.f};
  glm::vec3 eye{0.f};
  VkImageView exposureView = VK_NULL_HANDLE, shadowView = VK_NULL_HANDLE;
};

// What one render() draws with; it goes once the frame's submit has completed.
// Declared so that framebuffers go before their images and the pool before its buffer.
struct SceneRenderer::Frame {
  const RenderRequest& request;
  std::vector<MaterialResources*> materials;  // per object
  const scene::CameraPreset* camera = nullptr;
  ClipRange clip{};
  glm::vec3 towardsSun{0.f};
  glm::mat4 light{1.f};
  SkyIrradiance skyIrradiance;  // the sky's diffuse light; lit frames only
  std::vector<Pass> passes;
  std::optional<FrameSlices> slices;  // per (pass, object)
  vk::UniqueDescriptorPool pool;
  std::vector<std::array<VkDescriptorSet, 2>> sets;  // per (pass, object)
  vk::Image2D colour, depth;  // single-sampled: what later passes and the read-back see
  vk::Image2D multisampledColour, multisampledDepth;  // lit frames on a multisampled pass
  vk::UniqueFramebuffer colourTarget, shadowTarget;

  std::size_t slot(std::size_t pass, std::size_t object) const { return pass * materials.size() + object; }
};

SceneRenderer::SceneRenderer(vk::Context& ctx, scene::Scene scene, std::string graphsDirectory,
                             VkSampleCountFlagBits colourSamples)
    : ctx_(ctx), scene_(std::move(scene)), graphsDirectory_(std::move(graphsDirectory)), timer_(ctx) {
  colourSamples_ = colourPassSamples(ctx_, colourSamples);
  colourPass_ = colourSamples_ == VK_SAMPLE_COUNT_1_BIT ? createColourPass(ctx_.device(), vk::kColourFormat)
                                                       : createMultisampledColourPass(ctx_, colourSamples_);
  aovPass_ = createColourPass(ctx_.device(), vk::kAovFormat);
  depthPass_ = createDepthOnlyPass(ctx_.device());
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
  trilinearClamp_ = vk::createSampler(ctx_, "clamp", "clamp", "linear", "linear", vk::MipSampling::FullChain);
  skyLight_ = std::make_unique<SkyLightBuilder>(ctx_);
  const Image& noise = weather::noiseImage();  // the weather's noise texture, sampled with linearRepeat_
  weatherNoise_ = vk::Image2D(ctx_, static_cast<std::uint32_t>(noise.width), static_cast<std::uint32_t>(noise.height),
                              VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  weatherNoise_.upload(ctx_, noise.rgba.data(), noise.rgba.size());
  shadowMap_ = vk::Image2D(ctx_, kShadowResolution, kShadowResolution, vk::kDepthFormat,
                           VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  uploadTerrain();
  buildExposureMap();
}

SceneRenderer::~SceneRenderer() { vkDeviceWaitIdle(ctx_.device()); }

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

// One compiled material per graph, preset, quality tier, effect overrides and parameter
// values; the unweathered variant ignores the tier and the overrides, so every request
// shares it.
MaterialResources& SceneRenderer::material(const std::string& graph, const std::optional<std::string>& preset,
                                           const std::optional<std::string>& quality,
                                           const WeatherEffectOverrides& effects,
                                           const std::map<std::string, float>& parameters) {
  const bool unweathered = preset == "none";
  std::string key = graph + "|" + preset.value_or("");
  for (const auto& [name, value] : parameters) key += "|" + name + "=" + std::to_string(value);
  if (!unweathered) {
    key += "|" + quality.value_or("");
    for (const auto& [name, on] : effects) key += "|" + name + (on ? "=on" : "=off");
  }
  auto& slot = materials_[key];
  if (!slot) {
    CompileOptions options;
    options.weatherPreset = preset;
    if (!unweathered) {
      options.weatherEffects = effects;
      options.quality.requested = quality;
    }
    slot = std::make_unique<MaterialResources>(ctx_, scene::graphFilePath(graph, graphsDirectory_), options, parameters);
  }
  return *slot;
}

glm::mat4 SceneRenderer::viewProjection(const std::string& camera, std::uint32_t width, std::uint32_t height) const {
  const scene::CameraPreset* preset = scene_.cameras.empty() ? nullptr : &scene_.cameras.front();
  for (const auto& c : scene_.cameras)
    if (c.name == camera) preset = &c;
  if (!preset) throw std::runtime_error("scene '" + scene_.name + "' has no cameras");
  return cameraViewProjection(*preset, clipRange(scene_, preset->eye), width, height);
}

std::size_t SceneRenderer::gpuMemoryBytes() const {
  std::size_t n = terrainHeight_.byteSize() + exposureMap_.byteSize() + shadowMap_.byteSize() + skyLight_->reflectionBytes();
  for (const auto& o : objects_) n += o->mesh.vertices.size() + o->mesh.indices.size();
  for (const auto& [key, m] : materials_) n += m->textureBytes();
  return n;
}

const SkyIrradiance& SceneRenderer::skyIrradiance() const {
  return skyLight_->irradiance();
}

std::size_t SceneRenderer::skyLightBuilds() const { return skyLight_->builds(); }

std::vector<std::string> SceneRenderer::materialInputFiles() const {
  std::set<std::string> files;
  for (const auto& [key, m] : materials_) {
    files.insert(m->graphPath());
    for (auto& file : wg::materialInputFiles(m->compiled().ir)) files.insert(std::move(file));
  }
  return {files.begin(), files.end()};
}

RenderedFrame SceneRenderer::render(const RenderRequest& request) {
  ctx_.clearValidationMessages();
  Frame frame{request, materialsFor(request)};
  uploadObjects(frame.materials);
  frame.camera = &cameraFor(request);
  frame.clip = clipRange(scene_, frame.camera->eye);
  const auto& sun = request.weather.conditions.sunDirection;
  frame.towardsSun = glm::normalize(glm::vec3(sun[0], sun[1], sun[2]));
  frame.light = sunViewProjection(scene_, frame.towardsSun);
  frame.passes = passesFor(frame);
  if (request.debugView == 0) frame.skyIrradiance = skyLight_->lightFor(sharedFrameState(frame));
  writeFrameSlices(frame);
  allocateDescriptorSets(frame);
  createTargets(frame);
  const std::vector<std::size_t> order = drawOrder(frame);
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    timer_.reset(cmd);
    for (std::size_t p = 0; p < frame.passes.size(); ++p) recordScenePass(cmd, frame, p, order);
  });
  return readBack(frame);
}

// Materials for this request's preset: the unweathered variant while the weather is
// neutral, unless the request turns that off.
std::vector<MaterialResources*> SceneRenderer::materialsFor(const RenderRequest& request) {
  const WeatherLevels& levels = request.weather.levels;
  bool neutral = std::all_of(kLevelMembers.begin(), kLevelMembers.end(), [&](auto level) { return levels.*level <= 0.f; });
  std::optional<std::string> preset = request.weatherPreset;
  if (!preset && neutral && request.unweatheredVariantWhenNeutral) preset = "none";
  std::vector<MaterialResources*> mats;
  for (const auto& o : scene_.objects)
    mats.push_back(&material(o.graph, preset, request.quality, request.weatherEffects, o.parameters));
  return mats;
}

// Meshes go up once, in the first render's vertex formats: every variant of a graph
// reflects the same vertex inputs.
void SceneRenderer::uploadObjects(const std::vector<MaterialResources*>& mats) {
  if (!objects_.empty()) return;
  for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
    auto obj = std::make_unique<Object>();
    obj->source = &scene_.objects[i];
    obj->mesh = uploadMesh(ctx_, obj->source->mesh, vk::vertexLayoutFrom(mats[i]->reflection()));
    objects_.push_back(std::move(obj));
  }
}

const scene::CameraPreset& SceneRenderer::cameraFor(const RenderRequest& request) const {
  if (request.cameraPose) return *request.cameraPose;
  const scene::CameraPreset* camera = &scene_.cameras.front();
  for (const auto& c : scene_.cameras)
    if (c.name == request.camera) camera = &c;
  return *camera;
}

std::vector<SceneRenderer::Pass> SceneRenderer::passesFor(const Frame& frame) const {
  const RenderRequest& request = frame.request;
  std::vector<Pass> passes;
  if (request.shadows) passes.push_back({false, frame.light, frame.camera->eye, exposureMap_.view(), placeholderShadow_.view()});
  passes.push_back({true, cameraViewProjection(*frame.camera, frame.clip, request.width, request.height), frame.camera->eye,
                    exposureMap_.view(), request.shadows ? shadowMap_.view() : placeholderShadow_.view()});
  return passes;
}

glm::mat4 SceneRenderer::modelOf(std::size_t object, const RenderRequest& request) const {
  auto moved = request.objectModels.find(objects_[object]->source->name);
  return moved != request.objectModels.end() ? moved->second : objects_[object]->source->model;
}

namespace {
// The sky's tint (wg_sky_tint), overcast in snow and rain and darker in a blizzard: the
// clear colour under the sky the haze pass draws, and the precipitation's ambient.
glm::vec3 weatherSkyColour(const WeatherState& weather) {
  auto tint = skyTint({kSkyColor.r, kSkyColor.g, kSkyColor.b}, weather.conditions.precipitation,
                      weather.conditions.windIntensity);
  return {tint[0], tint[1], tint[2]};
}
}  // namespace

// The block's values shared by every pass and object of a frame.
FrameState SceneRenderer::sharedFrameState(const Frame& frame) const {
  FrameState uniforms;
  writeWeather(frame.request.weather, uniforms);
  storeInto(uniforms.sunDirection, frame.towardsSun);  // unit length, as the block requires
  storeInto(uniforms.lightViewProjection, frame.light);
  storeInto(uniforms.skyExposureRegion, exposureRegion_);
  storeInto(uniforms.terrainRegion, scene_.terrainRegion);
  writeSkyIrradiance(frame.skyIrradiance, uniforms);
  storeInto(uniforms.sunColor, kSunColor);
  uniforms.ambientIntensity = kAmbientIntensity;
  storeInto(uniforms.skyColor, kSkyColor);
  uniforms.exposure = kToneExposure;
  uniforms.debugView = frame.request.debugView;
  uniforms.terrainHeightScale = scene_.terrainHeightScale;
  uniforms.shadowMapTexel = frame.request.shadows ? 1.f / float(kShadowResolution) : 0.f;
  return uniforms;
}

// One slice per (pass, object); only the matrices and the eye differ between them.
void SceneRenderer::writeFrameSlices(Frame& frame) const {
  const vk::ReflectedBlock& block = frame.materials.front()->reflection().frame;
  frame.slices.emplace(ctx_, block, frame.passes.size() * objects_.size());
  FrameState uniforms = sharedFrameState(frame);
  for (std::size_t p = 0; p < frame.passes.size(); ++p)
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      glm::mat4 model = modelOf(i, frame.request);
      storeInto(uniforms.model, model);
      storeInto(uniforms.viewProjection, frame.passes[p].viewProjection);
      storeInto(uniforms.normalMatrix, glm::transpose(glm::inverse(model)));
      storeInto(uniforms.cameraPosition, frame.passes[p].eye);
      FrameUniforms f(block);
      f.set(uniforms);
      frame.slices->write(frame.slot(p, i), f);
    }
}

// Set 0 and set 1 per (pass, object), from a pool sized for exactly those.
void SceneRenderer::allocateDescriptorSets(Frame& frame) {
  const std::size_t setCount = 2 * frame.passes.size() * objects_.size();
  std::uint32_t images = 0;
  for (auto* m : frame.materials)
    images += static_cast<std::uint32_t>(m->reflection().textures.size() + m->reflection().weatherMaps.size());
  images = (images + 1) * static_cast<std::uint32_t>(frame.passes.size());
  const auto sets = static_cast<std::uint32_t>(setCount);
  frame.pool = createMaterialDescriptorPool(ctx_.device(), sets, sets, images);
  DescriptorWriter writer;
  frame.sets.resize(frame.passes.size() * objects_.size());
  for (std::size_t p = 0; p < frame.passes.size(); ++p)
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      const Pass& pass = frame.passes[p];
      SharedMaps maps{terrainHeight_.view(), pass.exposureView, pass.shadowView,
                      (snowDeformation_ ? *snowDeformation_ : placeholderDeformation_).view(), weatherNoise_.view(),
                      skyLight_->reflectionView(), linearClamp_.get(), nearestClamp_.get(), linearRepeat_.get(),
                      trilinearClamp_.get()};
      maps.baseLevelTextures = frame.request.debugView != 0;  // AOVs read textures as the CPU evaluator does
      MaterialResources& m = *frame.materials[i];
      frame.sets[frame.slot(p, i)] = allocateMaterialSets(ctx_.device(), frame.pool.get(), m, pipelineOf(m, frame.request),
                                                          writer, frame.slices->buffer(), frame.slices->blockSize(), maps);
    }
  writer.apply(ctx_.device());
}

vk::MaterialPipeline& SceneRenderer::pipelineOf(MaterialResources& material, const RenderRequest& request) {
  return material.pipeline(request.backend, {colourPass_.get(), colourSamples_, aovPass_.get(), depthPass_.get()});
}

// Lit frames draw multisampled where the device allows; AOVs single-sampled, so every
// pixel they read back is one surface's value at the pixel centre, as the CPU evaluator
// computes it (a resolve would average across edges).
bool SceneRenderer::multisampled(const RenderRequest& r) const {
  return r.debugView == 0 && colourSamples_ != VK_SAMPLE_COUNT_1_BIT;
}

VkRenderPass SceneRenderer::colourPassFor(const RenderRequest& r) const {
  return r.debugView == 0 ? colourPass_.get() : aovPass_.get();
}

// Later passes (request.afterColourPass) may write the colour in compute and sample the depth.
void SceneRenderer::createTargets(Frame& frame) {
  const RenderRequest& r = frame.request;
  const bool hazed = drawsHaze(scene_, r);
  VkImageUsageFlags later = r.afterColourPass || hazed ? VK_IMAGE_USAGE_STORAGE_BIT : 0;
  frame.colour = vk::Image2D(ctx_, r.width, r.height, r.debugView == 0 ? vk::kColourFormat : vk::kAovFormat,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | later);
  frame.depth = vk::Image2D(ctx_, r.width, r.height, vk::kDepthFormat,
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                (r.afterColourPass || hazed || drawsPrecipitation(r) ? VK_IMAGE_USAGE_SAMPLED_BIT : 0));
  if (multisampled(r)) {
    frame.multisampledColour = vk::Image2D(ctx_, r.width, r.height, vk::kColourFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, 1,
                                           colourSamples_);
    frame.multisampledDepth = vk::Image2D(ctx_, r.width, r.height, vk::kDepthFormat,
                                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, 1, colourSamples_);
    frame.colourTarget = createFramebuffer(
        ctx_.device(), colourPass_.get(),
        {frame.multisampledColour.view(), frame.multisampledDepth.view(), frame.colour.view(), frame.depth.view()}, r.width,
        r.height);
  } else {
    frame.colourTarget = createFramebuffer(ctx_.device(), colourPassFor(r), {frame.colour.view(), frame.depth.view()},
                                           r.width, r.height);
  }
  frame.shadowTarget = createFramebuffer(ctx_.device(), depthPass_.get(), {shadowMap_.view()}, kShadowResolution, kShadowResolution);
}

// Blended objects after the others, farthest first; AOVs draw them opaque.
std::vector<std::size_t> SceneRenderer::drawOrder(const Frame& frame) const {
  std::vector<DrawCandidate> candidates;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    bool blended = frame.materials[i]->reflection().blended();
    candidates.push_back({blended, blended ? worldCentre(objects_[i]->source->mesh, modelOf(i, frame.request)) : glm::vec3(0.f)});
  }
  return colourDrawOrder(candidates, frame.camera->eye);
}

// The shadow pass draws what casts shadows; the colour pass what the request shows.
std::vector<ObjectDraw> SceneRenderer::drawsOf(Frame& frame, std::size_t p, const std::vector<std::size_t>& order) {
  const bool colour = frame.passes[p].colour, aov = frame.request.debugView != 0;
  std::vector<ObjectDraw> draws;
  for (std::size_t i : order) {
    const scene::SceneObject& source = *objects_[i]->source;
    if (!colour && !source.castsShadow) continue;
    if (colour && !frame.request.onlyObject.empty() && source.name != frame.request.onlyObject) continue;
    auto& pipeline = pipelineOf(*frame.materials[i], frame.request);
    draws.push_back({&pipeline, colour ? pipeline.colourPipeline(aov) : pipeline.depthPipeline(), frame.sets[frame.slot(p, i)],
                     frame.slices->offset(frame.slot(p, i)), &objects_[i]->mesh});
  }
  return draws;
}

void SceneRenderer::recordScenePass(VkCommandBuffer cmd, Frame& frame, std::size_t p, const std::vector<std::size_t>& order) {
  const Pass& pass = frame.passes[p];
  const RenderRequest& r = frame.request;
  VkClearValue depthClear;
  depthClear.depthStencil = {1.f, 0};
  if (!pass.colour) {
    recordPass(cmd, {depthPass_.get(), frame.shadowTarget.get(), kShadowResolution, kShadowResolution, {depthClear}},
               drawsOf(frame, p, order));
    return;
  }
  // AOVs clear to alpha 0, which no surface writes, so read-backs can tell sky from surface.
  VkClearValue colourClear;
  const glm::vec3 sky = weatherSkyColour(r.weather);
  if (r.debugView == 0) colourClear.color = {{sky.r, sky.g, sky.b, 1.f}};
  else colourClear.color = {{0.f, 0.f, 0.f, 0.f}};
  timer_.start(cmd);
  recordPass(cmd, {colourPassFor(r), frame.colourTarget.get(), r.width, r.height, {colourClear, depthClear}},
             drawsOf(frame, p, order));
  timer_.stop(cmd);
  const ColourPassTargets targets{cmd, &frame.colour, &frame.depth, pass.viewProjection, pass.eye, frame.clip.nearPlane,
                                  frame.clip.farPlane};
  // Haze first: falling flakes near the viewer are not as far away as the ground behind them.
  if (drawsHaze(scene_, r)) recordHaze(targets, sharedFrameState(frame), r.weather);
  if (drawsPrecipitation(r)) recordPrecipitation(targets, r.weather);
  if (r.afterColourPass) r.afterColourPass(targets);
}

// The sky the surfaces reflect, and haze towards it, so the ground meets the sky without a seam.
void SceneRenderer::recordHaze(const ColourPassTargets& targets, const FrameState& frame, const WeatherState& weather) {
  if (!haze_) haze_ = std::make_unique<DistanceHazePass>(ctx_, kSunColor);
  HazeSettings settings;
  // The scene's own haze and the falling snow or rain dim the view together.
  settings.distance = 1.f / (1.f / scene_.hazeDistance + precipitationExtinction(weather.conditions));
  settings.horizonFrom = kHazeHorizonFrom;
  haze_->record(targets, frame, settings);
}

// Falling snow and rain over the lit colour, lit by the frame's sun and sky.
void SceneRenderer::recordPrecipitation(const ColourPassTargets& targets, const WeatherState& weather) {
  if (!precipitation_) precipitation_ = std::make_unique<PrecipitationPass>(ctx_);
  const PrecipitationLight light{kSunColor * weather.conditions.sunIntensity, weatherSkyColour(weather) * kAmbientIntensity,
                                 kToneExposure};
  precipitation_->record(targets, precipitationField(weather.conditions), light, weather.time);
}

RenderedFrame SceneRenderer::readBack(Frame& frame) {
  RenderedFrame out;
  out.width = frame.request.width;
  out.height = frame.request.height;
  out.gpuMilliseconds = timer_.milliseconds();
  auto raw = frame.colour.download(ctx_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  out.rgba.resize(std::size_t(out.width) * out.height * 4);
  if (frame.colour.format() == vk::kAovFormat) {
    std::memcpy(out.rgba.data(), raw.data(), out.rgba.size() * sizeof(float));
  } else {
    for (std::size_t i = 0; i < out.rgba.size(); ++i) {
      std::uint16_t half;
      std::memcpy(&half, raw.data() + 2 * i, sizeof half);
      out.rgba[i] = glm::unpackHalf1x16(half);
    }
  }
  return out;
}

}  // namespace wg
