// Cameras on a sphere round a scene: `render --camera orbit:AZIMUTH,ELEVATION[,DISTANCE]`
// and the presets a stage frames (stage.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "host/scene/scene.hpp"

namespace wg::scene {

inline constexpr float kOrbitFovYDegrees = 40.f;
inline constexpr float kWideAspect = 16.f / 9.f;  // the default frame (960x540)
// Elevations stop short of straight up or down, where "up" no longer orients the view.
inline constexpr float kOrbitMaxElevationDegrees = 89.f;
// Distances stay well inside the renderer's far plane (600 m).
inline constexpr float kOrbitMaxDistance = 500.f;

struct Orbit {
  // Degrees from +z towards +x, seen from above: 0 puts the camera on the +z side
  // looking towards -z, 90 on the +x side.
  float azimuthDegrees = 0.f;
  float elevationDegrees = 0.f;  // above the horizontal
  std::optional<float> distance;  // metres from the target; unset: framed
};

// How far from `target` a camera looking at it from the orbit's direction must stand
// for every point to fit a frame of `aspect` (width / height), with a small margin.
float framingDistance(const std::vector<glm::vec3>& points, glm::vec3 target, float azimuthDegrees,
                      float elevationDegrees, float aspect, float fovYDegrees = kOrbitFovYDegrees);
// The same for the eight corners of `bounds`, looking at its centre.
float framingDistance(const Bounds& bounds, float azimuthDegrees, float elevationDegrees, float aspect,
                      float fovYDegrees = kOrbitFovYDegrees);

// A camera looking at `target` from the orbit's direction and distance.
CameraPreset orbitCamera(std::string name, glm::vec3 target, float azimuthDegrees, float elevationDegrees,
                         float distance, float fovYDegrees = kOrbitFovYDegrees);
// Looking at the centre of the scene's framed bounds; an unset distance frames them in
// a frame of `aspect`.
CameraPreset orbitCamera(const Scene& scene, const Orbit& orbit, float aspect);

}  // namespace wg::scene
