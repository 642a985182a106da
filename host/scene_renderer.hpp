// Renders a validation scene with exactly the shaders the compiler emitted: a
// top-down sky-exposure map (once), a sun shadow map, then the lit colour or an AOV.
// Layouts, uniforms and vertex formats all come from the materials' reflection.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "nodes/frame_state.hpp"
#include "nodes/weather_model.hpp"
#include "host/frame_recording.hpp"
#include "host/material_resources.hpp"
#include "host/sky_irradiance.hpp"
#include "vulkan/gpu_timer.hpp"
#include "host/scene/scene.hpp"
#include "weather/weather_state.hpp"

namespace wg {

class DistanceHazePass;
class PrecipitationPass;
class SkyLightBuilder;

// What work recorded after the colour pass sees (particles, post passes): the colour
// target, to be left in COLOR_ATTACHMENT_OPTIMAL, and the depth target (D32, stored,
// sampleable) in DEPTH_STENCIL_ATTACHMENT_OPTIMAL, with the camera that drew them.
struct ColourPassTargets {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  const vk::Image2D* colour = nullptr;
  const vk::Image2D* depth = nullptr;
  glm::mat4 viewProjection{1.f};
  glm::vec3 eye{0.f};
  float nearPlane = 0.f, farPlane = 0.f;
};

struct RenderRequest {
  std::string camera;  // a preset of the scene; "" takes the first
  std::uint32_t width = 960, height = 540;
  ShaderLanguage backend = ShaderLanguage::Glsl;
  std::uint32_t debugView = 0;  // compiler/debug_views.hpp: 0 lit, 1 albedo, ...
  WeatherState weather;
  std::optional<std::string> weatherPreset;  // replaces every material's preset ("none" for baselines)
  WeatherEffectOverrides weatherEffects;     // switched over every weathered material's own effects
  std::optional<std::string> quality;        // the quality tier of every weathered material (low, medium, high)
  bool shadows = true;
  // Draw only this object (the others still cast shadows and shelter from the sky);
  // "" draws all. Lets tests know which material covers a pixel.
  std::string onlyObject;
  // While every weather level is 0 the weathered and unweathered shaders give the same
  // image; bind the unweathered variant then. GPUs skip the weather with one uniform
  // branch anyway, but lavapipe runs both sides of every branch under a mask.
  bool unweatheredVariantWhenNeutral = true;
  // Per-frame model matrices for named objects (the camera-following snow layer).
  std::map<std::string, glm::mat4> objectModels;
  // A camera for this frame only, instead of the preset named by `camera`.
  std::optional<scene::CameraPreset> cameraPose;
  // Recorded right after the colour pass, in the same command buffer.
  std::function<void(const ColourPassTargets&)> afterColourPass;
  // Falling snow and rain near the viewer (host/precipitation_pass.hpp), from the
  // weather's precipitation, temperature and wind, at weather.time; lit frames only
  // (never an AOV). Off unless asked: `render` asks unless --no-precipitation.
  bool precipitation = false;
};

struct RenderedFrame {
  std::uint32_t width = 0, height = 0;
  std::vector<float> rgba;       // linear, unclamped (read back from RGBA32F)
  double gpuMilliseconds = 0.0;  // the colour pass, from timestamp queries; 0 if unsupported
};

class SceneRenderer {
 public:
  // Lit frames draw with up to `colourSamples` samples per pixel (4x MSAA by default;
  // fewer where the device lacks them, 1 for none).
  SceneRenderer(vk::Context& ctx, scene::Scene scene, std::string graphsDirectory,
                VkSampleCountFlagBits colourSamples = VK_SAMPLE_COUNT_4_BIT);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  RenderedFrame render(const RenderRequest& request);

