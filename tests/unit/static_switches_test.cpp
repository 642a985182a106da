// Static switches: choosing cases, switched weather effects, variant enumeration and
// every error a switch can cause (checked by code).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "driver/material_compiler.hpp"
#include "compiler/static_switches.hpp"
#include "tests/unit/ir_fixture.hpp"

namespace wg {
namespace {

using testing::graphJson;

constexpr const char* kSwitches = R"("switches": {
    "quality": {"values": ["low", "medium", "high"], "default": "high"},
    "moss": {"type": "bool", "default": false}}, )";

// Roughness is 0.25, 0.5 or a parameter's 0.75, by quality.
const std::string kRoughnessGraph = graphJson(
    R"({"id": "r", "op": "parameter", "param": "rough"},
       {"id": "pick", "op": "switch", "switch": "quality", "cases": {"low": 0.25, "medium": "half.out", "high": "r.out"}},
       {"id": "half", "op": "multiply", "inputs": {"a": 0.5, "b": 1.0}})",
    R"("roughness": "pick.out")",
    std::string(kSwitches) + R"("parameters": {"rough": {"type": "float", "default": 0.75}}, )");

std::optional<IrGraph> build(const std::string& json, const SwitchValues& switches, DiagnosticList& d) {
  CompileOptions options;
  options.switches = switches;
  return buildOptimizedIr("inline.json", json, d, options);
}

IrGraph buildOk(const std::string& json, const SwitchValues& switches = {}) {
  DiagnosticList d;
  auto ir = build(json, switches, d);
  for (const auto& diag : d.items()) ADD_FAILURE() << formatDiagnosticText(diag);
  return ir ? std::move(*ir) : IrGraph{};
}

// The codes a graph with these switch values reports.
std::vector<std::string> codesOf(const std::string& json, const SwitchValues& switches = {}) {
  DiagnosticList d;
  build(json, switches, d);
  std::vector<std::string> codes;
  for (const auto& diag : d.items()) codes.emplace_back(diag.info().id);
  return codes;
}

TEST(StaticSwitches, EachValueChoosesItsCase) {
  IrGraph low = buildOk(kRoughnessGraph, {{"quality", "low"}});
  ASSERT_EQ(low.output(PbrField::Roughness).kind, Operand::Kind::Constant);
  EXPECT_FLOAT_EQ(low.output(PbrField::Roughness).constant.x(), 0.25f);
  IrGraph medium = buildOk(kRoughnessGraph, {{"quality", "medium"}});
  ASSERT_EQ(medium.output(PbrField::Roughness).kind, Operand::Kind::Constant);  // folded 0.5 * 1.0
  EXPECT_FLOAT_EQ(medium.output(PbrField::Roughness).constant.x(), 0.5f);
  IrGraph high = buildOk(kRoughnessGraph);  // the default
  ASSERT_EQ(high.output(PbrField::Roughness).kind, Operand::Kind::Node);
  EXPECT_EQ(high.nodes[high.output(PbrField::Roughness).node].op->name, "parameter");
}

TEST(StaticSwitches, UnchosenCasesLeaveNothingBehind) {
  IrGraph low = buildOk(kRoughnessGraph, {{"quality", "low"}});
  EXPECT_TRUE(low.nodes.empty());
}

TEST(StaticSwitches, DefaultVariantIsTheGraphWrittenWithoutSwitches) {
  const std::string plain = graphJson(R"({"id": "r", "op": "parameter", "param": "rough"})", R"("roughness": "r.out")",
                                      R"("parameters": {"rough": {"type": "float", "default": 0.75}}, )");
  CompileOptions options;
  options.emitSpirv = false;
  auto a = compileMaterialText("a.json", kRoughnessGraph, options);
  auto b = compileMaterialText("a.json", plain, options);
  ASSERT_TRUE(a.material && b.material);
  EXPECT_EQ(a.material->contentHash, b.material->contentHash);
  EXPECT_EQ(a.material->stages[3].source, b.material->stages[3].source);
}

