// The graph features a glTF importer needs, rendered on lavapipe with validation on, in
// both backends: sRGB textures read back linear (and agree with the CPU evaluator, with
// per-axis wrap and min/mag filters), a blended material lets what is behind show
// through, doubleSided draws back faces, and texcoord1 reaches the shaders.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "compiler/debug_views.hpp"
#include "driver/material_compiler.hpp"
#include "nodes/srgb_transfer.hpp"
#include "render_support.hpp"
#include "host/image/png_file.hpp"

namespace wg {
namespace {

using namespace testing;
namespace fs = std::filesystem;

#define REQUIRE_VULKAN() \
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)"

constexpr std::uint32_t kWidth = 192, kHeight = 108;
constexpr float kGlassOpacity = 0.5f;
const glm::vec3 kGlassColor{0.1f, 0.3f, 0.9f};
const std::uint8_t kFlatTexel[4] = {188, 128, 64, 255};

std::uint32_t view(std::string_view name) {
  for (const auto& v : kDebugViews)
    if (v.name == name) return v.id;
  throw std::logic_error("no view " + std::string(name));
}

// The graphs, by file stem.
const std::map<std::string, std::string>& graphs() {
  static const std::map<std::string, std::string> kGraphs = {
      {"srgb_flat", R"({"name": "srgb_flat", "textures": {"t": {"file": "flat.png", "colorSpace": "srgb"}},
        "nodes": [{"id": "uv", "op": "texcoord"}, {"id": "s", "op": "sample", "inputs": {"texture": "t", "uv": "uv.out"}}],
        "output": {"baseColor": "s.rgb"}})"},
      {"srgb_ramp", R"({"name": "srgb_ramp",
        "textures": {"t": {"file": "ramp.png", "colorSpace": "srgb", "wrap": ["repeat", "clamp"],
                           "filter": {"min": "nearest", "mag": "linear"}}},
        "nodes": [{"id": "uv", "op": "texcoord"}, {"id": "s", "op": "sample", "inputs": {"texture": "t", "uv": "uv.out"}}],
        "output": {"baseColor": "s.rgb"}})"},
      {"glass", R"({"name": "glass", "nodes": [], "alphaMode": "blend",
        "output": {"baseColor": [0.1, 0.3, 0.9], "opacity": 0.5, "roughness": 0.3}})"},
      {"wall", R"({"name": "wall", "nodes": [], "output": {"baseColor": [0.9, 0.1, 0.1], "emissive": [2.0, 0.0, 0.0]}})"},
      {"one_sided", R"({"name": "one_sided", "nodes": [], "output": {"baseColor": 0.5}})"},
      {"two_sided", R"({"name": "two_sided", "nodes": [], "doubleSided": true, "output": {"baseColor": 0.5}})"},
      {"uv1", R"({"name": "uv1", "nodes": [{"id": "uv", "op": "texcoord1"}, {"id": "s", "op": "split", "inputs": {"in": "uv.out"}},
        {"id": "c", "op": "combine3", "inputs": {"x": "s.x", "y": "s.y"}}], "output": {"baseColor": "c.out"}})"},
  };
  return kGraphs;
}

// A quad in the plane z = centre.z facing +z or -z (`outwardZ`), uv from uvMin at the
// top left to uvMax at the bottom right.
scene::Mesh quad(glm::vec3 centre, glm::vec2 half, float outwardZ, glm::vec2 uvMin = {0.f, 0.f}, glm::vec2 uvMax = {1.f, 1.f}) {
  scene::Mesh m;
  const glm::vec3 normal(0.f, 0.f, outwardZ);
  auto corner = [&](float sx, float sy) {
    glm::vec2 uv = glm::mix(uvMin, uvMax, glm::vec2((sx + 1.f) / 2.f, (1.f - sy) / 2.f));
    return scene::addVertex(m, centre + glm::vec3(sx * half.x, sy * half.y, 0.f), normal, uv);
  };
  std::uint32_t a = corner(-1, -1), b = corner(1, -1), c = corner(1, 1), d = corner(-1, 1);
  scene::addQuadFacing(m, a, b, c, d, normal);
  scene::computeTangents(m);
  return m;
}

