// Evaluates a compiled material at one surface point on the CPU, node for node with
// the same op functions the shaders mirror, so tools and tests can check what the GPU
// will compute (every PBR output and weather coverage term) without a GPU.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "compiler/ir.hpp"
#include "nodes/height_field.hpp"
#include "nodes/texture_sampling.hpp"

namespace wg {

struct EvalInputs {
  // The mesh's attributes at the point, in world space (the model matrix is taken as
  // the identity). The normal and tangent need not be unit length: the evaluator
  // normalises them as the shader stages do, and a zero normal stays zero.
  SurfacePoint surface;
  // The frame and weather uniforms, as the runtime uploads them.
  FrameState frame;
  // Material parameters by name (as in the reflection's material block), overriding
  // their defaults.
  std::map<std::string, Value, std::less<>> parameters;
  // The shared terrain height map the GPU samples (eq. 3.11-3.12); null: flat terrain.
  const HeightField* terrainHeight = nullptr;
  // The position already includes the vertex stage's offset, as a GPU read-back of the
  // fragment stage's world position does: the fragment stage then reads it unchanged.
  bool positionIsDisplaced = false;
};

struct EvalResult {
  // Every PBR field by its graph name ("baseColor", ...), converted to the field's type.
  // worldPositionOffset comes from the vertex stage, the rest from the fragment stage.
  std::map<std::string, Value, std::less<>> outputs;
  // Every coverage term by name ("snow", ..., "density"); a term the material's
  // weather does not produce has its neutral value.
  std::map<std::string, float, std::less<>> coverage;

  const Value& output(PbrField field) const;
  float coverageOf(CoverageTerm term) const;
};

class CpuEvaluator {
 public:
  // Makes the images of the graph's textures once. Throws std::runtime_error with a
  // one-line reason when a texture file can no longer be read.
  explicit CpuEvaluator(IrGraph graph);
  CpuEvaluator(IrGraph graph, TextureSampler textures);

  const IrGraph& ir() const { return graph_; }
  const TextureSampler& textures() const { return textures_; }

  // Throws std::invalid_argument when a parameter override names no parameter or has
  // a type that does not convert to the parameter's (only a float splats).
  EvalResult evaluate(const EvalInputs& inputs) const;

 private:
  std::vector<Value> parameterValues(const EvalInputs& inputs) const;
  // Evaluates, in topological order, the nodes marked in `needed`.
  void evaluateStage(const std::vector<bool>& needed, const EvalContext& context, std::vector<Value>& values) const;
  Value operandValue(const Operand& operand, const std::vector<Value>& values) const;

  IrGraph graph_;
  TextureSampler textures_;
  // Nodes each stage's shader computes: the vertex stage only what feeds
  // worldPositionOffset, the fragment stage the other fields and the coverage terms.
  std::vector<bool> vertexNodes_, fragmentNodes_;
};

}  // namespace wg
