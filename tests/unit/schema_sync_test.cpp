// graphs/schema/material-graph.schema.json must describe what the compiler accepts:
// the same ops, output fields and texture generators. Editing one without the other
// fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "compiler/pbr_output.hpp"
#include "compiler/static_switches.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/texture_generators.hpp"

namespace wg {
namespace {

nlohmann::json loadSchema() {
  std::ifstream in(std::string(WG_SOURCE_DIR) + "/graphs/schema/material-graph.schema.json");
  return nlohmann::json::parse(in);
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(SchemaSync, OpEnumMatchesTheOpRegistry) {
  auto schema = loadSchema();
  auto ops = schema["$defs"]["node"]["properties"]["op"]["enum"].get<std::vector<std::string>>();
  std::vector<std::string> registry;
  for (auto name : opNames()) registry.emplace_back(name);
  registry.emplace_back(kSwitchOp);  // resolved before typing, so not a registry op
  EXPECT_EQ(sorted(ops), sorted(registry));
}

TEST(SchemaSync, OutputPropertiesMatchThePbrFields) {
  auto schema = loadSchema();
  std::vector<std::string> properties;
  for (const auto& [key, value] : schema["properties"]["output"]["properties"].items()) properties.push_back(key);
  std::vector<std::string> fields;
  for (const auto& f : pbrFields()) fields.emplace_back(f.name);
  EXPECT_EQ(sorted(properties), sorted(fields));
}

TEST(SchemaSync, GeneratorEnumMatchesTheBuiltInGenerators) {
  auto schema = loadSchema();
  auto generators = schema["$defs"]["generatorTexture"]["properties"]["generator"]["enum"].get<std::vector<std::string>>();
  std::vector<std::string> builtIn;
  for (const auto& g : textureGenerators()) builtIn.emplace_back(g.name);
  EXPECT_EQ(sorted(generators), sorted(builtIn));
}

}  // namespace
}  // namespace wg
