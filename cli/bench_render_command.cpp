// weathergen bench-render: GPU time of the colour pass (timestamp queries) with the
// weather injected against the same scene compiled with preset "none", for active
// and for neutral weather; medians over many frames. Prints a markdown table.
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/bundled_graphs_directory.hpp"
#include "cli/bench_options.hpp"
#include "cli/number_text.hpp"
#include "cli/model_scene.hpp"
#include "cli/render_to_files.hpp"
#include "cli/sample_count.hpp"
#include "compiler/literal.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/effect_overrides_option.hpp"
#include "host/material_compile_error.hpp"
#include "host/scene/graph_path.hpp"
#include "host/scene/preview_stand.hpp"
#include "host/scene_renderer.hpp"

namespace wg {

namespace {

constexpr const char* kUsage = R"(Usage: weathergen bench-render [--scene NAME|all | --material GRAPH.json |
                               --model MODEL.gltf [--model-scale S]]
                              [--frames N] [--size WxH] [--samples N] [--device NAME]
                              [--effects NAME=on|off,...]

Renders each scene (or the graph on the preview stand, as 'render --material' draws
it, or the glTF model on its stage, as 'render --model' does) N times (default 30,
after 3 warm-up rounds) per configuration, the four in turn, and prints the median
GPU time of the colour pass, from Vulkan timestamp queries:
  none      every material compiled with weather preset "none" (the baseline)
  neutral   dry and warm (every level 0): the runtime binds the unweathered variant
  neutral*  the same weather drawn with the weathered shaders (their uniform branch)
  active    the materials' own presets in mixed snow, rain, moss, frost and puddles
and the overheads against none (each the median of one round's ratios, so a machine
whose speed drifts slows both sides alike), the weather's absolute cost (active - none,
the median of one round's differences), then the process's peak memory. --effects
switches looks on or off in every weathered configuration, so two runs tell what a
look costs on this device (docs/weather-model.md, "Looks beyond the seed").
)";

constexpr int kWarmUpRounds = 3;  // rounds of all four configurations, not timed

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

struct BenchRenderOptions {
  std::string sceneArg = "all", device, size = "1920x1080", materialPath, modelPath;
  float modelScale = 1.f;
  std::optional<std::string> quality;
  WeatherEffectOverrides effects;
  int frames = 30;
  unsigned samples = kDefaultColourSamples;
  bool help = false;
};

std::string setModelScale(const std::string& v, float& modelScale) {
  const auto scale = parseNumberText(v);
  modelScale = scale ? static_cast<float>(*scale) : 0.f;
  if (!(modelScale >= 1e-6f && modelScale <= 1e6f)) return "--model-scale takes metres per model unit, from 1e-6 to 1e6";
  return "";
}

OptionTable benchRenderOptionTable(BenchRenderOptions& o) {
  return {.options = {
      {"--scene", "", "NAME|all", "a bundled scene, or all of them (default)", storeValue(o.sceneArg)},
      {"--material", "", "GRAPH.json", "a graph on the preview stand instead of the scenes", storeValue(o.materialPath)},
      {"--model", "", "MODEL.gltf", "a glTF model on its stage instead of the scenes", storeValue(o.modelPath)},
      {"--model-scale", "", "S", "with --model: metres per model unit",
       [&o](const std::string& v) { return setModelScale(v, o.modelScale); }},
      {"--frames", "", "N", "frames measured per configuration (default 30)",
       [&o](const std::string& v) { return setFrameCount(v, o.frames); }},
      {"--size", "", "WxH", "image size (default 1920x1080)", storeValue(o.size)},
      {"--samples", "", "N", "MSAA samples per pixel of the lit pass, 1 for none (default 4)",
       [&o](const std::string& v) { return setSampleCount(v, o.samples); }},
      {"--device", "", "NAME", "Vulkan device, as render takes it", storeValue(o.device)},
      {"--quality", "", "TIER", kQualityOptionHelp, storeChecked(o.quality, checkQualityTierName)},
      {"--effects", "", "LIST", kEffectsOptionHelp,
       [&o](const std::string& v) { return addEffectOverrides(v, o.effects); }},
      {"--help", "-h", "", "this help", storeFlag(o.help), true},
  }};
}

