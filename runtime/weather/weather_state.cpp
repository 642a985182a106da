#include "runtime/weather/weather_state.hpp"

#include <cmath>
#include <locale>
#include <sstream>

namespace wg {
namespace {

// Locale-independent, shortest-ish rendering: "2", "-0.5", "nan", "inf".
std::string number(double x) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << x;
  return out.str();
}

std::string checkRange(const char* name, float value, float lo, float hi) {
  if (!std::isfinite(value))
    return std::string(name) + " = " + number(value) + " is not a finite number";
  if (value < lo || value > hi) {
    return std::string(name) + " = " + number(value) + " is outside [" + number(lo) + ", " +
           number(hi) + "]";
  }
  return {};
}

template <std::size_t N>
std::string checkFinite(const char* name, const std::array<float, N>& v) {
  for (std::size_t i = 0; i < N; ++i) {
    if (!std::isfinite(v[i])) {
      return std::string(name) + "[" + std::to_string(i) + "] = " + number(v[i]) +
             " is not a finite number";
    }
  }
  return {};
}

}  // namespace

std::string validate(const WeatherConditions& c) {
  for (std::string error :
       {checkRange("temperature", c.temperature, kMinTemperatureC, kMaxTemperatureC),
        checkRange("precipitation", c.precipitation, 0.0f, 1.0f),
        checkRange("windIntensity", c.windIntensity, 0.0f, 1.0f),
        checkFinite("windDirection", c.windDirection), checkFinite("sunDirection", c.sunDirection),
        checkRange("sunIntensity", c.sunIntensity, 0.0f, 1.0f),
        checkRange("sunMelt", c.sunMelt, 0.0f, 1.0f)}) {
    if (!error.empty()) return error;
  }
  return {};
}

std::string validate(const WeatherState& s) {
  if (std::string error = validate(s.conditions); !error.empty()) return error;
  if (!std::isfinite(s.time)) return "time = " + number(s.time) + " is not a finite number";
  const WeatherLevels& l = s.levels;
  for (std::string error :
       {checkRange("snow", l.snow, 0.0f, 1.0f), checkRange("wetness", l.wetness, 0.0f, 1.0f),
        checkRange("moss", l.moss, 0.0f, 1.0f), checkRange("frost", l.frost, 0.0f, 1.0f),
        checkRange("puddles", l.puddles, 0.0f, 1.0f),
        checkRange("rainMemory", l.rainMemory, 0.0f, 1.0f)}) {
    if (!error.empty()) return error;
  }
  return {};
}

}  // namespace wg
