// How every CLI command prints diagnostics (text or JSON, on stderr) and usage errors,
// and the checks of option values that several commands share.
#pragma once
#include <exception>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace wg {

void printDiagnostics(const std::vector<Diagnostic>& list, bool json);
// Prints WG9900 for an exception a command let escape (null: not a std::exception) and
// returns the internal-error exit code: anything that escapes is a bug.
int internalError(const std::exception* escaped);
// Prints WG9001 with the message and returns the usage exit code.
int usageError(const std::string& message, bool json = false);
// WG9001 as one line, with no hint: the bench commands' usage errors.
int briefUsageError(const std::string& message);
// Whether argv from `first` asks for --diagnostics json anywhere: read before the
// options, so that a usage error in front of it is JSON too.
bool jsonDiagnosticsRequested(int argc, char** argv, int first);
bool jsonDiagnosticsRequested(const std::vector<std::string>& args);
// The --diagnostics value: "" or the usage message.
std::string setDiagnosticsFormat(const std::string& value, bool& json);
// No Vulkan device opened (none matches --device, or no driver): the machine's setup,
// not a bug, so a usage error naming the fix. Returns the exit code.
int deviceUnavailable(const std::string& error, const std::string& requestedDevice);
// "" when `name` is a weather preset, else the one-line usage message naming them all.
std::string checkWeatherPresetName(const std::string& name);
// The --preset-map value (import, render --model): "" or the usage message.
std::string setPresetMap(const std::string& rules, std::string& presetMap);

}  // namespace wg
