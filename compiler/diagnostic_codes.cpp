#include "compiler/diagnostic_codes.hpp"

#include <algorithm>
#include <array>

namespace wg {

namespace {
using enum DiagCode;
constexpr auto E = Severity::Error;
constexpr auto W = Severity::Warning;
constexpr auto In = DiagCategory::Input;
constexpr auto Use = DiagCategory::Usage;
constexpr auto Bug = DiagCategory::Internal;

constexpr std::array<DiagnosticInfo, static_cast<std::size_t>(kCount)> kTable = {{
    {JsonSyntax, "WG1001", E, In, "json-syntax", "malformed JSON: {detail}",
     "fix the JSON syntax at this position", "detail"},
    {FileUnreadable, "WG1002", E, In, "file-unreadable", "cannot read '{path}': {reason}", "{fix}", "path reason fix"},
    {WrongJsonKind, "WG1003", E, In, "wrong-json-kind", "{what} must be {expected}, not {actual}",
     "change the value to {expected}", "what expected actual"},
    {MissingField, "WG1004", E, In, "missing-field", "missing required field '{field}'",
     "add '{field}' to this object", "field"},
    {UnknownField, "WG1005", E, In, "unknown-field", "unknown field '{field}'", "{suggestion}", "field suggestion"},
    {DuplicateKey, "WG1006", E, In, "duplicate-key", "key '{key}' appears twice in one object",
     "remove or rename one of the two entries", "key"},
    {ResourceLimit, "WG1007", E, In, "resource-limit", "{what} is {value}; the limit is {limit}",
     "bring it within the limit: split or simplify the input, or shrink the file or image", "what value limit"},
    {ImportIndex, "WG1008", E, In, "import-index", "this is the index 'weathergen import' writes, not a material graph",
     "compile the graphs it lists instead: {graphs}", "graphs"},
    {UnknownOp, "WG2001", E, In, "unknown-op", "unknown op '{op}'", "{suggestion}", "op suggestion"},
    {DuplicateId, "WG2002", E, In, "duplicate-id", "node id '{id}' is already used by {other}",
     "give every node a unique id", "id other"},
    {UnknownNode, "WG2003", E, In, "unknown-node", "link '{link}' names node '{node}', which does not exist",
     "{suggestion}", "link node suggestion"},
    {DanglingLink, "WG2004", E, In, "dangling-link",
     "link '{link}' names output '{output}', which op '{op}' does not have", "{suggestion}", "link output op suggestion"},
    {MalformedLink, "WG2005", E, In, "malformed-link", "link '{link}' is not of the form 'nodeId.output'",
     "write links as \"nodeId.output\", e.g. \"noise1.out\"", "link"},
    {UnknownInput, "WG2006", E, In, "unknown-input", "op '{op}' has no input '{input}'", "{suggestion}", "op input suggestion"},
    {MissingInput, "WG2007", E, In, "missing-input", "op '{op}' needs input '{input}' ({type})",
     "connect '{input}' to a node output or give it a literal", "op input type"},
    {TypeMismatch, "WG2008", E, In, "type-mismatch", "{what} expects {expected} but gets {actual}",
     "{fix}", "what expected actual fix"},
    {Cycle, "WG2009", E, In, "cycle", "the graph has a cycle: {path}",
     "break the cycle; a node cannot depend on its own output", "path"},
    {LiteralOutOfRange, "WG2010", E, In, "literal-out-of-range", "{what} is {value}, outside [{min}, {max}]",
     "use a value between {min} and {max}", "what value min max"},
    {LiteralNotFinite, "WG2011", E, In, "literal-not-finite", "{what} is not a finite number",
     "use a finite number", "what"},
    {UnknownParameter, "WG2012", E, In, "unknown-parameter", "parameter '{parameter}' is not declared",
     "{suggestion}", "parameter suggestion"},
    {InvalidParameterType, "WG2013", E, In, "invalid-parameter-type",
     "parameter '{parameter}': type '{type}' is not a parameter type", "use float, vec2, vec3, vec4 or bool",
     "parameter type"},
    {UnknownAlphaMode, "WG2014", E, In, "unknown-alpha-mode", "unknown alphaMode '{mode}'", "{suggestion}",
     "mode suggestion"},
    {UnknownSwitch, "WG2015", E, In, "unknown-switch", "switch '{switch}' is not declared", "{suggestion}", "switch suggestion"},
    {InvalidSwitchType, "WG2016", E, In, "invalid-switch-type", "switch '{switch}': type '{type}' is not a switch type",
     "use \"type\": \"bool\", or list the choices in \"values\"", "switch type"},
    {UnknownSwitchValue, "WG2017", E, In, "unknown-switch-value", "switch '{switch}' has no value {value}",
     "use one of: {values}", "switch value values"},
    {SwitchCasesMismatch, "WG2018", E, In, "switch-cases-mismatch", "switch node '{node}' {problem}",
     "give one case for each value of switch '{switch}': {values}", "node problem switch values"},
    {EmptyName, "WG2019", E, In, "empty-name", "the {what} is empty", "write a non-empty {what}", "what"},
    {OutputNameCollision, "WG2020", E, Use, "output-name-collision",
     "material '{material}' writes the same files as {other}", "give each material in one batch a distinct name",
     "material other"},
    {NotAPlainWord, "WG2021", E, In, "not-a-plain-word", "{what} '{word}' is not a plain word",
     "use letters, digits, '_' and '-' only, starting with a letter", "what word"},
    {SwizzleMismatch, "WG2022", E, In, "swizzle-mismatch", "swizzle channels '{channels}' do not fit a {type}",
     "use 1 to 4 channels the input has, all from x, y, z, w or all from r, g, b, a", "channels type"},
    {SwitchKindAmbiguous, "WG2023", E, In, "switch-kind-ambiguous",
     "switch '{switch}' needs exactly one of \"type\": \"bool\" and \"values\"",
     "declare \"type\": \"bool\" with \"default\": true, or \"values\": [\"low\", \"high\"] with \"default\": \"high\"",
     "switch"},
    {SwitchValueCount, "WG2024", E, In, "switch-value-count", "switch '{switch}' lists {count}",
     "list 2 to {max} values", "switch count max"},
    {DuplicateSwitchValue, "WG2025", E, In, "duplicate-switch-value", "switch '{switch}' lists value '{value}' twice",
     "list each value once", "switch value"},
    {DuplicateParameter, "WG2026", E, In, "duplicate-parameter", "parameter '{parameter}' is also declared at {other}",
     "rename one of them; a library's parameters are named ALIAS.NAME", "parameter other"},
    {BoolParameterRange, "WG2027", E, In, "bool-parameter-range", "parameter '{parameter}': a bool parameter has no {bound}",
     "remove '{bound}'", "parameter bound"},
    {ParameterRangeInverted, "WG2028", E, In, "parameter-range-inverted",
     "parameter '{parameter}': min {min} is above max {max}", "swap min and max", "parameter min max"},
    {UnknownTexture, "WG3001", E, In, "unknown-texture", "texture '{texture}' is not declared",
     "{suggestion}", "texture suggestion"},
    {TextureFileMissing, "WG3002", E, In, "texture-file-missing",
     "texture '{texture}': file '{file}' not found", "paths are relative to the graph file", "texture file"},
    {TextureUnsupported, "WG3003", E, In, "texture-unsupported", "texture '{texture}': {reason}",
     "use a PNG, JPEG, TGA or BMP image", "texture reason"},
    {DuplicateTexture, "WG3004", E, In, "duplicate-texture", "texture '{texture}' is also declared at {other}",
     "rename one of them", "texture other"},
    {TextureSourceConflict, "WG3005", E, In, "texture-source-conflict", "texture '{texture}' sets {what}",
     "give exactly one source: an image 'file' or a procedural 'generator'", "texture what"},
    {UnknownSamplerValue, "WG3006", E, In, "unknown-sampler-value", "texture '{texture}': unknown {setting} '{value}'",
     "{suggestion}", "texture setting value suggestion"},
    {UnknownGenerator, "WG3007", E, In, "unknown-generator", "texture '{texture}': unknown generator '{generator}'",
     "{suggestion}", "texture generator suggestion"},
    {InvalidGeneratorOption, "WG3008", E, In, "invalid-generator-option", "texture '{texture}': {problem}",
     "see 'weathergen list-generators' for each generator's options, seed and size", "texture problem"},
    {WrapModeCount, "WG3009", E, In, "wrap-mode-count", "texture '{texture}': 'wrap' lists {count}",
     "give one mode, or two as [u, v]: [\"repeat\", \"clamp\"]", "texture count"},
    {ProceduralSrgb, "WG3010", E, In, "procedural-srgb", "texture '{texture}': a procedural texture cannot be sRGB",
     "generators make linear values: remove colorSpace or set it to linear (srgb is for image files)", "texture"},
    {UnknownWeatherPreset, "WG4001", E, In, "unknown-weather-preset", "unknown weather preset '{preset}'", "{suggestion}", "preset suggestion"},
    {WeatherSettingOutOfRange, "WG4002", E, In, "weather-setting-out-of-range",
     "weather setting '{setting}' is {value}, outside [{min}, {max}]", "use a value between {min} and {max}",
     "setting value min max"},
    {WeatherEffectNeedsWhen, "WG4003", E, In, "weather-effect-needs-when",
     "weather effect '{effect}': switch '{switch}' is not a bool switch, so the effect needs 'when'",
     "add \"when\": the values that turn the effect on, e.g. [\"{value}\"]", "effect switch value"},
    {ReservedParameterPrefix, "WG4004", E, In, "reserved-parameter-prefix",
     "parameter '{parameter}' uses the prefix 'weather.', which the weather pass reserves", "rename the parameter",
     "parameter"},
    {WeatherEffectForm, "WG4005", E, In, "weather-effect-form", "weather effect '{effect}' is not true, false or a switched effect",
     "write true, false, or an object with \"switch\": a switch's name (and \"when\" for a switch with values)", "effect"},
    {UnknownWeatherKey, "WG4006", E, In, "unknown-weather-key", "unknown weather {kind} '{name}'", "{suggestion}",
     "kind name suggestion"},
    {WeatherSettingKind, "WG4007", E, In, "weather-setting-kind", "weather {what} must be {expected}, not {actual}",
     "change the value to {expected}", "what expected actual"},
    {WeatherPresetMissing, "WG4008", E, In, "weather-preset-missing", "the weather block has no 'preset'",
     "add \"preset\": one of {presets}", "presets"},
    {WeatherHeightRange, "WG4009", E, In, "weather-height-range", "minHeight {min} is not below maxHeight {max}",
     "make minHeight smaller than maxHeight", "min max"},
    {GltfContainer, "WG5001", E, In, "gltf-container", "not a readable glTF 2.0 file: {reason}", "{fix}", "reason fix"},
    {GltfSchema, "WG5002", E, In, "gltf-schema", "{what} must be {expected}, not {actual}",
     "see the glTF 2.0 schema for this property; re-export the model or fix the file", "what expected actual"},
    {GltfBadReference, "WG5003", E, In, "gltf-bad-reference", "{problem}", "{fix}", "problem fix"},
    {GltfResource, "WG5004", E, In, "gltf-resource", "{resource}: {problem}", "{fix}", "resource problem fix"},
    {GltfRequiredExtension, "WG5005", E, In, "gltf-required-extension",
     "the model requires extension '{extension}', which weathergen cannot read", "{fix}", "extension fix"},
    {GltfNodeHierarchy, "WG5006", E, In, "gltf-node-hierarchy", "{problem}",
     "glTF nodes form strict trees: each node has at most one parent and is never its own ancestor", "problem"},
    {GltfInvalidData, "WG5007", E, In, "gltf-invalid-data", "{problem}", "{fix}", "problem fix"},
    {GltfExtensionIgnored, "WG5101", W, In, "gltf-extension-ignored",
     "material {material} uses extension '{extension}', which the import does not map; it is ignored",
     "the graph keeps the core metallic-roughness model; edit the graph to add what the extension did", "material extension"},
    {GltfFeatureIgnored, "WG5102", W, In, "gltf-feature-ignored", "{problem}", "{fix}", "problem fix"},
    {GltfModelUnits, "WG5103", W, In, "gltf-model-units", "the model spans {size} m at {scale} m per unit; {guess}",
     "{fix}", "size scale guess fix"},
    {MtlxXml, "WG5201", E, In, "mtlx-xml", "not a readable MaterialX document: {reason}", "{fix}", "reason fix"},
    {MtlxSchema, "WG5202", E, In, "mtlx-schema", "{what} must be {expected}, not {actual}",
     "see the MaterialX 1.39 specification for this element; fix the document", "what expected actual"},
    {MtlxBadReference, "WG5203", E, In, "mtlx-bad-reference", "{problem}", "{fix}", "problem fix"},
    {MtlxUnsupportedNode, "WG5204", E, In, "mtlx-unsupported-node",
     "node '{node}' is a '{category}', which the import does not map", "{fix}", "node category fix"},
    {MtlxResource, "WG5205", E, In, "mtlx-resource", "{resource}: {problem}", "{fix}", "resource problem fix"},
    {MtlxInputIgnored, "WG5301", W, In, "mtlx-input-ignored",
     "shader '{shader}' sets '{input}', which the UE4 model cannot hold; it is ignored",
     "the graph keeps base colour, metallic, roughness, emission, opacity and normal; edit the graph to approximate the rest",
     "shader input"},
    {MtlxFeatureAdjusted, "WG5302", W, In, "mtlx-feature-adjusted", "{problem}", "{fix}", "problem fix"},
    {FilamentLimit, "WG6001", E, In, "filament-limit",
     "the Filament material needs {count} {what} ({parts}); Filament 1.9 gives a material {limit}", "{fix}",
     "count what parts limit fix"},
    {UsageError, "WG9001", E, Use, "usage", "{problem}", "run 'weathergen --help' for usage", "problem"},
    {InternalShaderError, "WG9901", E, Bug, "internal-shader-error",
     "emitted {stage} failed to compile: {log}", "this is a weathergen bug; please report it", "stage log"},
    {InternalSpirvInvalid, "WG9902", E, Bug, "internal-spirv-invalid",
     "SPIR-V for {stage} failed validation: {log}", "this is a weathergen bug; please report it", "stage log"},
    {InternalException, "WG9900", E, Bug, "internal-exception", "internal error: {what}",
     "this is a weathergen bug; please report it with the graph that caused it", "what"},
    {InternalIrInvalid, "WG9903", E, Bug, "internal-ir-invalid", "the IR breaks an invariant after '{pass}': {problem}",
     "this is a weathergen bug; please report it with the graph that caused it", "pass problem"},
}};

constexpr bool tableMatchesEnum() {
  for (std::size_t i = 0; i < kTable.size(); ++i)
    if (static_cast<std::size_t>(kTable[i].code) != i) return false;
  return true;
}
static_assert(tableMatchesEnum(), "kTable rows must follow DiagCode order");

constexpr bool isDigit(char c) { return c >= '0' && c <= '9'; }
constexpr bool isNameChar(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || isDigit(c) || c == '_'; }

// Calls f(placeholder) for each "{...}" in pattern; false if a brace is unbalanced.
template <class F>
constexpr bool forEachPlaceholder(std::string_view pattern, F&& f) {
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] == '}') return false;
    if (pattern[i] != '{') continue;
    std::size_t end = pattern.find('}', i);
    if (end == std::string_view::npos || end == i + 1) return false;
    std::string_view name = pattern.substr(i + 1, end - i - 1);
    for (char c : name)
      if (!isNameChar(c)) return false;
    if (!f(name)) return false;
    i = end;
  }
  return true;
}

