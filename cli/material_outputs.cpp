#include "cli/material_outputs.hpp"

#include <filesystem>

namespace wg {

std::map<std::string, std::string> materialOutputs(const CompiledMaterial& m, const OutputTargets& targets,
                                                   const std::string& outputDir) {
  std::map<std::string, std::string> files;
  std::filesystem::path dir(outputDir);
  for (const auto& s : m.stages) {
    bool wantSource = s.language == ShaderLanguage::Glsl ? targets.glsl : targets.hlsl;
    if (wantSource) files[(dir / (m.fileStem + "." + stageFileSuffix(s.language, s.stage))).string()] = s.source;
    if (targets.spirv) {
      std::string base = m.fileStem + "." + std::string(languageName(s.language)) +
                         (s.stage == ShaderStage::Vertex ? ".vert" : ".frag");
      files[(dir / (base + ".spv")).string()] =
          std::string(reinterpret_cast<const char*>(s.spirv.data()), s.spirv.size() * sizeof(std::uint32_t));
      files[(dir / (base + ".spvasm")).string()] = s.disassembly;
    }
    // One translation per stage: the GLSL stages' SPIR-V (the HLSL stages' is equivalent).
    const char* stageName = s.stage == ShaderStage::Vertex ? ".vert" : ".frag";
    if (s.language == ShaderLanguage::Glsl && targets.msl)
      files[(dir / (m.fileStem + stageName + ".msl")).string()] = s.msl;
    if (s.language == ShaderLanguage::Glsl && targets.glslEs)
      files[(dir / (m.fileStem + stageName + ".es.glsl")).string()] = s.glslEs;
  }
  files[(dir / (m.fileStem + ".reflect.json")).string()] = m.reflectionJson;
  if (targets.header) files[(dir / (m.fileStem + ".hpp")).string()] = m.cppHeader;
  return files;
}

}  // namespace wg
