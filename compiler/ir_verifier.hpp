// The IR's invariants, checked between passes in debug builds and in tests
// (PassPipelineOptions::verifyBetweenPasses). A broken invariant is a weathergen bug.
#pragma once
#include <string>

#include "compiler/ir.hpp"

namespace wg {

struct IrVerifyOptions {
  // The nodes must be exactly canonicalNodeOrder: reachable, in topo-order's order.
  bool canonicalOrder = false;
};

// "" when the graph holds every invariant, else the first one broken, in words that
// name nodes by index and op (never by user-spelled id):
// - every node has an op, one operand and one resolved type per port;
// - an operand names an earlier node (so the graph is acyclic and topologically
//   ordered) and an output that node has, a declared texture, or a constant;
// - each operand's type is what its source delivers and converts to its port's type;
//   port types follow the op's signature (one width for every generic port);
// - a node's value type follows the op's value rule; parameter nodes name a declared
//   parameter of that type;
// - every output binding names an existing node or is a constant, of its field's type.
std::string verifyIr(const IrGraph& graph, const IrVerifyOptions& options = {});

}  // namespace wg
