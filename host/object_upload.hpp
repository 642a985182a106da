// Meshes on the GPU, in the vertex format a material's reflection asks for.
#pragma once
#include <cstdint>

#include "host/scene/mesh.hpp"
#include "vulkan/gpu_buffer.hpp"
#include "vulkan/material_pipeline.hpp"

namespace wg {

struct UploadedMesh {
  vk::Buffer vertices, indices;
  std::uint32_t indexCount = 0;
};

// The mesh interleaved into the reflected vertex format (attributes in location order).
UploadedMesh uploadMesh(vk::Context& ctx, const scene::Mesh& mesh, const vk::VertexLayout& layout);

}  // namespace wg
