#include "cli/eval_inputs.hpp"

#include "cli/number_text.hpp"

#include <array>
#include <charconv>
#include <iterator>
#include <cmath>
#include <limits>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/literal.hpp"
#include "nodes/frame_fields.hpp"
#include "weather/frame_weather.hpp"

namespace wg {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr char kComponentSeparator = ':';
constexpr char kListSeparator = ',';
// Below this length a direction counts as zero ("no wind") and is left as it is.
constexpr float kMinDirectionLength = 1e-6f;

using G = EvalInputGroup;

std::span<float> one(float& x) { return {&x, 1}; }

std::vector<EvalInputSpec> makeSpecs() {
  std::vector<EvalInputSpec> specs;
  // --weather: the frame table's weather members, with its ranges and docs.
  for (const FrameField& f : frameFields()) {
    if (f.owner != FrameFieldOwner::Weather) continue;
    specs.push_back({f.name, G::Weather, componentCount(f.type), f.min, f.max, f.doc,
                     [field = &f](EvalInputs& in) { return fieldFloats(*field, in.frame); }});
  }
  // --at: the surface attributes.
  const EvalInputSpec surface[] = {
    {"worldPosition", G::Surface, 3, -kInf, kInf, "metres, y up; the vertex stage's offset moves it for the fragment stage",
     [](EvalInputs& in) { return std::span<float>(in.surface.worldPosition); }},
    {"normal", G::Surface, 3, -kInf, kInf, "geometric normal (normalised as the shaders do; 0:0:0 allowed)",
     [](EvalInputs& in) { return std::span<float>(in.surface.worldNormal); }},
    {"tangent", G::Surface, 3, -kInf, kInf, "x:y:z[:w], w the bitangent sign (made orthogonal to the normal)",
     [](EvalInputs& in) { return std::span<float>(in.surface.tangent); }},
    {"texcoord", G::Surface, 2, -kInf, kInf, "mesh texture coordinate u:v",
     [](EvalInputs& in) { return std::span<float>(in.surface.texcoord); }},
    {"texcoord1", G::Surface, 2, -kInf, kInf, "mesh texture coordinate set 1 u:v (op texcoord1)",
     [](EvalInputs& in) { return std::span<float>(in.surface.texcoord1); }},
    {"vertexColor", G::Surface, 3, 0.f, 1.f, "r:g:b[:a] mesh vertex colour",
     [](EvalInputs& in) { return std::span<float>(in.surface.vertexColor); }},
    {"skyExposure", G::Surface, 1, 0.f, 1.f, "open sky above the point (the shared map's value): 1 open, 0 roofed",
     [](EvalInputs& in) { return one(in.surface.skyExposure); }},
  };
  specs.insert(specs.end(), std::begin(surface), std::end(surface));
  return specs;
}

const std::vector<EvalInputSpec>& specs() {
  static const std::vector<EvalInputSpec> kSpecs = makeSpecs();
  return kSpecs;
}

std::string rangeText(float lo, float hi) {
  if (lo == -kInf && hi == kInf) return "any finite number";
  if (hi == kInf) return "at least " + formatNumber(lo);
  return "[" + formatNumber(lo) + ", " + formatNumber(hi) + "]";
}

// "0:1:0" -> components; false when a component is not a number by the graphs' rules.
bool parseComponents(std::string_view text, std::vector<float>& out) {
  out.clear();
  std::size_t start = 0;
  while (true) {
    std::size_t end = text.find(kComponentSeparator, start);
    std::string_view item = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    const std::optional<double> x = parseNumberText(item);
    if (!x) return false;
    // Beyond float's range becomes infinite, so the finiteness check reports it.
    out.push_back(std::abs(*x) > std::numeric_limits<float>::max() ? std::copysign(kInf, static_cast<float>(*x))
                                                                     : static_cast<float>(*x));
    if (end == std::string_view::npos) return true;
    start = end + 1;
  }
}

std::string example(std::string_view name, std::size_t components) {
  std::string value = "0";
  for (std::size_t i = 1; i < components; ++i) value += ":0";
  return std::string(name) + "=" + value;
}

// Splits "a=1,b=2" and hands each key and value text to `apply`, which returns an error.
template <class Apply>
std::string forEachEntry(std::string_view list, std::string_view flag, std::set<std::string>& seen, Apply apply) {
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t end = list.find(kListSeparator, start);
    std::string_view entry = list.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    std::size_t equals = entry.find('=');
    if (entry.empty()) return std::string(flag) + ": empty entry; write name=value pairs separated by ','";
    if (equals == std::string_view::npos)
      return std::string(flag) + ": '" + quoteUserText(entry) + "' has no value; write " + quoteUserText(entry) + "=VALUE";
    std::string key(entry.substr(0, equals));
    if (!seen.insert(key).second)
      return std::string(flag) + ": '" + quoteUserText(key) + "' is given twice; give each key once";
    if (std::string error = apply(key, entry.substr(equals + 1)); !error.empty()) return error;
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return "";
}

// Checks and stores `text` into `field` (size components, at least minComponents given).
std::string storeComponents(std::string_view flag, const std::string& key, std::string_view text, std::span<float> field,
                            std::size_t minComponents, float lo, float hi) {
  std::vector<float> values;
  std::string where = std::string(flag) + " " + quoteUserText(key);
  std::string counts = minComponents == field.size()
                           ? std::to_string(field.size())
                           : std::to_string(minComponents) + " or " + std::to_string(field.size());
  if (!parseComponents(text, values))
    return where + ": '" + quoteUserText(text) + "' is not a number list; write " + counts + " number" +
           (field.size() > 1 ? "s separated by ':', e.g. " : ", e.g. ") + example(key, field.size());
  if (values.size() < minComponents || values.size() > field.size())
    return where + ": '" + quoteUserText(text) + "' has " + std::to_string(values.size()) + " component" +
           (values.size() == 1 ? "" : "s") + "; write " + counts + ", e.g. " + example(key, field.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) return where + ": '" + quoteUserText(text) + "' is not finite; use finite numbers";
    if (values[i] < lo || values[i] > hi)
      return where + " = " + formatNumber(values[i]) + " is outside " + rangeText(lo, hi) + "; use a value in that range";
  }
  for (std::size_t i = 0; i < values.size(); ++i) field[i] = values[i];
  return "";
}

