// The MaterialX project's example documents (WEATHERGEN_MATERIALX_EXAMPLES): each imports
// and every graph compiles in both languages through the independent validators; constant materials evaluate to the
// documented mapping of their values; the brick, marble and wood node graphs evaluate to
// what the mapping predicts (with stand-in images).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <pugixml.hpp>
#include <regex>
#include <set>

#include "mtlx_test_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Texels = std::array<std::array<unsigned char, 3>, 4>;

const fs::path kExamples = WG_MATERIALX_EXAMPLES;

std::vector<fs::path> documents() {
  std::vector<fs::path> found;
  for (const char* folder : {"StandardSurface", "UsdPreviewSurface", "GltfPbr"})
    for (const auto& name : listFiles(kExamples / folder))
      if (name.ends_with(".mtlx")) found.push_back(kExamples / folder / name);
  return found;
}

// Distinct texels per image, so a wrong wire shows: from the name's bytes.
Texels standInTexels(const std::string& name) {
  static const std::map<std::string, Texels> kChosen = {
      {"brick_base_gray.jpg", {{{180, 180, 180}, {90, 90, 90}, {230, 230, 230}, {40, 40, 40}}}},
      {"brick_dirt_mask.jpg", {{{30, 30, 30}, {200, 200, 200}, {0, 0, 0}, {255, 255, 255}}}},
      {"brick_mask.jpg", {{{255, 255, 255}, {0, 0, 0}, {128, 128, 128}, {64, 64, 64}}}},
      {"brick_normal.jpg", {{{128, 128, 255}, {160, 110, 230}, {100, 150, 240}, {128, 200, 200}}}},
      {"brick_roughness.jpg", {{{100, 100, 100}, {220, 220, 220}, {10, 10, 10}, {150, 150, 150}}}},
      {"brick_variation_mask.jpg", {{{50, 50, 50}, {250, 250, 250}, {120, 120, 120}, {5, 5, 5}}}},
      {"wood_color.jpg", {{{150, 90, 40}, {120, 70, 30}, {200, 140, 80}, {60, 30, 10}}}},
      {"wood_roughness.jpg", {{{90, 90, 90}, {160, 160, 160}, {40, 40, 40}, {250, 250, 250}}}},
  };
  if (auto it = kChosen.find(name); it != kChosen.end()) return it->second;
  Texels t{};
  for (std::size_t i = 0; i < name.size(); ++i) t[i % 4][i % 3] = static_cast<unsigned char>(t[i % 4][i % 3] * 31 + name[i]);
  return t;
}

// Stand-ins for every image any example names, in one search-path folder.
class MaterialXExamples : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir("mtlx-examples");
    fs::create_directories(images());
    std::regex file(R"re(type="filename" value="([^"]+)")re");
    std::set<std::string> names;
    for (const auto& doc : documents()) {
      std::string text = readFile(doc);
      for (std::sregex_iterator it(text.begin(), text.end(), file), end; it != end; ++it) names.insert((*it)[1]);
    }
    for (const auto& name : names) writeStandIn(images() / name, standInTexels(name));
  }
  static void TearDownTestSuite() { delete dir_; }
  static fs::path images() { return dir_->path() / "images"; }
  static fs::path work() { return dir_->path(); }

  // Imports `document` with the stand-ins; the folder of its graphs.
  static fs::path imported(const fs::path& document) {
    fs::path out = work() / ("out-" + document.stem().string());
    if (!fs::exists(out)) {
      ImportResult run = importDocument(document, out, "--search-path " + shellQuote(images().string()));
      EXPECT_EQ(run.exitCode, 0) << document << ":\n" << run.output;
    }
    return out;
  }

  static TempDir* dir_;
};
TempDir* MaterialXExamples::dir_ = nullptr;

TEST_F(MaterialXExamples, EveryDocumentImportsAndCompiles) {
  auto docs = documents();
  ASSERT_GE(docs.size(), 30u) << "the example folders are incomplete";
  for (const auto& doc : docs) {
    SCOPED_TRACE(doc.filename().string());
    fs::path out = work() / ("check-" + doc.stem().string());
    ImportResult run = importDocument(doc, out, "--search-path " + shellQuote(images().string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto graphs = graphsIn(out);
    EXPECT_FALSE(graphs.empty());
    for (const auto& graph : graphs) EXPECT_EQ(compileAndValidate(graph, work() / "shaders"), "") << graph.filename();
  }
}

// --- constant materials: the documented mapping, computed here from the document ---

struct Expected {
  std::array<double, 3> baseColor{}, emissive{};
  double metallic = 0, roughness = 0, opacity = 1;
};

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) out.push_back(std::stod(part));
  return out;
}

