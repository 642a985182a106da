// The bad-input catalog (tests/bad/): one minimal graph per Input diagnostic code, each
// producing exactly that code, through the CLI and through the library. Also: coverage
// of the code table, reporting several independent errors, the text diagnostic format
// and command-line usage errors.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/diagnostic_codes.hpp"
#include "driver/material_compiler.hpp"
#include "import/gltf_asset.hpp"
#include "import/model_geometry.hpp"
#include "import/model_import.hpp"
#include "import/mtlx_import.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kBadDir = fs::path(WG_SOURCE_DIR) / "tests" / "bad";

// Catalog entries are named "<CODE>_<short-kebab-description>.json", or .gltf/.glb/.mtlx
// for the codes of glTF models and MaterialX documents, which go through `weathergen import`.
const std::regex kCatalogName(R"(^(WG[0-9]{4})_[a-z0-9]+(-[a-z0-9]+)*\.(json|gltf|glb|mtlx)$)");

struct CatalogEntry {
  std::string code;  // from the file name, e.g. "WG2001"
  fs::path path;     // absolute

  bool isModel() const { return path.extension() != ".json"; }
  bool isWarning() const { return wg::diagnosticInfo(*wg::diagnosticFromId(code)).severity == wg::Severity::Warning; }
  // Codes about a file as a whole, before any JSON is read, have no line.
  bool hasLine() const { return code != "WG1002" && code != "WG5001"; }
  // A target's limits (WG6xxx) are met only when compiling for it.
  bool forFilament() const { return code == "WG6001"; }
};

std::vector<CatalogEntry> catalog() {
  std::vector<CatalogEntry> entries;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(kBadDir, ec)) {
    std::string name = e.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, kCatalogName)) entries.push_back({m[1].str(), e.path()});
  }
  std::sort(entries.begin(), entries.end(),
            [](const CatalogEntry& a, const CatalogEntry& b) { return a.path < b.path; });
  return entries;
}

// Test names: the code, with a suffix only if a code (wrongly) has several files.
std::string entryTestName(const ::testing::TestParamInfo<CatalogEntry>& info) {
  std::size_t sameCodeBefore = 0;
  auto all = catalog();
  for (std::size_t i = 0; i < all.size() && i < info.index; ++i)
    if (all[i].code == info.param.code) ++sameCodeBefore;
  return sameCodeBefore == 0 ? info.param.code : info.param.code + "_" + std::to_string(info.index);
}

void PrintTo(const CatalogEntry& e, std::ostream* os) { *os << e.path.filename().string(); }

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

struct CliRun {
  int status = -1;  // exit status; 128 + signal when killed by one
  std::string err;  // stderr
};

// Runs the CLI with already-quoted arguments, capturing stderr and discarding stdout.
CliRun runCli(const std::string& quotedArgs) {
  std::string command = shellQuote(WG_CLI_PATH) + " " + quotedArgs + " 2>&1 1>/dev/null";
  CliRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.err.append(buffer, n);
  int status = ::pclose(pipe);
  if (status == -1) run.status = -1;
  else if (WIFEXITED(status)) run.status = WEXITSTATUS(status);
  else if (WIFSIGNALED(status)) run.status = 128 + WTERMSIG(status);
  return run;
}

// A fresh, empty directory under the system temp directory, removed afterwards.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "wg-bad-input-XXXXXX").string();
    if (::mkdtemp(pattern.data())) path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    if (!path_.empty()) fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Entries under dir, recursively, relative to it ("" when dir does not exist).
std::vector<std::string> listTree(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::exists(dir, ec)) return out;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    out.push_back(fs::relative(it->path(), dir, ec).string());
  return out;
}

std::multiset<std::string> codesOf(const nlohmann::json& diagnostics) {
  std::multiset<std::string> codes;
  for (const auto& d : diagnostics)
    if (d.is_object() && d.contains("code") && d["code"].is_string()) codes.insert(d["code"].get<std::string>());
  return codes;
}

std::set<std::string> codeSet(const std::vector<wg::Diagnostic>& list) {
  std::set<std::string> codes;
  for (const auto& d : list) codes.insert(std::string(d.info().id));
  return codes;
}

std::string joined(const std::multiset<std::string>& codes) {
  std::string out;
  for (const auto& c : codes) out += (out.empty() ? "" : ", ") + c;
  return "{" + out + "}";
}

