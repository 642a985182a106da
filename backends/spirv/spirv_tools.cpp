// Validation, optimisation and disassembly with SPIRV-Tools (Vulkan 1.1 environment).
#include <glslang/SPIRV/spirv.hpp>  // the opcode enum (Debian has no separate SPIRV-Headers)
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "backends/spirv/spirv_toolchain.hpp"

namespace wg {

namespace {
constexpr spv_target_env kTargetEnvironment = SPV_ENV_VULKAN_1_1;
}

namespace {
// Friendly names cost more than the validation itself (SPIRV-Tools maps every id to
// a unique name up front), so a module is validated without them and, only when it
// fails, again with them for a readable message.
std::string validateWith(const SpirvWords& words, bool friendlyNames) {
  spvtools::SpirvTools tools(kTargetEnvironment);
  std::string messages;
  tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& position, const char* message) {
    messages += "word " + std::to_string(position.index) + ": " + message + "\n";
  });
  spvtools::ValidatorOptions options;
  options.SetFriendlyNames(friendlyNames);
  if (tools.Validate(words.data(), words.size(), options)) return "";
  return messages.empty() ? "invalid module" : messages;
}
}  // namespace

std::string validateSpirv(const SpirvWords& words) {
  if (validateWith(words, false).empty()) return "";
  return validateWith(words, true);
}

SpirvWords optimizeSpirv(const SpirvWords& words) {
  spvtools::Optimizer optimizer(kTargetEnvironment);
  optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
  optimizer.RegisterPerformancePasses();
  SpirvWords out;
  if (!optimizer.Run(words.data(), words.size(), &out)) return words;
  return out;
}

std::string disassembleSpirv(const SpirvWords& words) {
  spvtools::SpirvTools tools(kTargetEnvironment);
  std::string text;
  tools.Disassemble(words, &text,
                    SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT);
  return text;
}

std::size_t countInstructions(const SpirvWords& words) { return spirvStatistics(words).instructions; }

SpirvStatistics spirvStatistics(const SpirvWords& words) {
  constexpr std::size_t kHeaderWords = 5;
  SpirvStatistics stats;
  for (std::size_t i = kHeaderWords; i < words.size();) {
    const std::uint32_t wordCount = words[i] >> 16;  // high half of each instruction's first word
    if (wordCount == 0) break;
    const auto op = static_cast<spv::Op>(words[i] & 0xffff);
    if (op >= spv::OpImageSampleImplicitLod && op <= spv::OpImageDrefGather) ++stats.textureReads;
    if (op == spv::OpBranchConditional || op == spv::OpSwitch) ++stats.branches;
    i += wordCount;
    ++stats.instructions;
  }
  return stats;
}

}  // namespace wg
