// weathergen: compile JSON material graphs into weather-aware GLSL, HLSL and SPIR-V.
#include <cstdio>
#include <cstring>
#include <string>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "compiler/literal.hpp"

namespace {

constexpr const char* kUsage = R"(weathergen - weather-aware material graph compiler

Usage:
  weathergen compile GRAPH... -o DIR [options]   compile material graphs
  weathergen eval GRAPH [options]                evaluate a material at one point on the CPU
  weathergen stats GRAPH... [--json]             SPIR-V cost per material, tier, stage, language
  weathergen import MODEL.gltf -o DIR            glTF 2.0 materials -> weather-aware graphs
  weathergen render --scene NAME -o OUT.png      draw a validation scene on Vulkan (lavapipe)
  weathergen bench-render [--scene NAME]         GPU time of the weather, timestamp queries
  weathergen bench-snow                          GPU time and memory of the deformable snow
  weathergen list-ops [--json]                   every node op with its ports
  weathergen list-passes [--json]                the IR pass pipeline, in order
  weathergen list-diagnostics [--json]           every diagnostic code
  weathergen list-generators [--json]            built-in procedural textures
  weathergen list-scenes [--json]                the bundled validation scenes
  weathergen --help | --version

Run 'weathergen COMMAND --help' for a command's options.
Exit codes: 0 success, 1 bad input, 2 bad usage, 3 internal error.
)";

}  // namespace

int runSubcommand(int argc, char** argv);

// No input may end the process by a signal: anything a command lets escape is a bug,
// reported as WG9900 with exit 3 instead of std::terminate.
int main(int argc, char** argv) {
  try {
    return runSubcommand(argc, argv);
  } catch (const std::exception& e) {
    return wg::internalError(&e);
  } catch (...) {
    return wg::internalError(nullptr);
  }
}

int runSubcommand(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return wg::kExitUsage;
  }
  std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::fputs(kUsage, stdout);
    return wg::kExitOk;
  }
  if (command == "--version") {
    std::printf("weathergen %s\n", WEATHERGEN_VERSION);
    return wg::kExitOk;
  }
  if (command == "compile") return wg::runCompileCommand(argc, argv);
  if (command == "eval") return wg::runEvalCommand(argc, argv);
  if (command == "stats") return wg::runStatsCommand(argc, argv);
  if (command == "import") return wg::runImportCommand(argc, argv);
  if (command == "render") return wg::runRenderCommand(argc, argv);
  if (command == "bench-render") return wg::runBenchRenderCommand(argc, argv);
  if (command == "bench-snow") return wg::runBenchSnowCommand(argc, argv);
  if (command.starts_with("list-")) return wg::runListCommand(argc, argv);
  std::fprintf(stderr, "weathergen: error WG9001: unknown command '%s'\n  hint: run 'weathergen --help' for usage\n",
               wg::quoteUserText(command).c_str());
  return wg::kExitUsage;
}
