#include "backends/stage_writer.hpp"

#include <algorithm>
#include <charconv>
#include <functional>
#include <optional>
#include <stdexcept>

#include "backends/op_template.hpp"
#include "backends/source_text.hpp"
#include "nodes/core_library.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/pbr_shading.hpp"

namespace wg {

namespace {

// A typical emitted statement's length, to size the body once.
constexpr std::size_t kBytesPerStatement = 96;

class StageWriter {
 public:
  StageWriter(const IrGraph& g, const MaterialInterface& mi, const ShaderSyntax& syntax, ShaderStage stage,
              const std::vector<std::string>& names)
      : graph_(g), mi_(mi), syntax_(syntax), stage_(stage), names_(names) {}

  StageSource run() {
    StageSource source;
    source.stage = stage_;
    source.interface = &mi_;
    markNeeded();
    collectLibraries(source.libraries);
    source.body.reserve(graph_.nodes.size() * kBytesPerStatement);
    emitBody(source.body);
    std::sort(calls_.begin(), calls_.end(), [](auto a, auto b) { return a.data() < b.data(); });
    calls_.erase(std::unique(calls_.begin(), calls_.end(), [](auto a, auto b) { return a.data() == b.data(); }), calls_.end());
    source.bodyCalls = std::move(calls_);
    return source;
  }

 private:
  // The local each output slot lands in; the stage frames read these names.
  static std::string_view slotLocal(std::size_t slot) {
    static const std::vector<std::string> kSlotLocals = [] {
      std::vector<std::string> locals = {"wg_baseColor", "wg_metallic", "wg_roughness", "wg_specular", "wg_normal",
                                         "wg_occlusion", "wg_emissive", "wg_opacity",  "wg_offset"};
      for (const auto& term : coverageTerms()) locals.push_back("wg_coverage_" + std::string(term.name));
      return locals;
    }();
    return kSlotLocals[slot];
  }
  static ValueType slotType(std::size_t slot) {
    return slot < kPbrFieldCount ? pbrFields()[slot].type : ValueType::Float;
  }

