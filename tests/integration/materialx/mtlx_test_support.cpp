#include "mtlx_test_support.hpp"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wg::testing {

namespace fs = std::filesystem;

ImportResult importDocument(const fs::path& document, const fs::path& out, const std::string& extra) {
  // -q: stdout stays empty, so the output is the diagnostics' JSON alone
  CommandResult run = runCommand(shellQuote(WG_CLI_PATH) + " import -q " + shellQuote(document.string()) + " -o " +
                                 shellQuote(out.string()) + " --diagnostics json " + extra);
  ImportResult result{run.exitCode, run.output, nlohmann::json::array()};
  if (!run.output.empty()) result.diagnostics = nlohmann::json::parse(run.output, nullptr, false);
  return result;
}

std::vector<std::string> codesOf(const nlohmann::json& diagnostics) {
  std::vector<std::string> codes;
  if (diagnostics.is_array())
    for (const auto& d : diagnostics) codes.push_back(d.value("code", ""));
  std::sort(codes.begin(), codes.end());
  codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
  return codes;
}

nlohmann::json evalOutputs(const fs::path& graph, const std::string& at, const std::string& extra, const std::string& preset) {
  CommandResult run = runCommand(shellQuote(WG_CLI_PATH) + " eval " + shellQuote(graph.string()) + " --weather-preset " + preset +
                                 (at.empty() ? "" : " --at " + at) + " " + extra + " 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  auto json = nlohmann::json::parse(run.output, nullptr, false);
  return json.is_object() ? json["outputs"] : nlohmann::json();
}

std::string compileAndValidate(const fs::path& graph, const fs::path& work) {
  fs::path out = work / graph.stem();
  CommandResult run = runCommand(shellQuote(WG_CLI_PATH) + " compile -q " + shellQuote(graph.string()) + " -o " +
                                 shellQuote(out.string()) + " 2>&1");
  if (run.exitCode != 0) return "compile: " + run.output;
  std::string failures;
  int checked = 0;
  for (const auto& name : listFiles(out)) {
    std::string stage = name.find(".vert.") != std::string::npos ? "vert" : "frag", file = shellQuote((out / name).string());
    std::string command;
    if (name.ends_with(".glsl") || name.ends_with(".hlsl"))
      command = shellQuote(WG_GLSLANG_VALIDATOR) + " -V --target-env vulkan1.1 -S " + stage +
                (name.ends_with(".hlsl") ? " -D -e main " : " ") + file + " -o /dev/null";
    else if (name.ends_with(".spv"))
      command = shellQuote(WG_SPIRV_VAL) + " --target-env vulkan1.1 " + file;
    else
      continue;
    ++checked;
    CommandResult v = runCommand(command + " 2>&1");
    if (v.exitCode != 0) failures += name + ": " + v.output + "\n";
  }
  if (checked != 8) failures += "expected 8 shaders (GLSL, HLSL, two SPIR-V; both stages), found " + std::to_string(checked);
  return failures;
}

void writeStandIn(const fs::path& file, const std::array<std::array<unsigned char, 3>, 4>& texels) {
  unsigned char bytes[12];
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) bytes[i * 3 + c] = texels[i][c];
  ASSERT_TRUE(stbi_write_png(file.c_str(), 2, 2, 3, bytes, 2 * 3)) << file;
}

std::vector<fs::path> graphsIn(const fs::path& dir) {
  std::vector<fs::path> graphs;
  for (const auto& name : listFiles(dir))
    if (name.ends_with(".json") && !name.ends_with(".import.json")) graphs.push_back(dir / name);
  return graphs;
}

double srgbToLinear(unsigned char byte) {
  double c = byte / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace wg::testing

// The examples live outside the checkout: without them, materialx_examples says so and
// skips (exit 77) instead of passing with nothing checked.
int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  bool examplesOnly = ::testing::GTEST_FLAG(filter).starts_with("MaterialXExamples");
  if (examplesOnly && !std::filesystem::is_directory(WG_MATERIALX_EXAMPLES)) {
    std::printf("SKIP: the MaterialX example documents are not at %s; set WEATHERGEN_MATERIALX_EXAMPLES to their folder\n",
                WG_MATERIALX_EXAMPLES);
    return 77;
  }
  return RUN_ALL_TESTS();
}