// Parses CLI stderr in --diagnostics json form; fails the test on anything else.
nlohmann::json parseDiagnosticsJson(const std::string& err) {
  nlohmann::json j = nlohmann::json::parse(err, nullptr, /*allow_exceptions=*/false);
  EXPECT_FALSE(j.is_discarded()) << "stderr is not JSON:\n" << err;
  EXPECT_TRUE(j.is_array()) << "stderr is not a JSON array:\n" << err;
  return j.is_array() ? j : nlohmann::json::array();
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---------------------------------------------------------------------------------------
// Coverage: the catalog and the code table agree.

TEST(BadInputCatalog, DirectoryExistsAndIsNotEmpty) {
  ASSERT_TRUE(fs::is_directory(kBadDir)) << kBadDir;
  EXPECT_FALSE(catalog().empty());
}

TEST(BadInputCatalog, EveryInputCodeHasExactlyOneExample) {
  std::map<std::string, std::vector<std::string>> byCode;
  for (const auto& e : catalog()) byCode[e.code].push_back(e.path.filename().string());
  for (const auto& info : wg::allDiagnostics()) {
    if (info.category != wg::DiagCategory::Input) continue;
    auto it = byCode.find(std::string(info.id));
    if (it == byCode.end()) {
      ADD_FAILURE() << "Input code " << info.id << " (" << info.name << ") has no example in tests/bad/; add "
                    << info.id << "_<short-kebab-description>.json";
      continue;
    }
    EXPECT_EQ(it->second.size(), 1u) << info.id << " has several examples: " << ::testing::PrintToString(it->second);
  }
}

TEST(BadInputCatalog, EveryExampleNamesAnExistingInputCode) {
  for (const auto& e : catalog()) {
    auto code = wg::diagnosticFromId(e.code);
    if (!code) {
      ADD_FAILURE() << e.path.filename() << " names " << e.code << ", which is not a diagnostic code";
      continue;
    }
    EXPECT_EQ(wg::diagnosticInfo(*code).category, wg::DiagCategory::Input)
        << e.path.filename() << " names " << e.code << ", which is not of category Input";
  }
}

// A misnamed example would otherwise be skipped silently.
TEST(BadInputCatalog, HoldsOnlyExamplesReadmeAndAssets) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(kBadDir, ec)) {
    std::string name = e.path().filename().string();
    if (name == "README.md" || name == "assets" || std::regex_match(name, kCatalogName)) continue;
    ADD_FAILURE() << "tests/bad/" << name << " is not named <CODE>_<short-kebab-description>.json";
  }
}

TEST(BadInputCatalog, ReadmeListsEveryExample) {
  std::string readme = readText(kBadDir / "README.md");
  ASSERT_FALSE(readme.empty()) << "tests/bad/README.md is missing";
  for (const auto& e : catalog())
    EXPECT_NE(readme.find(e.path.filename().string()), std::string::npos)
        << "tests/bad/README.md does not mention " << e.path.filename();
}

// ---------------------------------------------------------------------------------------
// Each example through the CLI.

class BadInputCatalogCli : public ::testing::TestWithParam<CatalogEntry> {};
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(BadInputCatalogCli);

TEST_P(BadInputCatalogCli, ExitsOneWithExactlyItsCodeAndWritesNothing) {
  const CatalogEntry& entry = GetParam();
  const std::string file = entry.path.string();
  TempDir temp;
  ASSERT_FALSE(temp.path().empty());
  const fs::path out = temp.path() / "out";

  std::string command = entry.isModel() ? "import -q " : "compile ";
  std::string target = entry.forFilament() ? " --target filament" : "";
  CliRun run = runCli(command + shellQuote(file) + " -o " + shellQuote(out.string()) + target + " --diagnostics json");
  EXPECT_EQ(run.status, entry.isWarning() ? 0 : 1) << "stderr:\n" << run.err;
  nlohmann::json diagnostics = parseDiagnosticsJson(run.err);
  ASSERT_FALSE(diagnostics.empty()) << "no diagnostics; stderr:\n" << run.err;

  std::multiset<std::string> codes = codesOf(diagnostics);
  EXPECT_EQ(std::set<std::string>(codes.begin(), codes.end()), std::set<std::string>{entry.code})
      << "reported " << joined(codes) << "; stderr:\n" << run.err;

  // The document as nlohmann sees it (for pointer checks), when it parses at all.
  nlohmann::json document;
  if (fs::is_regular_file(entry.path) && entry.path.extension() != ".glb")
    document = nlohmann::json::parse(readText(entry.path), nullptr, /*allow_exceptions=*/false);

  for (const auto& d : diagnostics) {
    SCOPED_TRACE(d.dump());
    ASSERT_TRUE(d.is_object());
    EXPECT_EQ(d.value("severity", ""), entry.isWarning() ? "warning" : "error");
    EXPECT_EQ(d.value("file", ""), file);
    ASSERT_TRUE(d.contains("line") && d["line"].is_number_integer());
    ASSERT_TRUE(d.contains("column") && d["column"].is_number_integer());
    if (entry.hasLine()) {
      EXPECT_GE(d["line"].get<int>(), 1);
      EXPECT_GE(d["column"].get<int>(), 1);
    }
    ASSERT_TRUE(d.contains("pointer") && d["pointer"].is_string());
    std::string pointer = d["pointer"].get<std::string>();
    // An RFC 6901 pointer; "" is the whole document (shown as "/" in text form).
    EXPECT_TRUE(pointer.empty() || pointer.front() == '/') << "pointer '" << pointer << "'";
    if (!document.is_discarded() && !document.is_null() && (pointer.empty() || pointer.front() == '/')) {
      try {
        EXPECT_TRUE(document.contains(nlohmann::json::json_pointer(pointer)))
            << "pointer '" << pointer << "' does not name a value of the document";
      } catch (const std::exception& e) {
        ADD_FAILURE() << "pointer '" << pointer << "' is malformed: " << e.what();
      }
    }
    EXPECT_FALSE(d.value("message", "").empty());
    EXPECT_FALSE(d.value("hint", "").empty());
  }

  // A warning leaves the import's output; an error writes nothing, no temporary files either.
  if (entry.isWarning()) {
    EXPECT_FALSE(listTree(out).empty()) << "a warning stopped the import";
    return;
  }
  EXPECT_EQ(listTree(out), std::vector<std::string>{}) << "files were written for a bad input";
  for (const auto& e : listTree(temp.path()))
    EXPECT_TRUE(e == "out") << "unexpected file beside the output directory: " << e;
}

