// `weathergen import` end to end: real glTF files from Debian's assimp-testmodels (the
// bootstrap installs it; tests that need it skip without it) and hostile files written
// here. Imported graphs compile and pass the independent validators; the same model gives
// the same bytes every time; every error exits 1 with its code and location and writes
// nothing, not even a temporary file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "process_support.hpp"
#include "host/image/png_file.hpp"

namespace wg {
namespace {

using testing::listFiles;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
using testing::writeFile;
using Json = nlohmann::json;
namespace fs = std::filesystem;

const std::string kCli = WG_CLI_PATH;
const fs::path kModels = "/usr/share/assimp/models/glTF2";

// Tests on the package's models skip without it; the bootstrap installs it, so CI runs them.
class GltfImportModels : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::is_directory(kModels))
      GTEST_SKIP() << kModels.string() << " is missing: install Debian's assimp-testmodels (scripts/bootstrap.sh does)";
  }
};

testing::CommandResult import(const fs::path& model, const fs::path& out, const std::string& extra = "") {
  return runCommand(shellQuote(kCli) + " import " + shellQuote(model.string()) + " -o " + shellQuote(out.string()) + " " +
                    extra);
}

// With -q nothing goes to stdout, so the output is the --diagnostics json array alone.
struct ImportRun {
  int exitCode = -1;
  Json diagnostics;  // discarded when the output was not JSON
  std::string output;
};

ImportRun importJson(const fs::path& model, const fs::path& out, const std::string& extra = "") {
  auto r = import(model, out, "-q --diagnostics json " + extra);
  return {r.exitCode, Json::parse(r.output, nullptr, /*allow_exceptions=*/false), r.output};
}

Json readJson(const fs::path& file) { return Json::parse(readFile(file), nullptr, /*allow_exceptions=*/false); }

// The model's JSON: the whole .gltf, or a .glb's JSON chunk; discarded when it is not JSON.
Json modelDocument(const fs::path& model) {
  std::string bytes = readFile(model);
  if (bytes.size() >= 20 && bytes.compare(0, 4, "glTF") == 0) {
    std::uint32_t length = 0;
    for (int i = 3; i >= 0; --i) length = length << 8 | static_cast<unsigned char>(bytes[12 + i]);
    bytes = bytes.substr(20, length);
  }
  return Json::parse(bytes, nullptr, /*allow_exceptions=*/false);
}

// Everything under dir, hidden entries included: relative path -> a file's bytes, or
// "<directory>". Empty when dir does not exist.
using Snapshot = std::map<std::string, std::string>;

Snapshot snapshot(const fs::path& dir) {
  Snapshot entries;
  if (!fs::exists(dir)) return entries;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    entries[fs::relative(e.path(), dir).string()] =
        e.is_directory() ? "<directory>" : e.is_regular_file() ? readFile(e.path()) : "<not a file>";
  return entries;
}

// "" when the two snapshots agree, else which entries were added, removed or changed.
std::string changes(const Snapshot& before, const Snapshot& after) {
  std::string out;
  for (const auto& [name, bytes] : after) {
    auto it = before.find(name);
    if (it == before.end()) out += " added '" + name + "';";
    else if (it->second != bytes) out += " changed '" + name + "';";
  }
  for (const auto& [name, bytes] : before)
    if (!after.count(name)) out += " removed '" + name + "';";
  return out;
}

// The import index's materials, in index order: their graph files.
std::vector<fs::path> indexedGraphs(const fs::path& dir, const Json& index) {
  std::vector<fs::path> graphs;
  for (const auto& m : index["materials"]) graphs.push_back(dir / m["graph"].get<std::string>());
  return graphs;
}

// A generated shader starts with a comment naming its material's hash; shaders that
// differ only in comments are validated once.
std::string withoutCommentLines(const std::string& source) {
  std::string out;
  for (std::size_t at = 0; at < source.size();) {
    std::size_t end = std::min(source.find('\n', at), source.size());
    std::string_view line(source.data() + at, end - at);
    if (!line.starts_with("//")) out.append(line) += '\n';
    at = end + 1;
  }
  return out;
}

