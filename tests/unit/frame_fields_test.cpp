// The frame table (nodes/frame_fields.hpp) is the one definition of the frame block:
// the std140 block, FrameState and the weather conversion must all agree with it.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "compiler/material_interface.hpp"
#include "nodes/frame_fields.hpp"
#include "weather/frame_weather.hpp"

namespace wg {
namespace {

TEST(FrameFields, TheBlockHasTheTableMembersInOrder) {
  const UniformBlock& block = frameBlock();
  ASSERT_EQ(block.members.size(), frameFields().size());
  for (std::size_t i = 0; i < block.members.size(); ++i) {
    EXPECT_EQ(block.members[i].name, frameFields()[i].name);
    EXPECT_EQ(interfaceTypeName(block.members[i].type), glslTypeName(frameFields()[i].type));
  }
}

TEST(FrameFields, EachFieldIsItsOwnFrameStateMember) {
  FrameState frame;
  const auto* begin = reinterpret_cast<const std::byte*>(&frame);
  std::set<std::string_view> names;
  std::set<const std::byte*> places;
  for (const FrameField& field : frameFields()) {
    EXPECT_TRUE(names.insert(field.name).second) << field.name;
    auto bytes = fieldBytes(field, frame);
    EXPECT_TRUE(places.insert(bytes.data()).second) << field.name;
    EXPECT_GE(bytes.data(), begin) << field.name;
    EXPECT_LE(bytes.data() + bytes.size(), begin + sizeof frame) << field.name;
    EXPECT_EQ(findFrameField(field.name), &field);
  }
}

TEST(FrameFields, WeatherSurvivesTheFrameBlock) {
  WeatherState weather;
  weather.conditions = {-5.f, 0.5f, {0.f, 1.f}, 0.25f, {0.f, 0.f, 1.f}, 0.75f};
  weather.time = 120.0;
  weather.levels = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.f};
  FrameState frame;
  writeWeather(weather, frame);
  const WeatherState back = weatherOf(frame);
  EXPECT_EQ(back.conditions.temperature, weather.conditions.temperature);
  EXPECT_EQ(back.conditions.precipitation, weather.conditions.precipitation);
  EXPECT_EQ(back.conditions.windDirection, weather.conditions.windDirection);
  EXPECT_EQ(back.conditions.windIntensity, weather.conditions.windIntensity);
  EXPECT_EQ(back.conditions.sunDirection, weather.conditions.sunDirection);
  EXPECT_EQ(back.conditions.sunIntensity, weather.conditions.sunIntensity);
  EXPECT_EQ(back.time, weather.time);
  EXPECT_EQ(back.levels.snow, weather.levels.snow);
  EXPECT_EQ(back.levels.wetness, weather.levels.wetness);
  EXPECT_EQ(back.levels.moss, weather.levels.moss);
  EXPECT_EQ(back.levels.frost, weather.levels.frost);
  EXPECT_EQ(back.levels.puddles, weather.levels.puddles);
}

}  // namespace
}  // namespace wg
