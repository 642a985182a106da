// The triangles a glTF scene draws: every mesh primitive of every node, in world space
// through the node transforms, with each vertex attribute read through a
// bounds-checked accessor and converted to float. Indexed and non-indexed triangle
// lists, strips and fans are all turned into one triangle list.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "compiler/diagnostic.hpp"
#include "import/gltf_asset.hpp"

namespace wg::gltf {

struct ModelPrimitive {
  std::string name;    // "MESHNAME/PRIMITIVE" for messages and object names
  int material = -1;   // -1: the glTF default material
  glm::mat4 transform{1.f};  // local to world
  std::vector<glm::vec3> positions, normals;  // normals empty when the file has none
  std::vector<glm::vec4> tangents;            // empty when the file has none
  std::vector<glm::vec2> texcoords0, texcoords1;
  std::vector<glm::vec4> colors;  // empty when the file has no COLOR_0
  std::vector<std::uint32_t> indices;  // triangle list
};

struct ModelGeometry {
  std::vector<ModelPrimitive> primitives;
  std::size_t triangleCount = 0;
};

// Most triangles drawn from one model (instances counted): bounds memory and time.
// Bounds on what a small file can make us allocate by instancing (about 600 MiB).
inline constexpr std::size_t kMaxModelTriangles = 8u << 20;
inline constexpr std::size_t kMaxModelVertices = 8u << 20;
inline constexpr std::size_t kMaxPrimitiveInstances = 65536;

// Reads the scene glTF says to show (the default scene, else scene 0, else every root
// node). Errors: WG5002 (unusable accessor types), WG5003 (a texture coordinate set a
// material needs is missing), WG5007 (out-of-range indices or accessor bytes,
// non-finite values, mismatched counts), WG1007 (too many triangles). Skins, morph
// targets, points and lines are WG5102 warnings.
std::optional<ModelGeometry> readModelGeometry(const Asset& asset, DiagnosticList& diagnostics);

}  // namespace wg::gltf