// Compiles the graphs in one CLI call (--target all) and runs glslangValidator on every
// GLSL and HLSL stage and spirv-val on every SPIR-V module it writes, as
// bundled_graphs_test does for the bundled graphs.
void expectCompilesAndValidates(const std::vector<fs::path>& graphs, const fs::path& out) {
  ASSERT_FALSE(graphs.empty());
  std::string command = shellQuote(kCli) + " compile -q --target all -o " + shellQuote(out.string());
  for (const auto& g : graphs) command += " " + shellQuote(g.string());
  auto r = runCommand(command);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto files = listFiles(out);
  std::set<std::string> written(files.begin(), files.end());
  for (const auto& g : graphs)
    for (const char* suffix : {".vert.glsl", ".frag.glsl", ".vert.hlsl", ".frag.hlsl", ".glsl.vert.spv", ".glsl.frag.spv",
                               ".hlsl.vert.spv", ".hlsl.frag.spv", ".reflect.json"})
      EXPECT_TRUE(written.count(g.stem().string() + suffix)) << g.stem().string() + suffix << " was not written";
  std::set<std::string> validated, kinds;
  std::vector<std::pair<std::string, std::string>> checks;  // file name, validator command
  for (const auto& name : files) {
    const std::string stage = name.find(".vert.") != std::string::npos ? "vert" : "frag";
    const std::string file = shellQuote((out / name).string());
    const std::string text = readFile(out / name), kind = stage + fs::path(name).extension().string();
    if (name.ends_with(".glsl") || name.ends_with(".hlsl")) {
      if (!validated.insert(kind + "\n" + withoutCommentLines(text)).second) continue;
      checks.emplace_back(name, shellQuote(WG_GLSLANG_VALIDATOR) + " -V --target-env vulkan1.1 -S " + stage +
                                    (name.ends_with(".hlsl") ? " -D -e main " : " ") + file + " -o /dev/null");
    } else if (name.ends_with(".spv")) {
      if (!validated.insert(kind + "\n" + text).second) continue;
      checks.emplace_back(name, shellQuote(WG_SPIRV_VAL) + " --target-env vulkan1.1 " + file);
    } else {
      continue;
    }
    kinds.insert(kind);
  }
  EXPECT_EQ(kinds.size(), 6u);  // GLSL, HLSL and SPIR-V, each for both stages
  // The validators run a few at a time: CI has two cores.
  std::vector<testing::CommandResult> results(checks.size());
  std::vector<std::thread> workers;
  const std::size_t threads = std::max(2u, std::thread::hardware_concurrency());
  for (std::size_t t = 0; t < threads; ++t)
    workers.emplace_back([&, t] {
      for (std::size_t i = t; i < checks.size(); i += threads) results[i] = runCommand(checks[i].second);
    });
  for (auto& w : workers) w.join();
  for (std::size_t i = 0; i < checks.size(); ++i)
    EXPECT_EQ(results[i].exitCode, 0) << checks[i].first << ":\n" << results[i].output;
}

// Runs an import that must fail: exit 1, only `code`, each diagnostic with its file,
// line, column and a JSON pointer into the model, and nothing at all written (the output
// directory is not created, and no temporary file lies beside it). Returns the diagnostics.
Json expectRejected(const fs::path& model, const std::string& code) {
  TempDir dir("gltf-rejected");
  const fs::path out = dir.path() / "out";
  ImportRun run = importJson(model, out);
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_TRUE(run.diagnostics.is_array() && !run.diagnostics.empty()) << run.output;
  if (!run.diagnostics.is_array()) return Json::array();
  const Json document = modelDocument(model);
  for (const auto& d : run.diagnostics) {
    SCOPED_TRACE(d.dump());
    EXPECT_EQ(d.value("code", ""), code);
    EXPECT_EQ(d.value("severity", ""), "error");
    EXPECT_EQ(d.value("file", ""), model.string());
    EXPECT_TRUE(d.contains("line") && d["line"].is_number_integer() && d.contains("column") && d["column"].is_number_integer());
    if (code != "WG5001") {  // a broken container is reported before any JSON is read
      EXPECT_GE(d.value("line", 0), 1);
      EXPECT_GE(d.value("column", 0), 1);
    }
    std::string pointer = d.value("pointer", std::string("<none>"));
    EXPECT_TRUE(pointer.empty() || pointer.front() == '/') << "pointer '" << pointer << "'";
    if (!document.is_discarded() && (pointer.empty() || pointer.front() == '/')) {
      EXPECT_TRUE(document.contains(Json::json_pointer(pointer))) << "'" << pointer << "' names nothing in the model";
    }
    EXPECT_FALSE(d.value("message", "").empty());
  }
  EXPECT_EQ(changes({}, snapshot(dir.path())), "") << "a rejected import wrote something";
  return run.diagnostics;
}

std::set<std::string> codesOf(const Json& diagnostics) {
  std::set<std::string> codes;
  if (!diagnostics.is_array()) return {"<not a JSON array>"};
  for (const auto& d : diagnostics) codes.insert(d.value("code", ""));
  return codes;
}

// ---------------------------------------------------------------------------------------
// Models from assimp-testmodels.