// Where each object sits, so that none overlaps another on screen except the glass
// over the wall.
const glm::vec3 kGlass{0.f, 1.2f, 0.f}, kFlat{-2.5f, -1.2f, 0.f}, kRamp{0.f, -1.2f, 0.f};
const glm::vec3 kOneSided{2.5f, -1.2f, 0.f}, kTwoSided{2.5f, 1.2f, 0.f};
const glm::vec3 kUv1{-2.5f, 1.2f, 0.f}, kUv1Fallback{-4.f, 0.f, 0.f};

scene::Scene modesScene() {
  scene::Scene s;
  s.name = "modes";
  auto add = [&](std::string name, std::string graph, scene::Mesh mesh) {
    scene::SceneObject o;
    o.name = std::move(name);
    o.graph = std::move(graph);
    o.mesh = std::move(mesh);
    o.castsShadow = false;
    o.occludesSky = false;
    s.objects.push_back(std::move(o));
  };
  add("wall", "wall", quad({0.f, 1.2f, -1.f}, {1.f, 1.f}, 1.f));
  add("glass", "glass", quad(kGlass, {0.5f, 0.5f}, 1.f));  // before the wall in scene order, drawn after it
  add("flat", "srgb_flat", quad(kFlat, {0.5f, 0.5f}, 1.f));
  add("ramp", "srgb_ramp", quad(kRamp, {0.9f, 0.9f}, 1.f, {-0.5f, -0.5f}, {1.5f, 1.5f}));
  add("oneSided", "one_sided", quad(kOneSided, {0.5f, 0.5f}, -1.f));
  add("twoSided", "two_sided", quad(kTwoSided, {0.5f, 0.5f}, -1.f));
  scene::Mesh withSecondSet = quad(kUv1, {0.5f, 0.5f}, 1.f);
  for (const auto& uv : withSecondSet.texcoords) withSecondSet.texcoords1.push_back({0.25f + 0.5f * uv.x, 1.f - uv.y});
  add("uv1", "uv1", std::move(withSecondSet));
  add("uv1Fallback", "uv1", quad(kUv1Fallback, {0.4f, 0.4f}, 1.f));
  std::swap(s.objects[0], s.objects[1]);
  s.cameras.push_back({"front", {0.f, 0.f, 6.f}, {0.f, 0.f, 0.f}, 50.f});
  s.towardsSun = glm::normalize(glm::vec3(0.3f, 1.f, 0.6f));
  scene::Bounds b;
  for (const auto& o : s.objects) b.include(scene::bounds(o.mesh));
  s.boundsMin = b.min;
  s.boundsMax = b.max;
  return s;
}

