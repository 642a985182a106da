// weathergen render --material (and bench-render --material), --camera orbit: and
// --watch through the CLI: any graph (bundled or a user's, with its own PNG) on the
// preview stand, the roof keeping its ground dry, framed orbit views of the stand and of a bundled scene, usage errors,
// graph errors as diagnostics, and a watch session that re-renders after edits and
// keeps the last good image through a broken one.
#include <gtest/gtest.h>

#include <signal.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <sstream>
#include <thread>

#include <glm/gtc/matrix_transform.hpp>

#include "host/image/png_file.hpp"
#include "host/scene/orbit_camera.hpp"
#include "host/scene/preview_stand.hpp"
#include "tests/integration/process_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 160, kHeight = 90;
constexpr float kAspect = float(kWidth) / float(kHeight);

constexpr const char* kChildSanitizers = kVulkanChildEnvironment;
std::string cli() { return kChildSanitizers + shellQuote(WG_CLI_PATH); }
std::string renderArgs(const fs::path& graph, const fs::path& out) {
  return cli() + " render --material " + shellQuote(graph.string()) + " -o " + shellQuote(out.string()) +
         " --size 160x90 -q";
}

Image readImage(const fs::path& path) {
  std::string error;
  auto img = image::readPng(path.string(), error);
  EXPECT_TRUE(img) << error;
  return img ? *img : Image{};
}
glm::ivec3 rgbAt(const Image& img, glm::ivec2 p) {
  const unsigned char* c = &img.rgba[(std::size_t(p.y) * img.width + p.x) * 4];
  return {c[0], c[1], c[2]};
}
bool isMagenta(glm::ivec3 c) { return c.r > 200 && c.g < 60 && c.b > 200; }

// The pixel a world point lands on (top row first, as PNGs are stored).
glm::ivec2 pixelOf(const scene::CameraPreset& c, glm::vec3 world) {
  glm::mat4 view = glm::lookAt(c.eye, c.target, glm::vec3(0.f, 1.f, 0.f));
  glm::vec4 clip = glm::perspective(glm::radians(c.fovYDegrees), kAspect, 0.1f, 600.f) * view * glm::vec4(world, 1.f);
  glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {int((ndc.x * 0.5f + 0.5f) * kWidth), int((0.5f - ndc.y * 0.5f) * kHeight)};
}

glm::vec3 centreOf(const scene::SceneObject& o) {
  scene::Bounds b = scene::bounds(o.mesh, o.model);
  return 0.5f * (b.min + b.max);
}

// A user's material: its base colour sampled from `image`, next to the graph.
std::string userGraphText(const std::string& op = "sample", const std::string& image = "magenta.png") {
  return R"({
  "name": "user",
  "textures": {"albedo": {"file": ")" + image + R"("}},
  "nodes": [
    {"id": "uv", "op": "texcoord"},
    {"id": "tex", "op": ")" + op + R"(", "inputs": {"texture": "albedo", "uv": "uv.out"}}
  ],
  "output": {"baseColor": "tex.rgb", "roughness": 0.5},
  "weather": "rock"
})";
}

Image solid(glm::ivec3 rgb) {
  Image img;
  img.width = img.height = 8;
  for (int i = 0; i < 64; ++i)
    img.rgba.insert(img.rgba.end(), {std::uint8_t(rgb.r), std::uint8_t(rgb.g), std::uint8_t(rgb.b), 255});
  return img;
}

// The user's graph in its own folder, with a magenta PNG.
fs::path writeUserGraph(const fs::path& dir, const std::string& op = "sample") {
  EXPECT_EQ(image::writePng((dir / "magenta.png").string(), solid({255, 0, 255})), "");
  fs::path graph = dir / "user.json";
  writeFile(graph, userGraphText(op));
  return graph;
}

