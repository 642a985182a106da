#include "host/snowfield/snow_weather.hpp"

#include <algorithm>

namespace wg::snow {

float snowDepth(const WeatherState& weather, const SnowWeatherSettings& settings) {
  return std::clamp(weather.levels.snow, 0.f, 1.f) * settings.fullCoverDepth;
}

double refillRate(const WeatherState& weather, const SnowWeatherSettings& settings) {
  const WeatherDynamics d = weatherDynamics(weather.conditions, settings.rates);
  double snowfall = d.snow.gain * settings.fullCoverDepth;
  double wind = std::clamp(double(weather.conditions.windIntensity), 0.0, 1.0);
  double lying = weather.levels.snow > 0.f ? 1.0 : 0.0;  // nothing to drift on bare ground
  double drift = settings.driftFillAtFullWind * wind * wind * snowFraction(weather.conditions.temperature, settings.rates) * lying;
  return snowfall + drift;
}

}  // namespace wg::snow
