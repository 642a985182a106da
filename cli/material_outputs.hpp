// The files `weathergen compile` writes for one compiled material, by target. The
// targets are one table: --target's names, the usage text and the files derive from it.
#pragma once
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "driver/material_compiler.hpp"

namespace wg {

struct OutputTargets {
  bool glsl = false, hlsl = false, spirv = false, msl = false, glslEs = false, surface = false, filament = false;
  bool header = false;  // --emit-header
};

struct OutputTarget {
  std::string_view name;   // --target's spelling
  std::string_view files;  // what it writes, for the usage text
  bool OutputTargets::*flag;
  bool inAll;  // part of --target all
  std::string_view defaultQuality;  // the tier it gets when nothing else names one
};
std::span<const OutputTarget> outputTargets();

// A comma-separated --target list; nullopt with `error` set on an unknown name.
std::optional<OutputTargets> parseOutputTargets(std::string_view list, std::string& error);

// The compile options the targets need, and the quality tier they default to.
void applyOutputTargets(const OutputTargets& targets, CompileOptions& options);

// path -> bytes, every path under `dir` and named after the material's file stem. The
// bytes are views into `m`, which must outlive the map: a warm rebuild copies no output.
std::map<std::string, std::string_view> materialOutputs(const CompiledMaterial& m, const OutputTargets& targets,
                                                        const std::string& dir);

}  // namespace wg
