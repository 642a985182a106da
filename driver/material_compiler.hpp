// The compiler's public entry: load -> validate -> IR -> passes -> backends -> SPIR-V.
// Diagnostics come back as values; nothing here writes files or prints.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "backends/shader_syntax.hpp"
#include "backends/spirv/spirv_toolchain.hpp"
#include "compiler/diagnostic.hpp"
#include "compiler/ir.hpp"
#include "compiler/material_interface.hpp"
#include "compiler/pass_pipeline.hpp"
#include "compiler/quality_tiers.hpp"
#include "compiler/static_switches.hpp"
#include "driver/spirv_module_cache.hpp"

namespace wg {

class CompileCache;  // driver/compile_cache.hpp

// A field that changes what a compile returns joins the compile cache's key too
// (addOptions in driver/compile_cache.cpp), or the cache would return stale results.
struct CompileOptions {
  bool emitSpirv = true;
  bool emitDisassembly = false;  // .spvasm text of each SPIR-V module (compile --target spirv)
  bool optimize = false;  // spirv-opt performance passes (-O)
  // Threads that compile the material's stages to SPIR-V at once; the output is the
  // same for any count, so it is not part of the compile cache's key.
  int stageThreads = 1;
  std::optional<std::string> weatherPreset;  // replaces the graph's preset (--weather-preset)
  WeatherEffectOverrides weatherEffects;     // switched over the graph's own effects (--effects)
  QualityChoice quality;                     // the tier (--quality); compiler/quality_tiers.hpp
  bool emitReflection = true;  // off for callers that only want shader text
  bool emitHlsl = true;        // off: the two GLSL stages alone
  bool emitCppHeader = false;  // C++ std140 structs of the uniform blocks (--emit-header)
  // SPIRV-Cross translations of each stage's validated, pre-optimisation SPIR-V
  // (--target msl / glsles); they need SPIR-V, which is then compiled even without emitSpirv.
  bool emitMsl = false, emitGlslEs = false;
  // The weathered surface behind the host contract, in every surface language
  // (--target surface; docs/engine-api.md, "The surface contract").
  bool emitSurface = false;
  bool emitFilament = false;  // NAME.mat for Filament's matc (--target filament)
  // Files named NAME.HASH.* (content hash), so identical variants share them (--variants).
  bool hashKeyedFileStem = false;
  SwitchValues switches;  // the variant: static switch values; unnamed switches keep their default
  // IR verification between passes (on in debug builds; tests turn it on) and a pass observer.
  PassPipelineOptions passes;
  // Modules shared across a batch (compileBatch sets it); null: every stage is compiled.
  SpirvModuleCache* modules = nullptr;
  // compileBatch takes each graph from this persistent cache, or compiles and stores it.
  const CompileCache* cache = nullptr;
};

struct CompiledStage {
  ShaderLanguage language;
  ShaderStage stage;
  std::string source;
  SpirvWords spirv;         // empty unless emitSpirv
  std::string disassembly;  // of spirv
  std::string msl, glslEs;  // empty unless emitMsl / emitGlslEs
};

struct CompiledMaterial {
  std::string name;         // as declared
  std::string fileStem;     // safe for file names: NAME, or NAME.HASH with hashKeyedFileStem
  std::string contentHash;
  IrGraph ir;               // after the pass pipeline; empty in a material from the CompileCache
  std::vector<std::string> inputFiles;  // read besides the graph: libraries, images (materialInputFiles)
  std::vector<CompiledStage> stages;  // glsl vert, glsl frag, then hlsl vert, hlsl frag with emitHlsl
  std::string reflectionJson;
  std::string cppHeader;    // empty unless emitCppHeader
  // Indexed like surfaceLanguages(); empty unless emitSurface.
  std::vector<std::string> surfaces;
  std::string filamentMaterial;  // empty unless emitFilament

  const CompiledStage& stage(ShaderLanguage language, ShaderStage stage) const;
};

struct CompileResult {
  std::optional<CompiledMaterial> material;
  DiagnosticList diagnostics;
};

CompileResult compileMaterialFile(const std::string& path, const CompileOptions& options);
CompileResult compileMaterialText(const std::string& file, std::string text, const CompileOptions& options);

// The front half alone (load, validate, IR, passes): for tools and tests.
std::optional<IrGraph> buildOptimizedIr(const std::string& file, std::string text, DiagnosticList& diagnostics,
                                        const CompileOptions& options = {});

// A material name made safe as a file name stem: [A-Za-z0-9_-], at most 64 bytes.
std::string fileStemFor(std::string_view name);

// Extension of a stage's source file: "vert.glsl", "frag.hlsl"...
std::string stageFileSuffix(ShaderLanguage language, ShaderStage stage);

}  // namespace wg
