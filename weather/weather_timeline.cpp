#include "weather/weather_timeline.hpp"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>

namespace wg {
namespace {

WeatherConditions conditionsOf(const WeatherKeyframe& k) {
  WeatherConditions c;
  c.temperature = k.temperature;
  c.precipitation = k.precipitation;
  c.windIntensity = k.windIntensity;
  c.windDirection = k.windDirection;
  return c;
}

float lerp(float a, float b, double f) { return static_cast<float>(a + (b - a) * f); }

std::string keyPointer(std::size_t index) { return "/keyframes/" + std::to_string(index); }

// One JSON pointer reference token (RFC 6901): '~' -> "~0", '/' -> "~1".
std::string pointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string number(double x) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << x;
  return out.str();
}

// Keeps the engine-owned sun while taking everything the timeline scripts; the sun's
// melt strength (eq. 3.5) follows from that sun and the scripted temperature.
WeatherConditions scriptedConditions(const WeatherTimeline& timeline, double t,
                                     const WeatherConditions& sun, const WeatherRates& rates) {
  WeatherConditions c = timeline.keys.empty() ? sun : timeline.at(t);
  c.sunDirection = sun.sunDirection;
  c.sunIntensity = sun.sunIntensity;
  c.sunMelt = sunMeltStrength(c, rates);
  return c;
}

bool readNumber(const nlohmann::json& object, const char* key, const std::string& pointer,
                bool required, double& out, std::string& error) {
  const auto it = object.find(key);
  if (it == object.end()) {
    if (required) error = pointer + ": missing required \"" + key + "\"";
    return !required;
  }
  if (!it->is_number()) {
    error = pointer + "/" + key + ": expected a number, got " + it->type_name();
    return false;
  }
  out = it->get<double>();
  return true;
}

}  // namespace

WeatherConditions WeatherTimeline::at(double t) const {
  if (keys.empty()) return {};
  if (std::isnan(t) || t <= keys.front().time) return conditionsOf(keys.front());
  // Linear scan: timelines are a handful of keys, and it stays safe on unsorted input.
  for (std::size_t i = 1; i < keys.size(); ++i) {
    const WeatherKeyframe& a = keys[i - 1];
    const WeatherKeyframe& b = keys[i];
    if (t >= b.time) continue;
    const double span = b.time - a.time;
    const double f = span > 0.0 ? std::clamp((t - a.time) / span, 0.0, 1.0) : 1.0;
    WeatherConditions c;
    c.temperature = lerp(a.temperature, b.temperature, f);
    c.precipitation = lerp(a.precipitation, b.precipitation, f);
    c.windIntensity = lerp(a.windIntensity, b.windIntensity, f);
    c.windDirection = {lerp(a.windDirection[0], b.windDirection[0], f),
                       lerp(a.windDirection[1], b.windDirection[1], f)};
    return c;
  }
  return conditionsOf(keys.back());
}

double WeatherTimeline::duration() const {
  return keys.size() < 2 ? 0.0 : keys.back().time - keys.front().time;
}

std::vector<std::pair<std::size_t, std::size_t>> timelineStages(const WeatherTimeline& timeline) {
  const auto& keys = timeline.keys;
  std::vector<std::pair<std::size_t, std::size_t>> stages;
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (!stages.empty() && !keys[k].label.empty() && keys[k].label == keys[stages.back().second].label)
      stages.back().second = k;
    else
      stages.push_back({k, k});
  return stages;
}

std::string validate(const WeatherTimeline& timeline) {
  if (timeline.keys.empty()) return "/keyframes: needs at least one keyframe";
  if (timeline.keys.size() > kMaxTimelineKeyframes)
    return keyPointer(kMaxTimelineKeyframes) + ": the timeline has " + std::to_string(timeline.keys.size()) +
           " keyframes; the limit is " + std::to_string(kMaxTimelineKeyframes) + ", so split it or drop keyframes";
  if (const auto stages = timelineStages(timeline); stages.size() > kMaxTimelineStages)
    return keyPointer(stages[kMaxTimelineStages].first) + ": the timeline has " + std::to_string(stages.size()) +
           " stages; the limit is " + std::to_string(kMaxTimelineStages) +
           " (keyframes in a row with one label are one stage), so give neighbouring keyframes one label or split the timeline";
  for (std::size_t i = 0; i < timeline.keys.size(); ++i) {
    const WeatherKeyframe& k = timeline.keys[i];
    if (k.label.size() > kMaxTimelineLabelBytes)
      return keyPointer(i) + "/label: " + std::to_string(k.label.size()) + " bytes long; the limit is " +
             std::to_string(kMaxTimelineLabelBytes) + ", so shorten the label";
    if (!std::isfinite(k.time)) return keyPointer(i) + "/time: not a finite number";
    if (i > 0 && !(k.time > timeline.keys[i - 1].time)) {
      return keyPointer(i) + "/time: must be greater than the previous keyframe's time (" +
             number(timeline.keys[i - 1].time) + ")";
    }
    if (std::string error = validate(conditionsOf(k)); !error.empty())
      return keyPointer(i) + ": " + error;
  }
  return {};
}

