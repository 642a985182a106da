// Properties of the weather model (seed 000, chapter 3; issue "Weather library",
// section 6) checked through the CPU evaluator on the bundled graphs, over
// deterministic grids of positions, normals and weather. Each test names the inputs
// and values of the first violations it finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/cpu_evaluator.hpp"
#include "driver/material_compiler.hpp"
#include "weather/weather_simulation.hpp"

namespace wg {
namespace {

using Vec3 = std::array<float, 3>;

// Float slack for comparisons between two evaluations of the same arithmetic.
constexpr float kTolerance = 1e-5f;
// Violations printed per property; the count is always reported.
constexpr std::size_t kShownViolations = 5;

// Table 4.1 (Remember Me, GDC 2013): measured reflectance bands, and eq. 3.19's
// luminance weights the reflectance is measured with.
constexpr Vec3 kLuminanceWeights{0.3f, 0.59f, 0.11f};
constexpr float kSnowBandLow = 0.90f, kSnowBandHigh = 0.95f;
constexpr float kGrassBandLow = 0.25f, kGrassBandHigh = 0.53f;
constexpr float kOceanIceBandLow = 0.50f, kOceanIceBandHigh = 0.70f;
// Eq. 3.16: wet diffuse is darkened to 70 %.
constexpr float kWetDiffuse = 0.7f;
// Section 5.1.2: puddles form only within 8 degrees of up; 10 degrees is clearly off.
constexpr float kPuddleTestTiltDegrees = 10.f;
// Tilt of the sun-facing and shaded sides: normalize(up +- 0.6 towardsSun).
constexpr float kSideTilt = 0.6f;
// Heights compared for the height terms (eq. 3.8 and 3.9, default range -50..50 m).
constexpr float kLowGround = -40.f, kHighGround = 40.f;
// A typical cold, snowy day.
constexpr float kFreezingC = -5.f;
// The ground grid: kGridSide x kGridSide points kGridStep metres apart, offset so
// no point falls on a noise lattice line; uv runs with the position.
constexpr int kGridSide = 7;
constexpr float kGridStep = 2.3f;
constexpr float kGridOrigin = -6.9f;
constexpr float kUvPerMetre = 0.137f;
// Steps the normal takes from facing down to facing up.
constexpr int kTurnSteps = 24;
constexpr float kDegenerateTemperatures[] = {-60.f, 60.f};

// ---- Graphs and evaluators -----------------------------------------------------------

std::string graphPath(const std::string& name) { return std::string(WG_SOURCE_DIR) + "/graphs/" + name + ".json"; }

nlohmann::json graphJson(const std::string& name) {
  std::ifstream in(graphPath(name));
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

CpuEvaluator evaluatorFor(const std::string& name, const nlohmann::json& graph, const CompileOptions& options = {}) {
  DiagnosticList diagnostics;
  auto ir = buildOptimizedIr(graphPath(name), graph.dump(), diagnostics, options);
  for (const auto& d : diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  if (!ir) throw std::runtime_error(name + " did not build");
  return CpuEvaluator(std::move(*ir));
}

// Built once per test binary: generating the textures is the slow part.
const CpuEvaluator& bundled(const std::string& name) {
  static std::map<std::string, CpuEvaluator> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, evaluatorFor(name, graphJson(name))).first;
  return it->second;
}

const CpuEvaluator& rockWithoutWeather() {
  static const CpuEvaluator e = evaluatorFor("rock", graphJson("rock"), CompileOptions{.weatherPreset = "none"});
  return e;
}

const CpuEvaluator& rockWithoutDisplacement() {
  static const CpuEvaluator e = [] {
    nlohmann::json graph = graphJson("rock");
    graph["weather"] = {{"preset", "rock"}, {"effects", {{"displacement", false}}}};
    return evaluatorFor("rock", graph);
  }();
  return e;
}

// The rock preset with every effect but wetness switched off.
const CpuEvaluator& rockWetOnly() {
  static const CpuEvaluator e = [] {
    nlohmann::json graph = graphJson("rock");
    graph["weather"] = {{"preset", "rock"},
                        {"effects", {{"snow", false}, {"moss", false}, {"displacement", false}, {"terrainOrientation", false}}}};
    return evaluatorFor("rock", graph);
  }();
  return e;
}

// ---- Vectors and samples ---------------------------------------------------------------

Vec3 normalized(Vec3 v) {
  const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / length, v[1] / length, v[2] / length};
}
Vec3 plus(Vec3 a, Vec3 b, float scale) { return {a[0] + b[0] * scale, a[1] + b[1] * scale, a[2] + b[2] * scale}; }
constexpr Vec3 kUp{0.f, 1.f, 0.f};

float reflectance(const Value& albedo) {
  return kLuminanceWeights[0] * albedo.v[0] + kLuminanceWeights[1] * albedo.v[1] + kLuminanceWeights[2] * albedo.v[2];
}

std::string text(Vec3 v) {
  std::ostringstream out;
  out << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return out.str();
}

// Points of the ground grid at height y, with the normal and tangent given.
std::vector<SurfacePoint> grid(float y, Vec3 normal = kUp, std::array<float, 4> tangent = {1.f, 0.f, 0.f, 1.f}) {
  std::vector<SurfacePoint> points;
  for (int i = 0; i < kGridSide; ++i)
    for (int j = 0; j < kGridSide; ++j) {
      SurfacePoint p;
      const float x = kGridOrigin + kGridStep * static_cast<float>(i), z = kGridOrigin + kGridStep * static_cast<float>(j);
      p.worldPosition = {x, y, z};
      p.worldNormal = normal;
      p.tangent = tangent;
      p.texcoord = {x * kUvPerMetre, z * kUvPerMetre};
      points.push_back(p);
    }
  return points;
}

std::string at(const SurfacePoint& p) {
  return "at " + text(p.worldPosition) + " normal " + text(p.worldNormal);
}

// Collects violations; reports the first few with their values and the count.
class Violations {
 public:
  void add(const std::string& what) {
    if (shown_.size() < kShownViolations) shown_.push_back(what);
    ++count_;
  }
  std::size_t count() const { return count_; }
  std::string report() const {
    std::string out = std::to_string(count_) + " violation(s):";
    for (const auto& s : shown_) out += "\n  " + s;
    return out;
  }

