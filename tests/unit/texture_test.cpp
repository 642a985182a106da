// Texture images, procedural generators, Vulkan-equivalent sampling and image files.
#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "nodes/image_file.hpp"
#include "nodes/texture_generators.hpp"
#include "nodes/texture_image.hpp"
#include "nodes/texture_sampling.hpp"

namespace wg {
namespace {

using nlohmann::json;

constexpr float kSampleTolerance = 1e-6f;  // float rounding in the bilinear blend

const GeneratorSpec& generator(std::string_view name) {
  const GeneratorSpec* spec = findTextureGenerator(name);
  if (!spec) throw std::runtime_error("missing generator " + std::string(name));
  return *spec;
}

// FNV-1a over the texels: a compact fingerprint for golden comparisons.
std::uint64_t fingerprint(const Image& image) {
  constexpr std::uint64_t kOffsetBasis = 14695981039346656037ull;
  constexpr std::uint64_t kPrime = 1099511628211ull;
  std::uint64_t h = kOffsetBasis;
  for (std::uint8_t byte : image.rgba) h = (h ^ byte) * kPrime;
  return h;
}

// Mean absolute byte difference (all channels) between columns a and b, or rows a and
// b when `rows` is set.
double meanLineDifference(const Image& image, int a, int b, bool rows) {
  double sum = 0;
  const int n = rows ? image.width : image.height;
  for (int k = 0; k < n; ++k) {
    const std::size_t pa = rows ? image.texelOffset(k, a) : image.texelOffset(a, k);
    const std::size_t pb = rows ? image.texelOffset(k, b) : image.texelOffset(b, k);
    for (int c = 0; c < kImageChannels; ++c)
      sum += std::abs(int(image.rgba[pa + c]) - int(image.rgba[pb + c]));
  }
  return sum / (n * kImageChannels);
}

// ---- Generators --------------------------------------------------------------------

TEST(TextureGenerators, TableListsTheFourGeneratorsWithConsistentDefaults) {
  std::vector<std::string_view> names;
  for (const GeneratorSpec& spec : textureGenerators()) {
    names.push_back(spec.name);
    EXPECT_FALSE(spec.summary.empty()) << spec.name;
    // The defaults themselves must pass validation.
    json defaults = json::object();
    for (const GeneratorOption& option : spec.options) {
      EXPECT_FALSE(option.doc.empty()) << spec.name << "." << option.name;
      if (option.kind == GeneratorOption::Kind::Color3)
        defaults[std::string(option.name)] = option.defaultValue;
      else
        defaults[std::string(option.name)] = option.defaultValue[0];
    }
    EXPECT_EQ(validateGeneratorOptions(spec, defaults), "") << spec.name;
  }
  EXPECT_EQ(names, (std::vector<std::string_view>{"fbm", "fbm_normal", "voronoi", "flow"}));
  EXPECT_EQ(findTextureGenerator("perlin"), nullptr);
  EXPECT_EQ(findTextureGenerator("fbm"), &textureGenerators()[0]);
}

TEST(TextureGenerators, SameSeedSameBytesDifferentSeedDifferentBytes) {
  for (const GeneratorSpec& spec : textureGenerators()) {
    const Image a = generateTexture(spec, 42, 64, json::object());
    const Image b = generateTexture(spec, 42, 64, json::object());
    const Image c = generateTexture(spec, 43, 64, json::object());
    ASSERT_TRUE(a.valid()) << spec.name;
    EXPECT_EQ(a.width, 64);
    EXPECT_EQ(a.height, 64);
    EXPECT_EQ(a.rgba, b.rgba) << spec.name;
    EXPECT_NE(a.rgba, c.rgba) << spec.name;
  }
}

// Golden fingerprints: the generators must give these exact bytes on every machine
// and build type. If an intentional algorithm change breaks this, regenerate the
// values and mention it in the change (existing graphs' textures change with it).
TEST(TextureGenerators, BytesMatchGoldenFingerprints) {
  const std::vector<std::pair<std::string_view, std::uint64_t>> golden = {
      {"fbm", 0x2e2037d6d7671becull},
      {"fbm_normal", 0x9afc9008e232a2fdull},
      {"voronoi", 0x05a4752021c9a83full},
      {"flow", 0x0452deabc4fb41e7ull},
  };
  for (const auto& [name, expected] : golden) {
    const Image image = generateTexture(generator(name), 1, 32, json::object());
    EXPECT_EQ(fingerprint(image), expected) << name << ": 0x" << std::hex << fingerprint(image);
  }
}

TEST(TextureGenerators, EveryGeneratorTilesSeamlessly) {
  constexpr int kSize = 128;
  // The wrap seam may differ from an interior neighbour pair by chance, but not by
  // much; a generator that does not wrap its lattice gives a seam difference of the
  // order of the difference between unrelated columns.
  constexpr double kSeamFactor = 2.0;
  constexpr double kSeamSlackBytes = 0.5;
  const std::vector<std::pair<std::string_view, json>> cases = {
      {"fbm", {{"scale", 4}}},
      {"fbm_normal", {{"scale", 4}, {"octaves", 2}, {"strength", 1}}},
      {"voronoi", {{"scale", 3}}},  // not a power of two on purpose
      {"flow", {{"scale", 3}}},
  };
  for (const auto& [name, options] : cases) {
    const Image image = generateTexture(generator(name), 9, kSize, options);
    for (bool rows : {false, true}) {
      double interior = 0;
      for (int i = 0; i + 1 < kSize; ++i) interior += meanLineDifference(image, i, i + 1, rows);
      interior /= kSize - 1;
      const double seam = meanLineDifference(image, kSize - 1, 0, rows);
      const double unrelated = meanLineDifference(image, 0, kSize / 2, rows);
      SCOPED_TRACE(std::string(name) + (rows ? " rows" : " columns"));
      const double limit = kSeamFactor * interior + kSeamSlackBytes;
      EXPECT_LE(seam, limit) << "interior " << interior << " unrelated " << unrelated;
      // The check has teeth: a seam joining unrelated lines (lines half a tile apart,
      // say) would be well over the limit.
      constexpr double kUnrelatedMargin = 1.5;
      EXPECT_GT(unrelated, kUnrelatedMargin * limit) << "seam " << seam;
    }
  }
}

TEST(TextureGenerators, FbmColoursAndHeight) {
  const json options = {{"colorA", {1, 0, 0}}, {"colorB", {1, 0, 0}}};
  const Image image = generateTexture(generator("fbm"), 3, 16, options);
  int minAlpha = 255, maxAlpha = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += kImageChannels) {
    EXPECT_EQ(image.rgba[i + 0], 255);
    EXPECT_EQ(image.rgba[i + 1], 0);
    EXPECT_EQ(image.rgba[i + 2], 0);
    minAlpha = std::min<int>(minAlpha, image.rgba[i + 3]);
    maxAlpha = std::max<int>(maxAlpha, image.rgba[i + 3]);
  }
  EXPECT_LT(minAlpha, maxAlpha);  // alpha carries the noise