TEST(RenderMaterialCli, DrawsAUserGraphWithItsImageOnEveryShapeOfTheStand) {
  TempDir dir("material-cli");
  fs::path graph = writeUserGraph(dir.path()), out = dir.path() / "stand.png";
  CommandResult r = runCommand(renderArgs(graph, out) + " --aov albedo --validation");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Image img = readImage(out);
  ASSERT_EQ(img.width, kWidth);
  scene::Scene stand = scene::previewStand(graph.string());
  const scene::CameraPreset& front = *stand.camera("front");
  for (auto name : scene::previewStandSubjects())
    EXPECT_TRUE(isMagenta(rgbAt(img, pixelOf(front, centreOf(*stand.find(name)))))) << name;
  for (const auto& probe : stand.probes)  // ground, in the open and under the roof
    EXPECT_FALSE(isMagenta(rgbAt(img, pixelOf(front, probe.position)))) << probe.name;
  int magenta = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) magenta += isMagenta(rgbAt(img, {x, y}));
  EXPECT_GT(magenta, kWidth * kHeight / 20);  // the shapes fill a good part of the frame
  EXPECT_LT(magenta, kWidth * kHeight / 2);   // and the ground shows round them
}

TEST(RenderMaterialCli, RoofKeepsItsGroundDryInTheRain) {
  TempDir dir("material-cli-rain");
  fs::path out = dir.path() / "wet.png", graph = fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json";
  CommandResult r = runCommand(renderArgs(graph, out) +
                               " --aov wet --weather temperature=10,precipitation=1,wetnessLevel=1 --backend hlsl");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Image img = readImage(out);
  scene::Scene stand = scene::previewStand(graph.string());
  for (const auto& probe : stand.probes) {
    int wet = rgbAt(img, pixelOf(*stand.camera("front"), probe.position)).r;
    if (probe.expect == "sheltered") EXPECT_LT(wet, 40) << probe.name;
    else EXPECT_GT(wet, 200) << probe.name;
  }
}

// The reference host's sky reflection: a chrome mirror on the stand shows the sky (it
// rendered 98 % black with the sun as its only light), and wet ground at a grazing view
// is brighter than dry, where it used to be darker at every angle.
int luminance(glm::ivec3 c) { return (2126 * c.r + 7152 * c.g + 722 * c.b) / 10000; }

TEST(RenderMaterialCli, ChromeMirrorsTheSky) {
  TempDir dir("material-cli-chrome");
  fs::path graph = dir.path() / "chrome.json", out = dir.path() / "chrome.png";
  writeFile(graph, R"({"name": "chrome", "nodes": [], "output": {"baseColor": 0.95, "metallic": 1.0, "roughness": 0.05}})");
  CommandResult r = runCommand(renderArgs(graph, out) + " --weather-preset none --camera front");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Image img = readImage(out);
  scene::Scene stand = scene::previewStand(graph.string());
  const scene::SceneObject& sphere = *stand.find("sphere");
  scene::Bounds b = scene::bounds(sphere.mesh, sphere.model);
  float radius = 0.5f * (b.max.x - b.min.x);
  // Five points on the sphere's silhouette-facing half: centre, and halfway to each side.
  glm::vec3 c = centreOf(sphere);
  for (glm::vec3 offset : {glm::vec3(0.f), glm::vec3(0.5f, 0.f, 0.f), glm::vec3(-0.5f, 0.f, 0.f),
                           glm::vec3(0.f, 0.5f, 0.f), glm::vec3(0.f, -0.3f, 0.f)})
    EXPECT_GT(luminance(rgbAt(img, pixelOf(*stand.camera("front"), c + offset * radius))), 60) << offset.x << "," << offset.y;
}

TEST(RenderMaterialCli, WetGroundAtAGrazingViewIsBrighterThanDry) {
  TempDir dir("material-cli-grazing");
  auto meanOfLowerRows = [&](const std::string& weather) {
    fs::path out = dir.path() / (weather.substr(0, 14) + ".png");
    CommandResult r = runCommand(cli() + " render --scene road --camera orbit:150,4,30 --no-precipitation --size 160x90 -q"
                                 " --weather " + weather + " -o " + shellQuote(out.string()));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    Image img = readImage(out);
    long sum = 0, count = 0;
    for (int y = kHeight * 6 / 10; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x, ++count) sum += luminance(rgbAt(img, {x, y}));
    return double(sum) / double(count);
  };
  double dry = meanOfLowerRows("temperature=12,wetnessLevel=0");
  double wet = meanOfLowerRows("temperature=12,wetnessLevel=1");
  EXPECT_GT(wet, dry * 1.05) << "dry " << dry << ", wet " << wet;
}

