#include "weather/frame_weather.hpp"

#include <type_traits>

namespace wg {

namespace {

// Each weather member with the frame member that carries it: the one list both
// conversions walk, so they cannot drift apart.
template <class Weather, class Frame, class Visit>
void forEachWeatherMember(Weather& weather, Frame& frame, Visit visit) {
  visit(weather.conditions.temperature, frame.temperature);
  visit(weather.conditions.precipitation, frame.precipitation);
  visit(weather.conditions.windDirection, frame.windDirection);
  visit(weather.conditions.windIntensity, frame.windIntensity);
  visit(weather.conditions.sunDirection, frame.sunDirection);
  visit(weather.conditions.sunIntensity, frame.sunIntensity);
  visit(weather.conditions.sunMelt, frame.sunMelt);
  visit(weather.time, frame.time);  // double in the simulation, float in the block
  for (std::size_t i = 0; i < kWeatherLevels.size(); ++i) visit(weather.levels.*kLevelMembers[i], frame.*kWeatherLevels[i].frame);
}

}  // namespace

void writeWeather(const WeatherState& weather, FrameState& frame) {
  forEachWeatherMember(weather, frame, [](const auto& from, auto& to) {
    to = static_cast<std::remove_reference_t<decltype(to)>>(from);
  });
}

WeatherState weatherOf(const FrameState& frame) {
  WeatherState weather;
  forEachWeatherMember(weather, frame, [](auto& to, const auto& from) { to = from; });
  return weather;
}

}  // namespace wg
