// Texture settings for imported materials: "colorSpace" (sRGB decoded before
// filtering), per-axis "wrap" and separate min/mag "filter". Each is loaded, reported in
// the reflection, changes what the CPU sampler returns, and is refused when malformed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "compiler/content_hash.hpp"
#include "compiler/cpu_evaluator.hpp"
#include "driver/material_compiler.hpp"
#include "nodes/srgb_transfer.hpp"
#include "host/image/png_file.hpp"

namespace wg {
namespace {

using json = nlohmann::json;

// IEC 61966-2-1 in double precision, the reference for the table.
double srgbReference(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

TEST(SrgbTransfer, TableFollowsTheIecCurveForEveryByte) {
  for (int byte = 0; byte < 256; ++byte)
    EXPECT_EQ(decodeSrgb8(static_cast<std::uint8_t>(byte)), static_cast<float>(srgbReference(byte / 255.0))) << byte;
  EXPECT_EQ(decodeSrgb8(0), 0.f);
  EXPECT_EQ(decodeSrgb8(255), 1.f);
  EXPECT_NEAR(decodeSrgb8(10), 0.0030353f, 1e-7f);   // the linear toe: (10/255) / 12.92
  EXPECT_NEAR(decodeSrgb8(188), 0.5028865f, 1e-6f);  // the power curve
  EXPECT_NEAR(srgbToLinear(0.5f), 0.2140411f, 1e-6f);
}

// One row of two texels: red 64 and 200, green 0 and 255, blue 128, alpha 51 (0.2).
Image twoTexels() {
  Image image = Image::blank(2, 1);
  const std::uint8_t texels[8] = {64, 0, 128, 51, 200, 255, 128, 51};
  std::copy(std::begin(texels), std::end(texels), image.rgba.begin());
  return image;
}

SamplerState srgb(TextureFilter filter) {
  SamplerState s;
  s.colorSpace = ColorSpace::Srgb;
  s.minFilter = s.magFilter = filter;
  return s;
}

TEST(TextureSettingsSampling, SrgbTexelsAreDecodedBeforeBilinearFiltering) {
  const Image image = twoTexels();
  // Texel centres: exactly the decoded bytes; alpha stays linear.
  const Value first = sampleImage(image, 0.25f, 0.5f, srgb(TextureFilter::Linear));
  EXPECT_EQ(first.v[0], decodeSrgb8(64));
  EXPECT_EQ(first.v[1], 0.f);
  EXPECT_EQ(first.v[2], decodeSrgb8(128));
  EXPECT_EQ(first.v[3], decodeUnorm8(51));
  // Halfway between the centres: the mean of the decoded texels, not the decoded mean.
  const Value middle = sampleImage(image, 0.5f, 0.5f, srgb(TextureFilter::Linear));
  EXPECT_FLOAT_EQ(middle.v[0], 0.5f * (decodeSrgb8(64) + decodeSrgb8(200)));
  EXPECT_FLOAT_EQ(middle.v[1], 0.5f);
  EXPECT_NE(middle.v[0], srgbToLinear(0.5f * (64 + 200) / 255.f));
  EXPECT_FLOAT_EQ(middle.v[3], decodeUnorm8(51));
  // Nearest: the decoded texel.
  EXPECT_EQ(sampleImage(image, 0.6f, 0.5f, srgb(TextureFilter::Nearest)).v[0], decodeSrgb8(200));
  // Linear data is read as stored.
  EXPECT_EQ(sampleImage(image, 0.6f, 0.5f, TextureWrap::Repeat, TextureFilter::Nearest).v[0], decodeUnorm8(200));
}

// 2x2 with red = 10 * (1 + x + 2y): texel (x, y) is recognisable by its red byte.
Image fourTexels() {
  Image image = Image::blank(2, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) image.rgba[image.texelOffset(x, y)] = static_cast<std::uint8_t>(10 * (1 + x + 2 * y));
  return image;
}

std::uint8_t redByte(const Value& sample) { return encodeUnorm8(sample.v[0]); }

SamplerState axes(TextureWrap u, TextureWrap v) {
  SamplerState s;
  s.wrapU = u;
  s.wrapV = v;
  s.minFilter = s.magFilter = TextureFilter::Nearest;
  return s;
}

TEST(TextureSettingsSampling, EachAxisWrapsOnItsOwn) {
  const Image image = fourTexels();
  // Texel -1 on both axes: repeat gives texel 1, clamp and mirror texel 0.
  EXPECT_EQ(redByte(sampleImage(image, -0.25f, -0.25f, axes(TextureWrap::Repeat, TextureWrap::Clamp))), 20);  // (1, 0)
  EXPECT_EQ(redByte(sampleImage(image, -0.25f, -0.25f, axes(TextureWrap::Clamp, TextureWrap::Repeat))), 30);  // (0, 1)
  // Texel 2 on both axes: repeat gives 0, clamp 1, mirror 1.
  EXPECT_EQ(redByte(sampleImage(image, 1.25f, 1.25f, axes(TextureWrap::Repeat, TextureWrap::Clamp))), 30);  // (0, 1)
  EXPECT_EQ(redByte(sampleImage(image, 1.25f, 1.25f, axes(TextureWrap::Mirror, TextureWrap::Repeat))), 20);  // (1, 0)
  // Texel 3 (two tiles on): repeat 1, mirror 0.
  EXPECT_EQ(redByte(sampleImage(image, 1.75f, 1.75f, axes(TextureWrap::Repeat, TextureWrap::Mirror))), 20);  // (1, 0)
  // Bilinear at the u seam blends texels 1 and 0 with repeat on u only; v clamps.
  SamplerState linear = axes(TextureWrap::Repeat, TextureWrap::Clamp);
  linear.magFilter = TextureFilter::Linear;
  EXPECT_EQ(redByte(sampleImage(image, 0.f, -3.f, linear)), 15);  // row 0: (20 + 10) / 2
}

TEST(TextureSettingsSampling, LodZeroUsesTheMagnificationFilter) {
  const Image image = fourTexels();
  SamplerState s = axes(TextureWrap::Clamp, TextureWrap::Clamp);
  s.minFilter = TextureFilter::Linear;  // never used: level 0 is magnified
  EXPECT_EQ(redByte(sampleImage(image, 0.5f, 0.25f, s)), 20);
  s.minFilter = TextureFilter::Nearest;
  s.magFilter = TextureFilter::Linear;
  EXPECT_EQ(redByte(sampleImage(image, 0.5f, 0.25f, s)), 15);
  // The evaluator's sampler keeps each texture's state.
  TextureSampler sampler;
  sampler.images = {image};
  sampler.states = {s};
  EXPECT_EQ(redByte(sampler.sample(0, 0.5f, 0.25f)), 15);
}

// ---- Graph files -----------------------------------------------------------------

class TextureSettingsGraph : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("wg_texture_settings_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    ASSERT_EQ(image::writePng((dir_ / "two.png").string(), twoTexels()), "");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // A graph sampling `texture` (the body of its declaration) at texcoord 0.
  std::string graph(const std::string& texture) const {
    return R"({"name": "t", "textures": {"tex": {)" + texture + R"(}},
      "nodes": [{"id": "uv", "op": "texcoord"}, {"id": "s", "op": "sample", "inputs": {"texture": "tex", "uv": "uv.out"}}],
      "output": {"baseColor": "s.rgb"}})";
  }
  std::string file() const { return (dir_ / "t.json").string(); }

