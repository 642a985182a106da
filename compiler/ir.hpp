// The typed, resolved graph the passes rewrite and the backends emit. It holds no
// user-spelled identifiers: node ids survive only as debug names for diagnostics.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/material_graph.hpp"
#include "compiler/pbr_output.hpp"
#include "compiler/weather_config.hpp"
#include "nodes/op_definition.hpp"

namespace wg {

struct Operand {
  enum class Kind : std::uint8_t { Node, Constant, Texture } kind = Kind::Constant;
  std::uint32_t node = 0;    // Kind::Node
  std::uint8_t output = 0;   // index into the op's outputs
  Value constant;            // Kind::Constant
  int texture = -1;          // Kind::Texture: index into IrGraph::textures
  ValueType type = ValueType::Float;  // type delivered, before conversion to the port

  static Operand ofConstant(const Value& v) { return {Kind::Constant, 0, 0, v, -1, v.type}; }
  static Operand ofNode(std::uint32_t node, std::uint8_t output, ValueType type) {
    return {Kind::Node, node, output, {}, -1, type};
  }
  static Operand ofTexture(int index) { return {Kind::Texture, 0, 0, Value::texture(index), index, ValueType::Texture}; }
  friend bool operator==(const Operand&, const Operand&) = default;
};

struct IrNode {
  const OpDef* op = nullptr;
  std::vector<Operand> inputs;         // one per port of op->inputs, defaults filled in
  std::vector<ValueType> inputTypes;   // each port's resolved type (T resolved)
  ValueType valueType = ValueType::Float;
  std::string text;                    // swizzle channels
  int parameter = -1;                  // op "parameter": index into IrGraph::parameters
  std::string debugName;               // the source node id, for diagnostics only
  bool weather = false;                // added by weather-inject: runs only while weather is active

  ValueType outputType(std::size_t output) const;
};

// The value type a port's signature fixes, or nullopt for a generic port (T). A text
// setting's port holds a placeholder float operand.
std::optional<ValueType> signatureValueType(PortType type);

// Weather coverage terms: published as AOVs, debug views and CPU-evaluator outputs.
enum class CoverageTerm : std::uint8_t { Snow, Wet, Moss, Frost, Ice, Puddle, Density };
inline constexpr std::size_t kCoverageCount = 7;
struct CoverageInfo {
  CoverageTerm term;
  std::string_view name;
  float neutral;  // value without weather: 0, or 1 for foliage density
};
const std::array<CoverageInfo, kCoverageCount>& coverageTerms();

// Every root of the graph: the PBR fields, then the coverage terms.
inline constexpr std::size_t kIrOutputCount = kPbrFieldCount + kCoverageCount;

// A stage's roots as output slots: its PBR fields and, in the fragment stage, the
// coverage terms. Made once: the stage writers ask for them per stage.
const std::vector<std::size_t>& stageOutputSlots(ShaderStage stage);

// What a fragment debug view (frame_debugView) shows instead of the lit colour: an
// output slot, or a value the stage frame computes.
enum class DebugSource : std::uint8_t { Slot, ShadingNormal, WorldPosition, GeometricNormal, Texcoord, Tangent };
struct IrDebugView {
  std::uint32_t id;
  std::string_view name;
  DebugSource source;
  std::size_t slot = 0;  // DebugSource::Slot: index into IrGraph::outputs
};

struct IrGraph {
  std::string name;
  std::vector<IrNode> nodes;  // always in a valid topological order
  std::array<Operand, kIrOutputCount> outputs;
  std::vector<ParameterDecl> parameters;
  std::vector<TextureDecl> textures;
  std::vector<std::string> includedFiles;  // graph libraries read: inputs for depfiles, not part of the hash
  float alphaCutoff = 0.5f;
  // Declared, or (when the graph leaves it out) mask once opacity is given, else opaque.
  AlphaMode alphaMode = AlphaMode::Opaque;
  bool alphaModeDeclared = false;
  bool doubleSided = false;
  WeatherConfig weather;  // what the weather-inject pass adds; preset "none" adds nothing
  // The bindings as they were before weather-inject. Shaders use them while every
  // weather level is 0 and run the weather nodes only otherwise (one uniform branch).
  std::array<Operand, kIrOutputCount> unweathered;
  // The frame uniforms whose sum, when above 0, runs the weather nodes; empty when the
  // weather is off and nothing is guarded.
  std::vector<std::string_view> weatherGuard;
  std::vector<IrDebugView> debugViews;  // the fragment stage's views besides "lit"
  // Nodes the vertex stage computes and the fragment stage reads interpolated, in index
  // order. Set by the last pass (vertex-rate), since it records node indices.
  std::vector<std::uint32_t> interpolants;

  bool weatherGuarded() const { return !weatherGuard.empty(); }

  // Every root: the outputs, then (with weather) the unweathered bindings.
  template <typename F>
  void forEachRoot(F&& f) {
    for (auto& o : outputs) f(o);
    if (weatherGuarded())
      for (auto& o : unweathered) f(o);
  }
  template <typename F>
  void forEachRoot(F&& f) const {
    for (const auto& o : outputs) f(o);
    if (weatherGuarded())
      for (const auto& o : unweathered) f(o);
  }

  // Fragments with opacity below alphaCutoff are discarded.
  bool alphaTested() const { return alphaMode == AlphaMode::Mask; }

  Operand& output(PbrField field) { return outputs[static_cast<std::size_t>(field)]; }
  const Operand& output(PbrField field) const { return outputs[static_cast<std::size_t>(field)]; }
  Operand& coverage(CoverageTerm term) { return outputs[kPbrFieldCount + static_cast<std::size_t>(term)]; }
  const Operand& coverage(CoverageTerm term) const { return outputs[kPbrFieldCount + static_cast<std::size_t>(term)]; }
};

}  // namespace wg
