#include "driver/material_compiler.hpp"

#include <algorithm>

#include "backends/filament_material.hpp"
#include "backends/reference_host.hpp"
#include "backends/spirv/cross_compile.hpp"
#include "backends/stage_writer.hpp"
#include "backends/surface_writer.hpp"
#include "compiler/constant_count.hpp"
#include "compiler/content_hash.hpp"
#include "compiler/cpp_header.hpp"
#include "compiler/graph_loader.hpp"
#include "compiler/ir_builder.hpp"
#include "compiler/material_input_files.hpp"
#include "compiler/name_mark.hpp"
#include "compiler/pass_pipeline.hpp"
#include "compiler/reflection.hpp"
#include "driver/concurrent_indices.hpp"

namespace wg {

const CompiledStage& CompiledMaterial::stage(ShaderLanguage language, ShaderStage stage) const {
  for (const auto& s : stages)
    if (s.language == language && s.stage == stage) return s;
  return stages.front();
}

namespace {
bool isFileSafe(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
}
}  // namespace

// Safe names are kept as they are (a name Windows reserves, CON or lpt1, is not safe).
// Any other name is sanitised and marked with its hash after a '.', which no kept name
// contains, so distinct names never share a stem.
std::string fileStemFor(std::string_view name) {
  constexpr std::size_t kMaxStem = 64;
  const bool safe = !name.empty() && name.size() <= kMaxStem &&
                    std::all_of(name.begin(), name.end(), isFileSafe) && !isWindowsReservedName(name);
  if (safe) return std::string(name);
  constexpr std::size_t kMaxSanitized = 48;
  std::string out;
  for (char c : name) {
    if (out.size() >= kMaxSanitized) break;
    out += isFileSafe(c) ? c : '_';
  }
  if (isWindowsReservedName(out)) out += '_';  // Windows reserves "CON.anything" too
  return (out.empty() ? "material" : out) + "." + nameMark(name);
}

std::string stageFileSuffix(ShaderLanguage language, ShaderStage stage) {
  return std::string(stage == ShaderStage::Vertex ? "vert." : "frag.") + std::string(languageName(language));
}

namespace {

std::string countOf(std::size_t n, std::string_view what) {
  return std::to_string(n) + " " + std::string(what) + (n == 1 ? "" : "s");
}

// A material Filament cannot hold is the graph's problem for that target, said before
// matc fails on it (too many parameters) or Filament leaves samplers unbound.
bool fitsFilament(const IrGraph& ir, const JsonDocument& document, DiagnosticList& diagnostics) {
  const FilamentParameterCount n = countFilamentParameters(buildSurfaceInterface(buildMaterialInterface(ir), "m"));
  if (n.samplers() > kFilamentMaterialSamplers) {
    diagnostics.report(
        DiagCode::FilamentLimit, document.locate("/textures"),
        {std::to_string(n.samplers()), "samplers",
         countOf(n.textures, "texture") + " and " + countOf(n.weatherMaps, "weather map"),
         std::to_string(kFilamentMaterialSamplers) + " (its lighting takes 8 of a shader's 16)",
         "for --target filament use at most " + std::to_string(kFilamentMaterialSamplers - n.weatherMaps) +
             " textures: pack single-channel maps (occlusion, roughness, metallic...) into the channels of one image"});
    return false;
  }
  if (n.total() > kFilamentMaxParameters) {
    diagnostics.report(DiagCode::FilamentLimit, document.locate(n.materialParameters ? "/parameters" : "/textures"),
                       {std::to_string(n.total()), "parameters",
                        countOf(n.weatherFields, "weather field") + ", " + countOf(n.materialParameters, "parameter") + ", " +
                            countOf(n.samplers(), "sampler"),
                        std::to_string(kFilamentMaxParameters) + ", samplers included",
                        "for --target filament combine float parameters into vec2, vec3 or vec4 ones (each is one "
                        "Filament parameter), or use fewer textures"});
    return false;
  }
  return true;
}

}  // namespace

std::optional<IrGraph> buildOptimizedIr(const std::string& file, std::string text, DiagnosticList& diagnostics,
                                        const CompileOptions& options) {
  auto document = parseJsonDocument(file, std::move(text), diagnostics);
  if (!document) return std::nullopt;
  auto graph = loadMaterialGraph(*document, diagnostics);
  if (!graph) return std::nullopt;
  SwitchValues switches = options.switches;
  QualityChoice quality = options.quality;
  bindQualitySwitch(*graph, switches, quality);
  if (!resolveStaticSwitches(*graph, switches, *document, diagnostics)) return std::nullopt;
  IrBuildOptions buildOptions;
  buildOptions.weatherPreset = options.weatherPreset;
  buildOptions.weatherEffects = options.weatherEffects;
  buildOptions.quality = quality;
  auto ir = buildIr(*graph, *document, diagnostics, buildOptions);
  if (!ir) return std::nullopt;
  if (auto violation = runPassPipeline(*ir, options.passes)) {
    diagnostics.report(DiagCode::InternalIrInvalid, {file, "", 0, 0}, {violation->after, violation->problem});
    return std::nullopt;
  }
  // Counted after folding and merging, which is what the shader compiler will see.
  if (std::size_t constants = distinctConstantCount(*ir); constants > kMaxDistinctConstants) {
    diagnostics.report(DiagCode::ResourceLimit, document->locate("/nodes"),
                       {"the number of distinct constants after folding (vector components counted)",
                        std::to_string(constants), std::to_string(kMaxDistinctConstants)});
    return std::nullopt;
  }
  if (options.emitFilament && !fitsFilament(*ir, *document, diagnostics)) return std::nullopt;
  return ir;
}

namespace {

std::string stageLabel(const CompiledStage& s) {
  return std::string(languageName(s.language)) + (s.stage == ShaderStage::Vertex ? " vertex" : " fragment") + " shader";
}

// The SPIR-V must carry exactly the offsets the reflection publishes.
std::string checkBlockOffsets(const SpirvWords& words, const MaterialInterface& mi) {
  for (const auto& reflected : reflectUniformBlocks(words)) {
    const UniformBlock* block = reflected.set == mi.frame->set && reflected.binding == mi.frame->binding ? mi.frame
                                : reflected.set == mi.material.set && reflected.binding == mi.material.binding
                                    ? &mi.material
                                    : nullptr;
    if (!block) return "unexpected uniform block at set " + std::to_string(reflected.set);
    for (const auto& member : reflected.members) {
      bool found = false;
      for (const auto& expected : block->members)
        if (expected.identifier == member.name) {
          found = true;
          if (expected.offset != member.offset)
            return "member " + member.name + " is at offset " + std::to_string(member.offset) + ", reflection says " +
                   std::to_string(expected.offset);
        }
      if (!found) return "member " + member.name + " is not in the reflection";
    }
  }
  return "";
}

// A SPIRV-Cross translation kept, or the reason there is none reported.
bool keepTranslation(CrossResult cross, const char* target, const CompiledStage& stage, std::string& out,
                     const std::string& file, DiagnosticList& diagnostics) {
  if (!cross.ok) {
    std::string why = std::string("SPIRV-Cross could not translate it to ") + target + ": " + cross.error;
    diagnostics.report(DiagCode::InternalSpirvInvalid, {file, "", 0, 0}, {stageLabel(stage), why});
    return false;
  }
  out = std::move(cross.source);
  return true;
}

// From the unoptimised module: it has passed the block-offset check as well as spirv-val.
bool crossCompileStage(CompiledStage& stage, const SpirvWords& words, const CompileOptions& options,
                       const std::string& file, DiagnosticList& diagnostics) {
  if (options.emitMsl && !keepTranslation(spirvToMsl(words, stage.stage), "MSL", stage, stage.msl, file, diagnostics))
    return false;
  if (options.emitGlslEs &&
      !keepTranslation(spirvToGlslEs(words, stage.stage), "GLSL ES", stage, stage.glslEs, file, diagnostics))
    return false;
  return true;
}

// glslang, spirv-val and the block-offset check, then spirv-opt and spirv-val again when
// the optimised module is wanted.
SpirvModule buildModule(const CompiledStage& stage, const MaterialInterface& mi, bool optimize) {
  SpirvModule module;
  SpirvCompileResult compiled = compileToSpirv(stage.source, stage.language, stage.stage);
  if (!compiled.ok) {
    module.compileLog = compiled.log;
    return module;
  }
  module.compiled = true;
  module.words = std::move(compiled.words);
  module.invalid = validateSpirv(module.words);
  if (module.invalid.empty()) module.invalid = checkBlockOffsets(module.words, mi);
  if (!module.invalid.empty() || !optimize) return module;
  module.optimized = optimizeSpirv(module.words);
  module.optimizedInvalid = validateSpirv(module.optimized);
  return module;
}

// The stage's module: from the batch's cache when there is one, so a text shared by
// several variants is compiled and checked once.
std::shared_ptr<const SpirvModule> stageModule(const CompiledStage& stage, const MaterialInterface& mi,
                                               const CompileOptions& options, bool optimize) {
  auto make = [&] { return buildModule(stage, mi, optimize); };
  if (!options.modules) return std::make_shared<const SpirvModule>(make());
  std::string variant = stageFileSuffix(stage.language, stage.stage) + (optimize ? " -O" : "");
  return options.modules->get(stage.source, variant, make);
}

bool compileStageToSpirv(CompiledStage& stage, const MaterialInterface& mi, const CompileOptions& options,
                         const std::string& file, DiagnosticList& diagnostics) {
  const bool optimize = options.emitSpirv && options.optimize;
  std::shared_ptr<const SpirvModule> module = stageModule(stage, mi, options, optimize);
  if (!module->compiled) {
    diagnostics.report(DiagCode::InternalShaderError, {file, "", 0, 0}, {stageLabel(stage), module->compileLog});
    return false;
  }
  if (!module->invalid.empty()) {
    diagnostics.report(DiagCode::InternalSpirvInvalid, {file, "", 0, 0}, {stageLabel(stage), module->invalid});
    return false;
  }
  if (!crossCompileStage(stage, module->words, options, file, diagnostics)) return false;
  if (!options.emitSpirv) return true;
  if (!module->optimizedInvalid.empty()) {
    diagnostics.report(DiagCode::InternalSpirvInvalid, {file, "", 0, 0},
                       {stageLabel(stage) + " after spirv-opt", module->optimizedInvalid});
    return false;
  }
  stage.spirv = optimize ? module->optimized : module->words;
  if (options.emitDisassembly) stage.disassembly = disassembleSpirv(stage.spirv);
  return true;
}

// Every stage, the longest texts first so that the threads finish together. The
// diagnostics are those of the first stage in order that fails, whatever the threads.
bool compileStagesToSpirv(std::vector<CompiledStage>& stages, const MaterialInterface& mi, const CompileOptions& options,
                          const std::string& file, DiagnosticList& diagnostics) {
  std::vector<std::size_t> order(stages.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return stages[a].source.size() > stages[b].source.size(); });
  std::vector<DiagnosticList> reports(stages.size());
  std::vector<char> compiled(stages.size(), 0);
  forEachIndexConcurrently(order.size(), options.stageThreads, [&](std::size_t k) {
    const std::size_t i = order[k];
    compiled[i] = compileStageToSpirv(stages[i], mi, options, file, reports[i]);
  });
  for (std::size_t i = 0; i < stages.size(); ++i) {
    diagnostics.append(reports[i]);
    if (!compiled[i]) return false;
  }
  return true;
}

// The surface files (--target surface, filament) and the reflection JSON.
void writeSurfaceAndReflection(CompiledMaterial& material, const IrGraph& ir, const MaterialInterface& mi,
                               const std::vector<std::string>& names, const CompileOptions& options) {
  const SurfaceInterface surface = buildSurfaceInterface(mi, material.fileStem);
  if (options.emitSurface)
    for (const auto& language : surfaceLanguages())
      material.surfaces.push_back(writeSurface(ir, surface, language.language, material.contentHash, names));
  if (options.emitFilament)
    material.filamentMaterial = writeFilamentMaterial(
        ir, surface, writeSurface(ir, surface, SurfaceLanguage::GlslEs, material.contentHash, names), material.contentHash);
  if (options.emitReflection)
    material.reflectionJson = buildReflectionJson(ir, mi, surface, material.contentHash, material.fileStem);
}

}  // namespace

