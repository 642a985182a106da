#include "compiler/pass_pipeline.hpp"

#include "compiler/ir_verifier.hpp"

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
     orderTopologically, /*ordersCanonically=*/true},
    {"vertex-rate", "moves smooth values the fragment stage needs (terrain slope) to the vertex stage, read interpolated",
     hoistVertexRate},
};
}  // namespace

std::span<const Pass> passPipeline() { return kPasses; }

const Pass* findPass(std::string_view name) {
  for (const Pass& pass : kPasses)
    if (pass.name == name) return &pass;
  return nullptr;
}

std::optional<IrViolation> runPassPipeline(IrGraph& graph, const PassPipelineOptions& options) {
  IrVerifyOptions expected;
  if (options.verifyBetweenPasses)
    if (std::string problem = verifyIr(graph, expected); !problem.empty()) return IrViolation{kIrBuilderStep, problem};
  for (const Pass& pass : kPasses) {
    pass.run(graph);
    if (options.afterPass) options.afterPass(pass, graph);
    expected.canonicalOrder = expected.canonicalOrder || pass.ordersCanonically;
    if (options.verifyBetweenPasses)
      if (std::string problem = verifyIr(graph, expected); !problem.empty()) return IrViolation{pass.name, problem};
  }
  return std::nullopt;
}

}  // namespace wg
