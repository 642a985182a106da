#include "compiler/ir_builder.hpp"

#include <algorithm>
#include <unordered_map>

#include "compiler/debug_views.hpp"
#include "compiler/literal.hpp"
#include "nodes/op_registry.hpp"

namespace wg {

namespace {

constexpr std::uint32_t kNoNode = 0xFFFFFFFFu;

// A resolved input before typing.
struct PendingInput {
  const InputSource* source = nullptr;
  std::uint32_t node = kNoNode;  // link target
  int output = -1;
  int texture = -1;
};

struct PendingNode {
  const NodeDecl* decl = nullptr;
  const OpDef* op = nullptr;
  int parameter = -1;
  std::vector<PendingInput> ports;  // one per op port
  std::vector<std::uint32_t> dependencies;
  bool bad = false;
};

ValueType fixedPortType(PortType type) { return signatureValueType(type).value_or(ValueType::Float); }

std::string describePort(PortType type) {
  switch (type) {
    case PortType::Generic: return "float, vec2, vec3 or vec4";
    case PortType::TextureName: return "a texture name";
    case PortType::Text: return "a text setting";
    default: return std::string(typeName(fixedPortType(type)));
  }
}

std::string conversionHint(ValueType from, ValueType to, bool generic) {
  if (from == ValueType::Bool || to == ValueType::Bool)
    return "bools and numbers do not convert: use 'greater' or 'less' to make a bool, 'select' to use one";
  if (generic) return "generic inputs must share one width (a float may feed any of them)";
  return "convert with swizzle, split or combine";
}

class Builder {
 public:
  Builder(const MaterialGraph& g, const JsonDocument& doc, DiagnosticList& diags, const IrBuildOptions& options)
      : graph_(g), doc_(doc), diags_(diags), limits_(options.limits), options_(options) {}

  std::optional<IrGraph> run() {
    if (graph_.nodes.size() > limits_.maxNodes) {
      report(DiagCode::ResourceLimit, "/nodes",
             {"the node count", std::to_string(graph_.nodes.size()), std::to_string(limits_.maxNodes)});
      return std::nullopt;
    }
    indexIds();
    // Ops first, so links to nodes later in the file find their target's outputs.
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i) resolveOp(static_cast<std::uint32_t>(i));
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i) resolveInputs(static_cast<std::uint32_t>(i));
    if (!orderAndDetectCycles()) return std::nullopt;
    if (!checkDepth()) return std::nullopt;
    ir_.name = graph_.name;
    ir_.debugViews = fragmentDebugViews();
    ir_.parameters = graph_.parameters;
    ir_.includedFiles = graph_.includedFiles;
    ir_.textures = graph_.textures;
    ir_.alphaCutoff = graph_.alphaCutoff;
    ir_.alphaMode = graph_.alphaMode.value_or(graph_.outputs.contains(PbrField::Opacity) ? AlphaMode::Mask : AlphaMode::Opaque);
    ir_.alphaModeDeclared = graph_.alphaMode.has_value();
    ir_.doubleSided = graph_.doubleSided;
    irIndex_.assign(pending_.size(), kNoNode);
    for (std::uint32_t n : order_) typeNode(n);
    bindOutputs();
    resolveWeather();
    if (failed_) return std::nullopt;
    return std::move(ir_);
  }

 private:
  void report(DiagCode code, const std::string& pointer, std::initializer_list<std::string_view> args) {
    failed_ = true;
    diags_.report(code, doc_.locate(pointer), args);
  }

