#include "compiler/pass_pipeline.hpp"


namespace wg {

namespace {
// Sized by its initialiser, so a pass can never be left out of the count.
constexpr Pass kPasses[] = {
    {"weather-inject", "inserts the weather subgraph between the PBR attributes and the output", injectWeather},
    {"constant-fold", "evaluates pure nodes whose inputs are all constant, via the ops' CPU semantics", foldConstants},
    {"algebraic-simplify", "removes identities: lerp(a, a, t), x * 1, x + 0, x - 0, x / 1", simplifyAlgebra},
    {"cse", "merges structurally identical nodes", eliminateCommonSubexpressions},
    {"dead-node-elim", "removes nodes no output depends on", eliminateDeadNodes},
    {"topo-order", "orders nodes by a depth-first walk from the outputs, so order depends only on content",
     orderTopologically},
};
}  // namespace

std::span<const Pass> passPipeline() { return kPasses; }

void runPassPipeline(IrGraph& graph) {
  for (const Pass& pass : kPasses) pass.run(graph);
}

}  // namespace wg
