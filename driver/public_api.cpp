// include/weathergen/weathergen.hpp over the internal compiler: copies results into the
// API's plain structs and turns every exception into a WG9900 diagnostic, so nothing
// internal (types or exceptions) crosses the boundary.
#include <weathergen/weathergen.hpp>

#include <exception>

#include "backends/spirv/spirv_toolchain.hpp"
#include "driver/compile_cache.hpp"
#include "driver/material_compiler.hpp"
#include "compiler/material_interface.hpp"
#include "compiler/surface_interface.hpp"

namespace weathergen {

namespace {

Diagnostic publicDiagnostic(const wg::Diagnostic& d) {
  const wg::DiagnosticInfo& info = d.info();
  return {std::string(info.id),
          info.severity == wg::Severity::Error ? "error" : "warning",
          d.location.file,
          d.location.pointer,
          d.message,
          d.hint,
          d.location.line,
          d.location.column};
}

// Rendered through the table like every other diagnostic, so wording stays in one place.
Diagnostic internalException(std::string_view fileName, std::string_view what) {
  wg::DiagnosticList list;
  list.report(wg::DiagCode::InternalException, {std::string(fileName), "", 0, 0}, {what});
  return publicDiagnostic(list.items().front());
}

// The result of a compile that threw.
Result failure(std::string_view fileName, std::string_view what) noexcept {
  try {
    Result failed;
    failed.diagnostics.push_back(internalException(fileName, what));
    return failed;
  } catch (...) {
    return {};  // reporting failed too (out of memory): ok stays false, no diagnostics
  }
}

Stage publicStage(wg::CompiledStage&& s) {
  return {std::string(wg::languageName(s.language)), s.stage == wg::ShaderStage::Vertex ? "vert" : "frag",
          std::move(s.source), std::move(s.spirv)};
}

// Through the compile cache when the options name a usable directory.
wg::CompileResult compileWithOptionalCache(const std::string& file, std::string json, const wg::CompileOptions& options,
                                           const std::string& cacheDirectory) {
  if (cacheDirectory.empty()) return wg::compileMaterialText(file, std::move(json), options);
  const wg::CompileCache cache(cacheDirectory);
  if (!cache.prepare().empty()) return wg::compileMaterialText(file, std::move(json), options);
  wg::CompileResult compiled = cache.compileText(file, std::move(json), options);
  cache.trim();
  return compiled;
}

Result compileOrThrow(std::string_view fileName, std::string_view json, const Options& options) {
  Result result;
  if (!initialize()) {
    result.diagnostics.push_back(internalException(fileName, "glslang could not be initialised"));
    return result;
  }
  wg::CompileOptions internal;
  internal.emitSpirv = options.spirv;
  internal.emitHlsl = options.hlsl;
  internal.emitReflection = options.reflection;
  internal.optimize = options.optimize;
  internal.stageThreads = options.threads;
  if (!options.weatherPreset.empty()) internal.weatherPreset = options.weatherPreset;
  internal.weatherEffects.assign(options.effects.begin(), options.effects.end());
  if (!options.quality.empty()) internal.quality.requested = options.quality;
  internal.emitCppHeader = options.cppHeader;
  internal.emitSurface = options.surface;
  internal.switches = wg::SwitchValues(options.switches.begin(), options.switches.end());
  wg::CompileResult compiled = compileWithOptionalCache(std::string(fileName), std::string(json), internal,
                                                       options.cacheDirectory);
  for (const auto& d : compiled.diagnostics.items()) result.diagnostics.push_back(publicDiagnostic(d));
  if (!compiled.material || compiled.diagnostics.hasErrors()) return result;
  wg::CompiledMaterial& material = *compiled.material;
  result.name = std::move(material.name);
  result.contentHash = std::move(material.contentHash);
  result.reflectionJson = std::move(material.reflectionJson);
  result.cppHeader = std::move(material.cppHeader);
  for (auto& stage : material.stages) result.stages.push_back(publicStage(std::move(stage)));
  for (std::size_t i = 0; i < material.surfaces.size(); ++i)
    result.surfaces.push_back({std::string(wg::surfaceLanguages()[i].name), std::move(material.surfaces[i])});
  result.ok = true;
  return result;
}

}  // namespace

bool initialize() {
  // The shared frame block is a function-local static too; building it here keeps the
  // first concurrent compiles from all waiting on it.
  wg::frameBlock();
  return wg::initializeGlslangProcess();
}

Result compile(std::string_view fileName, std::string_view json, const Options& options) noexcept {
  try {
    return compileOrThrow(fileName, json, options);
  } catch (const std::exception& e) {
    return failure(fileName, e.what());
  } catch (...) {
    return failure(fileName, "unknown exception");
  }
}

std::string version() { return WEATHERGEN_VERSION; }

}  // namespace weathergen
