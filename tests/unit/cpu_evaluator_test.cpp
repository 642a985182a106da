// The CPU evaluator: hand-computed outputs of a small graph, the shader stages'
// conventions (normalised normal, orthogonal tangent, displaced fragment position),
// parameter overrides, texture sampling and neutral coverage without weather.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "compiler/cpu_evaluator.hpp"
#include "driver/material_compiler.hpp"
#include "nodes/texture_generators.hpp"

namespace wg {
namespace {

constexpr float kTolerance = 1e-6f;

IrGraph optimizedIr(const std::string& json, const CompileOptions& options = {}, const std::string& file = "inline.json") {
  DiagnosticList diagnostics;
  auto ir = buildOptimizedIr(file, json, diagnostics, options);
  for (const auto& d : diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  if (!ir) throw std::runtime_error("graph did not build");
  return std::move(*ir);
}

std::string readSource(const std::string& relative) {
  std::ifstream in(std::string(WG_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void expectVec(const Value& v, std::array<float, 4> expected, int width) {
  ASSERT_EQ(v.width(), width);
  for (int i = 0; i < width; ++i) EXPECT_NEAR(v.v[i], expected[i], kTolerance) << "component " << i;
}

// baseColor = displaced position * scale; roughness = normal.y; metallic = u;
// specular = time / 4; emissive = tangent.xyz; worldPositionOffset = normal / 10.
const std::string kProbeGraph = R"({
  "name": "probe",
  "parameters": {"scale": {"type": "float", "default": 0.5}},
  "nodes": [
    {"id": "p", "op": "world_position"},
    {"id": "n", "op": "world_normal"},
    {"id": "uv", "op": "texcoord"},
    {"id": "t", "op": "time"},
    {"id": "tg", "op": "tangent"},
    {"id": "scale", "op": "parameter", "param": "scale"},
    {"id": "scaled", "op": "multiply", "inputs": {"a": "p.out", "b": "scale.out"}},
    {"id": "ny", "op": "split", "inputs": {"in": "n.out"}},
    {"id": "u", "op": "split", "inputs": {"in": "uv.out"}},
    {"id": "quarterTime", "op": "multiply", "inputs": {"a": "t.out", "b": 0.25}},
    {"id": "axis", "op": "swizzle", "inputs": {"in": "tg.out", "channels": "xyz"}},
    {"id": "lift", "op": "multiply", "inputs": {"a": "n.out", "b": 0.1}}
  ],
  "output": {"baseColor": "scaled.out", "roughness": "ny.y", "metallic": "u.x", "specular": "quarterTime.out",
             "emissive": "axis.out", "worldPositionOffset": "lift.out"}
})";

EvalInputs probeInputs() {
  EvalInputs in;
  in.surface.worldPosition = {1.f, 2.f, 3.f};
  in.surface.worldNormal = {0.f, 2.f, 0.f};  // not unit: the stages normalise it
  in.surface.tangent = {1.f, 1.f, 0.f, 1.f};  // not orthogonal to the normal
  in.surface.texcoord = {0.75f, 0.25f};
  in.frame.time = 2.f;
  return in;
}

TEST(CpuEvaluator, ComputesHandCheckedOutputsWithTheShaderStagesConventions) {
  const CpuEvaluator evaluator(optimizedIr(kProbeGraph));
  const EvalResult r = evaluator.evaluate(probeInputs());
  // Vertex stage: offset = normalize((0, 2, 0)) * 0.1.
  expectVec(r.output(PbrField::WorldPositionOffset), {0.f, 0.1f, 0.f}, 3);
  // Fragment stage: position (1, 2, 3) + offset, times the default scale 0.5.
  expectVec(r.output(PbrField::BaseColor), {0.5f, 1.05f, 1.5f}, 3);
  expectVec(r.output(PbrField::Roughness), {1.f}, 1);
  expectVec(r.output(PbrField::Metallic), {0.75f}, 1);
  expectVec(r.output(PbrField::Specular), {0.5f}, 1);
  // (1, 1, 0) made orthogonal to (0, 1, 0) and unit length.
  expectVec(r.output(PbrField::Emissive), {1.f, 0.f, 0.f}, 3);
  // Fields the graph leaves out keep their defaults.
  expectVec(r.output(PbrField::AmbientOcclusion), {1.f}, 1);
  expectVec(r.output(PbrField::Opacity), {1.f}, 1);
  expectVec(r.output(PbrField::Normal), {0.f, 0.f, 1.f}, 3);
  EXPECT_EQ(r.outputs.size(), kPbrFieldCount);
  EXPECT_EQ(r.coverage.size(), kCoverageCount);
}

TEST(CpuEvaluator, ZeroNormalStaysZeroAndFinite) {
  const CpuEvaluator evaluator(optimizedIr(kProbeGraph));
  EvalInputs in = probeInputs();
  in.surface.worldNormal = {0.f, 0.f, 0.f};
  const EvalResult r = evaluator.evaluate(in);
  expectVec(r.output(PbrField::WorldPositionOffset), {0.f, 0.f, 0.f}, 3);
  expectVec(r.output(PbrField::Roughness), {0.f}, 1);
  // Nothing to make the tangent orthogonal to: it is only normalised.
  expectVec(r.output(PbrField::Emissive), {std::sqrt(0.5f), std::sqrt(0.5f), 0.f}, 3);
}

TEST(CpuEvaluator, ParameterOverridesReplaceDefaultsAndAreChecked) {
  const CpuEvaluator evaluator(optimizedIr(kProbeGraph));
  EvalInputs in = probeInputs();
  in.parameters["scale"] = Value::scalar(2.f);
  expectVec(evaluator.evaluate(in).output(PbrField::BaseColor), {2.f, 4.2f, 6.f}, 3);

  in.parameters["scale"] = Value::vec3(1.f, 1.f, 1.f);  // a vec3 cannot become a float
  EXPECT_THROW(evaluator.evaluate(in), std::invalid_argument);
  in.parameters.clear();
  in.parameters["scael"] = Value::scalar(1.f);
  EXPECT_THROW(evaluator.evaluate(in), std::invalid_argument);
}

TEST(CpuEvaluator, SamplesProceduralTexturesLikeSampleImageOfTheGeneratedImage) {
  constexpr std::uint32_t kSeed = 7;
  constexpr int kSize = 32;
  const std::string graph = R"({
    "name": "textured",
    "textures": {"t": {"generator": "fbm", "seed": 7, "size": 32, "wrap": "mirror", "filter": "linear"}},
    "nodes": [
      {"id": "uv", "op": "texcoord"},
      {"id": "s", "op": "sample", "inputs": {"texture": "t", "uv": "uv.out"}}
    ],
    "output": {"baseColor": "s.rgb", "opacity": "s.a"}
  })";
  const CpuEvaluator evaluator(optimizedIr(graph));
  const Image image = generateTexture(*findTextureGenerator("fbm"), kSeed, kSize, nlohmann::json::object());
  for (auto [u, v] : {std::pair{0.1f, 0.2f}, {0.5f, 0.5f}, {0.013f, 0.977f}, {-0.3f, 1.7f}, {2.25f, -4.4f}}) {
    EvalInputs in;
    in.surface.texcoord = {u, v};
    const EvalResult r = evaluator.evaluate(in);
    const Value expected = sampleImage(image, u, v, TextureWrap::Mirror, TextureFilter::Linear);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(r.output(PbrField::BaseColor).v[c], expected.v[c]) << u << ", " << v;
    EXPECT_EQ(r.output(PbrField::Opacity).x(), expected.v[3]);
  }
}

TEST(CpuEvaluator, CoverageIsNeutralWithoutWeather) {
  EvalInputs in;
  in.frame.snowLevel = in.frame.wetnessLevel = in.frame.mossLevel = 1.f;
  in.frame.frostLevel = in.frame.puddleLevel = 1.f;
  in.frame.temperature = 5.f;
  in.frame.precipitation = 1.f;
  const std::string rock = readSource("graphs/rock.json");
  for (const CpuEvaluator& evaluator :
       {CpuEvaluator(optimizedIr(kProbeGraph)),
        CpuEvaluator(optimizedIr(rock, CompileOptions{.weatherPreset = "none"}, WG_SOURCE_DIR "/graphs/rock.json"))}) {
    const EvalResult r = evaluator.evaluate(in);
    for (const auto& term : coverageTerms()) {
      EXPECT_EQ(r.coverageOf(term.term), term.term == CoverageTerm::Density ? 1.f : 0.f) << term.name;
      EXPECT_EQ(r.coverageOf(term.term), term.neutral) << term.name;
    }
  }
}

TEST(CpuEvaluator, WeatherPresetProducesCoverage) {
  const CpuEvaluator evaluator(
      optimizedIr(readSource("graphs/rock.json"), {}, WG_SOURCE_DIR "/graphs/rock.json"));
  EvalInputs in;
  in.frame.snowLevel = 1.f;
  in.frame.temperature = -5.f;
  const EvalResult r = evaluator.evaluate(in);  // up-facing, mid height: full snow
  EXPECT_EQ(r.coverageOf(CoverageTerm::Snow), 1.f);
  // Displaced along the normal by at most maxSnowHeight.
  const Value offset = r.output(PbrField::WorldPositionOffset);
  EXPECT_GT(offset.v[1], 0.f);
  EXPECT_LE(offset.v[1], evaluator.ir().weather.maxSnowHeight);
}

}  // namespace
}  // namespace wg
