// The Vulkan runtime on lavapipe with the validation layers on (any message fails):
// both backends agree, the GPU agrees with the CPU evaluator, measured albedo bands
// hold, the weather behaves as seed 000 describes, and reference images match.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <set>

#include "compiler/debug_views.hpp"
#include "nodes/weather_model.hpp"
#include "render_support.hpp"
#include "host/display_image.hpp"
#include "host/image/image_compare.hpp"
#include "host/image/reference_images.hpp"
#include "host/timeline_renderer.hpp"

namespace wg {
namespace {

using namespace testing;
using image::loadToleranceTable;
using image::Tolerance;
using image::ToleranceTable;
namespace fs = std::filesystem;

// Small frames keep lavapipe on two cores fast; every property below is local.
constexpr std::uint32_t kWidth = 192, kHeight = 108;
// What scripts/update-reference-images.sh asks the CLI for: 160x90 frames of
// timelines/seasons.json at a 300 s step, default weather and the scene's sun.
constexpr std::uint32_t kReferenceWidth = 160, kReferenceHeight = 90;
constexpr double kReferenceStep = 300.0;

#define REQUIRE_VULKAN() \
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)"

std::uint32_t view(std::string_view name) {
  for (const auto& v : kDebugViews)
    if (v.name == name) return v.id;
  throw std::logic_error("no view");
}

RenderRequest requestFor(const std::string& sceneName, const WeatherState& weather, std::string_view aov = "lit") {
  RenderRequest r;
  r.width = kWidth;
  r.height = kHeight;
  r.weather = weather;
  r.debugView = view(aov);
  (void)sceneName;
  return r;
}

WeatherState mixedWeather(const scene::Scene& scene) {
  WeatherState w = weatherFor(scene);
  w.conditions.temperature = 3.f;
  w.conditions.precipitation = 0.5f;
  w.levels = {0.5f, 0.6f, 0.4f, 0.3f, 0.5f, 0.f};
  return w;
}

ToleranceTable tolerances() {
  std::string error;
  auto table = loadToleranceTable(std::string(WG_SOURCE_DIR) + "/" + std::string(image::kToleranceFile), error);
  EXPECT_TRUE(table) << error;
  return table.value_or(ToleranceTable{});
}

class EachScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EachScene, GlslAndHlslSpirvRenderTheSameImage) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer(GetParam());
  RenderRequest request = requestFor(GetParam(), mixedWeather(renderer.scene()));
  request.backend = ShaderLanguage::Glsl;
  Image glsl = toDisplayImage(renderer.render(request));
  expectNoValidationMessages();
  request.backend = ShaderLanguage::Hlsl;
  Image hlsl = toDisplayImage(renderer.render(request));
  expectNoValidationMessages();
  constexpr double kDiffering = 0.05;           // a visible difference
  constexpr double kMaxDifferingShare = 0.005;  // at most 0.5 % of pixels may show one
  Tolerance t = tolerances().lookup("cross-backend");
  auto d = image::compareImages(glsl, hlsl, kDiffering);
  EXPECT_LE(d.maxError, t.maxError);
  EXPECT_LE(d.meanError, t.meanError);
  EXPECT_LE(double(d.pixelsOverThreshold) / (kWidth * kHeight), kMaxDifferingShare);
}

