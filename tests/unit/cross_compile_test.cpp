// MSL and GLSL ES from the validated SPIR-V: what the compile driver fills in, the
// shape of each translation, and slots that follow (set, binding), not declaration order.
#include <gtest/gtest.h>

#include "backends/spirv/cross_compile.hpp"
#include "driver/material_compiler.hpp"

namespace wg {
namespace {

const std::string kSmallGraph = R"({
  "name": "small",
  "parameters": {"tint": {"type": "vec3", "default": [0.5, 0.4, 0.3]}},
  "textures": {"albedo": {"generator": "fbm", "seed": 3, "size": 16}},
  "nodes": [
    {"id": "uv", "op": "texcoord"},
    {"id": "albedo", "op": "sample", "inputs": {"texture": "albedo", "uv": "uv.out"}},
    {"id": "tint", "op": "parameter", "param": "tint"},
    {"id": "color", "op": "multiply", "inputs": {"a": "albedo.rgb", "b": "tint.out"}}
  ],
  "output": {"baseColor": "color.out", "roughness": 0.7}
})";

CompiledMaterial compileSmall(CompileOptions options) {
  CompileResult r = compileMaterialText("small.json", kSmallGraph, options);
  for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  EXPECT_TRUE(r.material);
  return r.material ? std::move(*r.material) : CompiledMaterial{};
}

CompileOptions bothTargets() {
  CompileOptions options;
  options.emitMsl = options.emitGlslEs = true;
  return options;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CrossCompile, OffByDefault) {
  for (const auto& stage : compileSmall({}).stages) {
    EXPECT_TRUE(stage.msl.empty());
    EXPECT_TRUE(stage.glslEs.empty());
  }
}

TEST(CrossCompile, FillsEveryStageOfBothLanguages) {
  CompiledMaterial m = compileSmall(bothTargets());
  ASSERT_EQ(m.stages.size(), 4u);
  for (const auto& stage : m.stages) {
    SCOPED_TRACE(std::string(languageName(stage.language)) + (stage.stage == ShaderStage::Vertex ? " vert" : " frag"));
    EXPECT_TRUE(stage.glslEs.starts_with("#version 310 es\n"));
    EXPECT_TRUE(contains(stage.msl, "#include <metal_stdlib>"));
    const char* qualifier = stage.stage == ShaderStage::Vertex ? "vertex " : "fragment ";
    EXPECT_TRUE(contains(stage.msl, qualifier)) << stage.msl;
    EXPECT_TRUE(contains(stage.msl, " main0(")) << stage.msl;
  }
}

TEST(CrossCompile, TranslationsNeedNoSpirvOutput) {
  CompileOptions options = bothTargets();
  options.emitSpirv = false;
  for (const auto& stage : compileSmall(options).stages) {
    EXPECT_TRUE(stage.spirv.empty());
    EXPECT_TRUE(stage.disassembly.empty());
    EXPECT_FALSE(stage.msl.empty());
    EXPECT_FALSE(stage.glslEs.empty());
  }
}

TEST(CrossCompile, GlslEsCombinesSamplersWithFullPrecisionAndExplicitBindings) {
  CompiledMaterial m = compileSmall(bothTargets());
  const std::string& frag = m.stage(ShaderLanguage::Glsl, ShaderStage::Fragment).glslEs;
  EXPECT_TRUE(contains(frag, "precision highp float;")) << frag;
  // Slot 2: after the host's shadow map and sky reflection (set 0), as in MSL's [[texture(2)]].
  EXPECT_TRUE(contains(frag, "layout(binding = 2) uniform highp sampler2D tex_albedo_smp_albedo;")) << frag;
  EXPECT_TRUE(contains(frag, "layout(binding = 1) uniform highp samplerCube wg_sky_reflection_map_wg_sky_reflection_sampler;"))
      << frag;
  EXPECT_TRUE(contains(m.stage(ShaderLanguage::Glsl, ShaderStage::Fragment).msl, "tex_albedo [[texture(2)]]"));
  EXPECT_FALSE(contains(frag, "texture2D ")) << frag;  // no separate images left
  EXPECT_FALSE(contains(frag, "set = ")) << frag;      // GL has no descriptor sets
  EXPECT_TRUE(contains(frag, "layout(binding = 0, std140) uniform FrameBlock")) << frag;
  EXPECT_TRUE(contains(frag, "} frameBlock;")) << frag;  // not an id-derived name
  EXPECT_TRUE(contains(frag, "layout(binding = 1, std140) uniform MaterialBlock")) << frag;
}

