// The one table of diagnostics: stable code, severity, category, message and hint
// templates. Tests check codes, never wording. docs/diagnostics.md lists the same table.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace wg {

enum class Severity : std::uint8_t { Error, Warning };

// Input: caused by a graph file (each has a case in tests/bad/).
// Usage: caused by the command line. Internal: a weathergen bug.
enum class DiagCategory : std::uint8_t { Input, Usage, Internal };

enum class DiagCode : std::uint16_t {
  JsonSyntax,
  FileUnreadable,
  WrongJsonKind,
  MissingField,
  UnknownField,
  DuplicateKey,
  ResourceLimit,
  ImportIndex,
  UnknownOp,
  DuplicateId,
  UnknownNode,
  DanglingLink,
  MalformedLink,
  UnknownInput,
  MissingInput,
  TypeMismatch,
  Cycle,
  LiteralOutOfRange,
  LiteralNotFinite,
  UnknownParameter,
  InvalidParameterType,
  UnknownAlphaMode,
  UnknownSwitch,
  InvalidSwitchType,
  UnknownSwitchValue,
  SwitchCasesMismatch,
  EmptyName,
  OutputNameCollision,
  NotAPlainWord,
  SwizzleMismatch,
  SwitchKindAmbiguous,
  SwitchValueCount,
  DuplicateSwitchValue,
  DuplicateParameter,
  BoolParameterRange,
  ParameterRangeInverted,
  UnknownTexture,
  TextureFileMissing,
  TextureUnsupported,
  DuplicateTexture,
  TextureSourceConflict,
  UnknownSamplerValue,
  UnknownGenerator,
  InvalidGeneratorOption,
  WrapModeCount,
  ProceduralSrgb,
  UnknownWeatherPreset,
  WeatherSettingOutOfRange,
  WeatherEffectNeedsWhen,
  ReservedParameterPrefix,
  WeatherEffectForm,
  UnknownWeatherKey,
  WeatherSettingKind,
  WeatherPresetMissing,
  WeatherHeightRange,
  GltfContainer,
  GltfSchema,
  GltfBadReference,
  GltfResource,
  GltfRequiredExtension,
  GltfNodeHierarchy,
  GltfInvalidData,
  GltfExtensionIgnored,
  GltfFeatureIgnored,
  GltfModelUnits,
  MtlxXml,
  MtlxSchema,
  MtlxBadReference,
  MtlxUnsupportedNode,
  MtlxResource,
  MtlxInputIgnored,
  MtlxFeatureAdjusted,
  FilamentLimit,
  UsageError,
  InternalShaderError,
  InternalSpirvInvalid,
  InternalException,
  InternalIrInvalid,
  kCount
};

struct DiagnosticInfo {
  DiagCode code;
  std::string_view id;  // stable, e.g. "WG2001"
  Severity severity;
  DiagCategory category;
  std::string_view name;             // kebab-case summary
  std::string_view messageTemplate;  // {name} placeholders, filled by the reporter
  std::string_view hintTemplate;
  // The named arguments, space-separated, in the order report() takes them:
  // "texture reason" means report(code, at, {textureValue, reasonValue}). A static check
  // over the table keeps the names and the templates in step (every row names its
  // arguments; fillTemplate still reads positional {0}..{9}); report() checks the count.
  std::string_view arguments = {};
};

// How many values report() takes for this row: its named arguments (for a row with
// positional placeholders, the highest {N} + 1).
std::size_t diagnosticArgumentCount(const DiagnosticInfo& info);
// "" when the row's templates and arguments agree; otherwise what is wrong.
std::string_view checkDiagnosticRow(const DiagnosticInfo& info);

const DiagnosticInfo& diagnosticInfo(DiagCode code);
std::span<const DiagnosticInfo> allDiagnostics();
std::optional<DiagCode> diagnosticFromId(std::string_view id);

}  // namespace wg
