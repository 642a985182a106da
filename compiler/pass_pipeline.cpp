#include "compiler/pass_pipeline.hpp"

#include <array>

namespace wg {

namespace {
constexpr std::array<Pass, 5> kPasses = {{
    {"weather-inject", "inserts the weather subgraph between the PBR attributes and the output", injectWeather},
    {"constant-fold", "evaluates pure nodes whose inputs are all constant, via the ops' CPU semantics", foldConstants},
    {"cse", "merges structurally identical nodes", eliminateCommonSubexpressions},
    {"dead-node-elim", "removes nodes no output depends on", eliminateDeadNodes},
    {"topo-order", "orders nodes by a depth-first walk from the outputs, so order depends only on content",
     orderTopologically},
}};
}  // namespace

std::span<const Pass> passPipeline() { return kPasses; }

void runPassPipeline(IrGraph& graph) {
  for (const Pass& pass : kPasses) pass.run(graph);
}

}  // namespace wg
