// Weather state, simulation and timeline: every rule of docs/weather-simulation.md, the
// continuity guarantees, time scaling and degenerate inputs.
#include "weather/weather_simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "weather/weather_state.hpp"
#include "weather/weather_timeline.hpp"

namespace wg {
namespace {

constexpr double kMinute = 60.0;
constexpr double kHour = 3600.0;
constexpr double kDay = 86400.0;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

WeatherState weather(float temperature, float precipitation, float windIntensity = 0.0f) {
  WeatherState s;
  s.conditions.temperature = temperature;
  s.conditions.precipitation = precipitation;
  s.conditions.windIntensity = windIntensity;
  return s;
}

WeatherState withLevels(WeatherState s, const WeatherLevels& levels) {
  s.levels = levels;
  return s;
}

// Holds the state's conditions for `seconds` in frame-sized steps, calling `each` after
// every step; frames of a minute are what an accelerated game clock typically produces.
void run(WeatherState& s, double seconds, double step = kMinute,
         const std::function<void(const WeatherState&)>& each = {}) {
  for (double done = 0.0; done < seconds; done += step) {
    advanceWeather(s, std::min(step, seconds - done));
    if (each) each(s);
  }
}

std::vector<float> levelsOf(const WeatherState& s) {
  const WeatherLevels& l = s.levels;
  return {l.snow, l.wetness, l.moss, l.frost, l.puddles, l.rainMemory};
}

std::vector<const LevelDynamics*> dynamicsOf(const WeatherDynamics& d) {
  return {&d.snow, &d.wetness, &d.moss, &d.frost, &d.puddles, &d.rainMemory};
}

const char* const kLevelNames[] = {"snow", "wetness", "moss", "frost", "puddles", "rainMemory"};

void expectFiniteInRange(const WeatherState& s) {
  const std::vector<float> levels = levelsOf(s);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    EXPECT_TRUE(std::isfinite(levels[i])) << kLevelNames[i];
    EXPECT_GE(levels[i], 0.0f) << kLevelNames[i];
    EXPECT_LE(levels[i], 1.0f) << kLevelNames[i];
  }
  EXPECT_TRUE(std::isfinite(s.time));
}

// ---------------------------------------------------------------------------------
// Validation

TEST(WeatherValidateTest, DefaultsAreValid) {
  EXPECT_EQ(validate(WeatherConditions{}), "");
  EXPECT_EQ(validate(WeatherState{}), "");
}

TEST(WeatherValidateTest, TemperatureLimitsAreInclusive) {
  for (float t : {-60.0f, 60.0f, 0.0f}) {
    EXPECT_EQ(validate(weather(t, 0.5f).conditions), "") << t;
  }
  for (float t : {-60.5f, 60.5f, -273.15f, 300.0f}) {
    const std::string error = validate(weather(t, 0.5f).conditions);
    EXPECT_NE(error.find("temperature"), std::string::npos) << t << ": " << error;
  }
}

TEST(WeatherValidateTest, RejectsPrecipitationOutsideUnitRange) {
  EXPECT_EQ(validate(weather(5.0f, 0.0f).conditions), "");
  EXPECT_EQ(validate(weather(5.0f, 1.0f).conditions), "");
  for (float p : {-1.0f, 2.0f, -0.001f, 1.001f}) {
    const std::string error = validate(weather(5.0f, p).conditions);
    EXPECT_NE(error.find("precipitation"), std::string::npos) << p << ": " << error;
    EXPECT_NE(error.find("[0, 1]"), std::string::npos) << error;
  }
}

TEST(WeatherValidateTest, RejectsNonFiniteValues) {
  WeatherConditions c;
  c.temperature = kNaN;
  EXPECT_NE(validate(c).find("temperature"), std::string::npos);
  c = {};
  c.precipitation = kInf;
  EXPECT_NE(validate(c).find("precipitation"), std::string::npos);
  c = {};
  c.windDirection = {0.0f, kNaN};
  EXPECT_NE(validate(c).find("windDirection[1]"), std::string::npos);
  c = {};
  c.sunDirection = {kInf, 1.0f, 0.0f};
  EXPECT_NE(validate(c).find("sunDirection[0]"), std::string::npos);
  c = {};
  c.windIntensity = kNaN;
  EXPECT_NE(validate(c).find("windIntensity"), std::string::npos);
}

// The accepted ranges are the frame table's: each input passes at its field's bounds
// and fails just outside them, so a range changed in nodes/frame_fields.cpp changes both.
TEST(WeatherValidateTest, RangesComeFromTheFrameTable) {
  struct Input {
    const char* field;
    float* value;
  };
  WeatherState s;
  const Input inputs[] = {{"temperature", &s.conditions.temperature}, {"precipitation", &s.conditions.precipitation},
                          {"windIntensity", &s.conditions.windIntensity}, {"sunIntensity", &s.conditions.sunIntensity},
                          {"sunMelt", &s.conditions.sunMelt}, {"snowLevel", &s.levels.snow},
                          {"wetnessLevel", &s.levels.wetness}, {"mossLevel", &s.levels.moss},
                          {"frostLevel", &s.levels.frost}, {"puddleLevel", &s.levels.puddles}};
  for (const auto& input : inputs) {
    const FrameField* field = findFrameField(input.field);
    ASSERT_NE(field, nullptr) << input.field;
    const float saved = *input.value;
    for (float ok : {field->min, field->max}) {
      *input.value = ok;
      EXPECT_EQ(validate(s), "") << input.field << " = " << ok;
    }
    for (float bad : {field->min - 0.5f, field->max + 0.5f}) {
      *input.value = bad;
      EXPECT_NE(validate(s), "") << input.field << " = " << bad;
    }
    *input.value = saved;
  }
}

TEST(WeatherValidateTest, AcceptsZeroWind) {
  WeatherConditions c;
  c.windDirection = {0.0f, 0.0f};
  c.windIntensity = 0.0f;
  EXPECT_EQ(validate(c), "");
}

TEST(WeatherValidateTest, StateChecksLevelsAndTime) {
  WeatherState s;
  s.levels.snow = 1.5f;
  EXPECT_NE(validate(s).find("snow"), std::string::npos);
  s = {};
  s.levels.moss = kNaN;
  EXPECT_NE(validate(s).find("moss"), std::string::npos);
  s = {};
  s.time = std::numeric_limits<double>::infinity();
  EXPECT_NE(validate(s).find("time"), std::string::npos);
}

// ---------------------------------------------------------------------------------
// The rules, one at a time

TEST(WeatherRulesTest, SnowAccumulatesOnlyAtOrBelowZeroWithPrecipitation) {
  for (float t : {1.0f, 5.0f, 20.0f}) {
    WeatherState s = weather(t, 1.0f);
    run(s, 6 * kHour);
    EXPECT_EQ(s.levels.snow, 0.0f) << "snow at " << t << " °C";
  }
  WeatherState dryCold = weather(-5.0f, 0.0f);
  run(dryCold, 6 * kHour);
  EXPECT_EQ(dryCold.levels.snow, 0.0f) << "snow without precipitation";

  for (float t : {-0.5f, -2.0f, -10.0f}) {
    WeatherState s = weather(t, 0.5f);
    run(s, 6 * kHour);
    EXPECT_GT(s.levels.snow, 0.3f) << "no snow at " << t << " °C";
  }
  // Seed 3.1: at exactly 0 °C precipitation is snow. In the sleet band above it, wet
  // snow still settles, more slowly and melting ("it is possible to see snow in
  // temperatures above zero degrees but melting takes place", 5.1.1).
  WeatherState freezing = weather(0.0f, 1.0f);
  run(freezing, 6 * kHour);
  EXPECT_GT(freezing.levels.snow, 0.3f);
  WeatherState sleet = weather(0.5f, 1.0f);
  run(sleet, 6 * kHour);
  EXPECT_LT(sleet.levels.snow, freezing.levels.snow);
}

TEST(WeatherRulesTest, ColderSnowfallAccumulatesFaster) {
  float previous = 0.0f;
  for (float t : {-1.5f, -3.0f, -6.0f, -12.0f, -25.0f}) {
    WeatherState s = weather(t, 0.5f);
    run(s, kHour);
    EXPECT_GT(s.levels.snow, previous) << t << " °C accumulates no faster than warmer snowfall";
    previous = s.levels.snow;
  }
}

TEST(WeatherRulesTest, WarmerWeatherMeltsSnowFaster) {
  WeatherLevels covered;
  covered.snow = 1.0f;
  WeatherState frozen = withLevels(weather(-5.0f, 0.0f), covered);
  run(frozen, 12 * kHour);
  EXPECT_EQ(frozen.levels.snow, 1.0f) << "snow melted below freezing";

  float previous = 1.0f;
  for (float t : {1.0f, 3.0f, 6.0f, 12.0f, 25.0f}) {
    WeatherState s = withLevels(weather(t, 0.0f), covered);
    run(s, 6 * kHour);
    EXPECT_LT(s.levels.snow, previous) << t << " °C melts no faster than cooler air";
    previous = s.levels.snow;
  }
}

TEST(WeatherRulesTest, RainSpeedsUpMelting) {
  WeatherLevels covered;
  covered.snow = 1.0f;
  WeatherState dry = withLevels(weather(3.0f, 0.0f), covered);
  WeatherState rainy = withLevels(weather(3.0f, 0.8f), covered);
  run(dry, 6 * kHour);
  run(rainy, 6 * kHour);
  // Effective melt rates (the cover decays exponentially): heavy rain brings about as
  // much melting heat as the air does, so expect well above dry-air melting.
  const double dryRate = -std::log(dry.levels.snow);
  const double rainyRate = -std::log(rainy.levels.snow);
  EXPECT_GT(dryRate, 0.0);
  EXPECT_GT(rainyRate, 1.4 * dryRate) << "rain on snow should add its heat to the melt";
}

TEST(WeatherRulesTest, WetnessRisesWithRainAndEvaporatesAfter) {
  WeatherState s = weather(20.0f, 1.0f);
  run(s, 30 * kMinute);
  EXPECT_GT(s.levels.wetness, 0.95f);

  s.conditions.precipitation = 0.0f;
  float previous = s.levels.wetness;
  run(s, 8 * kHour, kMinute, [&](const WeatherState& now) {
    EXPECT_LE(now.levels.wetness, previous) << "wetness rose with no rain and no snow";
    previous = now.levels.wetness;
  });
  EXPECT_LT(s.levels.wetness, 0.05f);

  WeatherState snowing = weather(-5.0f, 1.0f);
  run(snowing, 2 * kHour);
  EXPECT_EQ(snowing.levels.wetness, 0.0f) << "dry snowfall wetted the ground";
}

TEST(WeatherRulesTest, WarmerAndWindierAirDriesFaster) {
  WeatherLevels soaked;
  soaked.wetness = 1.0f;
  WeatherState cool = withLevels(weather(5.0f, 0.0f), soaked);
  WeatherState warm = withLevels(weather(25.0f, 0.0f), soaked);
  WeatherState windy = withLevels(weather(5.0f, 0.0f, 1.0f), soaked);
  for (WeatherState* s : {&cool, &warm, &windy}) run(*s, kHour);
  EXPECT_LT(warm.levels.wetness, cool.levels.wetness);
  EXPECT_LT(windy.levels.wetness, cool.levels.wetness);
}

TEST(WeatherRulesTest, MeltingSnowWetsTheGround) {
  WeatherLevels covered;
  covered.snow = 1.0f;
  WeatherState thaw = withLevels(weather(8.0f, 0.0f), covered);
  run(thaw, 3 * kHour);
  EXPECT_GT(thaw.levels.wetness, 0.3f);

  WeatherState bare = weather(8.0f, 0.0f);
  run(bare, 3 * kHour);
  EXPECT_EQ(bare.levels.wetness, 0.0f) << "warm dry air wetted bare ground";
}

TEST(WeatherRulesTest, MossGrowsAfterSustainedRainAndFades) {
  // A passing shower barely registers...
  WeatherState shower = weather(12.0f, 0.8f);
  float showerPeak = 0.0f;
  auto trackPeak = [&](const WeatherState& s) { showerPeak = std::max(showerPeak, s.levels.moss); };
  run(shower, 30 * kMinute, kMinute, trackPeak);
  shower.conditions.precipitation = 0.0f;
  run(shower, 12 * kHour, kMinute, trackPeak);
  EXPECT_LT(showerPeak, 0.05f);

  // ...sustained rain grows it, with a lag...
  WeatherState s = weather(12.0f, 0.8f);
  run(s, kHour);
  EXPECT_LT(s.levels.moss, 0.05f) << "moss should lag the rain";
  run(s, 23 * kHour);
  EXPECT_GT(s.levels.moss, 0.5f);

  // ...and it fades once the rain stops.
  s.conditions = weather(18.0f, 0.0f).conditions;
  float previous = s.levels.moss;
  run(s, 6 * kHour);
  EXPECT_LT(s.levels.moss, previous);
  run(s, 3 * kDay);
  EXPECT_LT(s.levels.moss, 0.02f);
}

TEST(WeatherRulesTest, FrostFormsBelowZeroWithoutPrecipitationAndThaws) {
  WeatherState s = weather(-5.0f, 0.0f);
  run(s, 12 * kHour);
  EXPECT_GT(s.levels.frost, 0.9f);

  WeatherState colder = weather(-15.0f, 0.0f);
  WeatherState milder = weather(-2.0f, 0.0f);
  run(colder, kHour);
  run(milder, kHour);
  EXPECT_GT(colder.levels.frost, milder.levels.frost) << "colder air should freeze faster";

  s.conditions.temperature = 5.0f;
  run(s, 2 * kDay);
  EXPECT_LT(s.levels.frost, 0.05f);

  WeatherState mild = weather(5.0f, 0.0f);
  run(mild, 12 * kHour);
  EXPECT_EQ(mild.levels.frost, 0.0f) << "frost above freezing";
}

TEST(WeatherRulesTest, PuddlesFillWithSustainedRainAndDrain) {
  WeatherState s = weather(12.0f, 1.0f);
  run(s, 30 * kMinute);
  const float afterShower = s.levels.puddles;
  EXPECT_LT(afterShower, 0.5f) << "a shower should not fill the puddles";
  run(s, 150 * kMinute);
  EXPECT_GT(s.levels.puddles, 0.8f);

  s.conditions.precipitation = 0.0f;
  run(s, 3 * kDay);
  EXPECT_LT(s.levels.puddles, 0.1f);

  WeatherState snowing = weather(-5.0f, 1.0f);
  run(snowing, 3 * kHour);
  EXPECT_EQ(snowing.levels.puddles, 0.0f) << "snowfall filled puddles";
}

// ---------------------------------------------------------------------------------
// A scripted season through the timeline parser and simulateTimeline.

constexpr const char* kSeasonJson = R"({"keyframes": [
  {"time":      0, "temperature":  15, "precipitation": 0,   "wind": [1, 0], "windIntensity": 0.1, "label": "sunny"},
  {"time":  21600, "temperature":  15, "precipitation": 0,   "wind": [1, 0], "windIntensity": 0.1},
  {"time":  23400, "temperature":  -3, "precipitation": 0.5, "wind": [1, 0], "windIntensity": 0.2, "label": "snowfall"},
  {"time":  37800, "temperature":  -3, "precipitation": 0.5, "wind": [1, 0], "windIntensity": 0.2},
  {"time":  39600, "temperature": -12, "precipitation": 1,   "wind": [0, 1], "windIntensity": 1,   "label": "blizzard"},
  {"time":  50400, "temperature": -12, "precipitation": 1,   "wind": [0, 1], "windIntensity": 1},
  {"time":  52200, "temperature":   6, "precipitation": 0.8, "wind": [1, 1], "windIntensity": 0.3, "label": "thaw with rain"},
  {"time": 138600, "temperature":   8, "precipitation": 0.8, "wind": [1, 1], "windIntensity": 0.3, "label": "moss"},
  {"time": 140400, "temperature":  18, "precipitation": 0,   "wind": [1, 0], "windIntensity": 0.2, "label": "dry"},
  {"time": 313200, "temperature":  18, "precipitation": 0,   "wind": [1, 0], "windIntensity": 0.2},
  {"time": 315000, "temperature":  -8, "precipitation": 0,   "wind": [1, 0], "windIntensity": 0.1, "label": "freeze"},
  {"time": 358200, "temperature":  -8, "precipitation": 0,   "wind": [1, 0], "windIntensity": 0.1}
]})";

