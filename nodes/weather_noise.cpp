#include "nodes/weather_noise.hpp"

#include <nlohmann/json.hpp>

#include "nodes/texture_generators.hpp"
#include "nodes/texture_sampling.hpp"
#include "nodes/weather_maps.hpp"

namespace wg::weather {

namespace {
// Each channel comes from its own generator call with its own seed, so the four
// fields are independent; the generators wrap their lattice by the tile, so it tiles.
struct Channel {
  std::string_view generator;
  std::uint32_t seed;
  int cells;
  int octaves;
  int sourceChannel;  // which channel of the generated image holds the noise
};
// fbm's alpha is its noise; flow's red is its first field. One octave keeps the
// contrast of the value noise it replaces (the ripple, the "high contrast" puddles);
// the transition gets a second octave at half amplitude for a ragged natural edge.
constexpr Channel kChannels[4] = {
    {"fbm", 3001, kTransitionCells, 2, 3},
    {"flow", 3002, kFlowCells, 2, 0},
    {"fbm", 3003, kRippleCells, 1, 3},
    {"fbm", 3004, kPuddleCells, 1, 3},
};

Image generateNoise() {
  Image out = Image::blank(kNoiseSize, kNoiseSize);
  for (int c = 0; c < 4; ++c) {
    const Channel& ch = kChannels[c];
    nlohmann::json options = {{"scale", ch.cells}, {"octaves", ch.octaves}};
    Image layer = generateTexture(*findTextureGenerator(ch.generator), ch.seed, kNoiseSize, options);
    for (std::size_t t = 0; t < out.rgba.size(); t += kImageChannels)
      out.rgba[t + static_cast<std::size_t>(c)] = layer.rgba[t + static_cast<std::size_t>(ch.sourceChannel)];
  }
  return out;
}
}  // namespace

const Image& noiseImage() {
  static const Image kImage = generateNoise();
  return kImage;
}

glm::vec4 sampleNoise(glm::vec2 uv) {
  Value v = sampleImage(noiseImage(), uv.x, uv.y, TextureWrap::Repeat, TextureFilter::Linear);
  return {v.v[0], v.v[1], v.v[2], v.v[3]};
}

glm::vec4 noiseAt(glm::vec3 position) { return sampleNoise(glm::vec2(position.x, position.z) / kNoiseTile); }

// 1 / kNoiseTile = 0.03125 is exact, so the GLSL multiply rounds as the CPU's divide.
const ShaderLibrary kWeatherNoiseLibrary = {
    "weather_noise",
    R"(// The shared weather noise (set 0): r transition, g flow, b ripple, a puddles; one
// repeat tile per 32 m of world xz, read at LOD 0 as the CPU evaluator does.
vec2 wg_weather_noise_uv(const vec3 p) { return p.xz * 0.03125; }
vec4 wg_weather_noise_at(const vec3 p) { return wg_weather_noise(wg_weather_noise_uv(p)); }
)",
    {&kWeatherMapLibrary}};

}  // namespace wg::weather
