// libFuzzer target: arbitrary bytes as a graph file through the whole front end and
// both code generators (load, validate, IR, passes, weather, GLSL and HLSL). Any
// crash, sanitizer report or hang is a bug; each one found becomes a regression case
// in tests/fuzz/regressions/.
#include <cstddef>
#include <cstdint>
#include <string>

#include "compiler/material_compiler.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // SPIR-V stays off: glslang only ever sees text we generated, and skipping it keeps
  // the fuzzer fast enough to explore the loader and the passes.
  wg::CompileOptions options;
  options.emitSpirv = false;
  auto result = wg::compileMaterialText("fuzz.json", std::string(reinterpret_cast<const char*>(data), size), options);
  // A successful compile must give all four stages; anything else is a bug too.
  if (result.material && result.material->stages.size() != 4) __builtin_trap();
  return 0;
}
