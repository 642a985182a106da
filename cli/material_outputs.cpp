#include "cli/material_outputs.hpp"

#include <array>
#include <filesystem>

#include "compiler/literal.hpp"
#include "compiler/surface_interface.hpp"

namespace wg {

namespace {

constexpr std::array<OutputTarget, 7> kOutputTargets = {{
    {"glsl", "NAME.vert.glsl NAME.frag.glsl", &OutputTargets::glsl, true, "high"},
    {"hlsl", "NAME.vert.hlsl NAME.frag.hlsl", &OutputTargets::hlsl, true, "high"},
    {"spirv", "NAME.{glsl,hlsl}.{vert,frag}.spv and .spvasm", &OutputTargets::spirv, true, "high"},
    {"msl", "NAME.vert.msl NAME.frag.msl", &OutputTargets::msl, false, "low"},
    {"glsles", "NAME.vert.es.glsl NAME.frag.es.glsl", &OutputTargets::glslEs, false, "low"},
    {"surface", "NAME.surface.glsl NAME.surface.es.glsl NAME.surface.hlsl (the unlit surface)",
     &OutputTargets::surface, false, "high"},
    {"filament", "NAME.mat (a Filament material lighting the surface; build it with matc)", &OutputTargets::filament,
     false, "high"},
}};

}  // namespace

std::span<const OutputTarget> outputTargets() { return kOutputTargets; }

std::optional<OutputTargets> parseOutputTargets(std::string_view list, std::string& error) {
  OutputTargets targets;
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t comma = list.find(',', start);
    std::string_view item = list.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    bool known = item == "all";
    for (const auto& target : kOutputTargets)
      if (item == target.name || (item == "all" && target.inAll)) {
        targets.*(target.flag) = true;
        known = true;
      }
    if (!known) {
      std::string names;
      for (const auto& target : kOutputTargets) names += std::string(target.name) + ", ";
      error = "unknown target '" + quoteUserText(item) + "' (use " + names + "or all)";
      return std::nullopt;
    }
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return targets;
}

void applyOutputTargets(const OutputTargets& targets, CompileOptions& options) {
  options.emitSpirv = targets.spirv;
  options.emitDisassembly = targets.spirv;  // .spv and .spvasm go together
  options.emitMsl = targets.msl;
  options.emitGlslEs = targets.glslEs;
  options.emitSurface = targets.surface;
  options.emitFilament = targets.filament;
  options.emitCppHeader = targets.header;
  // Every target chosen defaults to low (GLSL ES, MSL: mobile GPUs): the tier is low;
  // any other among them makes it high, for one compile serves every target.
  bool anyTarget = false, allLow = true;
  for (const auto& target : kOutputTargets)
    if (targets.*(target.flag)) {
      anyTarget = true;
      allLow = allLow && target.defaultQuality == "low";
    }
  options.quality.fallback = anyTarget && allLow ? "low" : "high";
}

std::map<std::string, std::string_view> materialOutputs(const CompiledMaterial& m, const OutputTargets& targets,
                                                        const std::string& outputDir) {
  std::map<std::string, std::string_view> files;
  std::filesystem::path dir(outputDir);
  for (const auto& s : m.stages) {
    bool wantSource = s.language == ShaderLanguage::Glsl ? targets.glsl : targets.hlsl;
    if (wantSource) files[(dir / (m.fileStem + "." + stageFileSuffix(s.language, s.stage))).string()] = s.source;
    if (targets.spirv) {
      std::string base = m.fileStem + "." + std::string(languageName(s.language)) +
                         (s.stage == ShaderStage::Vertex ? ".vert" : ".frag");
      files[(dir / (base + ".spv")).string()] =
          std::string_view(reinterpret_cast<const char*>(s.spirv.data()), s.spirv.size() * sizeof(std::uint32_t));
      files[(dir / (base + ".spvasm")).string()] = s.disassembly;
    }
    // One translation per stage: the GLSL stages' SPIR-V (the HLSL stages' is equivalent).
    const char* stageName = s.stage == ShaderStage::Vertex ? ".vert" : ".frag";
    if (s.language == ShaderLanguage::Glsl && targets.msl)
      files[(dir / (m.fileStem + stageName + ".msl")).string()] = s.msl;
    if (s.language == ShaderLanguage::Glsl && targets.glslEs)
      files[(dir / (m.fileStem + stageName + ".es.glsl")).string()] = s.glslEs;
  }
  if (targets.surface)
    for (std::size_t i = 0; i < m.surfaces.size(); ++i)
      files[(dir / (m.fileStem + "." + std::string(surfaceLanguages()[i].suffix))).string()] = m.surfaces[i];
  if (targets.filament) files[(dir / (m.fileStem + ".mat")).string()] = m.filamentMaterial;
  files[(dir / (m.fileStem + ".reflect.json")).string()] = m.reflectionJson;
  if (targets.header) files[(dir / (m.fileStem + ".hpp")).string()] = m.cppHeader;
  return files;
}

}  // namespace wg
