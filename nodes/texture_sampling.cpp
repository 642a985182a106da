#include "nodes/texture_sampling.hpp"

#include <cmath>

#include "nodes/srgb_transfer.hpp"

namespace wg {

namespace {

constexpr float kTexelCentre = 0.5f;  // texel i covers [i, i+1); its centre is i + 0.5

// Applies the wrap mode to integer texel coordinate i (held in a double so that any
// float coordinate converts without overflow; every value involved is an exact integer).
// Returns an index in [0, size).
int wrapTexel(double i, int size, TextureWrap wrap) {
  const double n = size;
  switch (wrap) {
    case TextureWrap::Repeat: {
      double r = std::fmod(i, n);  // exact; has the sign of i
      if (r < 0) r += n;
      return static_cast<int>(r);
    }
    case TextureWrap::Clamp:
      return static_cast<int>(i < 0 ? 0.0 : (i > n - 1 ? n - 1 : i));
    case TextureWrap::Mirror: {
      // Vulkan: (size - 1) - mirror((i mod (2 * size)) - size), mirror(a) = a >= 0 ? a : -(1 + a).
      double t = std::fmod(i, 2 * n);
      if (t < 0) t += 2 * n;
      const double a = t - n;
      const double mirrored = a >= 0 ? a : -(1 + a);
      return static_cast<int>((n - 1) - mirrored);
    }
  }
  return 0;
}

Value transparentBlack() { return Value::vec4(0.f, 0.f, 0.f, 0.f); }

float clamp01(float x) { return x < 0.f ? 0.f : (x > 1.f ? 1.f : x); }

// Texel (i, j) as the sampler reads it: sRGB colour decoded, alpha as stored.
std::array<float, 4> readTexel(const Image& image, int i, int j, ColorSpace space) {
  if (space == ColorSpace::Linear) return image.texel(i, j);
  const std::uint8_t* p = image.rgba.data() + image.texelOffset(i, j);
  return {decodeSrgb8(p[0]), decodeSrgb8(p[1]), decodeSrgb8(p[2]), decodeUnorm8(p[3])};
}

}  // namespace

std::optional<TextureWrap> parseTextureWrap(std::string_view name) {
  if (name == "repeat") return TextureWrap::Repeat;
  if (name == "clamp") return TextureWrap::Clamp;
  if (name == "mirror") return TextureWrap::Mirror;
  return std::nullopt;
}

std::optional<TextureFilter> parseTextureFilter(std::string_view name) {
  if (name == "linear") return TextureFilter::Linear;
  if (name == "nearest") return TextureFilter::Nearest;
  return std::nullopt;
}

std::optional<ColorSpace> parseColorSpace(std::string_view name) {
  if (name == "linear") return ColorSpace::Linear;
  if (name == "srgb") return ColorSpace::Srgb;
  return std::nullopt;
}

std::string_view textureWrapName(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Repeat: return "repeat";
    case TextureWrap::Clamp: return "clamp";
    case TextureWrap::Mirror: return "mirror";
  }
  return "repeat";
}

std::string_view textureFilterName(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::Linear: return "linear";
    case TextureFilter::Nearest: return "nearest";
  }
  return "linear";
}

std::string_view colorSpaceName(ColorSpace space) { return space == ColorSpace::Srgb ? "srgb" : "linear"; }

Value sampleImage(const Image& image, float u, float v, TextureWrap wrap, TextureFilter filter) {
  return sampleImage(image, u, v, SamplerState{wrap, wrap, filter, filter, ColorSpace::Linear});
}

Value sampleImage(const Image& image, float u, float v, const SamplerState& state) {
  if (!image.valid()) return transparentBlack();
  // Unnormalized coordinates, computed in float as the sampler does. A coordinate that
  // is not finite, or overflows when scaled (u = 1e38 on a 256-texel image), reads as 0:
  // wrapping infinity gives NaN, and NaN is no texel index.
  float x = u * static_cast<float>(image.width);
  float y = v * static_cast<float>(image.height);
  if (!std::isfinite(x)) x = 0.f;
  if (!std::isfinite(y)) y = 0.f;

  if (state.magFilter == TextureFilter::Nearest) {
    const int i = wrapTexel(std::floor(x), image.width, state.wrapU);
    const int j = wrapTexel(std::floor(y), image.height, state.wrapV);
    const auto t = readTexel(image, i, j, state.colorSpace);
    return Value::vec4(t[0], t[1], t[2], t[3]);
  }

  const float xs = x - kTexelCentre, ys = y - kTexelCentre;
  const float x0 = std::floor(xs), y0 = std::floor(ys);
  const float alpha = xs - x0, beta = ys - y0;  // weights of the second texel in x, y
  const int i0 = wrapTexel(x0, image.width, state.wrapU);
  const int i1 = wrapTexel(static_cast<double>(x0) + 1, image.width, state.wrapU);
  const int j0 = wrapTexel(y0, image.height, state.wrapV);
  const int j1 = wrapTexel(static_cast<double>(y0) + 1, image.height, state.wrapV);
  const ColorSpace space = state.colorSpace;
  const auto t00 = readTexel(image, i0, j0, space), t10 = readTexel(image, i1, j0, space);
  const auto t01 = readTexel(image, i0, j1, space), t11 = readTexel(image, i1, j1, space);
  const float w00 = (1.f - alpha) * (1.f - beta), w10 = alpha * (1.f - beta);
  const float w01 = (1.f - alpha) * beta, w11 = alpha * beta;
  Value out = Value::vec4(0.f, 0.f, 0.f, 0.f);
  // Rounding can push a blend of in-range texels a hair outside [0,1]; UNORM results
  // never leave it.
  for (int c = 0; c < kImageChannels; ++c)
    out.v[c] = clamp01(w00 * t00[c] + w10 * t10[c] + w01 * t01[c] + w11 * t11[c]);
  return out;
}

Value TextureSampler::sample(int index, float u, float v) const {
  if (index < 0 || static_cast<std::size_t>(index) >= images.size()) return transparentBlack();
  const auto i = static_cast<std::size_t>(index);
  return sampleImage(images[i], u, v, i < states.size() ? states[i] : SamplerState{});
}

}  // namespace wg
