// --target filament against Filament's own limits (Debian's 1.9.25): what weathergen
// writes, matc builds. When matc is installed each material also goes through it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "driver/material_compiler.hpp"
#include "process_support.hpp"

namespace wg {
namespace {

using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
namespace fs = std::filesystem;

bool haveMatc() { return !std::string(WG_MATC).ends_with("NOTFOUND"); }

// matc's verdict on a material: its exit code and output.
testing::CommandResult runMatc(const std::string& mat) {
  TempDir temp("wg-filament-target");
  const fs::path source = temp.path() / "material.mat";
  testing::writeFile(source, mat);
  return runCommand(std::string(WG_MATC) + " -p desktop -a opengl -o " + shellQuote((temp.path() / "m.filamat").string()) +
                    " " + shellQuote(source.string()) + " 2>&1");
}

CompileResult compileForFilament(const nlohmann::json& graph) {
  CompileOptions options;
  options.emitSpirv = false;
  options.emitFilament = true;
  return compileMaterialText("filament.json", graph.dump(), options);
}

// `count` distinct terrain slopes (vec3 values the vertex-rate pass moves to the vertex
// stage), summed into the base colour.
nlohmann::json terrainSlopes(int count) {
  nlohmann::json nodes = nlohmann::json::array();
  nodes.push_back({{"id", "p"}, {"op", "world_position"}});
  nodes.push_back({{"id", "uv"}, {"op", "terrain_coord"}, {"inputs", {{"position", "p.out"}}}});
  nodes.push_back({{"id", "h"}, {"op", "terrain_height"}, {"inputs", {{"uv", "uv.out"}}}});
  std::string sum;
  for (int i = 0; i < count; ++i) {
    const std::string slope = "s" + std::to_string(i);
    nodes.push_back({{"id", slope},
                     {"op", "weather_terrain_slope"},
                     {"inputs", {{"h0", "h.out"}, {"hShiftU", 0.1 * i}, {"hShiftV", 0.2}, {"intensity", 1.0 + i}}}});
    if (sum.empty()) {
      sum = slope + ".out";
      continue;
    }
    nodes.push_back({{"id", "sum" + std::to_string(i)}, {"op", "add"}, {"inputs", {{"a", sum}, {"b", slope + ".out"}}}});
    sum = "sum" + std::to_string(i) + ".out";
  }
  return {{"name", "slopes"}, {"nodes", nodes}, {"output", {{"baseColor", sum}}}};
}

// Filament hands the vertex stage's own values to the fragment stage in four vec4
// custom variables; nine vec3 slopes once made the writer give up (WG9900).
TEST(FilamentTarget, PerVertexValuesFitFilamentsFourVariables) {
  for (int count : {4, 5, 6, 9}) {
    SCOPED_TRACE(count);
    CompileResult r;
    ASSERT_NO_THROW(r = compileForFilament(terrainSlopes(count)));
    for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
    ASSERT_TRUE(r.material);
    const std::string& mat = r.material->filamentMaterial;
    std::smatch variables;
    ASSERT_TRUE(std::regex_search(mat, variables, std::regex(R"(variables : \[([^\]]*)\])")));
    EXPECT_LE(std::count(variables[1].first, variables[1].second, ',') + 1, 4) << variables[0];
    if (!haveMatc()) continue;
    testing::CommandResult matc = runMatc(mat);
    EXPECT_EQ(matc.exitCode, 0) << matc.output;
  }
}

// `textures` procedural textures and `parameters` float parameters, all read (summed).
nlohmann::json texturesAndParameters(int textures, int parameters) {
  nlohmann::json graph = {{"name", "many"}, {"nodes", nlohmann::json::array()}};
  std::string sum;
  graph["nodes"].push_back({{"id", "uv"}, {"op", "texcoord"}});
  auto add = [&](const std::string& id, const std::string& value) {
    if (sum.empty()) return void(sum = value);
    graph["nodes"].push_back({{"id", id + "+"}, {"op", "add"}, {"inputs", {{"a", sum}, {"b", value}}}});
    sum = id + "+.out";
  };
  for (int i = 0; i < textures; ++i) {
    const std::string name = "t" + std::to_string(i);
    graph["textures"][name] = {{"generator", "fbm"}, {"seed", i}, {"size", 16}};
    graph["nodes"].push_back({{"id", name}, {"op", "sample"}, {"inputs", {{"texture", name}, {"uv", "uv.out"}}}});
    add(name, name + ".r");
  }
  for (int i = 0; i < parameters; ++i) {
    const std::string name = "p" + std::to_string(i);
    graph["parameters"][name] = {{"type", "float"}, {"default", 0.5}};
    graph["nodes"].push_back({{"id", name}, {"op", "parameter"}, {"param", name}});
    add(name, name + ".out");
  }
  graph["output"] = {{"roughness", sum}};
  return graph;
}

std::string pointerOfOnlyError(const CompileResult& r, const std::string& code) {
  if (r.diagnostics.items().size() != 1) return "not one diagnostic";
  const Diagnostic& d = r.diagnostics.items().front();
  return std::string(d.info().id) == code ? d.location.pointer : formatDiagnosticText(d);
}

// Filament 1.9 leaves a material 8 of a shader's 16 samplers, and matc takes 48
// parameters, the weather block's 16 fields among them. At the limits matc builds the
// material without a word; one past them the graph gets WG6001, where matc would have
// crashed (parameters) or warned and left samplers unbound.
TEST(FilamentTarget, AMaterialPastFilamentsLimitsIsADiagnostic) {
  EXPECT_EQ(pointerOfOnlyError(compileForFilament(texturesAndParameters(9, 0)), "WG6001"), "/textures");
  EXPECT_EQ(pointerOfOnlyError(compileForFilament(texturesAndParameters(0, 33)), "WG6001"), "/parameters");
  EXPECT_EQ(pointerOfOnlyError(compileForFilament(texturesAndParameters(8, 25)), "WG6001"), "/parameters");
  for (auto [textures, parameters] : {std::pair{8, 24}, std::pair{0, 32}}) {
    SCOPED_TRACE(::testing::Message() << textures << " textures, " << parameters << " parameters");
    CompileResult r = compileForFilament(texturesAndParameters(textures, parameters));
    for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
    ASSERT_TRUE(r.material);
    if (!haveMatc()) continue;
    testing::CommandResult matc = runMatc(r.material->filamentMaterial);
    EXPECT_EQ(matc.exitCode, 0) << matc.output;
    EXPECT_EQ(matc.output.find("Exceeded"), std::string::npos) << matc.output;
  }
  // Other targets hold it.
  CompileOptions surface;
  surface.emitSurface = true;
  EXPECT_TRUE(compileMaterialText("many.json", texturesAndParameters(9, 33).dump(), surface).material);
}

}  // namespace
}  // namespace wg
