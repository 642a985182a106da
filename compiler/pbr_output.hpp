// The material's PBR output fields (seed 000, eq. 2.1-2.5 consume them).
#pragma once
#include <array>
#include <optional>
#include <string_view>

#include "nodes/shader_stage.hpp"
#include "nodes/value.hpp"

namespace wg {

enum class PbrField : std::uint8_t {
  BaseColor,
  Metallic,
  Roughness,
  Specular,
  Normal,  // tangent space
  AmbientOcclusion,
  Emissive,
  Opacity,
  WorldPositionOffset,  // vertex stage
};
inline constexpr std::size_t kPbrFieldCount = 9;

struct PbrFieldInfo {
  PbrField field;
  std::string_view name;  // graph spelling
  ValueType type;
  Value defaultValue;
  ShaderStage stage;
  float min, max;  // literal range
};

const std::array<PbrFieldInfo, kPbrFieldCount>& pbrFields();
const PbrFieldInfo& pbrField(PbrField field);
std::optional<PbrField> findPbrField(std::string_view name);

}  // namespace wg
