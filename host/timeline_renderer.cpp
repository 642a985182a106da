#include "host/timeline_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace wg {

namespace {
std::string fixed(double x, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

// Hours as a caption shows them: one decimal, or three digits and an exponent past a
// million hours, so a timeline of 1e300 s keeps its caption inside the picture.
std::string hours(double seconds) {
  const double h = seconds / 3600.0;
  if (std::fabs(h) < 1e6) return fixed(h, 1);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", h);
  return buf;
}

std::string slugOf(const std::string& label) {
  std::string out;
  for (char c : label) {
    bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (alnum) out += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

// The simulated state nearest time t. Found by time, not by step count: simulateTimeline
// enlarges a step too small for its step limit, so states[i] need not be at i * step.
std::size_t stateNearest(const std::vector<WeatherState>& states, double t) {
  auto after = std::lower_bound(states.begin(), states.end(), t,
                                [](const WeatherState& s, double time) { return s.time < time; });
  if (after == states.end()) return states.size() - 1;
  if (after != states.begin() && t - std::prev(after)->time < after->time - t) --after;
  return static_cast<std::size_t>(after - states.begin());
}
}  // namespace

std::vector<TimelineFrame> planTimeline(const WeatherTimeline& timeline, const RenderRequest& base, double step) {
  const auto& keys = timeline.keys;
  // A stage's frame shows the state at the end of its run of keyframes.
  const auto runs = timelineStages(timeline);
  double start = keys.front().time;
  double lastRunLength = keys[runs.back().second].time - keys[runs.back().first].time;
  double lastGap = keys.size() > 1 ? keys.back().time - keys[keys.size() - 2].time : 6 * 3600.0;
  // A single-keyframe last stage is held as long as the gap before it.
  double end = keys.back().time + (lastRunLength > 0.0 ? 0.0 : lastGap);
  WeatherState initial = base.weather;
  initial.time = start;
  initial.levels = {};
  auto states = simulateTimeline(timeline, initial, step, end - start);
  std::vector<TimelineFrame> frames;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto& [first, last] = runs[r];
    TimelineFrame out;
    out.label = keys[first].label.empty() ? "stage " + std::to_string(r + 1) : keys[first].label;
    char index[24];  // room for any size_t, so the format cannot truncate
    std::snprintf(index, sizeof index, "%02zu", r + 1);
    out.slug = std::string(index) + "-" + slugOf(out.label);
    double stageEnd = last > first ? keys[last].time : (r + 1 < runs.size() ? keys[runs[r + 1].first].time : end);
    out.state = states[stateNearest(states, stageEnd)];
    // The sun is the scene's; the conditions shown are the stage's own (a single
    // keyframe's stage already blends towards the next one by its end).
    out.state.conditions.sunDirection = base.weather.conditions.sunDirection;
    out.state.conditions.sunIntensity = base.weather.conditions.sunIntensity;
    out.state.conditions.temperature = keys[last].temperature;
    out.state.conditions.precipitation = keys[last].precipitation;
    const auto& w = out.state;
    out.lines = {out.label + "   t = " + hours(w.time) + " h",
                 "T = " + fixed(w.conditions.temperature, 1) + " C   P = " + fixed(w.conditions.precipitation, 2),
                 "snow " + fixed(w.levels.snow, 2) + "  wet " + fixed(w.levels.wetness, 2) + "  moss " +
                     fixed(w.levels.moss, 2) + "  frost " + fixed(w.levels.frost, 2)};
    frames.push_back(std::move(out));
  }
  return frames;
}

void renderTimelineFrames(SceneRenderer& renderer, std::vector<TimelineFrame>& stages, const RenderRequest& base,
                          const std::function<void(std::size_t, std::size_t, const std::string&)>& onFrame) {
  for (std::size_t i = 0; i < stages.size(); ++i) {
    if (onFrame) onFrame(i + 1, stages.size(), stages[i].label);
    RenderRequest request = base;
    request.weather = stages[i].state;
    stages[i].frame = renderer.render(request);
  }
}

std::vector<TimelineFrame> renderTimeline(SceneRenderer& renderer, const WeatherTimeline& timeline,
                                          const RenderRequest& base, double step,
                                          const std::function<void(std::size_t, std::size_t, const std::string&)>& onFrame) {
  std::vector<TimelineFrame> stages = planTimeline(timeline, base, step);
  renderTimelineFrames(renderer, stages, base, onFrame);
  return stages;
}

}  // namespace wg
