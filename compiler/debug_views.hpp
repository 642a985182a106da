// The views a fragment shader can show instead of the lit colour (frame_debugView):
// the same ids for every material, so a renderer needs one table. Coverage terms a
// material lacks show their neutral value.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>

#include "compiler/ir.hpp"

namespace wg {

constexpr std::size_t coverageSlot(CoverageTerm term) { return kPbrFieldCount + static_cast<std::size_t>(term); }
constexpr std::size_t fieldSlot(PbrField field) { return static_cast<std::size_t>(field); }

// Views 11-14 carry the fragment stage's surface inputs (unclamped, for read-back
// into the CPU evaluator); the tangent's handedness goes in alpha. View 0, "lit", is
// the shaded colour itself.
inline constexpr std::array<IrDebugView, 15> kDebugViews = {{
    {0, "lit", DebugSource::Slot, 0},
    {1, "albedo", DebugSource::Slot, fieldSlot(PbrField::BaseColor)},
    {2, "roughness", DebugSource::Slot, fieldSlot(PbrField::Roughness)},
    {3, "normal", DebugSource::ShadingNormal},
    {4, "snow", DebugSource::Slot, coverageSlot(CoverageTerm::Snow)},
    {5, "wet", DebugSource::Slot, coverageSlot(CoverageTerm::Wet)},
    {6, "moss", DebugSource::Slot, coverageSlot(CoverageTerm::Moss)},
    {7, "frost", DebugSource::Slot, coverageSlot(CoverageTerm::Frost)},
    {8, "ice", DebugSource::Slot, coverageSlot(CoverageTerm::Ice)},
    {9, "puddle", DebugSource::Slot, coverageSlot(CoverageTerm::Puddle)},
    {10, "density", DebugSource::Slot, coverageSlot(CoverageTerm::Density)},
    {11, "position", DebugSource::WorldPosition},
    {12, "geometricNormal", DebugSource::GeometricNormal},
    {13, "texcoord", DebugSource::Texcoord},
    {14, "tangent", DebugSource::Tangent},
}};

// The views a fragment stage selects besides "lit", for IrGraph::debugViews.
inline std::vector<IrDebugView> fragmentDebugViews() { return {kDebugViews.begin() + 1, kDebugViews.end()}; }

}  // namespace wg