// The shader's input values, the model's defaults under them.
std::map<std::string, std::vector<double>> shaderValues(const fs::path& document, std::string& model) {
  pugi::xml_document xml;
  EXPECT_TRUE(xml.load_file(document.c_str()));
  std::map<std::string, std::vector<double>> values;
  for (pugi::xml_node n : xml.document_element().children()) {
    std::string category = n.name();
    if (category != "standard_surface" && category != "gltf_pbr" && category != "UsdPreviewSurface") continue;
    model = category;
    if (category == "standard_surface")
      values = {{"base", {1}}, {"base_color", {0.8, 0.8, 0.8}}, {"metalness", {0}}, {"specular_roughness", {0.2}},
                {"emission", {0}}, {"emission_color", {1, 1, 1}}, {"opacity", {1, 1, 1}}};
    else if (category == "gltf_pbr")
      values = {{"base_color", {1, 1, 1}}, {"metallic", {1}}, {"roughness", {1}}, {"emissive", {0, 0, 0}},
                {"emissive_strength", {1}}, {"alpha", {1}}, {"alpha_mode", {0}}};
    else
      values = {{"diffuseColor", {0.18, 0.18, 0.18}}, {"metallic", {0}}, {"roughness", {0.5}},
                {"emissiveColor", {0, 0, 0}}, {"opacity", {1}}};
    for (pugi::xml_node input : n.children("input"))
      if (input.attribute("value") && std::string(input.attribute("type").value()) != "boolean" &&
          std::string(input.attribute("type").value()) != "string")
        values[input.attribute("name").value()] = numbers(input.attribute("value").value());
  }
  return values;
}

Expected expectedMapping(const fs::path& document) {
  std::string model;
  auto v = shaderValues(document, model);
  Expected e;
  if (model == "standard_surface") {
    for (int i = 0; i < 3; ++i) {
      e.baseColor[i] = v["base_color"][i] * v["base"][0];
      e.emissive[i] = v["emission_color"][i] * v["emission"][0];
    }
    e.metallic = v["metalness"][0];
    e.roughness = v["specular_roughness"][0];
    e.opacity = (v["opacity"][0] + v["opacity"][1] + v["opacity"][2]) / 3;
  } else if (model == "gltf_pbr") {
    for (int i = 0; i < 3; ++i) {
      e.baseColor[i] = v["base_color"][i];
      e.emissive[i] = v["emissive"][i] * v["emissive_strength"][0];
    }
    e.metallic = v["metallic"][0];
    e.roughness = v["roughness"][0];
    e.opacity = v["alpha_mode"][0] == 0 ? 1 : v["alpha"][0];
  } else {
    for (int i = 0; i < 3; ++i) {
      e.baseColor[i] = v["diffuseColor"][i];
      e.emissive[i] = v["emissiveColor"][i];
    }
    e.metallic = v["metallic"][0];
    e.roughness = v["roughness"][0];
    e.opacity = v["opacity"][0];
  }
  return e;
}

// Float rounding: values pass through 32-bit floats once.
void expectNear(const Json& got, double want, const std::string& what) {
  ASSERT_TRUE(got.is_number()) << what;
  EXPECT_NEAR(got.get<double>(), want, 1e-6 * std::max(1.0, std::fabs(want))) << what;
}

TEST_F(MaterialXExamples, ConstantMaterialsEvaluateToTheDocumentedMapping) {
  int checked = 0;
  for (const auto& doc : documents()) {
    std::string stem = doc.stem().string();
    bool constant = false;
    for (const char* name : {"_gold", "_copper", "_chrome", "_plastic", "_default", "_greysphere"})
      constant = constant || stem.ends_with(name);
    if (!constant) continue;
    SCOPED_TRACE(stem);
    auto graphs = graphsIn(imported(doc));
    ASSERT_EQ(graphs.size(), 1u);
    Expected want = expectedMapping(doc);
    Json got = evalOutputs(graphs[0]);
    for (int i = 0; i < 3; ++i) {
      expectNear(got["baseColor"][i], want.baseColor[i], "baseColor");
      expectNear(got["emissive"][i], want.emissive[i], "emissive");
    }
    expectNear(got["metallic"], want.metallic, "metallic");
    expectNear(got["roughness"], want.roughness, "roughness");
    expectNear(got["opacity"], want.opacity, "opacity");
    ++checked;
  }
  EXPECT_EQ(checked, 12);  // six standard_surface, three each of gltf_pbr and UsdPreviewSurface
}

// --- node graphs ---


// Mesh uvs (glTF's: v down the image) whose MaterialX uv (v up), tiled `tiles` times,
// lands on the centre of texel `index` (row by row from the top) of a 2 x 2 image.
std::string texelCentre(int index, double tiles) {
  double u = (index % 2 == 0 ? 0.25 : 0.75) / tiles;
  double vUp = (index / 2 == 0 ? 0.75 : 0.25) / tiles;  // from the bottom
  char at[64];
  std::snprintf(at, sizeof at, "texcoord=%.9g:%.9g", u, 1 - vUp);
  return at;
}

