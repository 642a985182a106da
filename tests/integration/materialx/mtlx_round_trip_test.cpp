// A glTF material and the equivalent gltf_pbr document give graphs that evaluate
// identically, dry and under weather.
#include <gtest/gtest.h>

#include "mtlx_test_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;

constexpr const char* kGltf = R"({
  "asset": {"version": "2.0"},
  "materials": [
    {"name": "Painted",
     "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.3, 0.1, 0.6], "metallicFactor": 0.25, "roughnessFactor": 0.7},
     "emissiveFactor": [0.2, 0.1, 0.05], "alphaMode": "BLEND"},
    {"name": "Steel", "pbrMetallicRoughness": {"baseColorFactor": [0.56, 0.57, 0.58, 1], "roughnessFactor": 0.35}}
  ]
})";

constexpr const char* kMaterialX = R"(<?xml version="1.0"?>
<materialx version="1.39" colorspace="lin_rec709">
  <gltf_pbr name="SR_painted" type="surfaceshader">
    <input name="base_color" type="color3" value="0.8, 0.3, 0.1" />
    <input name="metallic" type="float" value="0.25" />
    <input name="roughness" type="float" value="0.7" />
    <input name="emissive" type="color3" value="0.2, 0.1, 0.05" />
    <input name="alpha" type="float" value="0.6" />
    <input name="alpha_mode" type="integer" value="2" />
  </gltf_pbr>
  <surfacematerial name="Painted" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_painted" />
  </surfacematerial>
  <gltf_pbr name="SR_steel" type="surfaceshader">
    <input name="base_color" type="color3" value="0.56, 0.57, 0.58" />
    <input name="roughness" type="float" value="0.35" />
  </gltf_pbr>
  <surfacematerial name="Steel" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_steel" />
  </surfacematerial>
</materialx>
)";

TEST(MaterialXRoundTrip, GltfAndGltfPbrGraphsEvaluateIdentically) {
  TempDir dir("mtlx-round-trip");
  writeFile(dir.path() / "model.gltf", kGltf);
  writeFile(dir.path() / "model.mtlx", kMaterialX);
  CommandResult gltf = runCommand(shellQuote(WG_CLI_PATH) + " import -q " + shellQuote((dir.path() / "model.gltf").string()) +
                                  " -o " + shellQuote((dir.path() / "gltf").string()) + " 2>&1");
  ASSERT_EQ(gltf.exitCode, 0) << gltf.output;
  ImportResult mtlx = importDocument(dir.path() / "model.mtlx", dir.path() / "mtlx");
  ASSERT_EQ(mtlx.exitCode, 0) << mtlx.output;
  const std::string kConditions[] = {"", "--weather snowLevel=1,temperature=-5", "--weather wetnessLevel=0.8,puddleLevel=0.5,precipitation=1"};
  for (const char* name : {"model_Painted.json", "model_Steel.json"})
    for (const auto& weather : kConditions)
      for (const char* at : {"texcoord=0.2:0.7", "texcoord=0.9:0.1,normal=0:0.7:0.7"}) {
        SCOPED_TRACE(std::string(name) + " " + weather + " " + at);
        auto fromGltf = evalOutputs(dir.path() / "gltf" / name, at, weather, "rock");
        auto fromMtlx = evalOutputs(dir.path() / "mtlx" / name, at, weather, "rock");
        ASSERT_TRUE(fromGltf.is_object());
        EXPECT_EQ(fromGltf, fromMtlx) << "glTF: " << fromGltf.dump() << "\nMaterialX: " << fromMtlx.dump();
      }
}

}  // namespace
}  // namespace wg::testing
