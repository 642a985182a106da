// Every bundled graph, every stage of both languages: the GLSL ES translation compiles
// with the independent glslangValidator as an ES shader, and the two stages link; the MSL translation compiles
// with Metal's compiler where there is one, and otherwise is checked against the SPIR-V
// it came from (same entry point, as many resources per slot kind as it uses, distinct
// slots). Both agree between stages on every slot and are byte-identical across compiles.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>

#include "driver/material_compiler.hpp"
#include "process_support.hpp"

namespace wg {
namespace {

using testing::bundledGraphs;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
using testing::writeFile;
namespace fs = std::filesystem;

std::string graphName(const ::testing::TestParamInfo<fs::path>& info) { return info.param.stem().string(); }

CompiledMaterial compileBoth(const fs::path& graph) {
  CompileOptions options;
  options.emitMsl = options.emitGlslEs = true;
  CompileResult r = compileMaterialFile(graph.string(), options);
  for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  EXPECT_TRUE(r.material);
  return r.material ? std::move(*r.material) : CompiledMaterial{};
}

std::string stageName(ShaderStage stage) { return stage == ShaderStage::Vertex ? "vert" : "frag"; }
std::string label(const CompiledStage& s) { return std::string(languageName(s.language)) + "." + stageName(s.stage); }

// Metal's compiler ships with Xcode only; elsewhere the SPIRV-Cross checks stand in.
bool metalCompilerAvailable() {
  static const bool available = runCommand("xcrun --find metal").exitCode == 0;
  return available;
}

// Resource name -> slot, from `name [[kind(N)]]` in MSL or `layout(binding = N...) uniform
// [highp] type name` in GLSL ES (uniform blocks by block name).
using Slots = std::map<std::string, int>;

// Each match's name and slot; the pattern's groups are (name, slot), or (slot, name).
Slots matches(const std::string& text, const std::regex& pattern, bool slotFirst = false) {
  Slots slots;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator(); ++it)
    slots[(*it)[slotFirst ? 2 : 1].str()] = std::stoi((*it)[slotFirst ? 1 : 2].str());
  return slots;
}

Slots mslSlots(const std::string& msl, const std::string& kind) {
  return matches(msl, std::regex("(\\w+) \\[\\[" + kind + "\\((\\d+)\\)\\]\\]"));
}

Slots glslEsSlots(const std::string& glsl) {
  return matches(glsl, std::regex("layout\\(binding = (\\d+)[^)]*\\) uniform (?:highp )?(?:\\w+ )?(\\w+)"), true);
}

// The slots the MSL uses for a kind: as many as the SPIR-V's entry point uses, each below
// the number the module declares (slots are ranks among all declared resources).
void expectSlotsMatchReflection(const Slots& slots, std::size_t used, std::size_t declared, const std::string& kind) {
  std::set<int> distinct;
  for (const auto& [name, slot] : slots) distinct.insert(slot);
  EXPECT_EQ(distinct.size(), slots.size()) << kind << ": two resources share a slot";
  EXPECT_EQ(slots.size(), used) << kind;
  for (const auto& [name, slot] : slots) EXPECT_LT(static_cast<std::size_t>(slot), declared) << kind << " " << name;
}

// A resource both stages use has one slot: one binding table serves the whole material.
void expectStagesAgree(const Slots& vertex, const Slots& fragment, const std::string& what) {
  for (const auto& [name, slot] : vertex)
    if (auto it = fragment.find(name); it != fragment.end()) {
      EXPECT_EQ(it->second, slot) << what << " " << name;
    }
}

class CrossCompiledGraph : public ::testing::TestWithParam<fs::path> {};

TEST_P(CrossCompiledGraph, GlslEsCompilesWithGlslangValidator) {
  CompiledMaterial m = compileBoth(GetParam());
  TempDir dir("glsles");
  for (const auto& stage : m.stages) {
    ASSERT_TRUE(stage.glslEs.starts_with("#version 310 es\n")) << label(stage);
    fs::path file = dir.path() / (m.fileStem + "." + label(stage) + ".es.glsl");
    writeFile(file, stage.glslEs);
    // No -V: an OpenGL ES compile, as a GLES driver would do it.
    auto v = runCommand(shellQuote(WG_GLSLANG_VALIDATOR) + " -S " + stageName(stage.stage) + " " +
                        shellQuote(file.string()));
    EXPECT_EQ(v.exitCode, 0) << label(stage) << ":\n" << v.output << "\n" << stage.glslEs;
  }
}

// GL links the two stages into one program: interfaces and uniform bindings must agree.
TEST_P(CrossCompiledGraph, GlslEsStagesLinkAsOneProgram) {
  CompiledMaterial m = compileBoth(GetParam());
  TempDir dir("glsles-link");
  for (ShaderLanguage language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl}) {
    std::string command = shellQuote(WG_GLSLANG_VALIDATOR) + " -l";
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
      // With -l the stage comes from the extension.
      fs::path file = dir.path() / (m.fileStem + "." + std::string(languageName(language)) + "." + stageName(stage));
      writeFile(file, m.stage(language, stage).glslEs);
      command += " " + shellQuote(file.string());
    }
    auto v = runCommand(command);
    EXPECT_EQ(v.exitCode, 0) << languageName(language) << ":\n" << v.output;
  }
}

