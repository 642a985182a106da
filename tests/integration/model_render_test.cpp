// `render --model`: an imported glTF drawn on the stage. A synthetic model whose
// expected albedo is known texel by texel (sRGB texture x baseColorFactor x COLOR_0)
// checks the import's meaning of glTF; Table 4.1 bounds it under full snow; a real
// file from assimp-testmodels renders the same in both backends.
#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "process_support.hpp"
#include "nodes/weather_model.hpp"
#include "host/display_image.hpp"
#include "host/image/image_compare.hpp"
#include "host/image/png_file.hpp"

namespace {

namespace fs = std::filesystem;
using wg::testing::runCommand;
using wg::testing::shellQuote;
using wg::testing::TempDir;

const fs::path kAssimpModels = "/usr/share/assimp/models/glTF2";

float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

// The quad's texture: four sRGB quadrants, row 0 at the top (glTF's uv (0, 0)).
constexpr std::uint8_t kQuadrants[2][2][3] = {{{200, 40, 40}, {40, 200, 40}}, {{40, 40, 200}, {230, 230, 90}}};
constexpr float kFactor[3] = {0.8f, 1.f, 0.9f};
constexpr float kVertexColour[3] = {1.f, 0.75f, 1.f};

std::string base64(const std::string& bytes) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = std::uint8_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= std::uint8_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= std::uint8_t(bytes[i + 2]);
    out += abc[(n >> 18) & 63];
    out += abc[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? abc[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? abc[n & 63] : '=';
  }
  return out;
}

template <typename T>
void append(std::string& buffer, const std::vector<T>& values) {
  buffer.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// A 2 m horizontal quad, 1 m up, facing the sky, textured with the quadrants, plus a
// small untextured foot (the default material) that stands it on the ground. u runs
// along +x and v along +z, so seen from above with -z up the image is upright.
void writeQuadModel(const fs::path& dir) {
  wg::Image texture = wg::Image::blank(2, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      std::uint8_t* t = &texture.rgba[texture.texelOffset(x, y)];
      std::memcpy(t, kQuadrants[y][x], 3);
      t[3] = 255;
    }
  ASSERT_EQ(wg::image::writePng((dir / "quadrants.png").string(), texture), "");
  std::vector<float> positions = {-1, 1, -1, 1, 1, -1, 1, 1, 1, -1, 1, 1, 0, 0, 0, 0.1f, 0.9f, 0, -0.1f, 0.9f, 0};
  std::vector<float> normals = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  std::vector<float> uvs = {0, 0, 1, 0, 1, 1, 0, 1};
  std::vector<float> colours;
  for (int i = 0; i < 4; ++i) colours.insert(colours.end(), {kVertexColour[0], kVertexColour[1], kVertexColour[2], 1.f});
  std::vector<std::uint16_t> indices = {0, 3, 2, 0, 2, 1, 0, 1, 2, 0};  // quad, foot, padding to 4 bytes
  std::string buffer;
  append(buffer, positions);  // 0: 84 bytes (7 vec3)
  append(buffer, normals);    // 84: 84 bytes
  append(buffer, uvs);        // 168: 32 bytes
  append(buffer, colours);    // 200: 64 bytes
  append(buffer, indices);    // 264: 20 bytes
  using J = nlohmann::json;
  J gltf = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", J::array({{{"nodes", {0, 1}}}})},
      {"nodes", J::array({{{"mesh", 0}}, {{"mesh", 1}}})},
      {"meshes", J::array({{{"primitives", J::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}, {"COLOR_0", 3}}},
                                                    {"indices", 4}, {"material", 0}}})}},
                           {{"primitives", J::array({{{"attributes", {{"POSITION", 5}, {"NORMAL", 6}}}, {"indices", 7}}})}}})},
      {"materials", J::array({{{"name", "Quadrants"},
                               {"pbrMetallicRoughness", {{"baseColorFactor", {kFactor[0], kFactor[1], kFactor[2], 1.0}},
                                                         {"baseColorTexture", {{"index", 0}}},
                                                         {"metallicFactor", 0.0}}}}})},
      {"textures", J::array({{{"source", 0}, {"sampler", 0}}})},
      {"samplers", J::array({{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}}})},
      {"images", J::array({{{"uri", "quadrants.png"}}})},
      {"buffers", J::array({{{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}})},
      {"bufferViews", J::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                                {{"buffer", 0}, {"byteOffset", 84}, {"byteLength", 48}},
                                {{"buffer", 0}, {"byteOffset", 168}, {"byteLength", 32}},
                                {{"buffer", 0}, {"byteOffset", 200}, {"byteLength", 64}},
                                {{"buffer", 0}, {"byteOffset", 264}, {"byteLength", 12}},
                                {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 36}},
                                {{"buffer", 0}, {"byteOffset", 132}, {"byteLength", 36}},
                                {{"buffer", 0}, {"byteOffset", 276}, {"byteLength", 6}}})},
      {"accessors", J::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                               {"min", {-1, 1, -1}}, {"max", {1, 1, 1}}},
                              {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                              {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
                              {{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC4"}},
                              {{"bufferView", 4}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
                              {{"bufferView", 5}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                               {"min", {-0.1, 0, 0}}, {"max", {0.1, 0.9, 0}}},
                              {{"bufferView", 6}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                              {{"bufferView", 7}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}})},
  };
  wg::testing::writeFile(dir / "quad.gltf", gltf.dump());
}

struct Rendered {
  int exitCode;
  std::string output;
  wg::Image image;
};

Rendered renderModel(const fs::path& model, const fs::path& png, const std::string& options) {
  auto r = runCommand(wg::testing::kVulkanChildEnvironment + shellQuote(WG_CLI_PATH) + " render --model " + shellQuote(model.string()) + " -o " + shellQuote(png.string()) +
                      " --validation -q " + options);
  Rendered out{r.exitCode, r.output, {}};
  std::string error;
  if (r.exitCode == 0)
    if (auto img = wg::image::readPng(png.string(), error)) out.image = std::move(*img);
  return out;
}

// The linear value of a display (sRGB) pixel.
std::array<float, 3> linearAt(const wg::Image& img, int x, int y) {
  const std::uint8_t* p = &img.rgba[img.texelOffset(x, y)];
  return {srgbToLinear(p[0] / 255.f), srgbToLinear(p[1] / 255.f), srgbToLinear(p[2] / 255.f)};
}

// Looking straight down (orbit elevation 89, azimuth 0: screen up is -z), framed on
// the quad, which fills the middle of the view.
constexpr const char* kTopView = "--camera orbit:0,89,4 --size 96x96";

TEST(ModelRender, AlbedoIsTextureTimesFactorTimesVertexColour) {
  TempDir dir("wg-model-render");
  writeQuadModel(dir.path());
  Rendered r = renderModel(dir.path() / "quad.gltf", dir.path() / "albedo.png", std::string(kTopView) + " --aov albedo --weather-preset none");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_TRUE(r.image.valid());
  // Quadrant centres sit at +-0.5 m; with the quad about 2/3 of the view wide, they are
  // about 1/6 of the image from its centre.
  constexpr float kTolerance = 0.01f;  // linear; 8-bit sRGB storage of the AOV rounds to within it
  int c = r.image.width / 2, d = r.image.width / 6;
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 2; ++col) {
      auto got = linearAt(r.image, c + (col ? d : -d), c + (row ? d : -d));
      for (int k = 0; k < 3; ++k) {
        float expected = srgbToLinear(kQuadrants[row][col][k] / 255.f) * kFactor[k] * kVertexColour[k];
        EXPECT_NEAR(got[k], expected, kTolerance) << "quadrant row " << row << " column " << col << " channel " << k;
      }
    }
}

