// Mip chains for the materials' textures, made on the CPU at load: each level halves
// the one above (a 2x2 box; an odd edge repeats its last texel), down to 1x1.
// sRGB textures are averaged in linear light (decoded, averaged, encoded again), so
// a level is as bright as the area it covers; other data is averaged as stored.
#pragma once
#include <vector>

#include "nodes/texture_image.hpp"

namespace wg {

// Every level after `base`, largest first (none for a 1x1 image).
std::vector<Image> mipLevelsBelow(const Image& base, bool srgb);

// How many levels a full chain of a width x height image has (1 + floor(log2(max))).
std::uint32_t fullMipLevelCount(int width, int height);

}  // namespace wg