// The same box as .glb, as .gltf with data: URIs and as .gltf with files beside it.
TEST_F(GltfImportModels, BoxTexturedBinaryEmbeddedAndSeparateAgree) {
  TempDir dir("gltf-box");
  const fs::path binary = dir.path() / "binary", embedded = dir.path() / "embedded", separate = dir.path() / "separate";
  for (const auto& [model, out] : std::vector<std::pair<fs::path, fs::path>>{
           {kModels / "BoxTextured-glTF-Binary/BoxTextured.glb", binary},
           {kModels / "BoxTextured-glTF-Embedded/BoxTextured.gltf", embedded},
           {kModels / "BoxTextured-glTF/BoxTextured.gltf", separate}}) {
    auto r = import(model, out);
    ASSERT_EQ(r.exitCode, 0) << model << ":\n" << r.output;
  }
  const std::vector<std::string> expected = {"BoxTextured.import.json", "BoxTextured_Texture.json", "BoxTextured_image0.png"};
  ASSERT_EQ(listFiles(binary), expected);
  ASSERT_EQ(listFiles(embedded), expected);
  ASSERT_EQ(listFiles(separate), expected);
  EXPECT_TRUE(readFile(binary / expected[1]) == readFile(embedded / expected[1])) << "the graphs differ";
  EXPECT_TRUE(readFile(binary / expected[2]) == readFile(embedded / expected[2])) << "the images differ";
  EXPECT_TRUE(readFile(separate / expected[2]) == readFile(kModels / "BoxTextured-glTF/CesiumLogoFlat.png"))
      << "the image file was not copied as it is";
  Json indexBinary = readJson(binary / expected[0]), indexEmbedded = readJson(embedded / expected[0]);
  EXPECT_EQ(indexBinary["model"], "BoxTextured.glb");
  EXPECT_EQ(indexEmbedded["model"], "BoxTextured.gltf");
  indexBinary.erase("model");
  indexEmbedded.erase("model");
  EXPECT_EQ(indexBinary, indexEmbedded);
  EXPECT_EQ(indexBinary["materials"].size(), 1u);
  EXPECT_EQ(indexBinary["triangles"], 12);

  // Debian's separate-file copy samples with mirrored repeat along u and clamps along v.
  Json source = modelDocument(kModels / "BoxTextured-glTF/BoxTextured.gltf");
  const Json& sampler = source["samplers"][source["textures"][0]["sampler"].get<int>()];
  ASSERT_EQ(sampler["wrapS"], 33648) << "assimp-testmodels changed this file; " << sampler.dump();
  ASSERT_EQ(sampler["wrapT"], 33071) << "assimp-testmodels changed this file; " << sampler.dump();
  Json repeating = readJson(binary / expected[1]), mirrored = readJson(separate / expected[1]);
  ASSERT_TRUE(repeating.is_object() && mirrored.is_object());
  EXPECT_EQ(repeating["textures"]["baseColor"]["wrap"], "repeat");
  EXPECT_EQ(mirrored["textures"]["baseColor"]["wrap"], Json({"mirror", "clamp"}));
  mirrored["textures"]["baseColor"]["wrap"] = repeating["textures"]["baseColor"]["wrap"];
  EXPECT_EQ(mirrored, repeating) << "the graphs differ in more than the wrap";

  // The separate-file graph names the same material, so it compiles on its own.
  expectCompilesAndValidates({binary / expected[1]}, dir.path() / "compiled-binary");
  expectCompilesAndValidates({separate / expected[1]}, dir.path() / "compiled-separate");
}

TEST_F(GltfImportModels, ReimportIsByteIdentical) {
  for (const char* model : {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "textureTransform/TextureTransformTest.gltf"}) {
    SCOPED_TRACE(model);
    TempDir first("gltf-again-a"), second("gltf-again-b");
    ASSERT_EQ(import(kModels / model, first.path()).exitCode, 0);
    ASSERT_EQ(import(kModels / model, second.path()).exitCode, 0);
    Snapshot a = snapshot(first.path());
    EXPECT_GT(a.size(), 1u);
    EXPECT_EQ(changes(a, snapshot(second.path())), "");
  }
}