TEST(StaticSwitches, SwitchesOfSwitchesResolve) {
  std::string json = graphJson(
      R"({"id": "inner", "op": "switch", "switch": "moss", "cases": {"off": 0.1, "on": 0.2}},
         {"id": "outer", "op": "switch", "switch": "quality", "cases": {"low": 0.9, "medium": "inner.out", "high": "inner.out"}})",
      R"("roughness": "outer.out")", kSwitches);
  EXPECT_FLOAT_EQ(buildOk(json, {{"moss", "on"}}).output(PbrField::Roughness).constant.x(), 0.2f);
  EXPECT_FLOAT_EQ(buildOk(json, {{"quality", "low"}, {"moss", "on"}}).output(PbrField::Roughness).constant.x(), 0.9f);
}

std::string weatherGraph(const std::string& effects) {
  return graphJson("", R"("baseColor": [0.5, 0.5, 0.5])",
                   std::string(kSwitches) + R"("weather": {"preset": "rock", "effects": )" + effects + "}, ");
}

TEST(StaticSwitches, BoolSwitchTurnsAWeatherEffectOnAndOff) {
  std::string json = weatherGraph(R"({"moss": {"switch": "moss"}})");
  EXPECT_FALSE(buildOk(json).weather.effects.moss);  // default off
  EXPECT_TRUE(buildOk(json, {{"moss", "on"}}).weather.effects.moss);
}

TEST(StaticSwitches, WhenListsTheValuesThatEnableAnEffect) {
  std::string json = weatherGraph(R"({"displacement": {"switch": "quality", "when": ["medium", "high"]}})");
  EXPECT_FALSE(buildOk(json, {{"quality", "low"}}).weather.effects.displacement);
  EXPECT_TRUE(buildOk(json, {{"quality", "medium"}}).weather.effects.displacement);
  EXPECT_TRUE(buildOk(json).weather.effects.displacement);
}

TEST(StaticSwitchErrors, ReportedByCode) {
  const std::string two = R"("switches": {"q": {"values": ["a", "b"], "default": "a"}}, )";
  auto node = [&](const std::string& n, const std::string& out = R"("roughness": "s.out")") {
    return graphJson(n, out, two);
  };
  // WG2015: a node or effect names an undeclared switch; a variant names one.
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "switch", "switch": "nope", "cases": {"a": 0.1, "b": 0.2}})")),
            std::vector<std::string>{"WG2015"});
  EXPECT_EQ(codesOf(weatherGraph(R"({"moss": {"switch": "nope"}})")), std::vector<std::string>{"WG2015"});
  EXPECT_EQ(codesOf(kRoughnessGraph, {{"nope", "x"}}), std::vector<std::string>{"WG2015"});
  // WG2018: missing case, extra case. WG2017: a value the switch does not have.
  // WG4003: the bool form on a non-bool switch. WG4005: an effect object without "switch".
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "switch", "switch": "q", "cases": {"a": 0.1}})")),
            std::vector<std::string>{"WG2018"});
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "switch", "switch": "q", "cases": {"a": 0.1, "b": 0.2, "c": 0.3}})")),
            std::vector<std::string>{"WG2018"});
  EXPECT_EQ(codesOf(kRoughnessGraph, {{"quality", "ultra"}}), std::vector<std::string>{"WG2017"});
  EXPECT_EQ(codesOf(weatherGraph(R"({"moss": {"switch": "quality"}})")), std::vector<std::string>{"WG4003"});
  EXPECT_EQ(codesOf(weatherGraph(R"({"moss": {"when": ["high"]}})")), std::vector<std::string>{"WG4005"});
  EXPECT_EQ(codesOf(weatherGraph(R"({"moss": {"switch": "quality", "when": ["ultra"]}})")), std::vector<std::string>{"WG2017"});
  // Declarations, each with its own code: bad default, duplicate value, one value, not a
  // plain word, neither kind, both kinds, a type other than bool.
  const std::pair<const char*, const char*> declarations[] = {
      {R"({"values": ["a", "b"], "default": "c"})", "WG2017"},
      {R"({"values": ["a", "a"], "default": "a"})", "WG2025"},
      {R"({"values": ["a"], "default": "a"})", "WG2024"},
      {R"({"values": ["a b", "c"], "default": "c"})", "WG2021"},
      {R"({"default": "a"})", "WG2023"},
      {R"({"type": "bool", "values": ["a", "b"], "default": "a"})", "WG2023"},
      {R"({"type": "enum", "values": ["a", "b"], "default": "a"})", "WG2016"},
  };
  for (const auto& [decl, code] : declarations)
    EXPECT_EQ(codesOf(graphJson("", "", std::string(R"("switches": {"q": )") + decl + "}, ")),
              std::vector<std::string>{code})
        << decl;
  // Links to a switch name its one output; a switch cannot choose itself; ids stay unique.
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "switch", "switch": "q", "cases": {"a": 0.1, "b": 0.2}})",
                         R"("roughness": "s.rgb")")),
            std::vector<std::string>{"WG2004"});
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "switch", "switch": "q", "cases": {"a": "s.out", "b": 0.2}})")),
            std::vector<std::string>{"WG2009"});
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "switch", "switch": "q", "cases": {"a": 0.1, "b": 0.2}},
                             {"id": "s", "op": "uv"})")),
            std::vector<std::string>{"WG2002"});
  // Fields belong to their op.
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "switch", "switch": "q", "inputs": {}, "cases": {"a": 0.1, "b": 0.2}})")),
            std::vector<std::string>{"WG1005"});
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "texcoord", "switch": "q"})", "")), std::vector<std::string>{"WG1005"});
  // A case of the wrong type is typed where it is written.
  EXPECT_EQ(codesOf(node(R"({"id": "s", "op": "switch", "switch": "q", "cases": {"a": 0.1, "b": true}})"), {{"q", "b"}}),
            std::vector<std::string>{"WG2008"});
}

