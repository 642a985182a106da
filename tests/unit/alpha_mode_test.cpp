// Top-level "alphaMode" and "doubleSided": loaded, reflected, turned into shader code
// (discard, output alpha) and refused when malformed. Absent, both keep today's rules.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "driver/material_compiler.hpp"
#include "ir_fixture.hpp"

namespace wg {
namespace {

using json = nlohmann::json;

// A graph whose opacity comes from a parameter, with `extra` top-level fields.
std::string graph(const std::string& extra, bool withOpacity = true) {
  return R"({"name": "t", )" + extra + R"( "parameters": {"alpha": {"type": "float", "default": 0.4}},
    "nodes": [{"id": "a", "op": "parameter", "param": "alpha"}],
    "output": {"baseColor": [0.2, 0.4, 0.6])" + (withOpacity ? R"(, "opacity": "a.out")" : "") + "}}";
}

CompiledMaterial compile(const std::string& text) {
  CompileOptions options;
  options.emitSpirv = true;  // glslang must accept both languages
  CompileResult r = compileMaterialText("t.json", text, options);
  for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  if (!r.material) throw std::runtime_error("graph did not compile");
  return std::move(*r.material);
}

json reflection(const CompiledMaterial& m) { return json::parse(m.reflectionJson); }

const std::string& fragment(const CompiledMaterial& m, ShaderLanguage language) {
  return m.stage(language, ShaderStage::Fragment).source;
}

bool discards(const CompiledMaterial& m, ShaderLanguage language) {
  return fragment(m, language).find("discard") != std::string::npos;
}
bool writesOpacityAsAlpha(const CompiledMaterial& m, ShaderLanguage language) {
  return fragment(m, language).find("wg_alpha = frame_debugView == 0u ? wg_surface.opacity : 1.0;") != std::string::npos;
}

TEST(AlphaMode, AbsentFollowsTheOpacityRule) {
  json opaque = reflection(compile(graph("", false)));
  EXPECT_EQ(opaque["alphaMode"], "opaque");
  EXPECT_EQ(opaque["alphaTested"], false);
  json tested = reflection(compile(graph("")));
  EXPECT_EQ(tested["alphaMode"], "mask");
  EXPECT_EQ(tested["alphaTested"], true);
  EXPECT_EQ(tested["doubleSided"], false);
}

TEST(AlphaMode, MaskDiscardsBelowTheCutoff) {
  for (bool withOpacity : {true, false}) {  // without opacity the test reads opacity 1
    CompiledMaterial m = compile(graph(R"("alphaMode": "mask", "alphaCutoff": 0.3,)", withOpacity));
    EXPECT_EQ(reflection(m)["alphaMode"], "mask");
    EXPECT_EQ(reflection(m)["alphaTested"], true);
    for (auto language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl}) {
      EXPECT_NE(fragment(m, language).find("if (wg_surface.opacity < 0.3) discard;"), std::string::npos);
      EXPECT_FALSE(writesOpacityAsAlpha(m, language));
    }
  }
}

TEST(AlphaMode, BlendWritesOpacityAsTheLitAlphaAndNeverDiscards) {
  CompiledMaterial m = compile(graph(R"("alphaMode": "blend",)"));
  json r = reflection(m);
  EXPECT_EQ(r["alphaMode"], "blend");
  EXPECT_EQ(r["alphaTested"], false);
  for (auto language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl}) {
    EXPECT_FALSE(discards(m, language));
    EXPECT_TRUE(writesOpacityAsAlpha(m, language));
  }
}

TEST(AlphaMode, OpaqueIgnoresOpacity) {
  CompiledMaterial m = compile(graph(R"("alphaMode": "opaque",)"));
  EXPECT_EQ(reflection(m)["alphaMode"], "opaque");
  EXPECT_EQ(reflection(m)["alphaTested"], false);
  for (auto language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl}) {
    EXPECT_FALSE(discards(m, language));
    EXPECT_FALSE(writesOpacityAsAlpha(m, language));
  }
}