TEST_F(GltfImportModels, TwoCylinderEngineGivesThirtyFourGraphsThatCompile) {
  TempDir dir("gltf-engine");
  const fs::path out = dir.path() / "import";
  auto r = import(kModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb", out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Json index = readJson(out / "2CylinderEngine.import.json");
  ASSERT_TRUE(index.is_object());
  ASSERT_EQ(index["materials"].size(), 34u);
  std::set<std::string> graphFiles;
  for (std::size_t i = 0; i < index["materials"].size(); ++i) {
    const Json& m = index["materials"][i];
    EXPECT_EQ(m["index"], i);
    graphFiles.insert(m["graph"].get<std::string>());
  }
  EXPECT_EQ(graphFiles.size(), 34u) << "two materials share a graph file";
  std::set<std::string> written;
  for (const auto& name : listFiles(out))
    if (name != "2CylinderEngine.import.json") written.insert(name);
  EXPECT_EQ(written, graphFiles);
  expectCompilesAndValidates(indexedGraphs(out, index), dir.path() / "compiled");
}

// Evaluates the graph's value at `uv` through the few ops a texture transform uses.
std::vector<double> evaluate(const std::map<std::string, Json>& nodes, const Json& value, const std::vector<double>& uv) {
  if (value.is_number()) return {value.get<double>()};
  if (value.is_array()) return value.get<std::vector<double>>();
  std::string link = value.get<std::string>();
  std::string id = link.substr(0, link.rfind('.'));
  auto it = nodes.find(id);
  if (it == nodes.end() || !link.ends_with(".out")) {
    ADD_FAILURE() << "unexpected link '" << link << "' in the uv chain";
    return {};
  }
  const Json& node = it->second;
  const std::string op = node.at("op");
  if (op == "texcoord") return uv;
  const Json& in = node.at("inputs");
  if (op == "combine2") return {evaluate(nodes, in.at("x"), uv).at(0), evaluate(nodes, in.at("y"), uv).at(0)};
  std::vector<double> a = evaluate(nodes, in.at("a"), uv), b = evaluate(nodes, in.at("b"), uv);
  if (a.size() == 1) a.resize(b.size(), a[0]);
  if (b.size() == 1) b.resize(a.size(), b[0]);
  if (a.size() != b.size()) return {};
  std::vector<double> result(a.size());
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (op == "multiply") result[i] = a[i] * b[i];
    else if (op == "add") result[i] = a[i] + b[i];
    else if (op == "subtract") result[i] = a[i] - b[i];
    else if (op == "dot") sum += a[i] * b[i];
    else {
      ADD_FAILURE() << "unexpected op '" << op << "' in the uv chain";
      return {};
    }
  }
  return op == "dot" ? std::vector<double>{sum} : result;
}

// KHR_texture_transform: uv' = offset + R(rotation) (scale * uv), with the rotation of
// the glTF UV space (v down), as the sample model's green markers and KhronosGroup/glTF
// issue 1563 have it: u' = cos u + sin v, v' = -sin u + cos v.
TEST_F(GltfImportModels, TextureTransformReachesTheGraphs) {
  const fs::path model = kModels / "textureTransform/TextureTransformTest.gltf";
  TempDir dir("gltf-transform");
  const fs::path out = dir.path() / "import";
  auto r = import(model, out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Json source = modelDocument(model), index = readJson(out / "TextureTransformTest.import.json");
  ASSERT_TRUE(index.is_object());
  ASSERT_EQ(index["materials"].size(), source["materials"].size());
  int transformed = 0;
  for (std::size_t i = 0; i < source["materials"].size(); ++i) {
    SCOPED_TRACE(source["materials"][i]["name"].get<std::string>());
    Json::json_pointer at("/materials/" + std::to_string(i) +
                          "/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform");
    Json transform = source.contains(at) ? source.at(at) : Json::object();
    if (source.contains(at)) ++transformed;
    const auto offset = transform.value("offset", std::vector<double>{0, 0});
    const auto scale = transform.value("scale", std::vector<double>{1, 1});
    const double rotation = transform.value("rotation", 0.0), c = std::cos(rotation), s = std::sin(rotation);

    ASSERT_EQ(index["materials"][i]["index"], i);
    Json graph = readJson(out / index["materials"][i]["graph"].get<std::string>());
    ASSERT_TRUE(graph.is_object());
    std::map<std::string, Json> nodes;
    const Json* sample = nullptr;
    for (const auto& node : graph["nodes"]) {
      nodes[node.at("id").get<std::string>()] = node;
      if (node.value("op", "") == "sample" && node.at("inputs").value("texture", "") == "baseColor") sample = &node;
    }
    ASSERT_NE(sample, nullptr) << "no node samples the base colour";
    for (const auto& uv : std::vector<std::vector<double>>{{0, 0}, {1, 0}, {0, 1}, {0.3, 0.7}}) {
      const double x = scale[0] * uv[0], y = scale[1] * uv[1];
      const std::vector<double> expected = {offset[0] + c * x + s * y, offset[1] - s * x + c * y};
      const std::vector<double> got = evaluate(nodes, sample->at("inputs").at("uv"), uv);
      ASSERT_EQ(got.size(), 2u) << "at uv (" << uv[0] << ", " << uv[1] << ")";
      EXPECT_NEAR(got[0], expected[0], 1e-9) << "u at uv (" << uv[0] << ", " << uv[1] << ")";
      EXPECT_NEAR(got[1], expected[1], 1e-9) << "v at uv (" << uv[0] << ", " << uv[1] << ")";
    }
  }
  EXPECT_EQ(transformed, 6);
  expectCompilesAndValidates(indexedGraphs(out, index), dir.path() / "compiled");
}

// Extensions the import does not map warn (WG5101, exit 0) and leave graphs that compile.
TEST_F(GltfImportModels, UnmappedMaterialExtensionsWarnAndStillCompile) {
  struct Case {
    const char* model;
    const char* extension;
  };
  for (const Case& c : {Case{"ClearCoat-glTF/ClearCoatTest.gltf", "KHR_materials_clearcoat"},
                        Case{"BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", "KHR_materials_pbrSpecularGlossiness"}}) {
    SCOPED_TRACE(c.model);
    const fs::path model = kModels / c.model;
    TempDir dir("gltf-extension");
    const fs::path out = dir.path() / "import";
    ImportRun run = importJson(model, out);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    ASSERT_TRUE(run.diagnostics.is_array()) << run.output;
    std::set<std::string> expectedPointers, pointers;
    Json source = modelDocument(model);
    for (std::size_t i = 0; i < source["materials"].size(); ++i)
      if (source["materials"][i].contains("extensions") && source["materials"][i]["extensions"].contains(c.extension))
        expectedPointers.insert("/materials/" + std::to_string(i) + "/extensions/" + c.extension);
    ASSERT_FALSE(expectedPointers.empty());
    for (const auto& d : run.diagnostics) {
      EXPECT_EQ(d.value("severity", ""), "warning") << d.dump();
      if (d.value("code", "") != "WG5101") continue;
      EXPECT_NE(d.value("message", "").find(c.extension), std::string::npos) << d.dump();
      EXPECT_EQ(d.value("file", ""), model.string());
      EXPECT_GE(d.value("line", 0), 1);
      pointers.insert(d.value("pointer", ""));
    }
    EXPECT_EQ(pointers, expectedPointers);
    Json index = readJson(out / (model.stem().string() + ".import.json"));
    ASSERT_TRUE(index.is_object());
    EXPECT_EQ(index["materials"].size(), source["materials"].size());
    expectCompilesAndValidates(indexedGraphs(out, index), dir.path() / "compiled");
  }
}

TEST_F(GltfImportModels, SceneWithoutNodesImportsNoMaterials) {
  TempDir dir("gltf-empty-scene");
  ImportRun run = importJson(kModels / "TestNoRootNode/SceneWithoutNodes.gltf", dir.path());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.diagnostics, Json::array());
  EXPECT_EQ(listFiles(dir.path()), std::vector<std::string>{"SceneWithoutNodes.import.json"});
  Json index = readJson(dir.path() / "SceneWithoutNodes.import.json");
  EXPECT_EQ(index["materials"], Json::array());
  EXPECT_EQ(index["primitives"], 0);
}

