#include "backends/op_template.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "backends/library_functions.hpp"
#include "backends/surface_names.hpp"
#include "nodes/op_registry.hpp"

namespace wg {

namespace {

// Symbols that name a fixed stage-frame local or frame member.
constexpr std::array<std::pair<std::string_view, std::string_view>, 7> kFixedSymbols = {{
    {"texcoord", "wg_texcoord"},
    {"texcoord1", "wg_texcoord1"},
    {"worldPosition", "wg_worldPosition"},
    {"worldNormal", "wg_worldNormal"},
    {"worldTangent", "wg_worldTangent"},
    {"vertexColor", "wg_vertexColor"},
    {"time", "weather_time"},  // the weather block's member, as surfaces spell it
}};

constexpr std::array<std::pair<std::string_view, TemplatePiece::Kind>, 6> kSlotSymbols = {{
    {"channels", TemplatePiece::Kind::Channels},
    {"sampleFn", TemplatePiece::Kind::SampleFn},
    {"lodArg", TemplatePiece::Kind::LodArg},
    {"parameter", TemplatePiece::Kind::Parameter},
    {"texture", TemplatePiece::Kind::Texture},
    {"sampler", TemplatePiece::Kind::Sampler},
}};

TemplatePiece symbolPiece(const OpDef& op, std::string_view symbol) {
  for (auto [name, text] : kFixedSymbols)
    if (name == symbol) return {TemplatePiece::Kind::Text, text, 0};
  for (auto [name, kind] : kSlotSymbols)
    if (name == symbol) return {kind, {}, 0};
  // Unreachable: the registry refuses templates naming other symbols (op_template_check).
  throw std::logic_error("op " + std::string(op.name) + ": unknown template symbol @" + std::string(symbol));
}

TemplatePiece keyPiece(const OpDef& op, std::string_view key) {
  if (key == "T") return {TemplatePiece::Kind::Type, {}, 0};
  if (key.starts_with('@')) return symbolPiece(op, key.substr(1));
  for (std::size_t p = 0; p < op.inputs.size(); ++p)
    if (op.inputs[p].name == key) return {TemplatePiece::Kind::Input, {}, p};
  return {TemplatePiece::Kind::Text, {}, 0};  // refused by op_template_check; writes nothing
}

// Every registered op's template in both languages, spelled and split at first use.
struct SplitTemplates {
  std::array<std::unordered_map<const OpDef*, SpelledOpTemplate>, 2> byLanguage;
  SplitTemplates() {
    for (ShaderLanguage language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl})
      for (const OpDef* op : allOps())
        byLanguage[static_cast<std::size_t>(language)].try_emplace(op, *op, syntaxFor(language).opCode(*op));
  }
};

}  // namespace

OpTemplate splitOpTemplate(const OpDef& op, std::string_view code) {
  OpTemplate split;
  forEachLibraryCall(code, [&](std::string_view name) { split.calls.push_back(name); });
  std::vector<TemplatePiece>& pieces = split.pieces;
  std::size_t done = 0;
  for (std::size_t open = code.find('{'); open != std::string_view::npos; open = code.find('{', done)) {
    if (open > done) pieces.push_back({TemplatePiece::Kind::Text, code.substr(done, open - done), 0});
    std::size_t close = code.find('}', open);
    pieces.push_back(keyPiece(op, code.substr(open + 1, close - open - 1)));
    done = close + 1;
  }
  if (done < code.size()) pieces.push_back({TemplatePiece::Kind::Text, code.substr(done), 0});
  return split;
}

SpelledOpTemplate::SpelledOpTemplate(const OpDef& op, std::string_view languageCode)
    : code(renameTokens(languageCode, surfaceFrameNames())), split(splitOpTemplate(op, code)) {}

const OpTemplate* registeredOpTemplate(const ShaderSyntax& syntax, const OpDef& op) {
  static const SplitTemplates split;
  const auto& templates = split.byLanguage[static_cast<std::size_t>(syntax.language())];
  auto it = templates.find(&op);
  return it == templates.end() ? nullptr : &it->second.split;
}

}  // namespace wg
