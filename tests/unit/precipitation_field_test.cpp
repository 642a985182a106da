// What falls near the viewer: snow at and below 0 °C, rain from +1 °C, sleet (both)
// between, in the weather simulation's own share; nothing without precipitation; wind
// in m/s along its direction.
#include "weather/precipitation_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace wg {
namespace {

WeatherConditions conditions(float temperature, float precipitation) {
  WeatherConditions c;
  c.temperature = temperature;
  c.precipitation = precipitation;
  return c;
}

TEST(PrecipitationField, NothingFallsWithoutPrecipitation) {
  for (float t : {-20.f, -1.f, 0.f, 0.5f, 1.f, 15.f}) {
    PrecipitationField f = precipitationField(conditions(t, 0.f));
    EXPECT_EQ(f.snowflakes, 0u) << t;
    EXPECT_EQ(f.raindrops, 0u) << t;
  }
  EXPECT_EQ(precipitationField(conditions(-5.f, std::numeric_limits<float>::quiet_NaN())).total(), 0u);
}

TEST(PrecipitationField, SnowAtAndBelowFreezing) {
  const PrecipitationSettings s;
  for (float t : {-30.f, -4.f, -0.01f, 0.f}) {
    PrecipitationField f = precipitationField(conditions(t, 1.f), s);
    EXPECT_EQ(f.snowflakes, s.maxSnowflakes) << t;
    EXPECT_EQ(f.raindrops, 0u) << t;
    EXPECT_EQ(f.snowShare, 1.f) << t;
  }
}

TEST(PrecipitationField, RainFromTheSimulationsUpperBoundary) {
  const PrecipitationSettings s;
  const WeatherRates rates;
  for (float t : {float(rates.rainAboveC), 6.f, 13.f}) {
    PrecipitationField f = precipitationField(conditions(t, 1.f), s, rates);
    EXPECT_EQ(f.snowflakes, 0u) << t;
    EXPECT_EQ(f.raindrops, s.maxRaindrops) << t;
  }
}

TEST(PrecipitationField, SleetBetweenMixesBothInTheSimulationsShare) {
  const PrecipitationSettings s;
  PrecipitationField f = precipitationField(conditions(0.5f, 1.f), s);
  EXPECT_GT(f.snowflakes, 0u);
  EXPECT_GT(f.raindrops, 0u);
  EXPECT_FLOAT_EQ(f.snowShare, float(snowFraction(0.5)));
  EXPECT_NEAR(f.snowflakes, s.maxSnowflakes * snowFraction(0.5), 1.0);
  // Warmer sleet is wetter.
  PrecipitationField warmer = precipitationField(conditions(0.8f, 1.f), s);
  EXPECT_LT(warmer.snowflakes, f.snowflakes);
  EXPECT_GT(warmer.raindrops, f.raindrops);
}

TEST(PrecipitationField, CountGrowsWithPrecipitation) {
  const PrecipitationSettings s;
  EXPECT_EQ(precipitationField(conditions(-5.f, 0.5f), s).snowflakes, s.maxSnowflakes / 2);
  EXPECT_EQ(precipitationField(conditions(8.f, 0.25f), s).raindrops, s.maxRaindrops / 4);
  EXPECT_EQ(precipitationField(conditions(-5.f, 2.f), s).snowflakes, s.maxSnowflakes);  // clamped
}

TEST(PrecipitationField, WindIsItsDirectionTimesItsSpeed) {
  WeatherConditions c = conditions(-5.f, 1.f);
  c.windDirection = {3.f, -4.f};  // any length
  c.windIntensity = 0.5f;
  const WeatherRates rates;
  PrecipitationField f = precipitationField(c, {}, rates);
  const float speed = 0.5f * float(rates.windSpeedAtFullIntensity);
  EXPECT_NEAR(f.wind[0], 0.6f * speed, 1e-4f);
  EXPECT_NEAR(f.wind[1], -0.8f * speed, 1e-4f);
  c.windDirection = {0.f, 0.f};  // no direction: calm
  EXPECT_EQ(precipitationField(c).wind[0], 0.f);
  EXPECT_EQ(precipitationField(c).wind[1], 0.f);
}

TEST(PrecipitationField, TheVolumeIsTheSeedsEightMetres) {
  PrecipitationField f = precipitationField(conditions(-5.f, 1.f));
  EXPECT_EQ(f.radius, 8.f);
  EXPECT_GT(f.rainFallSpeed, f.snowFallSpeed);
}

// Koschmieder visibility 3.912 / extinction through the falling precipitation.
TEST(PrecipitationExtinction, SnowBlizzardAndRainVisibility) {
  auto visibility = [](float temperature, float precipitation, float wind) {
    WeatherConditions c;
    c.temperature = temperature;
    c.precipitation = precipitation;
    c.windIntensity = wind;
    float extinction = precipitationExtinction(c);
    return extinction > 0.f ? 3.912f / extinction : INFINITY;
  };
  EXPECT_EQ(visibility(-5.f, 0.f, 0.f), INFINITY);  // dry: only the scene's own haze
  EXPECT_NEAR(visibility(-5.f, 1.f, 0.f), 500.f, 1.f);   // heavy snow
  EXPECT_LT(visibility(-5.f, 1.f, 0.8f), 200.f);          // a blizzard: under the NWS's 400 m
  EXPECT_NEAR(visibility(12.f, 1.f, 0.f), 2000.f, 1.f);  // heavy rain
  EXPECT_GT(visibility(-5.f, 0.3f, 0.f), visibility(-5.f, 1.f, 0.f));  // light snow sees farther
}

}  // namespace
}  // namespace wg
