// Rendered linear values to an 8-bit sRGB image for PNGs and contact sheets.
#pragma once
#include "nodes/texture_image.hpp"
#include "host/scene_renderer.hpp"

namespace wg {

// sRGB-encodes each channel (values are clamped to [0, 1] first); alpha becomes 255.
Image toDisplayImage(const RenderedFrame& frame);
float linearToSrgb(float linear);

}  // namespace wg