double grey(const std::string& image, int texel) { return standInTexels(image)[texel][0] / 255.0; }

TEST_F(MaterialXExamples, WoodGraphEvaluatesToItsImages) {
  auto graphs = graphsIn(imported(kExamples / "StandardSurface/standard_surface_wood_tiled.mtlx"));
  ASSERT_EQ(graphs.size(), 1u);
  for (int texel = 0; texel < 4; ++texel) {
    SCOPED_TRACE(texel);
    Json got = evalOutputs(graphs[0], texelCentre(texel, 4));
    for (int c = 0; c < 3; ++c)  // srgb_texture, times base 1
      EXPECT_NEAR(got["baseColor"][c].get<double>(), srgbToLinear(standInTexels("wood_color.jpg")[texel][c]), 1e-4);
    EXPECT_NEAR(got["roughness"].get<double>(), grey("wood_roughness.jpg", texel), 1e-4);  // lin_rec709
  }
}

std::array<double, 3> rgbToHsv(std::array<double, 3> c) {
  double mx = std::max({c[0], c[1], c[2]}), mn = std::min({c[0], c[1], c[2]}), d = mx - mn, h = 0;
  if (d > 0) {
    if (mx == c[0]) h = (c[1] - c[2]) / d;
    else if (mx == c[1]) h = 2 + (c[2] - c[0]) / d;
    else h = 4 + (c[0] - c[1]) / d;
    h /= 6;
    if (h < 0) h += 1;
  }
  return {h, mx > 0 ? d / mx : 0, mx};
}

std::array<double, 3> hsvToRgb(std::array<double, 3> hsv) {
  double h = hsv[0] - std::floor(hsv[0]), s = hsv[1], v = hsv[2];
  double f = h * 6 - std::floor(h * 6), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (static_cast<int>(std::floor(h * 6)) % 6) {
    case 0: return {v, t, p};
    case 1: return {q, v, p};
    case 2: return {p, v, t};
    case 3: return {p, q, v};
    case 4: return {t, p, v};
    default: return {v, p, q};
  }
}

// NG_BrickPattern by hand, with the document's interface values; they are material
// parameters, so the last run sets two of them (--param).
TEST_F(MaterialXExamples, BrickGraphEvaluatesToThePredictedValues) {
  auto graphs = graphsIn(imported(kExamples / "StandardSurface/standard_surface_brick_procedural.mtlx"));
  ASSERT_EQ(graphs.size(), 1u);
  Json parameters = Json::parse(readFile(graphs[0]))["parameters"];
  EXPECT_EQ(parameters["brick_color"]["default"], Json::array({0.661876, 0.19088, 0.0})) << parameters.dump();
  EXPECT_EQ(parameters["dirt_amount"]["label"], "Dirt Amount");
  const std::array<double, 3> brick{0.661876, 0.19088, 0}, dirt{0.56372, 0.56372, 0.56372}, mortar{0.263273, 0.263273, 0.263273};
  const double hueVariation = 0.083, valueVariation = 0.787;
  for (int run = 0; run < 5; ++run) {
    int texel = run % 4;
    bool tuned = run == 4;
    double roughnessAmount = tuned ? 0.5 : 0.853, dirtAmount = tuned ? 0 : 0.248;
    SCOPED_TRACE(run);
    double base = grey("brick_base_gray.jpg", texel), variation = grey("brick_variation_mask.jpg", texel);
    double mask = grey("brick_mask.jpg", texel), dirtMask = grey("brick_dirt_mask.jpg", texel);
    double add19 = hueVariation * variation + base;
    std::array<double, 3> hsv = rgbToHsv(brick);
    hsv[0] += (add19 - 0.35) * hueVariation;
    hsv[2] += add19 * (valueVariation * variation);
    std::array<double, 3> varied = hsvToRgb(hsv), want{};
    double dirtMix = dirtAmount * dirtMask;
    for (int c = 0; c < 3; ++c) {
      double mixed6 = dirt[c] * dirtMix + varied[c] * (1 - dirtMix);
      double fg = mixed6 * base, bg = mortar[c] * base;
      want[c] = std::clamp(fg * mask + bg * (1 - mask), 0.0, 1.0);
    }
    double roughness = roughnessAmount / std::max(mask, 0.00001) * grey("brick_roughness.jpg", texel);
    auto normalTexel = standInTexels("brick_normal.jpg")[texel];
    std::array<double, 3> n{};
    double length = 0;
    for (int c = 0; c < 3; ++c) length += std::pow(n[c] = normalTexel[c] / 255.0 * 2 - 1, 2);
    Json got = evalOutputs(graphs[0], texelCentre(texel, 3), tuned ? "--param dirt_amount=0,roughness_amount=0.5" : "");
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(got["baseColor"][c].get<double>(), want[c], 2e-4) << "channel " << c;
      EXPECT_NEAR(got["normal"][c].get<double>(), n[c] / std::sqrt(length), 2e-3) << "normal " << c;
    }
    EXPECT_NEAR(got["roughness"].get<double>(), roughness, 2e-4 * std::max(1.0, roughness));  // unclamped, as the graph holds it
  }
}