  // rgb = mix(colorA, colorB, alpha).
  const Image grey = generateTexture(generator("fbm"), 3, 16,
                                     {{"colorA", {0, 0, 0}}, {"colorB", {1, 1, 1}}});
  for (std::size_t i = 0; i < grey.rgba.size(); i += kImageChannels)
    EXPECT_NEAR(grey.rgba[i], grey.rgba[i + 3], 1);
}

TEST(TextureGenerators, FbmNormalEncodesTheFbmHeight) {
  const json shared = {{"scale", 4}, {"octaves", 3}, {"gain", 0.6}};
  const Image height = generateTexture(generator("fbm"), 5, 32, shared);
  json flatOptions = shared;
  flatOptions["strength"] = 0;
  const Image flat = generateTexture(generator("fbm_normal"), 5, 32, flatOptions);
  for (std::size_t i = 0; i < flat.rgba.size(); i += kImageChannels) {
    // Strength 0: the normal is +z, encoded (0.5, 0.5, 1).
    EXPECT_EQ(flat.rgba[i + 0], 128);
    EXPECT_EQ(flat.rgba[i + 1], 128);
    EXPECT_EQ(flat.rgba[i + 2], 255);
    EXPECT_EQ(flat.rgba[i + 3], height.rgba[i + 3]);  // same height field as fbm
  }

  const Image bumpy = generateTexture(generator("fbm_normal"), 5, 32, shared);
  for (int y = 0; y < bumpy.height; ++y)
    for (int x = 0; x < bumpy.width; ++x) {
      const auto t = bumpy.texel(x, y);
      const float nx = 2 * t[0] - 1, ny = 2 * t[1] - 1, nz = 2 * t[2] - 1;
      EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.f, 0.03f);  // unit length up to 8-bit rounding
      EXPECT_GT(nz, 0.f);
    }
  // The normal leans away from uphill: where height rises along +u, x is negative.
  const auto h = [&](int x) { return height.texel((x + 32) % 32, 7)[3]; };
  int agree = 0, total = 0;
  for (int x = 0; x < 32; ++x) {
    const float slope = h(x + 1) - h(x - 1);
    if (std::abs(slope) < 0.02f) continue;
    ++total;
    agree += (slope > 0) == (bumpy.texel(x, 7)[0] < 0.5f);
  }
  ASSERT_GT(total, 0);
  EXPECT_EQ(agree, total);
}

