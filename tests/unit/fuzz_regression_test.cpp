// Every input in tests/fuzz/regressions goes through the fuzz target's path and must
// come back as diagnostics or a material, never a crash (ASan/UBSan in CI check the rest).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/material_compiler.hpp"

namespace wg {
namespace {

TEST(FuzzRegressions, EveryCaseCompilesOrFailsCleanly) {
  std::size_t cases = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(WG_SOURCE_DIR) + "/tests/fuzz/regressions")) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    CompileOptions options;
    options.emitSpirv = false;
    CompileResult r = compileMaterialText("fuzz.json", text.str(), options);
    EXPECT_TRUE(r.material.has_value() != r.diagnostics.hasErrors()) << entry.path();
    if (r.material) {
      EXPECT_EQ(r.material->stages.size(), 4u) << entry.path();
    }
    ++cases;
  }
  EXPECT_GE(cases, 4u);
}

}  // namespace
}  // namespace wg
