// Weather presets through the CLI (docs/weather-model.md): "none" is exactly no weather,
// every preset on every bundled graph passes the independent validators, disabled
// effects fold away at compile time, and the weather block's errors carry WG4001-WG4009.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "nodes/weather_shader_library.hpp"
#include "process_support.hpp"

namespace wg {
namespace {

using testing::bundledGraphs;
using testing::listFiles;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
using testing::writeFile;
namespace fs = std::filesystem;

const std::string kCli = WG_CLI_PATH;
const std::vector<std::string> kPresets = {"rock", "terrain", "foliage", "river", "road", "none"};

testing::CommandResult compile(const fs::path& graph, const fs::path& out, const std::string& extra = "") {
  return runCommand(shellQuote(kCli) + " compile " + shellQuote(graph.string()) + " -o " + shellQuote(out.string()) +
                    " --target all " + extra);
}

void expectSameOutputs(const fs::path& a, const fs::path& b) {
  auto filesA = listFiles(a), filesB = listFiles(b);
  ASSERT_EQ(filesA, filesB);
  ASSERT_FALSE(filesA.empty());
  for (const auto& name : filesA) EXPECT_TRUE(readFile(a / name) == readFile(b / name)) << name << " differs";
}

// The functions the weather library defines ("<type> wg_name(" at the start of a line).
std::set<std::string> weatherFunctions() {
  static const std::regex kDefinition(R"(^([A-Za-z_][A-Za-z0-9_]*)\s+(wg_[a-z0-9_]+)\s*\()");
  std::set<std::string> names;
  std::istringstream lines{std::string(kWeatherLibrary.glsl)};
  std::string line;
  std::smatch m;
  while (std::getline(lines, line))
    if (std::regex_search(line, m, kDefinition) && m[1].str() != "return") names.insert(m[2].str());
  return names;
}

// The entry point and everything after it: the body the weather pass writes into.
// The stage's own statements: its surface function, which the reference host's main() calls.
std::string surfaceBody(const std::string& source) {
  static const std::regex kMain(R"(\bsurface(Vertex|Fragment)\s*\(\w+ wg_in\))");
  std::smatch m;
  if (!std::regex_search(source, m, kMain)) return "";
  return source.substr(static_cast<std::size_t>(m.position(0)));
}

bool calls(const std::string& text, const std::string& function) {
  return std::regex_search(text, std::regex("\\b" + function + "\\s*\\("));
}

// ---------------------------------------------------------------------------------------
// "none" equals no weather block.

class WeatherNone : public ::testing::TestWithParam<fs::path> {};

TEST_P(WeatherNone, NoneIsByteIdenticalToNoBlock) {
  TempDir dir("weather-none");
  auto graph = nlohmann::ordered_json::parse(readFile(GetParam()));
  auto without = graph, none = graph;
  without.erase("weather");
  none["weather"] = "none";
  for (const char* variant : {"without", "none"}) fs::create_directories(dir.path() / variant);
  // Same file name in both, so nothing but the weather field differs.
  fs::path withoutGraph = dir.path() / "without" / GetParam().filename();
  fs::path noneGraph = dir.path() / "none" / GetParam().filename();
  writeFile(withoutGraph, without.dump(2));
  writeFile(noneGraph, none.dump(2));
  auto a = compile(withoutGraph, dir.path() / "out-without");
  ASSERT_EQ(a.exitCode, 0) << a.output;
  auto b = compile(noneGraph, dir.path() / "out-none");
  ASSERT_EQ(b.exitCode, 0) << b.output;
  expectSameOutputs(dir.path() / "out-without", dir.path() / "out-none");
  // --weather-preset none on the original graph is the same too.
  auto c = compile(GetParam(), dir.path() / "out-flag", "--weather-preset none");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  expectSameOutputs(dir.path() / "out-without", dir.path() / "out-flag");
}

// Preset "none" emits no call to (nor definition of) any weather library function.
TEST_P(WeatherNone, NoneEmitsNoWeatherCode) {
  TempDir dir("weather-none-code");
  auto r = compile(GetParam(), dir.path(), "--weather-preset none");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto functions = weatherFunctions();
  ASSERT_FALSE(functions.empty());
  int sources = 0;
  for (const auto& name : listFiles(dir.path())) {
    if (!name.ends_with(".glsl") && !name.ends_with(".hlsl")) continue;
    ++sources;
    std::string text = readFile(dir.path() / name);
    for (const auto& f : functions) EXPECT_FALSE(calls(text, f)) << name << " mentions " << f;
  }
  EXPECT_EQ(sources, 4);
}

std::string graphName(const ::testing::TestParamInfo<fs::path>& info) { return info.param.stem().string(); }
INSTANTIATE_TEST_SUITE_P(Graphs, WeatherNone, ::testing::ValuesIn(bundledGraphs()), graphName);

// ---------------------------------------------------------------------------------------
// Every preset on every bundled graph passes spirv-val and glslangValidator.

class EveryPreset : public ::testing::TestWithParam<std::tuple<fs::path, std::string>> {};

TEST_P(EveryPreset, CompilesAndPassesIndependentValidators) {
  const auto& [graph, preset] = GetParam();
  TempDir dir("weather-preset");
  auto r = compile(graph, dir.path(), "--weather-preset " + preset);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int sources = 0, modules = 0;
  for (const auto& name : listFiles(dir.path())) {
    fs::path file = dir.path() / name;
    std::string stage = name.find(".vert.") != std::string::npos ? "vert" : "frag";
    std::string command;
    if (name.ends_with(".glsl")) {
      command = shellQuote(WG_GLSLANG_VALIDATOR) + " -V --target-env vulkan1.1 -S " + stage + " " +
                shellQuote(file.string()) + " -o /dev/null";
      ++sources;
    } else if (name.ends_with(".hlsl")) {
      command = shellQuote(WG_GLSLANG_VALIDATOR) + " -V -D -e main --target-env vulkan1.1 -S " + stage + " " +
                shellQuote(file.string()) + " -o /dev/null";
      ++sources;
    } else if (name.ends_with(".spv")) {
      command = shellQuote(WG_SPIRV_VAL) + " --target-env vulkan1.1 " + shellQuote(file.string());
      ++modules;
    } else {
      continue;
    }
    auto v = runCommand(command);
    EXPECT_EQ(v.exitCode, 0) << name << " (" << preset << "):\n" << v.output;
  }
  EXPECT_EQ(sources, 4);
  EXPECT_EQ(modules, 4);
  auto reflection = nlohmann::json::parse(readFile(dir.path() / (graph.stem().string() + ".reflect.json")));
  EXPECT_EQ(reflection["weather"]["preset"], preset);
}

std::string presetCaseName(const ::testing::TestParamInfo<std::tuple<fs::path, std::string>>& info) {
  return std::get<0>(info.param).stem().string() + "_" + std::get<1>(info.param);
}
INSTANTIATE_TEST_SUITE_P(GraphsTimesPresets, EveryPreset,
                         ::testing::Combine(::testing::ValuesIn(bundledGraphs()), ::testing::ValuesIn(kPresets)),
                         presetCaseName);

// ---------------------------------------------------------------------------------------
// A disabled effect is folded away at compile time.

// graphs/rock.json with its "weather" field replaced.
fs::path rockWith(const TempDir& dir, const nlohmann::ordered_json& weather) {
  auto graph = nlohmann::ordered_json::parse(readFile(fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json"));
  graph["weather"] = weather;
  fs::path path = dir.path() / "rock.json";
  writeFile(path, graph.dump(2));
  return path;
}

TEST(WeatherFolding, RockWithoutMossEmitsNoMossCoverage) {
  TempDir dir("fold-moss");
  // Control: the full rock preset does call it.
  auto r = compile(rockWith(dir, "rock"), dir.path() / "full", "--target glsl,hlsl");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* file : {"rock.frag.glsl", "rock.frag.hlsl"})
    EXPECT_TRUE(calls(surfaceBody(readFile(dir.path() / "full" / file)), "wg_moss_coverage")) << file;

  r = compile(rockWith(dir, {{"preset", "rock"}, {"effects", {{"moss", false}}}}), dir.path() / "nomoss",
              "--target glsl,hlsl");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* file : {"rock.frag.glsl", "rock.frag.hlsl"}) {
    std::string body = surfaceBody(readFile(dir.path() / "nomoss" / file));
    ASSERT_FALSE(body.empty()) << file;
    EXPECT_FALSE(calls(body, "wg_moss_coverage")) << file;
    EXPECT_FALSE(calls(body, "wg_moss_albedo")) << file;
    EXPECT_TRUE(calls(body, "wg_snow_coverage")) << file;  // the rest stays
  }
}

TEST(WeatherFolding, RockWithoutDisplacementEmitsNoSnowOffset) {
  TempDir dir("fold-displacement");
  auto r = compile(rockWith(dir, "rock"), dir.path() / "full", "--target glsl,hlsl");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* file : {"rock.vert.glsl", "rock.vert.hlsl"})
    EXPECT_TRUE(calls(surfaceBody(readFile(dir.path() / "full" / file)), "wg_snow_offset")) << file;