TEST(TextureGenerators, VoronoiCracksAndCellColours) {
  const Image cracked = generateTexture(generator("voronoi"), 11, 64, {{"edgeWidth", 0.2}});
  int crackTexels = 0, cellTexels = 0;
  for (std::size_t i = 0; i < cracked.rgba.size(); i += kImageChannels) {
    if (cracked.rgba[i + 3] == 255) ++crackTexels;
    if (cracked.rgba[i + 3] == 0) ++cellTexels;
  }
  EXPECT_GT(crackTexels, 0);
  EXPECT_GT(cellTexels, crackTexels);  // cracks are thin lines between large cells

  const Image solid = generateTexture(
      generator("voronoi"), 11, 64, {{"edgeWidth", 0}, {"colorA", {0, 1, 0}}, {"colorB", {0, 1, 0}}});
  for (std::size_t i = 0; i < solid.rgba.size(); i += kImageChannels) {
    EXPECT_EQ(solid.rgba[i + 1], 255);  // no darkening without cracks
    EXPECT_EQ(solid.rgba[i + 3], 0);
  }
}

TEST(TextureGenerators, FlowChannels) {
  const Image image = generateTexture(generator("flow"), 2, 32, json::object());
  bool decorrelated = false;
  for (std::size_t i = 0; i < image.rgba.size(); i += kImageChannels) {
    const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
    EXPECT_NEAR(b, (r + g) / 2.0, 1.0);
    EXPECT_EQ(image.rgba[i + 3], 255);
    decorrelated |= std::abs(r - g) > 20;
  }
  EXPECT_TRUE(decorrelated);
}

