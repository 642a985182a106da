#include "compiler/cpu_evaluator.hpp"

#include <cmath>
#include <stdexcept>

#include "compiler/texture_loading.hpp"

namespace wg {

namespace {

// wg_safe_normalize's floor on the squared length (nodes/core_library.cpp): a zero
// vector stays zero instead of becoming NaN.
constexpr float kSafeNormalizeMinLengthSquared = 1e-12f;

std::array<float, 3> safeNormalize(const std::array<float, 3>& v) {
  const float lengthSquared = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const float inverse = 1.f / std::sqrt(std::max(lengthSquared, kSafeNormalizeMinLengthSquared));
  return {v[0] * inverse, v[1] * inverse, v[2] * inverse};
}

// What the vertex shader computes before the graph: world normal and tangent
// normalised (the model and normal matrices are the identity here).
SurfacePoint vertexSurface(const SurfacePoint& mesh) {
  SurfacePoint s = mesh;
  s.worldNormal = safeNormalize(mesh.worldNormal);
  const auto axis = safeNormalize({mesh.tangent[0], mesh.tangent[1], mesh.tangent[2]});
  s.tangent = {axis[0], axis[1], axis[2], mesh.tangent[3]};
  return s;
}

// What the fragment shader sees: the position moved by the vertex stage's
// worldPositionOffset, the interpolated normal renormalised (a front face), and the
// tangent made orthogonal to it (Gram-Schmidt) and renormalised.
SurfacePoint fragmentSurface(const SurfacePoint& vertex, const Value& offset) {
  SurfacePoint s = vertex;
  for (int i = 0; i < 3; ++i) s.worldPosition[i] = vertex.worldPosition[i] + offset.v[i];
  const auto& n = s.worldNormal = safeNormalize(vertex.worldNormal);
  const auto& t = vertex.tangent;
  const float along = n[0] * t[0] + n[1] * t[1] + n[2] * t[2];
  const auto axis = safeNormalize({t[0] - n[0] * along, t[1] - n[1] * along, t[2] - n[2] * along});
  s.tangent = {axis[0], axis[1], axis[2], t[3]};
  return s;
}

// The nodes a stage's shader computes: everything its roots depend on.
std::vector<bool> stageNodes(const IrGraph& graph, ShaderStage stage) {
  std::vector<bool> needed(graph.nodes.size(), false);
  auto mark = [&](const Operand& o) {
    if (o.kind == Operand::Kind::Node) needed[o.node] = true;
  };
  for (const auto& info : pbrFields())
    if (info.stage == stage) mark(graph.output(info.field));
  if (stage == ShaderStage::Fragment)
    for (const auto& info : coverageTerms()) mark(graph.coverage(info.term));
  // Inputs always precede their users, so one backwards sweep closes the set.
  for (std::size_t i = graph.nodes.size(); i-- > 0;)
    if (needed[i])
      for (const auto& o : graph.nodes[i].inputs) mark(o);
  return needed;
}

TextureSampler texturesOrThrow(const IrGraph& graph) {
  TextureLoadResult loaded = loadTextureSampler(graph.textures);
  if (!loaded.sampler) throw std::runtime_error("texture '" + loaded.texture + "': " + loaded.reason);
  return std::move(*loaded.sampler);
}

}  // namespace

const Value& EvalResult::output(PbrField field) const { return outputs.at(std::string(pbrField(field).name)); }

float EvalResult::coverageOf(CoverageTerm term) const {
  return coverage.at(std::string(coverageTerms()[static_cast<std::size_t>(term)].name));
}

CpuEvaluator::CpuEvaluator(IrGraph graph) : CpuEvaluator(graph, texturesOrThrow(graph)) {}

CpuEvaluator::CpuEvaluator(IrGraph graph, TextureSampler textures)
    : graph_(std::move(graph)),
      textures_(std::move(textures)),
      vertexNodes_(stageNodes(graph_, ShaderStage::Vertex)),
      fragmentNodes_(stageNodes(graph_, ShaderStage::Fragment)) {}

std::vector<Value> CpuEvaluator::parameterValues(const EvalInputs& inputs) const {
  std::vector<Value> values;
  for (const auto& p : graph_.parameters) values.push_back(p.defaultValue);
  for (const auto& [name, value] : inputs.parameters) {
    std::size_t index = 0;
    while (index < graph_.parameters.size() && graph_.parameters[index].name != name) ++index;
    if (index == graph_.parameters.size())
      throw std::invalid_argument("material '" + graph_.name + "' has no parameter '" + name + "'");
    const ValueType type = graph_.parameters[index].type;
    if (!isImplicitlyConvertible(value.type, type))
      throw std::invalid_argument("parameter '" + name + "' is a " + std::string(typeName(type)) + ", not a " +
                                  std::string(typeName(value.type)));
    values[index] = value.convertedTo(type);
  }
  return values;
}

Value CpuEvaluator::operandValue(const Operand& operand, const std::vector<Value>& values) const {
  switch (operand.kind) {
    case Operand::Kind::Constant: return operand.constant;
    case Operand::Kind::Texture: return Value::texture(operand.texture);
    case Operand::Kind::Node: break;
  }
  const IrNode& source = graph_.nodes[operand.node];
  return applyAccessor(values[operand.node], source.op->outputs[operand.output].accessor);
}

void CpuEvaluator::evaluateStage(const std::vector<bool>& needed, const EvalContext& stageContext,
                                 std::vector<Value>& values) const {
  std::vector<Value> inputs;
  EvalContext context = stageContext;
  for (std::size_t i = 0; i < graph_.nodes.size(); ++i) {
    if (!needed[i]) continue;
    const IrNode& node = graph_.nodes[i];
    inputs.clear();
    // Each port gets its resolved type, as the shader's expression does (a float
    // feeding a vector port is splatted), exactly as constant folding converts.
    for (std::size_t p = 0; p < node.inputs.size(); ++p)
      inputs.push_back(operandValue(node.inputs[p], values).convertedTo(node.inputTypes[p]));
    context.text = node.text;
    context.parameterIndex = node.parameter;
    values[i] = node.op->eval(inputs.data(), context);
  }
}

EvalResult CpuEvaluator::evaluate(const EvalInputs& in) const {
  const std::vector<Value> parameters = parameterValues(in);
  std::vector<Value> values(graph_.nodes.size());
  EvalContext context;
  context.textures = &textures_;
  context.parameters = &parameters;
  context.frame = &in.frame;
  context.terrainHeight = in.terrainHeight;

  // Vertex stage first: its offset moves the position the fragment stage reads.
  const SurfacePoint vertex = vertexSurface(in.surface);
  context.surface = &vertex;
  evaluateStage(vertexNodes_, context, values);
  const PbrFieldInfo& offsetField = pbrField(PbrField::WorldPositionOffset);
  const Value offset = operandValue(graph_.output(offsetField.field), values).convertedTo(offsetField.type);

  // Nodes both stages use are recomputed with the fragment stage's inputs.
  const SurfacePoint fragment = fragmentSurface(vertex, in.positionIsDisplaced ? Value::vec3(0.f, 0.f, 0.f) : offset);
  context.surface = &fragment;
  evaluateStage(fragmentNodes_, context, values);

  EvalResult result;
  for (const auto& info : pbrFields())
    result.outputs[std::string(info.name)] =
        info.field == offsetField.field ? offset : operandValue(graph_.output(info.field), values).convertedTo(info.type);
  for (const auto& info : coverageTerms())
    result.coverage[std::string(info.name)] = operandValue(graph_.coverage(info.term), values).convertedTo(ValueType::Float).x();
  return result;
}

}  // namespace wg
