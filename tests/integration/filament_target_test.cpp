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

}  // namespace
}  // namespace wg
