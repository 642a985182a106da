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

// Imports DIR/STEM.gltf into DIR/gltf and DIR/STEM.mtlx into DIR/mtlx.
void importBoth(const fs::path& dir, const std::string& stem) {
  CommandResult gltf = runCommand(shellQuote(WG_CLI_PATH) + " import -q " + shellQuote((dir / (stem + ".gltf")).string()) +
                                  " -o " + shellQuote((dir / "gltf").string()) + " 2>&1");
  ASSERT_EQ(gltf.exitCode, 0) << gltf.output;
  ImportResult mtlx = importDocument(dir / (stem + ".mtlx"), dir / "mtlx");
  ASSERT_EQ(mtlx.exitCode, 0) << mtlx.output;
}

TEST(MaterialXRoundTrip, GltfAndGltfPbrGraphsEvaluateIdentically) {
  TempDir dir("mtlx-round-trip");
  writeFile(dir.path() / "model.gltf", kGltf);
  writeFile(dir.path() / "model.mtlx", kMaterialX);
  ASSERT_NO_FATAL_FAILURE(importBoth(dir.path(), "model"));
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

// A textured glTF material and its gltf_pbr form with glTF's image nodes, as MaterialX's
// own glTF translation writes it (gltf_pbr_boombox.mtlx): equal within float rounding
// (the MaterialX uv goes through place2d and two v flips).
constexpr const char* kTexturedGltf = R"({
  "asset": {"version": "2.0"},
  "images": [{"uri": "colour.png"}, {"uri": "orm.png"}, {"uri": "normal.png"}, {"uri": "glow.png"}],
  "textures": [{"source": 0}, {"source": 1}, {"source": 2}, {"source": 3}],
  "materials": [{"name": "Box",
    "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1}},
    "normalTexture": {"index": 2}, "occlusionTexture": {"index": 1},
    "emissiveTexture": {"index": 3}, "emissiveFactor": [1, 1, 1]}]
})";

constexpr const char* kTexturedMaterialX = R"(<?xml version="1.0"?>
<materialx version="1.39" colorspace="lin_rec709">
  <gltf_colorimage name="colour" type="multioutput">
    <input name="file" type="filename" value="colour.png" colorspace="srgb_texture" />
  </gltf_colorimage>
  <gltf_image name="orm" type="vector3"><input name="file" type="filename" value="orm.png" /></gltf_image>
  <gltf_normalmap name="bumps" type="vector3"><input name="file" type="filename" value="normal.png" /></gltf_normalmap>
  <gltf_image name="glow" type="color3"><input name="file" type="filename" value="glow.png" colorspace="srgb_texture" /></gltf_image>
  <separate3 name="channels" type="multioutput"><input name="in" type="vector3" nodename="orm" /></separate3>
  <gltf_pbr name="SR_box" type="surfaceshader">
    <input name="base_color" type="color3" nodename="colour" output="outcolor" />
    <input name="metallic" type="float" nodename="channels" output="outz" />
    <input name="roughness" type="float" nodename="channels" output="outy" />
    <input name="occlusion" type="float" nodename="channels" output="outx" />
    <input name="normal" type="vector3" nodename="bumps" />
    <input name="emissive" type="color3" nodename="glow" />
  </gltf_pbr>
  <surfacematerial name="Box" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_box" />
  </surfacematerial>
</materialx>
)";

TEST(MaterialXRoundTrip, TexturedGltfAndGltfPbrGraphsEvaluateAlike) {
  TempDir dir("mtlx-round-trip-textured");
  writeFile(dir.path() / "box.gltf", kTexturedGltf);
  writeFile(dir.path() / "box.mtlx", kTexturedMaterialX);
  writeStandIn(dir.path() / "colour.png", {{{200, 100, 50}, {20, 40, 60}, {90, 180, 30}, {255, 255, 255}}});
  writeStandIn(dir.path() / "orm.png", {{{255, 128, 0}, {100, 30, 255}, {200, 200, 200}, {10, 250, 128}}});
  writeStandIn(dir.path() / "normal.png", {{{128, 128, 255}, {160, 110, 230}, {100, 150, 240}, {128, 200, 200}}});
  writeStandIn(dir.path() / "glow.png", {{{0, 0, 0}, {255, 0, 0}, {10, 20, 30}, {60, 60, 60}}});
  ASSERT_NO_FATAL_FAILURE(importBoth(dir.path(), "box"));
  for (const char* at : {"texcoord=0.25:0.25", "texcoord=0.75:0.25", "texcoord=0.3:0.8", "texcoord=0.61:0.47"}) {
    SCOPED_TRACE(at);
    auto fromGltf = evalOutputs(dir.path() / "gltf/box_Box.json", at);
    auto fromMtlx = evalOutputs(dir.path() / "mtlx/box_Box.json", at);
    ASSERT_TRUE(fromGltf.is_object() && fromMtlx.is_object());
    for (const auto& [name, value] : fromGltf.items()) {
      std::vector<double> a = value.is_array() ? value.get<std::vector<double>>() : std::vector<double>{value.get<double>()};
      std::vector<double> b = fromMtlx[name].is_array() ? fromMtlx[name].get<std::vector<double>>()
                                                        : std::vector<double>{fromMtlx[name].get<double>()};
      ASSERT_EQ(a.size(), b.size()) << name;
      for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-5) << name << "[" << i << "]";
    }
  }
}

}  // namespace
}  // namespace wg::testing
