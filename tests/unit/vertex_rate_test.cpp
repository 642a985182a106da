// The vertex-rate pass: smooth values the fragment stage needs are computed per vertex
// and read interpolated, in both languages, only where the vertex stage can compute
// their whole input cone.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "compiler/ir_text.hpp"
#include "compiler/pass_pipeline.hpp"
#include "driver/material_compiler.hpp"
#include "ir_fixture.hpp"

namespace wg {
namespace {

using json = nlohmann::json;
using testing::graphJson;
using testing::irBeforePasses;

std::string source(const CompiledMaterial& m, ShaderLanguage language, ShaderStage stage) {
  return m.stage(language, stage).source;
}
bool contains(const std::string& text, std::string_view piece) { return text.find(piece) != std::string::npos; }

IrGraph optimized(const std::string& json) {
  IrGraph g = irBeforePasses(json);
  EXPECT_EQ(runPassPipeline(g, {.verifyBetweenPasses = true}), std::nullopt);
  return g;
}

// Eq. 3.12's slope, from the terrain height map at the world position: nothing the
// vertex stage lacks.
const std::string kSlopeNodes =
    R"({"id": "p", "op": "world_position"},
       {"id": "uv", "op": "terrain_coord", "inputs": {"position": "p.out"}},
       {"id": "uvU", "op": "add", "inputs": {"a": "uv.out", "b": [0.05, 0]}},
       {"id": "uvV", "op": "add", "inputs": {"a": "uv.out", "b": [0, 0.05]}},
       {"id": "h0", "op": "terrain_height", "inputs": {"uv": "uv.out"}},
       {"id": "hu", "op": "terrain_height", "inputs": {"uv": "uvU.out"}},
       {"id": "hv", "op": "terrain_height", "inputs": {"uv": "uvV.out"}})";

TEST(VertexRatePass, ASlopeOfTheTerrainMapIsComputedPerVertex) {
  IrGraph g = optimized(graphJson(
      kSlopeNodes + R"(, {"id": "s", "op": "weather_terrain_slope", "inputs": {"h0": "h0.out", "hShiftU": "hu.out", "hShiftV": "hv.out"}})",
      R"("baseColor": "s.out")"));
  ASSERT_EQ(g.interpolants.size(), 1u);
  EXPECT_EQ(g.nodes[g.interpolants[0]].op->name, "weather_terrain_slope");
  EXPECT_TRUE(contains(formatIrText(g), "weather_terrain_slope(h0: ") && contains(formatIrText(g), ") [per vertex]\n"))
      << formatIrText(g);
}

// Every slope a different intensity, so none merge: more than the hosts can pass. Five
// vec3s fill 15 of the 16 components Filament's four custom variables hold.
TEST(VertexRatePass, AtMostSixteenComponentsAreInterpolatedAndTheRestStayPerPixel) {
  std::string nodes = kSlopeNodes;
  std::string sum = "0";
  for (int i = 0; i < 12; ++i) {
    std::string id = "s" + std::to_string(i);
    nodes += R"(, {"id": ")" + id + R"(", "op": "weather_terrain_slope", "inputs": {"h0": "h0.out", "hShiftU": "hu.out", "hShiftV": "hv.out", "intensity": )" +
             std::to_string(i + 2) + "}}";
    nodes += R"(, {"id": "a)" + std::to_string(i) + R"(", "op": "add", "inputs": {"a": )" +
             (i ? "\"a" + std::to_string(i - 1) + ".out\"" : std::string("0")) + R"(, "b": ")" + id + R"(.out"}})";
    sum = "a" + std::to_string(i) + ".out";
  }
  std::string json = graphJson(nodes, R"("baseColor": ")" + sum + R"(")");
  EXPECT_EQ(optimized(json).interpolants.size(), 5u);
  CompileResult r = compileMaterialText("t.json", json, {});
  ASSERT_TRUE(r.material);
  const CompiledMaterial& m = *r.material;
  for (const auto& stage : m.stages) EXPECT_FALSE(stage.spirv.empty());  // validated
  std::string fragment = source(m, ShaderLanguage::Glsl, ShaderStage::Fragment);
  EXPECT_TRUE(contains(fragment, "layout(location = 9) in vec3 v_interpolant4;"));
  EXPECT_FALSE(contains(fragment, "v_interpolant5"));
  EXPECT_TRUE(contains(fragment, "sampler2D(wg_terrain_height_map, wg_terrain_height_sampler)"));
}

// Twelve wind flows (floats) at distinct points: the count, not the components, binds.
TEST(VertexRatePass, AtMostEightValuesAreInterpolated) {
  std::string nodes = R"({"id": "p", "op": "world_position"})";
  std::string sum = "0";
  for (int i = 0; i < 12; ++i) {
    const std::string n = std::to_string(i);
    nodes += R"(, {"id": "q)" + n + R"(", "op": "add", "inputs": {"a": "p.out", "b": [)" + n + R"(, 0, 0]}})";
    nodes += R"(, {"id": "f)" + n + R"(", "op": "weather_wind_flow", "inputs": {"position": "q)" + n + R"(.out"}})";
    nodes += R"(, {"id": "a)" + n + R"(", "op": "add", "inputs": {"a": )" + (i ? "\"a" + std::to_string(i - 1) + ".out\"" : std::string("0")) +
             R"(, "b": "f)" + n + R"(.out"}})";
    sum = "a" + n + ".out";
  }
  EXPECT_EQ(optimized(graphJson(nodes, R"("roughness": ")" + sum + R"(")")).interpolants.size(), 8u);
}

TEST(VertexRatePass, ASlopeFromAMaterialTextureStaysInTheFragmentStage) {
  // The fragment stage samples a material texture with its mips: the vertex stage cannot.
  IrGraph g = optimized(graphJson(
      R"({"id": "uv", "op": "texcoord"},
         {"id": "t", "op": "sample", "inputs": {"texture": "heights", "uv": "uv.out"}},
         {"id": "s", "op": "weather_terrain_slope", "inputs": {"h0": "t.r", "hShiftU": "t.g", "hShiftV": "t.b"}})",
      R"("baseColor": "s.out")", R"("textures": {"heights": {"generator": "fbm", "seed": 3, "size": 16}}, )"));
  EXPECT_TRUE(g.interpolants.empty());
}

