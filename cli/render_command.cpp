// weathergen render: draws a validation scene with the emitted shaders on Vulkan
// (lavapipe by default) and writes a PNG, or for a timeline a frame strip and a
// labelled contact sheet.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "cli/bundled_graphs_directory.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/eval_inputs.hpp"
#include "compiler/debug_views.hpp"
#include "compiler/literal.hpp"
#include "compiler/weather_config.hpp"
#include "runtime/display_image.hpp"
#include "runtime/image/contact_sheet.hpp"
#include "runtime/image/png_file.hpp"
#include "runtime/scene_renderer.hpp"
#include "runtime/snow/snowfield_scene.hpp"
#include "runtime/timeline_renderer.hpp"
#include "cli/snowfield_render.hpp"
#include "runtime/weather/weather_timeline.hpp"

namespace wg {

namespace {

constexpr const char* kRenderUsage = R"(Usage: weathergen render --scene NAME -o OUT.png [options]

Options:
  --scene NAME              valley, rocks, river, road or snowfield (interactive snow:
                            walkers, a vehicle and a camera that leaves and returns;
                            writes OUT.png as a contact sheet and OUT.strip.png)
  --camera NAME             a camera preset of the scene (default: its first)
  --weather k=v,...         weather state, as 'weathergen eval --help' lists it
                            (temperature, precipitation, snowLevel, wetnessLevel, ...)
  --timeline FILE           scripted weather (runtime/timelines/seasons.json): writes
                            OUT.png as a labelled contact sheet, one frame per stage,
                            and OUT.strip.png as a frame strip
  --step SECONDS            simulation step for --timeline (default 300)
  --frames DIR              with --timeline: also write each stage as DIR/SCENE-NN-LABEL.png
  --weather-preset NAME     replace every material's preset (none for a baseline)
  --backend glsl|hlsl       which emitted SPIR-V to draw with (default glsl)
  --size WxH                image size (default 960x540)
  --aov NAME                lit, albedo, roughness, normal, snow, wet, moss, frost,
                            ice, puddle or density (default lit)
  --device NAME             Vulkan device: cpu, gpu, integrated, discrete or a name
                            (default: the CPU device, lavapipe)
  --validation              enable the Vulkan validation layers; any message fails
  --no-shadows              draw without the sun shadow map
  --graphs DIR              where the bundled graphs live (default: found next to the
                            executable: the source tree, or share/weathergen/graphs)
  -q, --quiet               no progress output
)";


WeatherState weatherFromFrame(const FrameState& f) {
  WeatherState s;
  s.conditions.temperature = f.temperature;
  s.conditions.precipitation = f.precipitation;
  s.conditions.windDirection = f.windDirection;
  s.conditions.windIntensity = f.windIntensity;
  s.conditions.sunDirection = f.sunDirection;
  s.conditions.sunIntensity = f.sunIntensity;
  s.time = f.time;
  s.levels.snow = f.snowLevel;
  s.levels.wetness = f.wetnessLevel;
  s.levels.moss = f.mossLevel;
  s.levels.frost = f.frostLevel;
  s.levels.puddles = f.puddleLevel;
  return s;
}


// Sets the request's debug view from --aov and its weather from the --weather lists
// over `inputs` (eval's names and checks). Returns a usage error, or "".
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
  request.weather = weatherFromFrame(inputs.frame);
  return "";
}

// The snowfield: deep snow (level 1) on a cold, clear day with the scene's low sun,
// unless --weather says otherwise.
int renderSnowfieldScene(const std::vector<std::string>& weatherLists, RenderRequest request, const std::string& aov,
                         const std::optional<std::string>& preset, const std::string& output, const std::string& framesDir,
                         const std::string& device, const std::string& graphsDir, bool validation, bool quiet) {
  constexpr float kColdDay = -6.f;
  EvalInputs inputs = defaultEvalInputs();
  glm::vec3 sun = snow::snowfieldTowardsSun();
  inputs.frame.sunDirection = {sun.x, sun.y, sun.z};
  inputs.frame.temperature = kColdDay;
  inputs.frame.snowLevel = 1.f;
  inputs.frame.sunIntensity = 1.f;
  inputs.frame.windIntensity = 0.f;
  if (std::string e = applyAovAndWeather(aov, weatherLists, inputs, request); !e.empty()) return usageError(e);
  request.weatherPreset = preset;
  SnowfieldRenderOptions options{output, framesDir, device, graphsDir, request, validation,
                                 !quiet && ::isatty(STDERR_FILENO)};
  try {
    return renderSnowfield(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "weathergen: error: %s\n", e.what());
    return kExitInternal;
  }
}

}  // namespace

int runRenderCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2);
  std::string sceneName, camera, output, timelinePath, aov = "lit", device, graphsDir = bundledGraphsDirectory(), framesDir;
  std::optional<std::string> preset;
  std::vector<std::string> weatherLists;
  RenderRequest request;
  double step = 300.0;
  bool validation = false, quiet = false;
  while (!cl.done()) {
    std::string error;
    if (cl.flag("-h") || cl.flag("--help")) {
      std::fputs(kRenderUsage, stdout);
      return kExitOk;
    }
    if (cl.flag("--validation")) { validation = true; continue; }
    if (cl.flag("--no-shadows")) { request.shadows = false; continue; }
    if (cl.flag("-q") || cl.flag("--quiet")) { quiet = true; continue; }
    auto value = [&](const char* name, std::string& out) {
      if (auto v = cl.valueFor(name, error)) {
        out = *v;
        return true;
      }
      return false;
    };
    std::string v;
    if (value("--scene", sceneName) || value("--camera", camera) || value("-o", output) || value("--output", output) ||
        value("--timeline", timelinePath) || value("--aov", aov) || value("--device", device) || value("--graphs", graphsDir) || value("--frames", framesDir))
      continue;
    if (value("--weather", v)) { weatherLists.push_back(v); continue; }
    if (value("--weather-preset", v)) {
      if (std::string e = checkWeatherPresetName(v); !e.empty()) return usageError(e);
      preset = v;
      continue;
    }
    if (value("--backend", v)) {
      if (v != "glsl" && v != "hlsl") return usageError("--backend takes glsl or hlsl");
      request.backend = v == "glsl" ? ShaderLanguage::Glsl : ShaderLanguage::Hlsl;
      continue;
    }
    if (value("--size", v)) {
      unsigned w = 0, h = 0;
      constexpr unsigned kMaxSide = 8192;
      if (std::sscanf(v.c_str(), "%ux%u", &w, &h) != 2 || w == 0 || h == 0 || w > kMaxSide || h > kMaxSide)
        return usageError("--size takes WxH, each from 1 to 8192 (e.g. 1920x1080)");
      request.width = w;
      request.height = h;
      continue;
    }
    if (value("--step", v)) {
      char* end = nullptr;
      step = std::strtod(v.c_str(), &end);
      if (*end || !(step > 0.0) || !std::isfinite(step)) return usageError("--step takes a positive number of seconds");
      continue;
    }
    if (!error.empty()) return usageError(error);
    return usageError("unknown option '" + quoteUserText(cl.peek()) + "'");
  }
  if (sceneName.empty()) return usageError("no scene; pass --scene NAME (valley, rocks, river, road or snowfield)");
  if (output.empty()) return usageError("no output; pass -o OUT.png");
  if (!timelinePath.empty() && !weatherLists.empty()) return usageError("--weather and --timeline exclude each other");
  if (graphsDir.empty()) return usageError("cannot find the bundled graphs next to this executable; pass --graphs DIR");
  if (sceneName == snow::kSnowfieldScene) {
    if (!timelinePath.empty() || !camera.empty()) return usageError("the snowfield scene has its own camera path and timeline");
    return renderSnowfieldScene(weatherLists, request, aov, preset, output, framesDir, device, graphsDir, validation, quiet);
  }
  auto scene = scene::makeScene(sceneName);
  if (!scene) {
    std::string names;
    for (auto n : scene::sceneNames()) names += (names.empty() ? "" : ", ") + std::string(n);
    return usageError("unknown scene '" + quoteUserText(sceneName) + "' (scenes: " + names + ")");
  }
  if (!camera.empty()) {
    bool found = false;
    std::string names;
    for (const auto& c : scene->cameras) {
      found = found || c.name == camera;
      names += (names.empty() ? "" : ", ") + c.name;
    }
    if (!found) return usageError("scene '" + sceneName + "' has no camera '" + quoteUserText(camera) + "' (cameras: " + names + ")");
  }
  request.camera = camera;
  request.weatherPreset = preset;

  // The weather: eval's names and checks; the sun comes from the scene unless given.
  EvalInputs inputs = defaultEvalInputs();
  inputs.frame.sunDirection = {scene->towardsSun.x, scene->towardsSun.y, scene->towardsSun.z};
  if (std::string e = applyAovAndWeather(aov, weatherLists, inputs, request); !e.empty()) return usageError(e);

  std::optional<WeatherTimeline> timeline;
  if (!timelinePath.empty()) {
    std::ifstream in(timelinePath);
    if (!in) return usageError("cannot read timeline '" + quoteUserText(timelinePath) + "'");
    auto json = nlohmann::json::parse(in, nullptr, false);
    std::string error = json.is_discarded() ? "malformed JSON" : "";
    if (error.empty()) timeline = parseWeatherTimeline(json, error);
    if (!timeline) return usageError("timeline " + quoteUserText(timelinePath) + ": " + error);
  }

  bool progress = !quiet && ::isatty(STDERR_FILENO);
  try {
    std::string error;
    auto ctx = vk::Context::create({device, validation}, error);
    if (!ctx) {
      std::fprintf(stderr, "weathergen: error: %s\n", error.c_str());
      return kExitInternal;
    }
    if (progress) std::fprintf(stderr, "render: %s on %s\n", sceneName.c_str(), ctx->deviceName().c_str());
    SceneRenderer renderer(*ctx, std::move(*scene), graphsDir);
    auto checkValidation = [&]() {
      const auto& messages = ctx->validationMessages();
      if (messages.empty()) return true;
      constexpr std::size_t kShown = 5;  // the first few tell the story; the rest repeat
      for (std::size_t i = 0; i < messages.size() && i < kShown; ++i)
        std::fprintf(stderr, "vulkan validation %s\n", messages[i].c_str());
      std::fprintf(stderr, "weathergen: error: %zu Vulkan validation message(s)\n", messages.size());
      return false;
    };
    if (!timeline) {
      RenderedFrame frame = renderer.render(request);
      if (!checkValidation()) return kExitInternal;
      if (std::string e = image::writePng(output, toDisplayImage(frame)); !e.empty()) return usageError(e);
      if (progress) std::fprintf(stderr, "render: wrote %s (%ux%u)\n", output.c_str(), frame.width, frame.height);
      return kExitOk;
    }
    auto stages = renderTimeline(renderer, *timeline, request, step, [&](std::size_t i, std::size_t n, const std::string& label) {
      if (progress) std::fprintf(stderr, "render: [%zu/%zu] %s\n", i, n, label.c_str());
    });
    if (!checkValidation()) return kExitInternal;
    std::vector<image::LabelledFrame> frames;
    std::vector<Image> strip;
    for (const auto& stage : stages) {
      Image img = toDisplayImage(stage.frame);
      if (!framesDir.empty()) {
        std::filesystem::create_directories(framesDir);
        std::string path = (std::filesystem::path(framesDir) / (sceneName + "-" + stage.slug + ".png")).string();
        if (std::string e = image::writePng(path, img); !e.empty()) return usageError(e);
      }
      frames.push_back({img, stage.lines});
      strip.push_back(std::move(img));
    }
    std::string title = "weathergen  " + sceneName + "  (" + std::string(languageName(request.backend)) + ", " + aov + ")";
    constexpr int kSheetColumns = 3;
    if (std::string e = image::writePng(output, image::contactSheet(title, frames, kSheetColumns)); !e.empty()) return usageError(e);
    std::filesystem::path stripPath = std::filesystem::path(output).replace_extension(".strip.png");
    if (std::string e = image::writePng(stripPath.string(), image::frameStrip(strip)); !e.empty()) return usageError(e);
    if (progress) std::fprintf(stderr, "render: wrote %s and %s\n", output.c_str(), stripPath.string().c_str());
    return kExitOk;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "weathergen: error: %s\n", e.what());
    return kExitInternal;
  }
}

}  // namespace wg
