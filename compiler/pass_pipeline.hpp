// The one named, ordered list of IR passes. Every compile runs exactly this list.
#pragma once
#include <span>
#include <string_view>

#include "compiler/ir.hpp"

namespace wg {

struct Pass {
  std::string_view name;
  std::string_view summary;
  void (*run)(IrGraph& graph);
};

std::span<const Pass> passPipeline();
void runPassPipeline(IrGraph& graph);

// The passes, one file each under compiler/passes/.
void injectWeather(IrGraph& graph);
void foldConstants(IrGraph& graph);
void simplifyAlgebra(IrGraph& graph);
void eliminateCommonSubexpressions(IrGraph& graph);
void eliminateDeadNodes(IrGraph& graph);
void orderTopologically(IrGraph& graph);

}  // namespace wg