// The scenes to measure: the graph on the stand, the model on its stage, or the bundled
// scenes --scene names. Returns the exit code when there are none.
int chooseScenes(const BenchRenderOptions& o, ModelScene& model, std::vector<scene::Scene>& scenes) {
  if (!o.materialPath.empty() && !o.modelPath.empty()) return briefUsageError("--material and --model exclude each other");
  if (!o.materialPath.empty()) {
    if (!scene::isGraphFilePath(o.materialPath))
      return briefUsageError("--material takes a graph file ending in .json, not '" + quoteUserText(o.materialPath) + "'");
    scenes.push_back(scene::previewStand(o.materialPath, "stand-" + std::filesystem::path(o.materialPath).stem().string()));
    return kExitOk;
  }
  if (!o.modelPath.empty()) {
    if (int e = loadModelScene(o.modelPath, {}, o.modelScale, model)) return e;
    scenes.push_back(std::move(model.scene));
  }
  for (auto n : scene::sceneNames())
    if (o.modelPath.empty() && (o.sceneArg == "all" || o.sceneArg == n)) scenes.push_back(*scene::makeScene(n));
  if (scenes.empty()) return briefUsageError("unknown scene '" + quoteUserText(o.sceneArg) + "'");
  return kExitOk;
}

// The four configurations of the table: none, neutral, neutral* and active.
struct BenchRequests {
  RenderRequest none, neutral, branchOnly, active;
};

BenchRequests benchRequests(glm::vec3 sun, unsigned width, unsigned height, const BenchRenderOptions& o) {
  RenderRequest base;
  base.width = width;
  base.height = height;
  base.weatherEffects = o.effects;  // "none" compiles without weather, so without them or a tier
  base.quality = o.quality;
  base.weather.conditions.sunDirection = {sun.x, sun.y, sun.z};
  base.weather.conditions.temperature = 15.f;  // neutral: dry and warm, every level 0
  BenchRequests r{base, base, base, base};
  r.none.weatherPreset = "none";
  r.active.weather.conditions.temperature = 2.f;
  r.active.weather.conditions.precipitation = 0.6f;
  r.active.weather.levels = {0.6f, 0.7f, 0.5f, 0.4f, 0.6f, 0.f};
  r.branchOnly.unweatheredVariantWhenNeutral = false;
  return r;
}

// One configuration's frame times, and each against the same round's "none": as a ratio
// and as a difference in milliseconds.
struct Series {
  std::vector<double> ms, overNone, aboveNone;
};

// One scene's row of the table, and its device allocations in bytes.
struct SceneMeasurement {
  std::string row;
  std::size_t gpuBytes = 0;
};

// Measures one scene. The configurations take turns frame by frame: on shared cores whose speed drifts,
// measuring them one after another made "none" alone vary by a fifth between runs.
SceneMeasurement measureScene(vk::Context& ctx, scene::Scene scene, const std::string& graphsDir, unsigned width,
                              unsigned height, const BenchRenderOptions& o) {
  const BenchRequests requests = benchRequests(scene.towardsSun, width, height, o);
  const RenderRequest* order[] = {&requests.none, &requests.neutral, &requests.branchOnly, &requests.active};
  std::string name = scene.name;
  SceneRenderer renderer(ctx, std::move(scene), graphsDir, static_cast<VkSampleCountFlagBits>(o.samples));
  Series series[4];
  for (int round = 0; round < kWarmUpRounds + o.frames; ++round) {
    double ms[4];
    for (int c = 0; c < 4; ++c) ms[c] = renderer.render(*order[c]).gpuMilliseconds;
    if (round < kWarmUpRounds) continue;
    for (int c = 0; c < 4; ++c) {
      series[c].ms.push_back(ms[c]);
      if (ms[0] > 0.0) series[c].overNone.push_back(ms[c] / ms[0]);
      series[c].aboveNone.push_back(ms[c] - ms[0]);
    }
  }
  // The stand's and a model's names carry the file's stem: user text, escaped.
  char numbers[256];
  std::snprintf(numbers, sizeof numbers, " | %.2f | %.2f | %.2f | %.2f | %.3f | %.3f | %.3f | %.2f |\n",
                median(series[0].ms), median(series[1].ms), median(series[2].ms), median(series[3].ms),
                median(series[1].overNone), median(series[2].overNone), median(series[3].overNone),
                median(series[3].aboveNone));
  return {"| " + quoteUserText(name, 200) + numbers, renderer.gpuMemoryBytes()};
}