  const scene::Scene& scene() const { return scene_; }
  // The occluder heights of the sky-exposure map (metres), for tests.
  const std::vector<float>& exposureHeights() const { return exposureHeights_; }
  std::uint32_t exposureResolution() const { return kExposureResolution; }
  glm::vec4 exposureRegion() const { return exposureRegion_; }
  glm::mat4 viewProjection(const std::string& camera, std::uint32_t width, std::uint32_t height) const;
  std::size_t gpuMemoryBytes() const;
  // The sky's diffuse light of the last lit frame (zero before one), and how often it
  // was built: once per sky (weather), never per frame; AOVs do not need it.
  const SkyIrradiance& skyIrradiance() const;
  std::size_t skyLightBuilds() const;
  // Samples per pixel of lit frames (4 where the device allows; resolved before
  // anything reads the colour); AOVs are always drawn single-sampled.
  std::uint32_t colourSamples() const { return static_cast<std::uint32_t>(colourSamples_); }
  // Every file the materials compiled so far were read from: each graph file, the
  // libraries it includes and the images it loads (what `compile --depfile` lists).
  // Sorted, each once; `render --watch` polls them.
  std::vector<std::string> materialInputFiles() const;
  // The map materials sample as "snowDeformation" (docs/deformable-snow.md): RGBA32F,
  // sampled with repeat so world xz / extent lands on the toroidal texel. Null: a flat
  // 1x1 stand-in. The image must outlive the renders that use it.
  void setSnowDeformation(const vk::Image2D* map) { snowDeformation_ = map; }

  static constexpr std::uint32_t kExposureResolution = weather::kSkyExposureResolution;
  static constexpr std::uint32_t kShadowResolution = 2048;

 private:
  struct Object;
  struct Pass;
  struct Frame;
  MaterialResources& material(const std::string& graph, const std::optional<std::string>& preset,
                              const std::optional<std::string>& quality, const WeatherEffectOverrides& effects,
                              const std::map<std::string, float>& parameters);
  vk::MaterialPipeline& pipelineOf(MaterialResources& material, const RenderRequest& request);
  void uploadTerrain();
  // The sky-exposure map, built once (sky_exposure_map.cpp).
  void buildExposureMap();

  // The steps of render(), in order.
  std::vector<MaterialResources*> materialsFor(const RenderRequest& request);
  void uploadObjects(const std::vector<MaterialResources*>& materials);
  const scene::CameraPreset& cameraFor(const RenderRequest& request) const;
  std::vector<Pass> passesFor(const Frame& frame) const;
  glm::mat4 modelOf(std::size_t object, const RenderRequest& request) const;
  FrameState sharedFrameState(const Frame& frame) const;
  void writeFrameSlices(Frame& frame) const;
  void allocateDescriptorSets(Frame& frame);
  void createTargets(Frame& frame);
  bool multisampled(const RenderRequest& request) const;
  VkRenderPass colourPassFor(const RenderRequest& request) const;
  std::vector<std::size_t> drawOrder(const Frame& frame) const;
  std::vector<ObjectDraw> drawsOf(Frame& frame, std::size_t pass, const std::vector<std::size_t>& order);
  void recordScenePass(VkCommandBuffer cmd, Frame& frame, std::size_t pass, const std::vector<std::size_t>& order);
  void recordHaze(const ColourPassTargets& targets, const FrameState& frame, const WeatherState& weather);
  void recordPrecipitation(const ColourPassTargets& targets, const WeatherState& weather);
  RenderedFrame readBack(Frame& frame);

  vk::Context& ctx_;
  scene::Scene scene_;
  std::string graphsDirectory_;
  // The lit colour pass (colourSamples_ per pixel), the single-sampled pass AOVs are
  // drawn in, and the depth-only pass; they outlive the materials' pipelines.
  VkSampleCountFlagBits colourSamples_ = VK_SAMPLE_COUNT_1_BIT;
  vk::UniqueRenderPass colourPass_, aovPass_, depthPass_;
  std::map<std::string, std::unique_ptr<MaterialResources>> materials_;  // by graph + preset
  std::vector<std::unique_ptr<Object>> objects_;
  vk::Image2D terrainHeight_, exposureMap_, shadowMap_, placeholderHeight_, placeholderShadow_, placeholderDeformation_;
  vk::Image2D weatherNoise_;  // the weather's shared noise texture, uploaded once
  const vk::Image2D* snowDeformation_ = nullptr;
  vk::UniqueSampler linearClamp_;
  vk::UniqueSampler linearRepeat_;  // the toroidal snow deformation map
  vk::UniqueSampler nearestClamp_;  // depth formats need not be filterable; PCF filters
  vk::UniqueSampler trilinearClamp_;  // the sky's reflection: a roughness per level
  std::vector<float> exposureHeights_;
  glm::vec4 exposureRegion_{0.f};
  vk::GpuTimer timer_;  // the colour pass
  std::unique_ptr<DistanceHazePass> haze_;            // made on the first frame that draws it
  std::unique_ptr<SkyLightBuilder> skyLight_;  // its shaders compiled on the first lit frame
  std::unique_ptr<PrecipitationPass> precipitation_;  // made on the first frame that draws it
};

}  // namespace wg
