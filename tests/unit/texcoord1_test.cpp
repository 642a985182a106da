// Op texcoord1, the mesh's second texture coordinate set: a vertex input and varying
// only in materials that read it, both backends, and the CPU evaluator.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "compiler/cpu_evaluator.hpp"
#include "driver/material_compiler.hpp"

namespace wg {
namespace {

using json = nlohmann::json;

// baseColor = (u1, v1, u0) and a vertex offset of v1 along y, so both stages read it.
const std::string kGraph = R"({"name": "t",
  "nodes": [{"id": "uv1", "op": "texcoord1"}, {"id": "uv0", "op": "texcoord"},
            {"id": "a", "op": "split", "inputs": {"in": "uv1.out"}}, {"id": "b", "op": "split", "inputs": {"in": "uv0.out"}},
            {"id": "c", "op": "combine3", "inputs": {"x": "a.x", "y": "a.y", "z": "b.x"}},
            {"id": "lift", "op": "combine3", "inputs": {"y": "a.y"}}],
  "output": {"baseColor": "c.out", "worldPositionOffset": "lift.out"}})";

CompiledMaterial compile(const std::string& text) {
  CompileResult r = compileMaterialText("t.json", text, {});
  for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  if (!r.material) throw std::runtime_error("graph did not compile");
  return std::move(*r.material);
}

json namesAndLocations(const json& list) {
  json out = json::object();
  for (const auto& v : list) out[v["name"].get<std::string>()] = v["location"];
  return out;
}

TEST(Texcoord1, IsAVertexInputAndVaryingOnlyWhenRead) {
  json r = json::parse(compile(kGraph).reflectionJson);
  EXPECT_EQ(namesAndLocations(r["vertexInputs"]),
            (json{{"position", 0}, {"normal", 1}, {"tangent", 2}, {"texcoord", 3}, {"color", 4}, {"texcoord1", 5}}));
  EXPECT_EQ(r["vertexInputs"][5]["type"], "vec2");
  EXPECT_EQ(namesAndLocations(r["varyings"])["texcoord1"], 5);
  // A node nobody uses is removed, and with it the input.
  json unused = json::parse(compile(R"({"name": "u", "nodes": [{"id": "uv1", "op": "texcoord1"}], "output": {}})").reflectionJson);
  EXPECT_EQ(unused["vertexInputs"].size(), 5u);
  EXPECT_EQ(unused["varyings"].size(), 5u);
}

TEST(Texcoord1, BothBackendsPassItThroughTheStages) {
  CompiledMaterial m = compile(kGraph);
  auto source = [&](ShaderLanguage l, ShaderStage s) { return m.stage(l, s).source; };
  EXPECT_NE(source(ShaderLanguage::Glsl, ShaderStage::Vertex).find("layout(location = 5) in vec2 in_texcoord1;"), std::string::npos);
  EXPECT_NE(source(ShaderLanguage::Glsl, ShaderStage::Vertex).find("wg_vertexInput.texcoord1 = in_texcoord1;"), std::string::npos);
  EXPECT_NE(source(ShaderLanguage::Glsl, ShaderStage::Vertex).find("wg_out.texcoord1 = wg_texcoord1;"), std::string::npos);
  EXPECT_NE(source(ShaderLanguage::Glsl, ShaderStage::Vertex).find("v_texcoord1 = wg_vertexOutput.texcoord1;"), std::string::npos);
  EXPECT_NE(source(ShaderLanguage::Glsl, ShaderStage::Fragment).find("wg_fragmentInput.texcoord1 = v_texcoord1;"), std::string::npos);
  EXPECT_NE(source(ShaderLanguage::Glsl, ShaderStage::Fragment).find("vec2 wg_texcoord1 = wg_in.texcoord1;"), std::string::npos);
  EXPECT_NE(source(ShaderLanguage::Hlsl, ShaderStage::Vertex).find("[[vk::location(5)]] float2 in_texcoord1 : TEXCOORD5;"),
            std::string::npos);
  EXPECT_NE(source(ShaderLanguage::Hlsl, ShaderStage::Fragment).find("wg_fragmentInput.texcoord1 = wg_in.v_texcoord1;"), std::string::npos);
  for (const auto& stage : m.stages) EXPECT_FALSE(stage.spirv.empty());
}

TEST(Texcoord1, CpuEvaluatorReadsTheSecondSet) {
  DiagnosticList diagnostics;
  auto ir = buildOptimizedIr("t.json", kGraph, diagnostics);
  ASSERT_TRUE(ir.has_value());
  EvalInputs in;
  in.surface.texcoord = {0.25f, 0.5f};
  in.surface.texcoord1 = {0.75f, 0.125f};
  EvalResult r = CpuEvaluator(std::move(*ir)).evaluate(in);
  EXPECT_EQ(r.output(PbrField::BaseColor), Value::vec3(0.75f, 0.125f, 0.25f));
  EXPECT_EQ(r.output(PbrField::WorldPositionOffset), Value::vec3(0.f, 0.125f, 0.f));
}

}  // namespace
}  // namespace wg
