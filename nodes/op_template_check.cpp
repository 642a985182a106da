#include "nodes/op_template_check.hpp"

#include <algorithm>
#include <array>

namespace wg {

namespace {

constexpr std::array<std::string_view, 13> kSymbols = {
    "texcoord", "texcoord1", "worldPosition", "worldNormal", "worldTangent", "vertexColor", "time",
    "channels", "sampleFn",  "lodArg",        "parameter",   "texture",      "sampler"};

bool hasTextureInput(const OpDef& op) {
  return std::any_of(op.inputs.begin(), op.inputs.end(), [](const PortSpec& p) { return p.type == PortType::TextureName; });
}

std::optional<std::string> keyError(const OpDef& op, std::string_view key) {
  if (key == "T" || op.findInput(key)) return std::nullopt;
  if (!key.starts_with('@')) return "{" + std::string(key) + "} names no input port";
  std::string_view symbol = key.substr(1);
  if (std::find(kSymbols.begin(), kSymbols.end(), symbol) == kSymbols.end())
    return "{" + std::string(key) + "} names no symbol the stage writer provides";
  if ((symbol == "texture" || symbol == "sampler") && !hasTextureInput(op))
    return "{" + std::string(key) + "} needs a texture input";
  return std::nullopt;
}

std::optional<std::string> codeError(const OpDef& op, std::string_view code, std::string_view language) {
  for (std::size_t open = code.find('{'); open != std::string_view::npos; open = code.find('{', open + 1)) {
    std::size_t close = code.find('}', open);
    if (close == std::string_view::npos) return std::string(language) + " template has an unclosed '{'";
    if (auto error = keyError(op, code.substr(open + 1, close - open - 1))) return std::string(language) + " template: " + *error;
  }
  return std::nullopt;
}

}  // namespace

std::span<const std::string_view> templateSymbols() { return kSymbols; }

std::optional<std::string> templateError(const OpDef& op) {
  if (op.glsl.empty()) return std::string("the glsl template is empty");
  if (auto error = codeError(op, op.glsl, "glsl")) return error;
  if (!op.hlsl.empty()) return codeError(op, op.hlsl, "hlsl");
  return std::nullopt;
}

}  // namespace wg
