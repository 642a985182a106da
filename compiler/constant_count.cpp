#include "compiler/constant_count.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <set>
#include <unordered_set>

namespace wg {

std::size_t distinctConstantCount(const IrGraph& ir) {
  std::unordered_set<std::uint32_t> scalars;
  std::set<std::array<std::uint32_t, 5>> vectors;  // components, then the width
  for (const IrNode& node : ir.nodes)
    for (const Operand& input : node.inputs) {
      if (input.kind != Operand::Kind::Constant) continue;
      const int width = input.constant.width();
      std::array<std::uint32_t, 5> bits{};
      bits[4] = static_cast<std::uint32_t>(width);
      for (int i = 0; i < width; ++i) {
        bits[static_cast<std::size_t>(i)] = std::bit_cast<std::uint32_t>(input.constant.v[static_cast<std::size_t>(i)]);
        scalars.insert(bits[static_cast<std::size_t>(i)]);
      }
      if (width > 1) vectors.insert(bits);
    }
  return scalars.size() + vectors.size();
}

}  // namespace wg