// A model whose size suggests other units is rendered, with one warning naming
// --model-scale; at a scale that makes it 5 m, none.
TEST(RenderMaterialCli, ModelInOtherUnitsWarnsOnceNamingModelScale) {
  TempDir dir("material-cli-units");
  const std::string model = shellQuote((fs::path(WG_SOURCE_DIR) / "tests/bad/WG5103_field-spans-500-units.gltf").string());
  const std::string render = cli() + " render --model " + model + " --size 160x90 -o " + shellQuote((dir.path() / "m.png").string());
  CommandResult metres = runCommand(render);
  ASSERT_EQ(metres.exitCode, 0) << metres.output;
  std::size_t first = metres.output.find("warning WG5103");
  ASSERT_NE(first, std::string::npos) << metres.output;
  EXPECT_EQ(metres.output.find("warning WG5103", first + 1), std::string::npos) << metres.output;
  EXPECT_NE(metres.output.find("--model-scale"), std::string::npos) << metres.output;
  CommandResult centimetres = runCommand(render + " --model-scale 0.01");
  ASSERT_EQ(centimetres.exitCode, 0) << centimetres.output;
  EXPECT_EQ(centimetres.output.find("warning WG5103"), std::string::npos) << centimetres.output;
}

TEST(RenderMaterialCli, OrbitCamerasLookAtTheStandFromAnyDirection) {
  TempDir dir("material-cli-orbit");
  fs::path graph = writeUserGraph(dir.path());
  scene::Scene stand = scene::previewStand(graph.string());
  fs::path front = dir.path() / "front.png", side = dir.path() / "side.png";
  ASSERT_EQ(runCommand(renderArgs(graph, front) + " --aov albedo").exitCode, 0);
  CommandResult r = runCommand(renderArgs(graph, side) + " --aov albedo --camera orbit:100,35");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Image a = readImage(front), b = readImage(side);
  int differing = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) differing += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1];
  EXPECT_GT(differing, kWidth * kHeight / 4);
  scene::CameraPreset orbit = scene::orbitCamera(stand, {100.f, 35.f, std::nullopt}, kAspect);
  EXPECT_GT(orbit.eye.x - orbit.target.x, 0.f);  // azimuth 90 and more: from +x
  for (auto name : scene::previewStandSubjects()) {
    glm::ivec2 p = pixelOf(orbit, centreOf(*stand.find(name)));
    ASSERT_TRUE(p.x >= 0 && p.y >= 0 && p.x < kWidth && p.y < kHeight) << name;
    EXPECT_TRUE(isMagenta(rgbAt(b, p))) << name;
  }
}

