// Slanting snow and rain reach under overhangs (docs/weather-model.md, "Sky exposure"):
// the sky-exposure map's heights lowered, texel by texel, to the lowest surface within
// reach, so ground near an occluder's outline counts as open while ground deep under a
// roof stays sheltered. Computed once per scene on the CPU; the shaders' lookup is
// unchanged.
#pragma once
#include <vector>

namespace wg {

struct ExposureReach {
  float slant = 0.3f;     // horizontal reach per metre of occluder above the ground (about 17 degrees)
  float maxReach = 1.5f;  // metres
};

// `heights`: a square map, `resolution` texels per side, over texelsPerMetre x and z.
// Each texel's reach is slant * (its height - the lowest height within maxReach),
// rounded down to half a metre; the texel becomes the lowest height within that
// reach (square windows). Heights only ever go down: nothing gets more sheltered.
std::vector<float> reachUnderOverhangs(const std::vector<float>& heights, int resolution, float texelsPerMetreX,
                                       float texelsPerMetreZ, const ExposureReach& reach = {});

}  // namespace wg
