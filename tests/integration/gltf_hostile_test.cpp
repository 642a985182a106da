// Hostile glTF files found by review that once crashed, aborted or overwrote an input:
// each must now be a diagnostic with its code, exit 1 (or 2 for usage), and no signal.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "process_support.hpp"

namespace {

namespace fs = std::filesystem;
using wg::testing::readFile;
using wg::testing::runCommand;
using wg::testing::shellQuote;
using wg::testing::TempDir;
using wg::testing::writeFile;

constexpr const char* kOnePixelPng =
    "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR4nGP4z8DwHwAFAAH/iZk9HQAAAABJRU5ErkJggg==";

struct CliRun {
  int exitCode;
  std::string output;
};

CliRun weathergen(const std::string& args) {
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " " + args);
  return {r.exitCode, r.output};
}

void expectCode(const CliRun& r, int exitCode, const std::string& code) {
  EXPECT_EQ(r.exitCode, exitCode) << r.output;
  EXPECT_NE(r.output.find(code), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("terminate called"), std::string::npos) << r.output;
}

// tinygltf hands an image its buffer view's bytes unchecked; a view past its buffer
// once read (and with a large offset, faulted) outside the buffer.
TEST(GltfHostile, ImageBufferViewOutsideItsBuffer) {
  TempDir dir("wg-gltf-hostile");
  writeFile(dir.path() / "m.gltf",
            R"({"asset":{"version":"2.0"},"buffers":[{"uri":"data:application/octet-stream;base64,AAAAAA==","byteLength":4}],
                "bufferViews":[{"buffer":0,"byteOffset":2,"byteLength":4096}],
                "images":[{"bufferView":0,"mimeType":"image/png"}]})");
  expectCode(weathergen("import " + shellQuote((dir.path() / "m.gltf").string()) + " -o " + shellQuote((dir.path() / "o").string())),
             1, "WG5007");
  EXPECT_FALSE(fs::exists(dir.path() / "o"));
}

// tinygltf keeps texCoord in an int: 4294967295 became -1 and indexed out of bounds.
TEST(GltfHostile, TexCoordBeyondIntIsASchemaError) {
  TempDir dir("wg-gltf-hostile");
  writeFile(dir.path() / "m.gltf", std::string(R"({"asset":{"version":"2.0"},"images":[{"uri":")") + kOnePixelPng +
                                       R"("}],"textures":[{"source":0}],
                "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0,"texCoord":4294967295}}}]})");
  expectCode(weathergen("import " + shellQuote((dir.path() / "m.gltf").string()) + " -o " + shellQuote((dir.path() / "o").string())),
             1, "WG5002");
}

// Each node's scale is finite, their product is not.
TEST(GltfHostile, OverflowingWorldTransform) {
  TempDir dir("wg-gltf-hostile");
  writeFile(dir.path() / "m.gltf",
            R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
                "nodes":[{"children":[1],"scale":[1e30,1e30,1e30]},{"mesh":0,"scale":[1e30,1e30,1e30]}],
                "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
                "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
                "bufferViews":[{"buffer":0,"byteLength":36}],
                "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}]})");
  expectCode(weathergen("render --model " + shellQuote((dir.path() / "m.gltf").string()) + " --size 32x32 -q -o " +
                        shellQuote((dir.path() / "x.png").string())),
             1, "WG5007");
}

// A percent-encoded buffer URI names a file the import would otherwise overwrite.
TEST(GltfHostile, EncodedUriOfAnInputIsNeverAnOutput) {
  TempDir dir("wg-gltf-hostile");
  const std::string buffer(36, '\0');
  writeFile(dir.path() / "m_Mat.json", buffer);
  writeFile(dir.path() / "m.gltf",
            R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
                "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"materials":[{"name":"Mat"}],
                "buffers":[{"byteLength":36,"uri":"m%5FMat.json"}],"bufferViews":[{"buffer":0,"byteLength":36}],
                "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}]})");
  CliRun r = weathergen("import " + shellQuote((dir.path() / "m.gltf").string()) + " -o " + shellQuote(dir.path().string()));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(readFile(dir.path() / "m_Mat.json"), buffer);
}

// Keys of the file reach pointers; control characters in them are escaped.
TEST(GltfHostile, ControlCharactersInKeysAreEscaped) {
  TempDir dir("wg-gltf-hostile");
  writeFile(dir.path() / "m.gltf", R"({"asset":{"version":"2.0"},"nodes":[{"extensions":{"\u001b[31mRED":5}}]})");
  CliRun r = weathergen("import " + shellQuote((dir.path() / "m.gltf").string()) + " -o " + shellQuote((dir.path() / "o").string()));
  expectCode(r, 1, "WG5002");
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << "a raw ESC reached the terminal";
  EXPECT_NE(r.output.find("\\x1b[31mRED"), std::string::npos) << r.output;
}

// A file name that is not UTF-8 once aborted the JSON writer.
TEST(GltfHostile, ModelFileNameThatIsNotUtf8) {
  TempDir dir("wg-gltf-hostile");
  fs::path model = dir.path() / std::string("bad\xff.gltf");
  writeFile(model, R"({"asset":{"version":"2.0"},"materials":[{"name":"Mat"}]})");
  CliRun r = weathergen("import " + shellQuote(model.string()) + " -o " + shellQuote((dir.path() / "o").string()) + " -q");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir.path() / "o" / "bad.import.json"));
}

TEST(GltfHostile, UnusableTemporaryDirectoryIsAUsageError) {
  TempDir dir("wg-gltf-hostile");
  writeFile(dir.path() / "m.gltf",
            R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
                "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
                "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
                "bufferViews":[{"buffer":0,"byteLength":36}],
                "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}]})");
  auto r = runCommand("TMPDIR=" + shellQuote((dir.path() / "missing").string()) + " " + shellQuote(WG_CLI_PATH) + " render --model " +
                      shellQuote((dir.path() / "m.gltf").string()) + " --size 32x32 -q -o " + shellQuote((dir.path() / "x.png").string()));
  expectCode({r.exitCode, r.output}, 2, "WG9001");
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
}

}  // namespace
