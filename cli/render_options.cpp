#include "cli/render_options.hpp"

#include "cli/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cli/bundled_graphs_directory.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/orbit_camera_option.hpp"
#include "compiler/literal.hpp"

namespace wg {

namespace {

constexpr const char* kRenderUsage = R"(Usage: weathergen render (--scene NAME | --material GRAPH.json | --model MODEL.gltf) -o OUT.png [options]

Options:
  --scene NAME              valley, rocks, river, road or snowfield (interactive snow:
                            walkers, a vehicle and a camera that leaves and returns;
                            writes OUT.png as a contact sheet and OUT.strip.png)
  --material GRAPH.json     any material graph on the preview stand: a sphere, a rock,
                            a 45 degree ramp and a cube on a post, on open ground next
                            to a small roof
  --model MODEL.gltf|glb    a glTF 2.0 model on a ground plane, every mesh drawn with
                            its imported material weathered (rock unless
                            --weather-preset or --preset-map says otherwise)
  --preset-map RULES        with --model: 'GLOB=PRESET,...' per material name, as
                            'weathergen import' takes it
  --model-scale S           with --model: metres per model unit (glTF says 1; 0.001
                            for a model authored in millimetres)
  --snow-displacement       with --model: keep the snow displacement, as import takes it
  --camera NAME             a camera preset of the scene (default: its first); the
                            stand has front, sun-side, shade-side and close-up
  --camera orbit:AZ,EL[,D]  any view of the scene's centre: azimuth (degrees from +z
                            towards +x), elevation (degrees, -89 to 89), distance
                            (metres; default: framed to the scene)
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
  --watch                   with --material or --model: render, then render again whenever the
                            graph, a library it includes, an image it reads or the model
                            (and its buffers and images) changes
                            (one line per render; errors keep the last good image);
                            Ctrl-C stops
  --watch-renders N         with --watch: stop after N renders, failed ones included
                            (for scripts and tests)
  --graphs DIR              where the bundled graphs live (default: found next to the
                            executable: the source tree, or share/weathergen/graphs)
  -q, --quiet               no progress output
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

// One of kValueOptions with its value; "" or a usage message.
std::string parseValueOption(const std::string& name, const std::string& v, RenderOptions& o) {
  if (name == "--scene") o.sceneName = v;
  else if (name == "--material") o.materialPath = v;
  else if (name == "--model") o.modelPath = v;
  else if (name == "--preset-map") {
    if (v.empty()) return "--preset-map takes rules, e.g. '*Leaf*=foliage,*=rock'";
    o.presetMap = v;
  }
  else if (name == "--model-scale") return parseModelScale(v, o.modelScale);
  else if (name == "--camera") return parseCamera(v, o);
  else if (name == "-o" || name == "--output") o.output = v;
  else if (name == "--timeline") o.timelinePath = v;
  else if (name == "--aov") o.aov = v;
  else if (name == "--device") o.device = v;
  else if (name == "--graphs") o.graphsDir = v;
  else if (name == "--frames") o.framesDir = v;
  else if (name == "--weather") o.weatherLists.push_back(v);
  else if (name == "--weather-preset") {
    o.weatherPreset = v;
    return checkWeatherPresetName(v);
  } else if (name == "--backend") {
    if (v != "glsl" && v != "hlsl") return "--backend takes glsl or hlsl";
    o.request.backend = v == "glsl" ? ShaderLanguage::Glsl : ShaderLanguage::Hlsl;
  } else if (name == "--size") return parseSize(v, o.request);
  else if (name == "--step") return parseStep(v, o.step);
  else if (name == "--watch-renders") return parseWatchRenders(v, o.watchRenders);
  return "";
}

constexpr const char* kValueOptions[] = {"--scene", "--material", "--model", "--preset-map", "--model-scale", "--camera",         "-o",      "--output",
                                         "--timeline", "--aov",     "--device",         "--graphs", "--frames",
                                         "--weather", "--weather-preset", "--backend",  "--size",  "--step",
                                         "--watch-renders"};

bool parseFlag(CommandLine& cl, RenderOptions& o) {
  if (cl.flag("--validation")) o.validation = true;
  else if (cl.flag("--no-shadows")) o.request.shadows = false;
  else if (cl.flag("-q") || cl.flag("--quiet")) o.quiet = true;
  else if (cl.flag("--watch")) o.watch = true;
  else if (cl.flag("--snow-displacement")) o.snowDisplacement = true;
  else return false;
  return true;
}

}  // namespace

std::optional<int> parseRenderOptions(int argc, char** argv, int first, RenderOptions& o) {
  o.graphsDir = bundledGraphsDirectory();
  CommandLine cl(argc, argv, first);
  while (!cl.done()) {
    if (cl.flag("-h") || cl.flag("--help")) {
      std::fputs(kRenderUsage, stdout);
      return kExitOk;
    }
    if (parseFlag(cl, o)) continue;
    std::string error;
    bool matched = false;
    for (const char* name : kValueOptions) {
      auto v = cl.valueFor(name, error);
      if (!v) continue;
      if (std::string e = parseValueOption(name, *v, o); !e.empty()) return usageError(e);
      matched = true;
      break;
    }
    if (matched) continue;
    if (!error.empty()) return usageError(error);
    return usageError("unknown option '" + quoteUserText(cl.peek()) + "'");
  }
  return std::nullopt;
}

}  // namespace wg
