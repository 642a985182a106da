#include "compiler/pbr_output.hpp"

#include <limits>

namespace wg {

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
// UE4's default specular 0.5 gives the dielectric F0 of 0.04 (F0 = 0.08 * specular).
const std::array<PbrFieldInfo, kPbrFieldCount> kFields = {{
    {PbrField::BaseColor, "baseColor", ValueType::Vec3, Value::vec3(0.5f, 0.5f, 0.5f), ShaderStage::Fragment, 0.f, 1.f},
    {PbrField::Metallic, "metallic", ValueType::Float, Value::scalar(0.f), ShaderStage::Fragment, 0.f, 1.f},
    {PbrField::Roughness, "roughness", ValueType::Float, Value::scalar(0.5f), ShaderStage::Fragment, 0.f, 1.f},
    {PbrField::Specular, "specular", ValueType::Float, Value::scalar(0.5f), ShaderStage::Fragment, 0.f, 1.f},
    {PbrField::Normal, "normal", ValueType::Vec3, Value::vec3(0.f, 0.f, 1.f), ShaderStage::Fragment, -1.f, 1.f},
    {PbrField::AmbientOcclusion, "ambientOcclusion", ValueType::Float, Value::scalar(1.f), ShaderStage::Fragment, 0.f, 1.f},
    {PbrField::Emissive, "emissive", ValueType::Vec3, Value::vec3(0.f, 0.f, 0.f), ShaderStage::Fragment, 0.f, kInf},
    {PbrField::Opacity, "opacity", ValueType::Float, Value::scalar(1.f), ShaderStage::Fragment, 0.f, 1.f},
    {PbrField::WorldPositionOffset, "worldPositionOffset", ValueType::Vec3, Value::vec3(0.f, 0.f, 0.f),
     ShaderStage::Vertex, -kInf, kInf},
}};
}  // namespace

const std::array<PbrFieldInfo, kPbrFieldCount>& pbrFields() { return kFields; }
const PbrFieldInfo& pbrField(PbrField field) { return kFields[static_cast<std::size_t>(field)]; }

std::optional<PbrField> findPbrField(std::string_view name) {
  for (const auto& f : kFields)
    if (f.name == name) return f.field;
  return std::nullopt;
}

}  // namespace wg