TEST_P(CrossCompiledGraph, MslCompilesOrMatchesTheSpirvItCameFrom) {
  CompiledMaterial m = compileBoth(GetParam());
  TempDir dir("msl");
  for (const auto& stage : m.stages) {
    SCOPED_TRACE(label(stage));
    ASSERT_FALSE(stage.msl.empty());
    if (metalCompilerAvailable()) {
      fs::path file = dir.path() / (m.fileStem + "." + label(stage) + ".metal");
      writeFile(file, stage.msl);
      auto v = runCommand("xcrun -sdk macosx metal -std=macos-metal2.0 -c " + shellQuote(file.string()) +
                          " -o /dev/null");
      EXPECT_EQ(v.exitCode, 0) << v.output;
    }
    // The round trip: the MSL must declare what SPIRV-Cross reflects from the SPIR-V.
    ReflectedResources spirv = reflectResources(stage.spirv);
    EXPECT_EQ(spirv.entryPoint, "main");
    // `main` is reserved in Metal; SPIRV-Cross renames it main0.
    const std::regex entry(std::string(stage.stage == ShaderStage::Vertex ? "vertex" : "fragment") + " [^\n(]* " +
                           spirv.entryPoint + "0\\(");
    EXPECT_TRUE(std::regex_search(stage.msl, entry)) << stage.msl;
    expectSlotsMatchReflection(mslSlots(stage.msl, "buffer"), spirv.used.uniformBuffers,
                               spirv.declared.uniformBuffers, "buffer");
    expectSlotsMatchReflection(mslSlots(stage.msl, "texture"), spirv.used.separateImages,
                               spirv.declared.separateImages, "texture");
    expectSlotsMatchReflection(mslSlots(stage.msl, "sampler"), spirv.used.separateSamplers,
                               spirv.declared.separateSamplers, "sampler");
  }
}

TEST_P(CrossCompiledGraph, StagesAgreeOnSlots) {
  CompiledMaterial m = compileBoth(GetParam());
  for (ShaderLanguage language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl}) {
    const CompiledStage& vertex = m.stage(language, ShaderStage::Vertex);
    const CompiledStage& fragment = m.stage(language, ShaderStage::Fragment);
    std::string from(languageName(language));
    for (const char* kind : {"buffer", "texture", "sampler"})
      expectStagesAgree(mslSlots(vertex.msl, kind), mslSlots(fragment.msl, kind), from + " MSL " + kind);
    // GL links the stages into one program, which rejects a uniform bound twice.
    Slots vertexEs = glslEsSlots(vertex.glslEs), fragmentEs = glslEsSlots(fragment.glslEs);
    EXPECT_FALSE(fragmentEs.empty()) << fragment.glslEs;
    expectStagesAgree(vertexEs, fragmentEs, from + " GLSL ES");
  }
}

TEST_P(CrossCompiledGraph, TranslationsAreByteIdenticalAcrossCompiles) {
  CompiledMaterial a = compileBoth(GetParam()), b = compileBoth(GetParam());
  ASSERT_EQ(a.stages.size(), b.stages.size());
  for (std::size_t i = 0; i < a.stages.size(); ++i) {
    EXPECT_EQ(a.stages[i].msl, b.stages[i].msl) << label(a.stages[i]);
    EXPECT_EQ(a.stages[i].glslEs, b.stages[i].glslEs) << label(a.stages[i]);
  }
}

INSTANTIATE_TEST_SUITE_P(Bundled, CrossCompiledGraph, ::testing::ValuesIn(bundledGraphs()), graphName);

}  // namespace
}  // namespace wg
