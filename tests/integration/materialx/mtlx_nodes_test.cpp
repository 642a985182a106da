// Single MaterialX nodes through import and the CPU evaluator: each feeds a
// standard_surface's base_color, and the evaluated colour is what MaterialX's node
// definition gives (docs/materialx-import.md, the node table).
#include <gtest/gtest.h>

#include "mtlx_test_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;

struct NodeCase {
  const char* name;
  const char* nodes;  // elements; the node named "out" (color3) feeds base_color
  const char* at;     // eval's --at
  std::array<double, 3> want;
};

const NodeCase kCases[] = {
    {"geompropvalue_and_geomcolor",
     R"(<geompropvalue name="uv" type="vector2"><input name="geomprop" type="string" value="UV0" /></geompropvalue>
        <geomcolor name="cd" type="color3" />
        <extract name="v" type="float"><input name="in" type="vector2" nodename="uv" /><input name="index" type="integer" value="1" /></extract>
        <multiply name="out" type="color3"><input name="in1" type="color3" nodename="cd" /><input name="in2" type="float" nodename="v" /></multiply>)",
     "texcoord=0.2:0.3,vertexColor=0.5:1:0.25:1", {0.35, 0.7, 0.175}},  // MaterialX's v runs up: 1 - 0.3
    {"ifgreater",
     R"(<ifgreater name="out" type="color3"><input name="value1" type="float" value="0.6" /><input name="value2" type="float" value="0.5" />
          <input name="in1" type="color3" value="1, 0, 0" /><input name="in2" type="color3" value="0, 1, 0" /></ifgreater>)",
     "", {1, 0, 0}},
    {"ifgreatereq_equal",
     R"(<ifgreatereq name="out" type="color3"><input name="value1" type="float" value="0.5" /><input name="value2" type="float" value="0.5" />
          <input name="in1" type="color3" value="1, 0, 0" /><input name="in2" type="color3" value="0, 1, 0" /></ifgreatereq>)",
     "", {1, 0, 0}},
    {"swizzle",
     R"(<constant name="c" type="color3"><input name="value" type="color3" value="0.1, 0.2, 0.3" /></constant>
        <swizzle name="out" type="color3"><input name="in" type="color3" nodename="c" /><input name="channels" type="string" value="bgr" /></swizzle>)",
     "", {0.3, 0.2, 0.1}},
    {"invert_and_clamp",
     R"(<invert name="i" type="color3"><input name="in" type="color3" value="0.25, 1.5, -1" /></invert>
        <clamp name="out" type="color3"><input name="in" type="color3" nodename="i" /></clamp>)",
     "", {0.75, 0, 1}},
    {"combine_convert_separate",
     R"(<combine3 name="v" type="vector3"><input name="in1" type="float" value="0.2" /><input name="in2" type="float" value="0.4" /><input name="in3" type="float" value="0.6" /></combine3>
        <separate3 name="s" type="multioutput"><input name="in" type="vector3" nodename="v" /></separate3>
        <convert name="g" type="color3"><input name="in" type="float" nodename="s" output="outy" /></convert>
        <mix name="out" type="color3"><input name="fg" type="color3" nodename="g" /><input name="bg" type="color3" value="0, 0, 0" /><input name="mix" type="float" value="0.5" /></mix>)",
     "", {0.2, 0.2, 0.2}},
    {"hsv_round_trip",
     R"(<rgbtohsv name="h" type="color3"><input name="in" type="color3" value="0.2, 0.6, 0.4" /></rgbtohsv>
        <hsvtorgb name="out" type="color3"><input name="in" type="color3" nodename="h" /></hsvtorgb>)",
     "", {0.2, 0.6, 0.4}},
    {"rgbtohsv",  // hue 150 degrees, saturation 2/3, value 0.6
     R"(<rgbtohsv name="out" type="color3"><input name="in" type="color3" value="0.2, 0.6, 0.4" /></rgbtohsv>)", "",
     {150.0 / 360, 2.0 / 3, 0.6}},
    {"place2d_then_texcoord",  // (uv - pivot) / scale - offset + pivot, in MaterialX's v-up uv
     R"(<texcoord name="t" type="vector2" />
        <place2d name="p" type="vector2"><input name="texcoord" type="vector2" nodename="t" /><input name="pivot" type="vector2" value="0.5, 0.5" />
          <input name="scale" type="vector2" value="2, 4" /><input name="offset" type="vector2" value="0.1, 0.2" /></place2d>
        <combine3 name="out" type="color3"><input name="in1" type="float" nodename="px" /><input name="in2" type="float" nodename="py" /></combine3>
        <extract name="px" type="float"><input name="in" type="vector2" nodename="p" /><input name="index" type="integer" value="0" /></extract>
        <extract name="py" type="float"><input name="in" type="vector2" nodename="p" /><input name="index" type="integer" value="1" /></extract>)",
     "texcoord=0.9:0.3", {(0.9 - 0.5) / 2 - 0.1 + 0.5, (0.7 - 0.5) / 4 - 0.2 + 0.5, 0}},
};

