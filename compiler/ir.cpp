#include "compiler/ir.hpp"

#include "nodes/op_registry.hpp"

namespace wg {

const std::array<CoverageInfo, kCoverageCount>& coverageTerms() {
  static const std::array<CoverageInfo, kCoverageCount> kTerms = {{
      {CoverageTerm::Snow, "snow", 0.f},
      {CoverageTerm::Wet, "wet", 0.f},
      {CoverageTerm::Moss, "moss", 0.f},
      {CoverageTerm::Frost, "frost", 0.f},
      {CoverageTerm::Ice, "ice", 0.f},
      {CoverageTerm::Puddle, "puddle", 0.f},
      {CoverageTerm::Density, "density", 1.f},
  }};
  return kTerms;
}

const std::vector<std::size_t>& stageOutputSlots(ShaderStage stage) {
  static const auto kSlots = [] {
    std::array<std::vector<std::size_t>, 2> slots;  // vertex, fragment
    for (const auto& info : pbrFields())
      slots[info.stage == ShaderStage::Vertex ? 0 : 1].push_back(static_cast<std::size_t>(info.field));
    for (std::size_t t = 0; t < kCoverageCount; ++t) slots[1].push_back(kPbrFieldCount + t);
    return slots;
  }();
  return kSlots[stage == ShaderStage::Vertex ? 0 : 1];
}

std::optional<ValueType> signatureValueType(PortType type) {
  switch (type) {
    case PortType::Float: return ValueType::Float;
    case PortType::Vec2: return ValueType::Vec2;
    case PortType::Vec3: return ValueType::Vec3;
    case PortType::Vec4: return ValueType::Vec4;
    case PortType::Bool: return ValueType::Bool;
    case PortType::TextureName: return ValueType::Texture;
    case PortType::Text: return ValueType::Float;
    case PortType::Generic: return std::nullopt;
  }
  return std::nullopt;
}

ValueType IrNode::outputType(std::size_t output) const {
  std::string_view accessor = op->outputs[output].accessor;
  if (accessor.empty()) return valueType;
  return floatVectorOfWidth(accessorWidth(accessor, componentCount(valueType)));
}

}  // namespace wg
