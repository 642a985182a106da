// Each IR pass on its own, then the whole pipeline's independence from spelling.
#include <gtest/gtest.h>

#include "compiler/content_hash.hpp"
#include "compiler/pass_pipeline.hpp"
#include "nodes/lattice_noise.hpp"
#include "ir_fixture.hpp"

namespace wg {
namespace {

using testing::graphJson;
using testing::irBeforePasses;

int countOps(const IrGraph& g, std::string_view op) {
  int n = 0;
  for (const auto& node : g.nodes) n += node.op->name == op;
  return n;
}

TEST(ConstantFoldPass, FoldsConstantSubgraphsThroughCpuSemantics) {
  IrGraph g = irBeforePasses(graphJson(
      R"({"id": "a", "op": "add", "inputs": {"a": 0.25, "b": 0.5}},
         {"id": "b", "op": "multiply", "inputs": {"a": "a.out", "b": [1, 0.5, 0.25]}})",
      R"("baseColor": "b.out")"));
  ASSERT_EQ(g.nodes.size(), 2u);
  foldConstants(g);
  const Operand& out = g.output(PbrField::BaseColor);
  ASSERT_EQ(out.kind, Operand::Kind::Constant);
  EXPECT_EQ(out.constant, Value::vec3(0.75f, 0.375f, 0.1875f));
}

TEST(ConstantFoldPass, KeepsVaryingAndNonFiniteNodes) {
  IrGraph g = irBeforePasses(graphJson(
      R"({"id": "uv", "op": "texcoord"},
         {"id": "n", "op": "value_noise", "inputs": {"p": "uv.out"}},
         {"id": "inf", "op": "divide", "inputs": {"a": 1, "b": 0}},
         {"id": "m", "op": "multiply", "inputs": {"a": "n.out", "b": "inf.out"}})",
      R"("roughness": "m.out")"));
  foldConstants(g);
  EXPECT_EQ(g.output(PbrField::Roughness).kind, Operand::Kind::Node);
  // 1/0 stays an instruction: folding it would need an infinite literal.
  EXPECT_EQ(g.nodes[3].inputs[1].kind, Operand::Kind::Node);
}

TEST(ConstantFoldPass, FoldsNoiseOfConstantsAndSwizzles) {
  IrGraph g = irBeforePasses(graphJson(
      R"({"id": "n", "op": "value_noise", "inputs": {"p": [3, 5]}},
         {"id": "v", "op": "combine3", "inputs": {"x": "n.out", "y": 1, "z": 2}},
         {"id": "s", "op": "swizzle", "inputs": {"in": "v.out", "channels": "zyx"}})",
      R"("baseColor": "s.out")"));
  foldConstants(g);
  const Operand& out = g.output(PbrField::BaseColor);
  ASSERT_EQ(out.kind, Operand::Kind::Constant);
  EXPECT_FLOAT_EQ(out.constant.v[0], 2.f);
  EXPECT_FLOAT_EQ(out.constant.v[2], valueNoise(3, 5));
}

TEST(AlgebraicSimplifyPass, RemovesIdentitiesButKeepsTypes) {
  IrGraph g = irBeforePasses(graphJson(
      R"({"id": "t", "op": "time"},
         {"id": "same", "op": "lerp", "inputs": {"a": 0.5, "b": 0.5, "t": "t.out"}},
         {"id": "one", "op": "multiply", "inputs": {"a": "t.out", "b": 1}},
         {"id": "zero", "op": "add", "inputs": {"a": 0, "b": "one.out"}},
         {"id": "widen", "op": "multiply", "inputs": {"a": "t.out", "b": [1, 1, 1]}})",
      R"("specular": "same.out", "roughness": "zero.out", "baseColor": "widen.out")"));
  simplifyAlgebra(g);
  EXPECT_EQ(g.output(PbrField::Specular).kind, Operand::Kind::Constant);
  EXPECT_EQ(g.output(PbrField::Specular).constant, Value::scalar(0.5f));
  ASSERT_EQ(g.output(PbrField::Roughness).kind, Operand::Kind::Node);
  EXPECT_EQ(g.nodes[g.output(PbrField::Roughness).node].op->name, "time");
  // float * vec3(1) is a vec3: replacing it by the float would change the output's type.
  EXPECT_EQ(g.nodes[g.output(PbrField::BaseColor).node].op->name, "multiply");
}