int measureScenes(std::vector<scene::Scene>& scenes, const BenchRenderOptions& asked, unsigned width, unsigned height,
                  const std::string& graphsDir, const std::vector<ImportedOrigin>& modelOrigins) {
  std::string error;
  auto ctx = vk::Context::create({asked.device, false}, error);
  if (!ctx) return deviceUnavailable(error, asked.device);
  BenchRenderOptions o = asked;  // with the samples the frame fits at
  o.samples = samplesThatFit(*ctx, width, height, asked.samples);
  if (o.samples == 0) return kExitBadInput;
  // The header comes with the first row, so a graph that does not compile prints only its errors.
  const auto printHeader = [&] {
    std::printf("Device: %s. %ux%u, up to %ux MSAA, median of %d frames per configuration, the four in turn (after %d "
                "warm-up rounds), colour pass only.\n\n",
                ctx->deviceName().c_str(), width, height, o.samples, o.frames, kWarmUpRounds);
    if (o.quality) std::printf("Quality tier of every weathered configuration: %s.\n\n", o.quality->c_str());
    if (!o.effects.empty())
      std::printf("Effects switched in every weathered configuration: %s.\n\n", effectOverridesText(o.effects).c_str());
    std::printf("| scene | none (ms) | neutral (ms) | neutral* (ms) | active (ms) | neutral / none | neutral* / none | "
                "active / none | active - none (ms) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
  };
  std::size_t gpuBytes = 0;
  try {
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      const SceneMeasurement measured = measureScene(*ctx, std::move(scenes[i]), graphsDir, width, height, o);
      if (i == 0) printHeader();
      std::fputs(measured.row.c_str(), stdout);
      std::fflush(stdout);
      gpuBytes = std::max(gpuBytes, measured.gpuBytes);
    }
  } catch (const MaterialCompileError& e) {  // a user's graph (--material, --model) that does not compile
    printDiagnostics(inModelTerms(e.diagnostics(), modelOrigins), false);
    return kExitBadInput;
  } catch (const vk::OutOfMemory& e) {
    return reportOutOfMemory(e);
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("\nPeak resident memory of the process: %.1f MiB (ru_maxrss). Largest scene's device allocations "
              "(meshes, textures, maps): %.1f MiB, plus per-frame colour and depth targets.\n",
              usage.ru_maxrss / 1024.0, gpuBytes / (1024.0 * 1024.0));
  return kExitOk;
}

}  // namespace

int runBenchRenderCommand(int argc, char** argv) {
  BenchRenderOptions o;
  if (auto exit = parseBenchOptions(benchRenderOptionTable(o), argc, argv, o.help, kUsage)) return *exit;
  constexpr std::uint32_t kMaxSide = 8192;
  const auto pixels = parsePixelSizeText(o.size, kMaxSide);
  if (!pixels) return briefUsageError("--size takes WxH, each a whole number from 1 to 8192");
  const std::string graphsDir = bundledGraphsDirectory();
  if (graphsDir.empty()) return briefUsageError("cannot find the bundled graphs next to this executable");
  std::vector<scene::Scene> scenes;
  ModelScene model;  // keeps the model's imported graphs while it is drawn
  if (int e = chooseScenes(o, model, scenes)) return e;
  return measureScenes(scenes, o, pixels->width, pixels->height, graphsDir, model.origins);
}

}  // namespace wg
