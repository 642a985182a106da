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

ValueType IrNode::outputType(std::size_t output) const {
  std::string_view accessor = op->outputs[output].accessor;
  if (accessor.empty()) return valueType;
  return floatVectorOfWidth(accessorWidth(accessor, componentCount(valueType)));
}

}  // namespace wg
