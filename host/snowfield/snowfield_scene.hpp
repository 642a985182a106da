// The `snowfield` scene of the interactive snow: snowy hills with a few
// rocks running out to a hazy horizon, the camera-following snow layer on the terrain, two walkers and a vehicle on scripted paths,
// and a camera that leaves the deformation window and comes back. SnowfieldAnimation
// advances it in simulated time; the renderer draws it with the deformation map bound.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "host/bloom_pass.hpp"
#include "host/scene/scene.hpp"
#include "snow/gpu_deformation_map.hpp"
#include "snow/snow_interactors.hpp"
#include "host/snowfield/snow_patch_grid.hpp"
#include "host/snowfield/snow_puffs.hpp"
#include "host/snowfield/snowfield_figures.hpp"
#include "host/snowfield/snow_weather.hpp"
#include "vulkan/gpu_image.hpp"

namespace wg::snow {

inline constexpr const char* kSnowfieldScene = "snowfield";
inline constexpr const char* kSnowLayerObject = "snowLayer";
inline constexpr const char* kSnowLayerGraph = "snow_layer";

struct SnowfieldSettings {
  WindowSettings window;      // the deformation map (default 1024² at 4 cm)
  PatchGridSettings grid;     // the layer's mesh (default: the seed's 8 x 8 patches of 8 m)
  // 12 cm at full cover (graphs/snow_layer.json's snowDepth): prints 8 cm deep whose
  // floors the camera sees, and shallower than the walkers lift their feet, so every
  // footprint stands alone.
  SnowWeatherSettings weather{0.12f};
  double frameSeconds = 1.0 / 30.0;   // simulation step
};

scene::Scene makeSnowfieldScene(const SnowfieldSettings& settings = {});
glm::vec3 snowfieldTowardsSun();  // unit: low and ahead of the camera, so glitter faces it
// The snowfield's terrain (the snow layer's base) at world (x, z): hills on a plain at
// y = 0. The scene's terrain height map holds it; the ground mesh lies 5 cm under it.
float snowfieldGround(float x, float z);

// One moment of the animation, ready to render.
struct SnowfieldMoment {
  double time = 0.0;
  scene::CameraPreset camera;
  std::map<std::string, glm::mat4> objectModels;  // the layer and the movers
  std::vector<std::string> caption;
};

class SnowfieldAnimation {
 public:
  SnowfieldAnimation(vk::Context& ctx, const SnowfieldSettings& settings, const WeatherState& weather);

  // Advances the simulation to `seconds` (never backwards).
  SnowfieldMoment advanceTo(double seconds);
  // What the snow layer samples as snowDeformation (kept current by the map's passes).
  const vk::Image2D& deformationImage() const { return map_.surfaceImage(); }
  // Snow puffs and bloom, to record after the colour pass
  // (RenderRequest::afterColourPass); the renderer hazes the frame before them
  // (Scene::hazeDistance).
  std::function<void(const ColourPassTargets&)> postPasses();
  const SnowPuffs& puffs() const { return puffs_; }
  GpuDeformationMap& map() { return map_; }
  // Times of the frames the gallery shows: prints forming, the camera leaving the
  // window, far away, and back over the restored prints.
  static std::vector<double> keyTimes();
  glm::vec3 cameraEye(double seconds) const;

 private:
  void step(double t0, double t1);

  SnowfieldSettings settings_;
  WeatherState weather_;
  GpuDeformationMap map_;
  std::vector<Walker> walkers_;
  Vehicle vehicle_;
  SnowPuffs puffs_;
  BloomPass bloom_;
  double time_ = 0.0;
  std::size_t stamps_ = 0;
};

}  // namespace wg::snow