TEST(CsePass, MergesStructurallyIdenticalNodes) {
  IrGraph g = irBeforePasses(graphJson(
      R"({"id": "uv1", "op": "texcoord"}, {"id": "uv2", "op": "texcoord"},
         {"id": "n1", "op": "value_noise", "inputs": {"p": "uv1.out", "scale": 4}},
         {"id": "n2", "op": "value_noise", "inputs": {"p": "uv2.out", "scale": 4}},
         {"id": "n3", "op": "value_noise", "inputs": {"p": "uv2.out", "scale": 5}},
         {"id": "sum", "op": "add", "inputs": {"a": "n1.out", "b": "n2.out"}},
         {"id": "all", "op": "add", "inputs": {"a": "sum.out", "b": "n3.out"}})",
      R"("roughness": "all.out")"));
  eliminateCommonSubexpressions(g);
  eliminateDeadNodes(g);
  EXPECT_EQ(countOps(g, "texcoord"), 1);
  EXPECT_EQ(countOps(g, "value_noise"), 2);  // scale 4 merged, scale 5 kept
}

TEST(DeadNodePass, RemovesNodesNoOutputUses) {
  IrGraph g = irBeforePasses(graphJson(
      R"({"id": "uv", "op": "texcoord"}, {"id": "unused", "op": "world_position"},
         {"id": "n", "op": "value_noise", "inputs": {"p": "uv.out"}})",
      R"("roughness": "n.out")"));
  ASSERT_EQ(g.nodes.size(), 3u);
  eliminateDeadNodes(g);
  EXPECT_EQ(g.nodes.size(), 2u);
  EXPECT_EQ(countOps(g, "world_position"), 0);
}

TEST(TopoOrderPass, InputsPrecedeUsersAndOrderFollowsOutputs) {
  IrGraph g = irBeforePasses(graphJson(
      R"({"id": "z", "op": "add", "inputs": {"a": "y.out", "b": "x.out"}},
         {"id": "y", "op": "value_noise", "inputs": {"p": "x.out"}},
         {"id": "x", "op": "time"})",
      R"("roughness": "z.out")"));
  orderTopologically(g);
  ASSERT_EQ(g.nodes.size(), 3u);
  for (std::uint32_t i = 0; i < g.nodes.size(); ++i)
    for (const auto& o : g.nodes[i].inputs) {
      if (o.kind == Operand::Kind::Node) {
        EXPECT_LT(o.node, i);
      }
    }
  EXPECT_EQ(g.nodes[0].op->name, "time");
  EXPECT_EQ(g.nodes[2].op->name, "add");
}

TEST(PassPipeline, IsOneNamedOrderedList) {
  std::vector<std::string_view> names;
  for (const auto& p : passPipeline()) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string_view>{"weather-inject", "constant-fold", "algebraic-simplify", "cse", "dead-node-elim", "topo-order", "vertex-rate"}));
}

TEST(PassPipeline, ResultDependsOnContentNotSpellingOrOrder) {
  std::string a = graphJson(
      R"({"id": "uv", "op": "texcoord"},
         {"id": "noise", "op": "value_noise", "inputs": {"p": "uv.out", "scale": 8}},
         {"id": "tint", "op": "multiply", "inputs": {"a": [0.5, 0.4, 0.3], "b": "noise.out"}})",
      R"("baseColor": "tint.out", "roughness": "noise.out")");
  std::string b = graphJson(
      R"({"id": "Q_tint", "op": "multiply", "inputs": {"b": "zz.out", "a": [0.5, 0.4, 0.3]}},
         {"id": "zz", "op": "value_noise", "inputs": {"scale": 8, "p": "else.out"}},
         {"id": "else", "op": "texcoord"})",
      R"("roughness": "zz.out", "baseColor": "Q_tint.out")");
  IrGraph ga = irBeforePasses(a), gb = irBeforePasses(b);
  runPassPipeline(ga);
  runPassPipeline(gb);
  EXPECT_EQ(contentHash(ga), contentHash(gb));
  ASSERT_EQ(ga.nodes.size(), gb.nodes.size());
  for (std::size_t i = 0; i < ga.nodes.size(); ++i) EXPECT_EQ(ga.nodes[i].op, gb.nodes[i].op);
}

}  // namespace
}  // namespace wg
