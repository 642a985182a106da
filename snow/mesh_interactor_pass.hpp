// Any mesh as an interactor: the engine's vertex and index buffers drawn with an
// orthographic projection from below into the deformation map, merged by the same
// atomicMax as the stamps (deformation_shaders.cpp, kMeshFragment). The framebuffer has
// no attachments: it only gives the raster the window's N x N texels, and the fragment
// shader writes the map's storage buffer (fragmentStoresAndAtomics).
#pragma once
#include <glm/glm.hpp>

#include <limits>
#include <map>
#include <memory>
#include <span>

#include "snow/deformation_pass.hpp"

namespace wg::snow {

// One mesh: positions are three floats at the start of each vertex (vertexOffset
// already points at the first position), drawn as an indexed triangle list.
struct MeshInteractor {
  VkBuffer vertices = VK_NULL_HANDLE;
  VkDeviceSize vertexOffset = 0;
  std::uint32_t vertexStride = 3 * sizeof(float);
  VkBuffer indices = VK_NULL_HANDLE;
  VkDeviceSize indexOffset = 0;
  VkIndexType indexType = VK_INDEX_TYPE_UINT32;
  std::uint32_t indexCount = 0;
  glm::mat4 model{1.f};
  // World xz the mesh covers this frame: where it is drawn (a scissor) and whose normals
  // are redone. Parts outside are cut.
  glm::vec2 footprintMin{0.f}, footprintMax{0.f};
  // The undisturbed snow surface under this mesh (world y); NaN: the SnowLevel's.
  float surfaceHeight = std::numeric_limits<float>::quiet_NaN();
};

// Where the undisturbed snow is: its surface height and depth (world y, metres).
struct SnowLevel {
  float surfaceHeight = 0.f;
  float depth = 0.f;
};

// Mirrors the mesh shaders' push-constant block `Window`.
struct MeshWindowConstants {
  glm::mat4 model;
  std::int32_t origin[2];
  std::int32_t originSlot[2];
  std::int32_t resolution;
  float texelSize;
  float surfaceHeight;
  float snowDepth;
};

class MeshInteractorPass {
 public:
  // Throws std::runtime_error when the device lacks fragmentStoresAndAtomics.
  MeshInteractorPass(vk::Context& ctx, std::uint32_t resolution, const vk::Buffer& heights);
  ~MeshInteractorPass();
  MeshInteractorPass(const MeshInteractorPass&) = delete;
  MeshInteractorPass& operator=(const MeshInteractorPass&) = delete;

  // Draws `meshes` into the map (outside any render pass; opens its own).
  void record(VkCommandBuffer cmd, const WindowConstants& window, const SnowLevel& level,
              std::span<const MeshInteractor> meshes);

 private:
  VkPipeline pipelineFor(std::uint32_t stride);

  vk::Context& ctx_;
  std::uint32_t resolution_;
  std::unique_ptr<vk::ReflectedDescriptorSet> set_;
  vk::UniqueShaderModule vertex_, fragment_;
  vk::UniqueRenderPass pass_;
  vk::UniqueFramebuffer framebuffer_;
  std::map<std::uint32_t, vk::UniquePipeline> pipelines_;  // by vertex stride
};

}  // namespace wg::snow
