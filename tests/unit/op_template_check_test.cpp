// Op templates are checked when the registry is built (nodes/op_template_check.hpp).
#include <gtest/gtest.h>

#include "nodes/op_registry.hpp"
#include "nodes/op_template_check.hpp"

namespace wg {
namespace {

OpDef opWithTemplate(std::string_view glsl) {
  OpDef op;
  op.name = "probe";
  op.inputs = {{"a", PortType::Float, std::nullopt}};
  op.glsl = glsl;
  return op;
}

TEST(OpTemplateCheck, EveryRegisteredOpPasses) {
  ASSERT_FALSE(allOps().empty());  // building the registry throws on a bad template
  for (const OpDef* op : allOps()) EXPECT_EQ(templateError(*op), std::nullopt) << op->name;
}

TEST(OpTemplateCheck, AcceptsPortsTypeAndKnownSymbols) {
  EXPECT_EQ(templateError(opWithTemplate("{T}({a}) * {@time} + {@worldPosition}.x")), std::nullopt);
}

TEST(OpTemplateCheck, RejectsAnUnknownPort) {
  auto error = templateError(opWithTemplate("({a} + {b})"));
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("{b}"), std::string::npos) << *error;
}

TEST(OpTemplateCheck, RejectsAnUnknownSymbol) {
  auto error = templateError(opWithTemplate("{a} * {@tiem}"));
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("@tiem"), std::string::npos) << *error;
}

TEST(OpTemplateCheck, RejectsTextureSymbolsWithoutATextureInput) {
  EXPECT_TRUE(templateError(opWithTemplate("{@sampleFn}(sampler2D({@texture}, {@sampler}), {a})")));
}

TEST(OpTemplateCheck, RejectsEmptyAndUnclosedTemplates) {
  EXPECT_TRUE(templateError(opWithTemplate("")));
  EXPECT_TRUE(templateError(opWithTemplate("{a")));
}

TEST(OpTemplateCheck, ChecksTheHlslOverrideToo) {
  OpDef op = opWithTemplate("{a}");
  op.hlsl = "{nope}";
  EXPECT_TRUE(templateError(op));
}

}  // namespace
}  // namespace wg