// Calls f(name) for each space-separated name in arguments.
template <class F>
constexpr void forEachArgument(std::string_view arguments, F&& f) {
  std::size_t start = 0;
  while (start < arguments.size()) {
    std::size_t end = arguments.find(' ', start);
    if (end == std::string_view::npos) end = arguments.size();
    if (end > start) f(arguments.substr(start, end - start));
    start = end + 1;
  }
}

constexpr std::string_view checkRow(const DiagnosticInfo& info) {
  const bool named = !info.arguments.empty();
  bool legacyOk = true, namedOk = true;
  auto declared = [&](std::string_view name) {
    bool found = false;
    forEachArgument(info.arguments, [&](std::string_view a) { found = found || a == name; });
    return found;
  };
  auto check = [&](std::string_view name) {
    if (!named) return legacyOk = name.size() == 1 && isDigit(name[0]);
    return namedOk = !isDigit(name[0]) && declared(name);
  };
  if (!forEachPlaceholder(info.messageTemplate, check) || !forEachPlaceholder(info.hintTemplate, check)) {
    if (!legacyOk) return "a row without named arguments uses a placeholder other than {0}..{9}";
    if (!namedOk) return "a template uses a placeholder that is not among the row's arguments";
    return "a template has an unbalanced or empty brace";
  }
  bool allUsed = true, unique = true;
  std::size_t index = 0;
  forEachArgument(info.arguments, [&](std::string_view a) {
    bool used = false;
    forEachPlaceholder(info.messageTemplate, [&](std::string_view p) { used = used || p == a; return true; });
    forEachPlaceholder(info.hintTemplate, [&](std::string_view p) { used = used || p == a; return true; });
    allUsed = allUsed && used;
    std::size_t other = 0;
    forEachArgument(info.arguments, [&](std::string_view b) { unique = unique && (other++ == index || a != b); });
    ++index;
  });
  if (!allUsed) return "an argument is used by neither template";
  if (!unique) return "an argument is named twice";
  return "";
}

