// The snowfield scene drawn by the runtime with the snow_layer graph and the
// deformation map bound, on lavapipe with validation on: prints
// show as packed snow, nothing ghosts where the camera travels, the prints are back
// after the round trip, no snow means no prints; puffs fade into the snow against its
// depth (§5), lit no brighter than the snow, and bloom only adds light.
#include "host/snowfield/snowfield_scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <numeric>
#include <sstream>

#include "compiler/cpu_evaluator.hpp"
#include "compiler/debug_views.hpp"
#include "driver/material_compiler.hpp"
#include "host/pass_cameras.hpp"
#include "host/scene_renderer.hpp"

#include "tests/snow/snow_gpu_support.hpp"

namespace wg::snow {
namespace {

using testing::snowContext;

std::uint32_t debugViewNamed(std::string_view name) {
  for (const auto& v : kDebugViews)
    if (v.name == name) return v.id;
  return 0;
}
std::uint32_t albedoView() { return debugViewNamed("albedo"); }

// The snowfield with a small grid (the shading is per pixel from the 4 cm map; the grid
// only carries the displacement), its animation, and a small lit request.
struct Snowscape {
  SnowfieldSettings settings;
  WeatherState weather;
  std::unique_ptr<SceneRenderer> renderer;
  std::unique_ptr<SnowfieldAnimation> animation;

