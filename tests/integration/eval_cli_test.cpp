// weathergen eval: the JSON it prints, its help, and how it rejects bad usage (exit 2,
// WG9001) and bad graphs (exit 1, the compiler's diagnostics).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "process_support.hpp"

namespace wg {
namespace {

using nlohmann::json;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;

const std::string kCli = WG_CLI_PATH;
const std::string kRock = std::string(WG_SOURCE_DIR) + "/graphs/rock.json";

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

// stdout and stderr together, for messages.
testing::CommandResult eval(const std::string& arguments) { return runCommand(shellQuote(kCli) + " eval " + arguments); }

// stdout alone, parsed; fails the test unless it is JSON and the exit code is 0.
json evalJson(const std::string& arguments) {
  auto r = runCommand("(" + shellQuote(kCli) + " eval " + arguments + " 2>/dev/null)");
  EXPECT_EQ(r.exitCode, 0) << arguments << "\n" << r.output;
  return json::parse(r.output, nullptr, false);
}

void expectAllFinite(const json& value, const std::string& where) {
  if (value.is_object() || value.is_array()) {
    for (auto it = value.begin(); it != value.end(); ++it)
      expectAllFinite(*it, where + "/" + (value.is_object() ? it.key() : std::string("[]")));
    return;
  }
  if (value.is_string() || value.is_boolean()) return;
  ASSERT_TRUE(value.is_number()) << where << " is " << value.dump();
  EXPECT_TRUE(std::isfinite(value.get<double>())) << where;
}

TEST(EvalCli, PrintsJsonWithEveryInputOutputAndCoverageTerm) {
  const json out = evalJson(shellQuote(kRock) +
                            " --weather temperature=-5,snowLevel=0.7,sunDirection=1:1:0 --weather windIntensity=0.4"
                            " --at worldPosition=1:5:2,normal=0:1:0,texcoord=0.3:0.6 --param roughness=0.3");
  ASSERT_FALSE(out.is_discarded());
  EXPECT_EQ(out["material"], "rock");
  EXPECT_EQ(out["weatherPreset"], "rock");
  for (const char* field : {"baseColor", "metallic", "roughness", "specular", "normal", "ambientOcclusion", "emissive",
                            "opacity", "worldPositionOffset"})
    EXPECT_TRUE(out["outputs"].contains(field)) << field;
  EXPECT_EQ(out["outputs"].size(), 9u);
  EXPECT_EQ(out["outputs"]["baseColor"].size(), 3u);
  EXPECT_TRUE(out["outputs"]["metallic"].is_number());
  for (const char* term : {"snow", "wet", "moss", "frost", "ice", "puddle", "density"})
    EXPECT_TRUE(out["coverage"][term].is_number()) << term;
  EXPECT_EQ(out["coverage"].size(), 7u);
  EXPECT_GT(out["coverage"]["snow"].get<double>(), 0.0);
  expectAllFinite(out, "");

  // The inputs actually used: every weather and surface input, overrides applied and
  // directions normalised; every parameter of the material.
  const json& weather = out["inputs"]["weather"];
  for (const char* key : {"temperature", "precipitation", "windDirection", "windIntensity", "sunDirection", "sunIntensity",
                          "time", "snowLevel", "wetnessLevel", "mossLevel", "frostLevel", "puddleLevel", "terrainHeightScale"})
    EXPECT_TRUE(weather.contains(key)) << key;
  EXPECT_EQ(weather["temperature"], -5.0);
  EXPECT_EQ(weather["windIntensity"], 0.4);
  EXPECT_NEAR(weather["sunDirection"][0].get<double>(), std::sqrt(0.5), 1e-6);
  const json& surface = out["inputs"]["surface"];
  for (const char* key : {"worldPosition", "normal", "tangent", "texcoord", "texcoord1", "vertexColor", "skyExposure"})
    EXPECT_TRUE(surface.contains(key)) << key;
  EXPECT_EQ(surface["worldPosition"], json({1.0, 5.0, 2.0}));
  EXPECT_EQ(out["inputs"]["parameters"]["roughness"], 0.3);
  EXPECT_EQ(out["inputs"]["parameters"]["tint"], json({0.52, 0.5, 0.47}));
  EXPECT_TRUE(out["inputs"]["parameters"].contains("weather.w1"));
}

TEST(EvalCli, AtSetsTheSecondTextureCoordinateSet) {
  TempDir dir("eval-texcoord1");
  const auto graph = dir.path() / "uv1.json";
  testing::writeFile(graph, R"({"name": "uv1", "nodes": [{"id": "uv", "op": "texcoord1"}, {"id": "s", "op": "split", "inputs": {"in": "uv.out"}},
    {"id": "c", "op": "combine3", "inputs": {"x": "s.x", "y": "s.y"}}], "output": {"baseColor": "c.out"}})");
  const json out = evalJson(shellQuote(graph.string()) + " --at texcoord=0.9:0.9,texcoord1=0.25:0.75");
  EXPECT_EQ(out["inputs"]["surface"]["texcoord1"], json({0.25, 0.75}));
  EXPECT_EQ(out["outputs"]["baseColor"], json({0.25, 0.75, 0.0}));
}

