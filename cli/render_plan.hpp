// What one `render` of a scene draws: the request (camera, weather, size, AOV), the
// timeline if any, and where the pictures go. Made from the options for each scene,
// since the default sun and a framed orbit camera come from the scene.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/eval_inputs.hpp"
#include "cli/imported_origin.hpp"
#include "cli/render_options.hpp"
#include "cli/run_inputs.hpp"
#include "weather/weather_timeline.hpp"

namespace wg {

struct RenderPlan {
  RenderRequest request;
  unsigned samples = kDefaultColourSamples;  // the lit pass's MSAA
  std::optional<WeatherTimeline> timeline;
  std::string timelinePath;  // names the timeline in its errors
  double step = 300.0;
  std::string output, framesDir, aov;
  bool progress = false;  // lines on stderr
  RunInputs inputs;       // the scene's files and the timeline; the materials' are added once compiled
  std::vector<ImportedOrigin> modelOrigins;  // --model: its diagnostics name the model, not these files
};

// Every file the render writes: the picture, and for a timeline its strip and, with
// --frames, one picture per stage (`stageSlugs`, TimelineFrame::slug).
std::vector<PlannedOutput> plannedOutputs(const RenderPlan& plan, const std::string& sceneName,
                                          const std::vector<std::string>& stageSlugs = {});
std::filesystem::path stripPath(const RenderPlan& plan);
std::filesystem::path framePath(const RenderPlan& plan, const std::string& sceneName, const std::string& stageSlug);

// "" or a usage message (unknown camera, bad weather, unreadable timeline).
std::string makeRenderPlan(const RenderOptions& options, const scene::Scene& scene, RenderPlan& plan);

// Sets the request's debug view from --aov and its weather from the --weather lists
// over `inputs` (eval's names and checks). Returns a usage error, or "".
std::string applyAovAndWeather(const std::string& aov, const std::vector<std::string>& weatherLists, EvalInputs inputs,
                               RenderRequest& request);

}  // namespace wg
