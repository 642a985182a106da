#include "cli/bench_options.hpp"

#include <cstdint>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/number_text.hpp"

namespace wg {

std::string setFrameCount(const std::string& value, int& frames) {
  constexpr std::uint32_t kMaxFrames = 1000000;
  const auto count = parseCountText(value, 1, kMaxFrames);
  frames = count ? static_cast<int>(*count) : 0;
  if (frames < 1) return "--frames takes a whole number of frames from 1 to 1000000";
  return "";
}

std::optional<int> parseBenchOptions(const OptionTable& table, int argc, char** argv, const bool& help,
                                     const char* usage) {
  const OptionParseResult parsed = parseOptions(table, argc, argv, 2);
  if (parsed.status == OptionParse::Failed) return briefUsageError(parsed.error);
  if (!help) return std::nullopt;
  std::fputs(usage, stdout);
  return kExitOk;
}

}  // namespace wg