TEST(TextureGenerators, OptionValidation) {
  const GeneratorSpec& fbm = generator("fbm");
  const auto expectError = [&](const json& options, std::string_view mentions) {
    const std::string error = validateGeneratorOptions(fbm, options);
    EXPECT_NE(error.find(mentions), std::string::npos) << options.dump() << " -> " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
  };
  EXPECT_EQ(validateGeneratorOptions(fbm, json::object()), "");
  EXPECT_EQ(validateGeneratorOptions(fbm, nullptr), "");
  EXPECT_EQ(validateGeneratorOptions(fbm, {{"scale", 64}, {"octaves", 1}, {"gain", 0}}), "");
  EXPECT_EQ(validateGeneratorOptions(fbm, {{"scale", 16.0}}), "");  // integral float is fine
  expectError({{"roughness", 1}}, "unknown option 'roughness'");
  expectError({{"roughness", 1}}, "scale, octaves, gain, colorA, colorB");  // lists the fix
  expectError({{"seed", 1}}, "'seed'");  // texture-level keys are not options
  expectError({{"octaves", 12}}, "'octaves' must be an integer from 1 to 8");
  expectError({{"scale", 0}}, "'scale'");
  expectError({{"scale", 2.5}}, "integer");
  expectError({{"gain", 1.5}}, "'gain' must be a number from 0 to 1");
  expectError({{"gain", "high"}}, "'gain'");
  expectError({{"gain", std::numeric_limits<double>::quiet_NaN()}}, "'gain'");
  expectError({{"colorA", {0.5, 0.5}}}, "array of 3 numbers");
  expectError({{"colorB", {0.5, 1.5, 0.5}}}, "'colorB'");
  expectError(json::array({1, 2}), "JSON object");
  EXPECT_NE(validateGeneratorOptions(generator("fbm_normal"), {{"colorA", {0, 0, 0}}}), "");
  EXPECT_NE(validateGeneratorOptions(generator("fbm_normal"), {{"strength", 17}}), "");
  EXPECT_NE(validateGeneratorOptions(generator("voronoi"), {{"edgeWidth", -0.1}}), "");
  EXPECT_NE(validateGeneratorOptions(generator("flow"), {{"gain", 0.5}}), "");
}

TEST(TextureGenerators, GenerateRejectsBadSizeAndOptions) {
  const GeneratorSpec& fbm = generator("fbm");
  EXPECT_TRUE(isValidGeneratorSize(16));
  EXPECT_TRUE(isValidGeneratorSize(2048));
  for (int size : {0, 8, 100, 4096}) {
    EXPECT_FALSE(isValidGeneratorSize(size)) << size;
    EXPECT_THROW(generateTexture(fbm, 0, size, json::object()), std::invalid_argument) << size;
  }
  EXPECT_THROW(generateTexture(fbm, 0, 16, {{"octaves", 0}}), std::invalid_argument);
}

// ---- Sampling ----------------------------------------------------------------------

// 2x2 image whose red channel is 0, 0.2 (row 0) and 0.4, 1 (row 1); green is 1 - red,
// blue is constant and alpha 1, so every channel is checked by the same weights.
Image twoByTwo() {
  Image image = Image::blank(2, 2);
  const std::uint8_t red[4] = {0, 51, 102, 255};  // 51/255 = 0.2, 102/255 = 0.4
  for (int i = 0; i < 4; ++i) {
    image.rgba[i * 4 + 0] = red[i];
    image.rgba[i * 4 + 1] = static_cast<std::uint8_t>(255 - red[i]);
    image.rgba[i * 4 + 2] = 128;
    image.rgba[i * 4 + 3] = 255;
  }
  return image;
}

void expectRed(const Image& image, float u, float v, TextureWrap wrap, TextureFilter filter,
               float expected) {
  const Value s = sampleImage(image, u, v, wrap, filter);
  SCOPED_TRACE("u=" + std::to_string(u) + " v=" + std::to_string(v) + " wrap=" +
               std::string(textureWrapName(wrap)) + " filter=" +
               std::string(textureFilterName(filter)));
  ASSERT_EQ(s.type, ValueType::Vec4);
  EXPECT_NEAR(s.v[0], expected, kSampleTolerance);
  EXPECT_NEAR(s.v[1], 1.f - expected, kSampleTolerance);
  EXPECT_NEAR(s.v[2], 128.f / 255.f, kSampleTolerance);
  EXPECT_NEAR(s.v[3], 1.f, kSampleTolerance);
}

constexpr TextureWrap kAllWraps[] = {TextureWrap::Repeat, TextureWrap::Clamp, TextureWrap::Mirror};

