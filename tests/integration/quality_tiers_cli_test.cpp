// Quality tiers through the CLI: compile --quality and the targets' default tier, and
// weathergen stats, whose rows are the static budgets' source (docs/BENCHMARKS.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <nlohmann/json.hpp>
#include <string>

#include "process_support.hpp"

namespace wg {
namespace {

using nlohmann::json;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;

const std::string kCli = WG_CLI_PATH;
std::string graph(const std::string& name) { return std::string(WG_SOURCE_DIR) + "/graphs/" + name + ".json"; }

json reflectedEffects(const std::string& arguments, const std::filesystem::path& dir) {
  auto r = runCommand(shellQuote(kCli) + " compile " + arguments + " -q -o " + shellQuote(dir.string()) + " 2>&1");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return json::parse(readFile(dir / "road.reflect.json"))["weather"]["effects"];
}

TEST(QualityTiersCli, CompileQualityAndTheTargetsDefault) {
  TempDir dir("quality");
  EXPECT_EQ(reflectedEffects(shellQuote(graph("road")) + " --target glsl", dir.path() / "high")["ripple"], true);
  const json low = reflectedEffects(shellQuote(graph("road")) + " --target glsl --quality low", dir.path() / "low");
  EXPECT_EQ(low["ripple"], false);
  EXPECT_EQ(low["skyExposure"], false);
  // GLSL ES alone is for mobile GPUs: low unless asked otherwise.
  EXPECT_EQ(reflectedEffects(shellQuote(graph("road")) + " --target glsles", dir.path() / "es")["skyExposure"], false);
  EXPECT_EQ(reflectedEffects(shellQuote(graph("road")) + " --target glsles --quality medium",
                             dir.path() / "es-medium")["skyExposure"], true);
  // With a desktop target beside it, the one compile serves both at high.
  EXPECT_EQ(reflectedEffects(shellQuote(graph("road")) + " --target glsles,glsl", dir.path() / "both")["ripple"], true);
}

TEST(QualityTiersCli, AnUnknownTierIsAUsageErrorListingTheTiers) {
  auto r = runCommand(shellQuote(kCli) + " compile " + shellQuote(graph("road")) + " --quality ultra -o /tmp 2>&1");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("low, medium, high"), std::string::npos) << r.output;
}

json statsRows(const std::string& arguments) {
  auto r = runCommand("(" + shellQuote(kCli) + " stats " + arguments + " --json 2>/dev/null)");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return json::parse(r.output, nullptr, false);
}

// Every row of every bundled weathered graph: each tier costs at least the one below
// it, HLSL stays within 5 % of GLSL, and the weather column is the difference from
// preset none (which has no weather: 0 added).
TEST(QualityTiersCli, StatsRowsAreOrderedByTierAndHlslFollowsGlsl) {
  std::string graphs;
  for (const char* name : {"rock", "terrain", "road", "river", "foliage"}) graphs += " " + shellQuote(graph(name));
  const json rows = statsRows(graphs);
  ASSERT_TRUE(rows.is_array());
  ASSERT_EQ(rows.size(), 5u * 3u * 2u * 2u);
  std::map<std::string, const json*> byKey;
  for (const json& row : rows) {
    for (const char* field : {"instructions", "weatherInstructions", "textureReads", "branches", "uniformBytes",
                              "interpolants"})
      ASSERT_TRUE(row.contains(field)) << field;
    byKey[row["material"].get<std::string>() + "/" + row["tier"].get<std::string>() + "/" +
          row["stage"].get<std::string>() + "/" + row["language"].get<std::string>()] = &row;
  }
  for (const auto& [key, row] : byKey) {
    const std::string material = (*row)["material"], stage = (*row)["stage"], language = (*row)["language"];
    const std::string tier = (*row)["tier"];
    if (tier != "low") {
      const std::string below = tier == "high" ? "medium" : "low";
      const json& lower = *byKey.at(material + "/" + below + "/" + stage + "/" + language);
      EXPECT_GE((*row)["weatherInstructions"].get<long>(), lower["weatherInstructions"].get<long>()) << key;
      EXPECT_GE((*row)["textureReads"].get<long>(), lower["textureReads"].get<long>()) << key;
    }
    if (language == "hlsl") {
      const json& glsl = *byKey.at(material + "/" + tier + "/" + stage + "/glsl");
      const double hlslCost = (*row)["weatherInstructions"], glslCost = glsl["weatherInstructions"];
      EXPECT_LE(std::abs(hlslCost - glslCost), 0.05 * std::max(glslCost, 1.0)) << key;
    }
  }
  // Sky exposure is what medium adds to low: on rock it reads the exposure map.
  EXPECT_GT((*byKey.at("rock/medium/frag/glsl"))["textureReads"].get<long>(),
            (*byKey.at("rock/low/frag/glsl"))["textureReads"].get<long>());
  // Road's looks (ripple, specular anti-aliasing) are what high adds to medium.
  EXPECT_GT((*byKey.at("road/high/frag/glsl"))["weatherInstructions"].get<long>(),
            (*byKey.at("road/medium/frag/glsl"))["weatherInstructions"].get<long>());
}

// The rows over their tier's budget, as docs/BENCHMARKS.md ("Quality tiers") explains
// them: material/tier/stage. Every other row of every bundled graph is held to its
// budget, and these are held to being over it, so the list shrinks when one comes in.
const std::set<std::string> kOverBudget = {
    "rock/low/frag",     "rock/medium/frag",    "rock/high/frag",    "rock/high/vert",
    "terrain/low/frag",  "terrain/medium/frag", "terrain/high/frag", "terrain/low/vert",
    "terrain/medium/vert", "terrain/high/vert", "grass/low/vert",    "grass/medium/vert",
    "grass/high/vert",
};

TEST(QualityTiersCli, StaticBudgetsHoldForEveryBundledGraph) {
  std::string graphs;
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(WG_SOURCE_DIR) + "/graphs"))
    if (entry.path().extension() == ".json") {
      graphs += " " + shellQuote(entry.path().string());
      ++count;
    }
  const json rows = statsRows(graphs);
  ASSERT_TRUE(rows.is_array());
  ASSERT_EQ(rows.size(), count * 3u * 2u * 2u);
  std::set<std::string> over;
  for (const json& row : rows) {
    if (row["language"] != "glsl") continue;  // HLSL follows GLSL within 5 % (above)
    const std::string key = row["material"].get<std::string>() + "/" + row["tier"].get<std::string>() + "/" +
                            row["stage"].get<std::string>();
    const long cost = row["weatherInstructions"], budget = row["weatherBudget"];
    if (kOverBudget.contains(key)) {
      EXPECT_GT(cost, budget) << key << " is within its budget now: take it off kOverBudget and docs/BENCHMARKS.md";
      over.insert(key);
    } else {
      EXPECT_LE(cost, budget) << key;
    }
  }
  EXPECT_EQ(over, kOverBudget);  // each listed row exists
}

