// The cameras of a frame's passes: the viewer's perspective, the sun's orthographic
// shadow view and the top-down view of the sky-exposure map. Clip space is Vulkan's
// (y down, depth 0 to 1).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>

#include "host/scene/scene.hpp"

namespace wg {

struct ClipRange {
  float nearPlane, farPlane;
};

// The fixed planes cover every bundled scene; a larger one (an imported model in
// millimetres) pushes the far plane out and the near plane with it, keeping their ratio.
ClipRange clipRange(const scene::Scene& scene, glm::vec3 eye);
glm::mat4 cameraViewProjection(const scene::CameraPreset& camera, ClipRange clip, std::uint32_t width, std::uint32_t height);
// Orthographic over the scene's bounds, looking along the light.
glm::mat4 sunViewProjection(const scene::Scene& scene, glm::vec3 towardsSun);

}  // namespace wg