TEST(RenderMaterialCli, OrbitWorksForBundledScenes) {
  TempDir dir("scene-orbit");
  fs::path out = dir.path() / "rocks.png";
  CommandResult r = runCommand(cli() + " render --scene rocks --camera orbit:200,40,90 --size 160x90 -q -o " +
                               shellQuote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(readImage(out).height, kHeight);
}

TEST(RenderMaterialCli, BadCamerasAreUsageErrors) {
  for (const char* camera : {"orbit:30", "orbit:a,b", "orbit:0,90", "orbit:0,10,0", "orbit:0,10,-3", "orbit:1,2,3,4",
                             "orbit:", "orbit:inf,0", "nowhere"}) {
    CommandResult r = runCommand(cli() + " render --material " +
                                 shellQuote((fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json").string()) +
                                 " -o /dev/null --camera " + shellQuote(camera));
    EXPECT_EQ(r.exitCode, 2) << camera << "\n" << r.output;
    EXPECT_NE(r.output.find(std::string("'") + camera + "'"), std::string::npos) << r.output;
  }
}

TEST(RenderMaterialCli, UsageErrorsNameTheProblem) {
  std::string rock = shellQuote((fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json").string());
  for (const std::string& args : {std::string("--material rock -o /dev/null"), "--material " + rock + " --scene rocks -o /dev/null",
                                  std::string("--scene rocks --watch -o /dev/null"), "--material " + rock + " --watch-renders 2 -o /dev/null",
                                  "--material " + rock + " --watch --watch-renders 0 -o /dev/null"}) {
    CommandResult r = runCommand(cli() + " render " + args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("WG9001"), std::string::npos) << r.output;
  }
}

TEST(RenderMaterialCli, GraphErrorsPrintDiagnosticsAndExitOne) {
  TempDir dir("material-cli-bad");
  fs::path graph = writeUserGraph(dir.path(), "sampel");
  CommandResult r = runCommand(renderArgs(graph, dir.path() / "out.png"));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("user.json:6:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("error WG2001"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("[/nodes/1/op]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("hint: did you mean 'sample'?"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out.png"));
}

// The numbers of a bench-render table's row for `name`, in column order.
std::vector<double> tableRow(const std::string& output, const std::string& name) {
  std::vector<double> values;
  const std::size_t at = output.find("\n| " + name + " | ");
  if (at == std::string::npos) return values;
  std::istringstream row(output.substr(at + 4 + name.size(), output.find('\n', at + 1) - at - 4 - name.size()));
  for (std::string cell; std::getline(row, cell, '|');)
    if (cell.find_first_not_of(' ') != std::string::npos) values.push_back(std::stod(cell));
  return values;
}

// bench-render --material: the weather's frame cost for a user's graph on the stand, one
// row named after the graph; a graph that does not compile is bad input, as for render.
TEST(RenderMaterialCli, BenchRenderMeasuresAUserGraphOnTheStand) {
  TempDir dir("material-cli-bench");
  fs::path graph = writeUserGraph(dir.path());
  const std::string bench = cli() + " bench-render --size 32x18 --frames 1 --material ";
  CommandResult r = runCommand(bench + shellQuote(graph.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("\n| stand-user | "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("| valley |"), std::string::npos) << r.output;  // the stand alone
  // The last column is the weather's absolute cost; of one frame, active less none.
  EXPECT_NE(r.output.find("| active / none | active - none (ms) |\n"), std::string::npos) << r.output;
  const std::vector<double> row = tableRow(r.output, "stand-user");
  ASSERT_EQ(row.size(), 8u) << r.output;
  EXPECT_NEAR(row[7], row[3] - row[0], 0.011) << r.output;

  fs::create_directories(dir.path() / "broken");
  fs::path broken = writeUserGraph(dir.path() / "broken", "sampel");
  r = runCommand(bench + shellQuote(broken.string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("user.json:6:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("error WG2001"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("Device:"), std::string::npos) << r.output;  // no table without a row
  EXPECT_EQ(r.output.find("| scene |"), std::string::npos) << r.output;

  fs::path oddName = dir.path() / "us\x1b[31mer.json";  // the row names the file: escaped
  fs::copy_file(graph, oddName);
  r = runCommand(bench + shellQuote(oddName.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("| stand-us"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;

  r = runCommand(bench + shellQuote(graph.string()) + " --model model.glb");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--material and --model exclude each other"), std::string::npos) << r.output;
}

TEST(RenderMaterialCli, TimelineWritesTheSheetStripAndFramesOfTheStand) {
  TempDir dir("material-cli-timeline");
  fs::path out = dir.path() / "sheet.png", graph = fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json";
  CommandResult r = runCommand(cli() + " render --material " + shellQuote(graph.string()) + " --size 64x36 -q -o " +
                               shellQuote(out.string()) + " --timeline " +
                               shellQuote(WG_SOURCE_DIR "/timelines/seasons.json") + " --frames " +
                               shellQuote((dir.path() / "frames").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_GT(readImage(out).width, 3 * 64);
  EXPECT_EQ(readImage(dir.path() / "sheet.strip.png").height, 36);
  auto frames = listFiles(dir.path() / "frames");
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_EQ(frames.front(), "stand-rock-01-sunny.png");
}

// ------------------------------------------------------------------------ --watch

// Replaces a file in one step, so the watcher never reads half of it.
void replaceFile(const fs::path& path, const std::string& bytes) {
  writeFile(path.string() + ".new", bytes);
  fs::rename(path.string() + ".new", path);
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Waits until the log holds `count` lines with `what`, the command ends or two minutes pass.
bool waitForLog(const fs::path& log, const std::string& what, std::size_t count, const std::atomic<bool>& ended) {
  auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (std::chrono::steady_clock::now() < deadline) {
    bool last = ended;  // read before the log: a line written just before the end counts
    if (occurrences(readFile(log), what) >= count) return true;
    if (last) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

TEST(RenderMaterialCli, WatchRendersAfterEditsAndKeepsTheLastGoodImageThroughErrors) {
  TempDir dir("material-cli-watch");
  fs::path graph = writeUserGraph(dir.path()), out = dir.path() / "out.png", log = dir.path() / "watch.log";
  auto writeImage = [&](const char* name, glm::ivec3 rgb) {
    EXPECT_EQ(image::writePng((dir.path() / name).string(), solid(rgb)), "");
  };
  CommandResult result;
  std::atomic<bool> ended{false};
  // Five renders: the first, after an image edit, a broken graph, the fix (which reads
  // a new image), and after an edit of that new image.
  std::thread watcher([&] {
    std::string args = renderArgs(graph, out).substr(std::string(kChildSanitizers).size());
    result = runCommand(kChildSanitizers + std::string("timeout 300 ") + args + " --aov albedo --watch --watch-renders 5 > " +
                        shellQuote(log.string()) + " 2>&1");
    ended = true;
  });
  auto seen = [&](const std::string& what, std::size_t count) {
    bool found = waitForLog(log, what, count, ended);
    EXPECT_TRUE(found) << "waiting for " << count << " x '" << what << "'\n" << readFile(log);
    return found;
  };
  std::string first, second, third;
  if (seen("rendered", 1)) {
    first = readFile(out);
    writeImage("magenta.png", {0, 255, 0});
  }
  if (seen("rendered", 2)) {
    second = readFile(out);
    EXPECT_NE(first, second) << "the image edit shows";
    replaceFile(graph, userGraphText("sampel"));
  }
  if (seen("failed", 1)) {
    EXPECT_EQ(readFile(out), second) << "the last good image is kept byte for byte";
    writeImage("extra.png", {255, 255, 255});
    replaceFile(graph, userGraphText("sample", "extra.png"));
  }
  if (seen("rendered", 3)) {
    third = readFile(out);
    EXPECT_NE(third, second) << "the fix shows";
    writeImage("extra.png", {90, 90, 90});  // newly read by the fix: watched from now on
  }
  if (seen("rendered", 4)) EXPECT_NE(readFile(out), third) << "the new image is watched";
  watcher.join();
  std::string text = readFile(log);
  EXPECT_EQ(result.exitCode, 0) << text;
  EXPECT_EQ(occurrences(text, "rendered " + out.string() + " in "), 4u) << text;
  EXPECT_NE(text.find("user.json:6:"), std::string::npos) << text;
  EXPECT_NE(text.find("error WG2001"), std::string::npos) << text;
}

TEST(RenderMaterialCli, WatchStopsCleanlyOnSigterm) {
  TempDir dir("material-cli-stop");
  fs::path graph = writeUserGraph(dir.path()), out = dir.path() / "out.png", log = dir.path() / "watch.log";
  fs::path pid = dir.path() / "pid";
  std::atomic<bool> ended{false};
  std::thread watcher([&] {
    runCommand("(" + renderArgs(graph, out) + " --watch > " + shellQuote(log.string()) + " 2>&1 & echo $! > " +
               shellQuote(pid.string()) + "; wait $!; echo \"exit $?\" >> " + shellQuote(log.string()) + ")");
    ended = true;
  });
  EXPECT_TRUE(waitForLog(log, "rendered", 1, ended)) << readFile(log);
  ::kill(std::stoi(readFile(pid)), SIGTERM);
  watcher.join();
  EXPECT_NE(readFile(log).find("exit 0"), std::string::npos) << readFile(log);
  EXPECT_TRUE(fs::exists(out));
}

}  // namespace
}  // namespace wg::testing
