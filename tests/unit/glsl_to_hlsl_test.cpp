// The GLSL -> HLSL token map the HLSL backend derives libraries, op templates and
// stage frames with (backends/glsl_to_hlsl.hpp).
#include <gtest/gtest.h>

#include <stdexcept>

#include "backends/glsl_to_hlsl.hpp"
#include "backends/glsl_tokens.hpp"

namespace wg {
namespace {

TEST(GlslToHlsl, MapsIdentifierTokensOnly) {
  EXPECT_EQ(glslToHlsl("vec3 a = mix(b, c, fract(t)) * inversesqrt(d);"),
            "float3 a = lerp(b, c, frac(t)) * rsqrt(d);");
  EXPECT_EQ(glslToHlsl("ivec2 i; uvec4 u; bvec3 b; mat3 m; dFdx(p); dFdy(p);"),
            "int2 i; uint4 u; bool3 b; float3x3 m; ddx(p); ddy(p);");
  // Never a substring: names that contain a mapped word stay as they are.
  EXPECT_EQ(glslToHlsl("float vec3x = mixer + wg_mix + fract_2 + myvec3;"),
            "float vec3x = mixer + wg_mix + fract_2 + myvec3;");
}

TEST(GlslToHlsl, LeavesSwizzlesMembersAndNumbersAlone) {
  EXPECT_EQ(glslToHlsl("v.xyz + s.mix + s . fract"), "v.xyz + s.mix + s . fract");
  EXPECT_EQ(glslToHlsl("1.0f + 1u + 1e-3 + 2.5E+2 + .5 + 0x1Fu + 3.0e2f"), "1.0f + 1u + 1e-3 + 2.5E+2 + .5 + 0x1Fu + 3.0e2f");
  std::vector<GlslToken> tokens = tokenizeGlsl("1e-3");
  ASSERT_EQ(tokens.size(), 1u);
  EXPECT_EQ(tokens[0].kind, GlslTokenKind::Number);
}

TEST(GlslToHlsl, CopiesCommentsVerbatim) {
  EXPECT_EQ(glslToHlsl("vec2 a; // a vec2, mixed\n/* vec3 mix( */ vec4 b;"),
            "float2 a; // a vec2, mixed\n/* vec3 mix( */ float4 b;");
}

TEST(GlslToHlsl, OneArgumentConstructorsBecomeCasts) {
  EXPECT_EQ(glslToHlsl("return vec3(0.0);"), "return ((float3)(0.0));");
  EXPECT_EQ(glslToHlsl("uvec4(ivec4(i.x, i.y, 0, 1))"), "((uint4)(int4(i.x, i.y, 0, 1)))");
  EXPECT_EQ(glslToHlsl("vec2(a, b)"), "float2(a, b)");
  EXPECT_EQ(glslToHlsl("float(n >> 8u)"), "float(n >> 8u)");
}

TEST(GlslToHlsl, RewritesComparisonsAtan2AndMod) {
  EXPECT_EQ(glslToHlsl("all(lessThan(uv, vec2(1.0)))"), "all((uv < ((float2)(1.0))))");
  EXPECT_EQ(glslToHlsl("any(greaterThanEqual(f(a, b), c))"), "any((f(a, b) >= c))");
  EXPECT_EQ(glslToHlsl("not(b)"), "(!b)");
  EXPECT_EQ(glslToHlsl("atan(y, x) + atan(t)"), "atan2(y, x) + atan(t)");
  EXPECT_EQ(glslToHlsl("mod(x, 2.0)"), "wg_glsl_mod(x, 2.0)");
  EXPECT_NE(hlslPrelude().find("float3 wg_glsl_mod(float3 x, float y) { return x - y * floor(x / y); }"),
            std::string_view::npos);
  EXPECT_TRUE(callsHlslPrelude(glslToHlsl("mod(x, 2.0)")));
  EXPECT_FALSE(callsHlslPrelude(glslToHlsl("fract(x)")));
}

TEST(GlslToHlsl, SamplingBecomesAMethodCall) {
  EXPECT_EQ(glslToHlsl("texture(sampler2D(tex, smp), uv + vec2(h, -h)).r"), "tex.Sample(smp, uv + float2(h, -h)).r");
  EXPECT_EQ(glslToHlsl("textureLod(sampler2D(tex, smp), uv, 0.0)"), "tex.SampleLevel(smp, uv, 0.0)");
  // Op templates: placeholders stay opaque; the symbol names the method in HLSL.
  EXPECT_EQ(glslToHlsl("{@sampleFn}(sampler2D({@texture}, {@sampler}), {uv}{@lodArg})"),
            "{@texture}.{@sampleFn}({@sampler}, {uv}{@lodArg})");
  EXPECT_EQ(glslToHlsl("{T}({x}, {y}) + {mix}"), "{T}({x}, {y}) + {mix}");
  EXPECT_THROW(glslToHlsl("sampler2D(tex, smp)"), std::invalid_argument);
}

TEST(GlslToHlsl, MatrixTimesOperandBecomesMul) {
  HlslTranslation t;
  t.matrices = {"frame_model"};
  EXPECT_EQ(glslToHlsl("(frame_model * vec4(p, 1.0)).xyz", t), "(mul(frame_model, float4(p, 1.0))).xyz");
  EXPECT_EQ(glslToHlsl("frame_model * v.xyz * 2.0", t), "mul(frame_model, v.xyz) * 2.0");
  EXPECT_EQ(glslToHlsl("frame_model * -f(a)[1]", t), "mul(frame_model, -f(a)[1])");
  EXPECT_EQ(glslToHlsl("other * v", t), "other * v");
}

TEST(GlslToHlsl, RenamesApplyToWholeNamesOutsideMembers) {
  HlslTranslation t;
  t.renames = {{"v_color", "wg_in.v_color"}, {"gl_FrontFacing", "wg_frontFacing"}};
  EXPECT_EQ(glslToHlsl("vec4 c = v_color; bool f = gl_FrontFacing; x.v_color;", t),
            "float4 c = wg_in.v_color; bool f = wg_frontFacing; x.v_color;");
}

}  // namespace
}  // namespace wg
