// weathergen bench-render: GPU time of the colour pass (timestamp queries) with the
// weather injected against the same scene compiled with preset "none", for active
// and for neutral weather; medians over many frames. Prints a markdown table.
#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/bundled_graphs_directory.hpp"
#include "cli/number_text.hpp"
#include "cli/command_line.hpp"
#include "cli/model_scene.hpp"
#include "compiler/literal.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "runtime/scene_renderer.hpp"

namespace wg {

namespace {

constexpr const char* kUsage = R"(Usage: weathergen bench-render [--scene NAME|all | --model MODEL.gltf [--model-scale S]]
                              [--frames N] [--size WxH] [--device NAME]

Renders each scene (or the glTF model on its stage, as 'render --model' draws it) N times (default 30, after 3 warm-up frames) per configuration and
prints the median GPU time of the colour pass, from Vulkan timestamp queries:
  none      every material compiled with weather preset "none" (the baseline)
  neutral   dry and warm (every level 0): the runtime binds the unweathered variant
  neutral*  the same weather drawn with the weathered shaders (their uniform branch)
  active    the materials' own presets in mixed snow, rain, moss, frost and puddles
and the overheads against none, then the process's peak memory.
)";

constexpr int kWarmUpFrames = 3;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

}  // namespace

int runBenchRenderCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2);
  std::string sceneArg = "all", device, size = "1920x1080", modelPath;
  float modelScale = 1.f;
  int frames = 30;
  while (!cl.done()) {
    std::string error, v;
    if (cl.flag("-h") || cl.flag("--help")) {
      std::fputs(kUsage, stdout);
      return kExitOk;
    }
    if (auto x = cl.valueFor("--scene", error)) { sceneArg = *x; continue; }
    if (auto x = cl.valueFor("--device", error)) { device = *x; continue; }
    if (auto x = cl.valueFor("--model", error)) { modelPath = *x; continue; }
    if (auto x = cl.valueFor("--model-scale", error)) {
      const auto scale = parseNumberText(*x);
      modelScale = scale ? static_cast<float>(*scale) : 0.f;
      if (!(modelScale >= 1e-6f && modelScale <= 1e6f)) error = "--model-scale takes metres per model unit, from 1e-6 to 1e6";
      else continue;
    }
    if (auto x = cl.valueFor("--size", error)) { size = *x; continue; }
    if (auto x = cl.valueFor("--frames", error)) {
      constexpr std::uint32_t kMaxFrames = 1000000;
      const auto count = parseCountText(*x, 1, kMaxFrames);
      frames = count ? static_cast<int>(*count) : 0;
      if (frames < 1) error = "--frames takes a whole number of frames from 1 to 1000000";
      else continue;
    }
    std::fprintf(stderr, "weathergen: error WG9001: %s\n", error.empty() ? ("unknown option '" + quoteUserText(cl.peek()) + "'").c_str() : error.c_str());
    return kExitUsage;
  }
  constexpr std::uint32_t kMaxSide = 8192;
  const auto pixels = parsePixelSizeText(size, kMaxSide);
  if (!pixels) {
    std::fprintf(stderr, "weathergen: error WG9001: --size takes WxH, each a whole number from 1 to 8192\n");
    return kExitUsage;
  }
  const unsigned width = pixels->width, height = pixels->height;
  const std::string graphsDir = bundledGraphsDirectory();
  if (graphsDir.empty()) {
    std::fprintf(stderr, "weathergen: error WG9001: cannot find the bundled graphs next to this executable\n");
    return kExitUsage;
  }
  std::vector<scene::Scene> scenes;
  ModelScene model;  // keeps the model's imported graphs while it is drawn
  if (!modelPath.empty()) {
    if (int e = loadModelScene(modelPath, {}, modelScale, model)) return e;
    scenes.push_back(std::move(model.scene));
  }
  for (auto n : scene::sceneNames())
    if (modelPath.empty() && (sceneArg == "all" || sceneArg == n)) scenes.push_back(*scene::makeScene(n));
  if (scenes.empty()) {
    std::fprintf(stderr, "weathergen: error WG9001: unknown scene '%s'\n", quoteUserText(sceneArg).c_str());
    return kExitUsage;
  }
  std::string error;
  auto ctx = vk::Context::create({device, false}, error);
  if (!ctx) return deviceUnavailable(error, device);
  std::printf("Device: %s. %ux%u, median of %d frames (after %d warm-up frames), colour pass only.\n\n",
              ctx->deviceName().c_str(), width, height, frames, kWarmUpFrames);
  std::printf("| scene | none (ms) | neutral (ms) | neutral* (ms) | active (ms) | neutral / none | neutral* / none | active / none |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  std::size_t gpuBytes = 0;
  for (auto& scene : scenes) {
    glm::vec3 sun = scene.towardsSun;
    std::string name = scene.name;
    SceneRenderer renderer(*ctx, std::move(scene), graphsDir);
    auto measure = [&](const RenderRequest& request) {
      std::vector<double> times;
      for (int i = 0; i < kWarmUpFrames + frames; ++i) {
        double ms = renderer.render(request).gpuMilliseconds;
        if (i >= kWarmUpFrames) times.push_back(ms);
      }
      return median(times);
    };
    RenderRequest base;
    base.width = width;
    base.height = height;
    base.weather.conditions.sunDirection = {sun.x, sun.y, sun.z};
    base.weather.conditions.temperature = 15.f;  // neutral: dry and warm, every level 0
    RenderRequest none = base;
    none.weatherPreset = "none";
    RenderRequest active = base;
    active.weather.conditions.temperature = 2.f;
    active.weather.conditions.precipitation = 0.6f;
    active.weather.levels = {0.6f, 0.7f, 0.5f, 0.4f, 0.6f, 0.f};
    RenderRequest branchOnly = base;
    branchOnly.unweatheredVariantWhenNeutral = false;
    double tNone = measure(none), tNeutral = measure(base), tBranch = measure(branchOnly), tActive = measure(active);
    std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.3f | %.3f | %.3f |\n", name.c_str(), tNone, tNeutral, tBranch, tActive,
                tNeutral / tNone, tBranch / tNone, tActive / tNone);
    std::fflush(stdout);
    gpuBytes = std::max(gpuBytes, renderer.gpuMemoryBytes());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("\nPeak resident memory of the process: %.1f MiB (ru_maxrss). Largest scene's device allocations "
              "(meshes, textures, maps): %.1f MiB, plus per-frame colour and depth targets.\n",
              usage.ru_maxrss / 1024.0, gpuBytes / (1024.0 * 1024.0));
  return kExitOk;
}

}  // namespace wg
