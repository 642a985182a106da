// weathergen::weather (include/weathergen/weather.hpp) through libweathergen_weather.so:
// the same simulation, block fields, noise and sky-exposure map the reference host uses.
#include <weathergen/weather.hpp>
#include <weathergen/weathergen.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "compiler/surface_interface.hpp"
#include "weather/weather_simulation.hpp"

namespace {

namespace ww = weathergen::weather;

TEST(PublicWeatherApi, StepAdvancesAsTheInternalSimulation) {
  ww::State state;
  state.conditions.temperature = -5.f;
  state.conditions.precipitation = 1.f;
  ASSERT_EQ(ww::step(state, 60.0, 60.0), "");  // a real minute is an hour of weather

  wg::WeatherState internal;
  internal.conditions.temperature = -5.f;
  internal.conditions.precipitation = 1.f;
  internal.conditions.sunMelt = wg::sunMeltStrength(internal.conditions);
  wg::advanceWeather(internal, 3600.0);
  EXPECT_DOUBLE_EQ(state.time, 3600.0);
  EXPECT_FLOAT_EQ(state.levels.snow, internal.levels.snow);
  EXPECT_GT(state.levels.snow, 0.5f);  // heavy snow covers 95 % in two hours
}

TEST(PublicWeatherApi, ConditionsOutOfRangeAreRefusedNamingTheFieldAndChangeNothing) {
  ww::State state;
  state.conditions.temperature = 300.f;  // kelvin, not °C
  state.levels.wetness = 0.25f;
  const std::string reason = ww::step(state, 10.0);
  EXPECT_NE(reason.find("temperature"), std::string::npos) << reason;
  EXPECT_EQ(state.levels.wetness, 0.25f);
  EXPECT_EQ(state.time, 0.0);
}

TEST(PublicWeatherApi, BlockFieldsAreTheSurfaceWeatherBlocksWeatherMembers) {
  ww::State state;
  state.conditions.sunDirection = {0.f, 2.f, 0.f};
  state.levels.snow = 0.5f;
  std::set<std::string> names;
  for (const ww::BlockField& field : ww::weatherBlock(state)) {
    names.insert(field.name);
    if (field.name == "snowLevel") {
      EXPECT_EQ(field.value[0], 0.5f);
    }
    if (field.name == "sunDirection") {
      EXPECT_EQ(field.components, 3u);
      EXPECT_FLOAT_EQ(field.value[1], 1.f);  // normalised
    }
  }
  std::set<std::string> surface;
  for (const auto& member : wg::surfaceWeatherBlock().members) surface.insert(member.name);
  // The block also holds the maps' placement (skyExposureRegion, terrainRegion).
  for (const std::string& name : names) EXPECT_TRUE(surface.count(name)) << name;
  EXPECT_EQ(surface.size() - names.size(), 2u);
  EXPECT_TRUE(names.count("snowLevel") && names.count("temperature") && names.count("time"));
}

TEST(PublicWeatherApi, NoiseTextureIsTheCompilersSharedNoise) {
  const ww::NoiseTexture noise = ww::noiseTexture();
  const weathergen::NoiseTexture compiler = weathergen::weatherNoiseTexture();
  ASSERT_GT(noise.width, 0);
  EXPECT_EQ(noise.width, compiler.width);
  EXPECT_EQ(noise.rgba8, compiler.rgba8);
}

// A 2 m x 2 m roof 2 m up over a 10 m x 10 m ground at 0.
struct RoofOverGround {
  std::vector<float> ground{-5, 0, -5, 5, 0, -5, 5, 0, 5, -5, 0, 5};
  std::vector<float> roof{-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
  std::vector<std::uint32_t> quad{0, 1, 2, 0, 2, 3};
  std::vector<ww::Occluder> occluders() const {
    ww::Occluder g{ground.data(), 4, 3, quad.data(), 6};
    ww::Occluder r{roof.data(), 4, 3, quad.data(), 6};
    r.model[13] = 2.f;  // translated up by 2 m
    return {g, r};
  }
};

float heightAt(const ww::SkyExposureMap& map, float x, float z) {
  const auto column = static_cast<std::uint32_t>((x - map.region[0]) * map.region[2] * map.resolution);
  const auto row = static_cast<std::uint32_t>((z - map.region[1]) * map.region[3] * map.resolution);
  return map.heights[std::size_t(row) * map.resolution + column];
}

TEST(PublicWeatherApi, SkyExposureMapHoldsTheHighestOccluderAboveEachTexel) {
  RoofOverGround scene;
  std::string error;
  const ww::SkyExposureMap map = ww::buildSkyExposureMap(scene.occluders(), 256, 1.f, error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(map.resolution, 256u);
  EXPECT_FLOAT_EQ(map.region[0], -6.f);  // bounds grown by the margin
  EXPECT_FLOAT_EQ(map.region[2], 1.f / 12.f);
  EXPECT_FLOAT_EQ(map.floor, -1.f);
  EXPECT_FLOAT_EQ(heightAt(map, 0.f, 0.f), 2.f);     // under the roof's middle
  EXPECT_FLOAT_EQ(heightAt(map, 4.f, 4.f), 0.f);     // open ground
  EXPECT_FLOAT_EQ(heightAt(map, -5.8f, 0.f), -1.f);  // beyond the ground: the floor
  // Slanting snow reaches under the roof's edge: 0.3 m per metre of height, in 0.5 m
  // steps, so texels just inside the edge see the ground.
  EXPECT_FLOAT_EQ(heightAt(map, 0.8f, 0.f), 0.f);
}

TEST(PublicWeatherApi, MalformedOccludersAreErrorsNotCrashes) {
  RoofOverGround scene;
  std::vector<ww::Occluder> occluders = scene.occluders();
  std::vector<std::uint32_t> bad{0, 1, 7};
  occluders[1].indices = bad.data();
  occluders[1].indexCount = 3;
  std::string error;
  EXPECT_EQ(ww::buildSkyExposureMap(occluders, 64, 0.f, error).resolution, 0u);
  EXPECT_NE(error.find("occluder 1"), std::string::npos) << error;
  EXPECT_NE(error.find("7"), std::string::npos) << error;

  occluders = scene.occluders();
  occluders[0].positions = nullptr;
  EXPECT_EQ(ww::buildSkyExposureMap(occluders, 64, 0.f, error).resolution, 0u);
  EXPECT_NE(error.find("null"), std::string::npos) << error;

  EXPECT_EQ(ww::buildSkyExposureMap(scene.occluders(), 1 << 20, 0.f, error).resolution, 0u);
  EXPECT_NE(error.find("resolution"), std::string::npos) << error;
}

TEST(PublicWeatherApi, NoOccludersGiveAnOpenMap) {
  std::string error;
  const ww::SkyExposureMap map = ww::buildSkyExposureMap({}, 16, 1.f, error);
  ASSERT_EQ(error, "");
  EXPECT_TRUE(std::all_of(map.heights.begin(), map.heights.end(), [&](float h) { return h == map.floor; }));
}

}  // namespace