TEST(VertexRatePass, AValueOnlyTheVertexStageNeedsIsNoInterpolant) {
  IrGraph g = optimized(graphJson(
      kSlopeNodes + R"(, {"id": "s", "op": "weather_terrain_slope", "inputs": {"h0": "h0.out", "hShiftU": "hu.out", "hShiftV": "hv.out"}})",
      R"("worldPositionOffset": "s.out")"));
  EXPECT_TRUE(g.interpolants.empty());
}

// Rock's snow reads eq. 3.12-3.13's terrain orientation: its three height-map samples
// move to the vertex stage, which writes the slope for the fragment stage to read.
TEST(VertexRatePass, RocksFragmentStageReadsTheSlopeInsteadOfSamplingTheHeightMap) {
  CompileResult r = compileMaterialFile(std::string(WG_SOURCE_DIR) + "/graphs/rock.json", {});
  ASSERT_TRUE(r.material) << r.diagnostics.items().size();
  const CompiledMaterial& m = *r.material;
  const std::string sample = "sampler2D(wg_terrain_height_map, wg_terrain_height_sampler)";
  std::string glslVertex = source(m, ShaderLanguage::Glsl, ShaderStage::Vertex);
  std::string glslFragment = source(m, ShaderLanguage::Glsl, ShaderStage::Fragment);
  EXPECT_FALSE(contains(glslFragment, sample));
  EXPECT_TRUE(contains(glslFragment, "layout(location = 5) in vec3 v_interpolant0;"));
  EXPECT_TRUE(contains(glslFragment, "_weather_terrain_slope = wg_in.interpolant0;"));
  EXPECT_TRUE(contains(glslVertex, sample));
  EXPECT_TRUE(contains(glslVertex, "layout(location = 5) out vec3 v_interpolant0;"));
  // Zero while the weather branch is skipped, the slope inside it.
  std::size_t zero = glslVertex.find("wg_out.interpolant0 = vec3(0.0);");
  std::size_t branch = glslVertex.find("  if (weather_snowLevel");
  std::size_t write = glslVertex.find("_weather_terrain_slope;");
  ASSERT_NE(zero, std::string::npos);
  EXPECT_LT(zero, branch);
  EXPECT_LT(branch, write);
  EXPECT_NE(write, std::string::npos);
  std::string hlslVertex = source(m, ShaderLanguage::Hlsl, ShaderStage::Vertex);
  std::string hlslFragment = source(m, ShaderLanguage::Hlsl, ShaderStage::Fragment);
  EXPECT_TRUE(contains(hlslVertex, "[[vk::location(5)]] float3 v_interpolant0 : TEXCOORD5;"));
  EXPECT_TRUE(contains(hlslVertex, "wg_out.v_interpolant0 = wg_vertexOutput.interpolant0;"));
  EXPECT_TRUE(contains(hlslFragment, "wg_fragmentInput.interpolant0 = wg_in.v_interpolant0;"));
  EXPECT_TRUE(contains(hlslFragment, "_weather_terrain_slope = wg_in.interpolant0;"));
  for (const auto& stage : m.stages) EXPECT_FALSE(stage.spirv.empty());

  json reflection = json::parse(m.reflectionJson);
  const json* slope = nullptr;
  for (const json& v : reflection["varyings"])
    if (v["name"] == "interpolant0") slope = &v;
  ASSERT_NE(slope, nullptr);
  EXPECT_EQ((*slope)["location"], 5);
  EXPECT_EQ((*slope)["type"], "vec3");
}

