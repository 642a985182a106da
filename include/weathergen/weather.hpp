// weathergen's weather loop for an engine: the simulation that turns temperature,
// precipitation and wind into the weather levels the surfaces read, the shared noise
// texture, and the sky-exposure map built from the engine's own meshes
// (docs/engine-api.md, "The weather loop").
//  - CPU only, no dependencies: link weathergen::weather.
//  - Every function is reentrant; no exception leaves this API.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace weathergen::weather {

// What the weather is doing now, set by the engine or its scripting. World space, y up.
struct Conditions {
  float temperature = 15.0f;                     // air, °C, in [-60, 60]
  float precipitation = 0.0f;                    // [0, 1]: 1 is heavy (about 10 mm/h of rain)
  std::array<float, 2> windDirection{1.0f, 0.0f};  // xz, where the wind blows to
  float windIntensity = 0.0f;                    // [0, 1]: calm .. blizzard-force
  std::array<float, 3> sunDirection{0.0f, 1.0f, 0.0f};  // towards the sun
  float sunIntensity = 1.0f;                     // [0, 1]
  // [0, 1]: how strongly direct sun melts snow (seed 000, eq. 3.5's SunIntensity).
  // Negative: derived from the sun's height and the temperature on every step.
  float sunMelt = -1.0f;
};

// The accumulated levels, each in [0, 1].
struct Levels {
  float snow = 0.0f;
  float wetness = 0.0f;
  float moss = 0.0f;
  float frost = 0.0f;
  float puddles = 0.0f;
  float rainMemory = 0.0f;  // simulation state: recent rain, which moss follows
};

struct State {
  Conditions conditions;
  double time = 0.0;  // simulated seconds
  Levels levels;
};

// Advances the levels by realSeconds * timeScale simulated seconds under the state's
// conditions (docs/weather-simulation.md). Exact, so step size does not matter; never
// produces NaN or a level outside [0, 1]. Returns "" or why the conditions were
// rejected (a value outside its range, naming it), in which case nothing changed.
std::string step(State& state, double realSeconds, double timeScale = 1.0) noexcept;

// One field of the surfaces' weather block: its name in the reflection's `surface`
// structs and resources (the `weather` uniform block) and its value.
struct BlockField {
  std::string name;
  std::uint32_t components = 1;  // 1..4
  std::array<float, 4> value{};
};
// The values a host writes into the weather block for this state, by field name; the
// reflection gives each field's offset. Time is the state's, in seconds; directions
// are normalised. terrainHeightScale is the terrain's, not the weather's: 0 (flat)
// here. Empty if out of memory.
std::vector<BlockField> weatherBlock(const State& state) noexcept;

// The shared noise texture the surfaces sample (the reflection's weatherNoise
// resource). Upload it once as R8G8B8A8_UNORM with one mip level, and sample it with
// REPEAT addressing, linear filtering and maxLod 0, as the CPU evaluator reads it.
// Empty if out of memory.
struct NoiseTexture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba8;
};
NoiseTexture noiseTexture() noexcept;

// A mesh that keeps snow and rain off what lies under it: positions are three floats
// at i * strideFloats, drawn as an indexed triangle list with `model` (column-major,
// to world, y up). The pointers need only live during the call.
struct Occluder {
  const float* positions = nullptr;
  std::size_t vertexCount = 0;
  std::size_t strideFloats = 3;
  const std::uint32_t* indices = nullptr;
  std::size_t indexCount = 0;
  std::array<float, 16> model{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
};

// The sky-exposure map: per texel, the height of the highest occluder above it (or
// `floor` where there is none), lowered where slanting snow and rain reach under an
// overhang. Row r, column c covers world x = originX + (c + 0.5) / scaleX / resolution,
// z = originZ + (r + 0.5) / scaleZ / resolution. Upload it as R32_SFLOAT, clamped and
// linearly filtered, and write `region` into the weather block's skyExposureRegion.
struct SkyExposureMap {
  std::uint32_t resolution = 0;
  std::array<float, 4> region{};  // origin x, origin z, 1 / size x, 1 / size z
  float floor = 0.0f;
  std::vector<float> heights;     // resolution * resolution, row-major in z
};
// Covers the occluders' xz bounds plus `margin` metres. Returns an empty map (resolution
// 0) and sets `error` when an occluder is malformed (an index out of range, a null
// pointer with a non-zero count) or resolution is outside [16, 4096].
SkyExposureMap buildSkyExposureMap(const std::vector<Occluder>& occluders, std::uint32_t resolution,
                                   float margin, std::string& error) noexcept;

}  // namespace weathergen::weather