  r = compile(rockWith(dir, {{"preset", "rock"}, {"effects", {{"displacement", false}}}}), dir.path() / "flat",
              "--target glsl,hlsl");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* file : {"rock.vert.glsl", "rock.vert.hlsl"}) {
    std::string text = readFile(dir.path() / "flat" / file);
    ASSERT_FALSE(surfaceBody(text).empty()) << file;
    EXPECT_FALSE(calls(text, "wg_snow_offset")) << file;  // neither called nor defined
  }
  // Snow cover itself is still in the fragment stage.
  EXPECT_TRUE(calls(surfaceBody(readFile(dir.path() / "flat" / "rock.frag.glsl")), "wg_snow_coverage"));
}

// A slope blend: the terrain's moss comes from its steep preset and fades in with the
// slope; its prediction's switches move with the slope. Without the blend the terrain
// has no moss, and --weather-preset replaces the blend with the preset.
TEST(WeatherSlopeBlend, SteepPartsTakeTheSteepPresetsEffectsAndTerms) {
  TempDir dir("slope-blend");
  fs::path graph = dir.path() / "terrain.json";
  auto json = nlohmann::ordered_json::parse(readFile(fs::path(WG_SOURCE_DIR) / "graphs" / "terrain.json"));
  ASSERT_TRUE(json["weather"].contains("steep"));
  json["weather"]["steep"]["slope"] = {20, 50};
  writeFile(graph, json.dump(2));
  auto r = compile(graph, dir.path() / "blend", "--target glsl");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string body = surfaceBody(readFile(dir.path() / "blend" / "terrain.frag.glsl"));
  EXPECT_TRUE(calls(body, "wg_moss_coverage"));
  EXPECT_FALSE(calls(body, "wg_terrain_orientation")) << "the terrain has no terrain under it to blend into";
  // The flat angle's cosine and the steep one's bound the smoothstep of the normal's up.
  EXPECT_NE(body.find("smoothstep(0.64278764, 0.9396926,"), std::string::npos) << body;
  EXPECT_NE(body.find("mix(vec4(0.0, 0.0, 1.0, 1.0), vec4(1.0), "), std::string::npos) << body;
  auto reflection = nlohmann::json::parse(readFile(dir.path() / "blend" / "terrain.reflect.json"));
  EXPECT_EQ(reflection["weather"]["steep"], nlohmann::json::parse(R"({"preset": "rock", "slope": [20.0, 50.0]})"));

  json["weather"] = "terrain";
  writeFile(graph, json.dump(2));
  ASSERT_EQ(compile(graph, dir.path() / "plain", "--target glsl").exitCode, 0);
  const std::string plain = surfaceBody(readFile(dir.path() / "plain" / "terrain.frag.glsl"));
  EXPECT_FALSE(calls(plain, "wg_moss_coverage"));

  r = compile(fs::path(WG_SOURCE_DIR) / "graphs" / "terrain.json", dir.path() / "override", "--target glsl --weather-preset terrain");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(readFile(dir.path() / "override" / "terrain.frag.glsl"), readFile(dir.path() / "plain" / "terrain.frag.glsl"));
}

