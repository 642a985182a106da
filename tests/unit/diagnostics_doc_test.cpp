// docs/diagnostics.md must be exactly what the diagnostic table generates.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "compiler/diagnostics_doc.hpp"

namespace wg {
namespace {

TEST(DiagnosticsDoc, CheckedInFileMatchesTheTable) {
  std::ifstream in(std::string(WG_SOURCE_DIR) + "/docs/diagnostics.md");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), diagnosticsMarkdown())
      << "regenerate with: build/weathergen list-diagnostics --markdown > docs/diagnostics.md";
}

TEST(DiagnosticsDoc, ListsEveryCode) {
  std::string doc = diagnosticsMarkdown();
  for (const char* code : {"WG1001", "WG2001", "WG3003", "WG4001", "WG9001", "WG9901"})
    EXPECT_NE(doc.find(std::string("| ") + code + " |"), std::string::npos) << code;
}

}  // namespace
}  // namespace wg
