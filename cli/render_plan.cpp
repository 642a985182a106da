#include "cli/render_plan.hpp"

#include <unistd.h>

#include <filesystem>
#include <set>

#include "compiler/debug_views.hpp"
#include "compiler/json_document.hpp"
#include "compiler/literal.hpp"
#include "nodes/regular_file.hpp"
#include "weather/frame_weather.hpp"

namespace wg {

namespace {

// A preset by name, or the framed orbit; "" or a usage message.
std::string applyCamera(const RenderOptions& o, const scene::Scene& scene, RenderRequest& request) {
  if (o.orbit) {
    request.cameraPose = scene::orbitCamera(scene, *o.orbit, float(request.width) / float(request.height));
    return "";
  }
  request.camera = o.camera;
  if (o.camera.empty() || scene.camera(o.camera)) return "";
  std::string names;
  for (const auto& c : scene.cameras) names += (names.empty() ? "" : ", ") + c.name;
  return "scene '" + scene.name + "' has no camera '" + quoteUserText(o.camera) + "' (cameras: " + names +
         ", or orbit:AZIMUTH,ELEVATION[,DISTANCE])";
}

// A timeline problem as "FILE:LINE:COL: POINTER: what" (parseWeatherTimeline's errors
// start with the pointer of the offending value).
std::string locatedTimelineError(const JsonDocument& document, const std::string& error) {
  std::string pointer;
  if (!error.empty() && error.front() == '/') pointer = error.substr(0, error.find(':'));
  const SourceLocation at = document.locate(pointer);
  return quoteUserText(at.file, 300) + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
         quoteUserText(error, 400);
}

// Read as graphs are: regular file, size limit, duplicate keys and depth refused.
std::string readTimeline(const std::string& path, std::optional<WeatherTimeline>& timeline) {
  if (path.empty()) return "";
  std::string text;
  if (FileRead read = readRegularFile(path, JsonLimits{}.maxBytes, text); read.status != FileReadStatus::Ok)
    return "cannot read timeline '" + quoteUserText(path) + "': " + read.reason;
  DiagnosticList diagnostics;
  auto document = parseJsonDocument(path, std::move(text), diagnostics);
  if (!document) {  // one usage error that says where and what to change, not a diagnostic inside one
    const Diagnostic& d = diagnostics.items().front();
    return "timeline " + quoteUserText(d.location.file, 300) + ":" + std::to_string(d.location.line) + ":" +
           std::to_string(d.location.column) + ": " + std::string(d.info().id) + ": " + quoteUserText(d.message, 400) +
           " [" + (d.location.pointer.empty() ? "/" : quoteUserText(d.location.pointer, 300)) + "]; " +
           quoteUserText(d.hint, 200);
  }
  std::string error;
  timeline = parseWeatherTimeline(document->root(), error);
  if (!timeline) return "timeline " + locatedTimelineError(*document, error);
  return "";
}

}  // namespace

std::string applyAovAndWeather(const std::string& aov, const std::vector<std::string>& weatherLists, EvalInputs inputs,
                               RenderRequest& request) {
  bool foundAov = false;
  for (const auto& view : kDebugViews)
    if (view.name == aov) {
      request.debugView = view.id;
      foundAov = true;
    }
  if (!foundAov) return "unknown --aov '" + quoteUserText(aov) + "'";
  std::set<std::string> seen;
  for (const auto& list : weatherLists)
    if (std::string e = applyEvalInputList(list, EvalInputGroup::Weather, inputs, seen); !e.empty()) return e;
  if (std::string e = finishEvalInputs(inputs); !e.empty()) return e;
  request.weather = weatherOf(inputs.frame);
  return "";
}

std::string makeRenderPlan(const RenderOptions& o, const scene::Scene& scene, RenderPlan& plan) {
  plan.request = o.request;
  plan.samples = o.samples;
  plan.request.weatherPreset = o.weatherPreset;
  plan.step = o.step;
  plan.output = o.output;
  plan.framesDir = o.framesDir;
  plan.timelinePath = o.timelinePath;
  plan.aov = o.aov;
  plan.progress = !o.quiet && ::isatty(STDERR_FILENO);
  if (std::string e = applyCamera(o, scene, plan.request); !e.empty()) return e;
  // The weather: eval's names and checks; the sun comes from the scene unless given.
  EvalInputs inputs = defaultEvalInputs();
  inputs.frame.sunDirection = {scene.towardsSun.x, scene.towardsSun.y, scene.towardsSun.z};
  if (std::string e = applyAovAndWeather(o.aov, o.weatherLists, inputs, plan.request); !e.empty()) return e;
  if (!o.timelinePath.empty()) plan.inputs.add(std::filesystem::path(o.timelinePath));
  return readTimeline(o.timelinePath, plan.timeline);
}

std::filesystem::path stripPath(const RenderPlan& plan) {
  return std::filesystem::path(plan.output).replace_extension(".strip.png");
}

std::filesystem::path framePath(const RenderPlan& plan, const std::string& sceneName, const std::string& stageSlug) {
  return std::filesystem::path(plan.framesDir) / (sceneName + "-" + stageSlug + ".png");
}

std::vector<PlannedOutput> plannedOutputs(const RenderPlan& plan, const std::string& sceneName,
                                          const std::vector<std::string>& stageSlugs) {
  std::vector<PlannedOutput> outputs{{"-o", plan.output}};
  if (!plan.timeline) return outputs;
  outputs.push_back({"-o", stripPath(plan)});
  if (plan.framesDir.empty()) return outputs;
  for (const auto& slug : stageSlugs) outputs.push_back({"--frames", framePath(plan, sceneName, slug)});
  return outputs;
}

}  // namespace wg