  explicit Snowscape(float snowLevel) {
    settings.grid.quadsPerPatch = 8;
    settings.grid.fineHalfWidth = 0.f;
    settings.frameSeconds = 0.1;
    weather.conditions.temperature = -6.f;
    glm::vec3 sun = snowfieldTowardsSun();
    weather.conditions.sunDirection = {sun.x, sun.y, sun.z};
    weather.levels.snow = snowLevel;
    // Single-sampled: lavapipe's multisampled rasterizer takes ten times as long over the
    // layer's dense mesh, and these tests look at prints, puffs and bloom, not edges.
    renderer = std::make_unique<SceneRenderer>(*snowContext(), makeSnowfieldScene(settings),
                                               std::string(WG_SOURCE_DIR) + "/graphs", VK_SAMPLE_COUNT_1_BIT);
    animation = std::make_unique<SnowfieldAnimation>(*snowContext(), settings, weather);
    renderer->setSnowDeformation(&animation->deformationImage());
  }
  RenderRequest request(const SnowfieldMoment& m) const {
    RenderRequest r;
    r.width = 240;
    r.height = 135;
    r.weather = weather;
    r.cameraPose = m.camera;
    r.objectModels = m.objectModels;
    return r;
  }
};

// The layer alone, as albedo, at each time.
std::vector<RenderedFrame> renderLayer(float snowLevel, const std::vector<double>& times) {
  Snowscape scape(snowLevel);
  std::vector<RenderedFrame> out;
  for (double t : times) {
    RenderRequest request = scape.request(scape.animation->advanceTo(t));
    request.debugView = albedoView();
    request.onlyObject = kSnowLayerObject;
    out.push_back(scape.renderer->render(request));
  }
  return out;
}

// Pixels of the layer whose albedo is the packed snow's rather than fresh snow's
// (graphs/snow_layer.json: red 0.62 packed, 0.9 fresh).
int packedPixels(const RenderedFrame& f) {
  constexpr float kBetween = 0.76f;
  int n = 0;
  for (std::size_t i = 0; i < f.rgba.size(); i += 4)
    if (f.rgba[i + 3] > 0.f && f.rgba[i] < kBetween) ++n;
  return n;
}

using Snowfield = testing::ValidatedGpuTest;

TEST_F(Snowfield, PrintsShowAsPackedSnowAndComeBackAfterTheRoundTrip) {
  // Prints formed; the camera 60 m away (out of the window); back at the start.
  auto r = renderLayer(1.f, {11.0, 34.0, 58.0});
  int before = packedPixels(r[0]), away = packedPixels(r[1]), back = packedPixels(r[2]);
  EXPECT_GT(before, 200) << "trails and ruts should cover hundreds of pixels";
  EXPECT_EQ(away, 0) << "stored prints must not ghost into the window elsewhere";
  EXPECT_EQ(back, before);
  double sum = 0.0;
  float worst = 0.f;
  for (std::size_t i = 0; i < r[0].rgba.size(); ++i) {
    float d = std::abs(r[0].rgba[i] - r[2].rgba[i]);
    sum += d;
    worst = std::max(worst, d);
  }
  EXPECT_LT(sum / double(r[0].rgba.size()), 1e-4);
  EXPECT_LT(worst, 0.05f);
}

TEST_F(Snowfield, NoSnowNoPrints) {
  EXPECT_EQ(packedPixels(renderLayer(0.f, {11.0})[0]), 0);
}

// Snow puffs against the scene's depth (seed 3.3.2): a puff in the air in front of the
// camera shows; the same puff under the snow surface is faded out completely, because
// the fragment stage compares with the scene's D32 depth at full precision.
TEST_F(Snowfield, PuffsShowInTheAirAndFadeIntoTheSnow) {
  Snowscape scape(1.f);
  RenderRequest request = scape.request(scape.animation->advanceTo(0.5));
  SceneRenderer& renderer = *scape.renderer;
  RenderedFrame plain = renderer.render(request);
  float brightest = 0.f;  // the most a puff pixel gained over the snow behind it
  auto changedBy = [&](float y) {
    SnowPuffs puffs(*snowContext());
    // 5 m in front of the camera, clear of walkers and rocks; y from the snow surface.
    glm::vec3 at(0.f, snowfieldGround(0.f, 1.f) + scape.settings.weather.fullCoverDepth + y, 1.f);
    puffs.emit(std::span(&at, 1));
    puffs.simulate(0.05, glm::vec2(0.f));
    RenderRequest withPuffs = request;
    withPuffs.afterColourPass = [&](const ColourPassTargets& t) { puffs.record(t); };
    RenderedFrame f = renderer.render(withPuffs);
    int changed = 0;
    for (std::size_t i = 0; i < f.rgba.size(); i += 4) {
      changed += std::abs(f.rgba[i] - plain.rgba[i]) > 0.02f;
      for (int c = 0; c < 3; ++c) brightest = std::max(brightest, f.rgba[i + c] - plain.rgba[i + c]);
    }
    return changed;
  };
  EXPECT_GT(changedBy(0.4f), 30) << "a puff above the snow";
  // Lit by the sun and sky like the snow it came from, never brighter than it.
  EXPECT_LE(brightest, 0.01f);
  EXPECT_EQ(changedBy(-0.7f), 0) << "a puff under the snow, at every point behind its surface";
}

// How far each pixel's darkest channel rises above the brightest sunlit snow (0.764
// tone-mapped with no glitter), which only glints reach; summed over the 3 x 3 pixels
// around a point and read bilinearly between pixel centres.
struct GlintEnergy {
  static constexpr float kAboveSnow = 0.77f;
  std::uint32_t width, height;
  std::vector<float> at;
  explicit GlintEnergy(const RenderedFrame& f) : width(f.width), height(f.height), at(f.width * f.height) {
    for (std::size_t i = 0; i < at.size(); ++i)
      at[i] = std::max(0.f, std::min({f.rgba[4 * i], f.rgba[4 * i + 1], f.rgba[4 * i + 2]}) - kAboveSnow);
  }
  float pixel(int x, int y) const {
    return at[std::clamp(y, 0, int(height) - 1) * width + std::clamp(x, 0, int(width) - 1)];
  }
  float around(int x, int y) const {
    float sum = 0.f;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) sum += pixel(x + dx, y + dy);
    return sum;
  }
  float around(float x, float y) const {
    int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    float fx = x - x0, fy = y - y0;
    return (1 - fy) * ((1 - fx) * around(x0, y0) + fx * around(x0 + 1, y0)) +
           fy * ((1 - fx) * around(x0, y0 + 1) + fx * around(x0 + 1, y0 + 1));
  }
};

// Glitter (seed 3.5.2) does not flicker: a sparkle stays on its spot of snow, as bright,
// while the camera moves. The camera steps by 1.1 cm, under a sparkle cell (1.7 cm) and
// 0.1 to 0.5 pixel of motion on the ground, sideways and then up. Each pixel of the
// layer is followed to where its world point lands in the moved frame, and the glint
// energy around it there is compared with before. Sparkles chosen at pixel centres
// (cells at least a pixel wide) changed 25 % (sideways) and 41 % (up) of the glint
// energy at 240x135; point glints drawn as smooth discs at least 1.5 pixels in radius
// change 9 % and 15 %. Counting pixels that cross a threshold would count the motion too.
TEST_F(Snowfield, GlitterDoesNotFlicker) {
  Snowscape scape(1.f);
  RenderRequest request = scape.request(scape.animation->advanceTo(0.0));
  request.onlyObject = kSnowLayerObject;
  RenderedFrame a = scape.renderer->render(request);
  RenderRequest where = request;
  where.debugView = debugViewNamed("position");
  RenderedFrame positions = scape.renderer->render(where);
  const GlintEnergy before(a);
  int glints = 0;
  double brightEnergy = 0.0;
  for (std::size_t i = 0; i < before.at.size(); ++i) {
    glints += before.at[i] > 0.f;
    if (before.at[i] > 0.1f) brightEnergy += before.at[i];
  }
  RecordProperty("glints", glints);
  EXPECT_GE(glints, 100) << "glitter shows at this size";
  // Sparkles, not a haze: most of the glint energy is in pixels well above the snow.
  EXPECT_GE(brightEnergy, 0.5 * std::accumulate(before.at.begin(), before.at.end(), 0.0));

  const glm::vec3 sideways = glm::normalize(glm::cross(request.cameraPose->target - request.cameraPose->eye,
                                                       glm::vec3(0.f, 1.f, 0.f)));
  struct Step {
    const char* name;
    glm::vec3 move;
    double limit;  // of the glint energy
  };
  for (const Step& step : {Step{"sideways", 0.011f * sideways, 0.14}, Step{"up", glm::vec3(0.f, 0.011f, 0.f), 0.22}}) {
    RenderRequest moved = request;
    moved.cameraPose->eye += step.move;
    moved.cameraPose->target += step.move;
    RenderedFrame b = scape.renderer->render(moved);
    const glm::mat4 toB = cameraViewProjection(*moved.cameraPose, clipRange(scape.renderer->scene(), moved.cameraPose->eye),
                                               b.width, b.height);
    const GlintEnergy after(b);
    double change = 0.0, energy = 0.0;
    for (std::uint32_t y = 0; y < a.height; ++y)
      for (std::uint32_t x = 0; x < a.width; ++x) {
        const float* p = &positions.rgba[4 * (y * a.width + x)];
        if (p[3] <= 0.f) continue;  // not the layer
        glm::vec4 clip = toB * glm::vec4(p[0], p[1], p[2], 1.f);
        float bx = (clip.x / clip.w * 0.5f + 0.5f) * b.width - 0.5f;
        float by = (clip.y / clip.w * 0.5f + 0.5f) * b.height - 0.5f;
        float e0 = before.around(int(x), int(y)), e1 = after.around(bx, by);
        change += std::abs(e1 - e0);
        energy += 0.5 * (e0 + e1);
      }
    RecordProperty(std::string("glint_energy_change_percent_") + step.name, int(std::lround(100.0 * change / energy)));
    EXPECT_LE(change, step.limit * energy) << step.name << ": glint energy changed by " << 100.0 * change / energy << " %";
  }
}

// Bloom (seed 3.5.1): sunlit snow glows, so the frame gets brighter, never darker.
TEST_F(Snowfield, BloomOnlyAddsLight) {
  Snowscape scape(1.f);
  SceneRenderer& renderer = *scape.renderer;
  RenderRequest request = scape.request(scape.animation->advanceTo(0.0));
  BloomPass bloom(*snowContext());
  RenderedFrame plain = renderer.render(request);
  request.afterColourPass = [&](const ColourPassTargets& t) { bloom.record(t.cmd, *t.colour); };
  RenderedFrame bloomed = renderer.render(request);
  double added = 0.0;
  for (std::size_t i = 0; i < plain.rgba.size(); ++i) {
    ASSERT_GE(bloomed.rgba[i], plain.rgba[i] - 1e-6f) << i;
    added += bloomed.rgba[i] - plain.rgba[i];
  }
  EXPECT_GT(added / double(plain.rgba.size()), 0.01) << "sunlit snow is above the threshold";
}

// No frame shows the world's edge: 60 m from its start the camera sees the ground run
// out to a level horizon at eye height, where the world's edge would be a tilted line
// below it (as it was before the horizon ring). Left quarter of the frame, clear of
// the hills.
TEST_F(Snowfield, TheGroundRunsOutToALevelHorizon) {
  Snowscape scape(1.f);
  SnowfieldMoment moment = scape.animation->advanceTo(34.0);  // the camera 60 m out
  RenderRequest request = scape.request(moment);
  // An AOV: the lit sky blends into the hazed ground by design, but an AOV's sky is
  // alpha 0, which no surface writes.
  request.debugView = albedoView();
  RenderedFrame f = scape.renderer->render(request);
  // Where a point far ahead at eye height projects.
  glm::mat4 vp = cameraViewProjection(moment.camera, clipRange(scape.renderer->scene(), moment.camera.eye), f.width, f.height);
  glm::vec4 far = vp * glm::vec4(moment.camera.eye + glm::vec3(0.f, 0.f, 5000.f), 1.f);
  float horizonRow = (far.y / far.w * 0.5f + 0.5f) * float(f.height);
  for (std::uint32_t x = 0; x < f.width / 4; x += 4) {
    std::uint32_t y = 0;
    auto isSky = [&](std::uint32_t row) { return f.rgba[4 * (row * f.width + x) + 3] == 0.f; };
    while (y < f.height && isSky(y)) ++y;
    EXPECT_NEAR(float(y), horizonRow, 3.f) << "column " << x;
  }
}

// Terrain-following snow: on a hill the layer lies on the terrain's height field,
// raised by the snow depth (graphs/snow_layer.json evaluated on the CPU with the
// scene's terrain map, as the vertex stage computes it).
TEST(SnowfieldTerrain, LayerLiesOnTheHillsRaisedByTheSnowDepth) {
  SnowfieldSettings settings;
  settings.grid = {2, 4.f, 4, 0.f, 0.04f, 1.f};
  scene::Scene scene = makeSnowfieldScene(settings);
  HeightField terrain{scene.terrainHeightResolution, scene.terrainHeights};
  std::string path = std::string(WG_SOURCE_DIR) + "/graphs/snow_layer.json";
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  DiagnosticList diagnostics;
  auto ir = buildOptimizedIr(path, text.str(), diagnostics);
  ASSERT_TRUE(ir.has_value());
  CpuEvaluator layer(std::move(*ir));
  EvalInputs in;
  in.terrainHeight = &terrain;
  in.frame.terrainRegion = {scene.terrainRegion.x, scene.terrainRegion.y, scene.terrainRegion.z, scene.terrainRegion.w};
  in.frame.terrainHeightScale = scene.terrainHeightScale;
  in.frame.snowLevel = 1.f;
  in.parameters["noiseHeight"] = Value::scalar(0.f);
  auto layerHeight = [&](float x, float z) {
    in.surface.worldPosition = {x, 0.f, z};
    in.frame.cameraPosition = {x, 2.f, z - 4.f};  // well inside the border fade
    return layer.evaluate(in).outputs.at("worldPositionOffset").v[1];
  };
  // The graph's snow depth is the scene's, which prints and puffs assume.
  float depth = settings.weather.fullCoverDepth;
  const glm::vec4& r = scene.terrainRegion;
  // On the flank of the walkers' rise, on the plain, and near the top of a 3.5 m hill.
  for (glm::vec2 p : {glm::vec2(0.f, 3.f), glm::vec2(-30.f, -30.f), glm::vec2(-13.f, 20.f)}) {
    float ground = terrain.sample((p.x - r.x) * r.z, (p.y - r.y) * r.w) * scene.terrainHeightScale;
    EXPECT_NEAR(ground, snowfieldGround(p.x, p.y), 0.06f) << "the 2 m map follows the hills";
    EXPECT_NEAR(layerHeight(p.x, p.y), ground + depth, 1e-3f) << p.x << ", " << p.y << ": ground " << ground;
  }
  EXPECT_GT(snowfieldGround(-13.f, 20.f), 2.5f) << "a hill, not the plain";
}

}  // namespace
}  // namespace wg::snow