// AOVs sampled at many pixels match 'weathergen eval' (the CPU evaluator) fed with the
// surface inputs read back from the position, normal, texcoord and tangent AOVs. The
// AOVs are the surface function's outputs (every full shader embeds its surface), so
// this checks the GLSL and the HLSL surfaces against the evaluator, and so each other.
TEST_P(EachScene, AovsOfBothLanguagesMatchTheCpuEvaluator) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer(GetParam());
  const auto& scene = renderer.scene();
  WeatherState weather = mixedWeather(scene);
  constexpr float kTolerance = 0.02f;         // per value: float rounding, amplified by thresholds
  constexpr double kInToleranceShare = 0.97;  // noise-edge pixels may straddle a threshold
  constexpr double kMaxMeanError = 0.005;
  for (ShaderLanguage language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl}) {
    std::size_t samples = 0, within = 0;
    double errorSum = 0.0;
    std::set<std::string> graphs;
    for (const auto& object : scene.objects) {
      if (!graphs.insert(object.graph).second) continue;  // one object per material
      RenderRequest request = requestFor(GetParam(), weather);
      request.backend = language;
      request.onlyObject = object.name;
      auto pixels = surfacePixels(renderer, request, 6);
      std::map<std::string, RenderedFrame> aovs;
      for (const char* name : {"albedo", "roughness", "snow", "wet", "moss", "frost", "ice", "puddle"}) {
        request.debugView = view(name);
        aovs[name] = renderer.render(request);
        expectNoValidationMessages();
      }
      const CpuEvaluator& cpu = evaluatorFor(object.graph);
      for (const auto& p : pixels) {
        EvalInputs in;
        in.surface = p.surface;
        in.frame = frameStateFor(renderer, weather);
        in.terrainHeight = &terrainField(renderer);
        in.positionIsDisplaced = true;
        for (const auto& [name, value] : object.parameters) in.parameters[name] = Value::scalar(value);
        EvalResult r = cpu.evaluate(in);
        auto compare = [&](float gpu, float expected) {
          float e = std::fabs(gpu - expected);
          ++samples;
          within += e <= kTolerance;
          errorSum += e;
        };
        glm::vec4 albedo = pixel(aovs["albedo"], p.at.x, p.at.y);
        const Value& base = r.output(PbrField::BaseColor);
        for (int c = 0; c < 3; ++c) compare(albedo[c], base.v[c]);
        compare(pixel(aovs["roughness"], p.at.x, p.at.y).x, r.output(PbrField::Roughness).x());
        for (auto [aov, term] : {std::pair{"snow", CoverageTerm::Snow}, {"wet", CoverageTerm::Wet}, {"moss", CoverageTerm::Moss},
                                 {"frost", CoverageTerm::Frost}, {"ice", CoverageTerm::Ice}, {"puddle", CoverageTerm::Puddle}})
          compare(pixel(aovs[aov], p.at.x, p.at.y).x, r.coverageOf(term));
      }
    }
    const std::string_view label = languageName(language);
    ASSERT_GE(samples, 64u * 10u) << label << ": too few pixels compared";
    EXPECT_GE(double(within) / samples, kInToleranceShare)
        << label << ": " << within << " of " << samples << " within " << kTolerance;
    EXPECT_LE(errorSum / samples, kMaxMeanError) << label;
  }
}

INSTANTIATE_TEST_SUITE_P(Bundled, EachScene, ::testing::Values("valley", "rocks", "river", "road"));

// Pixels of one object in one AOV, with their geometric normals.
struct Sample {
  glm::vec4 value, normal, albedo;
  glm::vec2 texcoord;
};
std::vector<Sample> samplesOf(SceneRenderer& renderer, RenderRequest request, const std::string& object, std::string_view aov) {
  request.onlyObject = object;
  request.debugView = view(aov);
  RenderedFrame values = renderer.render(request);
  request.debugView = view("geometricNormal");
  RenderedFrame normals = renderer.render(request);
  request.debugView = view("albedo");
  RenderedFrame albedos = renderer.render(request);
  request.debugView = view("texcoord");
  RenderedFrame uvs = renderer.render(request);
  expectNoValidationMessages();
  std::vector<Sample> out;
  for (int y = 0; y < int(values.height); ++y)
    for (int x = 0; x < int(values.width); ++x)
      if (isSurface(values, x, y))
        out.push_back({pixel(values, x, y), pixel(normals, x, y), pixel(albedos, x, y), glm::vec2(pixel(uvs, x, y))});
  return out;
}

std::vector<std::string> objectsUsing(const scene::Scene& scene, const std::string& graph) {
  std::vector<std::string> names;
  for (const auto& o : scene.objects)
    if (o.graph == graph) names.push_back(o.name);
  return names;
}

float reflectanceOf(glm::vec4 albedo) { return weather::reflectance(glm::vec3(albedo)); }

// Table 4.1: fully covered, up-facing snow on rock reflects 0.90-0.95.
TEST(PhysicalBands, SnowOnUpFacingRockIsInTheSnowBand) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("rocks");
  WeatherState w = weatherFor(renderer.scene());
  w.conditions.temperature = -6.f;
  w.levels.snow = 1.f;
  w.conditions.sunIntensity = 0.2f;
  std::size_t checked = 0;
  for (const auto& rock : objectsUsing(renderer.scene(), "rock"))
    for (const auto& s : samplesOf(renderer, requestFor("rocks", w), rock, "snow"))
      if (s.value.x >= 0.999f && s.normal.y >= 0.9f) {
        ++checked;
        EXPECT_GE(reflectanceOf(s.albedo), weather::kSnowBand.low - 1e-3f);
        EXPECT_LE(reflectanceOf(s.albedo), weather::kSnowBand.high + 1e-3f);
      }
  EXPECT_GE(checked, 20u);
}

