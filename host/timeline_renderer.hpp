// Renders a scripted weather timeline: one frame per stage (a run of keyframes sharing
// a label, i.e. held conditions), at the state the weather simulation reaches by the
// end of that stage. The CLI, the gallery and the
// reference-image tests all go through here, so they draw the same frames.
#pragma once
#include <string>
#include <vector>

#include "host/scene_renderer.hpp"
#include "weather/weather_timeline.hpp"

namespace wg {

struct TimelineFrame {
  std::string label;               // the stage's keyframe label, or "stage N"
  std::string slug;                // label made file-name safe ("thaw-with-rain")
  WeatherState state;              // what was rendered
  std::vector<std::string> lines;  // the contact sheet's caption
  RenderedFrame frame;
};

// The stages with their states and captions, simulated but not rendered (`frame` is
// empty): cheap, so callers can check what the render will produce first.
std::vector<TimelineFrame> planTimeline(const WeatherTimeline& timeline, const RenderRequest& base, double step);

// Renders each planned stage into its `frame`.
void renderTimelineFrames(SceneRenderer& renderer, std::vector<TimelineFrame>& stages, const RenderRequest& base,
                          const std::function<void(std::size_t, std::size_t, const std::string&)>& onFrame = {});

// Both of the above. `step` is the simulation step in seconds. A last stage of a single keyframe is held
// as long as the gap before it, so its weather has time to act. onFrame (optional)
// reports progress.
std::vector<TimelineFrame> renderTimeline(SceneRenderer& renderer, const WeatherTimeline& timeline,
                                          const RenderRequest& base, double step,
                                          const std::function<void(std::size_t, std::size_t, const std::string&)>& onFrame = {});

}  // namespace wg
