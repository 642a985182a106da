// The one named, ordered list of IR passes. Every compile runs exactly this list.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ir.hpp"

namespace wg {

struct Pass {
  std::string_view name;
  std::string_view summary;
  void (*run)(IrGraph& graph);
  // After this pass the nodes are in canonical order (canonicalNodeOrder), and every
  // later pass must keep them so: the verifier checks it from here on.
  bool ordersCanonically = false;
};

std::span<const Pass> passPipeline();
const Pass* findPass(std::string_view name);  // null when no pass has that name

// The IR's invariants are checked between passes in debug builds; tests turn the
// check on in any build (PassPipelineOptions::verifyBetweenPasses).
#ifdef NDEBUG
inline constexpr bool kVerifyIrBetweenPassesByDefault = false;
#else
inline constexpr bool kVerifyIrBetweenPassesByDefault = true;
#endif

struct PassPipelineOptions {
  // Runs verifyIr (compiler/ir_verifier.hpp) on the built IR and after every pass.
  bool verifyBetweenPasses = kVerifyIrBetweenPassesByDefault;
  // Sees the IR each pass leaves, before it is verified (--dump-ir-after).
  std::function<void(const Pass& pass, const IrGraph& graph)> afterPass;
};

// The first broken invariant and where it was found: after a pass, or in the IR the
// builder handed over (after == kIrBuilderStep). A weathergen bug, never the input's.
struct IrViolation {
  std::string_view after;
  std::string problem;
};
inline constexpr std::string_view kIrBuilderStep = "ir-build";

std::optional<IrViolation> runPassPipeline(IrGraph& graph, const PassPipelineOptions& options = {});

// The passes, one file each under compiler/passes/.
void injectWeather(IrGraph& graph);
void foldConstants(IrGraph& graph);
void simplifyAlgebra(IrGraph& graph);
void eliminateCommonSubexpressions(IrGraph& graph);
void eliminateDeadNodes(IrGraph& graph);
void orderTopologically(IrGraph& graph);
void hoistVertexRate(IrGraph& graph);

// The order topo-order sorts into: old node indices, reachable nodes only.
std::vector<std::uint32_t> canonicalNodeOrder(const IrGraph& graph);

}  // namespace wg
