#include "render_support.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "compiler/debug_views.hpp"
#include "driver/material_compiler.hpp"
#include "nodes/weather_model.hpp"
#include "weather/frame_weather.hpp"

namespace wg::testing {

vk::Context* renderContext() {
  static std::unique_ptr<vk::Context> context = [] {
    std::string error;
    auto ctx = vk::Context::create({"cpu", true}, error);
    if (!ctx) std::fprintf(stderr, "render tests: %s\n", error.c_str());
    return ctx;
  }();
  return context.get();
}

SceneRenderer& sceneRenderer(const std::string& name) {
  static std::map<std::string, std::unique_ptr<SceneRenderer>> renderers;
  auto& slot = renderers[name];
  if (!slot) slot = std::make_unique<SceneRenderer>(*renderContext(), *scene::makeScene(name), std::string(WG_SOURCE_DIR) + "/graphs");
  return *slot;
}

WeatherState weatherFor(const scene::Scene& scene) {
  WeatherState w;
  w.conditions.sunDirection = {scene.towardsSun.x, scene.towardsSun.y, scene.towardsSun.z};
  w.conditions.sunIntensity = 0.7f;
  return w;
}

glm::vec4 pixel(const RenderedFrame& frame, int x, int y) {
  const float* p = &frame.rgba[(std::size_t(y) * frame.width + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

bool isSurface(const RenderedFrame& frame, int x, int y) { return pixel(frame, x, y).a != 0.f; }

std::optional<glm::ivec2> project(const glm::mat4& vp, glm::vec3 world, std::uint32_t width, std::uint32_t height) {
  glm::vec4 clip = vp * glm::vec4(world, 1.f);
  if (clip.w <= 0.f) return std::nullopt;
  glm::vec3 ndc = glm::vec3(clip) / clip.w;
  int x = static_cast<int>((ndc.x * 0.5f + 0.5f) * width), y = static_cast<int>((ndc.y * 0.5f + 0.5f) * height);
  if (x < 0 || y < 0 || x >= int(width) || y >= int(height)) return std::nullopt;
  return glm::ivec2(x, y);
}

void expectNoValidationMessages() {
  for (const auto& m : renderContext()->validationMessages()) ADD_FAILURE() << "Vulkan validation: " << m;
}

namespace {
std::uint32_t viewId(std::string_view name) {
  for (const auto& v : kDebugViews)
    if (v.name == name) return v.id;
  throw std::logic_error("no debug view " + std::string(name));
}
}  // namespace

std::vector<PixelSurface> surfacePixels(SceneRenderer& renderer, RenderRequest request, int gridStep) {
  std::map<std::string, RenderedFrame> views;
  for (const char* name : {"position", "geometricNormal", "texcoord", "tangent"}) {
    request.debugView = viewId(name);
    views[name] = renderer.render(request);
    expectNoValidationMessages();
  }
  std::vector<PixelSurface> out;
  const RenderedFrame& position = views["position"];
  for (int y = gridStep / 2; y < int(position.height); y += gridStep)
    for (int x = gridStep / 2; x < int(position.width); x += gridStep) {
      if (!isSurface(position, x, y)) continue;
      PixelSurface s;
      s.at = {x, y};
      glm::vec4 p = pixel(position, x, y), n = pixel(views["geometricNormal"], x, y);
      glm::vec4 uv = pixel(views["texcoord"], x, y), t = pixel(views["tangent"], x, y);
      s.surface.worldPosition = {p.x, p.y, p.z};
      s.surface.worldNormal = {n.x, n.y, n.z};
      s.surface.texcoord = {uv.x, uv.y};
      s.surface.tangent = {t.x, t.y, t.z, t.w};
      s.surface.skyExposure = skyExposureAt(renderer, {p.x, p.y, p.z}, glm::normalize(glm::vec3(n)));
      out.push_back(s);
    }
  return out;
}

FrameState frameStateFor(const SceneRenderer& renderer, const WeatherState& w) {
  FrameState f;
  writeWeather(w, f);
  glm::vec3 sun = glm::normalize(glm::vec3(w.conditions.sunDirection[0], w.conditions.sunDirection[1], w.conditions.sunDirection[2]));
  f.sunDirection = {sun.x, sun.y, sun.z};  // unit length, as the renderer uploads it
  const auto& s = renderer.scene();
  f.terrainHeightScale = s.terrainHeightScale;
  f.terrainRegion = {s.terrainRegion.x, s.terrainRegion.y, s.terrainRegion.z, s.terrainRegion.w};
  return f;
}

float skyExposureAt(const SceneRenderer& renderer, glm::vec3 p, glm::vec3 normal) {
  glm::vec4 region = renderer.exposureRegion();
  glm::vec2 uv = (glm::vec2(p.x, p.z) - glm::vec2(region.x, region.y)) * glm::vec2(region.z, region.w) +
                 glm::vec2(normal.x, normal.z) * (weather::kSkyExposureNormalOffset / weather::kSkyExposureResolution);
  if (region.z <= 0.f || uv.x < 0.f || uv.y < 0.f || uv.x > 1.f || uv.y > 1.f) return 1.f;
  return weather::filteredSkyExposure(renderer.exposureHeights(), int(renderer.exposureResolution()), uv, p.y);
}

const CpuEvaluator& evaluatorFor(const std::string& stem) {
  static std::map<std::string, std::unique_ptr<CpuEvaluator>> evaluators;
  auto& slot = evaluators[stem];
  if (!slot) {
    std::string path = std::string(WG_SOURCE_DIR) + "/graphs/" + stem + ".json";
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    DiagnosticList diagnostics;
    auto ir = buildOptimizedIr(path, text.str(), diagnostics);
    if (!ir) throw std::runtime_error("cannot compile " + path);
    slot = std::make_unique<CpuEvaluator>(std::move(*ir));
  }
  return *slot;
}

const HeightField& terrainField(const SceneRenderer& renderer) {
  static std::map<const SceneRenderer*, HeightField> fields;
  auto& f = fields[&renderer];
  if (f.resolution == 0) f = HeightField{renderer.scene().terrainHeightResolution, renderer.scene().terrainHeights};
  return f;
}

}  // namespace wg::testing
