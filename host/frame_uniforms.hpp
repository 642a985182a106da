// Writes the frame and weather block by member name, at the offsets the reflection
// publishes; the runtime never hard-codes the layout.
#pragma once
#include <glm/glm.hpp>
#include <array>
#include <cstring>
#include <string_view>
#include <vector>

#include "nodes/frame_state.hpp"
#include "vulkan/material_reflection.hpp"

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
  // Every member, from the frame table (nodes/frame_fields.hpp).
  void set(const FrameState& frame);

  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  void write(std::string_view name, std::string_view type, const void* data, std::size_t size);
  const vk::ReflectedBlock* block_;
  std::vector<unsigned char> bytes_;
};

// A glm value into the FrameState member of the same size (glm stores matrices
// column-major, as the block does).
template <std::size_t N, class GlmValue>
void storeInto(std::array<float, N>& member, const GlmValue& value) {
  static_assert(sizeof(GlmValue) == sizeof(member), "glm value and frame member differ in size");
  std::memcpy(member.data(), &value, sizeof member);
}

}  // namespace wg
