// The IR verifier: each invariant planted broken is caught, the pipeline names the
// pass after which the IR broke, and every bundled graph passes with verification on.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/graph_loader.hpp"
#include "compiler/ir_verifier.hpp"
#include "driver/material_compiler.hpp"
#include "compiler/pass_pipeline.hpp"
#include "ir_fixture.hpp"

namespace wg {
namespace {

using testing::graphJson;
using testing::irBeforePasses;

// A parameter, a texture, a multi-output node, a generic op and a swizzle.
IrGraph sampleIr() {
  return irBeforePasses(graphJson(
      R"({"id": "uv", "op": "texcoord"},
         {"id": "scale", "op": "parameter", "param": "scale"},
         {"id": "suv", "op": "multiply", "inputs": {"a": "uv.out", "b": "scale.out"}},
         {"id": "tex", "op": "sample", "inputs": {"texture": "albedo", "uv": "suv.out"}},
         {"id": "parts", "op": "split", "inputs": {"in": "tex.rgb"}},
         {"id": "sw", "op": "swizzle", "inputs": {"in": "tex.rgb", "channels": "zyx"}})",
      R"("baseColor": "sw.out", "roughness": "parts.y")",
      R"("parameters": {"scale": {"type": "float", "default": 2}},
         "textures": {"albedo": {"generator": "fbm", "size": 16}}, )"));
}

std::uint32_t nodeOf(const IrGraph& g, std::string_view op) {
  for (std::uint32_t i = 0; i < g.nodes.size(); ++i)
    if (g.nodes[i].op->name == op) return i;
  ADD_FAILURE() << "no " << op << " node";
  return 0;
}

// The verifier's complaint about a planted violation; it must name one.
std::string violationIn(const IrGraph& g, IrVerifyOptions options = {}) {
  std::string problem = verifyIr(g, options);
  EXPECT_FALSE(problem.empty()) << "the planted violation went unnoticed";
  return problem;
}

TEST(IrVerifier, CatchesAnInterpolantThatIsNoVertexRateNode) {
  IrGraph g = sampleIr();
  g.interpolants = {nodeOf(g, "multiply")};
  EXPECT_EQ(verifyIr(g), "interpolant 0 (node 2) is not a vertex-rate op");
  g.interpolants = {99};
  EXPECT_EQ(verifyIr(g), "interpolant 0 (node 99) does not exist");
}

TEST(IrVerifier, AcceptsTheBuiltIrAndEveryPassResult) {
  IrGraph g = sampleIr();
  ASSERT_EQ(g.nodes.size(), 6u);
  EXPECT_EQ(verifyIr(g), "");
  EXPECT_FALSE(runPassPipeline(g, {.verifyBetweenPasses = true}).has_value());
  EXPECT_EQ(verifyIr(g, {.canonicalOrder = true}), "");
}

TEST(IrVerifier, CatchesAnOperandNamingALaterNode) {
  IrGraph g = sampleIr();
  std::uint32_t multiply = nodeOf(g, "multiply");
  g.nodes[0].inputs.push_back(Operand::ofNode(multiply, 0, ValueType::Vec2));  // texcoord has no ports
  EXPECT_NE(violationIn(g).find("operands"), std::string::npos);
  g = sampleIr();
  std::uint32_t sample = nodeOf(g, "sample");
  g.nodes[multiply].inputs[0] = Operand::ofNode(sample, 0, g.nodes[sample].outputType(0));
  EXPECT_NE(violationIn(g).find("not before it"), std::string::npos);
}

TEST(IrVerifier, CatchesASelfReference) {
  IrGraph g = sampleIr();
  std::uint32_t multiply = nodeOf(g, "multiply");
  g.nodes[multiply].inputs[0] = Operand::ofNode(multiply, 0, ValueType::Vec2);
  EXPECT_NE(violationIn(g).find("not before it"), std::string::npos);
}

TEST(IrVerifier, CatchesAnOutputBindingToAMissingNode) {
  IrGraph g = sampleIr();
  g.output(PbrField::BaseColor) = Operand::ofNode(99, 0, ValueType::Vec3);
  std::string problem = violationIn(g);
  EXPECT_NE(problem.find("baseColor"), std::string::npos) << problem;
  EXPECT_NE(problem.find("does not exist"), std::string::npos) << problem;
}

TEST(IrVerifier, CatchesAnOutputIndexTheSourceLacks) {
  IrGraph g = sampleIr();
  g.output(PbrField::Roughness).output = 9;
  EXPECT_NE(violationIn(g).find("which it does not have"), std::string::npos);
}

TEST(IrVerifier, CatchesAnOperandClaimingTheWrongType) {
  IrGraph g = sampleIr();
  g.nodes[nodeOf(g, "multiply")].inputs[0].type = ValueType::Vec4;
  EXPECT_NE(violationIn(g).find("claims vec4"), std::string::npos);
  g = sampleIr();
  g.nodes[nodeOf(g, "multiply")].inputs[1] = Operand{Operand::Kind::Constant, 0, 0, Value::scalar(1), -1, ValueType::Vec3};
  EXPECT_NE(violationIn(g).find("constant"), std::string::npos);
}

TEST(IrVerifier, CatchesAnOperandItsPortCannotTake) {
  IrGraph g = sampleIr();
  g.nodes[nodeOf(g, "multiply")].inputs[1] = Operand::ofConstant(Value::vec3(1, 2, 3));  // vec3 into a vec2 port
  EXPECT_NE(violationIn(g).find("port"), std::string::npos);
}

TEST(IrVerifier, CatchesPortTypesOffTheSignature) {
  IrGraph g = sampleIr();
  std::uint32_t sample = nodeOf(g, "sample");
  g.nodes[sample].inputs[1] = Operand::ofConstant(Value::vec3(0, 0, 0));
  g.nodes[sample].inputTypes[1] = ValueType::Vec3;  // uv is vec2
  EXPECT_NE(violationIn(g).find("signature"), std::string::npos);
  g = sampleIr();
  g.nodes[nodeOf(g, "multiply")].inputTypes[1] = ValueType::Vec3;  // generic ports differ
  EXPECT_NE(violationIn(g).find("generic"), std::string::npos);
}

TEST(IrVerifier, CatchesAValueTypeOffTheOpsRule) {
  IrGraph g = sampleIr();
  g.nodes[nodeOf(g, "swizzle")].valueType = ValueType::Vec2;  // three channels
  EXPECT_NE(violationIn(g).find("rule"), std::string::npos);
  g = sampleIr();
  g.nodes[nodeOf(g, "multiply")].valueType = ValueType::Vec4;
  EXPECT_NE(violationIn(g).find("rule"), std::string::npos);
}

TEST(IrVerifier, CatchesUndeclaredParametersAndTextures) {
  IrGraph g = sampleIr();
  g.nodes[nodeOf(g, "parameter")].parameter = 5;
  EXPECT_NE(violationIn(g).find("not declared"), std::string::npos);
  g = sampleIr();
  g.nodes[nodeOf(g, "multiply")].parameter = 0;
  EXPECT_NE(violationIn(g).find("parameter"), std::string::npos);
  g = sampleIr();
  g.nodes[nodeOf(g, "sample")].inputs[0] = Operand::ofTexture(3);
  EXPECT_NE(violationIn(g).find("texture 3"), std::string::npos);
}

TEST(IrVerifier, CatchesAnOutputOfTheWrongType) {
  IrGraph g = sampleIr();
  g.output(PbrField::Roughness) = Operand::ofConstant(Value::boolean(true));
  EXPECT_NE(violationIn(g).find("roughness"), std::string::npos);
}

TEST(IrVerifier, CatchesAMissingOp) {
  IrGraph g = sampleIr();
  g.nodes[0].op = nullptr;
  EXPECT_NE(violationIn(g).find("no op"), std::string::npos);
}

TEST(IrVerifier, CatchesABrokenCanonicalOrderAndUnreachableNodes) {
  IrGraph g = sampleIr();
  ASSERT_FALSE(runPassPipeline(g, {.verifyBetweenPasses = true}).has_value());
  IrGraph unreachable = g;
  unreachable.nodes.push_back(unreachable.nodes.front());  // a second texcoord no output reads
  EXPECT_EQ(verifyIr(unreachable), "");  // fine before topo-order
  EXPECT_NE(violationIn(unreachable, {.canonicalOrder = true}).find("unreachable"), std::string::npos);
  // texcoord and the parameter are independent: swapping them keeps a valid
  // topological order but not the canonical one.
  ASSERT_EQ(g.nodes[0].op->name, "texcoord");
  ASSERT_EQ(g.nodes[1].op->name, "parameter");
  std::swap(g.nodes[0], g.nodes[1]);
  for (auto& node : g.nodes)
    for (auto& operand : node.inputs)
      if (operand.kind == Operand::Kind::Node && operand.node < 2) operand.node = 1 - operand.node;
  EXPECT_EQ(verifyIr(g), "");
  EXPECT_NE(violationIn(g, {.canonicalOrder = true}).find("canonical order"), std::string::npos);
}

TEST(PassPipelineVerification, NamesThePassAfterWhichTheIrBroke) {
  IrGraph g = sampleIr();
  PassPipelineOptions options{.verifyBetweenPasses = true};
  // The observer sees the IR before it is verified; breaking it there stands in for a buggy pass.
  options.afterPass = [](const Pass& pass, const IrGraph& graph) {
    if (pass.name == "cse") const_cast<IrGraph&>(graph).nodes.back().valueType = ValueType::Bool;
  };
  auto violation = runPassPipeline(g, options);
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->after, "cse");
  EXPECT_FALSE(violation->problem.empty());
}

TEST(PassPipelineVerification, ChecksTheBuiltIrBeforeTheFirstPass) {
  IrGraph g = sampleIr();
  g.nodes[0].op = nullptr;
  auto violation = runPassPipeline(g, {.verifyBetweenPasses = true});
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->after, kIrBuilderStep);
}

