#include "cli/render_options.hpp"

#include "cli/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cli/bundled_graphs_directory.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/effect_overrides_option.hpp"
#include "cli/option_table.hpp"
#include "host/scene/scene.hpp"
#include "cli/orbit_camera_option.hpp"
#include "compiler/literal.hpp"

namespace wg {

std::string sceneNameList() {
  std::string names;
  for (auto n : scene::sceneNames()) names += std::string(n) + ", ";
  names.resize(names.size() - 2);
  return names + " or snowfield";
}

namespace {

constexpr const char* kRenderUsage = R"(Usage: weathergen render (--scene NAME | --material GRAPH.json | --model MODEL.gltf) -o OUT.png [options]

Options:
)";

// --size WxH; "" or a usage message.
std::string parseSize(const std::string& v, RenderRequest& request) {
  constexpr std::uint32_t kMaxSide = 8192;
  const auto size = parsePixelSizeText(v, kMaxSide);
  if (!size) return "--size takes WxH, each a whole number from 1 to 8192 (e.g. 1920x1080)";
  request.width = size->width;
  request.height = size->height;
  return "";
}

std::string parseStep(const std::string& v, double& step) {
  const auto seconds = parseNumberText(v);
  if (!seconds || !(*seconds > 0.0) || !std::isfinite(*seconds)) return "--step takes a positive number of seconds";
  step = *seconds;
  return "";
}

std::string parseWatchRenders(const std::string& v, std::optional<unsigned>& count) {
  constexpr std::uint32_t kMaxRenders = 1000000;
  const auto n = parseCountText(v, 1, kMaxRenders);
  if (!n) return "--watch-renders takes a whole number of renders from 1 to 1000000";
  count = *n;
  return "";
}

std::string parseModelScale(const std::string& v, float& scale) {
  const auto s = parseNumberText(v);
  if (!s || !(*s >= 1e-6 && *s <= 1e6)) return "--model-scale takes metres per model unit, from 1e-6 to 1e6 (0.001 for millimetres)";
  scale = static_cast<float>(*s);
  return "";
}

std::string parseCamera(const std::string& v, RenderOptions& o) {
  o.camera = v;
  o.orbit.reset();
  if (!isOrbitCamera(v)) return "";
  std::string error;
  o.orbit = parseOrbitCamera(v, error);
  return error;
}

std::string setBackend(const std::string& v, RenderRequest& request) {
  if (v != "glsl" && v != "hlsl") return "--backend takes glsl or hlsl";
  request.backend = v == "glsl" ? ShaderLanguage::Glsl : ShaderLanguage::Hlsl;
  return "";
}

// --scene's help: the bundled scenes (list-scenes) and the snowfield.
std::string_view sceneOptionHelp() {
  static const std::string help = sceneNameList() +
                                  " (interactive snow:\n"
                                  "walkers, a vehicle and a camera that leaves and returns;\n"
                                  "writes OUT.png as a contact sheet and OUT.strip.png)";
  return help;
}

// Where the scene comes from, and how it is looked at.
std::vector<Option> sceneOptions(RenderOptions& o) {
  return {
      {"--scene", "", "NAME", sceneOptionHelp(), storeValue(o.sceneName)},
      {"--material", "", "GRAPH.json",
       "any material graph on the preview stand: a sphere, a rock,\n"
       "a 45 degree ramp and a cube on a post, on open ground next\n"
       "to a small roof",
       storeValue(o.materialPath)},
      {"--model", "", "MODEL.gltf|glb",
       "a glTF 2.0 model on a ground plane, every mesh drawn with\n"
       "its imported material weathered (rock unless\n"
       "--weather-preset or --preset-map says otherwise)",
       storeValue(o.modelPath)},
      {"--preset-map", "", "RULES", "with --model: 'GLOB=PRESET,...' per material name, as\n'weathergen import' takes it",
       [&o](const std::string& v) { return setPresetMap(v, o.presetMap); }},
      {"--model-scale", "", "S",
       "with --model: metres per model unit (glTF says 1; 0.001\nfor a model authored in millimetres)",
       [&o](const std::string& v) { return parseModelScale(v, o.modelScale); }},
      {"--snow-displacement", "", "", "with --model: keep the snow displacement, as import takes it",
       storeFlag(o.snowDisplacement)},
      {"--camera", "", "NAME",
       "a camera preset of the scene (default: its first); the\nstand has front, sun-side, shade-side and close-up",
       [&o](const std::string& v) { return parseCamera(v, o); }},
      {"--camera", "", "orbit:AZ,EL[,D]",
       "any view of the scene's centre: azimuth (degrees from +z\n"
       "towards +x), elevation (degrees, -89 to 89), distance\n"
       "(metres; default: framed to the scene)",
       nullptr},
  };
}

// The weather, over time or at once.
std::vector<Option> weatherOptions(RenderOptions& o) {
  return {
      {"--weather", "", "k=v,...",
       "weather state, as 'weathergen eval --help' lists it\n(temperature, precipitation, snowLevel, wetnessLevel, ...)",
       [&o](const std::string& v) {
         o.weatherLists.push_back(v);
         return std::string();
       }},
      {"--timeline", "", "FILE",
       "scripted weather (timelines/seasons.json): writes\n"
       "OUT.png as a labelled contact sheet, one frame per stage,\n"
       "and OUT.strip.png as a frame strip",
       storeValue(o.timelinePath)},
      {"--step", "", "SECONDS", "simulation step for --timeline (default 300)",
       [&o](const std::string& v) { return parseStep(v, o.step); }},
      {"--frames", "", "DIR", "with --timeline: also write each stage as DIR/SCENE-NN-LABEL.png",
       storeValue(o.framesDir)},
      {"--weather-preset", "", "NAME", "replace every material's preset (none for a baseline)",
       [&o](const std::string& v) {
         o.weatherPreset = v;
         return checkWeatherPresetName(v);
       }},
      {"--quality", "", "TIER", kQualityOptionHelp, storeChecked(o.request.quality, checkQualityTierName)},
      {"--effects", "", "LIST", kEffectsOptionHelp,
       [&o](const std::string& v) { return addEffectOverrides(v, o.request.weatherEffects); }},
  };
}

// How it is drawn, and where to.
std::vector<Option> outputOptions(RenderOptions& o) {
  return {
      {"--output", "-o", "OUT.png", "", storeValue(o.output)},  // in the usage line
      {"--backend", "", "glsl|hlsl", "which emitted SPIR-V to draw with (default glsl)",
       [&o](const std::string& v) { return setBackend(v, o.request); }},
      {"--size", "", "WxH", "image size (default 960x540)", [&o](const std::string& v) { return parseSize(v, o.request); }},
      {"--samples", "", "N", "MSAA samples per pixel of lit frames: 1 (none), 2, 4\nor 8 (default 4; fewer where the device has fewer)",
       [&o](const std::string& v) { return setSampleCount(v, o.samples); }},
      {"--aov", "", "NAME",
       "lit, albedo, roughness, normal, snow, wet, moss, frost,\nice, puddle or density (default lit)",
       storeValue(o.aov)},
      {"--device", "", "NAME",
       "Vulkan device: cpu, gpu, integrated, discrete or a name\n(default: the CPU device, lavapipe)",
       storeValue(o.device)},
      {"--validation", "", "", "enable the Vulkan validation layers; any message fails", storeFlag(o.validation)},
      {"--no-shadows", "", "", "draw without the sun shadow map", storeFlag(o.request.shadows, false)},
      {"--no-precipitation", "", "",
       "no falling snow or rain near the viewer (lit frames draw\nit from the weather's precipitation; AOVs never do)",
       storeFlag(o.request.precipitation, false)},
  };
}

// Rendering again on every change, and what the rest needs.
std::vector<Option> watchAndOtherOptions(RenderOptions& o) {
  return {
      {"--watch", "", "",
       "with --material or --model: render, then render again whenever the\n"
       "graph, a library it includes, an image it reads or the model\n"
       "(and its buffers and images) changes\n"
       "(one line per render; errors keep the last good image);\n"
       "Ctrl-C stops",
       storeFlag(o.watch)},
      {"--watch-renders", "", "N",
       "with --watch: stop after N renders, failed ones included\n(for scripts and tests)",
       [&o](const std::string& v) { return parseWatchRenders(v, o.watchRenders); }},
      {"--graphs", "", "DIR",
       "where the bundled graphs live (default: found next to the\n"
       "executable: the source tree, or share/weathergen/graphs)",
       storeValue(o.graphsDir)},
      {"--quiet", "-q", "", "no progress output", storeFlag(o.quiet)},
  };
}

// `help` is set by --help, which ends the parse.
OptionTable renderOptionTable(RenderOptions& o, bool& help) {
  OptionTable table{.helpColumn = 26};
  for (auto part : {sceneOptions, weatherOptions, outputOptions, watchAndOtherOptions})
    for (auto& option : part(o)) table.options.push_back(std::move(option));
  table.options.push_back({"--help", "-h", "", "", storeFlag(help), true});
  return table;
}

}  // namespace

std::optional<int> parseRenderOptions(int argc, char** argv, int first, RenderOptions& o) {
  o.graphsDir = bundledGraphsDirectory();
  o.request.precipitation = true;  // render draws it unless --no-precipitation
  bool help = false;
  const OptionTable table = renderOptionTable(o, help);
  const OptionParseResult parsed = parseOptions(table, argc, argv, first);
  if (parsed.status == OptionParse::Failed) return usageError(parsed.error);
  if (help) {
    std::fputs((kRenderUsage + formatOptionList(table)).c_str(), stdout);
    return kExitOk;
  }
  return std::nullopt;
}

}  // namespace wg