  void indexIds() {
    pending_.resize(graph_.nodes.size());
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i) {
      const NodeDecl& n = graph_.nodes[i];
      pending_[i].decl = &n;
      auto [it, inserted] = ids_.emplace(n.id, static_cast<std::uint32_t>(i));
      if (!inserted) {
        report(DiagCode::DuplicateId, appendPointer(n.pointer, "id"),
               {quoteUserText(n.id), "the node at " + graph_.nodes[it->second].pointer});
        pending_[i].bad = true;
      }
    }
  }

  int findTexture(const std::string& name) const {
    for (std::size_t i = 0; i < graph_.textures.size(); ++i)
      if (graph_.textures[i].name == name) return static_cast<int>(i);
    return -1;
  }

  void resolveOp(std::uint32_t index) {
    PendingNode& p = pending_[index];
    const NodeDecl& n = *p.decl;
    p.op = findOp(n.op);
    if (!p.op) {
      report(DiagCode::UnknownOp, appendPointer(n.pointer, "op"),
             {quoteUserText(n.op), unknownNameHintOr(n.op, opNames(), "run 'weathergen list-ops' to see every op")});
      p.bad = true;
      return;
    }
    if (p.op->name == "parameter") {
      if (n.param.empty()) {
        report(DiagCode::MissingField, n.pointer, {"param"});
        p.bad = true;
      } else {
        for (std::size_t i = 0; i < graph_.parameters.size(); ++i)
          if (graph_.parameters[i].name == n.param) p.parameter = static_cast<int>(i);
        if (p.parameter < 0) {
          std::vector<std::string_view> names;
          for (const auto& q : graph_.parameters) names.push_back(q.name);
          report(DiagCode::UnknownParameter, appendPointer(n.pointer, "param"),
                 {quoteUserText(n.param), unknownNameHint(n.param, names, "declared parameters")});
          p.bad = true;
        }
      }
    } else if (!n.param.empty()) {
      report(DiagCode::UnknownField, appendPointer(n.pointer, "param"), {"param", "only op 'parameter' takes 'param'"});
    }
  }

  void resolveInputs(std::uint32_t index) {
    PendingNode& p = pending_[index];
    const NodeDecl& n = *p.decl;
    if (!p.op) return;
    p.ports.resize(p.op->inputs.size());
    for (const auto& [port, source] : n.inputs) {
      const PortSpec* spec = p.op->findInput(port);
      if (!spec) {
        std::vector<std::string_view> names;
        for (const auto& s : p.op->inputs) names.push_back(s.name);
        std::string hint = unknownNameHint(port, names, "inputs of '" + std::string(p.op->name) + "'");
        report(DiagCode::UnknownInput, source.pointer, {p.op->name, quoteUserText(port), hint});
        p.bad = true;
        continue;
      }
      PendingInput& in = p.ports[static_cast<std::size_t>(spec - p.op->inputs.data())];
      in.source = &source;
      if (spec->type == PortType::TextureName) {
        if (source.kind != InputSource::Kind::Link) {
          report(DiagCode::TypeMismatch, source.pointer,
                 {"input '" + std::string(spec->name) + "'", "a texture name", describeJsonKind(source.literal),
                  "name a texture declared under \"textures\""});
          p.bad = true;
        } else if ((in.texture = findTexture(source.text)) < 0) {
          std::vector<std::string_view> names;
          for (const auto& t : graph_.textures) names.push_back(t.name);
          report(DiagCode::UnknownTexture, source.pointer,
                 {quoteUserText(source.text), unknownNameHint(source.text, names, "declared textures")});
          p.bad = true;
        }
        continue;
      }
      if (spec->type == PortType::Text) {
        if (source.kind != InputSource::Kind::Link) {
          report(DiagCode::TypeMismatch, source.pointer,
                 {"input '" + std::string(spec->name) + "'", "a text setting", describeJsonKind(source.literal),
                  "write the channels as a string, e.g. \"xz\""});
          p.bad = true;
        }
        continue;
      }
      if (source.kind == InputSource::Kind::Link) resolveLink(p, in, source);
    }
  }

  void resolveLink(PendingNode& p, PendingInput& in, const InputSource& source) {
    auto dot = source.text.rfind('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == source.text.size()) {
      report(DiagCode::MalformedLink, source.pointer, {quoteUserText(source.text)});
      p.bad = true;
      return;
    }
    std::string id = source.text.substr(0, dot), output = source.text.substr(dot + 1);
    auto it = ids_.find(id);
    if (it == ids_.end()) {
      std::vector<std::string_view> ids;
      for (const auto& n : graph_.nodes) ids.push_back(n.id);
      report(DiagCode::UnknownNode, source.pointer,
             {quoteUserText(source.text), quoteUserText(id), unknownNameHintOr(id, ids, "link to the id of a node in \"nodes\"")});
      p.bad = true;
      return;
    }
    in.node = it->second;
    const PendingNode& target = pending_[in.node];
    if (target.op) {
      in.output = target.op->findOutput(output);
      if (in.output < 0) {
        std::string known;
        for (const auto& o : target.op->outputs) known += " " + std::string(o.name);
        report(DiagCode::DanglingLink, source.pointer,
               {quoteUserText(source.text), quoteUserText(output), target.op->name, "outputs of '" + std::string(target.op->name) + "':" + known});
        p.bad = true;
        return;
      }
    }
    p.dependencies.push_back(in.node);
  }

  // Iterative DFS (hostile graphs may be deep): post-order gives a topological order.
  bool orderAndDetectCycles() {
    enum : std::uint8_t { White, Grey, Black };
    std::vector<std::uint8_t> colour(pending_.size(), White);
    std::vector<std::pair<std::uint32_t, std::size_t>> stack;
    bool cyclic = false;
    for (std::uint32_t root = 0; root < pending_.size(); ++root) {
      if (colour[root] != White) continue;
      stack.push_back({root, 0});
      colour[root] = Grey;
      while (!stack.empty()) {
        auto& [node, next] = stack.back();
        if (next < pending_[node].dependencies.size()) {
          std::uint32_t dep = pending_[node].dependencies[next++];
          if (colour[dep] == White) {
            colour[dep] = Grey;
            stack.push_back({dep, 0});
          } else if (colour[dep] == Grey) {
            reportCycle(stack, dep);
            cyclic = true;
          }
        } else {
          colour[node] = Black;
          order_.push_back(node);
          stack.pop_back();
        }
      }
    }
    return !cyclic;
  }

  // order_ lists dependencies first, so one pass finds every node's chain length.
  bool checkDepth() {
    std::vector<std::size_t> depth(pending_.size(), 0);
    std::uint32_t deepest = 0;
    for (std::uint32_t n : order_) {
      std::size_t d = 0;
      for (std::uint32_t dep : pending_[n].dependencies) d = std::max(d, depth[dep]);
      depth[n] = d + 1;
      if (depth[n] > depth[deepest]) deepest = n;
    }
    if (depth.empty() || depth[deepest] <= limits_.maxDepth) return true;
    report(DiagCode::ResourceLimit, graph_.nodes[deepest].pointer,
           {"the graph depth (the longest link chain, ending at node '" + quoteUserText(graph_.nodes[deepest].id) + "')",
            std::to_string(depth[deepest]), std::to_string(limits_.maxDepth)});
    return false;
  }

  void reportCycle(const std::vector<std::pair<std::uint32_t, std::size_t>>& stack, std::uint32_t start) {
    std::string path;
    bool inCycle = false;
    for (const auto& [node, next] : stack) {
      if (node == start) inCycle = true;
      if (inCycle) path += quoteUserText(graph_.nodes[node].id) + " -> ";
    }
    path += quoteUserText(graph_.nodes[start].id);
    // Reported at the node that closes the loop, so each cycle is named once.
    report(DiagCode::Cycle, graph_.nodes[stack.back().first].pointer, {path});
  }

  // A literal as an operand; reports shape, finiteness and range problems. `what()`
  // names the input in a report, and is called only for one: most literals are fine.
  template <typename What>
  std::optional<Operand> literalOperand(const InputSource& source, const What& what, float min, float max) {
    LiteralResult r = parseLiteral(source.literal);
    if (!r.value) {
      report(DiagCode::TypeMismatch, source.pointer, {what(), "a literal", r.shapeError, "use a number, a bool or an array of 2-4 numbers"});
      return std::nullopt;
    }
    if (r.notFinite) {
      report(DiagCode::LiteralNotFinite, source.pointer, {what()});
      return std::nullopt;
    }
    for (int i = 0; i < r.value->width() && r.value->type != ValueType::Bool; ++i) {
      float x = r.value->v[i];
      if (x < min || x > max) {
        report(DiagCode::LiteralOutOfRange, source.pointer, {what(), formatFloat(x), formatFloat(min), formatFloat(max)});
        return std::nullopt;
      }
    }
    return Operand::ofConstant(*r.value);
  }

  void typeNode(std::uint32_t index) {
    PendingNode& p = pending_[index];
    if (p.bad || !p.op) return;
    const OpDef& op = *p.op;
    IrNode node;
    node.op = &op;
    node.parameter = p.parameter;
    node.debugName = p.decl->id;
    node.inputs.reserve(op.inputs.size());
    node.inputTypes.reserve(op.inputs.size());
    bool ok = true;
    for (std::size_t i = 0; i < op.inputs.size(); ++i) {
      const PortSpec& spec = op.inputs[i];
      const PendingInput& in = p.ports[i];
      if (!in.source) {
        if (!spec.defaultValue) {
          report(DiagCode::MissingInput, p.decl->pointer, {op.name, spec.name, describePort(spec.type)});
          ok = false;
        }
        node.inputs.push_back(spec.defaultValue ? Operand::ofConstant(*spec.defaultValue) : Operand{});
        continue;
      }
      if (spec.type == PortType::TextureName) {
        node.inputs.push_back(Operand::ofTexture(in.texture));
        continue;
      }
      if (spec.type == PortType::Text) {
        node.text = in.source->text;
        node.inputs.push_back(Operand::ofConstant(Value::scalar(0.f)));
        continue;
      }
      if (in.source->kind == InputSource::Kind::Literal) {
        auto what = [&] { return "input '" + std::string(spec.name) + "' of node '" + quoteUserText(p.decl->id) + "'"; };
        auto operand = literalOperand(*in.source, what, spec.min, spec.max);
        if (!operand) ok = false;
        node.inputs.push_back(operand.value_or(Operand{}));
        continue;
      }
      std::uint32_t target = irIndex_[in.node];
      if (target == kNoNode) {  // the source node had errors: already reported
        ok = false;
        node.inputs.push_back(Operand{});
        continue;
      }
      const IrNode& source = ir_.nodes[target];
      if (accessorWidth(source.op->outputs[in.output].accessor, componentCount(source.valueType)) == 0) {
        report(DiagCode::DanglingLink, in.source->pointer,
               {quoteUserText(in.source->text), source.op->outputs[in.output].name, source.op->name,
                "a " + std::string(typeName(source.valueType)) + " value has no such component"});
        ok = false;
        node.inputs.push_back(Operand{});
        continue;
      }
      node.inputs.push_back(Operand::ofNode(target, static_cast<std::uint8_t>(in.output), source.outputType(in.output)));
    }
    if (!ok) return;
    if (!resolveTypes(p, node)) return;
    irIndex_[index] = static_cast<std::uint32_t>(ir_.nodes.size());
    ir_.nodes.push_back(std::move(node));
  }

  bool resolveTypes(const PendingNode& p, IrNode& node) {
    const OpDef& op = *node.op;
    int width = 1;
    bool ok = true;
    for (std::size_t i = 0; i < op.inputs.size(); ++i)
      if (op.inputs[i].type == PortType::Generic) {
        ValueType t = node.inputs[i].type;
        if (!isFloatVector(t)) {
          report(DiagCode::TypeMismatch, portPointer(p, i),
                 {"input '" + std::string(op.inputs[i].name) + "' of '" + std::string(op.name) + "'",
                  "float, vec2, vec3 or vec4", std::string(typeName(t)), "connect a numeric value"});
          ok = false;
        } else {
          width = std::max(width, componentCount(t));
        }
      }
    if (!ok) return false;
    ValueType generic = floatVectorOfWidth(width);
    for (std::size_t i = 0; i < op.inputs.size(); ++i) {
      const PortSpec& spec = op.inputs[i];
      if (spec.type == PortType::Text) {
        node.inputTypes.push_back(ValueType::Float);
        continue;
      }
      ValueType portType = spec.type == PortType::Generic ? generic : fixedPortType(spec.type);
      node.inputTypes.push_back(portType);
      if (!isImplicitlyConvertible(node.inputs[i].type, portType)) {
        std::string hint = conversionHint(node.inputs[i].type, portType, spec.type == PortType::Generic);
        report(DiagCode::TypeMismatch, portPointer(p, i),
               {"input '" + std::string(spec.name) + "' of '" + std::string(op.name) + "'", std::string(typeName(portType)),
                std::string(typeName(node.inputs[i].type)), hint});
        ok = false;
      }
    }
    switch (op.valueRule) {
      case ValueRule::Fixed: node.valueType = op.valueType; break;
      case ValueRule::Generic: node.valueType = generic; break;
      case ValueRule::Parameter: node.valueType = graph_.parameters[static_cast<std::size_t>(node.parameter)].type; break;
      case ValueRule::SwizzleText: {
        int w = accessorWidth("." + node.text, width);
        if (w == 0) {
          report(DiagCode::SwizzleMismatch, textPointer(p), {quoteUserText(node.text), typeName(generic)});
          ok = false;
        }
        node.valueType = floatVectorOfWidth(std::max(w, 1));
        break;
      }
    }
    return ok;
  }

  std::string portPointer(const PendingNode& p, std::size_t port) const {
    return p.ports[port].source ? p.ports[port].source->pointer : p.decl->pointer;
  }
  std::string textPointer(const PendingNode& p) const {
    for (const auto& in : p.ports)
      if (in.source && in.source->kind == InputSource::Kind::Link && p.op->inputs[&in - p.ports.data()].type == PortType::Text)
        return in.source->pointer;
    return p.decl->pointer;
  }

  void bindOutputs() {
    for (const auto& info : pbrFields()) {
      Operand& out = ir_.output(info.field);
      out = Operand::ofConstant(info.defaultValue);
      auto it = graph_.outputs.find(info.field);
      if (it == graph_.outputs.end()) continue;
      const InputSource& source = it->second;
      std::string what = "output '" + std::string(info.name) + "'";
      if (source.kind == InputSource::Kind::Literal) {
        if (auto operand = literalOperand(source, [&] { return what; }, info.min, info.max)) {
          if (!isImplicitlyConvertible(operand->type, info.type))
            report(DiagCode::TypeMismatch, source.pointer, {what, std::string(typeName(info.type)),
                                                            std::string(typeName(operand->type)), "give a value of the output's type"});
          else
            out = Operand::ofConstant(operand->constant.convertedTo(info.type));
        }
        continue;
      }
      PendingNode dummy;
      PendingInput in;
      resolveLink(dummy, in, source);
      if (dummy.bad || in.node == kNoNode || in.output < 0) continue;
      std::uint32_t target = irIndex_[in.node];
      if (target == kNoNode) {
        failed_ = true;
        continue;
      }
      const IrNode& node = ir_.nodes[target];
      if (accessorWidth(node.op->outputs[in.output].accessor, componentCount(node.valueType)) == 0) {
        report(DiagCode::DanglingLink, source.pointer, {quoteUserText(source.text), node.op->outputs[in.output].name,
                                                        node.op->name, "that component does not exist"});
        continue;
      }
      ValueType t = node.outputType(in.output);
      if (!isImplicitlyConvertible(t, info.type)) {
        report(DiagCode::TypeMismatch, source.pointer,
               {what, std::string(typeName(info.type)), std::string(typeName(t)), conversionHint(t, info.type, false)});
        continue;
      }
      out = Operand::ofNode(target, static_cast<std::uint8_t>(in.output), t);
    }
  }

  void resolveWeather() {
    auto config = resolveWeatherConfig(graph_.weather, graph_.weatherPointer.empty() ? "/weather" : graph_.weatherPointer,
                                       options_.weatherPreset, options_.quality, options_.weatherEffects, doc_, diags_);
    if (!config) {
      failed_ = true;
      return;
    }
    ir_.weather = *config;
    for (const auto& info : coverageTerms()) ir_.coverage(info.term) = Operand::ofConstant(Value::scalar(info.neutral));
    if (!config->active()) return;
    for (const auto& p : graph_.parameters)
      if (p.name.starts_with("weather."))
        report(DiagCode::ReservedParameterPrefix, p.pointer, {quoteUserText(p.name)});
  }

  const MaterialGraph& graph_;
  const JsonDocument& doc_;
  DiagnosticList& diags_;
  IrLimits limits_;
  IrBuildOptions options_;
  std::unordered_map<std::string, std::uint32_t> ids_;
  std::vector<PendingNode> pending_;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint32_t> irIndex_;
  IrGraph ir_;
  bool failed_ = false;
};

}  // namespace

std::optional<IrGraph> buildIr(const MaterialGraph& graph, const JsonDocument& document, DiagnosticList& diagnostics,
                               const IrBuildOptions& options) {
  return Builder(graph, document, diagnostics, options).run();
}

}  // namespace wg
