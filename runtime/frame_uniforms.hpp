// Writes the frame and weather block by member name, at the offsets the reflection
// publishes; the runtime never hard-codes the layout.
#pragma once
#include <glm/glm.hpp>
#include <string_view>
#include <vector>

#include "runtime/vulkan/material_reflection.hpp"

namespace wg {

class FrameUniforms {
 public:
  explicit FrameUniforms(const vk::ReflectedBlock& block) : block_(&block), bytes_(block.size, 0) {}

  // Each setter checks the member's reflected type; an unknown name or a type
  // mismatch throws, since it means the runtime and compiler disagree.
  void set(std::string_view name, float value);
  void set(std::string_view name, std::uint32_t value);
  void set(std::string_view name, glm::vec2 value);
  void set(std::string_view name, glm::vec3 value);
  void set(std::string_view name, glm::vec4 value);
  void set(std::string_view name, const glm::mat4& value);

  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  void write(std::string_view name, std::string_view type, const void* data, std::size_t size);
  const vk::ReflectedBlock* block_;
  std::vector<unsigned char> bytes_;
};

}  // namespace wg
