// --effects through the CLI: compile, eval, render and bench-render switch the named
// weather effects in every graph that has weather, and a bad list is a usage error
// that writes nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "host/image/png_file.hpp"
#include "tests/integration/process_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string cli() { return shellQuote(WG_CLI_PATH); }
std::string graph(const std::string& name) { return shellQuote(std::string(WG_SOURCE_DIR) + "/graphs/" + name + ".json"); }
bool contains(const std::string& text, std::string_view piece) { return text.find(piece) != std::string::npos; }

TEST(EffectsOptionCli, CompileSwitchesTheEffectInEveryWeatheredGraph) {
  TempDir dir("effects-compile");
  const std::string out = shellQuote((dir.path() / "out").string());
  CommandResult r = runCommand(cli() + " compile " + graph("rock") + " " + graph("road") + " " + graph("snow_layer") +
                               " --target glsl -q -o " + out + " --effects specularAntiAliasing=off --effects relief=off");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* name : {"rock", "road"}) {
    const std::string frag = readFile(dir.path() / "out" / (std::string(name) + ".frag.glsl"));
    EXPECT_FALSE(contains(frag, "wg_specular_aa(")) << name;
    EXPECT_TRUE(contains(frag, "= wg_wet_roughness(")) << name;
    const json reflection = json::parse(readFile(dir.path() / "out" / (std::string(name) + ".reflect.json")));
    EXPECT_EQ(reflection["weather"]["effects"]["specularAntiAliasing"], false) << name;
    EXPECT_EQ(reflection["weather"]["effects"]["relief"], false) << name;
    EXPECT_EQ(reflection["weather"]["effects"]["ripple"], true) << name;
  }
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "snow_layer.frag.glsl"));  // no weather: compiled as it is

  r = runCommand(cli() + " compile " + graph("rock") + " --target glsl -q -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(contains(readFile(dir.path() / "out" / "rock.frag.glsl"), "= wg_specular_aa("));
}

TEST(EffectsOptionCli, ABadListIsAUsageErrorThatWritesNothing) {
  TempDir dir("effects-bad");
  const fs::path out = dir.path() / "out";
  CommandResult r = runCommand(cli() + " compile " + graph("rock") + " -q -o " + shellQuote(out.string()) +
                               " --effects specularAntiAlias=off");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "unknown effect 'specularAntiAlias' (effects: snow,")) << r.output;
  EXPECT_TRUE(contains(r.output, "specularAntiAliasing")) << r.output;
  EXPECT_FALSE(fs::exists(out));
  r = runCommand(cli() + " bench-render --effects relief=maybe");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "relief takes on or off, not 'maybe'")) << r.output;
}

TEST(EffectsOptionCli, EvalLeavesASwitchedOffEffectOut) {
  const std::string args = " eval " + graph("rock") + " --weather temperature=-5,snowLevel=0.8 --at normal=0:1:0";
  CommandResult on = runCommand("(" + cli() + args + " 2>/dev/null)");
  CommandResult off = runCommand("(" + cli() + args + " --effects snow=off 2>/dev/null)");
  ASSERT_EQ(on.exitCode, 0) << on.output;
  ASSERT_EQ(off.exitCode, 0) << off.output;
  EXPECT_GT(json::parse(on.output)["coverage"]["snow"].get<double>(), 0.5);
  EXPECT_EQ(json::parse(off.output)["coverage"]["snow"].get<double>(), 0.0);
}

// The snow AOV of the rocks in a snowfall, with and without snow switched off.
TEST(EffectsOptionCli, RenderDrawsWithTheSwitchedEffects) {
  TempDir dir("effects-render");
  auto brightest = [&](const std::string& extra) {
    const fs::path png = dir.path() / "snow.png";
    CommandResult r = runCommand(std::string(kVulkanChildEnvironment) + cli() +
                                 " render --scene rocks --aov snow --weather temperature=-5,snowLevel=1 --size 48x27 -q -o " +
                                 shellQuote(png.string()) + extra);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::string error;
    auto image = image::readPng(png.string(), error);
    EXPECT_TRUE(image) << error;
    int most = 0;
    if (image)
      for (std::size_t i = 0; i < image->rgba.size(); i += 4) most = std::max<int>(most, image->rgba[i]);
    return most;
  };
  EXPECT_GT(brightest(""), 200);
  EXPECT_EQ(brightest(" --effects snow=off"), 0);
}

TEST(EffectsOptionCli, BenchRenderSaysWhichEffectsItSwitched) {
  CommandResult r = runCommand(std::string(kVulkanChildEnvironment) + cli() +
                               " bench-render --scene rocks --size 32x18 --frames 1 --effects relief=off,ripple=off");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "Effects switched in every weathered configuration: relief=off, ripple=off.\n"))
      << r.output;
  EXPECT_TRUE(contains(r.output, "\n| rocks | ")) << r.output;
}

}  // namespace
}  // namespace wg::testing
