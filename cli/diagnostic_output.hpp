// How every CLI command prints diagnostics (text or JSON, on stderr) and usage errors,
// and the one check of a --weather-preset value.
#pragma once
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace wg {

void printDiagnostics(const std::vector<Diagnostic>& list, bool json);
// Prints WG9001 with the message and returns the usage exit code.
int usageError(const std::string& message, bool json = false);
// No Vulkan device opened (none matches --device, or no driver): the machine's setup,
// not a bug, so a usage error naming the fix. Returns the exit code.
int deviceUnavailable(const std::string& error, const std::string& requestedDevice);
// "" when `name` is a weather preset, else the one-line usage message naming them all.
std::string checkWeatherPresetName(const std::string& name);

}  // namespace wg