// ---------------------------------------------------------------------------------------
// Weather block errors.

struct Diagnostics {
  int exitCode = -1;
  nlohmann::json list;  // the --diagnostics json array
  std::string raw;
};

Diagnostics compileText(const TempDir& dir, const std::string& graphText, const std::string& extra = "") {
  fs::path graph = dir.path() / "graph.json";
  writeFile(graph, graphText);
  auto r = runCommand(shellQuote(kCli) + " compile " + shellQuote(graph.string()) + " -o " +
                      shellQuote((dir.path() / "out").string()) + " -q --diagnostics json " + extra);
  Diagnostics d{r.exitCode, nlohmann::json::array(), r.output};
  auto open = r.output.find('[');
  if (open != std::string::npos) d.list = nlohmann::json::parse(r.output.substr(open), nullptr, false);
  return d;
}

std::string minimalGraph(const std::string& weather, const std::string& parameters = "") {
  return R"({"name": "w", )" + (parameters.empty() ? "" : R"("parameters": )" + parameters + ", ") +
         R"("nodes": [], "weather": )" + weather + R"(, "output": {"roughness": 0.5}})";
}

void expectOnly(const Diagnostics& d, const std::string& code, const std::string& pointer) {
  ASSERT_EQ(d.exitCode, 1) << d.raw;
  ASSERT_TRUE(d.list.is_array()) << d.raw;
  ASSERT_EQ(d.list.size(), 1u) << d.raw;
  EXPECT_EQ(d.list[0]["code"], code) << d.raw;
  EXPECT_EQ(d.list[0]["pointer"], pointer) << d.raw;
  EXPECT_FALSE(d.list[0]["message"].get<std::string>().empty());
}