TEST(QualityTiersCli, StatsOfAGraphWithoutWeatherAddNothing) {
  const json rows = statsRows(shellQuote(graph("snowfield")) + " --quality high");
  ASSERT_EQ(rows.size(), 4u);
  for (const json& row : rows) EXPECT_EQ(row["weatherInstructions"], 0) << row.dump();
}

TEST(QualityTiersCli, StatsOfABrokenGraphIsExitOneWithItsDiagnostic) {
  TempDir dir("quality");
  const std::string bad = (dir.path() / "bad.json").string();
  testing::writeFile(bad, "{\"name\": \"bad\", \"nodes\": [");
  auto r = runCommand(shellQuote(kCli) + " stats " + shellQuote(bad) + " 2>&1");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("WG1001"), std::string::npos) << r.output;
}

// Every broken graph is reported, not only the first, and none of the graphs' rows are
// printed; under --json the diagnostics on stderr are one array for the whole run.
TEST(QualityTiersCli, StatsReportsEveryBrokenGraphInOneJsonArray) {
  TempDir dir("quality");
  const std::string bad = (dir.path() / "bad.json").string(), missing = (dir.path() / "missing.json").string();
  testing::writeFile(bad, "{\"name\": \"bad\", \"nodes\": [");
  const std::string graphs = shellQuote(bad) + " " + shellQuote(graph("road")) + " " + shellQuote(missing);
  auto r = runCommand("(" + shellQuote(kCli) + " stats " + graphs + " --quality low --json 2>&1 >" +
                      shellQuote((dir.path() / "rows").string()) + ")");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(readFile(dir.path() / "rows"), "");
  const json diagnostics = json::parse(r.output, nullptr, false);
  ASSERT_TRUE(diagnostics.is_array()) << r.output;
  ASSERT_EQ(diagnostics.size(), 2u) << r.output;
  EXPECT_EQ(diagnostics[0]["code"], "WG1001");
  EXPECT_EQ(diagnostics[0]["file"], bad);
  EXPECT_EQ(diagnostics[1]["code"], "WG1002");
  EXPECT_EQ(diagnostics[1]["file"], missing);
}

