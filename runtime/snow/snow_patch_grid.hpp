// The snow layer's mesh (issue 5, §1; seed 3.1): a square of patches, each a level
// grid of vertices, centred on the camera. The seed uses 8 x 8 patches of 8 m with 64
// vertices per side (12.5 cm apart) and moves the outermost row or column of patches
// ahead of the camera (seed 2.3). Here every height comes from textures in the vertex
// stage (snow depth, noise, the deformation map), so a patch that wraps around holds
// exactly the vertices it held before: following the camera is a translation by whole
// patches, and no vertex is ever re-uploaded.
#pragma once
#include <glm/glm.hpp>

#include "runtime/scene/mesh.hpp"

namespace wg::snow {

struct PatchGridSettings {
  int patches = 8;          // per side (seed 2.3: "8 x 8 terrain patches")
  float patchSize = 8.f;    // metres (seed 3.1: LOD 3, "8 x 8 meters")
  int quadsPerPatch = 64;   // per side (seed 3.1: 64 x 64; 5.2.1: 1.25 dm apart)
  float extent() const { return float(patches) * patchSize; }
};

// The grid in its own space: level at y = 0, centred on the origin, normals up,
// tangents along +x with the bitangent along +z (the frame snow_deformation's normal
// output assumes), texcoords in patches.
scene::Mesh patchGridMesh(const PatchGridSettings& settings);

// Where the grid goes for a camera: the camera's patch in the centre, so the camera
// never gets closer than half the grid minus one patch to the edge.
glm::vec3 patchGridOrigin(const PatchGridSettings& settings, glm::vec3 camera, float groundHeight);

// How many patches a move from one camera position to another wraps to the other
// side (those the seed would rebuild); the vertex data of all of them is unchanged.
int wrappedPatches(const PatchGridSettings& settings, glm::vec3 from, glm::vec3 to);

}  // namespace wg::snow