INSTANTIATE_TEST_SUITE_P(Catalog, BadInputCatalogCli, ::testing::ValuesIn(catalog()), entryTestName);

// ---------------------------------------------------------------------------------------
// Each example through the library API.

class BadInputCatalogLibrary : public ::testing::TestWithParam<CatalogEntry> {};
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(BadInputCatalogLibrary);

// A model through the import library: asset, geometry, graphs; or a MaterialX document.
wg::DiagnosticList importModelFile(const std::string& file, bool& imported) {
  wg::DiagnosticList diagnostics;
  if (file.ends_with(".mtlx")) {
    auto document = wg::mtlx::loadDocument(file, {}, diagnostics);
    imported = document && wg::mtlx::importDocument(*document, {}, diagnostics);
    return diagnostics;
  }
  auto asset = wg::gltf::loadAsset(file, diagnostics);
  std::optional<wg::gltf::ModelGeometry> geometry;
  if (asset) geometry = wg::gltf::readModelGeometry(*asset, diagnostics);
  imported = geometry && wg::gltf::importModel(*asset, *geometry, {}, diagnostics);
  return diagnostics;
}

TEST_P(BadInputCatalogLibrary, ReturnsNoMaterialAndExactlyItsCode) {
  const CatalogEntry& entry = GetParam();
  const std::string file = entry.path.string();
  if (entry.isModel()) {
    bool imported = false;
    wg::DiagnosticList diagnostics = importModelFile(file, imported);
    EXPECT_EQ(imported, entry.isWarning());
    EXPECT_EQ(codeSet(diagnostics.items()), std::set<std::string>{entry.code});
    for (const auto& d : diagnostics.items()) EXPECT_EQ(d.location.file, file) << d.message;
    return;
  }
  wg::CompileOptions options;
  options.emitFilament = entry.forFilament();
  wg::CompileResult result = wg::compileMaterialFile(file, options);
  EXPECT_FALSE(result.material.has_value());
  EXPECT_TRUE(result.diagnostics.hasErrors());
  EXPECT_EQ(codeSet(result.diagnostics.items()), std::set<std::string>{entry.code});
  for (const auto& d : result.diagnostics.items()) {
    EXPECT_EQ(d.location.file, file) << d.info().id << ": " << d.message;
    EXPECT_FALSE(d.hint.empty()) << d.info().id << ": " << d.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Catalog, BadInputCatalogLibrary, ::testing::ValuesIn(catalog()), entryTestName);

// ---------------------------------------------------------------------------------------
// All errors are reported, not only the first.

TEST(BadInputReporting, ReportsEveryIndependentError) {
  const std::string text = R"({
  "name": "three-errors",
  "nodes": [
    {"id": "x", "op": "no_such_op"},
    {"id": "uv", "op": "texcoord"},
    {"id": "b", "op": "one_minus", "inputs": {"in": "uv.nope"}},
    {"id": "d", "op": "desaturate", "inputs": {"color": [0.5, 0.5, 0.5], "amount": 2}}
  ],
  "output": {}
})";
  wg::CompileResult result = wg::compileMaterialText("three-errors.json", text, wg::CompileOptions{});
  EXPECT_FALSE(result.material.has_value());
  std::multiset<std::string> codes;
  std::map<std::string, std::string> pointerOf;
  for (const auto& d : result.diagnostics.items()) {
    codes.insert(std::string(d.info().id));
    pointerOf[std::string(d.info().id)] = d.location.pointer;
    EXPECT_EQ(d.location.file, "three-errors.json");
    EXPECT_GE(d.location.line, 1);
  }
  EXPECT_EQ(codes, (std::multiset<std::string>{"WG2001", "WG2004", "WG2010"})) << joined(codes);
  // Each error is located in its own node.
  EXPECT_TRUE(pointerOf["WG2001"].starts_with("/nodes/0")) << pointerOf["WG2001"];
  EXPECT_TRUE(pointerOf["WG2004"].starts_with("/nodes/2")) << pointerOf["WG2004"];
  EXPECT_TRUE(pointerOf["WG2010"].starts_with("/nodes/3")) << pointerOf["WG2010"];
}

