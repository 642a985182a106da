// The snow layer's mesh (seed 3.1): a square of patches, each a level
// grid of vertices, centred on the camera. The seed uses 8 x 8 patches of 8 m with 64
// vertices per side (12.5 cm apart). Its prints are 9-11 cm wide, narrower than that
// spacing, so a finer square around the camera puts a vertex on every texel of the 4 cm
// print map: the grid's columns and rows are spaced finely inside it and coarsely
// outside (a tensor grid, so there are no T-junctions and no cracks). Every height
// comes from textures in the vertex stage (snow depth, noise, terrain, the deformation
// map), so moving the grid is a translation: it follows the camera by whole steps that
// are multiples of both spacings, every vertex lands where a vertex stood before, and
// no vertex is ever re-uploaded (seed 2.3 moves whole patches the same way).
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "host/scene/mesh.hpp"

namespace wg::snow {

struct PatchGridSettings {
  int patches = 8;          // per side (seed 2.3: "8 x 8 terrain patches")
  float patchSize = 8.f;    // metres (seed 3.1: LOD 3, "8 x 8 meters")
  int quadsPerPatch = 64;   // per side (seed 3.1: 64 x 64; 5.2.1: 1.25 dm apart)
  // The fine square around the camera (half its side; 0: none) and its spacing: one
  // texel of the default print map, so heel, toe and rims are in the geometry.
  float fineHalfWidth = 8.f;
  float fineSpacing = 0.04f;
  // The grid moves by whole steps: 1 m is 8 coarse and 25 fine quads.
  float followStep = 1.f;
  float extent() const { return float(patches) * patchSize; }
  float spacing() const { return patchSize / float(quadsPerPatch); }
};

// The grid in its own space: level at y = 0, centred on the origin, normals up,
// tangents along +x with the bitangent along +z (the frame snow_deformation's normal
// output assumes), texcoords in patches. Throws std::invalid_argument for settings
// whose fine square or step is not a whole number of quads.
scene::Mesh patchGridMesh(const PatchGridSettings& settings);

// The x (and z) coordinates of the grid's columns (rows), from -extent/2 to +extent/2.
std::vector<float> patchGridLines(const PatchGridSettings& settings);

// Where the grid goes to centre its fine square on `focus` (the camera, or the ground it
// looks at): the nearest whole step, so the focus is never more than half a step off.
// Keep the focus within half the grid minus the border fade of the camera.
glm::vec3 patchGridOrigin(const PatchGridSettings& settings, glm::vec3 focus, float groundHeight);

// How many patches a move from one camera position to another wraps to the other
// side (those the seed would rebuild); the vertex data of all of them is unchanged.
int wrappedPatches(const PatchGridSettings& settings, glm::vec3 from, glm::vec3 to);

}  // namespace wg::snow
