// Scripted weather: keyframed conditions, linearly interpolated, and a helper that runs
// the simulation along them. Used for previews, tests and cut-scenes.
#pragma once
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "weather/weather_simulation.hpp"
#include "weather/weather_state.hpp"

namespace wg {

struct WeatherKeyframe {
  double time = 0.0;  // simulated seconds
  float temperature = 15.0f;
  float precipitation = 0.0f;
  float windIntensity = 0.0f;
  std::array<float, 2> windDirection{1.0f, 0.0f};
  std::string label;  // optional name for tools ("blizzard"); no effect on the weather
};

struct WeatherTimeline {
  std::vector<WeatherKeyframe> keys;  // by strictly increasing time (validate checks)

  // Conditions at time t: linear between the surrounding keyframes, held constant before
  // the first and after the last. Sun fields are WeatherConditions defaults (keyframes
  // do not script the sun). No keys: default conditions. Wind direction is interpolated
  // as a vector, so it turns through the shorter way and may shrink mid-way.
  WeatherConditions at(double t) const;
  // Time from the first to the last keyframe; 0 with fewer than two.
  double duration() const;
};

// A timeline's limits. Each keyframe is interpolated by a linear scan at every
// simulation step, a stage is one picture of a render's contact sheet and strip, and a
// label is printed in its stage's caption.
inline constexpr std::size_t kMaxTimelineKeyframes = 256;
inline constexpr std::size_t kMaxTimelineStages = 64;
inline constexpr std::size_t kMaxTimelineLabelBytes = 64;

// The stages: runs of consecutive keyframes with the same label (a held plateau), as
// the first and last keyframe of each. An unlabelled keyframe is a stage of its own.
std::vector<std::pair<std::size_t, std::size_t>> timelineStages(const WeatherTimeline& timeline);

// "" when the timeline has 1 to kMaxTimelineKeyframes keyframes in at most
// kMaxTimelineStages stages, finite strictly increasing times, labels of at most
// kMaxTimelineLabelBytes and every keyframe's conditions pass validate(); otherwise the
// first problem, prefixed with its JSON pointer ("/keyframes/2: precipitation = 2 is
// outside [0, 1]").
std::string validate(const WeatherTimeline& timeline);

// Most steps simulateTimeline takes (bounds the history it allocates).
inline constexpr std::size_t kMaxTimelineSteps = 1'000'000;

// Runs the simulation from `start` (whose time places it on the timeline) for `duration`
// simulated seconds in steps of `dt` (the last one shorter if dt does not divide
// duration). Each step holds the conditions sampled at its midpoint; the start state's
// sun is kept, and its melt strength is derived (sunMeltStrength) from that sun and the
// timeline's temperature. Returns the states after every step, preceded by the start state; each
// state's conditions are the timeline's at its own time. Non-positive or non-finite dt
// or duration: just the start state. dt is enlarged if needed to stay within
// kMaxTimelineSteps (the integration is exact, so only condition sampling coarsens).
std::vector<WeatherState> simulateTimeline(const WeatherTimeline& timeline,
                                           const WeatherState& start, double dt, double duration,
                                           const WeatherRates& rates = {});

// Reads {"keyframes": [{"time": 0, "temperature": 5, "precipitation": 0, "wind": [1, 0],
// "windIntensity": 0.2, "label": "sunny"}, ...]}. time, temperature and precipitation are
// required; wind, windIntensity and label default to WeatherKeyframe's defaults. Unknown
// keys are errors (they are usually typos). On failure returns nullopt and sets `error`
// to one line starting with the JSON pointer of the offending value (no prefix for the
// document itself); validate() is applied, so a returned timeline is always valid.
std::optional<WeatherTimeline> parseWeatherTimeline(const nlohmann::json& document,
                                                    std::string& error);

}  // namespace wg
