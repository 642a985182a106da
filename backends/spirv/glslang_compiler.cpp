// GLSL/HLSL -> SPIR-V with glslang, in-process.
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <mutex>

#include "backends/spirv/spirv_toolchain.hpp"

namespace wg {

// glslang keeps process-global tables; initialise them exactly once. After that,
// glslang 12 keeps its pool allocators per thread, so compiles may run concurrently.
bool initializeGlslangProcess() {
  static std::once_flag once;
  static bool initialised = false;
  std::call_once(once, [] { initialised = glslang::InitializeProcess(); });
  return initialised;
}

namespace {
constexpr int kClientInputVersion = 100;  // Vulkan client semantics version 1.00
}  // namespace

namespace {
SpirvCompileResult compileStage(std::string_view source, bool hlsl, EShLanguage glslangStage) {
  initializeGlslangProcess();
  glslang::TShader shader(glslangStage);
  const char* text = source.data();
  int length = static_cast<int>(source.size());
  shader.setStringsWithLengths(&text, &length, 1);
  shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, glslangStage, glslang::EShClientVulkan,
                     kClientInputVersion);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  shader.setEntryPoint("main");
  auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | (hlsl ? static_cast<int>(EShMsgReadHlsl) : 0));
  SpirvCompileResult result;
  if (!shader.parse(GetDefaultResources(), kGlslVersion, false, messages)) {
    result.log = shader.getInfoLog();
    return result;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    result.log = program.getInfoLog();
    return result;
  }
  glslang::SpvOptions options;
  options.disableOptimizer = true;  // spirv-opt runs separately, only with -O
  options.validate = false;         // SPIRV-Tools validates below
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(glslangStage), result.words, &logger, &options);
  result.ok = !result.words.empty();
  if (!result.ok) result.log = logger.getAllMessages();
  return result;
}
}  // namespace

SpirvCompileResult compileToSpirv(std::string_view source, ShaderLanguage language, ShaderStage stage) {
  return compileStage(source, language == ShaderLanguage::Hlsl,
                      stage == ShaderStage::Vertex ? EShLangVertex : EShLangFragment);
}

SpirvCompileResult compileComputeToSpirv(std::string_view glsl) { return compileStage(glsl, false, EShLangCompute); }

}  // namespace wg
