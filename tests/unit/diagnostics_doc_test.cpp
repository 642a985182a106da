// docs/diagnostics.md must be exactly what the diagnostic table generates.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "compiler/diagnostic.hpp"
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

// The static check (diagnostic_codes.cpp) at run time, row by row, so a failure names it.
TEST(DiagnosticTable, TemplatesUseExactlyTheDeclaredArguments) {
  for (const auto& d : allDiagnostics()) EXPECT_EQ(checkDiagnosticRow(d), "") << d.id;
}

// Positional {0} rows are still read, but every row of the table names its arguments.
TEST(DiagnosticTable, EveryRowNamesItsArguments) {
  for (const auto& d : allDiagnostics())
    EXPECT_FALSE(d.arguments.empty() && diagnosticArgumentCount(d) > 0) << d.id << " still uses {0}, {1}...";
}

TEST(DiagnosticTable, NamedArgumentsFillInDeclaredOrder) {
  EXPECT_EQ(fillTemplate("'{b}' then '{a}', '{b}' again", {"first", "second"}, "a b"), "'second' then 'first', 'second' again");
  EXPECT_EQ(fillTemplate("{1}/{0}", {"x", "y"}), "y/x");
  const auto& info = diagnosticInfo(DiagCode::TextureUnsupported);
  EXPECT_EQ(diagnosticArgumentCount(info), 2u);
  DiagnosticList list;
  auto& d = list.report(DiagCode::TextureUnsupported, {}, {"t", "file 'a.png': not an image"});
  EXPECT_EQ(d.message, "texture 't': file 'a.png': not an image");
  EXPECT_EQ(d.hint, info.hintTemplate);
}

TEST(DiagnosticTable, CheckFindsUndeclaredAndUnusedArguments) {
  DiagnosticInfo row = diagnosticInfo(DiagCode::DuplicateTexture);
  row.arguments = "texture";  // {other} is not declared
  EXPECT_NE(checkDiagnosticRow(row), "");
  row.arguments = "texture other extra";  // extra is never used
  EXPECT_NE(checkDiagnosticRow(row), "");
  row.arguments = "";  // a positional row may not use names
  EXPECT_NE(checkDiagnosticRow(row), "");
}

#ifndef NDEBUG
TEST(DiagnosticTable, DebugBuildsRejectTheWrongNumberOfValues) {
  DiagnosticList list;
  EXPECT_THROW(list.report(DiagCode::TextureUnsupported, {}, {"t", "reason", "a hint the table now owns"}), std::logic_error);
}
#endif

}  // namespace
}  // namespace wg