TEST(WeatherScenarioTest, SunnySnowfallBlizzardThawMossFreeze) {
  std::string error;
  const std::optional<WeatherTimeline> timeline =
      parseWeatherTimeline(nlohmann::json::parse(kSeasonJson), error);
  ASSERT_TRUE(timeline) << error;
  const double step = kMinute;
  const std::vector<WeatherState> history =
      simulateTimeline(*timeline, WeatherState{}, step, timeline->duration());
  ASSERT_EQ(history.size(), static_cast<std::size_t>(timeline->duration() / step) + 1);

  auto at = [&](double t) -> const WeatherLevels& {
    return history.at(static_cast<std::size_t>(std::lround(t / step))).levels;
  };
  auto keyTime = [&](std::size_t i) { return timeline->keys.at(i).time; };

  // Sunny: nothing accumulates.
  for (float level : levelsOf(history[static_cast<std::size_t>(keyTime(1) / step)]))
    EXPECT_EQ(level, 0.0f);

  // Snowfall: snow builds steadily; frost forms at -3 °C. The front arrives as rain
  // while it is still above freezing, but the snow itself wets nothing.
  EXPECT_GT(at(keyTime(3)).snow, 0.5f);
  EXPECT_GT(at(keyTime(3)).snow, at(keyTime(2) + kHour).snow);
  EXPECT_GT(at(keyTime(2)).wetness, 0.0f);
  EXPECT_LE(at(keyTime(3)).wetness, at(keyTime(2)).wetness);
  EXPECT_GT(at(keyTime(3)).frost, 0.3f);

  // Blizzard: tops the cover up.
  EXPECT_GT(at(keyTime(5)).snow, 0.95f);
  EXPECT_GT(at(keyTime(5)).snow, at(keyTime(3)).snow);

  // Thaw with rain: snow and ice go, everything gets wet, puddles fill.
  const WeatherLevels& thawed = at(keyTime(6) + 24 * kHour);
  EXPECT_LT(thawed.snow, 0.1f);
  EXPECT_LT(thawed.frost, 0.1f);
  EXPECT_GT(thawed.wetness, 0.9f);
  EXPECT_GT(thawed.puddles, 0.8f);

  // Sustained rain: moss.
  EXPECT_GT(at(keyTime(7)).moss, 0.5f);
  EXPECT_GT(at(keyTime(7)).moss, at(keyTime(6) + 6 * kHour).moss);

  // Dry spell: the water evaporates and the moss fades.
  const WeatherLevels& dried = at(keyTime(9));
  EXPECT_LT(dried.wetness, 0.05f);
  EXPECT_LT(dried.moss, 0.05f);
  EXPECT_LT(dried.puddles, 0.1f);

  // Freeze without precipitation: frost, no snow.
  const WeatherLevels& frozen = at(keyTime(11));
  EXPECT_GT(frozen.frost, 0.9f);
  EXPECT_LE(frozen.snow, at(keyTime(9)).snow) << "snow without precipitation";
  EXPECT_LT(frozen.snow, 1e-6f);

  // No pops anywhere along the way: each step moves a level by at most its rate * dt.
  for (std::size_t i = 1; i < history.size(); ++i) {
    const double h = history[i].time - history[i - 1].time;
    const WeatherDynamics d =
        weatherDynamics(timeline->at(0.5 * (history[i].time + history[i - 1].time)));
    const std::vector<float> before = levelsOf(history[i - 1]);
    const std::vector<float> after = levelsOf(history[i]);
    const std::vector<const LevelDynamics*> rates = dynamicsOf(d);
    for (std::size_t k = 0; k < before.size(); ++k) {
      ASSERT_LE(std::abs(after[k] - before[k]), rates[k]->maxRate() * h + 1e-6)
          << kLevelNames[k] << " popped at t = " << history[i].time;
    }
  }
}