TEST(WeatherErrors, UnknownPresetIsWG4001) {
  TempDir dir("weather-err");
  expectOnly(compileText(dir, minimalGraph(R"("snowy")")), "WG4001", "/weather");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rok"})")), "WG4001", "/weather/preset");
}

TEST(WeatherErrors, OutOfRangeMaxSnowHeightIsWG4002) {
  TempDir dir("weather-err");
  // Metres, not the seed's centimetres: 25 is outside [0, 10].
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "maxSnowHeight": 25})")), "WG4002",
             "/weather/maxSnowHeight");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "maxSnowHeight": -0.1})")), "WG4002",
             "/weather/maxSnowHeight");
  // In range compiles.
  auto ok = compileText(dir, minimalGraph(R"({"preset": "rock", "maxSnowHeight": 0.5})"));
  EXPECT_EQ(ok.exitCode, 0) << ok.raw;
}

// The block's tier is checked even where --quality replaces it, as its kind is: the
// same file must not compile under one command line and fail under another.
TEST(WeatherErrors, AnUnknownTierIsWG4006AndANonStringTierWG4007WhateverTheQualityOption) {
  TempDir dir("weather-err");
  for (const char* option : {"", "--quality low"}) {
    expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "quality": "ultra"})"), option), "WG4006",
               "/weather/quality");
    expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "quality": 3})"), option), "WG4007",
               "/weather/quality");
  }
  auto ok = compileText(dir, minimalGraph(R"({"preset": "rock", "quality": "medium"})"), "--quality low");
  EXPECT_EQ(ok.exitCode, 0) << ok.raw;
}

// As with the tier: a graph's unknown preset is reported where it is written, whatever
// --weather-preset puts in its place; a known one is simply replaced.
TEST(WeatherErrors, AnUnknownPresetIsReportedWhateverReplacesIt) {
  TempDir dir("weather-err");
  for (const char* option : {"", "--weather-preset rock", "--weather-preset none"}) {
    expectOnly(compileText(dir, minimalGraph(R"("blizzard")"), option), "WG4001", "/weather");
    expectOnly(compileText(dir, minimalGraph(R"({"preset": "blizzard"})"), option), "WG4001", "/weather/preset");
  }
  auto ok = compileText(dir, minimalGraph(R"({"preset": "road"})"), "--weather-preset rock");
  EXPECT_EQ(ok.exitCode, 0) << ok.raw;
}