TEST(EvalCli, EvaluatesTheMaterialThatCompileBuilds) {
  TempDir dir("eval-hash");
  auto compiled = runCommand(shellQuote(kCli) + " compile " + shellQuote(kRock) + " --target glsl -o " +
                             shellQuote(dir.path().string()));
  ASSERT_EQ(compiled.exitCode, 0) << compiled.output;
  const json reflection = json::parse(readFile(dir.path() / "rock.reflect.json"));
  EXPECT_EQ(evalJson(shellQuote(kRock))["contentHash"], reflection["contentHash"]);
}

TEST(EvalCli, WithoutWeatherCoverageIsNeutral) {
  const json out = evalJson(shellQuote(kRock) + " --weather-preset none --weather snowLevel=1,mossLevel=1,temperature=-5");
  EXPECT_EQ(out["weatherPreset"], "none");
  EXPECT_EQ(out["coverage"], json({{"snow", 0.0}, {"wet", 0.0}, {"moss", 0.0}, {"frost", 0.0}, {"ice", 0.0},
                                   {"puddle", 0.0}, {"density", 1.0}}));
}

TEST(EvalCli, DegenerateInputsGiveFiniteOutputs) {
  for (const char* inputs : {"--at normal=0:0:0 --weather temperature=60,windDirection=0:0,snowLevel=1,wetnessLevel=1",
                             "--at normal=0:-1:0,tangent=0:0:0 --weather temperature=-60,sunDirection=0:0:0,frostLevel=1",
                             "--weather windIntensity=1,precipitation=1,mossLevel=1,puddleLevel=1,time=100000"}) {
    const json out = evalJson(shellQuote(kRock) + " " + inputs);
    expectAllFinite(out, inputs);
  }
}

// Far from the origin a texture coordinate (the weather noise's, or road's own image's)
// overflows when scaled to texels; it used to wrap to a NaN index and read outside the
// image (SIGSEGV).
TEST(EvalCli, PositionsAndTexcoordsNearTheLargestFloatDoNotCrash) {
  const std::string road = std::string(WG_SOURCE_DIR) + "/graphs/road.json";
  for (const std::string& graph : {kRock, road})
    for (const char* inputs : {"--at worldPosition=1e38:0:0", "--at worldPosition=0:0:-3e38",
                               "--at texcoord=3e38:-3e38,texcoord1=3e38:3e38"}) {
      const json out = evalJson(shellQuote(graph) + " " + inputs);
      EXPECT_TRUE(out.contains("coverage")) << graph << " " << inputs;
    }
}

