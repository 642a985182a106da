#include "tests/fuzz/timeline_case.hpp"

#include <cmath>
#include <optional>

#include "compiler/json_document.hpp"
#include "weather/weather_timeline.hpp"

namespace wg::fuzz {

namespace {

// Enough steps to cross every keyframe of a small timeline; bounded so a timeline of
// years does not make one input take seconds.
constexpr double kSimulationSteps = 200.0;

std::string checkSimulation(const WeatherTimeline& timeline) {
  const double span = timeline.duration();
  // Past the last keyframe too, as planTimeline holds a last stage.
  const double duration = span > 0.0 ? span * 1.25 : 3600.0;
  WeatherState start;
  start.time = timeline.keys.front().time;
  const double end = start.time + duration;
  if (!std::isfinite(duration) || !std::isfinite(end)) return "";
  const auto states = simulateTimeline(timeline, start, duration / kSimulationSteps, duration);
  if (states.empty() || states.size() > static_cast<std::size_t>(kSimulationSteps) + 2)
    return "simulateTimeline returned " + std::to_string(states.size()) + " states";
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (std::string e = validate(states[i]); !e.empty()) return "state " + std::to_string(i) + ": " + e;
    if (i > 0 && !(states[i].time >= states[i - 1].time)) return "time goes backwards at state " + std::to_string(i);
  }
  if (states.size() > 1 && states.back().time != end) return "the last state is not at start + duration";
  return "";
}

}  // namespace

std::string checkTimelineInput(std::string_view input) {
  DiagnosticList diagnostics;
  auto document = parseJsonDocument("timeline.json", std::string(input), diagnostics);
  if (!document) return diagnostics.hasErrors() ? "" : "parseJsonDocument failed without an error";
  std::string error;
  const auto timeline = parseWeatherTimeline(document->root(), error);
  if (!timeline) {
    if (error.empty()) return "parseWeatherTimeline failed without an error";
    // As the CLI places the error (cli/render_plan.cpp): its leading JSON pointer.
    document->locate(error.front() == '/' ? error.substr(0, error.find(':')) : "");
    return "";
  }
  if (!error.empty()) return "parseWeatherTimeline returned a timeline and an error";
  if (std::string e = validate(*timeline); !e.empty()) return "an accepted timeline fails validate: " + e;
  const auto& keys = timeline->keys;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    std::optional<double> between;
    if (k + 1 < keys.size()) between = keys[k].time + 0.5 * (keys[k + 1].time - keys[k].time);
    for (double t : {keys[k].time, between.value_or(keys[k].time + 1.0)})
      if (std::string e = validate(timeline->at(t)); !e.empty())
        return "conditions at t = " + std::to_string(t) + ": " + e;
  }
  return checkSimulation(*timeline);
}

}  // namespace wg::fuzz