// ---------------------------------------------------------------------------------
// Continuity

// Deterministic pseudo-random conditions and levels covering the whole valid range.
struct RandomWeather {
  std::mt19937 rng{20240611u};
  float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
  WeatherState next() {
    WeatherState s = weather(uniform(-30.0f, 30.0f), uniform(0.0f, 1.0f), uniform(0.0f, 1.0f));
    s.levels = {uniform(0, 1), uniform(0, 1), uniform(0, 1),
                uniform(0, 1), uniform(0, 1), uniform(0, 1)};
    return s;
  }
};

TEST(WeatherContinuityTest, PerStepChangeIsBoundedByRateTimesDt) {
  RandomWeather random;
  for (int i = 0; i < 300; ++i) {
    const WeatherState start = random.next();
    const WeatherDynamics d = weatherDynamics(start.conditions);
    const std::vector<const LevelDynamics*> rates = dynamicsOf(d);
    for (double h : {1.0, kMinute, kHour, kDay}) {
      WeatherState s = start;
      advanceWeather(s, h);
      const std::vector<float> before = levelsOf(start);
      const std::vector<float> after = levelsOf(s);
      for (std::size_t k = 0; k < before.size(); ++k) {
        EXPECT_LE(std::abs(after[k] - before[k]), rates[k]->maxRate() * h + 1e-6)
            << kLevelNames[k] << " h = " << h << " T = " << start.conditions.temperature;
      }
    }
  }
}

