// The table of every op, looked up by name.
#pragma once
#include <span>
#include <string_view>
#include <vector>

#include "nodes/op_definition.hpp"

namespace wg {

const OpDef* findOp(std::string_view name);
std::span<const OpDef* const> allOps();  // sorted by name
std::vector<std::string_view> opNames();

// Every shader library a stage can emit: the core and shading libraries, each op's and
// their dependencies, each once, in a fixed order.
std::span<const ShaderLibrary* const> allShaderLibraries();

// Each family file contributes its ops.
void appendMathOps(std::vector<OpDef>& ops);
void appendVectorOps(std::vector<OpDef>& ops);
void appendGeometryOps(std::vector<OpDef>& ops);
void appendTextureOps(std::vector<OpDef>& ops);
void appendProceduralOps(std::vector<OpDef>& ops);
void appendNormalMapOps(std::vector<OpDef>& ops);
void appendWeatherOps(std::vector<OpDef>& ops);
void appendSnowOps(std::vector<OpDef>& ops);

}  // namespace wg