TEST(CrossCompile, IsByteDeterministic) {
  CompiledMaterial a = compileSmall(bothTargets()), b = compileSmall(bothTargets());
  for (std::size_t i = 0; i < a.stages.size(); ++i) {
    EXPECT_EQ(a.stages[i].msl, b.stages[i].msl);
    EXPECT_EQ(a.stages[i].glslEs, b.stages[i].glslEs);
  }
}

// Two textures declared in the reverse of their binding order, in two descriptor sets.
const std::string kReversedDeclarations = R"(#version 440
layout(set = 1, binding = 4) uniform texture2D late;
layout(set = 1, binding = 2) uniform texture2D early;
layout(set = 1, binding = 5) uniform sampler lateSampler;
layout(set = 1, binding = 3) uniform sampler earlySampler;
layout(set = 1, binding = 0, std140) uniform Material { vec4 tint; } material;
layout(set = 0, binding = 0, std140) uniform Frame { vec4 light; } frame;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
  color = texture(sampler2D(late, lateSampler), uv) + texture(sampler2D(early, earlySampler), uv) +
          material.tint + frame.light;
}
)";

SpirvWords reversedModule() {
  SpirvCompileResult compiled = compileToSpirv(kReversedDeclarations, ShaderLanguage::Glsl, ShaderStage::Fragment);
  EXPECT_TRUE(compiled.ok) << compiled.log;
  EXPECT_EQ(validateSpirv(compiled.words), "");
  return compiled.words;
}

TEST(CrossCompile, MslSlotsFollowSetAndBindingNotDeclarationOrder) {
  CrossResult msl = spirvToMsl(reversedModule(), ShaderStage::Fragment);
  ASSERT_TRUE(msl.ok) << msl.error;
  EXPECT_EQ(msl.entryPoint, "main0");
  EXPECT_TRUE(contains(msl.source, "frame [[buffer(0)]]")) << msl.source;     // set 0 before set 1
  EXPECT_TRUE(contains(msl.source, "material [[buffer(1)]]")) << msl.source;
  EXPECT_TRUE(contains(msl.source, "early [[texture(0)]]")) << msl.source;    // binding 2 before 4
  EXPECT_TRUE(contains(msl.source, "late [[texture(1)]]")) << msl.source;
  EXPECT_TRUE(contains(msl.source, "earlySampler [[sampler(0)]]")) << msl.source;
  EXPECT_TRUE(contains(msl.source, "lateSampler [[sampler(1)]]")) << msl.source;
}

TEST(CrossCompile, GlslEsSlotsFollowSetAndBindingNotFirstUse) {
  CrossResult es = spirvToGlslEs(reversedModule(), ShaderStage::Fragment);
  ASSERT_TRUE(es.ok) << es.error;
  EXPECT_EQ(es.entryPoint, "main");
  EXPECT_TRUE(contains(es.source, "layout(binding = 0) uniform highp sampler2D early_earlySampler;")) << es.source;
  EXPECT_TRUE(contains(es.source, "layout(binding = 1) uniform highp sampler2D late_lateSampler;")) << es.source;
  EXPECT_TRUE(contains(es.source, "layout(binding = 0, std140) uniform Frame")) << es.source;
  EXPECT_TRUE(contains(es.source, "layout(binding = 1, std140) uniform Material")) << es.source;
}

TEST(CrossCompile, ReportsSpirvCrossErrorsAsValues) {
  const SpirvWords truncated = {0x07230203u};  // the magic number and nothing else
  for (CrossResult r : {spirvToMsl(truncated, ShaderStage::Vertex), spirvToGlslEs(truncated, ShaderStage::Vertex)}) {
    EXPECT_FALSE(r.ok);
    EXPECT_FALSE(r.error.empty());
    EXPECT_TRUE(r.source.empty());
  }
}

}  // namespace
}  // namespace wg
