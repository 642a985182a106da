// The files `weathergen compile` writes for one compiled material, by target.
#pragma once
#include <map>
#include <string>

#include "driver/material_compiler.hpp"

namespace wg {

struct OutputTargets {
  bool glsl = false, hlsl = false, spirv = false, msl = false, glslEs = false;
  bool header = false;  // --emit-header
};

// path -> bytes, every path under `dir` and named after the material's file stem.
std::map<std::string, std::string> materialOutputs(const CompiledMaterial& m, const OutputTargets& targets,
                                                   const std::string& dir);

}  // namespace wg