TEST(EvalCli, HelpListsEveryInputWithItsDefault) {
  auto plain = eval("--help");
  EXPECT_EQ(plain.exitCode, 0) << plain.output;
  for (const char* entry : {"temperature=15", "precipitation=0", "windDirection=1:0", "windIntensity=0", "sunDirection=0:1:0",
                            "sunIntensity=1", "time=0", "snowLevel=0", "wetnessLevel=0", "mossLevel=0", "frostLevel=0",
                            "puddleLevel=0", "terrainHeightScale=1", "worldPosition=0:0:0", "normal=0:1:0",
                            "tangent=1:0:0:1", "texcoord=0:0", "texcoord1=0:0", "vertexColor=1:1:1:1", "skyExposure=1"})
    EXPECT_NE(plain.output.find(entry), std::string::npos) << entry;

  auto withGraph = eval(shellQuote(kRock) + " --help");
  EXPECT_EQ(withGraph.exitCode, 0) << withGraph.output;
  for (const char* entry : {"temperature=15", "tint=0.52:0.5:0.47", "roughness=0.82", "uvScale=2", "weather.w1=2",
                            "weather.maxSnowHeight=0.25"})
    EXPECT_NE(withGraph.output.find(entry), std::string::npos) << entry;
}

struct UsageCase {
  std::string arguments;
  std::string mentions;  // the key or value the message must name
};

TEST(EvalCli, BadUsageExitsTwoWithOneLineNamingTheKey) {
  const std::string rock = shellQuote(kRock);
  const std::vector<UsageCase> cases = {
      {rock + " --weather temprature=3", "did you mean 'temperature'"},
      {rock + " --weather precipitation=1.5", "precipitation"},
      {rock + " --weather temperature=-61", "temperature"},
      {rock + " --weather temperature=abc", "temperature"},
      {rock + " --weather time=inf", "time"},
      {rock + " --weather snowLevel=1e999", "snowLevel"},
      {rock + " --weather windDirection=1:0:0", "windDirection"},
      {rock + " --weather temperature", "temperature"},
      {rock + " --weather temperature=1,temperature=2", "temperature"},
      {rock + " --at normal=0:1", "normal"},
      {rock + " --at skyExposure=2", "skyExposure"},
      {rock + " --at position=0:0:0", "position"},
      {rock + " --at normal=nan:0:0", "normal"},
      {rock + " --param roughnes=0.5", "did you mean 'roughness'"},
      {rock + " --param roughness=2", "roughness"},
      {rock + " --param tint=0.5", "tint"},
      {rock + " --weather-preset blizzard", "blizzard"},
      {rock + " --frobnicate", "frobnicate"},
      {rock + " " + rock, "one graph"},
      {"--weather temperature=1", "no input graph"},
  };
  for (const auto& c : cases) {
    auto r = eval(c.arguments);
    EXPECT_EQ(r.exitCode, kExitUsage) << c.arguments << "\n" << r.output;
    EXPECT_NE(r.output.find("WG9001"), std::string::npos) << c.arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(c.mentions), std::string::npos) << c.arguments << "\n" << r.output;
    // The message itself is one line (the fixed hint line follows it).
    const std::string first = r.output.substr(0, r.output.find('\n'));
    EXPECT_NE(first.find("WG9001"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("WG9001", first.size()), std::string::npos) << "one error, not several: " << r.output;
  }
}

TEST(EvalCli, BadGraphsExitOneWithTheCompilersDiagnostics) {
  TempDir dir("eval-bad");
  const auto bad = dir.path() / "bad.json";
  testing::writeFile(bad, R"({"name": "bad", "nodes": [{"id": "a", "op": "lerpp"}], "output": {"baseColor": "a.out"}})");
  auto r = eval(shellQuote(bad.string()));
  EXPECT_EQ(r.exitCode, kExitBadInput) << r.output;
  EXPECT_NE(r.output.find("WG2001"), std::string::npos) << r.output;

  auto missing = eval(shellQuote((dir.path() / "missing.json").string()));
  EXPECT_EQ(missing.exitCode, kExitBadInput) << missing.output;
  EXPECT_NE(missing.output.find("WG1002"), std::string::npos) << missing.output;

  auto help = eval(shellQuote(bad.string()) + " --help");
  EXPECT_EQ(help.exitCode, kExitBadInput) << help.output;
}

}  // namespace
}  // namespace wg