// Hostile files in assimp-testmodels, each with the code it must give.
struct HostileModel {
  const char* file;  // under glTF2/
  const char* code;
};

const HostileModel kHostileModels[] = {
    {"IndexOutOfRange/IndexOutOfRange.gltf", "WG5007"},
    {"IndexOutOfRange/AllIndicesOutOfRange.gltf", "WG5007"},
    {"wrongTypes/badArray.gltf", "WG5002"},
    {"wrongTypes/badExtension.gltf", "WG5002"},
    {"wrongTypes/badNumber.gltf", "WG5002"},
    {"wrongTypes/badObject.gltf", "WG5002"},
    {"wrongTypes/badString.gltf", "WG5002"},
    {"wrongTypes/badUint.gltf", "WG5002"},
    {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "WG5007"},
    {"MissingBin/BoxTextured.gltf", "WG5004"},
    {"RecursiveNodes/RecursiveNodes.gltf", "WG5006"},
    {"TestNoRootNode/NoScene.gltf", "WG5003"},
    {"SchemaFailures/sceneWrongType.gltf", "WG5002"},
    {"issue_3269/texcoord_crash.gltf", "WG5003"},
    {"draco/2CylinderEngine.gltf", "WG5005"},
};

void PrintTo(const HostileModel& m, std::ostream* os) { *os << m.file; }

class GltfImportHostileModel : public GltfImportModels, public ::testing::WithParamInterface<HostileModel> {};

TEST_P(GltfImportHostileModel, ExitsOneWithItsCodeAndWritesNothing) {
  const fs::path model = kModels / GetParam().file;
  ASSERT_TRUE(fs::is_regular_file(model)) << model << " is missing from assimp-testmodels";
  expectRejected(model, GetParam().code);
}

INSTANTIATE_TEST_SUITE_P(GltfImportAssimpTestModels, GltfImportHostileModel, ::testing::ValuesIn(kHostileModels),
                         [](const ::testing::TestParamInfo<HostileModel>& info) {
                           std::string name;
                           for (const char* c = info.param.file; *c && *c != '.'; ++c)
                             if (std::isalnum(static_cast<unsigned char>(*c))) name += *c;
                           return name;
                         });

