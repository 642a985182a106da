// Deterministic procedural shapes for the validation scenes. Every generator returns a
// finished mesh: unit normals, tangents from the texcoords, white vertex colours.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "host/scene/mesh.hpp"

namespace wg::scene {

// World height (metres) of the ground at (x, z).
using HeightFn = std::function<float(float x, float z)>;

// Closed axis-aligned box, flat faces with outward normals; each face's uv is its
// plane coordinates in metres (so materials tile at their own scale).
Mesh box(glm::vec3 min, glm::vec3 max);

// A sphere centred on the origin, made of a cube's six faces pushed out onto it (each
// face a `cells` x `cells` grid at equal angles), so no pole pinches the tangents. Each
// face is its own uv chart in metres along the surface; charts share positions and
// normals along their seams.
Mesh sphere(float radius, int cells = 16);

// A closed box from min to max whose edges and corners are rounded with `radius`
// (quarter circles of `bevelSteps` segments). Normals are smooth across the bevels, so
// a displacement along the normal (eq. 3.10's snow) stretches the edges instead of
// tearing the faces apart as it does on box(). Each face is its own uv chart, in metres
// on its plane.
Mesh roundedBox(glm::vec3 min, glm::vec3 max, float radius, int bevelSteps = 4);

// A wedge standing on its base: size.x wide (x), size.z deep (z), size.y tall at its
// back (the -z face, vertical); the slope rises from the front edge (z = +size.z / 2,
// y = 0) to the back's top edge. The base is centred on the origin. Flat faces, uv in
// metres in each face's plane. With an edgeRadius, edges and corners are rounded as
// roundedBox's are (bevelSteps segments per quarter turn): faces keep their planes, and
// the two 45 degree corners recede by about 1.6 times the radius.
Mesh ramp(glm::vec3 size, float edgeRadius = 0.f, int bevelSteps = 4);

// Square height field centred on the world origin: `resolution` x `resolution` cells of
// size / resolution metres, (resolution + 1)^2 vertices at y = heightFn(x, z), normals
// from central differences of the samples, uv = world xz / uvTiling.
Mesh heightFieldTerrain(float size, int resolution, const HeightFn& heightFn, float uvTiling = 8.f);

// A boulder: an icosphere subdivided `detail` times (20 * 4^detail triangles), squashed
// into a seed-dependent ellipsoid, lumped by lattice noise, cut by a few seeded fracture
// planes and a flatter base, with fine grain on top and smooth normals.
// Centred on its local origin; `radius` is the undisplaced radius. uv is a cube
// projection of the local position (in metres / 2) split into six charts, so tangents
// never degenerate; charts share positions and normals along their seams.
Mesh rock(std::uint32_t seed, float radius, int detail = 4);

// Water surface along `centreline` (points at the water level, ordered downstream),
// resampled into `segments` equal lengths. u runs downstream in units of the width;
// v runs across from 0 on the left bank to 1 on the right bank (looking downstream),
// which is what eq. 3.20's frost map F = 1 - |2v - 1| reads.
Mesh riverStrip(const std::vector<glm::vec3>& centreline, float width, int segments);

// A straight road made of sections. Each section climbs at a constant grade and has a
// crowned cross-section whose camber (fall from the crown to each edge) changes
// linearly from the previous section's to its own, so a camber needs a transition
// section before and after it.
struct RoadSection {
  float length = 10.f;        // metres along the road
  float gradeDegrees = 0.f;   // positive climbs in the road's direction
  float camberDegrees = 0.f;  // at the section's end
};
struct RoadLayout {
  glm::vec3 start{0.f};           // centreline start, y = road surface there
  glm::vec2 direction{1.f, 0.f};  // unit, world xz
  float width = 6.f;
  std::vector<RoadSection> sections;

  float length() const;
  glm::vec3 forward() const;  // horizontal unit direction
  glm::vec3 right() const;    // horizontal unit, to the right looking along the road
  // (along, across) road coordinates of a world xz point (across > 0 on the right).
  glm::vec2 toRoad(glm::vec2 xz) const;
  float centreHeight(float along) const;
  float camberDegreesAt(float along) const;
  // Height of the top surface at road coordinates (clamped to the road's extent).
  float surfaceHeight(float along, float across) const;
  glm::vec3 surfacePoint(float along, float across) const;
  // Section index at `along` (the last one past the end).
  int sectionAt(float along) const;
};
// The road's top surface (flat-shaded pieces, hard edges at section borders and at the
// crown) plus a skirt round its edges that reaches skirtDepth below them, so the road
// never shows a gap above ground graded slightly below it. u runs across (0 left edge,
// 1 right edge), v along the road in units of the width.
Mesh roadStrip(const RoadLayout& layout, float skirtDepth = 0.3f);

// `count` vertical quads crossing at `center` (the middle of their bottom edges), each
// size.x wide and size.y tall, turned evenly around Y with a seeded jitter; uv spans
// 0..1 with v = 0 at the bottom. One face per card: they are two-sided through the
// alpha-tested pipeline (no culling, normal flipped by gl_FrontFacing), and a second,
// coincident back face would only z-fight with the first.
Mesh crossedCards(glm::vec3 center, glm::vec2 size, int count, std::uint32_t seed);

// A flat roof (a thin box of size.x by size.y in xz) whose underside is `height` above
// center.y, on four square posts inset from its corners that reach kShelterFooting
// below center.y. All five are closed boxes.
inline constexpr float kShelterRoofThickness = 0.2f;
inline constexpr float kShelterPostWidth = 0.25f;
inline constexpr float kShelterPostInset = 0.4f;
inline constexpr float kShelterFooting = 0.5f;
Mesh shelter(glm::vec3 center, glm::vec2 size, float height);
// The xz centres of the shelter's posts (for grounding them on a height field).
std::vector<glm::vec2> shelterPostPositions(glm::vec3 center, glm::vec2 size);

}  // namespace wg::scene