class MaterialXNodes : public ::testing::TestWithParam<NodeCase> {};

TEST_P(MaterialXNodes, EvaluatesAsMaterialXDefinesIt) {
  const NodeCase& c = GetParam();
  TempDir dir("mtlx-node");
  writeFile(dir.path() / "node.mtlx", std::string("<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n") + c.nodes +
                                          "\n<standard_surface name=\"SR\" type=\"surfaceshader\"><input name=\"base_color\" "
                                          "type=\"color3\" nodename=\"out\" /></standard_surface>\n"
                                          "<surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                                          "type=\"surfaceshader\" nodename=\"SR\" /></surfacematerial>\n</materialx>\n");
  ImportResult run = importDocument(dir.path() / "node.mtlx", dir.path() / "out");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto got = evalOutputs(dir.path() / "out/node_M.json", c.at);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got["baseColor"][i].get<double>(), c.want[i], 1e-5) << "channel " << i;
}

INSTANTIATE_TEST_SUITE_P(Nodes, MaterialXNodes, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<NodeCase>& info) { return std::string(info.param.name); });

// open_pbr_surface has no example document: its mapping (the table in
// docs/materialx-import.md) checked on one with every mapped input set.
TEST(MaterialXShadingModels, OpenPbrSurfaceMapsAsDocumented) {
  TempDir dir("mtlx-open-pbr");
  writeFile(dir.path() / "open.mtlx", R"(<?xml version="1.0"?>
<materialx version="1.39">
  <open_pbr_surface name="SR" type="surfaceshader">
    <input name="base_weight" type="float" value="0.5" />
    <input name="base_color" type="color3" value="0.8, 0.4, 0.2" />
    <input name="base_metalness" type="float" value="0.3" />
    <input name="specular_roughness" type="float" value="0.4" />
    <input name="specular_ior" type="float" value="1.3" />
    <input name="emission_luminance" type="float" value="2" />
    <input name="emission_color" type="color3" value="0.1, 0.2, 0.3" />
    <input name="geometry_opacity" type="float" value="0.5" />
    <input name="coat_weight" type="float" value="0.5" />
  </open_pbr_surface>
  <surfacematerial name="M" type="material"><input name="surfaceshader" type="surfaceshader" nodename="SR" /></surfacematerial>
</materialx>
)");
  ImportResult run = importDocument(dir.path() / "open.mtlx", dir.path() / "out");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(codesOf(run.diagnostics), std::vector<std::string>{"WG5301"});  // coat_weight
  auto got = evalOutputs(dir.path() / "out/open_M.json");
  const double baseColor[] = {0.4, 0.2, 0.1}, emissive[] = {0.2, 0.4, 0.6};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(got["baseColor"][i].get<double>(), baseColor[i], 1e-6);
    EXPECT_NEAR(got["emissive"][i].get<double>(), emissive[i], 1e-6);
  }
  EXPECT_NEAR(got["metallic"].get<double>(), 0.3, 1e-6);
  EXPECT_NEAR(got["roughness"].get<double>(), 0.4, 1e-6);
  EXPECT_NEAR(got["opacity"].get<double>(), 0.5, 1e-6);
  double f0 = (0.3 / 2.3) * (0.3 / 2.3);  // ((ior - 1) / (ior + 1))^2
  EXPECT_NEAR(got["specular"].get<double>(), f0 / 0.08, 1e-6);
}

}  // namespace
}  // namespace wg::testing