  // Unguarded nodes, the result locals at their unweathered values, then one uniform
  // branch that runs the weather nodes and rebinds the results while any weather
  // level is above 0: with no weather, the weather costs that one branch.
  void emitBody(std::string& body) {
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i)
      if (needed_[i] && !graph_.nodes[i].weather) emitNode(i, body, "  ");
    appendInterpolantWrites(body, "  ", /*weather=*/false);
    const auto& slots = stageOutputSlots(stage_);
    for (std::size_t slot : slots) {
      const Operand& base = graph_.weatherGuarded() ? graph_.unweathered[slot] : graph_.outputs[slot];
      body += "  ";
      body += syntax_.typeName(slotType(slot));
      appendSlotAssignment(body, " ", slot, base);
    }
    bool anyGuarded = false;
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i) anyGuarded = anyGuarded || (needed_[i] && graph_.nodes[i].weather);
    if (!graph_.weatherGuarded() || !anyGuarded) return;
    appendInterpolantDefaults(body);
    body += "  if (";
    for (std::size_t i = 0; i < graph_.weatherGuard.size(); ++i) {
      if (i) body += " + ";
      body += graph_.weatherGuard[i];
    }
    body += " > 0.0) {\n";
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i)
      if (needed_[i] && graph_.nodes[i].weather) emitNode(i, body, "    ");
    appendInterpolantWrites(body, "    ", /*weather=*/true);
    for (std::size_t slot : slots)
      if (!(graph_.outputs[slot] == graph_.unweathered[slot])) appendSlotAssignment(body, "    ", slot, graph_.outputs[slot]);
    body += "  }\n";
  }

  // The interpolants, as the surface functions' output (vertex) or input (fragment) fields.
  std::string interpolantVariable(std::size_t k) const {
    return (stage_ == ShaderStage::Vertex ? "wg_out." : "wg_in.") + mi_.varyings[mi_.interpolantVaryings[k]].name;
  }
  // The vertex stage writes each interpolant where its node was emitted: the weather's
  // inside the weather branch, after a zero for when the branch is skipped.
  void appendInterpolantWrites(std::string& body, std::string_view lead, bool weather) const {
    if (stage_ != ShaderStage::Vertex) return;
    for (std::size_t k = 0; k < graph_.interpolants.size(); ++k) {
      std::uint32_t node = graph_.interpolants[k];
      if (graph_.nodes[node].weather != weather) continue;
      appendText(body, lead, interpolantVariable(k), " = ", names_[node], ";\n");
    }
  }
  void appendInterpolantDefaults(std::string& body) const {
    if (stage_ != ShaderStage::Vertex) return;
    for (std::size_t k = 0; k < graph_.interpolants.size(); ++k) {
      const IrNode& node = graph_.nodes[graph_.interpolants[k]];
      if (node.weather) appendText(body, "  ", interpolantVariable(k), " = ", syntax_.splat(node.valueType, "0.0"), ";\n");
    }
  }

  // "<lead><slot local> = <operand>;": the result locals' lines.
  void appendSlotAssignment(std::string& body, std::string_view lead, std::size_t slot, const Operand& operand) const {
    body += lead;
    body += slotLocal(slot);
    body += " = ";
    appendOperand(body, operand, slotType(slot));
    body += ";\n";
  }

  // The stage's nodes. The fragment stage reads an interpolant and needs nothing of its
  // inputs for it; the vertex stage computes it.
  void markNeeded() {
    needed_.assign(graph_.nodes.size(), false);
    interpolated_.assign(graph_.nodes.size(), false);
    for (std::size_t slot : stageOutputSlots(stage_)) {
      for (const Operand* o : {&graph_.outputs[slot], &graph_.unweathered[slot]}) {
        if (o == &graph_.unweathered[slot] && !graph_.weatherGuarded()) continue;
        if (o->kind == Operand::Kind::Node) needed_[o->node] = true;
      }
    }
    for (std::uint32_t node : graph_.interpolants) {
      if (stage_ == ShaderStage::Vertex) needed_[node] = true;
      else interpolated_[node] = true;
    }
    for (std::size_t i = graph_.nodes.size(); i-- > 0;)
      if (needed_[i] && !interpolated_[i])
        for (const auto& o : graph_.nodes[i].inputs)
          if (o.kind == Operand::Kind::Node) needed_[o.node] = true;
  }

  void collectLibraries(std::vector<const ShaderLibrary*>& out) {
    std::function<void(const ShaderLibrary*)> add = [&](const ShaderLibrary* lib) {
      if (std::find(out.begin(), out.end(), lib) != out.end()) return;
      for (const ShaderLibrary* dep : lib->dependencies) add(dep);
      out.push_back(lib);
    };
    add(&kCoreLibrary);
    std::vector<const ShaderLibrary*> used;
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i)
      if (needed_[i])
        for (const ShaderLibrary* lib : graph_.nodes[i].op->libraries) used.push_back(lib);
    // Sorted by name so the order never depends on which node came first.
    std::sort(used.begin(), used.end(), [](auto* a, auto* b) { return a->name < b->name; });
    for (const ShaderLibrary* lib : used) add(lib);
    if (stage_ == ShaderStage::Fragment) add(&kPbrShadingLibrary);
  }

  // Appends the operand's expression: the common cases write straight into out.
  void appendOperand(std::string& out, const Operand& operand, ValueType portType) const {
    switch (operand.kind) {
      case Operand::Kind::Constant: syntax_.appendConstant(out, operand.constant.convertedTo(portType)); return;
      case Operand::Kind::Texture: out += mi_.textures[static_cast<std::size_t>(operand.texture)].textureIdentifier; return;
      case Operand::Kind::Node: break;
    }
    const IrNode& source = graph_.nodes[operand.node];
    std::string_view accessor = source.op->outputs[operand.output].accessor;
    if (operand.type == ValueType::Float && portType != ValueType::Float && portType != ValueType::Bool) {
      out += syntax_.splat(portType, names_[operand.node] + std::string(accessor));
      return;
    }
    out += names_[operand.node];
    out += accessor;
  }
  // A texture input's binding: the op template check guarantees the op has one.
  const TextureBinding& textureOf(const IrNode& node) const {
    for (const auto& o : node.inputs)
      if (o.kind == Operand::Kind::Texture) return mi_.textures[static_cast<std::size_t>(o.texture)];
    throw std::logic_error("op " + std::string(node.op->name) + " samples without a texture input");
  }

  void appendPiece(std::string& body, const TemplatePiece& piece, const IrNode& node) const {
    using Kind = TemplatePiece::Kind;
    switch (piece.kind) {
      case Kind::Text: body += piece.text; return;
      case Kind::Type: body += syntax_.typeName(node.valueType); return;
      case Kind::Input: appendOperand(body, node.inputs[piece.input], node.inputTypes[piece.input]); return;
      case Kind::Channels: (body += '.') += node.text; return;  // validated: 1-4 of xyzw/rgba
      case Kind::SampleFn: body += syntax_.sampleFunction(stage_); return;
      case Kind::LodArg: body += syntax_.lodArgument(stage_); return;
      case Kind::Parameter:
        syntax_.appendParameterRead(body, mi_.material.members[static_cast<std::size_t>(node.parameter)], node.valueType);
        return;
      case Kind::Texture: body += textureOf(node).textureIdentifier; return;
      case Kind::Sampler: body += textureOf(node).samplerIdentifier; return;
    }
  }

  void emitNode(std::size_t index, std::string& body, std::string_view indent) {
    const IrNode& node = graph_.nodes[index];
    if (interpolated_[index]) return emitInterpolantRead(index, body, indent);
    const OpDef& op = *node.op;
    const OpTemplate* pieces = registeredOpTemplate(syntax_, op);
    std::optional<SpelledOpTemplate> unregistered;
    if (!pieces) pieces = &unregistered.emplace(op, syntax_.opCode(op)).split;
    body += indent;
    body += syntax_.typeName(node.valueType);
    body += ' ';
    body += names_[index];
    body += " = ";
    for (const TemplatePiece& piece : pieces->pieces) appendPiece(body, piece, node);
    calls_.insert(calls_.end(), pieces->calls.begin(), pieces->calls.end());
    body += ";\n";
  }

  void emitInterpolantRead(std::size_t index, std::string& body, std::string_view indent) const {
    auto k = static_cast<std::size_t>(
        std::find(graph_.interpolants.begin(), graph_.interpolants.end(), index) - graph_.interpolants.begin());
    appendText(body, indent, syntax_.typeName(graph_.nodes[index].valueType), ' ', names_[index], " = ",
               interpolantVariable(k), ";\n");
  }

  const IrGraph& graph_;
  const MaterialInterface& mi_;
  const ShaderSyntax& syntax_;
  ShaderStage stage_;
  const std::vector<std::string>& names_;
  std::vector<bool> needed_;
  std::vector<bool> interpolated_;  // fragment stage: read from an interpolant
  std::vector<std::string_view> calls_;  // of the emitted nodes' templates
};

}  // namespace

// "n<index>_<op>" is unique by its index and cannot meet another emitted name: globals
// and frame locals carry other prefixes (mat_, tex_, frame_, wg_, in_, v_...), and op
// names are clean identifiers (a unit test checks every registered op), so no
// identifier scope is needed.
std::vector<std::string> nameNodes(const IrGraph& graph) {
  std::vector<std::string> names;
  names.reserve(graph.nodes.size());
  char digits[24];
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    auto end = std::to_chars(digits, digits + sizeof digits, i).ptr;
    std::string_view op = graph.nodes[i].op->name;
    std::string& name = names.emplace_back();
    name.reserve(2 + static_cast<std::size_t>(end - digits) + op.size());
    name += 'n';
    name.append(digits, end);
    name += '_';
    name += op;
  }
  return names;
}

StageSource writeStageSource(const IrGraph& graph, const MaterialInterface& interface, const ShaderSyntax& syntax,
                             ShaderStage stage, const std::vector<std::string>& nodeNames) {
  return StageWriter(graph, interface, syntax, stage, nodeNames).run();
}

}  // namespace wg