TEST(AlphaMode, FoliageThinningKeepsADeclaredBlend) {
  // The foliage preset alpha-tests its cards unless the graph declared another mode.
  EXPECT_EQ(reflection(compile(graph(R"("weather": "foliage",)", false)))["alphaMode"], "mask");
  EXPECT_EQ(reflection(compile(graph(R"("weather": "foliage", "alphaMode": "blend",)")))["alphaMode"], "blend");
}

TEST(AlphaMode, HashChangesOnlyWithWhatTheShadersDo) {
  const std::string implicitOpaque = compile(graph("", false)).contentHash;
  EXPECT_EQ(compile(graph(R"("alphaMode": "opaque",)", false)).contentHash, implicitOpaque);
  EXPECT_EQ(compile(graph(R"("doubleSided": false,)", false)).contentHash, implicitOpaque);
  EXPECT_NE(compile(graph(R"("alphaMode": "blend",)", false)).contentHash, implicitOpaque);
  EXPECT_NE(compile(graph(R"("alphaMode": "mask",)", false)).contentHash, implicitOpaque);
  EXPECT_NE(compile(graph(R"("doubleSided": true,)", false)).contentHash, implicitOpaque);
}

TEST(DoubleSided, IsReflected) {
  EXPECT_EQ(reflection(compile(graph(R"("doubleSided": true,)")))["doubleSided"], true);
  EXPECT_EQ(reflection(compile(graph(R"("doubleSided": false,)")))["doubleSided"], false);
}

TEST(DoubleSided, BothBackendsFlipTheNormalOfBackFaces) {
  CompiledMaterial m = compile(graph(R"("doubleSided": true,)"));
  EXPECT_NE(fragment(m, ShaderLanguage::Glsl).find("(gl_FrontFacing ? 1.0 : -1.0)"), std::string::npos);
  EXPECT_NE(fragment(m, ShaderLanguage::Hlsl).find("bool wg_frontFacing : SV_IsFrontFace"), std::string::npos);
  EXPECT_NE(fragment(m, ShaderLanguage::Hlsl).find("(wg_frontFacing ? 1.0 : -1.0)"), std::string::npos);
}

std::vector<std::pair<DiagCode, std::string>> diagnosticsOf(const std::string& text) {
  DiagnosticList d;
  (void)buildOptimizedIr("t.json", text, d);
  std::vector<std::pair<DiagCode, std::string>> out;
  for (const auto& item : d.items()) out.emplace_back(item.code, item.location.pointer);
  return out;
}

TEST(AlphaMode, MalformedValuesAreRefused) {
  using Diags = std::vector<std::pair<DiagCode, std::string>>;
  EXPECT_EQ(diagnosticsOf(graph(R"("alphaMode": "translucent",)")), (Diags{{DiagCode::UnknownAlphaMode, "/alphaMode"}}));
  EXPECT_EQ(diagnosticsOf(graph(R"("alphaMode": "BLEND",)")), (Diags{{DiagCode::UnknownAlphaMode, "/alphaMode"}}));
  EXPECT_EQ(diagnosticsOf(graph(R"("alphaMode": 2,)")), (Diags{{DiagCode::WrongJsonKind, "/alphaMode"}}));
  EXPECT_EQ(diagnosticsOf(graph(R"("doubleSided": "yes",)")), (Diags{{DiagCode::WrongJsonKind, "/doubleSided"}}));
  EXPECT_EQ(diagnosticsOf(graph(R"("doubleSided": 1,)")), (Diags{{DiagCode::WrongJsonKind, "/doubleSided"}}));
}

TEST(AlphaMode, MisspeltFieldIsUnknown) {
  EXPECT_EQ(diagnosticsOf(R"({"name": "t", "nodes": [], "output": {}, "alphamode": "blend"})"),
            (std::vector<std::pair<DiagCode, std::string>>{{DiagCode::UnknownField, "/alphamode"}}));
}

}  // namespace
}  // namespace wg