CompileResult compileMaterialText(const std::string& file, std::string text, const CompileOptions& options) {
  CompileResult result;
  auto ir = buildOptimizedIr(file, std::move(text), result.diagnostics, options);
  if (!ir) return result;
  CompiledMaterial material;
  material.name = ir->name;
  material.contentHash = contentHash(*ir);
  material.fileStem = fileStemFor(ir->name) + (options.hashKeyedFileStem ? "." + material.contentHash : "");
  MaterialInterface mi = buildMaterialInterface(*ir);
  std::vector<std::string> names = nameNodes(*ir);
  // Every full stage is the material's surface in the reference host.
  const SurfaceInterface embedded = buildEmbeddedSurfaceInterface(mi);
  for (ShaderLanguage language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl})
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment})
      if (language == ShaderLanguage::Glsl || options.emitHlsl)
        material.stages.push_back(
            {language, stage, writeReferenceHostStage(*ir, embedded, language, stage, material.contentHash, names), {}, {}});
  // The SPIR-V translations need the module even when it is not wanted itself.
  if ((options.emitSpirv || options.emitMsl || options.emitGlslEs) &&
      !compileStagesToSpirv(material.stages, mi, options, file, result.diagnostics))
    return result;
  // Only the surface files and the reflection read the surface interface.
  if (options.emitSurface || options.emitFilament || options.emitReflection)
    writeSurfaceAndReflection(material, *ir, mi, names, options);
  if (options.emitCppHeader) material.cppHeader = emitCppHeader(*ir, mi, material.contentHash);
  material.inputFiles = materialInputFiles(*ir);
  material.ir = std::move(*ir);
  result.material = std::move(material);
  return result;
}

CompileResult compileMaterialFile(const std::string& path, const CompileOptions& options) {
  CompileResult result;
  auto text = readGraphFile(path, result.diagnostics);
  if (!text) return result;
  return compileMaterialText(path, std::move(*text), options);
}

}  // namespace wg
