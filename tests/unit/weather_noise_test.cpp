// The weather's shared noise texture (nodes/weather_noise.hpp; docs/weather-model.md,
// "Noise textures"): made by the procedural generators, tiling, one independent field
// per channel, sampled on the CPU as the GPU's repeating linear sampler does; the
// public API hands out the same texels; materials bind it in set 0 and share one lookup
// between the effects that eq. 3.14 gives one NoiseMap.
#include <gtest/gtest.h>

#include <weathergen/weathergen.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "driver/material_compiler.hpp"
#include "nodes/texture_generators.hpp"
#include "nodes/weather_noise.hpp"

namespace wg {
namespace {

using weather::kNoiseSize;
using weather::noiseImage;
using weather::sampleNoise;

float channelAt(int x, int y, int c) { return noiseImage().texel(x, y)[static_cast<std::size_t>(c)]; }

TEST(WeatherNoise, IsTheGeneratorsOutputOneFieldPerChannel) {
  const Image& image = noiseImage();
  ASSERT_EQ(image.width, kNoiseSize);
  ASSERT_EQ(image.height, kNoiseSize);
  ASSERT_TRUE(image.valid());
  // r: fbm's noise (alpha), g: flow's first field (red), b, a: fbm's noise.
  struct Source {
    const char* generator;
    std::uint32_t seed;
    int cells, octaves, channel;
  };
  const std::array<Source, 4> sources = {{{"fbm", 3001, weather::kTransitionCells, 2, 3},
                                          {"flow", 3002, weather::kFlowCells, 2, 0},
                                          {"fbm", 3003, weather::kRippleCells, 1, 3},
                                          {"fbm", 3004, weather::kPuddleCells, 1, 3}}};
  for (int c = 0; c < 4; ++c) {
    const Source& s = sources[static_cast<std::size_t>(c)];
    Image layer = generateTexture(*findTextureGenerator(s.generator), s.seed, kNoiseSize,
                                  nlohmann::json{{"scale", s.cells}, {"octaves", s.octaves}});
    std::size_t differing = 0;
    for (std::size_t t = 0; t < image.rgba.size(); t += 4)
      differing += image.rgba[t + static_cast<std::size_t>(c)] != layer.rgba[t + static_cast<std::size_t>(s.channel)];
    EXPECT_EQ(differing, 0u) << "channel " << c;
  }
}

TEST(WeatherNoise, ChannelsAreIndependentAndHaveContrast) {
  std::array<double, 4> sum{}, sumSquares{};
  std::array<std::array<double, 4>, 4> products{};
  std::array<float, 4> lo{1, 1, 1, 1}, hi{0, 0, 0, 0};
  const double n = double(kNoiseSize) * kNoiseSize;
  for (int y = 0; y < kNoiseSize; ++y)
    for (int x = 0; x < kNoiseSize; ++x) {
      auto t = noiseImage().texel(x, y);
      for (int i = 0; i < 4; ++i) {
        sum[i] += t[i];
        sumSquares[i] += double(t[i]) * t[i];
        lo[i] = std::min(lo[i], t[i]);
        hi[i] = std::max(hi[i], t[i]);
        for (int j = 0; j < 4; ++j) products[i][j] += double(t[i]) * t[j];
      }
    }
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(sum[i] / n, 0.5, 0.1) << "channel " << i;
    EXPECT_LT(lo[i], 0.25f) << "channel " << i;
    EXPECT_GT(hi[i], 0.75f) << "channel " << i;
    for (int j = i + 1; j < 4; ++j) {
      double cov = products[i][j] / n - sum[i] / n * sum[j] / n;
      double sdi = std::sqrt(sumSquares[i] / n - sum[i] / n * sum[i] / n);
      double sdj = std::sqrt(sumSquares[j] / n - sum[j] / n * sum[j] / n);
      // Independent fields, but the flow channel has only 8 x 8 lattice cells per tile,
      // so the sample correlation of two of them spreads by about 1/8.
      EXPECT_LT(std::abs(cov / (sdi * sdj)), 0.3) << "channels " << i << " and " << j;
    }
  }
}

TEST(WeatherNoise, TilesAndSamplesLikeARepeatingLinearSampler) {
  const float texel = 1.f / kNoiseSize;
  // Texel centres read the texel itself.
  for (auto [x, y] : {std::pair{0, 0}, {17, 300}, {kNoiseSize - 1, 5}}) {
    glm::vec4 s = sampleNoise({(x + 0.5f) * texel, (y + 0.5f) * texel});
    for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(s[c], channelAt(x, y, c));
  }
  // Halfway between two texels: their mean; across the edge, wrapped to the other side.
  glm::vec4 mid = sampleNoise({(10 + 1.f) * texel, (20 + 0.5f) * texel});
  EXPECT_NEAR(mid.x, 0.5f * (channelAt(10, 20, 0) + channelAt(11, 20, 0)), 1e-6f);
  glm::vec4 edge = sampleNoise({0.f, (3 + 0.5f) * texel});
  EXPECT_NEAR(edge.y, 0.5f * (channelAt(0, 3, 1) + channelAt(kNoiseSize - 1, 3, 1)), 1e-6f);
  // One tile (32 m) further is the same noise.
  for (glm::vec2 uv : {glm::vec2(0.123f, 0.456f), glm::vec2(0.9f, 0.01f)}) {
    glm::vec4 a = sampleNoise(uv), b = sampleNoise(uv + glm::vec2(1.f, -2.f));
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], 1e-4f);
  }
  // World points map to tile coordinates xz / 32.
  glm::vec4 at = weather::noiseAt({4.f, 100.f, 8.f}), uv = sampleNoise({0.125f, 0.25f});
  for (int c = 0; c < 4; ++c) EXPECT_EQ(at[c], uv[c]);
  // The tile itself is seamless: the generators wrap their lattice by the tile, so the
  // step across the edge is no larger than the steps inside it.
  for (int c = 0; c < 4; ++c) {
    float inside = 0.f, across = 0.f;
    for (int y = 0; y < kNoiseSize; ++y) {
      inside = std::max(inside, std::abs(channelAt(1, y, c) - channelAt(0, y, c)));
      across = std::max(across, std::abs(channelAt(0, y, c) - channelAt(kNoiseSize - 1, y, c)));
    }
    EXPECT_LE(across, inside + 2.f / 255.f) << "channel " << c;
  }
}

