#include "cli/diagnostic_output.hpp"

#include <cstdio>
#include <map>

#include "cli/commands.hpp"
#include "compiler/literal.hpp"
#include "compiler/weather_config.hpp"

namespace wg {

namespace {
// Text shows this many warnings of one code; the rest are counted in one line, so a
// document with 60,000 ignored inputs does not bury its errors. JSON lists every one.
constexpr std::size_t kWarningsShownPerCode = 20;
}  // namespace

void printDiagnostics(const std::vector<Diagnostic>& list, bool json) {
  if (json) {
    std::fputs(formatDiagnosticsJson(list).c_str(), stderr);
    return;
  }
  std::map<DiagCode, std::size_t> warnings;
  for (const auto& d : list) {
    if (d.info().severity == Severity::Warning && ++warnings[d.code] > kWarningsShownPerCode) continue;
    std::fputs(formatDiagnosticText(d).c_str(), stderr);
  }
  for (const auto& [code, count] : warnings)
    if (count > kWarningsShownPerCode)
      std::fprintf(stderr, "weathergen: note: %zu more %s warnings are not shown; the JSON diagnostics list every one\n",
                   count - kWarningsShownPerCode, std::string(diagnosticInfo(code).id).c_str());
}

int usageError(const std::string& message, bool json) {
  DiagnosticList list;
  list.report(DiagCode::UsageError, {}, {message});
  printDiagnostics(list.items(), json);
  return kExitUsage;
}

int internalError(const std::exception* escaped) {
  if (escaped)
    std::fprintf(stderr, "weathergen: error WG9900: internal error: %s\n  hint: this is a weathergen bug; please report it\n",
                 quoteUserText(escaped->what(), 300).c_str());
  else
    std::fputs("weathergen: error WG9900: internal error: unknown exception\n  hint: this is a weathergen bug; please report it\n",
               stderr);
  return kExitInternal;
}

int briefUsageError(const std::string& message) {
  std::fprintf(stderr, "weathergen: error WG9001: %s\n", message.c_str());
  return kExitUsage;
}

bool jsonDiagnosticsRequested(int argc, char** argv, int first) {
  return first < argc && jsonDiagnosticsRequested(std::vector<std::string>(argv + first, argv + argc));
}

bool jsonDiagnosticsRequested(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i)
    if (args[i] == "--diagnostics=json" || (args[i] == "--diagnostics" && i + 1 < args.size() && args[i + 1] == "json"))
      return true;
  return false;
}

std::string setDiagnosticsFormat(const std::string& value, bool& json) {
  if (value != "text" && value != "json") return "--diagnostics takes text or json";
  json = value == "json";
  return "";
}

int deviceUnavailable(const std::string& error, const std::string& requestedDevice) {
  return usageError(error + (requestedDevice.empty() ? "; install mesa-vulkan-drivers for lavapipe" : "; pass --device with one of them"));
}

std::string checkWeatherPresetName(const std::string& name) {
  if (weatherPreset(name)) return "";
  std::string presets;
  for (auto n : weatherPresetNames()) presets += (presets.empty() ? "" : ", ") + std::string(n);
  return "unknown weather preset '" + quoteUserText(name) + "' (presets: " + presets + ")";
}

std::string setPresetMap(const std::string& rules, std::string& presetMap) {
  if (rules.empty()) return "--preset-map takes rules, e.g. '*Leaf*=foliage,*=rock'";
  presetMap = rules;
  return "";
}

}  // namespace wg
