// The inputs 'weathergen eval' accepts, as name=value lists: the frame block's weather
// members (--weather), the surface attributes (--at) and the material's parameters
// (--param). Vectors are written with ':' between components ("normal=0:1:0",
// "windDirection=1:0" for x:z). Every error is one line naming the key and the fix.
#pragma once
#include <cstdint>
#include <functional>
#include <set>
#include <span>
#include <string>
#include <string_view>

#include "compiler/cpu_evaluator.hpp"

namespace wg {

enum class EvalInputGroup : std::uint8_t { Weather, Surface };

// The weather inputs come from the frame table (nodes/frame_fields.hpp).
struct EvalInputSpec {
  std::string_view name;  // the frame block member or surface attribute
  EvalInputGroup group;
  std::size_t minComponents;  // fewer than the field's size keeps the default tail (tangent w, colour alpha)
  float min, max;             // accepted range of each component
  std::string_view doc;       // unit and meaning, for --help
  std::function<std::span<float>(EvalInputs&)> field;
};

std::span<const EvalInputSpec> evalInputSpecs();
std::string_view evalInputFlag(EvalInputGroup group);  // "--weather" or "--at"

// The defaults: the runtime's initial weather state (mild, dry, calm, sun overhead at
// full intensity, no accumulated levels) on an up-facing point at the origin.
EvalInputs defaultEvalInputs();

// Parses one list ("temperature=-5,precipitation=1") into `inputs`. `seen` collects
// the keys given so far, so a key given twice is an error. Returns "" or the error.
std::string applyEvalInputList(std::string_view list, EvalInputGroup group, EvalInputs& inputs,
                               std::set<std::string>& seen);
// The same for --param, against the compiled material's parameters (types, ranges).
std::string applyParameterList(std::string_view list, const IrGraph& graph, EvalInputs& inputs,
                               std::set<std::string>& seen);
// After every list: checks the weather conditions as the runtime does and makes the
// sun and wind directions unit length, as the frame block requires (zero stays zero).
std::string finishEvalInputs(EvalInputs& inputs);

// Shortest round-trip text without a needless ".0": "15", "0.82", "1e-07".
std::string formatNumber(float x);
// Components joined with ':', as the lists take them.
std::string formatComponents(std::span<const float> components);

}  // namespace wg