TEST(TextureSampling, ParseAndNameRoundTrip) {
  for (TextureWrap wrap : kAllWraps) EXPECT_EQ(parseTextureWrap(textureWrapName(wrap)), wrap);
  for (TextureFilter f : {TextureFilter::Linear, TextureFilter::Nearest})
    EXPECT_EQ(parseTextureFilter(textureFilterName(f)), f);
  EXPECT_EQ(parseTextureWrap("repeat"), TextureWrap::Repeat);
  EXPECT_EQ(parseTextureWrap("clamp"), TextureWrap::Clamp);
  EXPECT_EQ(parseTextureWrap("mirror"), TextureWrap::Mirror);
  EXPECT_EQ(parseTextureFilter("nearest"), TextureFilter::Nearest);
  EXPECT_EQ(parseTextureWrap("Repeat"), std::nullopt);
  EXPECT_EQ(parseTextureWrap("wrap"), std::nullopt);
  EXPECT_EQ(parseTextureFilter("bilinear"), std::nullopt);
}

TEST(TextureSampling, BilinearAtTexelCentresReturnsTheTexel) {
  const Image image = twoByTwo();
  for (TextureWrap wrap : kAllWraps) {
    expectRed(image, 0.25f, 0.25f, wrap, TextureFilter::Linear, 0.f);
    expectRed(image, 0.75f, 0.25f, wrap, TextureFilter::Linear, 0.2f);
    expectRed(image, 0.25f, 0.75f, wrap, TextureFilter::Linear, 0.4f);
    expectRed(image, 0.75f, 0.75f, wrap, TextureFilter::Linear, 1.f);
  }
}

TEST(TextureSampling, BilinearInteriorWeights) {
  const Image image = twoByTwo();
  for (TextureWrap wrap : kAllWraps) {
    // Centre of the image: the four texels equally, (0 + 0.2 + 0.4 + 1) / 4.
    expectRed(image, 0.5f, 0.5f, wrap, TextureFilter::Linear, 0.4f);
    // u*w - 0.5 = 0.25: 3/4 of texel 0 and 1/4 of texel 1 on row 0.
    expectRed(image, 0.375f, 0.25f, wrap, TextureFilter::Linear, 0.05f);
    // Along v on column 1: 0.2 + (1 - 0.2) * 0.25.
    expectRed(image, 0.75f, 0.375f, wrap, TextureFilter::Linear, 0.4f);
  }
}

TEST(TextureSampling, BilinearWrapSeams) {
  const Image image = twoByTwo();
  constexpr auto L = TextureFilter::Linear;
  // u = 0: halfway between texel -1 and texel 0 (row 0).
  expectRed(image, 0.f, 0.25f, TextureWrap::Repeat, L, 0.1f);  // texel -1 is texel 1
  expectRed(image, 0.f, 0.25f, TextureWrap::Clamp, L, 0.f);    // texel -1 clamps to 0
  expectRed(image, 0.f, 0.25f, TextureWrap::Mirror, L, 0.f);   // texel -1 mirrors to 0
  // u = 1: halfway between texel 1 and texel 2.
  expectRed(image, 1.f, 0.25f, TextureWrap::Repeat, L, 0.1f);
  expectRed(image, 1.f, 0.25f, TextureWrap::Clamp, L, 0.2f);
  expectRed(image, 1.f, 0.25f, TextureWrap::Mirror, L, 0.2f);
  // One tile to the right, texel 3's centre: repeat -> texel 1, mirror -> texel 0.
  expectRed(image, 1.75f, 0.25f, TextureWrap::Repeat, L, 0.2f);
  expectRed(image, 1.75f, 0.25f, TextureWrap::Clamp, L, 0.2f);
  expectRed(image, 1.75f, 0.25f, TextureWrap::Mirror, L, 0.f);
  // Two tiles left: every mode's period ends here, mirror included.
  expectRed(image, -1.75f, 0.25f, TextureWrap::Repeat, L, 0.f);
  expectRed(image, -1.75f, 0.25f, TextureWrap::Mirror, L, 0.f);
  expectRed(image, -1.75f, 0.25f, TextureWrap::Clamp, L, 0.f);
  // Texel -1's centre: repeat -> texel 1; clamp and mirror -> texel 0.
  expectRed(image, -0.25f, 0.25f, TextureWrap::Repeat, L, 0.2f);
  expectRed(image, -0.25f, 0.25f, TextureWrap::Clamp, L, 0.f);
  expectRed(image, -0.25f, 0.25f, TextureWrap::Mirror, L, 0.f);
  // The corner: repeat blends all four texels, the others only texel (0,0).
  expectRed(image, 0.f, 0.f, TextureWrap::Repeat, L, 0.4f);
  expectRed(image, 0.f, 0.f, TextureWrap::Clamp, L, 0.f);
  expectRed(image, 0.f, 0.f, TextureWrap::Mirror, L, 0.f);
  // Along v at the bottom edge (column 1): between row 1 and row 2.
  expectRed(image, 0.75f, 1.f, TextureWrap::Repeat, L, 0.6f);  // (1 + 0.2) / 2
  expectRed(image, 0.75f, 1.f, TextureWrap::Clamp, L, 1.f);
  expectRed(image, 0.75f, 1.f, TextureWrap::Mirror, L, 1.f);
}