// ---------------------------------------------------------------------------------------
// Text diagnostics: "file:line:col: error WGxxxx: message [pointer]" then "  hint: ...".

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(BadInputTextFormat, FileLineColumnCodeMessageAndHint) {
  const std::string file = (kBadDir / "WG2001_unknown-op.json").string();
  ASSERT_TRUE(fs::is_regular_file(file));
  TempDir temp;
  CliRun run = runCli("compile " + shellQuote(file) + " -o " + shellQuote((temp.path() / "out").string()));
  EXPECT_EQ(run.status, 1);
  auto text = lines(run.err);
  ASSERT_EQ(text.size(), 2u) << run.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_match(text[0], m, std::regex(R"(^(.+):([0-9]+):([0-9]+): error WG2001: .+ \[/.*\]$)")))
      << text[0];
  EXPECT_EQ(m[1].str(), file);
  EXPECT_GE(std::stoi(m[2].str()), 1);
  EXPECT_GE(std::stoi(m[3].str()), 1);
  EXPECT_TRUE(std::regex_match(text[1], std::regex(R"(^  hint: .+$)"))) << text[1];
}

TEST(BadInputTextFormat, UnreadableFileHasNoLineOrColumn) {
  const std::string file = (kBadDir / "WG1002_is-a-directory.json").string();
  TempDir temp;
  CliRun run = runCli("compile " + shellQuote(file) + " -o " + shellQuote((temp.path() / "out").string()));
  EXPECT_EQ(run.status, 1);
  auto text = lines(run.err);
  ASSERT_EQ(text.size(), 2u) << run.err;
  EXPECT_TRUE(text[0].starts_with(file + ": error WG1002: ")) << text[0];
  EXPECT_TRUE(std::regex_match(text[1], std::regex(R"(^  hint: .+$)"))) << text[1];
}

// ---------------------------------------------------------------------------------------
// Usage errors: exit 2 with WG9001 only, and nothing written.

void expectUsageError(const std::string& quotedArgs, const fs::path& out) {
  CliRun run = runCli(quotedArgs);
  EXPECT_EQ(run.status, 2) << "stderr:\n" << run.err;
  nlohmann::json diagnostics = parseDiagnosticsJson(run.err);
  std::multiset<std::string> codes = codesOf(diagnostics);
  EXPECT_EQ(codes, std::multiset<std::string>{"WG9001"}) << joined(codes) << "; stderr:\n" << run.err;
  for (const auto& d : diagnostics) {
    EXPECT_FALSE(d.value("message", "").empty()) << d.dump();
    EXPECT_FALSE(d.value("hint", "").empty()) << d.dump();
  }
  EXPECT_FALSE(fs::exists(out)) << "a usage error created " << out;
}

const std::string kGoodGraph = (fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json").string();

TEST(CliUsage, NoInputGraph) {
  TempDir temp;
  fs::path out = temp.path() / "out";
  expectUsageError("compile -o " + shellQuote(out.string()) + " --diagnostics json", out);
}

TEST(CliUsage, UnknownOption) {
  TempDir temp;
  fs::path out = temp.path() / "out";
  expectUsageError("compile " + shellQuote(kGoodGraph) + " -o " + shellQuote(out.string()) +
                       " --frobnicate --diagnostics json",
                   out);
}

TEST(CliUsage, UnknownTarget) {
  TempDir temp;
  fs::path out = temp.path() / "out";
  expectUsageError("compile " + shellQuote(kGoodGraph) + " -o " + shellQuote(out.string()) +
                       " --target bogus --diagnostics json",
                   out);
}

TEST(CliUsage, MissingOutputDirectory) {
  TempDir temp;
  expectUsageError("compile " + shellQuote(kGoodGraph) + " --diagnostics json", temp.path() / "out");
}

// "-o" as the last argument, with no directory after it.
TEST(CliUsage, OutputOptionWithoutValue) {
  TempDir temp;
  expectUsageError("compile " + shellQuote(kGoodGraph) + " --diagnostics json -o", temp.path() / "out");
}

}  // namespace