template <std::size_t N>
void normaliseDirection(std::array<float, N>& v) {
  // In double: a float square overflows from 2e19, which made "1e20:0" calm (0:0).
  double lengthSquared = 0.0;
  for (float x : v) lengthSquared += double(x) * double(x);
  const double length = std::sqrt(lengthSquared);
  if (length < kMinDirectionLength) return;
  for (float& x : v) x = static_cast<float>(x / length);
}

}  // namespace

std::span<const EvalInputSpec> evalInputSpecs() { return specs(); }

std::string_view evalInputFlag(EvalInputGroup group) { return group == G::Weather ? "--weather" : "--at"; }

EvalInputs defaultEvalInputs() {
  EvalInputs in;
  writeWeather(WeatherState{}, in.frame);
  return in;
}

std::string applyEvalInputList(std::string_view list, EvalInputGroup group, EvalInputs& inputs,
                               std::set<std::string>& seen) {
  std::string_view flag = evalInputFlag(group);
  return forEachEntry(list, flag, seen, [&](const std::string& key, std::string_view text) -> std::string {
    std::vector<std::string_view> names;
    for (const auto& spec : specs()) {
      if (spec.group != group) continue;
      names.push_back(spec.name);
      if (spec.name == key)
        return storeComponents(flag, key, text, spec.field(inputs), spec.minComponents, spec.min, spec.max);
    }
    std::string hint = suggestClosest(key, names);
    if (hint.empty()) {
      hint = "keys:";
      for (auto name : names) {
        hint += ' ';
        hint += name;
      }
    }
    return std::string(flag) + ": unknown key '" + quoteUserText(key) + "'; " + hint;
  });
}

std::string applyParameterList(std::string_view list, const IrGraph& graph, EvalInputs& inputs,
                               std::set<std::string>& seen) {
  return forEachEntry(list, "--param", seen, [&](const std::string& key, std::string_view text) -> std::string {
    std::vector<std::string_view> names;
    for (const auto& p : graph.parameters) {
      names.push_back(p.name);
      if (p.name != key) continue;
      Value value{p.type, {}};
      if (p.type == ValueType::Bool) {
        if (text != "true" && text != "false" && text != "1" && text != "0")
          return "--param " + quoteUserText(key) + ": '" + quoteUserText(text) + "' is not a boolean; write true or false";
        value = Value::boolean(text == "true" || text == "1");
      } else {
        std::span<float> field(value.v.data(), static_cast<std::size_t>(value.width()));
        std::string error = storeComponents("--param", key, text, field, field.size(), p.min.value_or(-kInf),
                                            p.max.value_or(kInf));
        if (!error.empty()) return error;
      }
      inputs.parameters[key] = value;
      return "";
    }
    std::string hint = suggestClosest(key, names);
    if (hint.empty()) hint = "run 'weathergen eval GRAPH --help' to list them";
    return "--param: material '" + quoteUserText(graph.name) + "' has no parameter '" + quoteUserText(key) + "'; " + hint;
  });
}

std::string finishEvalInputs(EvalInputs& inputs) {
  // The runtime's own check of the conditions, so eval accepts exactly what it does.
  if (std::string error = validate(weatherOf(inputs.frame).conditions); !error.empty())
    return "--weather " + error + "; use a value in that range";
  normaliseDirection(inputs.frame.sunDirection);
  normaliseDirection(inputs.frame.windDirection);
  return "";
}

std::string formatNumber(float x) {
  std::string s = formatFloat(x);
  if (s.ends_with(".0")) s.resize(s.size() - 2);
  return s;
}

std::string formatComponents(std::span<const float> components) {
  std::string out;
  for (std::size_t i = 0; i < components.size(); ++i) {
    if (i) out += kComponentSeparator;
    out += formatNumber(components[i]);
  }
  return out;
}

}  // namespace wg