// The documented fractal3d (docs/materialx-import.md), written as a graph of its own: the
// sum over octaves of 0.5^i x the signed mean of gradient noise on three planes at
// position x scale x 2^i. Its value comes out through worldPositionOffset.x, which no
// range clamps.
std::string fractalGraph(double scale, int octaves) {
  Json nodes = Json::array({{{"id", "p"}, {"op", "world_position"}}});
  std::string sum;
  const std::pair<const char*, Json> planes[] = {{"xy", Json::array({0.0, 0.0})}, {"yz", Json::array({31.7, 11.3})},
                                                 {"zx", Json::array({7.1, 53.9})}};
  for (int i = 0; i < octaves; ++i) {
    std::string o = "o" + std::to_string(i);
    nodes.push_back({{"id", o + "p"}, {"op", "multiply"}, {"inputs", {{"a", "p.out"}, {"b", scale * std::pow(2.0, i)}}}});
    std::string mean;
    for (const auto& [plane, offset] : planes) {
      std::string id = o + plane;
      nodes.push_back({{"id", id + "s"}, {"op", "swizzle"}, {"inputs", {{"in", o + "p.out"}, {"channels", plane}}}});
      nodes.push_back({{"id", id + "a"}, {"op", "add"}, {"inputs", {{"a", id + "s.out"}, {"b", offset}}}});
      nodes.push_back({{"id", id}, {"op", "gradient_noise"}, {"inputs", {{"p", id + "a.out"}}}});
      if (mean.empty()) {
        mean = id + ".out";
      } else {
        nodes.push_back({{"id", id + "sum"}, {"op", "add"}, {"inputs", {{"a", mean}, {"b", id + ".out"}}}});
        mean = id + "sum.out";
      }
    }
    // signed: (sum / 3) x 2 - 1, then the octave's weight
    nodes.push_back({{"id", o + "n"}, {"op", "remap"}, {"inputs", {{"x", mean}, {"inHigh", 3.0}, {"outLow", -1.0}, {"outHigh", 1.0}}}});
    nodes.push_back({{"id", o}, {"op", "multiply"}, {"inputs", {{"a", o + "n.out"}, {"b", std::pow(0.5, i)}}}});
    if (sum.empty()) {
      sum = o + ".out";
    } else {
      nodes.push_back({{"id", o + "sum"}, {"op", "add"}, {"inputs", {{"a", sum}, {"b", o + ".out"}}}});
      sum = o + "sum.out";
    }
  }
  nodes.push_back({{"id", "f"}, {"op", "combine3"}, {"inputs", {{"x", sum}}}});
  return Json{{"name", "fractal"}, {"nodes", nodes}, {"output", {{"worldPositionOffset", "f.out"}}}}.dump();
}

// NG_marble1 by hand: mix(color 1, color 2, (0.5 + 0.5 sin(6 (x + y + z) + 3 fractal(4 p)))^3).
TEST_F(MaterialXExamples, MarbleGraphEvaluatesToThePredictedValues) {
  auto graphs = graphsIn(imported(kExamples / "StandardSurface/standard_surface_marble_solid.mtlx"));
  ASSERT_EQ(graphs.size(), 1u);
  writeFile(work() / "fractal.json", fractalGraph(4.0, 3));
  const std::array<double, 3> colour1{0.8, 0.8, 0.8}, colour2{0.1, 0.1, 0.3};
  const std::array<std::array<double, 3>, 3> points = {{{0.1, 0.2, 0.3}, {-0.4, 0.05, 0.7}, {1.3, -0.6, 0.25}}};
  for (const auto& p : points) {
    char at[96];
    std::snprintf(at, sizeof at, "worldPosition=%.9g:%.9g:%.9g", p[0], p[1], p[2]);
    SCOPED_TRACE(at);
    double fractal = evalOutputs(work() / "fractal.json", at)["worldPositionOffset"][0].get<double>();
    double m = std::pow(0.5 + 0.5 * std::sin(6 * (p[0] + p[1] + p[2]) + 3 * fractal), 3);
    Json got = evalOutputs(graphs[0], at);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got["baseColor"][c].get<double>(), colour1[c] * (1 - m) + colour2[c] * m, 1e-4) << "channel " << c;
    expectNear(got["roughness"], 0.1, "roughness");
  }
}

}  // namespace
}  // namespace wg::testing
