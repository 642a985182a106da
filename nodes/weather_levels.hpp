// The accumulated weather levels, defined once: each level's name (the simulation's and
// the timelines'), its frame member and its field in the frame table. The weather
// branch of every shader runs while any level is above 0, and the renderer draws the
// unweathered variants while all are 0. weather/weather_state.hpp holds the simulation's
// member of each, in this order.
#pragma once
#include <array>
#include <string_view>

#include "nodes/frame_state.hpp"

namespace wg {

struct WeatherLevel {
  std::string_view name;        // "snow": the simulation's and the timelines' spelling
  std::string_view frameField;  // "snowLevel": its member in nodes/frame_fields.cpp
  float FrameState::*frame;
};

inline constexpr std::array<WeatherLevel, 5> kWeatherLevels = {{
    {"snow", "snowLevel", &FrameState::snowLevel},
    {"wetness", "wetnessLevel", &FrameState::wetnessLevel},
    {"moss", "mossLevel", &FrameState::mossLevel},
    {"frost", "frostLevel", &FrameState::frostLevel},
    {"puddles", "puddleLevel", &FrameState::puddleLevel},
}};

}  // namespace wg
