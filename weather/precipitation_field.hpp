// What falls near the viewer (seed 000, ch. 5: "particle effects only run near the
// observer, with max distance of eight meters"): how many snowflakes and raindrops the
// camera-following volume holds, and how fast they move, from the weather conditions.
// The runtime's precipitation pass (host/precipitation_pass.hpp) draws exactly
// these; this part is plain CPU arithmetic so it can be tested without a GPU.
#pragma once
#include <array>
#include <cstdint>

#include "weather/weather_simulation.hpp"
#include "weather/weather_state.hpp"

namespace wg {

struct PrecipitationSettings {
  float radius = 8.f;  // m: the volume's half-size around the eye (seed 000, 5.1.1 and 5.1.2)
  // Particles in the volume at precipitation 1, all of one kind. Sleet splits both
  // by the snow share; less precipitation draws proportionally fewer.
  std::uint32_t maxSnowflakes = 100000;
  std::uint32_t maxRaindrops = 30000;
  float snowFallSpeed = 1.0f;  // m/s: terminal speed of dry snowflakes (~0.5-1.5)
  float rainFallSpeed = 8.0f;  // m/s: of 1-2 mm raindrops (~6-9)
};

struct PrecipitationField {
  std::uint32_t snowflakes = 0;
  std::uint32_t raindrops = 0;
  float snowShare = 0.f;  // of the precipitation, by temperature; 1 all snow, 0 all rain
  // Horizontal wind the particles drift with (m/s, world xz): windDirection made unit
  // length times windIntensity times rates.windSpeedAtFullIntensity.
  std::array<float, 2> wind{0.f, 0.f};
  float snowFallSpeed = 0.f, rainFallSpeed = 0.f;  // m/s, downwards
  float radius = 0.f;

  std::uint32_t total() const { return snowflakes + raindrops; }
};

// Snow at and below rates.snowBelowC, rain at and above rates.rainAboveC, sleet (both,
// in the simulation's own smoothstep share, snowFraction) between: the same boundary
// the weather simulation accumulates snow and wetness with. No precipitation, or a
// non-finite one, draws nothing.
PrecipitationField precipitationField(const WeatherConditions& conditions, const PrecipitationSettings& settings = {},
                                      const WeatherRates& rates = {});

// How falling snow and rain dim the view: their extinction coefficient (1/m), so that
// exp(-extinction * d) of what lies d metres away still shows (Koschmieder: visibility
// 3.912 / extinction). Heavy snow (precipitation 1) sees about 500 m, heavy rain about
// 2 km; wind blows the snow about, and a blizzard (wind 0.8 or more) sees under 200 m,
// below the NWS's 400 m. No precipitation: 0.
float precipitationExtinction(const WeatherConditions& conditions, const WeatherRates& rates = {});

}  // namespace wg
