#include "cli/diagnostic_output.hpp"

#include <cstdio>

#include "cli/commands.hpp"
#include "compiler/literal.hpp"
#include "compiler/weather_config.hpp"

namespace wg {

void printDiagnostics(const std::vector<Diagnostic>& list, bool json) {
  if (json) {
    std::fputs(formatDiagnosticsJson(list).c_str(), stderr);
    return;
  }
  for (const auto& d : list) std::fputs(formatDiagnosticText(d).c_str(), stderr);
}

int usageError(const std::string& message, bool json) {
  DiagnosticList list;
  list.report(DiagCode::UsageError, {}, {message});
  printDiagnostics(list.items(), json);
  return kExitUsage;
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

}  // namespace wg
