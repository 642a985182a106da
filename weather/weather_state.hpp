// The one weather state every weather-aware material reads: the conditions an engine
// (or a scripted timeline) sets, the simulated clock, and the levels the simulation
// accumulates from them. Plain data so it can be copied into a uniform buffer as is.
#pragma once
#include <algorithm>
#include <array>
#include <string>

#include "nodes/frame_fields.hpp"
#include "nodes/weather_levels.hpp"

namespace wg {

// Accepted input ranges are the frame table's (nodes/frame_fields.hpp). Outside them an
// input is almost certainly a unit or sign mistake (Fahrenheit, kelvin, a percentage),
// so validate() rejects it rather than letting it saturate silently. The simulation
// still clamps into them.

// What the weather is doing right now; set by the engine or a timeline.
// Coordinates are world space with y up, so the ground plane is xz.
struct WeatherConditions {
  float temperature = 15.0f;  // air temperature, °C, in [-60, 60]
  // Intensity in [0, 1]: 0 dry, 1 heavy (about 10 mm/h of rain). It falls as snow,
  // rain or a mix of both depending on temperature (see WeatherRates).
  float precipitation = 0.0f;
  std::array<float, 2> windDirection{
      1.0f, 0.0f};             // where the wind blows to, xz; any length, zero allowed
  float windIntensity = 0.0f;  // [0, 1]: calm .. blizzard-force wind
  std::array<float, 3> sunDirection{0.0f, 1.0f, 0.0f};  // towards the sun; any length
  float sunIntensity = 1.0f;  // [0, 1]: the light's brightness (radiance = sunColor * sunIntensity)
  // [0, 1]: eq. 3.5's SunIntensity, how strongly direct sun melts snow and dries moss on
  // the faces it shines on. Set it directly, or derive it with sunMeltStrength()
  // (weather_simulation.hpp; simulateTimeline does). The default is what the default
  // conditions derive: a full sun overhead at 15 °C.
  float sunMelt = 1.0f;
};

// Accumulated amounts, each in [0, 1]: 0 none, 1 full cover / fully soaked / frozen over.
struct WeatherLevels {
  float snow = 0.0f;
  float wetness = 0.0f;
  float moss = 0.0f;
  float frost = 0.0f;    // how frozen standing and surface water is
  float puddles = 0.0f;  // standing water in ground depressions
  // Slowly integrated recent rainfall: the memory that lets moss respond to sustained
  // rain but not to a passing shower. Simulation state, not a material input.
  float rainMemory = 0.0f;
};

// Each level of nodes/weather_levels.hpp's table, in its order.
inline constexpr std::array<float WeatherLevels::*, kWeatherLevels.size()> kLevelMembers = {
    &WeatherLevels::snow, &WeatherLevels::wetness, &WeatherLevels::moss, &WeatherLevels::frost, &WeatherLevels::puddles};
static_assert(std::ranges::none_of(kLevelMembers, [](auto member) { return member == nullptr; }),
              "every weather level of nodes/weather_levels.hpp needs its member here");

struct WeatherState {
  WeatherConditions conditions;
  double time = 0.0;  // simulated seconds
  WeatherLevels levels;
};

// "" when every input is in range, otherwise a one-line reason naming the field
// ("precipitation = 2 is outside [0, 1]") for the CLI to turn into a diagnostic.
std::string validate(const WeatherConditions& conditions);
// The conditions, plus a finite time and every level finite and in [0, 1].
std::string validate(const WeatherState& state);

}  // namespace wg