TEST(WeatherErrors, UnknownEffectIsWG4006AndANonBooleanEffectWG4007) {
  TempDir dir("weather-err");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "effects": {"glitter": true}})")), "WG4006",
             "/weather/effects/glitter");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "glitter": 1})")), "WG4006", "/weather/glitter");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "effects": {"moss": "no"}})")), "WG4007",
             "/weather/effects/moss");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "effects": true})")), "WG4007", "/weather/effects");
}

TEST(WeatherErrors, APresetlessBlockIsWG4008AndInvertedHeightsWG4009) {
  TempDir dir("weather-err");
  expectOnly(compileText(dir, minimalGraph(R"({"maxSnowHeight": 0.2})")), "WG4008", "/weather");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": 3})")), "WG4007", "/weather/preset");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "terrain", "minHeight": 100, "maxHeight": 50})")), "WG4009",
             "/weather");
}

TEST(WeatherErrors, BadWeightsShapeIsWG4007AndAWeightOutOfRangeWG4002) {
  TempDir dir("weather-err");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "weights": [1, 2, 3]})")), "WG4007", "/weather/weights");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "weights": 2})")), "WG4007", "/weather/weights");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "weights": [1, 2, "3", 4]})")), "WG4007",
             "/weather/weights");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "weights": [1, 2, 3, 17]})")), "WG4002",
             "/weather/weights/3");
  // The switches have the same shape and take only 0 or 1.
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "terms": [1, 1, 1]})")), "WG4007", "/weather/terms");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "rock", "terms": [1, 0, 1, 0.5]})")), "WG4007",
             "/weather/terms/3");
}

TEST(WeatherErrors, ABadSlopeBlendNamesItsMember) {
  TempDir dir("weather-err");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "terrain", "steep": {"preset": "rock", "slope": [45, 30]}})")),
             "WG4007", "/weather/steep/slope");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "terrain", "steep": {"preset": "rock", "slope": [30]}})")),
             "WG4007", "/weather/steep/slope");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "terrain", "steep": {"preset": "road"}})")), "WG4007",
             "/weather/steep/preset");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "terrain", "steep": {"preset": "none"}})")), "WG4007",
             "/weather/steep/preset");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "terrain", "steep": {"preset": "rock", "angle": 3}})")),
             "WG4006", "/weather/steep/angle");
  expectOnly(compileText(dir, minimalGraph(R"({"preset": "terrain", "steep": "rock"})")), "WG4007", "/weather/steep");
}

TEST(WeatherErrors, ReservedParameterPrefixIsWG4004WithAnActivePreset) {
  TempDir dir("weather-err");
  const std::string parameters = R"({"weather.w1": {"type": "float", "default": 1}})";
  expectOnly(compileText(dir, minimalGraph(R"("rock")", parameters)), "WG4004", "/parameters/weather.w1");
  // The preset from the command line counts too.
  expectOnly(compileText(dir, minimalGraph(R"("none")", parameters), "--weather-preset road"), "WG4004",
             "/parameters/weather.w1");
  // Without weather the name is free.
  auto ok = compileText(dir, minimalGraph(R"("none")", parameters));
  EXPECT_EQ(ok.exitCode, 0) << ok.raw;
}

TEST(WeatherErrors, UnknownCommandLinePresetIsUsageError) {
  TempDir dir("weather-err");
  auto d = compileText(dir, minimalGraph(R"("rock")"), "--weather-preset bogus");
  EXPECT_EQ(d.exitCode, 2) << d.raw;
  ASSERT_TRUE(d.list.is_array() && d.list.size() == 1) << d.raw;
  EXPECT_EQ(d.list[0]["code"], "WG9001") << d.raw;
  EXPECT_NE(d.list[0]["message"].get<std::string>().find("bogus"), std::string::npos) << d.raw;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace
}  // namespace wg
