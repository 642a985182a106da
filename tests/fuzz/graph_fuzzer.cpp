// libFuzzer target: arbitrary bytes as a graph file, and the graph libraries it
// includes (graph_with_libraries.hpp says how one input holds both), through the whole
// front end and both code generators (load, includes, validate, IR, passes, weather,
// GLSL and HLSL). Any crash, sanitizer report or hang is a bug; each one found becomes
// a regression case in tests/fuzz/regressions/.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "tests/fuzz/graph_with_libraries.hpp"

namespace {

const std::filesystem::path& fuzzDirectory() {
  // One per process, so parallel workers (-jobs) never share library files. Never
  // destroyed, so the exit handler that removes it can still read it.
  static const auto* dir = [] {
    auto* made = new std::filesystem::path(wg::fuzz::makeFuzzDirectory());
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(fuzzDirectory(), ec);
    });
    return made;
  }();
  return *dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  auto result = wg::fuzz::compileGraphWithLibraries(
      std::string_view(reinterpret_cast<const char*>(data), size), fuzzDirectory());
  // A successful compile must give all four stages; anything else is a bug too.
  if (result.material && result.material->stages.size() != 4) __builtin_trap();
  return 0;
}
