// What the weather state means for the snow layer: how deep the snow lies and how fast
// fresh snowfall and wind refill prints (the seed names refill as missing,
// 5.1.2: "some snow would have fallen or ... the wind had filled the prints").
#pragma once
#include "weather/weather_simulation.hpp"
#include "weather/weather_state.hpp"

namespace wg::snow {

struct SnowWeatherSettings {
  // Depth of a full cover (snow level 1). docs/weather-simulation.md takes ~10 cm of
  // fresh snow as the depth that hides the ground; scenes may ask for deeper drifts.
  float fullCoverDepth = 0.10f;
  // Drift infill at blizzard-force wind (intensity 1), metres per second: 5 cm per
  // hour. Chosen, not measured: a print a few centimetres deep fills in about an hour
  // of blizzard. Scaled by intensity² (transport grows steeply with wind speed) and by
  // the snow fraction (wet snow does not drift).
  double driftFillAtFullWind = 0.05 / 3600.0;
  WeatherRates rates;
};

// Local snow depth (metres) under this weather.
float snowDepth(const WeatherState& weather, const SnowWeatherSettings& settings = {});

// Refill rate (metres per second) of print depth and rim height.
// Fresh snow: the rate the weather simulation raises the snow level from bare ground
// (its gain term, per second), times the depth of a full cover. Wind: see above.
double refillRate(const WeatherState& weather, const SnowWeatherSettings& settings = {});

}  // namespace wg::snow
