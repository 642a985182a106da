// The weather state's place in the frame block: which FrameState members the weather
// sets. The one conversion between WeatherState and FrameState, used by the renderer,
// eval and render's --weather.
#pragma once
#include "nodes/frame_state.hpp"
#include "weather/weather_state.hpp"

namespace wg {

// Writes the weather's members (conditions, time, levels) into `frame`, leaving the
// others as they are. Directions are copied as given; the caller makes them unit length.
void writeWeather(const WeatherState& weather, FrameState& frame);
// The weather the frame's weather members describe (rainMemory, which the block does not
// carry, is zero).
WeatherState weatherOf(const FrameState& frame);

}  // namespace wg
