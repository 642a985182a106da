// A stage: arbitrary objects stood on a ground plane, lit by a sun and framed by four
// camera presets. The preview stand (`render --material`) and imported models
// (`render --model`) are both built this way.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "host/scene/scene.hpp"

namespace wg::scene {

// The sun of a stage: from the front right (azimuth 60 degrees, see Orbit), 40 degrees high.
inline constexpr glm::vec3 kStageTowardsSun{0.663414f, 0.642788f, 0.383022f};

struct StageOptions {
  glm::vec3 towardsSun = kStageTowardsSun;  // need not be unit
  std::string groundGraph = "terrain";      // a SceneObject::graph value
  // World y of the ground; unset: the lowest point of the objects.
  std::optional<float> groundHeight;
};

// Returns the scene `name` made of:
// - objects: `objects` unchanged and in their order (meshes in their local space, placed
//   by their model matrices, flags kept), then "ground": a flat square of
//   options.groundGraph at the ground height, centred under the objects and wide enough
//   (kStageGroundScale times the objects' width) for shadows and wide shots; it casts
//   no shadow and does occlude the sky, and its snow is stageSnowDepth(the subject's
//   height) deep at most; then "horizon": its apron out to the horizon
//   (horizon_apron.hpp), flat, outside the bounds, with distance haze (hazeDistance).
// - subject: the objects' world bounds above the ground. Cameras frame it and
//   `--camera orbit:` turns round its centre.
// - boundsMin/boundsMax: every object, the ground included, the horizon not.
// - towardsSun: options.towardsSun, normalised.
// - cameras, in this order, all looking at the subject's centre from a distance that
//   fits every vertex above the ground into a 16:9 frame (framingDistance,
//   orbit_camera.hpp): "front" (from +z,
//   looking towards -z), "sun-side" (from the sun's horizontal direction), "shade-side"
//   (the opposite side) and "close-up" (in front, a little to the right, at 0.6 of
//   the distance).
// - no terrain height map (the ground is flat; eq. 3.12 sees no slope) and no probes.
// Object names must be distinct and neither "ground" nor "horizon". Throws std::invalid_argument when
// `objects` holds no vertex.
inline constexpr float kStageGroundScale = 4.f;
// The stand shows the model, so its ground's snow (weather.maxSnowHeight, eq. 3.10) is
// at most this share of the subject's height: a 10 cm model stands in 2.5 cm of snow,
// not under the presets' 25 cm. Subjects 1 m and taller get the full 25 cm.
inline constexpr float kStageSnowDepthShare = 0.25f;
float stageSnowDepth(float subjectHeight);
Scene stageAround(std::string name, std::vector<SceneObject> objects, const StageOptions& options = {});

}  // namespace wg::scene
