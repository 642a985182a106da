// The one place glslang, SPIRV-Tools and SPIRV-Cross are used: compile GLSL or HLSL to
// SPIR-V in-process, validate for Vulkan 1.1, optimise, disassemble and reflect.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "backends/shader_syntax.hpp"

namespace wg {

using SpirvWords = std::vector<std::uint32_t>;

struct SpirvCompileResult {
  bool ok = false;
  SpirvWords words;
  std::string log;  // glslang's messages when !ok
};

// Initialises glslang's process-global tables; idempotent and thread-safe (once per
// process). compileToSpirv calls it too; engines call it early to pay the cost up front.
bool initializeGlslangProcess();

// Thread-safe: glslang's process state is initialised once, on first use.
SpirvCompileResult compileToSpirv(std::string_view source, ShaderLanguage language, ShaderStage stage);
// A GLSL compute shader (kGlslVersion) of the runtime's own passes (the deformable snow), with the
// same glslang setup as the materials' stages.
SpirvCompileResult compileComputeToSpirv(std::string_view glsl);
// Empty when the module is valid in the Vulkan 1.1 environment.
std::string validateSpirv(const SpirvWords& words);
// spirv-opt's performance recipe; returns the input unchanged if optimisation fails.
SpirvWords optimizeSpirv(const SpirvWords& words);
std::string disassembleSpirv(const SpirvWords& words);

struct ReflectedMember {
  std::string name;
  std::uint32_t offset;
};
struct ReflectedBlock {
  std::uint32_t set, binding;
  std::vector<ReflectedMember> members;
};
// Uniform blocks of a module as SPIRV-Cross sees them.
std::vector<ReflectedBlock> reflectUniformBlocks(const SpirvWords& words);
// The entry point and its resources per slot kind, as SPIRV-Cross sees them: what the
// module declares, and what the entry point uses (all that a translation declares).
struct ResourceCounts {
  std::size_t uniformBuffers = 0, separateImages = 0, separateSamplers = 0;
};
struct ReflectedResources {
  std::string entryPoint;
  ResourceCounts declared, used;
};
ReflectedResources reflectResources(const SpirvWords& words);
// The interface of one of the runtime's own modules (compute, or the particle and
// post stages) as SPIRV-Cross sees it: the runtime builds descriptor set layouts and
// push-constant ranges from this, never by hand.
struct ModuleBinding {
  enum class Kind : std::uint8_t { StorageBuffer, UniformBuffer, StorageImage, SampledImage, Sampler };
  std::string name;  // the block's type name
  std::uint32_t set = 0, binding = 0;
  Kind kind = Kind::StorageBuffer;
};
struct ModuleInterface {
  std::vector<ModuleBinding> bindings;
  std::uint32_t pushConstantBytes = 0;
  std::uint32_t localSize[3] = {1, 1, 1};  // compute modules only
};
ModuleInterface reflectModule(const SpirvWords& words);
// Instruction count (words are grouped into instructions), for cost reports.
std::size_t countInstructions(const SpirvWords& words);
// What a material stats panel shows of a module: instructions, texture reads (samples,
// fetches and gathers) and conditional branches (OpBranchConditional, OpSwitch).
struct SpirvStatistics {
  std::size_t instructions = 0, textureReads = 0, branches = 0;
};
SpirvStatistics spirvStatistics(const SpirvWords& words);

}  // namespace wg