TEST(QualityTiersCli, StatsOfEveryTierWritesOneEmptyDiagnosticsArray) {
  auto r = runCommand("(" + shellQuote(kCli) + " stats " + shellQuote(graph("road")) + " --json 2>&1 >/dev/null)");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(json::parse(r.output, nullptr, false), json::array()) << r.output;
}

// A usage error is JSON when --json comes after it, and names every --quality value.
TEST(QualityTiersCli, StatsUsageErrorsBeforeJsonAreJson) {
  for (const char* options : {"--weather-preset bogus --json", "--quality ultra --json"}) {
    auto r = runCommand("(" + shellQuote(kCli) + " stats " + shellQuote(graph("road")) + " " + options +
                        " 2>&1 >/dev/null)");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    const json diagnostics = json::parse(r.output, nullptr, false);
    ASSERT_TRUE(diagnostics.is_array() && diagnostics.size() == 1u) << options << ": " << r.output;
    EXPECT_EQ(diagnostics[0]["code"], "WG9001");
  }
  auto r = runCommand(shellQuote(kCli) + " stats " + shellQuote(graph("road")) + " --quality ultra");
  EXPECT_NE(r.output.find("low, medium, high, or all"), std::string::npos) << r.output;
}

// Rows lost on the way out are not a success: a full disk, a closed stdout.
TEST(QualityTiersCli, StatsRowsThatCannotBeWrittenFailTheCommand) {
  for (const char* stdoutTo : {">/dev/full", ">&-"}) {
    auto r = runCommand("(" + shellQuote(kCli) + " stats " + shellQuote(graph("road")) + " --quality low " + stdoutTo + ")");
    EXPECT_EQ(r.exitCode, 2) << stdoutTo << ": " << r.output;
    EXPECT_NE(r.output.find("cannot write the rows to standard output"), std::string::npos) << r.output;
  }
}

// Two graphs may declare one material: each JSON row names its file, a name that is not
// UTF-8 with U+FFFD for its stray byte.
TEST(QualityTiersCli, StatsJsonRowsNameTheirGraphFile) {
  TempDir dir("quality");
  const std::string plain = (dir.path() / "road.json").string(), hostile = (dir.path() / "r\xff.json").string();
  testing::writeFile(plain, readFile(graph("road")));
  testing::writeFile(hostile, readFile(graph("road")));
  const json rows = statsRows(shellQuote(plain) + " " + shellQuote(hostile) + " --quality low");
  ASSERT_TRUE(rows.is_array() && rows.size() == 8u) << rows.dump();
  EXPECT_EQ(rows[0]["graph"], plain);
  EXPECT_EQ(rows[7]["graph"], (dir.path() / "r\xef\xbf\xbd.json").string());
  EXPECT_EQ(rows[7]["material"], "road");
}

