// Slanting snow and rain reach under overhangs (docs/weather-model.md, "Sky exposure"):
// the sky-exposure map's heights lowered, texel by texel, so that the ground under an
// overhang's edge gets snow, thinning out with a soft edge deeper under it, while ground
// deep under a roof stays sheltered. Computed once per scene on the CPU; the shaders'
// lookup is unchanged.
#pragma once
#include <vector>

namespace wg {

struct ExposureReach {
  float slant = 0.3f;     // horizontal reach per metre of overhang above what lies under it (about 17 degrees)
  float maxReach = 1.5f;  // metres
};

// `highest` and `lowest`: square maps, `resolution` texels per side over texelsPerMetre x
// and z, of the highest and the lowest surface above each texel. A texel is open where
// they lie within the shelter clearance of each other (nothing above its surface);
// elsewhere the overhang stands highest - lowest above what lies under it, and its reach
// R = slant * that (at most maxReach). Ground at distance d from the nearest open texel
// gets exposure 1 - smoothstep(R / 2, R, d): full snow half the reach in, none beyond it.
// The texel's height becomes the height over the lowest surface that gives the lowest
// surface that exposure. Heights only ever go down: nothing gets more sheltered.
std::vector<float> reachUnderOverhangs(const std::vector<float>& highest, const std::vector<float>& lowest,
                                       int resolution, float texelsPerMetreX, float texelsPerMetreZ,
                                       const ExposureReach& reach = {});

}  // namespace wg