// Table 4.1: fully covered, up-facing snow reflects 0.90-0.95, whatever lies under it.
TEST(ModelRender, FullSnowOnTheImportedMaterialIsInsideTheMeasuredBand) {
  TempDir dir("wg-model-render");
  writeQuadModel(dir.path());
  Rendered r = renderModel(dir.path() / "quad.gltf", dir.path() / "snow.png",
                           std::string(kTopView) + " --aov albedo --weather snowLevel=1,temperature=-5,precipitation=1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int c = r.image.width / 2, d = r.image.width / 6;
  for (int dy : {-d, d})
    for (int dx : {-d, d}) {
      auto a = linearAt(r.image, c + dx, c + dy);
      float reflectance = wg::weather::reflectance({a[0], a[1], a[2]});
      EXPECT_GE(reflectance, wg::weather::kSnowBand.low - 0.01f) << dx << "," << dy;
      EXPECT_LE(reflectance, wg::weather::kSnowBand.high + 0.01f) << dx << "," << dy;
    }
}

TEST(ModelRender, RealModelRendersTheSameInGlslAndHlsl) {
  fs::path model = kAssimpModels / "BoxTextured-glTF-Binary" / "BoxTextured.glb";
  if (!fs::exists(model)) GTEST_SKIP() << "assimp-testmodels is not installed (scripts/bootstrap.sh installs it)";
  TempDir dir("wg-model-render");
  const std::string weather = " --size 160x90 --weather snowLevel=0.5,wetnessLevel=0.5,temperature=-2";
  Rendered glsl = renderModel(model, dir.path() / "glsl.png", "--backend glsl" + weather);
  Rendered hlsl = renderModel(model, dir.path() / "hlsl.png", "--backend hlsl" + weather);
  ASSERT_EQ(glsl.exitCode, 0) << glsl.output;
  ASSERT_EQ(hlsl.exitCode, 0) << hlsl.output;
  auto diff = wg::image::compareImages(glsl.image, hlsl.image, 0.05);
  EXPECT_LE(diff.meanError, 0.002);  // the cross-backend tolerance of tests/reference/tolerances.json
  EXPECT_LE(double(diff.pixelsOverThreshold) / (160 * 90), 0.005);
}

// A model that cannot be drawn is exit 1 with its code, and no image.
void expectInputError(const std::string& relative, const std::string& code) {
  fs::path model = kAssimpModels / relative;
  if (!fs::exists(model)) GTEST_SKIP() << "assimp-testmodels is not installed (scripts/bootstrap.sh installs it)";
  TempDir dir("wg-model-render");
  Rendered r = renderModel(model, dir.path() / "x.png", "--size 32x32");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find(code), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
}

TEST(ModelRender, ModelWithoutTrianglesIsAnInputError) { expectInputError("TestNoRootNode/SceneWithoutNodes.gltf", "WG5007"); }

TEST(ModelRender, HostileModelIsAnInputErrorNotACrash) { expectInputError("RecursiveNodes/RecursiveNodes.gltf", "WG5006"); }

}  // namespace
