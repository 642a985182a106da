#include "tests/fuzz/cli_options_case.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "cli/eval_inputs.hpp"
#include "cli/number_text.hpp"
#include "cli/orbit_camera_option.hpp"
#include "cli/render_options.hpp"
#include "compiler/ir.hpp"

namespace wg::fuzz {

namespace {

// More arguments only repeat what the parser does per argument.
constexpr std::size_t kMaxArguments = 64;

std::vector<std::string> splitArguments(std::string_view input) {
  std::vector<std::string> args;
  std::size_t begin = 0;
  while (args.size() < kMaxArguments) {
    const std::size_t nul = input.find('\0', begin);
    args.emplace_back(input.substr(begin, nul == std::string_view::npos ? nul : nul - begin));
    if (nul == std::string_view::npos) break;
    begin = nul + 1;
  }
  return args;
}

bool isJsonSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// parseNumberText promises JSON's number grammar: it must accept exactly what a JSON
// reader takes as a lone number, and what it returns must read back from its shortest text.
std::string checkNumber(const std::string& text) {
  const auto value = parseNumberText(text);
  // JSON readers refuse a number beyond double's range; parseNumberText reads it as
  // infinite on purpose (number_text.hpp), so those are not compared.
  const bool overflows = value && !std::isfinite(*value);
  if (!overflows && !text.empty() && !isJsonSpace(text.front()) && !isJsonSpace(text.back())) {
    const auto json = nlohmann::json::parse(text, nullptr, false);
    if (value.has_value() != json.is_number()) return "parseNumberText and JSON disagree on '" + text + "'";
  }
  if (!value || !std::isfinite(*value)) return "";
  char buffer[64];
  const auto written = std::to_chars(buffer, buffer + sizeof buffer, *value);
  const std::string shortest(buffer, written.ptr);
  const auto again = parseNumberText(shortest);
  if (!again || *again != *value || std::signbit(*again) != std::signbit(*value))
    return "'" + text + "' reads as " + shortest + ", which does not read back";
  return "";
}

std::string checkCounts(const std::string& text) {
  constexpr std::uint32_t kRanges[][2] = {{0, std::numeric_limits<std::uint32_t>::max()}, {1, 8192}, {7, 7}, {9, 3}};
  for (const auto& [min, max] : kRanges) {
    const auto count = parseCountText(text, min, max);
    if (!count) continue;
    if (*count < min || *count > max) return "parseCountText('" + text + "') is outside its range";
    if (std::to_string(*count) != text) return "parseCountText('" + text + "') = " + std::to_string(*count);
  }
  if (const auto size = parsePixelSizeText(text, 8192)) {
    if (size->width < 1 || size->width > 8192 || size->height < 1 || size->height > 8192)
      return "parsePixelSizeText('" + text + "') is outside 1..8192";
  }
  return "";
}

std::string checkOrbit(const std::string& text) {
  std::string error;
  const auto orbit = parseOrbitCamera(std::string(kOrbitCameraPrefix) + text, error);
  if (orbit.has_value() == !error.empty()) return "parseOrbitCamera gave both or neither of an orbit and an error";
  if (!orbit) return "";
  if (!std::isfinite(orbit->azimuthDegrees) || !(std::abs(orbit->elevationDegrees) <= scene::kOrbitMaxElevationDegrees))
    return "orbit:" + text + " has its angles out of range";
  if (orbit->distance && !(*orbit->distance > 0.f && *orbit->distance <= scene::kOrbitMaxDistance))
    return "orbit:" + text + " has its distance out of range";
  return "";
}

// Material parameters of every kind applyParameterList reads, some with ranges.
const IrGraph& parameterGraph() {
  static const IrGraph graph = [] {
    IrGraph g;
    g.parameters.push_back({"scale", ValueType::Float, Value::scalar(1.f), 0.01f, 64.f, "", ""});
    g.parameters.push_back({"offset", ValueType::Vec2, Value::vec2(0.f, 0.f), std::nullopt, std::nullopt, "", ""});
    g.parameters.push_back({"tint", ValueType::Vec3, Value::vec3(1.f, 1.f, 1.f), 0.f, 1.f, "", ""});
    g.parameters.push_back({"colour", ValueType::Vec4, Value::vec4(1.f, 1.f, 1.f, 1.f), 0.f, 1.f, "", ""});
    g.parameters.push_back({"wet", ValueType::Bool, Value::boolean(false), std::nullopt, std::nullopt, "", ""});
    return g;
  }();
  return graph;
}

// Every eval input is either still its default or within its spec's range; a direction
// that was not (near) zero comes out of finishEvalInputs unit length.
std::string checkEvalInputs(const std::string& text) {
  const EvalInputs defaults = defaultEvalInputs();
  EvalInputs inputs = defaultEvalInputs();
  std::set<std::string> seen;
  const bool weatherOk = applyEvalInputList(text, EvalInputGroup::Weather, inputs, seen).empty();
  const bool surfaceOk = applyEvalInputList(text, EvalInputGroup::Surface, inputs, seen).empty();
  EvalInputs before = inputs;
  for (const auto& spec : evalInputSpecs()) {
    auto field = spec.field(inputs);
    auto original = spec.field(const_cast<EvalInputs&>(defaults));
    for (std::size_t i = 0; i < field.size(); ++i)
      if (field[i] != original[i] && !(field[i] >= spec.min && field[i] <= spec.max))
        return std::string(spec.name) + " accepted a value outside its range from '" + text + "'";
  }
  if ((weatherOk || surfaceOk) && finishEvalInputs(inputs).empty()) {
    auto unitOrKept = [](std::span<const float> given, std::span<const float> out) {
      double lengthSquared = 0.0, outSquared = 0.0;
      for (float x : given) lengthSquared += double(x) * double(x);
      for (float x : out) outSquared += double(x) * double(x);
      return std::sqrt(lengthSquared) < 1e-6 || std::abs(std::sqrt(outSquared) - 1.0) < 1e-4;
    };
    if (!unitOrKept(before.frame.windDirection, inputs.frame.windDirection) ||
        !unitOrKept(before.frame.sunDirection, inputs.frame.sunDirection))
      return "a direction from '" + text + "' is not unit length after finishEvalInputs";
  }
  seen.clear();
  if (applyParameterList(text, parameterGraph(), inputs, seen).empty())
    for (const auto& p : parameterGraph().parameters) {
      const auto it = inputs.parameters.find(p.name);
      if (it == inputs.parameters.end()) continue;
      if (it->second.type != p.type) return "--param " + p.name + " changed type";
      for (int i = 0; i < componentCount(p.type); ++i) {
        const float x = it->second.v[i];
        if (!std::isfinite(x) || (p.min && x < *p.min) || (p.max && x > *p.max))
          return "--param " + p.name + " accepted a value outside its range from '" + text + "'";
      }
    }
  return "";
}

// A parse that goes on must leave every option within what its usage text promises.
std::string checkRenderOptions(const std::vector<std::string>& args) {
  std::vector<std::string> storage = {"weathergen", "render"};
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);
  RenderOptions o;
  if (parseRenderOptions(static_cast<int>(storage.size()), argv.data(), 2, o)) return "";
  const auto& r = o.request;
  if (r.width < 1 || r.width > 8192 || r.height < 1 || r.height > 8192) return "render --size out of range";
  if (!(o.step > 0.0) || !std::isfinite(o.step)) return "render --step is not a positive number";
  if (!(o.modelScale >= 1e-6f && o.modelScale <= 1e6f)) return "render --model-scale out of range";
  if (o.watchRenders && (*o.watchRenders < 1 || *o.watchRenders > 1000000)) return "render --watch-renders out of range";
  if (o.orbit.has_value() != isOrbitCamera(o.camera)) return "render --camera orbit not parsed";
  return "";
}

}  // namespace

std::string checkCliOptionsInput(std::string_view input) {
  const std::vector<std::string> args = splitArguments(input);
  for (const auto& arg : args) {
    for (auto check : {checkNumber, checkCounts, checkOrbit, checkEvalInputs})
      if (std::string broken = check(arg); !broken.empty()) return broken;
  }
  return checkRenderOptions(args);
}

}  // namespace wg::fuzz
