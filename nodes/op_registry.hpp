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
