// The stage writer takes the weather guard and the debug views from the IR: a backend
// knows syntax, not which uniforms gate the weather or what each view shows.
#include <gtest/gtest.h>

#include <set>

#include "backends/op_template.hpp"
#include "backends/reference_host.hpp"
#include "backends/shader_syntax.hpp"
#include "backends/stage_writer.hpp"
#include "compiler/debug_views.hpp"
#include "compiler/identifier.hpp"
#include "compiler/pass_pipeline.hpp"
#include "ir_fixture.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/op_template_check.hpp"

namespace wg {
namespace {

IrGraph weatheredRock() {
  IrGraph ir = testing::irBeforePasses(testing::graphJson(
      R"({"id": "c", "op": "multiply", "inputs": {"a": [0.4, 0.4, 0.4], "b": 1.0}})", R"("baseColor": "c.out")",
      R"("weather": {"preset": "rock"}, )"));
  EXPECT_FALSE(runPassPipeline(ir).has_value());
  return ir;
}

std::string fragmentText(const IrGraph& ir, ShaderLanguage language = ShaderLanguage::Glsl) {
  MaterialInterface mi = buildMaterialInterface(ir);
  return writeReferenceHostStage(ir, buildEmbeddedSurfaceInterface(mi), language, ShaderStage::Fragment, "0",
                                 nameNodes(ir));
}

TEST(StageWriter, WeatherGuardComesFromTheIr) {
  IrGraph ir = weatheredRock();
  ASSERT_TRUE(ir.weatherGuarded());
  EXPECT_NE(fragmentText(ir).find("if (weather_snowLevel + weather_wetnessLevel + weather_mossLevel + "
                                  "weather_frostLevel + weather_puddleLevel > 0.0) {"),
            std::string::npos);
  ir.weatherGuard = {"weather_snowLevel"};
  std::string text = fragmentText(ir);
  EXPECT_NE(text.find("if (weather_snowLevel > 0.0) {"), std::string::npos);
  EXPECT_EQ(text.find("weather_wetnessLevel +"), std::string::npos);
}

// Node names are built without an identifier scope; this is what makes that safe.
TEST(StageWriter, NodeNamesAreCleanAndMeetNoGlobal) {
  for (const OpDef* op : allOps()) {
    std::string name = "n99999_" + std::string(op->name);
    EXPECT_EQ(IdentifierScope::sanitize(name), name);
    EXPECT_LE(name.size(), IdentifierScope::kMaxLength);
  }
  IrGraph ir = weatheredRock();
  MaterialInterface mi = buildMaterialInterface(ir);
  std::set<std::string> globals = {mi.frame->identifier, mi.material.identifier};
  for (const UniformBlock* block : {mi.frame, static_cast<const UniformBlock*>(&mi.material)})
    for (const auto& member : block->members) globals.insert(member.identifier);
  for (const auto* list : {&mi.textures, &mi.weatherMaps})
    for (const auto& t : *list) globals.insert({t.textureIdentifier, t.samplerIdentifier});
  for (const auto* list : {&mi.vertexInputs, &mi.varyings})
    for (const auto& v : *list) globals.insert(v.identifier);
  ASSERT_GT(globals.size(), 40u);
  for (const std::string& name : nameNodes(ir)) {
    EXPECT_FALSE(globals.contains(name)) << name;
    EXPECT_FALSE(name.starts_with("wg_")) << name;  // the frame locals' prefix
  }
}

// The registry's template check and the splitter list the same symbols.
TEST(StageWriter, EverySymbolTheTemplateCheckAllowsIsSplit) {
  const OpDef* op = findOp("sample");
  ASSERT_NE(op, nullptr);
  for (std::string_view symbol : templateSymbols()) {
    OpTemplate pieces;
    EXPECT_NO_THROW(pieces = splitOpTemplate(*op, "{@" + std::string(symbol) + "}")) << symbol;
    ASSERT_EQ(pieces.pieces.size(), 1u) << symbol;
    EXPECT_TRUE(pieces.pieces[0].kind != TemplatePiece::Kind::Text || !pieces.pieces[0].text.empty()) << symbol;
  }
}

TEST(StageWriter, NoWeatherMeansNoGuard) {
  IrGraph ir = testing::irBeforePasses(
      testing::graphJson(R"({"id": "c", "op": "multiply", "inputs": {"a": [0.4, 0.4, 0.4], "b": 1.0}})", R"("baseColor": "c.out")"));
  ASSERT_FALSE(runPassPipeline(ir).has_value());
  EXPECT_FALSE(ir.weatherGuarded());
  EXPECT_EQ(fragmentText(ir).find("> 0.0) {"), std::string::npos);
}

TEST(StageWriter, DebugViewsComeFromTheIr) {
  IrGraph ir = weatheredRock();
  ASSERT_EQ(ir.debugViews.size(), kDebugViews.size() - 1);  // every view but "lit"
  std::string text = fragmentText(ir);
  EXPECT_NE(text.find("case 4u: wg_color = vec3(wg_surface.snow); break;"), std::string::npos);
  EXPECT_NE(text.find("case 14u: wg_color = wg_worldTangent.xyz; wg_alpha = wg_worldTangent.w; break;"),
            std::string::npos);

  ir.debugViews[3].source = DebugSource::WorldPosition;  // view 4, "snow"
  text = fragmentText(ir);
  EXPECT_NE(text.find("case 4u: wg_color = wg_worldPosition; break;"), std::string::npos);
  ir.debugViews.clear();
  EXPECT_EQ(fragmentText(ir).find("switch (frame_debugView)"), std::string::npos);
}

TEST(StageWriter, DebugViewsSplatScalarSlotsInEachLanguage) {
  IrGraph ir = weatheredRock();
  EXPECT_NE(fragmentText(ir).find("case 2u: wg_color = vec3(wg_surface.roughness); break;"), std::string::npos);
  EXPECT_NE(
      fragmentText(ir, ShaderLanguage::Hlsl).find("case 2u: wg_color = ((float3)(wg_surface.roughness)); break;"),
      std::string::npos);
}

}  // namespace
}  // namespace wg
