// Whether a camera sees a probe point: inside a square viewport's frustum, facing the
// camera and not hidden by any mesh (alpha cards count as solid).
#pragma once
#include <vector>

#include "host/scene/scene.hpp"

namespace wg::scene {

// `worldMeshes`: every object's mesh in world space.
bool cameraSees(const CameraPreset& camera, const Probe& probe, const std::vector<Mesh>& worldMeshes);
// Fills each probe's visibleFrom from the scene's cameras.
void markProbeVisibility(Scene& scene, const std::vector<Mesh>& worldMeshes);
// Every object's mesh in world space (through its model matrix).
std::vector<Mesh> worldMeshes(const Scene& scene);

}  // namespace wg::scene