TEST(TextureSampling, NearestUsesFloorOfScaledCoordinate) {
  const Image image = twoByTwo();
  constexpr auto N = TextureFilter::Nearest;
  for (TextureWrap wrap : kAllWraps) {
    expectRed(image, 0.49f, 0.1f, wrap, N, 0.f);
    expectRed(image, 0.5f, 0.1f, wrap, N, 0.2f);  // floor(1.0) = 1: the boundary goes right
    expectRed(image, 0.99f, 0.5f, wrap, N, 1.f);
    expectRed(image, 0.f, 0.f, wrap, N, 0.f);
  }
  expectRed(image, -0.1f, 0.1f, TextureWrap::Repeat, N, 0.2f);
  expectRed(image, -0.1f, 0.1f, TextureWrap::Clamp, N, 0.f);
  expectRed(image, -0.1f, 0.1f, TextureWrap::Mirror, N, 0.f);
  expectRed(image, 1.1f, 0.1f, TextureWrap::Repeat, N, 0.f);
  expectRed(image, 1.1f, 0.1f, TextureWrap::Clamp, N, 0.2f);
  expectRed(image, 1.1f, 0.1f, TextureWrap::Mirror, N, 0.2f);
  expectRed(image, 0.1f, 1.f, TextureWrap::Repeat, N, 0.f);  // v = 1 is row 2 -> row 0
  expectRed(image, 0.1f, 1.f, TextureWrap::Clamp, N, 0.4f);
}

TEST(TextureSampling, HugeAndNonFiniteCoordinatesAreSafe) {
  const Image image = twoByTwo();
  for (TextureWrap wrap : kAllWraps)
    for (TextureFilter filter : {TextureFilter::Linear, TextureFilter::Nearest})
      for (float u : {1e30f, -1e30f, 4096.25f, std::numeric_limits<float>::infinity(),
                      std::numeric_limits<float>::quiet_NaN()}) {
        const Value s = sampleImage(image, u, 0.25f, wrap, filter);
        for (int c = 0; c < 4; ++c) {
          EXPECT_GE(s.v[c], 0.f);
          EXPECT_LE(s.v[c], 1.f);
        }
      }
  // An exact integer number of tiles away, repeat returns the same texel.
  expectRed(image, 4096.25f, 0.25f, TextureWrap::Repeat, TextureFilter::Linear, 0.f);
  expectRed(image, 4096.75f, 0.25f, TextureWrap::Repeat, TextureFilter::Linear, 0.2f);
  expectRed(image, std::numeric_limits<float>::quiet_NaN(), 0.25f, TextureWrap::Clamp,
            TextureFilter::Nearest, 0.f);
  // No image: transparent black.
  EXPECT_EQ(sampleImage(Image{}, 0.5f, 0.5f, TextureWrap::Repeat, TextureFilter::Linear),
            Value::vec4(0, 0, 0, 0));
}

