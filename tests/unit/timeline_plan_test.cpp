// planTimeline: which simulated state each stage of a timeline shows.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "host/timeline_renderer.hpp"

namespace wg {
namespace {

// Two held stages: dry and warm for six hours, then cold and snowing for six.
WeatherTimeline dryThenSnow() {
  std::string error;
  auto timeline = parseWeatherTimeline(nlohmann::json::parse(R"({"keyframes": [
    {"time": 0,     "temperature": 12, "precipitation": 0,   "label": "dry"},
    {"time": 21600, "temperature": 12, "precipitation": 0,   "label": "dry"},
    {"time": 25200, "temperature": -6, "precipitation": 0.8, "label": "snow"},
    {"time": 43200, "temperature": -6, "precipitation": 0.8, "label": "snow"}
  ]})"),
                                       error);
  EXPECT_TRUE(timeline) << error;
  return timeline.value_or(WeatherTimeline{});
}

// Each stage shows the state at the end of its run of keyframes, whatever the step.
// A step too small for simulateTimeline's step limit is enlarged there; the stage
// must still be found at its own time, not at the end of the timeline.
TEST(TimelinePlan, EachStageShowsTheStateAtItsEndEvenWhenTheStepIsEnlarged) {
  const WeatherTimeline timeline = dryThenSnow();
  for (double step : {300.0, 0.01}) {
    SCOPED_TRACE(step);
    const std::vector<TimelineFrame> stages = planTimeline(timeline, RenderRequest{}, step);
    ASSERT_EQ(stages.size(), 2u);
    EXPECT_NEAR(stages[0].state.time, 21600.0, 1.0);
    EXPECT_EQ(stages[0].state.levels.snow, 0.0f) << "the dry stage shows the snow that falls after it";
    EXPECT_NEAR(stages[1].state.time, 43200.0, 1.0);
    EXPECT_GT(stages[1].state.levels.snow, 0.5f);
  }
}

// A step that does not divide the timeline: the last stage still ends at its last keyframe.
TEST(TimelinePlan, TheLastStageEndsAtItsLastKeyframeWhenTheStepDoesNotDivideIt) {
  const std::vector<TimelineFrame> stages = planTimeline(dryThenSnow(), RenderRequest{}, 7000.0);
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_EQ(stages[1].state.time, 43200.0);
}

// A stage's caption gives its time in hours: with one decimal, and past a million hours
// in three digits, so that a timeline 1e300 s long does not write 300 of them.
TEST(TimelinePlan, CaptionsGiveTheTimeInHoursInAFewDigits) {
  std::vector<TimelineFrame> stages = planTimeline(dryThenSnow(), RenderRequest{}, 300.0);
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_EQ(stages[1].lines.front(), "snow   t = 12.0 h");
  std::string error;
  auto longest = parseWeatherTimeline(nlohmann::json::parse(R"({"keyframes": [
    {"time": 0, "temperature": 12, "precipitation": 0, "label": "a"},
    {"time": 1e300, "temperature": 12, "precipitation": 0, "label": "b"}]})"),
                                      error);
  ASSERT_TRUE(longest) << error;
  stages = planTimeline(*longest, RenderRequest{}, 300.0);
  ASSERT_FALSE(stages.empty());
  const std::string caption = stages.back().lines.front();
  EXPECT_TRUE(caption.starts_with("b   t = ") && caption.ends_with("e+296 h")) << caption;
  EXPECT_LT(caption.size(), 24u) << caption;
}

}  // namespace
}  // namespace wg