  CompileResult compile(const std::string& texture) const {
    CompileOptions options;
    options.emitSpirv = false;
    return compileMaterialText(file(), graph(texture), options);
  }
  json reflectedTexture(const std::string& texture) const {
    CompileResult r = compile(texture);
    for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
    if (!r.material) return json();
    return json::parse(r.material->reflectionJson)["textures"][0];
  }
  std::vector<std::pair<DiagCode, std::string>> diagnostics(const std::string& texture) const {
    std::vector<std::pair<DiagCode, std::string>> out;
    const CompileResult r = compile(texture);
    for (const auto& d : r.diagnostics.items()) out.emplace_back(d.code, d.location.pointer);
    return out;
  }

  std::filesystem::path dir_;
};

TEST_F(TextureSettingsGraph, DefaultsAreReflectedAsBefore) {
  json t = reflectedTexture(R"("file": "two.png")");
  EXPECT_EQ(t["wrap"], "repeat");
  EXPECT_EQ(t["filter"], "linear");
  EXPECT_EQ(t["wrapU"], "repeat");
  EXPECT_EQ(t["wrapV"], "repeat");
  EXPECT_EQ(t["minFilter"], "linear");
  EXPECT_EQ(t["magFilter"], "linear");
  EXPECT_EQ(t["colorSpace"], "linear");
}

TEST_F(TextureSettingsGraph, SettingsAppearInTheReflection) {
  json t = reflectedTexture(R"("file": "two.png", "colorSpace": "srgb", "wrap": ["mirror", "clamp"],
                               "filter": {"min": "nearest", "mag": "linear"})");
  EXPECT_FALSE(t.contains("wrap"));    // the axes differ
  EXPECT_FALSE(t.contains("filter"));  // so do the directions
  EXPECT_EQ(t["wrapU"], "mirror");
  EXPECT_EQ(t["wrapV"], "clamp");
  EXPECT_EQ(t["minFilter"], "nearest");
  EXPECT_EQ(t["magFilter"], "linear");
  EXPECT_EQ(t["colorSpace"], "srgb");
  // Two equal axes and directions are the single-string forms.
  t = reflectedTexture(R"("generator": "fbm", "size": 16, "wrap": ["clamp", "clamp"], "filter": {"mag": "nearest", "min": "nearest"},
                         "colorSpace": "linear")");
  EXPECT_EQ(t["wrap"], "clamp");
  EXPECT_EQ(t["filter"], "nearest");
  // A direction left out is linear.
  t = reflectedTexture(R"("file": "two.png", "filter": {"mag": "nearest"})");
  EXPECT_EQ(t["minFilter"], "linear");
  EXPECT_EQ(t["magFilter"], "nearest");
}

TEST_F(TextureSettingsGraph, ExplicitDefaultsKeepTheContentHash) {
  auto hash = [&](const std::string& texture) {
    CompileResult r = compile(texture);
    return r.material ? r.material->contentHash : std::string("failed");
  };
  const std::string plain = hash(R"("file": "two.png")");
  EXPECT_EQ(hash(R"("file": "two.png", "wrap": ["repeat", "repeat"], "filter": {"min": "linear", "mag": "linear"},
                    "colorSpace": "linear")"),
            plain);
  EXPECT_NE(hash(R"("file": "two.png", "colorSpace": "srgb")"), plain);
  EXPECT_NE(hash(R"("file": "two.png", "wrap": ["repeat", "clamp"])"), plain);
  EXPECT_NE(hash(R"("file": "two.png", "filter": {"min": "nearest"})"), plain);
  EXPECT_NE(hash(R"("file": "two.png", "wrap": ["repeat", "clamp"])"), hash(R"("file": "two.png", "wrap": ["clamp", "repeat"])"));
}

TEST_F(TextureSettingsGraph, CpuEvaluatorDecodesSrgbFiles) {
  auto baseColorAt = [&](const std::string& texture, float u) {
    DiagnosticList diagnostics;
    auto ir = buildOptimizedIr(file(), graph(texture), diagnostics);
    EXPECT_TRUE(ir.has_value());
    EvalInputs in;
    in.surface.texcoord = {u, 0.5f};
    return CpuEvaluator(std::move(*ir)).evaluate(in).output(PbrField::BaseColor);
  };
  EXPECT_EQ(baseColorAt(R"("file": "two.png", "colorSpace": "srgb")", 0.25f).v[0], decodeSrgb8(64));
  EXPECT_EQ(baseColorAt(R"("file": "two.png")", 0.25f).v[0], decodeUnorm8(64));
  EXPECT_FLOAT_EQ(baseColorAt(R"("file": "two.png", "colorSpace": "srgb")", 0.5f).v[0],
                  0.5f * (decodeSrgb8(64) + decodeSrgb8(200)));
  // Per-axis wrap reaches the evaluator: u repeats onto texel 1, v clamps.
  EXPECT_EQ(baseColorAt(R"("file": "two.png", "wrap": ["repeat", "clamp"], "filter": "nearest")", -0.25f).v[0],
            decodeUnorm8(200));
}

TEST_F(TextureSettingsGraph, MalformedSettingsAreRefusedWithTheirPointers) {
  using D = DiagCode;
  const std::string at = "/textures/tex/";
  struct Case {
    std::string texture;
    DiagCode code;
    std::string pointer;
  };
  const Case cases[] = {
      {R"("file": "two.png", "colorSpace": "sRGB")", D::UnknownSamplerValue, at + "colorSpace"},
      {R"("file": "two.png", "colorSpace": true)", D::WrongJsonKind, at + "colorSpace"},
      {R"("generator": "fbm", "colorSpace": "srgb")", D::ProceduralSrgb, at + "colorSpace"},
      {R"("file": "two.png", "wrap": ["repeat"])", D::WrapModeCount, at + "wrap"},
      {R"("file": "two.png", "wrap": ["repeat", "clamp", "mirror"])", D::WrapModeCount, at + "wrap"},
      {R"("file": "two.png", "wrap": ["repeat", "bounce"])", D::UnknownSamplerValue, at + "wrap/1"},
      {R"("file": "two.png", "wrap": [1, "clamp"])", D::WrongJsonKind, at + "wrap/0"},
      {R"("file": "two.png", "wrap": {"u": "clamp"})", D::WrongJsonKind, at + "wrap"},
      {R"("file": "two.png", "filter": {"min": "cubic"})", D::UnknownSamplerValue, at + "filter/min"},
      {R"("file": "two.png", "filter": {"max": "linear"})", D::UnknownField, at + "filter/max"},
      {R"("file": "two.png", "filter": ["linear", "nearest"])", D::WrongJsonKind, at + "filter"},
      {R"("file": "two.png", "filter": {"mag": 1})", D::WrongJsonKind, at + "filter/mag"},
  };
  for (const auto& c : cases)
    EXPECT_EQ(diagnostics(c.texture), (std::vector<std::pair<DiagCode, std::string>>{{c.code, c.pointer}})) << c.texture;
  // A procedural texture may say it is linear.
  EXPECT_TRUE(diagnostics(R"("generator": "fbm", "size": 16, "colorSpace": "linear")").empty());
}

}  // namespace
}  // namespace wg