std::vector<WeatherState> simulateTimeline(const WeatherTimeline& timeline,
                                           const WeatherState& start, double dt, double duration,
                                           const WeatherRates& rates) {
  std::vector<WeatherState> history;
  WeatherState state = start;
  advanceWeather(state, 0.0, rates);  // only sanitizes garbage levels and time
  state.conditions = scriptedConditions(timeline, state.time, start.conditions, rates);
  history.push_back(state);
  if (!(std::isfinite(dt) && dt > 0.0 && std::isfinite(duration) && duration > 0.0)) return history;

  dt = std::max(dt, duration / static_cast<double>(kMaxTimelineSteps));
  // The tolerance keeps rounding in duration / dt from adding a sliver of a last step.
  constexpr double kStepCountTolerance = 1e-9;
  const auto steps =
      static_cast<std::size_t>(std::max(1.0, std::ceil(duration / dt - kStepCountTolerance)));
  const double t0 = state.time;
  history.reserve(steps + 1);
  for (std::size_t i = 0; i < steps; ++i) {
    // Times from t0 + i * dt rather than accumulated, so rounding does not drift.
    const double begin = t0 + static_cast<double>(i) * dt;
    const double end = i + 1 == steps ? t0 + duration : begin + dt;
    state.conditions = scriptedConditions(timeline, 0.5 * (begin + end), start.conditions, rates);
    state.time = begin;
    advanceWeather(state, end - begin, rates);
    state.time = end;
    state.conditions = scriptedConditions(timeline, end, start.conditions, rates);
    history.push_back(state);
  }
  return history;
}

std::optional<WeatherTimeline> parseWeatherTimeline(const nlohmann::json& document,
                                                    std::string& error) {
  error.clear();
  if (!document.is_object()) {
    error = "expected an object with \"keyframes\", got " + std::string(document.type_name());
    return std::nullopt;
  }
  for (const auto& [key, value] : document.items()) {
    if (key != "keyframes") {
      error = "/" + pointerToken(key) + ": unknown key (expected \"keyframes\")";
      return std::nullopt;
    }
  }
  const auto keyframes = document.find("keyframes");
  if (keyframes == document.end()) {
    error = "missing required \"keyframes\"";
    return std::nullopt;
  }
  if (!keyframes->is_array()) {
    error = "/keyframes: expected an array, got " + std::string(keyframes->type_name());
    return std::nullopt;
  }

  static constexpr std::array<const char*, 6> kKeys{"time", "temperature",   "precipitation",
                                                    "wind", "windIntensity", "label"};
  WeatherTimeline timeline;
  for (std::size_t i = 0; i < keyframes->size(); ++i) {
    const nlohmann::json& item = (*keyframes)[i];
    const std::string pointer = keyPointer(i);
    if (!item.is_object()) {
      error = pointer + ": expected an object, got " + std::string(item.type_name());
      return std::nullopt;
    }
    for (const auto& [key, value] : item.items()) {
      if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end()) {
        error =
            pointer + "/" + pointerToken(key) +
            ": unknown key (expected time, temperature, precipitation, wind, windIntensity, label)";
        return std::nullopt;
      }
    }
    WeatherKeyframe k;
    double time = 0.0;
    double temperature = k.temperature;
    double precipitation = k.precipitation;
    double windIntensity = k.windIntensity;
    if (!readNumber(item, "time", pointer, true, time, error) ||
        !readNumber(item, "temperature", pointer, true, temperature, error) ||
        !readNumber(item, "precipitation", pointer, true, precipitation, error) ||
        !readNumber(item, "windIntensity", pointer, false, windIntensity, error)) {
      return std::nullopt;
    }
    k.time = time;
    k.temperature = static_cast<float>(temperature);
    k.precipitation = static_cast<float>(precipitation);
    k.windIntensity = static_cast<float>(windIntensity);
    if (const auto wind = item.find("wind"); wind != item.end()) {
      if (!wind->is_array() || wind->size() != 2 || !(*wind)[0].is_number() ||
          !(*wind)[1].is_number()) {
        error = pointer + "/wind: expected [x, z], an array of two numbers";
        return std::nullopt;
      }
      k.windDirection = {(*wind)[0].get<float>(), (*wind)[1].get<float>()};
    }
    if (const auto label = item.find("label"); label != item.end()) {
      if (!label->is_string()) {
        error = pointer + "/label: expected a string, got " + std::string(label->type_name());
        return std::nullopt;
      }
      k.label = label->get<std::string>();
    }
    timeline.keys.push_back(std::move(k));
  }
  if (error = validate(timeline); !error.empty()) return std::nullopt;
  return timeline;
}

}  // namespace wg