TEST(WeatherNoise, PublicApiHandsOutTheSameTexels) {
  weathergen::NoiseTexture api = weathergen::weatherNoiseTexture();
  EXPECT_EQ(api.width, noiseImage().width);
  EXPECT_EQ(api.height, noiseImage().height);
  EXPECT_TRUE(api.rgba8 == noiseImage().rgba);
}

std::string readGraph(const std::string& stem) {
  std::ifstream in(std::string(WG_SOURCE_DIR) + "/graphs/" + stem + ".json");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The text of main() only: the library defines the functions once whatever calls them.
// The statements of the stage's surface function, which the full shader's main() calls.
std::string surfaceFunctionOf(const std::string& source) { return source.substr(source.find("Output surface")); }

struct Compiled {
  std::string vert, frag;
  nlohmann::json reflection;
};
Compiled compileGraph(const std::string& stem, const std::string& preset = "") {
  CompileOptions options;
  if (!preset.empty()) options.weatherPreset = preset;
  auto r = compileMaterialText(stem + ".json", readGraph(stem), options);
  EXPECT_TRUE(r.material) << stem;
  if (!r.material) return {};
  return {surfaceFunctionOf(r.material->stage(ShaderLanguage::Glsl, ShaderStage::Vertex).source),
          surfaceFunctionOf(r.material->stage(ShaderLanguage::Glsl, ShaderStage::Fragment).source),
          nlohmann::json::parse(r.material->reflectionJson)};
}

const nlohmann::json* weatherMap(const nlohmann::json& reflection, const std::string& name) {
  for (const auto& m : reflection.at("weatherMaps"))
    if (m.at("name") == name) return &m;
  return nullptr;
}

// Eq. 3.14 gives snow, moss and ice one NoiseMap: rock's snow and moss (and the snow's
// displacement in the vertex stage) read one lookup; road's puddles and hoarfrost too.
TEST(WeatherNoise, EffectsShareOneLookup) {
  Compiled rock = compileGraph("rock");
  EXPECT_EQ(count(rock.frag, "wg_weather_noise_at("), 1u);
  EXPECT_EQ(count(rock.vert, "wg_weather_noise_at("), 1u);
  EXPECT_EQ(count(rock.frag, "wg_moss_coverage("), 1u);
  EXPECT_EQ(count(rock.frag, "wg_snow_coverage("), 1u);
  EXPECT_EQ(count(rock.frag, "wg_value_noise("), 1u);  // the rock material's own roughness jitter only
  Compiled road = compileGraph("road");
  EXPECT_EQ(count(road.frag, "wg_weather_noise_at("), 1u);
  EXPECT_EQ(count(road.frag, "wg_puddle_coverage("), 1u);
  EXPECT_EQ(count(road.frag, "wg_hoarfrost_coverage("), 1u);
}

// The frame set's layout comes from the reflection: weathered materials list the noise
// texture at set 0, bindings 9 and 10; unweathered ones do not.
TEST(WeatherNoise, ReflectionListsTheNoiseMapInTheFrameSet) {
  for (const char* stem : {"rock", "road", "river", "foliage", "terrain"}) {
    Compiled c = compileGraph(stem);
    const nlohmann::json* map = weatherMap(c.reflection, "weatherNoise");
    ASSERT_NE(map, nullptr) << stem;
    EXPECT_EQ(map->at("set"), 0) << stem;
    EXPECT_EQ(map->at("binding"), 9) << stem;
    EXPECT_EQ(map->at("samplerBinding"), 10) << stem;
    EXPECT_EQ(map->at("textureIdentifier"), "wg_weather_noise_map") << stem;
  }
  EXPECT_EQ(weatherMap(compileGraph("rock", "none").reflection, "weatherNoise"), nullptr);
}

}  // namespace
}  // namespace wg
