#include "weather/weather_state.hpp"

#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

namespace wg {
namespace {

// Locale-independent, shortest-ish rendering: "2", "-0.5", "nan", "inf".
std::string number(double x) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << x;
  return out.str();
}

std::string checkRange(std::string_view name, float value, float lo, float hi) {
  if (!std::isfinite(value))
    return std::string(name) + " = " + number(value) + " is not a finite number";
  if (value < lo || value > hi) {
    return std::string(name) + " = " + number(value) + " is outside [" + number(lo) + ", " +
           number(hi) + "]";
  }
  return {};
}

// A value against its frame field's accepted range: one table holds every range.
std::string checkField(std::string_view label, std::string_view field, float value) {
  const FrameField* f = findFrameField(field);
  if (!f) throw std::logic_error("no frame field " + std::string(field));
  return checkRange(label, value, f->min, f->max);
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
       {checkField("temperature", "temperature", c.temperature),
        checkField("precipitation", "precipitation", c.precipitation),
        checkField("windIntensity", "windIntensity", c.windIntensity),
        checkFinite("windDirection", c.windDirection), checkFinite("sunDirection", c.sunDirection),
        checkField("sunIntensity", "sunIntensity", c.sunIntensity), checkField("sunMelt", "sunMelt", c.sunMelt)}) {
    if (!error.empty()) return error;
  }
  return {};
}

std::string validate(const WeatherState& s) {
  if (std::string error = validate(s.conditions); !error.empty()) return error;
  if (!std::isfinite(s.time)) return "time = " + number(s.time) + " is not a finite number";
  for (std::size_t i = 0; i < kWeatherLevels.size(); ++i)
    if (std::string error = checkField(kWeatherLevels[i].name, kWeatherLevels[i].frameField, s.levels.*kLevelMembers[i]);
        !error.empty())
      return error;
  return checkRange("rainMemory", s.levels.rainMemory, 0.0f, 1.0f);  // simulation state, not a frame field
}

}  // namespace wg
