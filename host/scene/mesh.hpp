// Triangle meshes of the validation scenes, in the layout the Vulkan runtime uploads:
// one array per vertex attribute plus a triangle list. World space is Y-up, metres,
// right-handed; front faces wind counter-clockwise seen from outside.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace wg::scene {

struct Mesh {
  std::vector<glm::vec3> positions, normals;
  // xyz: unit, orthogonal to the normal, along +u; w = +-1 so that the bitangent (+v)
  // is cross(normal, tangent.xyz) * w, the convention of wg_tangent_to_world.
  std::vector<glm::vec4> tangents;
  std::vector<glm::vec2> texcoords;
  std::vector<glm::vec2> texcoords1;  // a second set (glTF TEXCOORD_1); empty: texcoord 0 stands in
  std::vector<glm::vec4> colors;
  std::vector<std::uint32_t> indices;  // triangle list
};

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};
  bool empty() const { return min.x > max.x; }
  void include(glm::vec3 p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void include(const Bounds& b) {
    if (b.empty()) return;
    include(b.min);
    include(b.max);
  }
};

// Where a ray meets a mesh: the interpolated (unit) vertex normal and texcoord there.
struct SurfaceHit {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 texcoord;
  float distance;
  std::uint32_t triangle;
};

std::size_t triangleCount(const Mesh& mesh);
// Triangle `tri`'s face normal by its winding, unnormalised: its length is twice the area.
glm::vec3 faceNormal(const Mesh& mesh, std::size_t tri);

// Adds a vertex with the given attributes; the tangent is left for computeTangents.
std::uint32_t addVertex(Mesh& mesh, glm::vec3 position, glm::vec3 normal, glm::vec2 texcoord,
                        glm::vec4 color = glm::vec4(1.f));
// Adds triangle (a, b, c), reversed if needed so that its face normal points along `outward`.
void addTriangleFacing(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, glm::vec3 outward);
// Adds the quad with consecutive corners a, b, c, d (either winding) facing `outward`.
void addQuadFacing(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, glm::vec3 outward);

// Area-weighted smooth vertex normals from the triangles (vertices are not welded).
void computeNormals(Mesh& mesh);
// Per-vertex tangents from the texcoord derivatives of the adjacent triangles, made
// orthogonal to the normal (Gram-Schmidt); w is the handedness of the uv frame.
void computeTangents(Mesh& mesh);

// Appends src transformed by `transform` (normals by its inverse transpose; a mirroring
// transform flips the winding and the tangent sign so faces stay front-facing).
void append(Mesh& dst, const Mesh& src, const glm::mat4& transform = glm::mat4(1.f));
Mesh transformed(const Mesh& mesh, const glm::mat4& transform);

Bounds bounds(const Mesh& mesh);
Bounds bounds(const Mesh& mesh, const glm::mat4& transform);

// The nearest intersection of the ray origin + t * direction (t > 0) with any triangle,
// from either side; direction need not be unit (distance is in units of its length).
std::optional<SurfaceHit> raycast(const Mesh& mesh, glm::vec3 origin, glm::vec3 direction);
// The highest point of the mesh on the vertical line through (x, z), if any.
std::optional<SurfaceHit> topSurfaceAt(const Mesh& mesh, float x, float z);

}  // namespace wg::scene