TEST(VariantSelection, ParsesAllAndLists) {
  std::string error;
  EXPECT_TRUE(parseVariantSelection("all", error)->all);
  auto s = parseVariantSelection("quality=low|high,moss", error);
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->chosen.at("quality"), (std::vector<std::string>{"low", "high"}));
  EXPECT_TRUE(s->chosen.at("moss").empty());
  EXPECT_FALSE(parseVariantSelection("quality=,moss", error));
  EXPECT_FALSE(parseVariantSelection(",", error));
}

std::vector<SwitchDecl> declared() {
  return {{"moss", {"off", "on"}, "off", ""}, {"quality", {"low", "medium", "high"}, "high", ""}};
}

std::vector<std::string> namesOf(const std::vector<SwitchValues>& variants) {
  std::vector<std::string> names;
  for (const auto& v : variants) names.push_back(variantName(v));
  return names;
}

TEST(VariantSelection, EnumeratesInAStableOrder) {
  std::string error;
  auto all = enumerateVariants(declared(), *parseVariantSelection("all", error), error);
  EXPECT_EQ(namesOf(all), (std::vector<std::string>{"moss=off,quality=low", "moss=off,quality=medium", "moss=off,quality=high",
                                                    "moss=on,quality=low", "moss=on,quality=medium", "moss=on,quality=high"}));
  // Listed values come in declared order; unnamed switches keep their default.
  auto some = enumerateVariants(declared(), *parseVariantSelection("quality=high|low", error), error);
  EXPECT_EQ(namesOf(some), (std::vector<std::string>{"moss=off,quality=low", "moss=off,quality=high"}));
  EXPECT_TRUE(error.empty());
  enumerateVariants(declared(), *parseVariantSelection("quality=ultra", error), error);
  EXPECT_NE(error.find("ultra"), std::string::npos);
}

TEST(VariantSelection, RefusesMoreThanTheVariantLimit) {
  std::vector<SwitchDecl> many;
  for (int i = 0; i < 11; ++i) many.push_back({"s" + std::to_string(i), {"off", "on"}, "off", ""});  // 2^11 > 1024
  std::string error;
  EXPECT_TRUE(enumerateVariants(many, *parseVariantSelection("all", error), error).empty());
  EXPECT_NE(error.find("1024"), std::string::npos);
  many.pop_back();  // 2^10 = 1024 is allowed
  error.clear();
  EXPECT_EQ(enumerateVariants(many, *parseVariantSelection("all", error), error).size(), kMaxVariants);
}

}  // namespace
}  // namespace wg