// Graphs and images in a temporary directory, and one renderer for every test.
class MaterialModesRender : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!renderContext()) return;
    dir_ = fs::temp_directory_path() / ("wg_material_modes_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    for (const auto& [stem, text] : graphs()) std::ofstream(dir_ / (stem + ".json")) << text;
    Image flat = Image::blank(1, 1);
    std::copy(std::begin(kFlatTexel), std::end(kFlatTexel), flat.rgba.begin());
    ASSERT_EQ(image::writePng((dir_ / "flat.png").string(), flat), "");
    ASSERT_EQ(image::writePng((dir_ / "ramp.png").string(), ramp()), "");
    renderer_ = std::make_unique<SceneRenderer>(*renderContext(), modesScene(), dir_.string());
  }
  static void TearDownTestSuite() {
    renderer_.reset();
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // 2x2 with strong contrasts, where filtering decoded texels differs most from
  // decoding filtered ones: red 0 and 255 on top, 64 and 200 below; green the inverse.
  static Image ramp() {
    Image image = Image::blank(2, 2);
    image.rgba = {0, 255, 128, 255, 255, 0, 128, 255, 64, 191, 128, 255, 200, 55, 128, 255};
    return image;
  }

  static RenderedFrame render(ShaderLanguage backend, std::string_view aov, const std::string& only = "") {
    RenderRequest r;
    r.width = kWidth;
    r.height = kHeight;
    r.backend = backend;
    r.debugView = view(aov);
    r.weather = weatherFor(renderer_->scene());
    r.shadows = false;
    r.onlyObject = only;
    RenderedFrame frame = renderer_->render(r);
    expectNoValidationMessages();
    return frame;
  }

  static glm::ivec2 at(glm::vec3 world) {
    auto p = project(renderer_->viewProjection("front", kWidth, kHeight), world, kWidth, kHeight);
    EXPECT_TRUE(p.has_value());
    return p.value_or(glm::ivec2(0));
  }
  static glm::vec4 pixelAt(const RenderedFrame& frame, glm::vec3 world) {
    glm::ivec2 p = at(world);
    return pixel(frame, p.x, p.y);
  }

  static CpuEvaluator evaluator(const std::string& stem) {
    DiagnosticList diagnostics;
    std::string path = (dir_ / (stem + ".json")).string();
    auto ir = buildOptimizedIr(path, graphs().at(stem), diagnostics);
    if (!ir) throw std::runtime_error("cannot compile " + path);
    return CpuEvaluator(std::move(*ir));
  }

  static inline fs::path dir_;
  static inline std::unique_ptr<SceneRenderer> renderer_;
};

constexpr ShaderLanguage kBackends[] = {ShaderLanguage::Glsl, ShaderLanguage::Hlsl};

TEST_F(MaterialModesRender, SrgbTextureReadsBackAsTheLinearValue) {
  REQUIRE_VULKAN();
  constexpr float kDecodeTolerance = 2e-3f;  // drivers may decode sRGB a little inexactly
  for (ShaderLanguage backend : kBackends) {
    SCOPED_TRACE(std::string(languageName(backend)));
    glm::vec4 albedo = pixelAt(render(backend, "albedo", "flat"), kFlat);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(albedo[c], decodeSrgb8(kFlatTexel[c]), kDecodeTolerance) << "channel " << c;
      EXPECT_GT(std::fabs(albedo[c] - decodeUnorm8(kFlatTexel[c])), 0.05f) << "read as linear data";
    }
    EXPECT_EQ(albedo.a, 1.f);
  }
}

// Every pixel of the ramp against the CPU evaluator at the read-back texcoord: sRGB
// decoded before filtering, u repeating and v clamping over uv -0.5..1.5, and the
// magnification filter (linear) rather than the minification one (nearest).
TEST_F(MaterialModesRender, SrgbPerAxisWrapAndFiltersAgreeWithTheCpuEvaluator) {
  REQUIRE_VULKAN();
  constexpr float kTolerance = 0.01f;  // 8-bit filter weights and the sRGB decode
  const CpuEvaluator cpu = evaluator("srgb_ramp");
  for (ShaderLanguage backend : kBackends) {
    SCOPED_TRACE(std::string(languageName(backend)));
    RenderedFrame albedo = render(backend, "albedo", "ramp"), uv = render(backend, "texcoord", "ramp");
    std::size_t compared = 0, within = 0;
    float worst = 0.f;
    for (int y = 0; y < int(kHeight); ++y)
      for (int x = 0; x < int(kWidth); ++x) {
        if (!isSurface(albedo, x, y)) continue;
        EvalInputs in;
        in.surface.texcoord = {pixel(uv, x, y).x, pixel(uv, x, y).y};
        const Value expected = cpu.evaluate(in).output(PbrField::BaseColor);
        for (int c = 0; c < 3; ++c) {
          float e = std::fabs(pixel(albedo, x, y)[c] - expected.v[c]);
          worst = std::max(worst, e);
          ++compared;
          within += e <= kTolerance;
        }
      }
    ASSERT_GE(compared, 3u * 400u);
    EXPECT_GE(double(within) / compared, 0.99) << "worst " << worst;
  }
}

