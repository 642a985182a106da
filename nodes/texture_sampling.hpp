// CPU texture sampling that reproduces what a Vulkan sampler returns for the same
// image, so the CPU evaluator and the generated shaders agree.
#pragma once
#include <optional>
#include <string_view>
#include <vector>

#include "nodes/value.hpp"
#include "nodes/texture_image.hpp"

namespace wg {

// Vulkan's VK_SAMPLER_ADDRESS_MODE_REPEAT / CLAMP_TO_EDGE / MIRRORED_REPEAT.
enum class TextureWrap { Repeat, Clamp, Mirror };
// Vulkan's VK_FILTER_LINEAR / NEAREST (one mip level, no anisotropy).
enum class TextureFilter { Linear, Nearest };

// How texels are stored: linear data, or sRGB-encoded colour that is decoded to linear
// before filtering, as Vulkan's *_SRGB formats do. Alpha is always linear.
enum class ColorSpace { Linear, Srgb };

// Graph spellings: "repeat", "clamp", "mirror"; "linear", "nearest"; "linear", "srgb".
std::optional<TextureWrap> parseTextureWrap(std::string_view name);
std::optional<TextureFilter> parseTextureFilter(std::string_view name);
std::optional<ColorSpace> parseColorSpace(std::string_view name);
std::string_view textureWrapName(TextureWrap wrap);
std::string_view textureFilterName(TextureFilter filter);
std::string_view colorSpaceName(ColorSpace space);

// A texture's sampler and format settings: wrap per axis, filter per direction.
struct SamplerState {
  TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;
  TextureFilter minFilter = TextureFilter::Linear, magFilter = TextureFilter::Linear;
  ColorSpace colorSpace = ColorSpace::Linear;
  friend bool operator==(const SamplerState&, const SamplerState&) = default;
};

// Samples `image` at normalized (u, v) following the Vulkan specification's texel
// filtering rules for a single level: texel centres lie at ((i+0.5)/w, (j+0.5)/h);
// linear blends texels floor(u*w-0.5) and the next with weight frac(u*w-0.5); nearest
// takes floor(u*w); the wrap mode is applied to the integer texel coordinates.
// Returns a vec4 in [0,1]. Non-finite coordinates are read as 0 (the GPU result for
// them is undefined). GPUs quantize the linear weights to their sub-texel precision
// (commonly 8 bits), so linear results may differ from the GPU's by up to about 1/256
// of the difference between neighbouring texels; texel centres and nearest sampling
// match exactly. An invalid (empty) image samples as transparent black.
//
// Each axis uses its own wrap mode. Sampling happens at LOD 0, where the texture is
// magnified (the runtime's samplers have maxLod 0), so the filter is magFilter. sRGB
// texels have their colour decoded (decodeSrgb8) before they are blended.
Value sampleImage(const Image& image, float u, float v, const SamplerState& state);
// Both axes wrapped alike, one filter, linear data.
Value sampleImage(const Image& image, float u, float v, TextureWrap wrap, TextureFilter filter);

// The textures a compiled graph declares, by index (the texture Value's v[0]), with
// their sampler settings. Used by the CPU evaluator (EvalContext::textures).
struct TextureSampler {
  std::vector<Image> images;
  std::vector<SamplerState> states;  // missing entries: SamplerState{}

  // An index with no image samples as transparent black, like an unbound descriptor
  // with robustness features enabled.
  Value sample(int index, float u, float v) const;
};

}  // namespace wg