// A graph given twice, under another spelling of its path, adds no rows; in the table,
// two files declaring one material name each name their file beside it.
TEST(QualityTiersCli, StatsRowsOfEachFileOnceAndSharedNamesShowTheirFile) {
  TempDir dir("quality");
  const std::string plain = (dir.path() / "road.json").string(), copy = (dir.path() / "copy.json").string();
  testing::writeFile(plain, readFile(graph("road")));
  testing::writeFile(copy, readFile(graph("road")));
  const std::string respelt = (dir.path() / "." / "road.json").string();
  EXPECT_EQ(statsRows(shellQuote(plain) + " " + shellQuote(respelt) + " --quality low").size(), 4u);
  auto r = runCommand(shellQuote(kCli) + " stats " + shellQuote(plain) + " " + shellQuote(copy) + " --quality low");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("| road (" + plain + ") | low | frag | glsl |"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("| road (" + copy + ") | low | frag | glsl |"), std::string::npos) << r.output;
  r = runCommand(shellQuote(kCli) + " stats " + shellQuote(plain) + " --quality low");
  EXPECT_NE(r.output.find("| road | low | frag | glsl |"), std::string::npos) << r.output;
}

// A '|' in a material's name is escaped in the table, so each row keeps its 11 cells.
TEST(QualityTiersCli, StatsTableEscapesAPipeInTheName) {
  TempDir dir("quality");
  json road = json::parse(readFile(graph("road")));
  road["name"] = "wet|road";
  const std::string path = (dir.path() / "pipe.json").string();
  testing::writeFile(path, road.dump());
  auto r = runCommand(shellQuote(kCli) + " stats " + shellQuote(path) + " --quality low");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::size_t row = r.output.find("| wet\\|road |");
  ASSERT_NE(row, std::string::npos) << r.output;
  const std::string line = r.output.substr(row, r.output.find('\n', row) - row);
  std::size_t separators = 0;
  for (std::size_t i = 0; i < line.size(); ++i) separators += line[i] == '|' && (i == 0 || line[i - 1] != '\\');
  EXPECT_EQ(separators, 12u) << line;
}

// --gpu: what AMD's own shader compiler (RADV's null device, no GPU needed) makes of each
// GLSL stage: registers, waves, ISA instructions and what the weather adds to them.
TEST(QualityTiersCli, StatsGpuShowsWhatAnAmdCompilerMakesOfEachGlslStage) {
  const json rows = statsRows(shellQuote(graph("rock")) + " --quality high --gpu navi21");
  ASSERT_EQ(rows.size(), 4u) << rows;
  for (const json& r : rows) {
    if (r["language"] == "hlsl") {
      EXPECT_FALSE(r.contains("gpu")) << r;
      continue;
    }
    const json& gpu = r.at("gpu");
    EXPECT_GE(gpu.at("vgprs").get<int>(), 8) << r;
    EXPECT_GE(gpu.at("wavesPerSimd").get<int>(), 1) << r;
    EXPECT_GE(gpu.at("codeBytes").get<int>(), 4 * gpu.at("instructions").get<int>()) << r;  // 4 or 8 bytes each
    // Rock's high tier displaces snow and shades it: both stages run more than without.
    EXPECT_GT(gpu.at("weatherInstructions").get<int>(), 20) << r;
    EXPECT_GT(gpu.at("instructions").get<int>(), gpu.at("weatherInstructions").get<int>()) << r;
  }
  // Against itself (preset none), the weather adds nothing on the GPU either.
  for (const json& r : statsRows(shellQuote(graph("rock")) + " --quality low --gpu navi21 --weather-preset none"))
    if (r["language"] == "glsl") EXPECT_EQ(r.at("gpu").at("weatherInstructions"), 0) << r;
  auto table = runCommand(shellQuote(kCli) + " stats " + shellQuote(graph("rock")) + " --quality low --gpu navi21");
  ASSERT_EQ(table.exitCode, 0) << table.output;
  EXPECT_NE(table.output.find("| VGPRs | waves per SIMD | ISA instructions | weather ISA |"), std::string::npos)
      << table.output;
  EXPECT_NE(table.output.find("| - | - | - | - |"), std::string::npos) << table.output;  // the HLSL rows
}

// RADV ends the process on a family it does not know, so none reaches it.
TEST(QualityTiersCli, StatsGpuRefusesAFamilyItDoesNotKnow) {
  for (const std::string family : {"nosuch", "arcturus", ""}) {
    auto r = runCommand(shellQuote(kCli) + " stats " + shellQuote(graph("rock")) + " --gpu " + shellQuote(family) + " 2>&1");
    EXPECT_EQ(r.exitCode, 2) << family << ": " << r.output;
    EXPECT_NE(r.output.find("navi21"), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace wg
