// Running `weathergen import`, `compile` and `eval` on MaterialX documents from tests,
// and the stand-in images the example documents read (their own are not shipped).
#pragma once
#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "process_support.hpp"

namespace wg::testing {

struct ImportResult {
  int exitCode = -1;
  std::string output;
  nlohmann::json diagnostics;  // --diagnostics json, [] when none
};

// `weathergen import DOCUMENT -o OUT --diagnostics json EXTRA`.
ImportResult importDocument(const std::filesystem::path& document, const std::filesystem::path& out,
                            const std::string& extra = "");

// The codes of the diagnostics, sorted, e.g. {"WG5203"}.
std::vector<std::string> codesOf(const nlohmann::json& diagnostics);

// `weathergen eval GRAPH --weather-preset PRESET --at AT EXTRA` (AT as eval takes it, may
// be empty): the "outputs" object.
nlohmann::json evalOutputs(const std::filesystem::path& graph, const std::string& at = "", const std::string& extra = "",
                           const std::string& preset = "none");

// Compiles a graph for glsl, hlsl and spirv, and checks every shader with the independent
// validators (glslangValidator, spirv-val); "" or what failed.
std::string compileAndValidate(const std::filesystem::path& graph, const std::filesystem::path& work);

// A 2 x 2 RGB PNG; texels row by row from the top.
void writeStandIn(const std::filesystem::path& file, const std::array<std::array<unsigned char, 3>, 4>& texels);

// The graphs an import wrote (every .json but the index), sorted.
std::vector<std::filesystem::path> graphsIn(const std::filesystem::path& dir);

// IEC 61966-2-1 decoding of an 8-bit sRGB value.
double srgbToLinear(unsigned char byte);

}  // namespace wg::testing