TEST(TextureSampling, SamplerUsesEachTexturesSettings) {
  TextureSampler sampler;
  sampler.images = {twoByTwo(), twoByTwo()};
  SamplerState clampNearest;
  clampNearest.wrapU = clampNearest.wrapV = TextureWrap::Clamp;
  clampNearest.minFilter = clampNearest.magFilter = TextureFilter::Nearest;
  sampler.states = {clampNearest};  // texture 1 falls back to repeat, linear
  EXPECT_NEAR(sampler.sample(0, -0.1f, 0.1f).v[0], 0.f, kSampleTolerance);   // clamp, nearest
  EXPECT_NEAR(sampler.sample(1, -0.1f, 0.25f).v[0], 0.14f, kSampleTolerance);  // repeat, linear
  EXPECT_EQ(sampler.sample(2, 0.5f, 0.5f), Value::vec4(0, 0, 0, 0));
  EXPECT_EQ(sampler.sample(-1, 0.5f, 0.5f), Value::vec4(0, 0, 0, 0));
}

TEST(TextureImage, Unorm8RoundTripsAndClamps) {
  for (int byte = 0; byte <= 255; ++byte)
    EXPECT_EQ(encodeUnorm8(decodeUnorm8(static_cast<std::uint8_t>(byte))), byte);
  EXPECT_EQ(encodeUnorm8(-1.f), 0);
  EXPECT_EQ(encodeUnorm8(2.f), 255);
  EXPECT_EQ(encodeUnorm8(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(encodeUnorm8(0.5f), 128);  // 127.5 rounds up
  Image image = Image::blank(3, 2);
  EXPECT_TRUE(image.valid());
  image.setTexel(2, 1, {1.f, 0.f, 0.2f, 0.4f});
  EXPECT_EQ(image.rgba[(1 * 3 + 2) * 4 + 2], 51);
  EXPECT_EQ(image.texel(2, 1), (std::array<float, 4>{1.f, 0.f, 0.2f, 0.4f}));
  EXPECT_FALSE(Image{}.valid());
}

// ---- Image files -------------------------------------------------------------------

class TextureImageFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("wg_texture_test_" + std::to_string(::getpid()) + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

// A 3x2 RGBA test pattern, row 0 first.
std::vector<std::uint8_t> pattern() {
  return {255, 0, 0, 255,  0, 255, 0, 128,  0, 0, 255, 0,
          10, 20, 30, 40,  50, 60, 70, 80,  90, 100, 110, 120};
}

TEST_F(TextureImageFile, PngProbeAndLoadKeepBytesAndRowOrder) {
  const std::string file = path("pattern.png");
  const auto pixels = pattern();
  ASSERT_TRUE(stbi_write_png(file.c_str(), 3, 2, 4, pixels.data(), 3 * 4));
  int w = -1, h = -1;
  std::string error;
  EXPECT_EQ(probeImageFile(file, w, h, error), ImageFileStatus::Ok) << error;
  EXPECT_EQ(w, 3);
  EXPECT_EQ(h, 2);
  const std::optional<Image> image = loadImageFile(file, error);
  ASSERT_TRUE(image) << error;
  EXPECT_EQ(image->width, 3);
  EXPECT_EQ(image->height, 2);
  EXPECT_EQ(image->rgba, pixels);
  // Row 0 of the file is v in [0, 1/2): a nearest sample there reads it.
  EXPECT_EQ(sampleImage(*image, 0.1f, 0.1f, TextureWrap::Clamp, TextureFilter::Nearest),
            Value::vec4(1, 0, 0, 1));
}

TEST_F(TextureImageFile, RgbFileGetsOpaqueAlpha) {
  const std::string file = path("rgb.png");
  const std::uint8_t rgb[] = {1, 2, 3, 4, 5, 6};
  ASSERT_TRUE(stbi_write_png(file.c_str(), 2, 1, 3, rgb, 2 * 3));
  std::string error;
  const auto image = loadImageFile(file, error);
  ASSERT_TRUE(image) << error;
  EXPECT_EQ(image->rgba, (std::vector<std::uint8_t>{1, 2, 3, 255, 4, 5, 6, 255}));
}

TEST_F(TextureImageFile, AcceptsJpegTgaAndBmp) {
  std::vector<std::uint8_t> grey(8 * 8 * 4, 200);
  ASSERT_TRUE(stbi_write_jpg(path("a.jpg").c_str(), 8, 8, 4, grey.data(), 90));
  ASSERT_TRUE(stbi_write_tga(path("a.tga").c_str(), 8, 8, 4, grey.data()));
  ASSERT_TRUE(stbi_write_bmp(path("a.bmp").c_str(), 8, 8, 4, grey.data()));
  for (const char* name : {"a.jpg", "a.tga", "a.bmp"}) {
    int w = 0, h = 0;
    std::string error;
    EXPECT_EQ(probeImageFile(path(name), w, h, error), ImageFileStatus::Ok) << name << ": " << error;
    EXPECT_EQ(w, 8);
    const auto image = loadImageFile(path(name), error);
    ASSERT_TRUE(image) << name << ": " << error;
    EXPECT_NEAR(image->rgba[0], 200, 2) << name;  // JPEG is lossy
  }
}

TEST_F(TextureImageFile, MissingFileIsNotFound) {
  int w = 7, h = 7;
  std::string error;
  EXPECT_EQ(probeImageFile(path("nope.png"), w, h, error), ImageFileStatus::NotFound);
  EXPECT_EQ(error, "file not found");
  EXPECT_EQ(w, 0);
  error.clear();
  EXPECT_FALSE(loadImageFile(path("nope.png"), error));
  EXPECT_EQ(error, "file not found");
}

TEST_F(TextureImageFile, TextFileNamedPngIsUnsupported) {
  const std::string file = path("x.png");
  std::ofstream(file) << "this is not an image\n";
  int w = 0, h = 0;
  std::string error;
  EXPECT_EQ(probeImageFile(file, w, h, error), ImageFileStatus::Unsupported);
  EXPECT_EQ(error, "unsupported image format (supported: PNG, JPEG, TGA, BMP)");
  EXPECT_FALSE(loadImageFile(file, error));
  // The same text named .tga (TGA has no signature) is rejected too.
  std::ofstream(path("x.tga")) << "this is not an image\n";
  EXPECT_EQ(probeImageFile(path("x.tga"), w, h, error), ImageFileStatus::Unsupported);
}

TEST_F(TextureImageFile, FormatsStbDecodesButWeDoNotSupportAreRejected) {
  const float hdr[] = {1.f, 2.f, 3.f};
  ASSERT_TRUE(stbi_write_hdr(path("a.hdr").c_str(), 1, 1, 3, hdr));
  int w = 0, h = 0;
  std::string error;
  EXPECT_EQ(probeImageFile(path("a.hdr"), w, h, error), ImageFileStatus::Unsupported);
  EXPECT_NE(error.find("PNG, JPEG, TGA, BMP"), std::string::npos);
}

TEST_F(TextureImageFile, TruncatedPngIsUnsupportedWithReason) {
  const std::string file = path("cut.png");
  const unsigned char signatureOnly[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(signatureOnly), sizeof signatureOnly);
  int w = 0, h = 0;
  std::string error;
  EXPECT_EQ(probeImageFile(file, w, h, error), ImageFileStatus::Unsupported);
  EXPECT_NE(error.find("PNG"), std::string::npos) << error;
}

TEST_F(TextureImageFile, OversizedImageIsTooLarge) {
  const int wide = kMaxImageFileDimension + 1;
  const std::vector<std::uint8_t> row(static_cast<std::size_t>(wide), 0);
  ASSERT_TRUE(stbi_write_png(path("wide.png").c_str(), wide, 1, 1, row.data(), wide));
  int w = 0, h = 0;
  std::string error;
  EXPECT_EQ(probeImageFile(path("wide.png"), w, h, error), ImageFileStatus::TooLarge);
  EXPECT_EQ(w, wide);  // the actual size, for the caller's message
  EXPECT_EQ(h, 1);
  EXPECT_NE(error.find("8192"), std::string::npos) << error;
  EXPECT_FALSE(loadImageFile(path("wide.png"), error));
}

}  // namespace
}  // namespace wg
