// Reads a texture's sampler settings from its JSON object: "wrap" (one mode, or [u, v]),
// "filter" (one filter, or {"min", "mag"}) and "colorSpace" (image files only).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "compiler/json_document.hpp"
#include "nodes/texture_sampling.hpp"

namespace wg {

// Fills `state` from the texture object `texture` at `pointer` (fields left out keep
// their defaults). Reports WG1003 for a wrong JSON kind, WG1005 for an unknown filter
// key and WG3003 for an unknown value or an sRGB procedural texture (`procedural`).
// Returns false when it reported anything.
bool loadSamplerState(const nlohmann::json& texture, const std::string& pointer, const std::string& shownName,
                      bool procedural, const JsonDocument& doc, DiagnosticList& diagnostics, SamplerState& state);

}  // namespace wg
