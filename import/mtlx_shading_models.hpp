// The surface shaders MaterialX import maps onto the UE4 model, as data: for each, the
// input that feeds each graph output, the inputs' MaterialX defaults, and the inputs the
// UE4 model cannot hold (docs/materialx-import.md, "Shading models").
#pragma once
#include <string_view>
#include <utility>
#include <vector>

namespace wg::mtlx {

// An input the UE4 model cannot hold, and when setting it changes nothing: its neutral
// value, or the lobe weight that switches it off.
struct IgnoredInput {
  const char* prefix;  // the input, or every input starting with it when it ends in '_'
  const char* weight;  // the lobe's weight input ("" for none)
  const char* neutral; // the value that changes nothing ("" for none)
};

struct ShadingModel {
  const char* category;
  // the input feeding each graph output; "" when the model has none
  const char* baseColor;
  const char* baseWeight;
  const char* metallic;
  const char* roughness;
  const char* emissive;
  const char* emissiveWeight;
  const char* opacity;
  const char* normal;
  const char* occlusion;
  const char* specularWeight;
  const char* ior;
  std::vector<std::pair<const char*, const char*>> defaults;  // input -> default value text
  std::vector<IgnoredInput> ignored;
};

// The model of a shader category (standard_surface...), or nullptr.
const ShadingModel* shadingModel(std::string_view category);

}  // namespace wg::mtlx