TEST(PhysicalBands, MossIsInTheGrassBand) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("rocks");
  WeatherState w = weatherFor(renderer.scene());
  w.conditions.temperature = 12.f;
  w.levels.moss = 1.f;
  w.conditions.sunIntensity = 0.3f;
  std::size_t checked = 0;
  for (const auto& rock : objectsUsing(renderer.scene(), "rock"))
    for (const auto& s : samplesOf(renderer, requestFor("rocks", w), rock, "moss"))
      if (s.value.x >= 0.999f) {
        ++checked;
        EXPECT_GE(reflectanceOf(s.albedo), weather::kGrassBand.low - 1e-3f);
        EXPECT_LE(reflectanceOf(s.albedo), weather::kGrassBand.high + 1e-3f);
      }
  EXPECT_GE(checked, 20u);
}

TEST(PhysicalBands, FrozenRiverIsInTheOceanIceBand) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("river");
  WeatherState w = weatherFor(renderer.scene());
  w.conditions.temperature = -10.f;
  w.levels.frost = 1.f;
  std::size_t checked = 0;
  for (const auto& s : samplesOf(renderer, requestFor("river", w), "river", "ice"))
    if (s.value.x >= 0.999f) {
      ++checked;
      EXPECT_GE(reflectanceOf(s.albedo), weather::kOceanIceBand.low - 1e-3f);
      EXPECT_LE(reflectanceOf(s.albedo), weather::kOceanIceBand.high + 1e-3f);
    }
  EXPECT_GE(checked, 20u);
}

double mean(const std::vector<float>& v) { return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }

// Seed 000, section 3.2: snow settles first on faces that look up, and on faces that
// look away from the sun.
TEST(WeatherBehaviour, SnowAppearsFirstOnUpFacingAndShadedFaces) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("rocks");
  WeatherState w = weatherFor(renderer.scene());
  w.conditions.temperature = -4.f;
  w.levels.snow = 0.3f;
  w.conditions.sunIntensity = 0.9f;
  glm::vec2 sun = glm::normalize(glm::vec2(renderer.scene().towardsSun.x, renderer.scene().towardsSun.z));
  std::vector<float> up, side, sunSide, shadeSide;
  for (const auto& rock : objectsUsing(renderer.scene(), "rock"))
    for (const auto& s : samplesOf(renderer, requestFor("rocks", w), rock, "snow")) {
      if (s.normal.y > 0.8f) up.push_back(s.value.x);
      if (s.normal.y > 0.2f && s.normal.y < 0.6f) {
        side.push_back(s.value.x);
        float facing = glm::dot(glm::normalize(glm::vec2(s.normal.x, s.normal.z)), sun);
        if (facing > 0.5f) sunSide.push_back(s.value.x);
        if (facing < -0.5f) shadeSide.push_back(s.value.x);
      }
    }
  ASSERT_FALSE(up.empty() || side.empty() || sunSide.empty() || shadeSide.empty());
  EXPECT_GT(mean(up), mean(side));
  EXPECT_GT(mean(shadeSide), mean(sunSide));
}

// Eq. 3.5's melt strength is not the light: under a bright overhead sun at full melt
// strength, rock tops that face straight up stay covered at snowLevel 1.
TEST(WeatherBehaviour, UpFacingRockKeepsItsSnowUnderABrightHighSun) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("rocks");
  WeatherState w = weatherFor(renderer.scene());
  w.conditions.temperature = -4.f;
  w.levels.snow = 1.f;
  w.conditions.sunDirection = {0.f, 1.f, 0.f};
  w.conditions.sunIntensity = 1.f;
  w.conditions.sunMelt = 1.f;
  std::vector<float> tops;
  for (const auto& rock : objectsUsing(renderer.scene(), "rock"))
    for (const auto& s : samplesOf(renderer, requestFor("rocks", w), rock, "snow"))
      if (s.normal.y > 0.95f) tops.push_back(s.value.x);
  ASSERT_GE(tops.size(), 20u);
  EXPECT_GE(mean(tops), 0.95);
}

