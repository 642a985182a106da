// The surface (--target surface) is what the full shaders run: they embed its functions
// in the reference host. The full shaders are validated against the CPU evaluator and
// the reference images, so this is what ties a surface to them.
#include <gtest/gtest.h>

#include <cctype>
#include <set>

#include "backends/shader_syntax.hpp"
#include "backends/surface_writer.hpp"
#include "backends/token_renames.hpp"
#include "compiler/name_mark.hpp"
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

// A top-level definition: from the start of the line that names it to its closing "}".
std::string definition(const std::string& text, const std::string& head) {
  std::size_t at = text.find(head);
  if (at == std::string::npos) return "";
  std::size_t begin = text.rfind('\n', at) + 1;
  return text.substr(begin, text.find("\n}", at) + 3 - begin);
}

// The material's identifiers without their prefix, as a shader of one material names them.
std::string withoutPrefix(std::string text, const std::string& prefix) {
  for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) text.erase(at, prefix.size());
  return text;
}

class SurfaceOfBundledGraph : public ::testing::TestWithParam<std::string> {};

// One code path: every full stage embeds the surface file's own structs and function,
// byte for byte but for the prefix, and its main() only calls that function. So the
// CPU-evaluator and reference-image checks of the full shaders check the surfaces.
TEST_P(SurfaceOfBundledGraph, FullShadersEmbedTheSurfaceFunctions) {
  CompiledMaterial m = compileBundled(GetParam());
  MaterialInterface mi = buildMaterialInterface(m.ir);
  SurfaceInterface s = buildSurfaceInterface(mi, m.fileStem);
  for (const auto& language : surfaceLanguages()) {
    if (language.language == SurfaceLanguage::GlslEs) continue;  // full GLSL ES comes from SPIR-V
    bool hlsl = language.language == SurfaceLanguage::Hlsl;
    std::size_t index = static_cast<std::size_t>(&language - surfaceLanguages().data());
    const std::string& surface = m.surfaces[index];
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
      bool vertex = stage == ShaderStage::Vertex;
      const std::string& full = m.stage(hlsl ? ShaderLanguage::Hlsl : ShaderLanguage::Glsl, stage).source;
      const std::string function = vertex ? s.vertexFunction : s.fragmentFunction;
      const std::string label = std::string(language.name) + (vertex ? " vertex" : " fragment");
      std::string embedded = withoutPrefix(definition(surface, " " + function + "("), s.prefix);
      ASSERT_GT(embedded.size(), 100u) << label;
      EXPECT_NE(full.find(embedded), std::string::npos) << label << ":\n" << embedded;
      for (const SurfaceStruct* st : {vertex ? &s.vertexInput : &s.fragmentInput, vertex ? &s.vertexOutput : &s.fragmentOutput})
        EXPECT_NE(full.find(withoutPrefix(definition(surface, "struct " + st->name + " {"), s.prefix)), std::string::npos)
            << label << ' ' << st->name;
      std::string main = full.substr(full.find(" main("));
      EXPECT_NE(main.find(withoutPrefix(function, s.prefix) + "(wg_" + (vertex ? "vertexInput" : "fragmentInput") + ")"),
                std::string::npos)
          << label;
      EXPECT_EQ(main.find(" n0_"), std::string::npos) << label << ": a node statement outside the surface";
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
  EXPECT_EQ(buildSurfaceInterface(mi, "snow_layer2").prefix, "snow_layer2_");
  EXPECT_EQ(buildSurfaceInterface(mi, "wet-road--2").prefix, "wet_road_2_" + nameMark("wet-road--2") + "_");
  EXPECT_EQ(buildSurfaceInterface(mi, "9lives").prefix, "m9lives_" + nameMark("9lives") + "_");
  EXPECT_EQ(buildSurfaceInterface(mi, "gl_stone").prefix, "mgl_stone_" + nameMark("gl_stone") + "_");
  EXPECT_EQ(buildSurfaceInterface(mi, "WG").prefix, "mWG_" + nameMark("WG") + "_");
  EXPECT_EQ(buildSurfaceInterface(mi, "_x_").prefix, "x_" + nameMark("_x_") + "_");
}

// Several surfaces share one shader, so distinct stems (file names in one folder) must
// never share a prefix: each pair here read alike before stems were marked.
TEST(Surface, DistinctStemsGetDistinctPrefixes) {
  MaterialInterface mi;
  const std::vector<std::string> stems = {
      "a-b", "a_b", "a__b", "a-_b", "a", "a_", "_a", "gl", "mgl", "1x", "m1x", "weather", "mweather",
      "a_" + nameMark("a-b"), "a_b_" + nameMark("a-b"), "___.h47b3ec86", "m_h47b3ec86", "rock.5031108184e10afe",
      "rock_5031108184e10afe", std::string(64, 'x'), std::string(63, 'x') + "-"};
  std::set<std::string> prefixes;
  for (const auto& stem : stems) {
    const std::string prefix = buildSurfaceInterface(mi, stem).prefix;
    EXPECT_TRUE(prefixes.insert(prefix).second) << stem << " shares the prefix " << prefix;
    EXPECT_TRUE(std::isalpha(static_cast<unsigned char>(prefix[0]))) << prefix;
    EXPECT_EQ(prefix.find("__"), std::string::npos) << prefix;
    EXPECT_EQ(prefix.back(), '_') << prefix;
  }
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
