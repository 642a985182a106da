// The shared weather noise texture: one tiling RGBA8 image, bound once in the frame set
// (set 0, "weatherNoise"), that replaces the weather's ALU value noise (seed 000 samples
// noise textures: eq. 3.6's flow map and the NoiseMap of eq. 3.10, 3.14). It is made
// by the procedural generators of nodes/texture_generators.hpp, so it is the same bytes
// on every run; the CPU evaluator samples these texels exactly as the GPU's sampler does
// (bilinear, repeat, LOD 0). docs/weather-model.md, "Noise textures".
#pragma once
#include <glm/glm.hpp>

#include "nodes/op_definition.hpp"
#include "nodes/texture_image.hpp"

namespace wg::weather {

// One channel per noise, each an independent field (its own generator seed):
//   r: the transition noise of eq. 3.14 (snow, moss, ice, hoarfrost) and eq. 3.10
//   g: eq. 3.6's flow map (wind's two panning phases)
//   b: the eq. 3.18 ripple
//   a: the puddle shapes of section 5.1.2
inline constexpr int kNoiseSize = 512;         // texels per side
inline constexpr float kNoiseTile = 32.f;      // metres of world xz per repeat
inline constexpr int kTransitionCells = 48;    // lattice cells per tile: 1.5 per metre
inline constexpr int kFlowCells = 8;           // 0.25 per metre
inline constexpr int kRippleCells = 64;        // 2 per metre
inline constexpr int kPuddleCells = 11;        // about 0.34 per metre: 3 m blobs

// The texture's texels, generated on first use (thread-safe).
const Image& noiseImage();
// The texture at tile coordinates uv (world xz / kNoiseTile), as a linear, repeating
// sampler reads it at LOD 0.
glm::vec4 sampleNoise(glm::vec2 uv);
// Every channel at a world point: the one lookup the effects share.
glm::vec4 noiseAt(glm::vec3 position);

// GLSL: wg_weather_noise(uv) and wg_weather_noise_at(p), sampling "weatherNoise": an op
// whose library depends on it lists "weatherNoise" in its OpDef::weatherMaps.
extern const ShaderLibrary kWeatherNoiseLibrary;

}  // namespace wg::weather
