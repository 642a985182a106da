// The views a fragment shader can show instead of the lit colour (frame_debugView):
// the same ids for every material, so a renderer needs one table. Coverage terms a
// material lacks show their neutral value.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "compiler/ir.hpp"

namespace wg {

struct DebugViewInfo {
  std::uint32_t id;
  std::string_view name;
  std::optional<CoverageTerm> coverage;  // set for coverage views
};

// Views 11-14 carry the fragment stage's surface inputs (unclamped, for read-back
// into the CPU evaluator); the tangent's handedness goes in alpha.
inline constexpr std::array<DebugViewInfo, 15> kDebugViews = {{
    {0, "lit", std::nullopt},
    {1, "albedo", std::nullopt},
    {2, "roughness", std::nullopt},
    {3, "normal", std::nullopt},
    {4, "snow", CoverageTerm::Snow},
    {5, "wet", CoverageTerm::Wet},
    {6, "moss", CoverageTerm::Moss},
    {7, "frost", CoverageTerm::Frost},
    {8, "ice", CoverageTerm::Ice},
    {9, "puddle", CoverageTerm::Puddle},
    {10, "density", CoverageTerm::Density},
    {11, "position", std::nullopt},
    {12, "geometricNormal", std::nullopt},
    {13, "texcoord", std::nullopt},
    {14, "tangent", std::nullopt},
}};

}  // namespace wg