TEST_F(MaterialModesRender, BlendedMaterialLetsTheBackgroundShowThrough) {
  REQUIRE_VULKAN();
  for (ShaderLanguage backend : kBackends) {
    SCOPED_TRACE(std::string(languageName(backend)));
    RenderedFrame glassOnly = render(backend, "lit", "glass"), wallOnly = render(backend, "lit", "wall");
    RenderedFrame both = render(backend, "lit");
    const glm::vec4 sky = pixel(glassOnly, 0, 0);
    const glm::vec4 overSky = pixelAt(glassOnly, kGlass), wall = pixelAt(wallOnly, kGlass), overWall = pixelAt(both, kGlass);
    // Straight alpha "over": glass * a + behind * (1 - a), so swapping the sky for the
    // wall behind changes the pixel by (1 - a) * (wall - sky).
    // The lit colour target is RGBA16F: each of the four values is rounded to half a
    // step of 2^-11 near 0.5, so the identity holds to about 1e-3.
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(overWall[c], overSky[c] + (1.f - kGlassOpacity) * (wall[c] - sky[c]), 1e-3f) << "channel " << c;
    EXPECT_GT(overWall.r - overSky.r, 0.1f) << "the red wall shows through";
    EXPECT_NE(overSky, sky);  // and the glass is there
    EXPECT_FLOAT_EQ(overWall.a, 1.f);
    // AOVs draw the glass opaque: its own albedo, readable alpha.
    glm::vec4 albedo = pixelAt(render(backend, "albedo"), kGlass);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(albedo[c], kGlassColor[c]);
    EXPECT_EQ(albedo.a, 1.f);
  }
}

TEST_F(MaterialModesRender, DoubleSidedDrawsBackFacesWithTheNormalFlipped) {
  REQUIRE_VULKAN();
  for (ShaderLanguage backend : kBackends) {
    SCOPED_TRACE(std::string(languageName(backend)));
    RenderedFrame albedo = render(backend, "albedo");
    EXPECT_EQ(pixelAt(albedo, kOneSided).a, 0.f) << "a single-sided back face is culled";
    EXPECT_EQ(pixelAt(albedo, kTwoSided), glm::vec4(0.5f, 0.5f, 0.5f, 1.f));
    // The mesh normal is -z, away from the camera; the shaded one faces it.
    EXPECT_NEAR(pixelAt(render(backend, "geometricNormal", "twoSided"), kTwoSided).z, 1.f, 1e-5f);
  }
}

TEST_F(MaterialModesRender, Texcoord1ReadsTheSecondSetOrTheFirstWhenTheMeshHasNone) {
  REQUIRE_VULKAN();
  for (ShaderLanguage backend : kBackends) {
    SCOPED_TRACE(std::string(languageName(backend)));
    RenderedFrame albedo = render(backend, "albedo"), uv = render(backend, "texcoord");
    glm::vec4 first = pixelAt(uv, kUv1), second = pixelAt(albedo, kUv1);
    EXPECT_NEAR(second.x, 0.25f + 0.5f * first.x, 1e-5f);
    EXPECT_NEAR(second.y, 1.f - first.y, 1e-5f);
    glm::vec4 fallbackUv = pixelAt(uv, kUv1Fallback), fallback = pixelAt(albedo, kUv1Fallback);
    EXPECT_NEAR(fallback.x, fallbackUv.x, 1e-6f);
    EXPECT_NEAR(fallback.y, fallbackUv.y, 1e-6f);
  }
}

}  // namespace
}  // namespace wg
