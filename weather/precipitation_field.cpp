#include "weather/precipitation_field.hpp"

#include <algorithm>
#include <cmath>

namespace wg {

PrecipitationField precipitationField(const WeatherConditions& c, const PrecipitationSettings& s, const WeatherRates& rates) {
  PrecipitationField field;
  field.radius = s.radius;
  field.snowFallSpeed = s.snowFallSpeed;
  field.rainFallSpeed = s.rainFallSpeed;
  const float amount = std::isfinite(c.precipitation) ? std::clamp(c.precipitation, 0.f, 1.f) : 0.f;
  const float temperature = std::isfinite(c.temperature) ? c.temperature : 0.f;
  field.snowShare = static_cast<float>(snowFraction(temperature, rates));
  field.snowflakes = static_cast<std::uint32_t>(std::lround(double(s.maxSnowflakes) * amount * field.snowShare));
  field.raindrops = static_cast<std::uint32_t>(std::lround(double(s.maxRaindrops) * amount * (1.0 - field.snowShare)));
  const float dx = c.windDirection[0], dz = c.windDirection[1];
  const float length = std::sqrt(dx * dx + dz * dz);
  const float intensity = std::isfinite(c.windIntensity) ? std::clamp(c.windIntensity, 0.f, 1.f) : 0.f;
  if (std::isfinite(length) && length > 1e-6f) {
    const float speed = intensity * static_cast<float>(rates.windSpeedAtFullIntensity) / length;
    field.wind = {dx * speed, dz * speed};
  }
  return field;
}

float precipitationExtinction(const WeatherConditions& c, const WeatherRates& rates) {
  constexpr float kKoschmieder = 3.912f;         // ln(1 / 0.02): the eye's 2 % contrast threshold
  constexpr float kHeavySnowVisibility = 500.f;  // m at precipitation 1 (Rasmussen et al. 1999: 0.3-1 km)
  constexpr float kHeavyRainVisibility = 2000.f;  // m at about 10 mm/h
  constexpr float kBlowingSnow = 3.f;            // wind 1 quadruples snow's extinction
  if (!(c.precipitation > 0.f)) return 0.f;
  const float p = std::min(c.precipitation, 1.f);
  const float snow = static_cast<float>(snowFraction(c.temperature, rates));
  const float wind = std::clamp(c.windIntensity, 0.f, 1.f);
  return p * (snow * kKoschmieder / kHeavySnowVisibility * (1.f + kBlowingSnow * wind) +
              (1.f - snow) * kKoschmieder / kHeavyRainVisibility);
}

}  // namespace wg