TEST(PassPipelineVerification, IsOffUnlessAskedInReleaseBuilds) {
  IrGraph g = sampleIr();
  g.output(PbrField::Roughness) = Operand::ofConstant(Value::boolean(true));
  EXPECT_EQ(runPassPipeline(g, {.verifyBetweenPasses = false}).has_value(), false);
#ifdef NDEBUG
  EXPECT_FALSE(kVerifyIrBetweenPassesByDefault);
#else
  EXPECT_TRUE(kVerifyIrBetweenPassesByDefault);
#endif
}

TEST(PassPipelineVerification, AViolationIsAnInternalDiagnosticNamingThePass) {
  CompileOptions options;
  options.passes.verifyBetweenPasses = true;
  options.passes.afterPass = [](const Pass& pass, const IrGraph& graph) {
    if (pass.name == "constant-fold")
      const_cast<IrGraph&>(graph).output(PbrField::Metallic) = Operand::ofNode(1000, 0, ValueType::Float);
  };
  DiagnosticList diagnostics;
  auto ir = buildOptimizedIr("t.json", graphJson(R"({"id": "uv", "op": "texcoord"},
                                                       {"id": "n", "op": "value_noise", "inputs": {"p": "uv.out"}})",
                                                    R"("roughness": "n.out")"),
                             diagnostics, options);
  EXPECT_FALSE(ir.has_value());
  ASSERT_TRUE(diagnostics.contains(DiagCode::InternalIrInvalid))
      << (diagnostics.empty() ? "no diagnostic" : formatDiagnosticText(diagnostics.items().front()));
  const Diagnostic& d = diagnostics.items().front();
  EXPECT_EQ(d.info().category, DiagCategory::Internal);
  EXPECT_NE(d.message.find("'constant-fold'"), std::string::npos) << d.message;
}