 private:
  std::vector<std::string> shown_;
  std::size_t count_ = 0;
};

using ParameterValues = std::map<std::string, Value, std::less<>>;
// The rock's normal map made flat: the detail normal is then the geometric normal.
const ParameterValues kFlatDetail = {{"normalStrength", Value::scalar(0.f)}};

EvalInputs inputs(const SurfacePoint& surface, const FrameState& frame, const ParameterValues& parameters = {}) {
  EvalInputs in;
  in.surface = surface;
  in.frame = frame;
  in.parameters = parameters;
  return in;
}

FrameState snowyFrame(float snowLevel) {
  FrameState f;
  f.temperature = kFreezingC;
  f.snowLevel = snowLevel;
  return f;
}

// ---- Snow and inclination ----------------------------------------------------------------

// Counts the samples where snow decreases as the normal turns from facing down to
// facing up. It turns about the x axis with its x component fixed, so n.sun and n.wind
// stay fixed while n.y grows; the tangent lies along the axis, so the whole surface
// frame turns rigidly.
struct TurningUp {
  Violations decreasing;
  float largestDrop = 0.f;
  std::size_t covered = 0;  // samples with some snow
};
TurningUp snowWhileTurningUp(const CpuEvaluator& rock, const ParameterValues& parameters) {
  TurningUp result;
  for (float level : {0.35f, 0.7f, 1.f})
    for (float y : {-30.f, 0.f, 30.f})
      for (float nx : {-0.5f, 0.f, 0.5f})
        for (float side : {1.f, -1.f}) {
          FrameState frame = snowyFrame(level);
          frame.sunDirection = {1.f, 0.f, 0.f};
          frame.sunMelt = 0.8f;
          frame.windDirection = {1.f, 0.f};
          frame.windIntensity = 0.3f;
          const float radius = std::sqrt(1.f - nx * nx);
          for (const SurfacePoint& base : grid(y)) {
            float previous = 0.f;
            for (int k = 0; k <= kTurnSteps; ++k) {
              const float angle = std::numbers::pi_v<float> * (1.f - static_cast<float>(k) / kTurnSteps);
              SurfacePoint p = base;
              p.worldNormal = {nx, radius * std::cos(angle), side * radius * std::sin(angle)};
              const float snow = rock.evaluate(inputs(p, frame, parameters)).coverageOf(CoverageTerm::Snow);
              result.covered += snow > 0.f;
              if (k > 0) result.largestDrop = std::max(result.largestDrop, previous - snow);
              if (k > 0 && snow < previous - kTolerance)
                result.decreasing.add(at(p) + " level " + std::to_string(level) + ": snow " + std::to_string(snow) +
                                      " < " + std::to_string(previous) + " one step less upward");
              previous = snow;
            }
          }
        }
  return result;
}

// Eq. 3.4 adds the detail normal's own inclination: on a normal-mapped surface that
// turns rigidly, a facet tilted towards the bitangent turns away from up while the
// geometric normal turns towards it, so the geometric property only holds with the
// detail normal flat. Without displacement the fragment reads the mesh position.
TEST(WeatherProperties, SnowNeverDecreasesAsTheSurfaceTurnsUp) {
  const TurningUp result = snowWhileTurningUp(rockWithoutDisplacement(), kFlatDetail);
  EXPECT_EQ(result.decreasing.count(), 0u) << result.decreasing.report();
  EXPECT_GT(result.covered, 0u) << "no sample had snow: the property was not exercised";
}

// With snow displacement the fragment stage reads the position the vertex stage moved
// along the normal, and the coverage noise (eq. 3.14) is looked up there: turning the
// normal moves that point sideways by up to maxSnowHeight. Coverage may then dip by the
// noise difference, which stays below 0.011 (measured 0.0098); anything larger means
// the prediction itself stopped growing with inclination.
TEST(WeatherProperties, SnowTurningUpUnderSnowDisplacementDipsOnlyByTheNoise) {
  const TurningUp result = snowWhileTurningUp(bundled("rock"), kFlatDetail);
  constexpr float kNoiseShift = 0.011f;
  EXPECT_LT(result.largestDrop, kNoiseShift) << result.decreasing.report();
  EXPECT_GT(result.covered, 0u);
}

// Snow on faces from just below the horizon to straight down.
Violations snowOnDownwardFaces(const CpuEvaluator& rock, const ParameterValues& parameters) {
  Violations snowy;
  for (float level : {0.5f, 1.f})
    for (float y : {-30.f, 0.f, 30.f})
      for (int k = 1; k <= kTurnSteps; ++k)
        for (float azimuthDegrees : {0.f, 90.f, 200.f, 300.f}) {
          const float below = std::numbers::pi_v<float> / 2.f * static_cast<float>(k) / kTurnSteps;
          const float azimuth = azimuthDegrees * std::numbers::pi_v<float> / 180.f;
          const Vec3 normal{std::cos(below) * std::cos(azimuth), -std::sin(below), std::cos(below) * std::sin(azimuth)};
          FrameState frame = snowyFrame(level);
          frame.windIntensity = 1.f;  // the strongest wind term, which inclination must still gate
          for (const SurfacePoint& p : grid(y, normal)) {
            const float snow = rock.evaluate(inputs(p, frame, parameters)).coverageOf(CoverageTerm::Snow);
            if (snow != 0.f) snowy.add(at(p) + " level " + std::to_string(level) + ": snow " + std::to_string(snow));
          }
        }
  return snowy;
}

// With displacement; the detail normal flat for the reason above.
TEST(WeatherProperties, DownwardFacesStayBare) {
  const Violations snowy = snowOnDownwardFaces(bundled("rock"), kFlatDetail);
  EXPECT_EQ(snowy.count(), 0u) << snowy.report();
}

// With the rock's normal map: an up-facing detail facet on a slightly downward face
// once held snow (0.132 at normal (0.998, -0.065, 0)); the geometric gate in eq. 3.4
// keeps every underside bare.
TEST(WeatherProperties, DownwardFacesStayBareWithTheNormalMap) {
  const Violations snowy = snowOnDownwardFaces(bundled("rock"), {});
  EXPECT_EQ(snowy.count(), 0u) << snowy.report();
}

// ---- Sun ---------------------------------------------------------------------------------

// Sides tilted towards the sun's horizontal direction against sides tilted away (a
// sun above the horizon would also tilt the sunny side further up). The wind blows
// across that direction, so both sides see the same wind term; both have the same
// n.y, so the same inclination, as long as the detail normal is flat (see above: the
// two sides' tangent frames mirror each other, so a normal map tilts them apart).
TEST(WeatherProperties, SunFacingSidesHoldLessSnowAndLessMoss) {
  const CpuEvaluator& rock = bundled("rock");
  Violations moreSnow, moreMoss;
  double snowToward = 0, snowAway = 0, mossToward = 0, mossAway = 0;
  for (float azimuthDegrees : {0.f, 70.f, 160.f, 250.f})
    for (float elevationDegrees : {0.f, 35.f})
      for (float intensity : {0.5f, 1.f})
        for (float y : {kLowGround, -15.f, 0.f, 15.f, kHighGround}) {
          const float azimuth = azimuthDegrees * std::numbers::pi_v<float> / 180.f;
          const float elevation = elevationDegrees * std::numbers::pi_v<float> / 180.f;
          const Vec3 horizontal{std::cos(azimuth), 0.f, std::sin(azimuth)};
          FrameState frame;
          frame.temperature = kFreezingC;
          frame.snowLevel = 0.f;
          frame.mossLevel = 1.f;
          frame.sunDirection = {std::cos(elevation) * horizontal[0], std::sin(elevation), std::cos(elevation) * horizontal[2]};
          frame.sunMelt = intensity;
          frame.windDirection = {-horizontal[2], horizontal[0]};
          frame.windIntensity = 0.3f;
          FrameState snowy = frame;
          snowy.snowLevel = 0.8f;
          const Vec3 toward = normalized(plus(kUp, horizontal, kSideTilt));
          const Vec3 away = normalized(plus(kUp, horizontal, -kSideTilt));
          for (const SurfacePoint& base : grid(y)) {
            SurfacePoint sunny = base, shaded = base;
            sunny.worldNormal = toward;
            shaded.worldNormal = away;
            // Moss without snow, so no snow displacement moves the points apart.
            const float mossSunny = rock.evaluate(inputs(sunny, frame)).coverageOf(CoverageTerm::Moss);
            const float mossShaded = rock.evaluate(inputs(shaded, frame)).coverageOf(CoverageTerm::Moss);
            const float snowSunny = rock.evaluate(inputs(sunny, snowy, kFlatDetail)).coverageOf(CoverageTerm::Snow);
            const float snowShaded = rock.evaluate(inputs(shaded, snowy, kFlatDetail)).coverageOf(CoverageTerm::Snow);
            const std::string where = at(sunny) + " sun " + text(frame.sunDirection) + " melt " + std::to_string(intensity);
            if (mossSunny > mossShaded + kTolerance)
              moreMoss.add(where + ": moss " + std::to_string(mossSunny) + " facing the sun > " + std::to_string(mossShaded));
            if (snowSunny > snowShaded + kTolerance)
              moreSnow.add(where + ": snow " + std::to_string(snowSunny) + " facing the sun > " + std::to_string(snowShaded));
            mossToward += mossSunny;
            mossAway += mossShaded;
            snowToward += snowSunny;
            snowAway += snowShaded;
          }
        }
  EXPECT_EQ(moreSnow.count(), 0u) << moreSnow.report();
  EXPECT_EQ(moreMoss.count(), 0u) << moreMoss.report();
  EXPECT_LT(snowToward, snowAway) << "snow on average: facing the sun " << snowToward << ", away " << snowAway;
  EXPECT_LT(mossToward, mossAway) << "moss on average: facing the sun " << mossToward << ", away " << mossAway;
}

// The sun's direction at an elevation and azimuth (degrees).
Vec3 sunAt(float elevationDegrees, float azimuthDegrees) {
  const float e = elevationDegrees * std::numbers::pi_v<float> / 180.f;
  const float a = azimuthDegrees * std::numbers::pi_v<float> / 180.f;
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}
// A normal tilted from up by tiltDegrees towards the azimuth (negative: away from it).
Vec3 tiltedTowards(float tiltDegrees, float azimuthDegrees) {
  const float t = tiltDegrees * std::numbers::pi_v<float> / 180.f;
  const float a = azimuthDegrees * std::numbers::pi_v<float> / 180.f;
  return {std::sin(t) * std::cos(a), std::cos(t), std::sin(t) * std::sin(a)};
}

// Mean coverage of a term over the ground grid at height y, facing `normal`.
double meanCoverage(const CpuEvaluator& e, const FrameState& frame, CoverageTerm term, float y, Vec3 normal,
                    const ParameterValues& parameters = {}) {
  double total = 0;
  const std::vector<SurfacePoint> points = grid(y, normal);
  for (const SurfacePoint& p : points) total += e.evaluate(inputs(p, frame, parameters)).coverageOf(term);
  return total / static_cast<double>(points.size());
}

// Eq. 3.5's SunIntensity is the melt strength (sunMelt), not the light: at snowLevel 1,
// level ground stays covered (>= 0.95) whatever the sun's brightness, direction and melt
// strength, since snowLevel is the simulation's cover of open level ground.
TEST(WeatherProperties, BrightSunNeverClearsLevelGround) {
  const CpuEvaluator& rock = bundled("rock");
  Violations bare;
  for (float elevation : {3.f, 15.f, 30.f, 45.f, 60.f, 75.f, 90.f})
    for (float azimuth : {0.f, 130.f, 250.f})
      for (float light : {0.f, 1.f})
        for (float melt : {0.f, 0.5f, 1.f})
          for (float y : {0.f, 20.f}) {
            FrameState frame = snowyFrame(1.f);
            frame.sunDirection = sunAt(elevation, azimuth);
            frame.sunIntensity = light;
            frame.sunMelt = melt;
            for (const SurfacePoint& p : grid(y)) {
              const float snow = rock.evaluate(inputs(p, frame)).coverageOf(CoverageTerm::Snow);
              if (snow < 0.95f)
                bare.add(at(p) + " sun " + text(frame.sunDirection) + " light " + std::to_string(light) + " melt " +
                         std::to_string(melt) + ": snow " + std::to_string(snow));
            }
          }
  EXPECT_EQ(bare.count(), 0u) << bare.report();
}

// The light's brightness alone never changes the cover: only the melt strength does.
TEST(WeatherProperties, TheLightsBrightnessDoesNotMeltSnow) {
  const CpuEvaluator& rock = bundled("rock");
  Violations changed;
  for (float elevation : {15.f, 45.f, 90.f})
    for (float tilt : {0.f, 30.f, 45.f, 70.f}) {
      FrameState dim = snowyFrame(0.7f), bright = dim;
      dim.sunDirection = bright.sunDirection = sunAt(elevation, 0.f);
      dim.sunMelt = bright.sunMelt = 0.6f;
      dim.sunIntensity = 0.f;
      bright.sunIntensity = 1.f;
      for (const SurfacePoint& p : grid(0.f, tiltedTowards(tilt, 0.f))) {
        const float a = rock.evaluate(inputs(p, dim)).coverageOf(CoverageTerm::Snow);
        const float b = rock.evaluate(inputs(p, bright)).coverageOf(CoverageTerm::Snow);
        if (a != b) changed.add(at(p) + ": snow " + std::to_string(a) + " in a dim sun, " + std::to_string(b) + " in a bright one");
      }
    }
  EXPECT_EQ(changed.count(), 0u) << changed.report();
}

// At snowLevel 1 and full melt strength, slopes facing the sun hold less snow than the
// same slopes facing away (visibly so for steep slopes under a low sun), yet 30-degree
// slopes facing the sun are never bare. The detail normal is flat: the two slopes'
// tangent frames mirror each other, so the rock's normal map would tilt them apart.
TEST(WeatherProperties, SunFacingSlopesHoldLessSnowButThirtyDegreesIsNotBare) {
  const CpuEvaluator& rock = bundled("rock");
  for (float azimuth : {0.f, 130.f, 250.f}) {
    for (float elevation : {3.f, 15.f, 25.f, 45.f, 60.f, 80.f}) {
      FrameState frame = snowyFrame(1.f);
      frame.sunDirection = sunAt(elevation, azimuth);
      frame.sunIntensity = frame.sunMelt = 1.f;
      for (float tilt : {30.f, 45.f}) {
        const double toward = meanCoverage(rock, frame, CoverageTerm::Snow, 0.f, tiltedTowards(tilt, azimuth), kFlatDetail);
        const double away = meanCoverage(rock, frame, CoverageTerm::Snow, 0.f, tiltedTowards(-tilt, azimuth), kFlatDetail);
        EXPECT_LE(toward, away + kTolerance) << tilt << " degree slope, sun at " << elevation << " degrees";
        if (tilt == 30.f) {
          EXPECT_GT(toward, 0.5) << "30 degree slope facing a sun at " << elevation << " degrees is nearly bare";
        }
        if (tilt == 45.f && elevation <= 15.f) {
          EXPECT_LT(toward, away - 0.1) << "45 degree slope, sun at " << elevation << " degrees: facing it " << toward
                                        << ", facing away " << away;
        }
      }
    }
  }
}

// Seed 3.2.2 and 5.1.2: moss grows on the side that sees the least sun. With the sun 25
// degrees up, the flank facing away holds the most moss, the top less, the flank facing
// the sun the least, at moss levels 0.3 and 0.6.
TEST(WeatherProperties, MossGrowsMostOnTheShadedFlank) {
  const CpuEvaluator& rock = bundled("rock");
  for (float level : {0.3f, 0.6f})
    for (float azimuth : {0.f, 130.f, 250.f})
      for (float y : {-10.f, 0.f}) {
        FrameState frame;
        frame.temperature = 13.f;
        frame.mossLevel = level;
        frame.sunDirection = sunAt(25.f, azimuth);
        frame.sunIntensity = frame.sunMelt = 1.f;
        const double shaded = meanCoverage(rock, frame, CoverageTerm::Moss, y, tiltedTowards(-90.f, azimuth));
        const double top = meanCoverage(rock, frame, CoverageTerm::Moss, y, kUp);
        const double sunlit = meanCoverage(rock, frame, CoverageTerm::Moss, y, tiltedTowards(90.f, azimuth));
        EXPECT_GT(shaded, top) << "moss level " << level << " azimuth " << azimuth << " y " << y;
        EXPECT_GT(top, sunlit) << "moss level " << level << " azimuth " << azimuth << " y " << y;
      }
}

// ---- Height ------------------------------------------------------------------------------

TEST(WeatherProperties, HigherPointsHoldMoreSnowAndLessMoss) {
  const CpuEvaluator& rock = bundled("rock");
  Violations lessSnow, moreMoss;
  double snowLow = 0, snowHigh = 0, mossLow = 0, mossHigh = 0;
  const std::vector<Vec3> normals = {kUp, normalized({0.5f, 1.f, 0.f}), normalized({0.f, 1.f, -0.5f}),
                                     normalized({-1.f, 1.f, 0.3f}), normalized({0.2f, 0.3f, 1.f})};
  for (float level : {0.4f, 0.8f})
    for (const Vec3& normal : normals) {
      FrameState frame;
      frame.temperature = kFreezingC;
      frame.sunDirection = normalized({0.5f, 0.8f, 0.3f});
      frame.sunMelt = 0.7f;
      frame.windDirection = {0.6f, 0.8f};
      frame.windIntensity = 0.2f;
      FrameState snowy = frame, mossy = frame;
      snowy.snowLevel = level;
      mossy.mossLevel = level;
      const std::vector<SurfacePoint> low = grid(kLowGround, normal), high = grid(kHighGround, normal);
      for (std::size_t i = 0; i < low.size(); ++i) {
        const float sLow = rock.evaluate(inputs(low[i], snowy)).coverageOf(CoverageTerm::Snow);
        const float sHigh = rock.evaluate(inputs(high[i], snowy)).coverageOf(CoverageTerm::Snow);
        const float mLow = rock.evaluate(inputs(low[i], mossy)).coverageOf(CoverageTerm::Moss);
        const float mHigh = rock.evaluate(inputs(high[i], mossy)).coverageOf(CoverageTerm::Moss);
        if (sHigh < sLow - kTolerance)
          lessSnow.add(at(high[i]) + " level " + std::to_string(level) + ": snow " + std::to_string(sHigh) + " < " +
                       std::to_string(sLow) + " at y = " + std::to_string(kLowGround));
        if (mHigh > mLow + kTolerance)
          moreMoss.add(at(high[i]) + " level " + std::to_string(level) + ": moss " + std::to_string(mHigh) + " > " +
                       std::to_string(mLow) + " at y = " + std::to_string(kLowGround));
        snowLow += sLow;
        snowHigh += sHigh;
        mossLow += mLow;
        mossHigh += mHigh;
      }
    }
  EXPECT_EQ(lessSnow.count(), 0u) << lessSnow.report();
  EXPECT_EQ(moreMoss.count(), 0u) << moreMoss.report();
  EXPECT_GT(snowHigh, snowLow) << "snow on average";
  EXPECT_LT(mossHigh, mossLow) << "moss on average";
}

// ---- Thaw ----------------------------------------------------------------------------------

// Melting snow breaks up in patches with soft edges, not a partial cover everywhere:
// on level ground (the terrain graph, a square of kThawSide points kThawStep apart),
// at levels that leave about half the ground covered, most points are bare or covered,
// and neighbours a quarter metre apart mostly agree. Settling snow at the same level
// keeps eq. 3.14's partial cover (the contrast the property is about).
constexpr int kThawSide = 48;
constexpr float kThawStep = 0.25f;
constexpr float kThawC = 6.f;
struct CoverShares {
  double mean = 0, partial = 0, neighboursDiffer = 0;
};
CoverShares groundCover(const CpuEvaluator& terrain, const FrameState& frame) {
  std::vector<float> cover;
  for (int i = 0; i < kThawSide; ++i)
    for (int j = 0; j < kThawSide; ++j) {
      SurfacePoint p = grid(0.f).front();
      p.worldPosition = {0.37f + kThawStep * static_cast<float>(i), 0.f, 0.61f + kThawStep * static_cast<float>(j)};
      p.texcoord = {p.worldPosition[0] * kUvPerMetre, p.worldPosition[2] * kUvPerMetre};
      cover.push_back(terrain.evaluate(inputs(p, frame)).coverageOf(CoverageTerm::Snow));
    }
  CoverShares s;
  std::size_t pairs = 0;
  for (int i = 0; i < kThawSide; ++i)
    for (int j = 0; j < kThawSide; ++j) {
      const float c = cover[static_cast<std::size_t>(i * kThawSide + j)];
      s.mean += c;
      s.partial += c > 0.1f && c < 0.9f;
      if (j + 1 < kThawSide) {
        s.neighboursDiffer += std::fabs(c - cover[static_cast<std::size_t>(i * kThawSide + j + 1)]) > 0.5f;
        ++pairs;
      }
    }
  const double n = static_cast<double>(cover.size());
  s.mean /= n;
  s.partial /= n;
  s.neighboursDiffer /= static_cast<double>(pairs);
  return s;
}

TEST(WeatherProperties, ThawingSnowBreaksUpInSoftEdgedPatches) {
  const CpuEvaluator& terrain = bundled("terrain");
  int halfCovered = 0;
  for (float level : {0.25f, 0.3f, 0.35f, 0.4f}) {
    FrameState thaw;
    thaw.temperature = kThawC;
    thaw.snowLevel = level;
    const CoverShares melting = groundCover(terrain, thaw);
    if (melting.mean < 0.25 || melting.mean > 0.75) continue;
    ++halfCovered;
    EXPECT_LT(melting.partial, 0.35) << "level " << level << ": a partial cover everywhere, not patches (mean "
                                    << melting.mean << ")";
    EXPECT_LT(melting.neighboursDiffer, 0.05) << "level " << level << ": bare and covered alternate within 0.25 m";
    const CoverShares settling = groundCover(terrain, snowyFrame(level));
    EXPECT_GT(settling.partial, 0.5) << "level " << level << ": settling snow should keep eq. 3.14's partial cover";
  }
  EXPECT_GE(halfCovered, 1) << "no level left about half the ground covered";
}

// ---- Wetness -----------------------------------------------------------------------------

// The frame the runtime uploads for a weather state.
FrameState frameOf(const WeatherState& s) {
  FrameState f;
  f.temperature = s.conditions.temperature;
  f.precipitation = s.conditions.precipitation;
  f.windDirection = s.conditions.windDirection;
  f.windIntensity = s.conditions.windIntensity;
  f.sunDirection = s.conditions.sunDirection;
  f.sunIntensity = s.conditions.sunIntensity;
  f.sunMelt = s.conditions.sunMelt;
  f.time = static_cast<float>(s.time);
  f.snowLevel = s.levels.snow;
  f.wetnessLevel = s.levels.wetness;
  f.mossLevel = s.levels.moss;
  f.frostLevel = s.levels.frost;
  f.puddleLevel = s.levels.puddles;
  return f;
}

TEST(WeatherProperties, WetnessAppearsOnlyWhenItRainsAboveFreezing) {
  constexpr double kOneHour = weather_physics::kSecondsPerHour;
  const CpuEvaluator& rock = bundled("rock");
  Violations wrong;
  for (float temperature : {-20.f, -5.f, -1.f, -0.25f, 0.f, 0.25f, 1.f, 5.f, 20.f})
    for (float precipitation : {0.f, 0.05f, 0.4f, 1.f}) {
      WeatherState state;  // dry: every level 0
      state.conditions.temperature = temperature;
      state.conditions.precipitation = precipitation;
      advanceWeather(state, kOneHour);
      const FrameState frame = frameOf(state);
      const bool shouldBeWet = temperature > 0.f && precipitation > 0.f;
      for (const SurfacePoint& p : grid(0.f)) {
        const float wet = rock.evaluate(inputs(p, frame)).coverageOf(CoverageTerm::Wet);
        if ((wet > 0.f) != shouldBeWet)
          wrong.add(at(p) + " T " + std::to_string(temperature) + " P " + std::to_string(precipitation) +
                    " (wetnessLevel " + std::to_string(state.levels.wetness) + "): wet " + std::to_string(wet));
      }
    }
  EXPECT_EQ(wrong.count(), 0u) << wrong.report();
}

// Eq. 3.16-3.17 against the material without weather: the same base graph, so the
// wet outputs are exactly the dry ones transformed by p = coverage.wet.
TEST(WeatherProperties, WetSurfacesDarkenAndSmoothenByTheWetCoverage) {
  Violations wrong;
  float largestP = 0.f;
  for (float temperature : {0.5f, 2.f, 12.f})
    for (float level : {0.25f, 0.6f, 1.f})
      for (float precipitation : {0.f, 0.5f})
        for (float exposure : {1.f, 0.5f})
          for (SurfacePoint p : grid(0.f, normalized({0.3f, 1.f, 0.2f}))) {
            FrameState frame;
            frame.temperature = temperature;
            frame.wetnessLevel = level;
            frame.precipitation = precipitation;
            p.skyExposure = exposure;
            const EvalResult dry = rockWithoutWeather().evaluate(inputs(p, frame));
            const EvalResult wet = rockWetOnly().evaluate(inputs(p, frame));
            const float wetness = wet.coverageOf(CoverageTerm::Wet);
            largestP = std::max(largestP, wetness);
            const float darkening = 1.f * (1.f - wetness) + kWetDiffuse * wetness;
            for (int c = 0; c < 3; ++c) {
              const float expected = dry.output(PbrField::BaseColor).v[c] * darkening;
              if (std::abs(wet.output(PbrField::BaseColor).v[c] - expected) > kTolerance)
                wrong.add(at(p) + " p " + std::to_string(wetness) + ": baseColor[" + std::to_string(c) + "] " +
                          std::to_string(wet.output(PbrField::BaseColor).v[c]) + ", expected " + std::to_string(expected));
            }
            const float roughness = std::clamp(dry.output(PbrField::Roughness).x() - wetness, 0.f, 1.f);
            if (std::abs(wet.output(PbrField::Roughness).x() - roughness) > kTolerance)
              wrong.add(at(p) + " p " + std::to_string(wetness) + ": roughness " +
                        std::to_string(wet.output(PbrField::Roughness).x()) + ", expected " + std::to_string(roughness));
          }
  EXPECT_EQ(wrong.count(), 0u) << wrong.report();
  EXPECT_GT(largestP, 0.5f) << "the samples never got wet enough to test eq. 3.16-3.17";
}

// ---- Albedo bands (Table 4.1) ------------------------------------------------------------

// Checks the albedo of every sample whose coverage term is full; returns how many were.
std::size_t checkBand(const CpuEvaluator& evaluator, const std::vector<SurfacePoint>& points, const FrameState& frame,
                      CoverageTerm term, float low, float high, Violations& outside) {
  std::size_t full = 0;
  for (const SurfacePoint& p : points) {
    const EvalResult r = evaluator.evaluate(inputs(p, frame));
    if (r.coverageOf(term) != 1.f) continue;
    ++full;
    const float value = reflectance(r.output(PbrField::BaseColor));
    if (value < low - kTolerance || value > high + kTolerance)
      outside.add(at(p) + ": reflectance " + std::to_string(value) + " outside [" + std::to_string(low) + ", " +
                  std::to_string(high) + "]");
  }
  return full;
}

TEST(WeatherProperties, FullySnowCoveredRockIsInTheSnowBand) {
  Violations outside;
  std::size_t full = 0;
  for (float y : {-10.f, 0.f, 20.f}) full += checkBand(bundled("rock"), grid(y), snowyFrame(1.f), CoverageTerm::Snow,
                                                      kSnowBandLow, kSnowBandHigh, outside);
  EXPECT_EQ(outside.count(), 0u) << outside.report();
  EXPECT_GT(full, 0u) << "no sample was fully snow covered";
}

TEST(WeatherProperties, FullMossOnShadedLowGroundIsInTheGrassBand) {
  FrameState frame;
  frame.mossLevel = 1.f;
  frame.sunDirection = normalized({1.f, 0.5f, 0.f});
  frame.sunMelt = 1.f;
  const Vec3 shaded = normalized(plus(kUp, {1.f, 0.f, 0.f}, -kSideTilt));
  Violations outside;
  const std::size_t full = checkBand(bundled("rock"), grid(kLowGround, shaded), frame, CoverageTerm::Moss,
                                     kGrassBandLow, kGrassBandHigh, outside);
  EXPECT_EQ(outside.count(), 0u) << outside.report();
  EXPECT_GT(full, 0u) << "no sample was fully moss covered";
}

TEST(WeatherProperties, FrozenRiverMidStreamIsInTheOceanIceBand) {
  constexpr float kMidStream = 0.5f;  // v across the river: 0 and 1 are the banks
  FrameState frame;
  frame.temperature = kFreezingC;
  frame.frostLevel = 1.f;
  std::vector<SurfacePoint> points = grid(0.f);
  for (SurfacePoint& p : points) p.texcoord[1] = kMidStream;
  Violations outside;
  const std::size_t full = checkBand(bundled("river"), points, frame, CoverageTerm::Ice, kOceanIceBandLow,
                                     kOceanIceBandHigh, outside);
  EXPECT_EQ(outside.count(), 0u) << outside.report();
  EXPECT_EQ(full, points.size()) << "mid-stream should freeze over completely at frostLevel 1";
}

// ---- Degenerate inputs -------------------------------------------------------------------

bool inUnitRange(float x) { return std::isfinite(x) && x >= 0.f && x <= 1.f; }

// Every output finite; colours, factors and coverage in [0, 1].
std::string rangeProblem(const EvalResult& r) {
  for (const auto& [name, value] : r.outputs) {
    if (!value.allFinite()) return name + " is not finite";
    const bool unitRange = name != "normal" && name != "worldPositionOffset" && name != "emissive";
    for (int c = 0; c < value.width(); ++c) {
      if (unitRange && !inUnitRange(value.v[c])) return name + "[" + std::to_string(c) + "] = " + std::to_string(value.v[c]);
      if (name == "emissive" && value.v[c] < 0.f) return "emissive is negative";
    }
  }
  for (const auto& [name, value] : r.coverage)
    if (!inUnitRange(value)) return "coverage " + name + " = " + std::to_string(value);
  return "";
}

TEST(WeatherProperties, DegenerateInputsGiveFiniteInRangeOutputs) {
  const std::vector<Vec3> normals = {{0.f, 0.f, 0.f}, kUp, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}};
  const std::vector<std::array<float, 4>> tangents = {{1.f, 0.f, 0.f, 1.f}, {0.f, 0.f, 0.f, 1.f}, {0.f, 1.f, 0.f, -1.f}};
  for (const char* name : {"rock", "road", "river", "foliage", "terrain", "grass", "snowfield"}) {
    const CpuEvaluator& evaluator = bundled(name);
    Violations problems;
    for (float temperature : kDegenerateTemperatures)
      for (float level : {0.f, 1.f})
        for (float precipitation : {0.f, 1.f})
          for (bool calm : {true, false})
            for (const Vec3& normal : normals)
              for (const auto& tangent : tangents)
                for (float exposure : {0.f, 1.f}) {
                  FrameState f;
                  f.temperature = temperature;
                  f.precipitation = precipitation;
                  f.snowLevel = f.wetnessLevel = f.mossLevel = f.frostLevel = f.puddleLevel = level;
                  f.windDirection = calm ? std::array<float, 2>{0.f, 0.f} : std::array<float, 2>{0.f, 1.f};
                  f.windIntensity = calm ? 0.f : 1.f;
                  f.sunDirection = calm ? Vec3{0.f, 0.f, 0.f} : kUp;  // a zero sun, like the zero wind
                  f.sunIntensity = f.sunMelt = level;
                  f.time = calm ? 0.f : 1e4f;
                  SurfacePoint p;
                  p.worldNormal = normal;
                  p.tangent = tangent;
                  p.skyExposure = exposure;
                  p.texcoord = {0.3f, 0.6f};
                  const std::string problem = rangeProblem(evaluator.evaluate(inputs(p, f)));
                  if (!problem.empty())
                    problems.add(std::string(name) + " " + at(p) + " tangent " +
                                 text({tangent[0], tangent[1], tangent[2]}) + " T " + std::to_string(temperature) +
                                 " levels " + std::to_string(level) + (calm ? " calm" : " windy") + ": " + problem);
                }
    EXPECT_EQ(problems.count(), 0u) << problems.report();
  }
}

// ---- Puddles -----------------------------------------------------------------------------

TEST(WeatherProperties, PuddlesFormOnlyOnNearlyFlatGround) {
  const CpuEvaluator& road = bundled("road");
  FrameState frame;
  frame.temperature = 8.f;
  frame.puddleLevel = 1.f;
  frame.wetnessLevel = 1.f;
  frame.precipitation = 1.f;
  Violations onSlopes;
  const float tilt = kPuddleTestTiltDegrees * std::numbers::pi_v<float> / 180.f;
  for (float azimuthDegrees : {0.f, 90.f, 180.f, 270.f, 45.f}) {
    const float azimuth = azimuthDegrees * std::numbers::pi_v<float> / 180.f;
    const Vec3 tilted{std::sin(tilt) * std::cos(azimuth), std::cos(tilt), std::sin(tilt) * std::sin(azimuth)};
    for (const SurfacePoint& p : grid(0.f, tilted)) {
      const float puddle = road.evaluate(inputs(p, frame)).coverageOf(CoverageTerm::Puddle);
      if (puddle != 0.f) onSlopes.add(at(p) + ": puddle " + std::to_string(puddle) + " on a 10 degree slope");
    }
  }
  EXPECT_EQ(onSlopes.count(), 0u) << onSlopes.report();
  float largest = 0.f;
  for (const SurfacePoint& p : grid(0.f))
    largest = std::max(largest, road.evaluate(inputs(p, frame)).coverageOf(CoverageTerm::Puddle));
  EXPECT_GT(largest, 0.f) << "no puddle anywhere on flat ground at puddleLevel 1";
}

// ---- Wetness on every preset -------------------------------------------------------------

// Section 5.1.2: in rain above 0 C "the wetness function is applied to any scene object
// regardless of their material" (eq. 3.15-3.17): every preset darkens and smooths,
// foliage and the river's banks included; the river's open water stays as it was.
TEST(WeatherProperties, EveryPresetGetsWetInRainAboveFreezing) {
  constexpr float kBankV = 0.03f, kMidStreamV = 0.5f;
  for (const char* name : {"rock", "terrain", "grass", "foliage", "road", "river"}) {
    const CpuEvaluator& e = bundled(name);
    FrameState dry;
    dry.temperature = 8.f;
    FrameState wet = dry;
    wet.wetnessLevel = 1.f;
    wet.precipitation = 0.5f;
    Violations wrong;
    for (SurfacePoint p : grid(0.f)) {
      if (std::string(name) == "river") p.texcoord[1] = kBankV;
      const EvalResult a = e.evaluate(inputs(p, dry)), b = e.evaluate(inputs(p, wet));
      const float pWet = b.coverageOf(CoverageTerm::Wet);
      const float darker = reflectance(b.output(PbrField::BaseColor)) / std::max(reflectance(a.output(PbrField::BaseColor)), 1e-6f);
      if (pWet < 0.5f) wrong.add(std::string(name) + " " + at(p) + ": wet " + std::to_string(pWet));
      if (darker > 1.f - 0.3f * pWet + kTolerance)
        wrong.add(std::string(name) + " " + at(p) + ": colour only " + std::to_string(darker) + " of the dry one");
      if (b.output(PbrField::Roughness).x() > a.output(PbrField::Roughness).x() + kTolerance ||
          (a.output(PbrField::Roughness).x() > 0.05f && b.output(PbrField::Roughness).x() >= a.output(PbrField::Roughness).x()))
        wrong.add(std::string(name) + " " + at(p) + ": roughness " + std::to_string(b.output(PbrField::Roughness).x()) +
                  " wet, " + std::to_string(a.output(PbrField::Roughness).x()) + " dry");
    }
    EXPECT_EQ(wrong.count(), 0u) << wrong.report();
  }
  // The river's water itself stays water.
  const CpuEvaluator& river = bundled("river");
  FrameState wet;
  wet.temperature = 8.f;
  wet.wetnessLevel = 1.f;
  wet.precipitation = 0.5f;
  FrameState dry = wet;
  dry.wetnessLevel = 0.f;
  for (SurfacePoint p : grid(0.f)) {
    p.texcoord[1] = kMidStreamV;
    const EvalResult a = river.evaluate(inputs(p, dry)), b = river.evaluate(inputs(p, wet));
    EXPECT_EQ(b.coverageOf(CoverageTerm::Wet), 0.f) << at(p);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(b.output(PbrField::BaseColor).v[c], a.output(PbrField::BaseColor).v[c]) << at(p);
    EXPECT_EQ(b.output(PbrField::Roughness).x(), a.output(PbrField::Roughness).x()) << at(p);
  }
}

// ---- Puddles freeze ----------------------------------------------------------------------

// Below 0 C a puddle is ice: ice's roughness and F0 (specular 0.225) and the Table 4.1
// ice band, and the ice AOV shows it. Above, it is water again (specular 0.25, near
// mirror).
TEST(WeatherProperties, PuddlesFreezeBelowZero) {
  const CpuEvaluator& road = bundled("road");
  std::size_t frozen = 0, liquid = 0;
  Violations wrong;
  for (float temperature : {-10.f, -0.5f, 0.f, 8.f})
    for (const SurfacePoint& p : grid(0.f)) {
      FrameState frame;
      frame.temperature = temperature;
      frame.puddleLevel = 1.f;
      const EvalResult r = road.evaluate(inputs(p, frame));
      const float puddle = r.coverageOf(CoverageTerm::Puddle);
      if (puddle != 1.f) continue;
      const bool cold = temperature <= 0.f;
      (cold ? frozen : liquid) += 1;
      const float roughness = r.output(PbrField::Roughness).x(), specular = r.output(PbrField::Specular).x();
      const float expectRoughness = cold ? 0.12f : 0.02f, expectSpecular = cold ? 0.225f : 0.25f;
      if (std::abs(roughness - expectRoughness) > kTolerance || std::abs(specular - expectSpecular) > kTolerance)
        wrong.add(at(p) + " T " + std::to_string(temperature) + ": roughness " + std::to_string(roughness) +
                  " specular " + std::to_string(specular));
      if (cold) {
        const float value = reflectance(r.output(PbrField::BaseColor));
        if (value < kOceanIceBandLow - kTolerance || value > kOceanIceBandHigh + kTolerance)
          wrong.add(at(p) + " T " + std::to_string(temperature) + ": reflectance " + std::to_string(value));
        if (r.coverageOf(CoverageTerm::Ice) != 1.f) wrong.add(at(p) + ": ice AOV " + std::to_string(r.coverageOf(CoverageTerm::Ice)));
      } else if (r.coverageOf(CoverageTerm::Ice) != 0.f) {
        wrong.add(at(p) + ": ice AOV on a liquid puddle");
      }
    }
  EXPECT_EQ(wrong.count(), 0u) << wrong.report();
  EXPECT_GT(frozen, 0u);
  EXPECT_GT(liquid, 0u);
}

// Puddles fill only from the liquid part of precipitation: none at or below 0 C (all
// snow), less in sleet than in rain.
TEST(WeatherProperties, PuddlesFillOnlyFromLiquidPrecipitation) {
  auto puddlesAfterThreeHours = [](float temperature) {
    WeatherState s;
    s.conditions.temperature = temperature;
    s.conditions.precipitation = 1.f;
    advanceWeather(s, 3 * weather_physics::kSecondsPerHour);
    return s.levels.puddles;
  };
  for (float t : {-10.f, -1.f, -0.5f, 0.f}) EXPECT_EQ(puddlesAfterThreeHours(t), 0.f) << t << " C";
  EXPECT_GT(puddlesAfterThreeHours(0.5f), 0.f);
  EXPECT_LT(puddlesAfterThreeHours(0.5f), puddlesAfterThreeHours(5.f));
}

// ---- Terrain renormalises its weights ---------------------------------------------------

// The terrain preset has the sun term off. Its weight w1 (2, which balances a typical
// f_sun of 0.5) is then 1 too, so eq. 3.8's height shapes the cover over the lower half
// of the range instead of saturating from a quarter of it (y = -25 m).
TEST(WeatherProperties, TerrainHeightShapesTheCoverWhenTheSunTermIsOff) {
  const CpuEvaluator& terrain = bundled("terrain");
  const FrameState frame = snowyFrame(0.5f);
  const double low = meanCoverage(terrain, frame, CoverageTerm::Snow, -40.f, kUp);
  const double quarter = meanCoverage(terrain, frame, CoverageTerm::Snow, -25.f, kUp);
  const double middle = meanCoverage(terrain, frame, CoverageTerm::Snow, 0.f, kUp);
  EXPECT_LT(low, quarter);
  EXPECT_LT(quarter, middle - 0.2) << "cover at y = -25 m " << quarter << ", at 0 m " << middle;
  EXPECT_GT(middle, 0.9);
}

// ---- Ice edges ---------------------------------------------------------------------------

// Eq. 3.14: ice gets noisy edges, like snow and moss. Along the river (same distance
// from the bank, v fixed) the ice coverage of a freezing river varies with position.
TEST(WeatherProperties, IceEdgesAreNoisy) {
  const CpuEvaluator& river = bundled("river");
  FrameState frame;
  frame.temperature = -5.f;
  frame.frostLevel = 0.6f;
  float widest = 0.f;
  for (float v : {0.1f, 0.2f, 0.3f}) {
    float lo = 1.f, hi = 0.f;
    for (SurfacePoint p : grid(0.f)) {
      p.texcoord[1] = v;
      const float ice = river.evaluate(inputs(p, frame)).coverageOf(CoverageTerm::Ice);
      lo = std::min(lo, ice);
      hi = std::max(hi, ice);
    }
    widest = std::max(widest, hi - lo);
  }
  EXPECT_GT(widest, 0.3f) << "the ice edge is a smooth gradient across the stream";
}

}  // namespace
}  // namespace wg
