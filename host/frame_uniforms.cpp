#include "host/frame_uniforms.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include "nodes/frame_fields.hpp"

namespace wg {

void FrameUniforms::write(std::string_view name, std::string_view type, const void* data, std::size_t size) {
  const vk::ReflectedMember* m = block_->find(name);
  if (!m) throw std::runtime_error("frame block has no member '" + std::string(name) + "'");
  if (m->type != type)
    throw std::runtime_error("frame member '" + std::string(name) + "' is " + m->type + ", not " + std::string(type));
  std::memcpy(bytes_.data() + m->offset, data, size);
}

void FrameUniforms::set(std::string_view name, float v) { write(name, "float", &v, sizeof v); }
void FrameUniforms::set(std::string_view name, std::uint32_t v) { write(name, "uint", &v, sizeof v); }
void FrameUniforms::set(std::string_view name, glm::vec2 v) { write(name, "vec2", &v, sizeof v); }
void FrameUniforms::set(std::string_view name, glm::vec3 v) { write(name, "vec3", &v, sizeof v); }
void FrameUniforms::set(std::string_view name, glm::vec4 v) { write(name, "vec4", &v, sizeof v); }
// glm matrices are column-major, as std140 and both shading languages expect here.
void FrameUniforms::set(std::string_view name, const glm::mat4& v) { write(name, "mat4", &v, sizeof v); }

void FrameUniforms::set(const FrameState& frame) {
  for (const FrameField& field : frameFields()) {
    std::span<const std::byte> bytes = fieldBytes(field, frame);
    write(field.name, glslTypeName(field.type), bytes.data(), bytes.size());
  }
}

}  // namespace wg
