#include "compiler/ir.hpp"

#include "nodes/op_registry.hpp"

namespace wg {

ValueType IrNode::outputType(std::size_t output) const {
  std::string_view accessor = op->outputs[output].accessor;
  if (accessor.empty()) return valueType;
  return floatVectorOfWidth(accessorWidth(accessor, componentCount(valueType)));
}

}  // namespace wg