// The list above holds every model of the directories whose models are all hostile.
TEST_F(GltfImportModels, HostileListCoversItsDirectories) {
  std::set<std::string> listed, found;
  for (const auto& m : kHostileModels) listed.insert(m.file);
  for (const char* folder : {"IndexOutOfRange", "wrongTypes", "BoxWithInfinites-glTF-Binary", "MissingBin", "RecursiveNodes",
                             "SchemaFailures", "issue_3269", "draco"})
    for (const auto& e : fs::directory_iterator(kModels / folder))
      if (e.path().extension() == ".gltf" || e.path().extension() == ".glb")
        found.insert(std::string(folder) + "/" + e.path().filename().string());
  found.insert("TestNoRootNode/NoScene.gltf");
  EXPECT_EQ(listed, found);
}

// ---------------------------------------------------------------------------------------
// Hostile files written here. Each goes with a control that differs only in the hostile
// part and imports, so the rejection is for that part.

std::string littleEndian32(std::uint32_t v) {
  std::string out;
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
  return out;
}

// A GLB of `json` and `bin`; the chunk headers claim `jsonExtra` and `binExtra` more
// bytes than they hold, while the file header's total length stays true.
std::string glb(std::string json, std::string bin, std::uint32_t jsonExtra = 0, std::uint32_t binExtra = 0) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  std::string body = littleEndian32(static_cast<std::uint32_t>(json.size()) + jsonExtra) + "JSON" + json +
                     littleEndian32(static_cast<std::uint32_t>(bin.size()) + binExtra) + std::string("BIN\0", 4) + bin;
  return "glTF" + littleEndian32(2) + littleEndian32(static_cast<std::uint32_t>(12 + body.size())) + body;
}

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 2]);
    for (std::size_t k = 0; k < 4; ++k) out += i + k <= bytes.size() ? kAlphabet[(n >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

// CRC-32 as PNG chunks use it (ISO 3309, reflected 0xEDB88320).
std::uint32_t crc32(std::string_view bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = crc & 1 ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
  }
  return ~crc;
}

std::string bigEndian32(std::uint32_t v) {
  std::string out;
  for (int i = 3; i >= 0; --i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
  return out;
}

// A real 2x2 PNG, written by the runtime's encoder.
std::string smallPng(const fs::path& dir) {
  const fs::path file = dir / "small.png";
  EXPECT_EQ(image::writePng(file.string(), Image::blank(2, 2)), "");
  std::string png = readFile(file);
  fs::remove(file);
  return png;
}

// A model file in its own folder (with `extras` beside it), and the folder's state.
struct CraftedModel {
  TempDir dir{"gltf-crafted"};
  fs::path model;
  CraftedModel(const std::string& name, const std::string& bytes, const std::map<std::string, std::string>& extras = {}) {
    model = dir.path() / name;
    writeFile(model, bytes);
    for (const auto& [file, content] : extras) writeFile(dir.path() / file, content);
  }
};

void expectImports(const CraftedModel& crafted) {
  TempDir out("gltf-control");
  ImportRun run = importJson(crafted.model, out.path());
  EXPECT_EQ(run.exitCode, 0) << "the control does not import:\n" << run.output;
}

// Rejected with `code`, and the model's folder is left as it was.
Json expectCraftedRejected(const CraftedModel& crafted, const std::string& code) {
  Snapshot before = snapshot(crafted.dir.path());
  Json diagnostics = expectRejected(crafted.model, code);
  EXPECT_EQ(changes(before, snapshot(crafted.dir.path())), "") << "the model's folder changed";
  return diagnostics;
}

TEST(GltfImportCrafted, GlbChunkLengthsThatLie) {
  const std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":8}]})", bin(8, '\x01');
  expectImports(CraftedModel("box.glb", glb(json, bin)));
  expectCraftedRejected(CraftedModel("box.glb", glb(json, bin, /*jsonExtra=*/4096)), "WG5001");
  expectCraftedRejected(CraftedModel("box.glb", glb(json, bin, 0, /*binExtra=*/4096)), "WG5001");
}

std::string modelWithImageUri(const std::string& uri) {
  return Json{{"asset", {{"version", "2.0"}}}, {"images", {{{"uri", uri}}}}}.dump();
}

TEST(GltfImportCrafted, ImageUriLeavingTheModelFolder) {
  TempDir scratch("gltf-png");
  const std::map<std::string, std::string> beside = {{"img.png", smallPng(scratch.path())}};
  expectImports(CraftedModel("m.gltf", modelWithImageUri("img.png"), beside));
  std::string passwd = readFile("/etc/passwd");
  std::string firstLine = passwd.substr(0, passwd.find('\n'));
  // The second reaches /etc/passwd from any temp folder.
  for (const std::string uri : {"../../etc/passwd", "../../../../../../../../../../../../etc/passwd"}) {
    SCOPED_TRACE(uri);
    Json diagnostics = expectCraftedRejected(CraftedModel("m.gltf", modelWithImageUri(uri), beside), "WG5004");
    if (!firstLine.empty()) {
      EXPECT_EQ(diagnostics.dump().find(firstLine), std::string::npos) << "the message shows /etc/passwd";
    }
    for (const auto& d : diagnostics) EXPECT_EQ(d.value("pointer", ""), "/images/0/uri");
  }
}

// Cut at the NUL, the path would name the image that lies beside the model.
TEST(GltfImportCrafted, ImageUriWithPercentEncodedNul) {
  TempDir scratch("gltf-png");
  const std::map<std::string, std::string> beside = {{"img.png", smallPng(scratch.path())}};
  expectImports(CraftedModel("m.gltf", modelWithImageUri("img.png"), beside));
  expectCraftedRejected(CraftedModel("m.gltf", modelWithImageUri("img.png%00.jpg"), beside), "WG5004");
}

TEST(GltfImportCrafted, BufferDataUriThatIsNotBase64) {
  auto model = [](const std::string& payload) {
    return Json{{"asset", {{"version", "2.0"}}},
                {"buffers", {{{"byteLength", 3}, {"uri", "data:application/octet-stream;base64," + payload}}}}}
        .dump();
  };
  expectImports(CraftedModel("m.gltf", model("AAEC")));
  expectCraftedRejected(CraftedModel("m.gltf", model("AA*C")), "WG5004");
}

// An embedded PNG whose IHDR (with a correct CRC) claims 60000x60000 pixels.
TEST(GltfImportCrafted, EmbeddedPngHeaderClaimingHugeSize) {
  TempDir scratch("gltf-png");
  std::string png = smallPng(scratch.path());
  ASSERT_GE(png.size(), 33u);
  ASSERT_EQ(png.substr(12, 4), "IHDR");
  ASSERT_EQ(png.substr(29, 4), bigEndian32(crc32(std::string_view(png).substr(12, 17)))) << "crc32 is wrong";
  auto model = [](const std::string& image) { return modelWithImageUri("data:image/png;base64," + base64(image)); };
  CraftedModel control("m.gltf", model(png));
  expectImports(control);
  std::string huge = png;
  huge.replace(16, 8, bigEndian32(60000) + bigEndian32(60000));
  huge.replace(29, 4, bigEndian32(crc32(std::string_view(huge).substr(12, 17))));
  expectCraftedRejected(CraftedModel("m.gltf", model(huge)), "WG5007");
}

TEST(GltfImportCrafted, NodeWithTwoParents) {
  auto model = [](const Json& secondChildren) {
    return Json{{"asset", {{"version", "2.0"}}},
                {"scene", 0},
                {"scenes", {{{"nodes", {0, 1}}}}},
                {"nodes", {{{"children", {2}}}, {{"children", secondChildren}}, Json::object()}}}
        .dump();
  };
  expectImports(CraftedModel("m.gltf", model(Json::array())));
  Json diagnostics = expectCraftedRejected(CraftedModel("m.gltf", model({2})), "WG5006");
  for (const auto& d : diagnostics) EXPECT_EQ(d.value("pointer", ""), "/nodes/1/children/0");
}

TEST(GltfImportCrafted, FileThatIsNotGltf) {
  expectCraftedRejected(CraftedModel("m.gltf", "hello, this is not glTF\n"), "WG1001");
  expectCraftedRejected(CraftedModel("m.glb", "#!/bin/sh\necho not a glb\n"), "WG1001");
}

// ---------------------------------------------------------------------------------------
// Material names and weather presets.

const std::vector<std::string> kMaterialNames = {"Red", "Red", "../a/b c", "Red_0", "", "RED", "default", "DarkRed", "Blue"};

std::string namedMaterialsModel() {
  Json materials = Json::array();
  for (const auto& name : kMaterialNames) materials.push_back({{"name", name}});
  return Json{{"asset", {{"version", "2.0"}}}, {"materials", materials}}.dump();
}

// Same names, a path-like one, one that an index suffix would produce, an empty one, one
// that differs only in case, and the default graph's: every graph gets its own file name
// (case-insensitively, for case-insensitive file systems), safe on any file system, and
// the same on every run.
TEST(GltfImportNames, DistinctStableAndFileSafe) {
  CraftedModel crafted("names.gltf", namedMaterialsModel());
  TempDir first("gltf-names-a"), second("gltf-names-b");
  for (const auto& dir : {first.path(), second.path()}) {
    auto r = import(crafted.model, dir);
    ASSERT_EQ(r.exitCode, 0) << r.output;
  }
  Json index = readJson(first.path() / "names.import.json");
  ASSERT_TRUE(index.is_object());
  ASSERT_EQ(index["materials"].size(), kMaterialNames.size());
  std::set<std::string> files, folded;
  for (std::size_t i = 0; i < kMaterialNames.size(); ++i) {
    const Json& m = index["materials"][i];
    EXPECT_EQ(m["index"], i);
    EXPECT_EQ(m["name"], kMaterialNames[i]);
    std::string file = m["graph"];
    EXPECT_TRUE(file.starts_with("names_") && file.ends_with(".json")) << file;
    EXPECT_EQ(file.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-."), std::string::npos) << file;
    EXPECT_EQ(file.find(".."), std::string::npos) << file;
    EXPECT_NE(file, "names_default.json") << "the default graph's name";
    EXPECT_TRUE(fs::is_regular_file(first.path() / file)) << file;
    std::string lower = file;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    files.insert(file);
    folded.insert(lower);
  }
  EXPECT_EQ(files.size(), kMaterialNames.size()) << "two materials share a file name";
  EXPECT_EQ(folded.size(), kMaterialNames.size()) << "two file names differ only in case";
  EXPECT_EQ(changes(snapshot(first.path()), snapshot(second.path())), "");
}

TEST(GltfImportPresets, PresetMapChoosesEachMaterialsWeather) {
  CraftedModel crafted("names.gltf", namedMaterialsModel());
  struct Case {
    std::string options;
    std::function<std::string(const std::string&)> expected;  // material name -> preset
  };
  const std::vector<Case> cases = {
      {"--preset-map '*Red*=foliage,*=rock'",
       [](const std::string& n) { return n.find("Red") != std::string::npos ? "foliage" : "rock"; }},
      {"--preset-map 'Blue=river'", [](const std::string& n) { return n == "Blue" ? "river" : "none"; }},
      {"--weather-preset road", [](const std::string&) { return "road"; }},
      {"", [](const std::string&) { return "rock"; }},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.options);
    TempDir out("gltf-presets");
    auto r = import(crafted.model, out.path(), c.options);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Json index = readJson(out.path() / "names.import.json");
    ASSERT_EQ(index["materials"].size(), kMaterialNames.size());
    for (const auto& m : index["materials"]) {
      std::string name = m["name"], expected = c.expected(name);
      EXPECT_EQ(m["weatherPreset"], expected) << name;
      // "weather" is the preset's name, or an object naming it with settings of the graph's own.
      Json weather = readJson(out.path() / m["graph"].get<std::string>())["weather"];
      EXPECT_EQ(weather.is_object() ? weather["preset"] : weather, expected) << name;
    }
  }
}

TEST(GltfImportPresets, BadPresetOptionsAreUsageErrors) {
  CraftedModel crafted("names.gltf", namedMaterialsModel());
  for (const std::string options : {"--preset-map nonsense", "--preset-map '*=blizzard'", "--preset-map '*Red*=foliage,'",
                                    "--weather-preset rock --preset-map '*=rock'", "--weather-preset blizzard"}) {
    SCOPED_TRACE(options);
    TempDir dir("gltf-usage");
    ImportRun run = importJson(crafted.model, dir.path() / "out", options);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_EQ(codesOf(run.diagnostics), std::set<std::string>{"WG9001"}) << run.output;
    EXPECT_EQ(changes({}, snapshot(dir.path())), "") << "a usage error wrote something";
  }
}

// ---------------------------------------------------------------------------------------
// An existing output directory.

TEST(GltfImportOutputDirectory, KeepsUnrelatedFilesAndAFailedImportChangesNothing) {
  CraftedModel good("names.gltf", namedMaterialsModel());
  CraftedModel bad("names.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"scene\": 3}");
  TempDir dir("gltf-existing");
  const fs::path out = dir.path() / "out";
  writeFile(dir.path() / "beside.txt", "not the import's");
  fs::create_directories(out / "sub");
  writeFile(out / "notes.txt", "mine");
  writeFile(out / ".hidden", "also mine");
  writeFile(out / "sub" / "names_Blue.json", "a graph of my own");
  const Snapshot unrelated = snapshot(dir.path());

  expectRejected(bad.model, "WG5003");  // a control: the bad model fails on its own
  ImportRun failed = importJson(bad.model, out);
  EXPECT_EQ(failed.exitCode, 1) << failed.output;
  EXPECT_EQ(changes(unrelated, snapshot(dir.path())), "") << "a failed import changed the directory";

  auto r = import(good.model, out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const Snapshot imported = snapshot(dir.path());
  for (const auto& [name, bytes] : unrelated) {
    auto it = imported.find(name);
    EXPECT_TRUE(it != imported.end() && it->second == bytes) << name << " was not kept";
  }
  EXPECT_EQ(imported.size(), unrelated.size() + kMaterialNames.size() + 1);  // the graphs and the index

  failed = importJson(bad.model, out);
  EXPECT_EQ(failed.exitCode, 1) << failed.output;
  EXPECT_EQ(changes(imported, snapshot(dir.path())), "") << "a failed import changed the directory";
}

}  // namespace
}  // namespace wg