constexpr bool tableTemplatesAgree() {
  for (const auto& row : kTable)
    if (!checkRow(row).empty()) return false;
  return true;
}
static_assert(tableTemplatesAgree(), "a row's templates and arguments disagree: see checkDiagnosticRow");
}  // namespace

std::string_view checkDiagnosticRow(const DiagnosticInfo& info) { return checkRow(info); }

std::size_t diagnosticArgumentCount(const DiagnosticInfo& info) {
  std::size_t count = 0;
  if (!info.arguments.empty()) {
    forEachArgument(info.arguments, [&](std::string_view) { ++count; });
    return count;
  }
  auto highest = [&](std::string_view p) {
    if (p.size() == 1 && isDigit(p[0])) count = std::max<std::size_t>(count, static_cast<std::size_t>(p[0] - '0') + 1);
    return true;
  };
  forEachPlaceholder(info.messageTemplate, highest);
  forEachPlaceholder(info.hintTemplate, highest);
  return count;
}

const DiagnosticInfo& diagnosticInfo(DiagCode code) { return kTable[static_cast<std::size_t>(code)]; }

std::span<const DiagnosticInfo> allDiagnostics() { return kTable; }

std::optional<DiagCode> diagnosticFromId(std::string_view id) {
  for (const auto& row : kTable)
    if (row.id == id) return row.code;
  return std::nullopt;
}

}  // namespace wg