// Eq. 3.6's wind flow (4 m cells) runs per vertex: its two noise lookups leave every
// fragment stage whose snow has the wind term, and the vertex stage writes the flow.
TEST(VertexRatePass, TheWindFlowIsComputedPerVertex) {
  for (std::string graph : {"rock", "terrain"}) {
    CompileResult r = compileMaterialFile(std::string(WG_SOURCE_DIR) + "/graphs/" + graph + ".json", {});
    ASSERT_TRUE(r.material) << graph;
    const CompiledMaterial& m = *r.material;
    for (ShaderLanguage language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl}) {
      std::string fragment = source(m, language, ShaderStage::Fragment);
      std::string vertex = source(m, language, ShaderStage::Vertex);
      EXPECT_FALSE(contains(fragment, "wg_wind_flow(")) << graph;  // neither called nor defined
      EXPECT_TRUE(contains(fragment, "wg_wind_from_flow(")) << graph;
      EXPECT_TRUE(contains(fragment, "_weather_wind_flow = ")) << graph;
      EXPECT_TRUE(contains(vertex, "_weather_wind_flow = wg_wind_flow(")) << graph;
    }
    json reflection = json::parse(m.reflectionJson);
    bool flow = false;
    for (const json& v : reflection["varyings"]) flow |= v["type"] == "float" && v["name"].get<std::string>().starts_with("interpolant");
    EXPECT_TRUE(flow) << graph;
    for (const auto& stage : m.stages) EXPECT_FALSE(stage.spirv.empty());
  }
}

// Foliage's snow has no wind term: no flow is computed anywhere.
TEST(VertexRatePass, SnowWithoutTheWindTermComputesNoFlow) {
  CompileResult r = compileMaterialFile(std::string(WG_SOURCE_DIR) + "/graphs/foliage.json", {});
  ASSERT_TRUE(r.material);
  for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
    std::string text = source(*r.material, ShaderLanguage::Glsl, stage);
    EXPECT_FALSE(contains(text, "wg_wind_flow("));
    EXPECT_FALSE(contains(text, "_weather_wind_flow"));
    EXPECT_FALSE(contains(text, "v_interpolant"));
  }
}

TEST(VertexRatePass, WithoutTheWeatherNothingIsInterpolated) {
  CompileResult r = compileMaterialFile(std::string(WG_SOURCE_DIR) + "/graphs/rock.json", {.weatherPreset = "none"});
  ASSERT_TRUE(r.material);
  EXPECT_FALSE(contains(source(*r.material, ShaderLanguage::Glsl, ShaderStage::Fragment), "v_interpolant"));
  EXPECT_FALSE(contains(source(*r.material, ShaderLanguage::Glsl, ShaderStage::Vertex), "v_interpolant"));
}

}  // namespace
}  // namespace wg