// Seed 3.2.2 and 5.1.2: moss grows on the side that sees the least sun. With the sun 25
// degrees up, flanks facing away from it hold more moss than tops, and tops more than
// flanks facing it.
TEST(WeatherBehaviour, MossGrowsMostOnTheShadedFlanks) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("rocks");
  WeatherState w = weatherFor(renderer.scene());
  w.conditions.temperature = 13.f;
  w.levels.moss = 0.6f;
  glm::vec2 sun = glm::normalize(glm::vec2(renderer.scene().towardsSun.x, renderer.scene().towardsSun.z));
  const float elevation = glm::radians(25.f);
  w.conditions.sunDirection = {std::cos(elevation) * sun.x, std::sin(elevation), std::cos(elevation) * sun.y};
  w.conditions.sunIntensity = w.conditions.sunMelt = 1.f;
  std::vector<float> top, sunFlank, shadeFlank;
  for (const auto& rock : objectsUsing(renderer.scene(), "rock"))
    for (const auto& s : samplesOf(renderer, requestFor("rocks", w), rock, "moss")) {
      if (s.normal.y > 0.9f) top.push_back(s.value.x);
      if (std::abs(s.normal.y) < 0.3f) {
        float facing = glm::dot(glm::normalize(glm::vec2(s.normal.x, s.normal.z)), sun);
        if (facing > 0.7f) sunFlank.push_back(s.value.x);
        if (facing < -0.7f) shadeFlank.push_back(s.value.x);
      }
    }
  ASSERT_FALSE(top.empty() || sunFlank.empty() || shadeFlank.empty());
  EXPECT_GT(mean(shadeFlank), mean(top));
  EXPECT_GT(mean(top), mean(sunFlank));
}

// Nothing accumulates under the shelter, while open ground beside it is covered.
TEST(WeatherBehaviour, NothingAccumulatesUnderTheShelter) {
  REQUIRE_VULKAN();
  for (const std::string sceneName : {"road", "valley"}) {
    SceneRenderer& renderer = sceneRenderer(sceneName);
    WeatherState w = weatherFor(renderer.scene());
    w.conditions.temperature = 4.f;
    w.conditions.precipitation = 1.f;
    w.levels = {1.f, 1.f, 0.f, 0.f, 1.f, 0.f};
    std::size_t sheltered = 0, open = 0;
    // Each probe's own object is drawn alone: the roof still shelters it (the sky-exposure
    // map was made from the whole scene) but cannot hide it from the camera.
    std::set<std::string> probeObjects;
    for (const auto& probe : renderer.scene().probes)
      if (probe.expect == "sheltered" || probe.expect == "open") probeObjects.insert(probe.object);
    for (const auto& camera : renderer.scene().cameras)
      for (const auto& object : probeObjects) {
        RenderRequest base = requestFor(sceneName, w);
        base.camera = camera.name;
        base.onlyObject = object;
        std::map<std::string, RenderedFrame> aovs;
        for (const char* name : {"snow", "wet", "puddle", "position"}) {
          base.debugView = view(name);
          aovs[name] = renderer.render(base);
          expectNoValidationMessages();
        }
        glm::mat4 vp = renderer.viewProjection(camera.name, kWidth, kHeight);
        for (const auto& probe : renderer.scene().probes) {
          if (probe.object != object || (probe.expect != "sheltered" && probe.expect != "open")) continue;
          auto at = project(vp, probe.position, kWidth, kHeight);
          if (!at) continue;
          // The pixel must show the probe's surface (a pixel spans up to about a metre).
          constexpr float kPixelFootprint = 1.f;
          glm::vec4 p = pixel(aovs["position"], at->x, at->y);
          if (p.a == 0.f || glm::distance(glm::vec3(p), probe.position) > kPixelFootprint) continue;
          float snow = pixel(aovs["snow"], at->x, at->y).x, wet = pixel(aovs["wet"], at->x, at->y).x;
          float puddle = pixel(aovs["puddle"], at->x, at->y).x;
          if (probe.expect == "sheltered") {
            ++sheltered;
            EXPECT_LE(snow, 0.01f) << probe.name << " from " << camera.name;
            EXPECT_LE(wet, 0.01f) << probe.name;
            EXPECT_LE(puddle, 0.01f) << probe.name;
          } else {
            ++open;
            EXPECT_GT(wet, 0.5f) << probe.name << " from " << camera.name;
          }
        }
      }
    EXPECT_GT(sheltered, 0u) << sceneName << ": no sheltered probe was visible";
    EXPECT_GT(open, 0u) << sceneName;
  }
}

