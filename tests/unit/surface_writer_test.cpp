// The surface (--target surface) computes what the full shaders compute: the same node
// statements, with the frame's names swapped for the host contract's. The full shaders
// are validated against the CPU evaluator and the reference images, so this is what
// ties a surface to them.
#include <gtest/gtest.h>

#include <sstream>

#include "backends/shader_syntax.hpp"
#include "backends/stage_writer.hpp"
#include "backends/surface_writer.hpp"
#include "backends/token_renames.hpp"
#include "compiler/surface_interface.hpp"
#include "driver/material_compiler.hpp"
#include "nodes/frame_fields.hpp"

namespace wg {
namespace {

CompiledMaterial compileBundled(const std::string& name, const std::string& preset = "") {
  CompileOptions options;
  options.emitSpirv = false;
  options.emitSurface = true;
  if (!preset.empty()) options.weatherPreset = preset;
  auto result = compileMaterialFile(std::string(WG_SOURCE_DIR) + "/graphs/" + name + ".json", options);
  EXPECT_TRUE(result.material.has_value());
  return std::move(*result.material);
}

// The node statements of a stage: lines that declare an n<index>_ local.
std::vector<std::string> nodeStatements(const std::string& text, const std::string& from, const std::string& to) {
  std::size_t begin = text.find(from), end = text.find(to, begin);
  EXPECT_NE(begin, std::string::npos) << from;
  std::vector<std::string> lines;
  std::istringstream in(text.substr(begin, end - begin));
  for (std::string line; std::getline(in, line);) {
    std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos) continue;
    std::size_t space = line.find(' ', start);
    if (space != std::string::npos && line.compare(space + 1, 1, "n") == 0 && line.find(" = ") != std::string::npos)
      lines.push_back(line.substr(start));
  }
  return lines;
}

// The full shader's statements spelled as the surface spells them.
TokenRenames surfaceSpelling(const SurfaceInterface& s, const MaterialInterface& mi, ShaderStage stage) {
  TokenRenames r;
  for (const auto& field : frameFields()) {
    std::string name(field.name);
    if (field.owner != FrameFieldOwner::Host) r.bare["frame_" + name] = "weather_" + name;
  }
  r.bare["frame_cameraPosition"] = "wg_cameraPosition";
  for (std::size_t i = 0; i < mi.material.members.size(); ++i)
    r.bare[mi.material.members[i].identifier] = s.prefixed.material.members[i].identifier;
  for (std::size_t i = 0; i < mi.textures.size(); ++i) {
    r.bare[mi.textures[i].textureIdentifier] = s.prefixed.textures[i].textureIdentifier;
    r.bare[mi.textures[i].samplerIdentifier] = s.prefixed.textures[i].samplerIdentifier;
  }
  for (const auto& v : mi.varyings) {
    r.bare[v.identifier] = (stage == ShaderStage::Vertex ? "wg_out." : "wg_in.") + v.name;
    r.member[v.identifier] = v.name;
  }
  return r;
}

class SurfaceOfBundledGraph : public ::testing::TestWithParam<std::string> {};

TEST_P(SurfaceOfBundledGraph, RunsTheFullShadersStatements) {
  CompiledMaterial m = compileBundled(GetParam());
  MaterialInterface mi = buildMaterialInterface(m.ir);
  SurfaceInterface s = buildSurfaceInterface(mi, m.fileStem);
  for (const auto& language : surfaceLanguages()) {
    if (language.language == SurfaceLanguage::GlslEs) continue;  // GLSL's text, samplers combined
    bool hlsl = language.language == SurfaceLanguage::Hlsl;
    std::size_t index = static_cast<std::size_t>(&language - surfaceLanguages().data());
    const std::string& surface = m.surfaces[index];
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
      const std::string& full = m.stage(hlsl ? ShaderLanguage::Hlsl : ShaderLanguage::Glsl, stage).source;
      std::string function = stage == ShaderStage::Vertex ? s.vertexFunction : s.fragmentFunction;
      auto fromFull = nodeStatements(renameTokens(full, surfaceSpelling(s, mi, stage)), "main(", "\n}\n");
      auto fromSurface = nodeStatements(surface, function + "(", "\n}\n");
      if (stage == ShaderStage::Fragment) ASSERT_FALSE(fromFull.empty());  // a vertex stage may have none
      EXPECT_EQ(fromSurface, fromFull) << language.name << (stage == ShaderStage::Vertex ? " vertex" : " fragment");
    }
  }
}

TEST_P(SurfaceOfBundledGraph, ReadsNothingOfTheHostsFrame) {
  CompiledMaterial m = compileBundled(GetParam());
  for (const std::string& surface : m.surfaces) {
    EXPECT_EQ(surface.find("frame_"), std::string::npos);
    EXPECT_EQ(surface.find("void main"), std::string::npos);
    EXPECT_EQ(surface.find("#version"), std::string::npos);
    EXPECT_EQ(surface.find("wg_shade("), std::string::npos);
    EXPECT_EQ(surface.find("wg_tonemap("), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(Graphs, SurfaceOfBundledGraph,
                         ::testing::Values("foliage", "grass", "river", "road", "rock", "snow_layer", "snowfield",
                                           "terrain"));

// Preset none leaves the material untouched: no weather block read, no weather branch.
TEST(Surface, PresetNoneHasNoWeather) {
  CompiledMaterial m = compileBundled("rock", "none");
  for (const std::string& surface : m.surfaces) {
    std::size_t function = surface.find("rock_surfaceFragment(");
    ASSERT_NE(function, std::string::npos);
    EXPECT_EQ(surface.find("weather_", function), std::string::npos) << surface.substr(function, 2000);
  }
}

TEST(Surface, PrefixIsAnIdentifierThatMeetsNoReservedName) {
  MaterialInterface mi;
  EXPECT_EQ(buildSurfaceInterface(mi, "rock").prefix, "rock_");
  EXPECT_EQ(buildSurfaceInterface(mi, "wet-road--2").prefix, "wet_road_2_");
  EXPECT_EQ(buildSurfaceInterface(mi, "9lives").prefix, "m9lives_");
  EXPECT_EQ(buildSurfaceInterface(mi, "gl_stone").prefix, "mgl_stone_");
  EXPECT_EQ(buildSurfaceInterface(mi, "WG").prefix, "mWG_");
  EXPECT_EQ(buildSurfaceInterface(mi, "_x_").prefix, "m_x_");
}

// The weather block holds exactly the frame fields the weather owns or places.
TEST(Surface, WeatherBlockIsTheWeathersFields) {
  std::vector<std::string> expected, actual;
  for (const auto& field : frameFields())
    if (field.owner != FrameFieldOwner::Host) expected.push_back("weather_" + std::string(field.name));
  for (const auto& member : surfaceWeatherBlock().members) actual.push_back(member.identifier);
  EXPECT_EQ(actual, expected);
  EXPECT_EQ(surfaceWeatherBlock().size % 16, 0u);
}

TEST(TokenRenames, RenamesIdentifiersNotCommentsAndCombinesSamplers) {
  TokenRenames r;
  r.bare["frame_time"] = "weather_time";
  r.member["v_x"] = "x";
  r.combineSamplers = true;
  EXPECT_EQ(renameTokens("a = frame_time; // frame_time\nb = s.v_x + v_x;", r),
            "a = weather_time; // frame_time\nb = s.x + v_x;");
  EXPECT_EQ(renameTokens("texture(sampler2D(t, s), uv)", r), "texture(t, uv)");
  EXPECT_EQ(renameTokens("x.sampler2D(t, s)", r), "x.sampler2D(t, s)");
}

}  // namespace
}  // namespace wg