TEST(WeatherContinuityTest, OneStepEqualsManySubSteps) {
  RandomWeather random;
  for (int i = 0; i < 200; ++i) {
    const WeatherState start = random.next();
    for (double total : {kMinute, kHour, 6 * kHour}) {
      WeatherState once = start;
      advanceWeather(once, total);
      for (int parts : {2, 7, 100}) {
        WeatherState split = start;
        for (int p = 0; p < parts; ++p) advanceWeather(split, total / parts);
        const std::vector<float> a = levelsOf(once);
        const std::vector<float> b = levelsOf(split);
        for (std::size_t k = 0; k < a.size(); ++k) {
          EXPECT_NEAR(a[k], b[k], 2e-6 * parts)
              << kLevelNames[k] << " total " << total << " in " << parts;
        }
        EXPECT_NEAR(once.time, split.time, 1e-6);
      }
      // Uneven steps, as a variable frame rate produces.
      WeatherState uneven = start;
      for (double fraction : {0.5, 0.03, 0.27, 0.2}) advanceWeather(uneven, total * fraction);
      const std::vector<float> a = levelsOf(once);
      const std::vector<float> b = levelsOf(uneven);
      for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-5) << kLevelNames[k];
    }
  }
}

TEST(WeatherContinuityTest, NoJumpAcrossTheFreezingPoint) {
  WeatherLevels mid{0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
  auto difference = [&](float delta) {
    WeatherState below = withLevels(weather(-delta, 0.5f), mid);
    WeatherState above = withLevels(weather(delta, 0.5f), mid);
    advanceWeather(below, kHour);
    advanceWeather(above, kHour);
    const std::vector<float> a = levelsOf(below);
    const std::vector<float> b = levelsOf(above);
    float largest = 0.0f;
    for (std::size_t k = 0; k < a.size(); ++k) largest = std::max(largest, std::abs(a[k] - b[k]));
    return largest;
  };
  const float atOneDegree = difference(1.0f);
  const float atHundredth = difference(0.01f);
  const float atThousandth = difference(0.001f);
  EXPECT_GT(atOneDegree, 0.02f) << "the test would not see a jump";
  // Right above 0 °C meltwater starts to wet the snow-covered fraction: over this hour
  // wetness changes by about 0.3 per °C (0.0032 at +-0.01 °C), a slope, not a jump.
  EXPECT_LT(atHundredth, 5e-3f);
  // Continuity, not just smallness: the gap shrinks with the temperature difference
  // instead of levelling off at the size of a step.
  EXPECT_LT(atThousandth, 0.2f * atHundredth);
}

TEST(WeatherContinuityTest, RatesAreContinuousInTemperature) {
  WeatherConditions c;
  c.precipitation = 0.6f;
  c.windIntensity = 0.3f;
  constexpr float kFrom = -5.0f;
  constexpr float kTo = 5.0f;
  constexpr float kStepC = 1e-3f;
  auto coefficients = [&](float t) {
    c.temperature = t;
    const WeatherDynamics d = weatherDynamics(c);
    std::vector<double> out;
    for (const LevelDynamics* level : dynamicsOf(d)) {
      for (double x : {level->gain, level->loss, level->feed}) out.push_back(x);
    }
    return out;
  };
  std::vector<double> previous = coefficients(kFrom);
  std::vector<double> jump(previous.size(), 0.0);
  std::vector<double> scale(previous.size(), 0.0);
  for (int i = 1; kFrom + i * kStepC <= kTo; ++i) {
    const std::vector<double> now = coefficients(kFrom + i * kStepC);
    for (std::size_t k = 0; k < now.size(); ++k) {
      jump[k] = std::max(jump[k], std::abs(now[k] - previous[k]));
      scale[k] = std::max(scale[k], std::abs(now[k]));
    }
    previous = now;
  }
  for (std::size_t k = 0; k < jump.size(); ++k) {
    // A step anywhere in [-5, 5] °C would be a sizeable fraction of the coefficient's
    // range; a continuous rate changes by ~slope * 1e-3 between samples.
    EXPECT_LE(jump[k], 5e-3 * scale[k] + 1e-15) << kLevelNames[k / 3] << " coefficient " << k % 3;
  }
}

// The seed (3.1): "if temperature is less than or equal to zero rain becomes snowfall".
// The continuity band lies above 0 °C.
TEST(WeatherContinuityTest, SnowAtAndBelowZeroAndTheBandAboveIt) {
  EXPECT_EQ(snowFraction(0.0), 1.0);
  EXPECT_EQ(snowFraction(-0.5), 1.0);
  EXPECT_EQ(snowFraction(-20.0), 1.0);
  EXPECT_EQ(snowFraction(1.0), 0.0);
  EXPECT_EQ(snowFraction(5.0), 0.0);
  EXPECT_NEAR(snowFraction(0.5), 0.5, 1e-12);
  EXPECT_GT(snowFraction(0.01), 1.0 - 1e-3);
  EXPECT_LT(snowFraction(0.99), 1e-3);
  // At and below 0 °C nothing falls as rain: no wetting, no puddles, no rain memory.
  for (float t : {0.0f, -0.25f, -1.0f, -5.0f}) {
    const WeatherDynamics d = weatherDynamics(weather(t, 1.0f, 0.0f).conditions);
    EXPECT_EQ(d.wetness.gain, 0.0) << t;
    EXPECT_EQ(d.puddles.gain, 0.0) << t;
    EXPECT_EQ(d.rainMemory.gain, 0.0) << t;
    EXPECT_GT(d.snow.gain, 0.0) << t;
  }
}

// ---------------------------------------------------------------------------------
// Sun melt (eq. 3.5's SunIntensity, separate from the light's brightness)

TEST(WeatherSunMeltTest, DefaultConditionsDeriveTheDefaultMeltStrength) {
  EXPECT_FLOAT_EQ(sunMeltStrength(WeatherConditions{}), WeatherConditions{}.sunMelt);
}

TEST(WeatherSunMeltTest, FollowsTheLightTheSunsHeightAndTheTemperature) {
  WeatherConditions c;
  c.temperature = 5.0f;
  c.sunIntensity = 0.6f;
  EXPECT_FLOAT_EQ(sunMeltStrength(c), 0.6f);  // warm, sun overhead: the light's brightness
  c.sunIntensity = 0.0f;
  EXPECT_EQ(sunMeltStrength(c), 0.0f);  // no light, no melt
  c.sunIntensity = 1.0f;
  c.sunDirection = {1.0f, -0.2f, 0.0f};
  EXPECT_EQ(sunMeltStrength(c), 0.0f);  // below the horizon
  c.sunDirection = {1.0f, 0.0f, 0.0f};
  EXPECT_EQ(sunMeltStrength(c), 0.0f);  // on the horizon
  c.sunDirection = {0.0f, 0.0f, 0.0f};
  EXPECT_EQ(sunMeltStrength(c), 0.0f);  // no sun at all
  c.sunDirection = {0.0f, 3.0f, 0.0f};  // any length
  EXPECT_FLOAT_EQ(sunMeltStrength(c), 1.0f);
  // Colder air: weaker, never stronger, and nothing at or below sunMeltColdC.
  float previous = 2.0f;
  for (float t = 10.0f; t >= -30.0f; t -= 0.5f) {
    c.temperature = t;
    const float melt = sunMeltStrength(c);
    EXPECT_LE(melt, previous) << t;
    EXPECT_GE(melt, 0.0f);
    previous = melt;
  }
  c.temperature = static_cast<float>(WeatherRates{}.sunMeltColdC);
  EXPECT_EQ(sunMeltStrength(c), 0.0f);
  c.temperature = -4.0f;
  EXPECT_GT(sunMeltStrength(c), 0.5f);  // a sunny snowy day still melts sun-facing slopes
  c.temperature = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(std::isfinite(sunMeltStrength(c)));
}

// ---------------------------------------------------------------------------------
// Time scale

TEST(WeatherTimeScaleTest, DoubleSpeedOverTEqualsNormalSpeedOver2T) {
  const WeatherState start =
      withLevels(weather(2.0f, 0.7f, 0.4f), {0.8f, 0.1f, 0.2f, 0.6f, 0.3f, 0.4f});
  const WeatherSimulation normal{WeatherRates{}, 600.0};
  const WeatherSimulation fast{WeatherRates{}, 1200.0};
  constexpr double kFrame = 1.0 / 60.0;
  constexpr int kFrames = 1800;  // 30 real seconds
  WeatherState a = start;
  WeatherState b = start;
  for (int i = 0; i < kFrames; ++i) fast.step(a, kFrame);
  for (int i = 0; i < 2 * kFrames; ++i) normal.step(b, kFrame);
  EXPECT_NEAR(a.time, b.time, 1e-6);
  EXPECT_NEAR(a.time, 1200.0 * kFrames * kFrame, 1e-6);
  const std::vector<float> la = levelsOf(a);
  const std::vector<float> lb = levelsOf(b);
  const std::vector<float> l0 = levelsOf(start);
  for (std::size_t k = 0; k < la.size(); ++k) {
    EXPECT_NEAR(la[k], lb[k], 2e-5) << kLevelNames[k];
  }
  EXPECT_GT(std::abs(la[0] - l0[0]), 0.05f) << "the run should have visibly melted snow";
}

TEST(WeatherTimeScaleTest, ZeroNegativeOrNaNScaleFreezesTime) {
  const WeatherState start = withLevels(weather(10.0f, 1.0f), {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
  for (double scale : {0.0, -5.0, std::numeric_limits<double>::quiet_NaN()}) {
    WeatherState s = start;
    WeatherSimulation{WeatherRates{}, scale}.step(s, 10.0);
    EXPECT_EQ(levelsOf(s), levelsOf(start)) << scale;
    EXPECT_EQ(s.time, start.time);
  }
}

// ---------------------------------------------------------------------------------
// Degenerate inputs

TEST(WeatherDegenerateTest, TemperatureExtremesStayFiniteAndInRange) {
  for (float t : {-60.0f, 60.0f}) {
    for (double h : {1.0, kHour, 365 * kDay}) {
      WeatherState s = withLevels(weather(t, 1.0f, 1.0f), {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
      EXPECT_EQ(validate(s), "");
      advanceWeather(s, h);
      expectFiniteInRange(s);
    }
  }
}

TEST(WeatherDegenerateTest, OutOfRangePrecipitationIsRejectedButClampedWhenStepped) {
  for (float p : {-1.0f, 2.0f}) {
    WeatherState bad = weather(10.0f, p);
    EXPECT_NE(validate(bad), "");
    WeatherState clamped = weather(10.0f, std::clamp(p, 0.0f, 1.0f));
    advanceWeather(bad, kHour);
    advanceWeather(clamped, kHour);
    expectFiniteInRange(bad);
    EXPECT_EQ(levelsOf(bad), levelsOf(clamped)) << p;
  }
}

TEST(WeatherDegenerateTest, NonFiniteConditionsAreHarmless) {
  for (float x : {kNaN, kInf, -kInf}) {
    WeatherState s = withLevels(weather(x, x, x), {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
    s.conditions.windDirection = {x, x};
    EXPECT_NE(validate(s), "");
    advanceWeather(s, kHour);
    expectFiniteInRange(s);
  }
}

TEST(WeatherDegenerateTest, GarbageLevelsAreReset) {
  WeatherState s = withLevels(weather(10.0f, 0.5f), {kNaN, kInf, -3.0f, 7.0f, -kInf, kNaN});
  s.time = std::numeric_limits<double>::quiet_NaN();
  advanceWeather(s, kMinute);
  expectFiniteInRange(s);
}

TEST(WeatherDegenerateTest, GarbageTimeStepsDoNothing) {
  const WeatherState start = withLevels(weather(10.0f, 1.0f), {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
  for (double h : {-1.0, 0.0, std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::infinity()}) {
    WeatherState s = start;
    advanceWeather(s, h);
    EXPECT_EQ(levelsOf(s), levelsOf(start)) << h;
    EXPECT_EQ(s.time, start.time) << h;
  }
}

TEST(WeatherDegenerateTest, HugeStepLandsOnTheSteadyState) {
  WeatherState s = weather(12.0f, 0.5f, 0.2f);
  advanceWeather(s, 1e12);
  expectFiniteInRange(s);
  const WeatherDynamics d = weatherDynamics(s.conditions);
  EXPECT_NEAR(s.levels.wetness, d.wetness.gain / (d.wetness.gain + d.wetness.loss), 1e-6);
  EXPECT_NEAR(s.levels.puddles, d.puddles.gain / (d.puddles.gain + d.puddles.loss), 1e-6);
  EXPECT_NEAR(s.levels.rainMemory, 0.5f, 1e-6);
}

TEST(WeatherDegenerateTest, GarbageRatesNeverProduceNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double garbage : {nan, inf, -1.0, 1e300}) {
    WeatherRates rates;
    rates.snowAccumulation = garbage;
    rates.wetEvaporation = garbage;
    rates.mossGrowth = garbage;
    rates.freezePerDegree = garbage;
    rates.rainAboveC = garbage;
    rates.evaporationReferenceC = garbage;
    for (float t : {-10.0f, -0.5f, 10.0f}) {
      WeatherState s = withLevels(weather(t, 0.7f, 0.5f), {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
      for (double h : {1.0, kHour, 1e9}) {
        advanceWeather(s, h, rates);
        expectFiniteInRange(s);
      }
    }
  }
}

// ---------------------------------------------------------------------------------
// Timeline

WeatherKeyframe key(double time, float temperature, float precipitation, float windIntensity = 0.0f,
                    std::array<float, 2> wind = {1.0f, 0.0f}) {
  WeatherKeyframe k;
  k.time = time;
  k.temperature = temperature;
  k.precipitation = precipitation;
  k.windIntensity = windIntensity;
  k.windDirection = wind;
  return k;
}

TEST(WeatherTimelineTest, InterpolatesLinearlyAndClampsAtTheEnds) {
  WeatherTimeline timeline{
      {key(100, 10, 0, 0, {1, 0}), key(200, -10, 1, 1, {0, 1}), key(400, -10, 0.5f)}};
  EXPECT_EQ(timeline.at(0).temperature, 10.0f);
  EXPECT_EQ(timeline.at(100).temperature, 10.0f);
  const WeatherConditions mid = timeline.at(150);
  EXPECT_FLOAT_EQ(mid.temperature, 0.0f);
  EXPECT_FLOAT_EQ(mid.precipitation, 0.5f);
  EXPECT_FLOAT_EQ(mid.windIntensity, 0.5f);
  EXPECT_FLOAT_EQ(mid.windDirection[0], 0.5f);
  EXPECT_FLOAT_EQ(mid.windDirection[1], 0.5f);
  EXPECT_FLOAT_EQ(timeline.at(300).precipitation, 0.75f);
  EXPECT_EQ(timeline.at(400).precipitation, 0.5f);
  EXPECT_EQ(timeline.at(1e9).precipitation, 0.5f);
  EXPECT_EQ(timeline.at(std::numeric_limits<double>::quiet_NaN()).temperature, 10.0f);
  EXPECT_EQ(timeline.duration(), 300.0);
  // Sun is not scripted.
  EXPECT_EQ(mid.sunIntensity, WeatherConditions{}.sunIntensity);
}

TEST(WeatherTimelineTest, EmptyTimelineGivesDefaultsAndIsInvalid) {
  const WeatherTimeline empty;
  EXPECT_EQ(empty.at(5).temperature, WeatherConditions{}.temperature);
  EXPECT_NE(validate(empty), "");
}

TEST(WeatherTimelineTest, ParsesKeyframesAndKeepsLabels) {
  std::string error;
  const auto timeline = parseWeatherTimeline(nlohmann::json::parse(R"({"keyframes": [
      {"time": 0, "temperature": 5, "precipitation": 0, "wind": [1, 0], "windIntensity": 0.2, "label": "sunny"},
      {"time": 3600, "temperature": -4, "precipitation": 0.8}]})"),
                                             error);
  ASSERT_TRUE(timeline) << error;
  EXPECT_EQ(error, "");
  ASSERT_EQ(timeline->keys.size(), 2u);
  EXPECT_EQ(timeline->keys[0].label, "sunny");
  EXPECT_EQ(timeline->keys[0].windIntensity, 0.2f);
  EXPECT_EQ(timeline->keys[1].label, "");
  EXPECT_EQ(timeline->keys[1].temperature, -4.0f);
  EXPECT_EQ(timeline->keys[1].windDirection, (std::array<float, 2>{1.0f, 0.0f}));
  EXPECT_EQ(timeline->keys[1].windIntensity, 0.0f);
}

TEST(WeatherTimelineTest, ParseReportsPointerAndReason) {
  struct Case {
    const char* json;
    const char* expected;
  };
  const Case cases[] = {
      {R"([])", "expected an object"},
      {R"({})", "missing required \"keyframes\""},
      {R"({"keyframes": {}})", "/keyframes: expected an array"},
      {R"({"keyframes": []})", "/keyframes: needs at least one keyframe"},
      {R"({"keyframes": [], "extra": 1})", "/extra: unknown key"},
      {R"({"keyframes": [{"time": 0, "temperature": 5}]})",
       "/keyframes/0: missing required \"precipitation\""},
      {R"({"keyframes": [{"time": 0, "temperature": "5", "precipitation": 0}]})",
       "/keyframes/0/temperature: expected a number"},
      {R"({"keyframes": [{"time": 0, "temprature": 5, "precipitation": 0}]})",
       "/keyframes/0/temprature: unknown key"},
      {R"({"keyframes": [{"time": 0, "temperature": 5, "precipitation": 0},
                         {"time": 10, "temperature": 5, "precipitation": 2}]})",
       "/keyframes/1: precipitation = 2 is outside [0, 1]"},
      {R"({"keyframes": [{"time": 0, "temperature": 75, "precipitation": 0}]})",
       "/keyframes/0: temperature = 75"},
      {R"({"keyframes": [{"time": 10, "temperature": 5, "precipitation": 0},
                         {"time": 10, "temperature": 5, "precipitation": 0}]})",
       "/keyframes/1/time: must be greater"},
      {R"({"keyframes": [{"time": 0, "temperature": 5, "precipitation": 0, "wind": [1]}]})",
       "/keyframes/0/wind"},
      {R"({"keyframes": [{"time": 0, "temperature": 5, "precipitation": 0, "label": 3}]})",
       "/keyframes/0/label: expected a string"},
      {R"({"keyframes": [{"time": 0, "temperature": 5, "precipitation": 0, "windIntensity": -1}]})",
       "/keyframes/0: windIntensity = -1"},
  };
  for (const Case& c : cases) {
    std::string error;
    EXPECT_FALSE(parseWeatherTimeline(nlohmann::json::parse(c.json), error)) << c.json;
    EXPECT_EQ(error.rfind(c.expected, 0), 0u) << "got \"" << error << "\" for " << c.json;
  }
}

TEST(WeatherSunMeltTest, TimelinesDeriveTheMeltStrengthFromTheEnginesSun) {
  const WeatherTimeline timeline{{key(0, 10, 0), key(1000, -20, 0)}};
  WeatherState start;
  start.conditions.sunIntensity = 0.5f;
  start.conditions.sunMelt = 0.9f;  // replaced by the derived value
  const std::vector<WeatherState> history = simulateTimeline(timeline, start, 250.0, 1000.0);
  ASSERT_FALSE(history.empty());
  for (const WeatherState& s : history) EXPECT_FLOAT_EQ(s.conditions.sunMelt, sunMeltStrength(s.conditions));
  EXPECT_FLOAT_EQ(history.front().conditions.sunMelt, 0.5f);
  EXPECT_EQ(history.back().conditions.sunMelt, 0.0f);
}

TEST(WeatherTimelineTest, SimulateTimelineRecordsEveryStep) {
  const WeatherTimeline timeline{{key(0, 5, 0), key(1000, -5, 1)}};
  WeatherState start;
  start.time = 0.0;
  start.conditions.sunIntensity = 0.25f;
  const std::vector<WeatherState> history = simulateTimeline(timeline, start, 300.0, 1000.0);
  ASSERT_EQ(history.size(), 5u);  // start + 300 + 300 + 300 + 100
  EXPECT_EQ(history[0].time, 0.0);
  EXPECT_EQ(history[1].time, 300.0);
  EXPECT_EQ(history[4].time, 1000.0);
  EXPECT_FLOAT_EQ(history[4].conditions.temperature, -5.0f);
  EXPECT_FLOAT_EQ(history[2].conditions.precipitation, 0.6f);
  for (const WeatherState& s : history) {
    EXPECT_EQ(s.conditions.sunIntensity, 0.25f) << "the engine's sun was overwritten";
    expectFiniteInRange(s);
  }
  EXPECT_GT(history.back().levels.snow, 0.0f);

  EXPECT_EQ(simulateTimeline(timeline, start, 0.0, 1000.0).size(), 1u);
  EXPECT_EQ(simulateTimeline(timeline, start, 60.0, -1.0).size(), 1u);
  EXPECT_EQ(
      simulateTimeline(timeline, start, std::numeric_limits<double>::quiet_NaN(), 10.0).size(), 1u);
}

TEST(WeatherTimelineTest, ResultBarelyDependsOnStepSize) {
  // Conditions change continuously along the timeline; midpoint sampling keeps a coarse
  // run close to a fine one.
  std::string error;
  const auto timeline = parseWeatherTimeline(nlohmann::json::parse(kSeasonJson), error);
  ASSERT_TRUE(timeline) << error;
  const WeatherState fine =
      simulateTimeline(*timeline, WeatherState{}, 10.0, timeline->duration()).back();
  const WeatherState coarse =
      simulateTimeline(*timeline, WeatherState{}, 300.0, timeline->duration()).back();
  const std::vector<float> a = levelsOf(fine);
  const std::vector<float> b = levelsOf(coarse);
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 2e-3) << kLevelNames[k];
}

}  // namespace
}  // namespace wg