// Every bundled graph, every variant, with the IR checked after each pass.
TEST(PassPipelineVerification, EveryBundledGraphAndVariantHoldsTheInvariants) {
  namespace fs = std::filesystem;
  int compiled = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(WG_SOURCE_DIR) / "graphs")) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    DiagnosticList loadDiagnostics;
    auto document = parseJsonDocument(entry.path().string(), text.str(), loadDiagnostics);
    ASSERT_TRUE(document.has_value()) << entry.path();
    auto graph = loadMaterialGraph(*document, loadDiagnostics);
    ASSERT_TRUE(graph.has_value()) << entry.path();
    std::string error;
    auto variants = enumerateVariants(graph->switches, VariantSelection{.all = true}, error);
    ASSERT_EQ(error, "") << entry.path();
    for (const auto& switches : variants) {
      CompileOptions options;
      options.switches = switches;
      options.passes.verifyBetweenPasses = true;
      DiagnosticList diagnostics;
      auto ir = buildOptimizedIr(entry.path().string(), text.str(), diagnostics, options);
      EXPECT_TRUE(ir.has_value()) << entry.path() << " [" << variantName(switches) << "]";
      for (const auto& d : diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
      ++compiled;
    }
  }
  EXPECT_GE(compiled, 8);
}

}  // namespace
}  // namespace wg
