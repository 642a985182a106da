#include "host/object_upload.hpp"

#include <stdexcept>
#include <vector>

namespace wg {

namespace {
std::vector<float> packVertices(const scene::Mesh& mesh, const vk::VertexLayout& layout) {
  std::vector<float> out;
  out.reserve(mesh.positions.size() * layout.stride / sizeof(float));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (const auto& name : layout.names) {
      if (name == "position") out.insert(out.end(), {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z});
      else if (name == "normal") out.insert(out.end(), {mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z});
      else if (name == "tangent")
        out.insert(out.end(), {mesh.tangents[i].x, mesh.tangents[i].y, mesh.tangents[i].z, mesh.tangents[i].w});
      else if (name == "texcoord") out.insert(out.end(), {mesh.texcoords[i].x, mesh.texcoords[i].y});
      else if (name == "texcoord1") {
        const glm::vec2 uv = mesh.texcoords1.empty() ? mesh.texcoords[i] : mesh.texcoords1[i];  // set 0 stands in
        out.insert(out.end(), {uv.x, uv.y});
      }
      else if (name == "color")
        out.insert(out.end(), {mesh.colors[i].r, mesh.colors[i].g, mesh.colors[i].b, mesh.colors[i].a});
      else throw std::runtime_error("reflection names an unknown vertex input '" + name + "'");
    }
  }
  return out;
}
}  // namespace

UploadedMesh uploadMesh(vk::Context& ctx, const scene::Mesh& mesh, const vk::VertexLayout& layout) {
  UploadedMesh out;
  auto packed = packVertices(mesh, layout);
  out.vertices = vk::Buffer(ctx, packed.size() * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  out.vertices.write(packed.data(), packed.size() * sizeof(float));
  out.indices = vk::Buffer(ctx, mesh.indices.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  out.indices.write(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  out.indexCount = static_cast<std::uint32_t>(mesh.indices.size());
  return out;
}

}  // namespace wg
