// weathergen render: draws a scene with the emitted shaders on Vulkan (lavapipe by
// default) and writes a PNG, or for a timeline a frame strip and a labelled contact
// sheet. The scene comes from --scene or --material (render_scene_source.hpp); the
// rest is shared, including --watch.
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "compiler/literal.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/render_options.hpp"
#include "cli/render_plan.hpp"
#include "cli/render_scene_source.hpp"
#include "cli/render_to_files.hpp"
#include "cli/render_watch.hpp"
#include "cli/snowfield_render.hpp"
#include "host/snowfield/snowfield_scene.hpp"

namespace wg {

namespace {

// The snowfield: deep snow (level 1) on a cold, clear day with the scene's low sun,
// unless --weather says otherwise.
int renderSnowfieldScene(const RenderOptions& o) {
  if (!o.timelinePath.empty() || !o.camera.empty()) return usageError("the snowfield scene has its own camera path and timeline");
  if (o.watch) return usageError("--watch takes --material");
  constexpr float kColdDay = -6.f;
  EvalInputs inputs = defaultEvalInputs();
  glm::vec3 sun = snow::snowfieldTowardsSun();
  inputs.frame.sunDirection = {sun.x, sun.y, sun.z};
  inputs.frame.temperature = kColdDay;
  inputs.frame.snowLevel = 1.f;
  inputs.frame.sunIntensity = 1.f;
  inputs.frame.windIntensity = 0.f;
  RenderRequest request = o.request;
  if (std::string e = applyAovAndWeather(o.aov, o.weatherLists, inputs, request); !e.empty()) return usageError(e);
  request.weatherPreset = o.weatherPreset;
  SnowfieldRenderOptions options{o.output,  o.framesDir,  o.device, o.graphsDir,
                                 request,   o.validation, !o.quiet && ::isatty(STDERR_FILENO), o.samples};
  try {
    return renderSnowfield(options);
  } catch (const vk::OutOfMemory& e) {
    return reportOutOfMemory(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "weathergen: error: %s\n", quoteUserText(e.what(), 1000).c_str());
    return kExitInternal;
  }
}

// --frames DIR is created when the stages are written: a file on its way fails now.
std::string checkFramesFolder(const std::string& framesDir) {
  std::error_code ec;
  for (std::filesystem::path p = std::filesystem::absolute(framesDir, ec); !p.empty(); p = p.parent_path()) {
    if (std::filesystem::exists(p, ec) && !std::filesystem::is_directory(p, ec))
      return "--frames '" + quoteUserText(framesDir) + "': '" + quoteUserText(p.string()) + "' is a file; name a directory";
    if (p == p.parent_path()) break;
  }
  return "";
}

// Checks between options, before anything is built.
std::string checkRenderOptions(const RenderOptions& o) {
  if (std::string e = checkOneSceneSource(o); !e.empty()) return e;
  if (o.output.empty()) return "no output; pass -o OUT.png";
  if (!o.timelinePath.empty() && !o.weatherLists.empty()) return "--weather and --timeline exclude each other";
  if (o.graphsDir.empty()) return "cannot find the bundled graphs next to this executable; pass --graphs DIR";
  if (o.watch && o.materialPath.empty() && o.modelPath.empty()) return "--watch takes --material or --model";
  if ((!o.presetMap.empty() || o.modelScale != 1.f || o.snowDisplacement) && o.modelPath.empty())
    return "--preset-map, --model-scale and --snow-displacement take --model";
  if (!o.presetMap.empty() && o.weatherPreset) return "--weather-preset and --preset-map exclude each other";
  if (o.watchRenders && !o.watch) return "--watch-renders takes --watch";
  if (!o.framesDir.empty())
    if (std::string e = checkFramesFolder(o.framesDir); !e.empty()) return e;
  return "";
}

// The scene and what to draw of it: checked before a device is opened.
struct PreparedRender {
  SceneSource source;
  RenderPlan plan;
};

// The outputs are checked against the scene's files and the timeline here, before a
// device is opened, and against the materials' files once they are compiled.
int prepareRender(const RenderOptions& o, PreparedRender& prepared) {
  if (int e = chooseScene(o, prepared.source)) return e;
  RenderPlan& plan = prepared.plan;
  if (std::string e = makeRenderPlan(o, prepared.source.scene, plan); !e.empty()) return usageError(e);
  plan.inputs.add(prepared.source.inputFiles);
  plan.modelOrigins = prepared.source.origins;
  const auto outputs = plannedOutputs(plan, prepared.source.scene.name);
  if (std::string e = plan.inputs.checkOutputs(outputs); !e.empty()) return usageError(e);
  if (std::string e = checkNoSpecialFiles(outputs); !e.empty()) return usageError(e);
  return kExitOk;
}

// Draws it and writes the pictures: what one render and each --watch render do.
WatchedRender renderPrepared(PreparedRender prepared, vk::Context& ctx, const std::string& graphsDir) {
  SceneSource& source = prepared.source;
  if (prepared.plan.progress) std::fprintf(stderr, "render: %s on %s\n", quoteUserText(source.scene.name).c_str(), ctx.deviceName().c_str());
  RenderedFiles files = renderToFiles(ctx, std::move(source.scene), prepared.plan, graphsDir);
  if (files.exitCode != kExitOk) return {files.exitCode, {}};
  std::vector<std::string> read = std::move(source.inputFiles);
  read.insert(read.end(), files.materialInputs.begin(), files.materialInputs.end());
  return {kExitOk, std::move(read)};
}

// Renders the prepared scene, then (--watch) prepares and renders again on each change.
int renderAndWatch(const RenderOptions& o, PreparedRender first, vk::Context& ctx) {
  if (!o.watch) return renderPrepared(std::move(first), ctx, o.graphsDir).exitCode;
  std::optional<PreparedRender> pending = std::move(first);
  auto render = [&]() -> WatchedRender {
    PreparedRender prepared;
    if (pending) prepared = std::move(*pending), pending.reset();
    else if (int e = prepareRender(o, prepared)) return {e, {}};
    return renderPrepared(std::move(prepared), ctx, o.graphsDir);
  };
  WatchSettings watch{{o.materialPath.empty() ? o.modelPath : o.materialPath}, o.output, o.watchRenders};
  watch.announce = !o.quiet;
  return watchAndRender(render, watch);
}

}  // namespace

int runRenderCommand(int argc, char** argv) {
  RenderOptions o;
  if (auto exit = parseRenderOptions(argc, argv, 2, o)) return *exit;
  if (std::string e = checkRenderOptions(o); !e.empty()) return usageError(e);
  if (o.sceneName == snow::kSnowfieldScene) return renderSnowfieldScene(o);
  PreparedRender prepared;
  if (int e = prepareRender(o, prepared)) return e;
  std::string error;
  auto ctx = vk::Context::create({o.device, o.validation}, error);
  if (!ctx) return deviceUnavailable(error, o.device);
  return renderAndWatch(o, std::move(prepared), *ctx);
}

}  // namespace wg
