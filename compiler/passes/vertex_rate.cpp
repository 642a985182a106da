// Moves smooth values to the vertex stage. A node whose op is smooth across a triangle
// (OpRate::Vertex), that the fragment stage needs, and whose inputs the vertex stage can
// all compute (OpRate::Any or Vertex, no material texture), is computed per vertex and
// read interpolated: the fragment stage then skips its whole input cone, texture
// lookups included. Nodes keep their order; only IrGraph::interpolants is set.
#include "compiler/pass_pipeline.hpp"

namespace wg {

namespace {

// Vulkan guarantees 64 components, 16 locations, between the stages; the fixed varyings
// take up to 6 of them. The surface's hosts carry the values too, and Filament has room
// for four vec4s (its custom variables). Beyond either, values stay in the fragment stage.
constexpr std::size_t kMaxInterpolants = 8;
constexpr int kMaxInterpolantComponents = 16;

// Whether the vertex stage can compute each node: its op allows it and so do its inputs.
std::vector<bool> vertexComputable(const IrGraph& graph) {
  std::vector<bool> ok(graph.nodes.size(), false);
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const IrNode& node = graph.nodes[i];
    bool computable = node.op->rate != OpRate::Pixel;
    for (const Operand& o : node.inputs) {
      if (o.kind == Operand::Kind::Texture) computable = false;
      if (o.kind == Operand::Kind::Node && !ok[o.node]) computable = false;
    }
    ok[i] = computable;
  }
  return ok;
}

// The fragment stage's roots, weathered and not.
std::vector<bool> fragmentRoots(const IrGraph& graph) {
  std::vector<bool> needed(graph.nodes.size(), false);
  auto mark = [&](const Operand& o) {
    if (o.kind == Operand::Kind::Node) needed[o.node] = true;
  };
  for (std::size_t slot : stageOutputSlots(ShaderStage::Fragment)) {
    mark(graph.outputs[slot]);
    if (graph.weatherGuarded()) mark(graph.unweathered[slot]);
  }
  return needed;
}

}  // namespace

void hoistVertexRate(IrGraph& graph) {
  graph.interpolants.clear();
  const std::vector<bool> computable = vertexComputable(graph);
  std::vector<bool> needed = fragmentRoots(graph);
  int components = 0;
  // Backwards from the roots: an interpolant cuts the walk, so its cone stays out of
  // the fragment stage unless something else there needs it.
  for (std::size_t i = graph.nodes.size(); i-- > 0;) {
    if (!needed[i]) continue;
    const IrNode& node = graph.nodes[i];
    bool interpolable = node.valueType != ValueType::Bool && node.valueType != ValueType::Texture;
    bool room = graph.interpolants.size() < kMaxInterpolants &&
                components + componentCount(node.valueType) <= kMaxInterpolantComponents;
    if (node.op->rate == OpRate::Vertex && computable[i] && interpolable && room) {
      graph.interpolants.insert(graph.interpolants.begin(), static_cast<std::uint32_t>(i));
      components += componentCount(node.valueType);
      continue;
    }
    for (const Operand& o : node.inputs)
      if (o.kind == Operand::Kind::Node) needed[o.node] = true;
  }
}

}  // namespace wg
