// Snow depth and refill rate from the weather state.
#include "host/snowfield/snow_weather.hpp"

#include <gtest/gtest.h>

namespace wg::snow {
namespace {

WeatherState weather(float temperature, float precipitation, float wind, float snowLevel) {
  WeatherState s;
  s.conditions.temperature = temperature;
  s.conditions.precipitation = precipitation;
  s.conditions.windIntensity = wind;
  s.levels.snow = snowLevel;
  return s;
}

TEST(SnowWeather, DepthFollowsTheSnowLevel) {
  EXPECT_FLOAT_EQ(snowDepth(weather(-5.f, 0.f, 0.f, 0.f)), 0.f);
  EXPECT_FLOAT_EQ(snowDepth(weather(-5.f, 0.f, 0.f, 0.5f)), 0.05f);
  SnowWeatherSettings deep;
  deep.fullCoverDepth = 0.4f;
  EXPECT_FLOAT_EQ(snowDepth(weather(-5.f, 0.f, 0.f, 1.f), deep), 0.4f);
}

TEST(SnowWeather, CalmDryWeatherRefillsNothing) {
  EXPECT_EQ(refillRate(weather(-5.f, 0.f, 0.f, 1.f)), 0.0);
  EXPECT_EQ(refillRate(weather(10.f, 1.f, 0.f, 1.f)), 0.0);  // rain is no snowfall
}

TEST(SnowWeather, SnowfallRefillsAtTheSimulationsAccumulationRate) {
  SnowWeatherSettings s;
  WeatherState w = weather(-5.f, 1.f, 0.f, 0.5f);
  double expected = weatherDynamics(w.conditions, s.rates).snow.gain * s.fullCoverDepth;
  EXPECT_DOUBLE_EQ(refillRate(w, s), expected);
  // Heavy snowfall at -5 °C: a few centimetres per hour (docs/weather-simulation.md).
  EXPECT_GT(expected * 3600.0, 0.02);
  EXPECT_LT(expected * 3600.0, 0.2);
  EXPECT_LT(refillRate(weather(-5.f, 0.3f, 0.f, 0.5f), s), expected);
}

TEST(SnowWeather, WindDriftsDrySnowIntoPrints) {
  SnowWeatherSettings s;
  EXPECT_DOUBLE_EQ(refillRate(weather(-5.f, 0.f, 1.f, 0.5f), s), s.driftFillAtFullWind);
  EXPECT_DOUBLE_EQ(refillRate(weather(-5.f, 0.f, 0.5f, 0.5f), s), 0.25 * s.driftFillAtFullWind);
  EXPECT_EQ(refillRate(weather(-5.f, 0.f, 1.f, 0.f), s), 0.0);  // bare ground
  EXPECT_EQ(refillRate(weather(5.f, 0.f, 1.f, 0.5f), s), 0.0);  // wet snow stays put
}

}  // namespace
}  // namespace wg::snow