// Section 5.1.2: water pools only where the road is within 8 degrees of flat.
TEST(WeatherBehaviour, PuddlesFormOnlyOnFlatRoad) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("road");
  WeatherState w = weatherFor(renderer.scene());
  w.conditions.temperature = 8.f;
  w.levels.puddles = 1.f;
  const float cos8 = std::cos(glm::radians(8.f));
  std::size_t tilted = 0, flatWithWater = 0;
  for (const auto& s : samplesOf(renderer, requestFor("road", w), "road", "puddle")) {
    if (s.normal.y < cos8 - 1e-4f) {
      ++tilted;
      EXPECT_EQ(s.value.x, 0.f) << "puddle on a road tilted " << glm::degrees(std::acos(s.normal.y)) << " degrees";
    } else if (s.value.x > 0.5f) {
      ++flatWithWater;
    }
  }
  EXPECT_GT(tilted, 50u);
  EXPECT_GT(flatWithWater, 50u);
}

// Eq. 3.20: the river freezes from its banks (v = 0 and 1) towards the middle.
TEST(WeatherBehaviour, RiverFreezesFromTheBanksInward) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("river");
  WeatherState w = weatherFor(renderer.scene());
  w.conditions.temperature = -6.f;
  w.levels.frost = 0.35f;
  std::vector<float> banks, middle;
  for (const auto& s : samplesOf(renderer, requestFor("river", w), "river", "ice")) {
    float acrossFromCentre = std::fabs(2.f * s.texcoord.y - 1.f);
    if (acrossFromCentre > 0.75f) banks.push_back(s.value.x);
    if (acrossFromCentre < 0.25f) middle.push_back(s.value.x);
  }
  ASSERT_FALSE(banks.empty() || middle.empty());
  EXPECT_GT(mean(banks), 0.3);
  EXPECT_LT(mean(middle), 0.05);
}

// Eq. 3.15-3.17: rain darkens (x Lerp(1, 0.7, p)) and smooths (R - p) only above 0 C.
TEST(WeatherBehaviour, RainDarkensAndSmoothsOnlyAboveFreezing) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("road");
  WeatherState dry = weatherFor(renderer.scene());
  dry.conditions.temperature = 5.f;
  WeatherState rain = dry;
  rain.conditions.precipitation = 1.f;
  rain.levels.wetness = 1.f;
  WeatherState frozen = rain;
  frozen.conditions.temperature = -5.f;
  auto mean3 = [&](const WeatherState& w, std::string_view aov) {
    double sum = 0;
    auto samples = samplesOf(renderer, requestFor("road", w), "road", aov);
    for (const auto& s : samples) sum += aov == "albedo" ? reflectanceOf(s.value) : s.value.x;
    return sum / std::max<std::size_t>(samples.size(), 1);
  };
  double dryAlbedo = mean3(dry, "albedo"), dryRoughness = mean3(dry, "roughness");
  EXPECT_LT(mean3(rain, "albedo"), dryAlbedo * 0.9);
  EXPECT_LT(mean3(rain, "roughness"), dryRoughness - 0.1);
  EXPECT_GT(mean3(rain, "wet"), 0.3);
  EXPECT_NEAR(mean3(frozen, "albedo"), dryAlbedo, 1e-4);
  EXPECT_NEAR(mean3(frozen, "roughness"), dryRoughness, 1e-4);
  EXPECT_EQ(mean3(frozen, "wet"), 0.0);
}

// One small reference image per scene and weather stage (timelines/seasons.json),
// regenerated only by scripts/update-reference-images.sh.
class ReferenceImages : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceImages, EveryStageMatchesItsReference) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer(GetParam());
  std::ifstream in(std::string(WG_SOURCE_DIR) + "/timelines/seasons.json");
  std::string error;
  auto timeline = parseWeatherTimeline(nlohmann::json::parse(in), error);
  ASSERT_TRUE(timeline) << error;
  RenderRequest base;
  base.width = kReferenceWidth;
  base.height = kReferenceHeight;
  base.weather = weatherFor(renderer.scene());
  base.weather.conditions.sunIntensity = WeatherConditions{}.sunIntensity;  // the CLI's default
  ToleranceTable table = tolerances();
  for (const auto& stage : renderTimeline(renderer, *timeline, base, kReferenceStep)) {
    expectNoValidationMessages();
    std::string name = GetParam() + "-" + stage.slug;
    fs::path reference = fs::path(WG_SOURCE_DIR) / "tests" / "reference" / (name + ".png");
    auto check = image::checkAgainstReference(toDisplayImage(stage.frame), reference.string(), table.lookup(name));
    EXPECT_TRUE(check.passed) << name << ": " << check.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Bundled, ReferenceImages, ::testing::Values("valley", "rocks", "river", "road"));

}  // namespace
}  // namespace wg
