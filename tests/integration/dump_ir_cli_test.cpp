// weathergen compile --dump-ir-after=PASS: the IR on stdout after a pass or every pass,
// nothing written, independent of node ids and file order, user text escaped.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "process_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;

const std::string kCli = WG_CLI_PATH;
const std::string kRock = std::string(WG_SOURCE_DIR) + "/graphs/rock.json";

// stdout alone (stderr dropped), and the exit code.
CommandResult dumpStdout(const std::string& quotedArgs) {
  return runCommand(shellQuote(kCli) + " compile " + quotedArgs + " 2>/dev/null");
}

std::vector<std::string> headerLines(const std::string& text) {
  std::vector<std::string> headers;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("# ")) headers.push_back(line);
  return headers;
}

// The dump without its "# FILE after PASS" lines, which name the graph file.
std::string withoutHeaders(const std::string& text) {
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (!line.starts_with("# ")) out += line + "\n";
  return out;
}

TEST(DumpIrCli, PrintsTheIrAfterTheNamedPassOnStdoutAndWritesNothing) {
  TempDir temp("dump-ir");
  fs::path out = temp.path() / "out";
  auto r = dumpStdout(shellQuote(kRock) + " --dump-ir-after=cse -o " + shellQuote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(headerLines(r.output), std::vector<std::string>{"# " + kRock + " after cse"});
  for (const char* section : {"parameters:\n", "textures:\n", "nodes:\n", "outputs:\n", "  baseColor = n"})
    EXPECT_NE(r.output.find(section), std::string::npos) << section;
  EXPECT_FALSE(fs::exists(out)) << "a dump writes no outputs";
  auto stderrOnly = runCommand(shellQuote(kCli) + " compile " + shellQuote(kRock) + " --dump-ir-after cse 2>&1 1>/dev/null");
  EXPECT_EQ(stderrOnly.output, "");
  EXPECT_EQ(dumpStdout(shellQuote(kRock) + " --dump-ir-after=cse").output, r.output) << "the dump is deterministic";
}

TEST(DumpIrCli, AllPrintsAfterEveryPassInPipelineOrder) {
  auto r = dumpStdout("--dump-ir-after=all " + shellQuote(kRock) + " --variants moss");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::vector<std::string> expected;
  for (const char* variant : {"moss=off,quality=high", "moss=on,quality=high"})
    for (const char* pass : {"weather-inject", "constant-fold", "algebraic-simplify", "cse", "dead-node-elim", "topo-order", "vertex-rate"})
      expected.push_back("# " + kRock + " [" + variant + "] after " + pass);
  EXPECT_EQ(headerLines(r.output), expected);
}

TEST(DumpIrCli, AnUnknownPassIsAUsageErrorWithAHint) {
  auto r = runCommand(shellQuote(kCli) + " compile " + shellQuote(kRock) + " --dump-ir-after=constant-folt 2>&1");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("WG9001"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("did you mean 'constant-fold'?"), std::string::npos) << r.output;
  auto missing = runCommand(shellQuote(kCli) + " compile " + shellQuote(kRock) + " --dump-ir-after 2>&1");
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
}

const char* kGraph = R"({"name": "m", "parameters": {"tint": {"type": "vec3", "default": [0.5, 0.4, 0.3]}},
  "nodes": [
    {"id": "idUv", "op": "texcoord"},
    {"id": "idNoise", "op": "value_noise", "inputs": {"p": "idUv.out", "scale": 8}},
    {"id": "idTint", "op": "parameter", "param": "tint"},
    {"id": "idMix", "op": "multiply", "inputs": {"a": "idTint.out", "b": "idNoise.out"}}],
  "output": {"baseColor": "idMix.out", "roughness": "idNoise.out"}})";

// The same graph, ids renamed (links follow) and nodes in another order.
const char* kRenamedAndShuffled = R"({"name": "m", "parameters": {"tint": {"type": "vec3", "default": [0.5, 0.4, 0.3]}},
  "nodes": [
    {"id": "Zz_mix", "op": "multiply", "inputs": {"b": "else.out", "a": "t0.out"}},
    {"id": "t0", "op": "parameter", "param": "tint"},
    {"id": "else", "op": "value_noise", "inputs": {"scale": 8, "p": "coords.out"}},
    {"id": "coords", "op": "texcoord"}],
  "output": {"roughness": "else.out", "baseColor": "Zz_mix.out"}})";

// Only the ids renamed: the order before topo-order follows the file, so this shows
// that no pass's dump depends on how the ids are spelled.
const char* kRenamed = R"({"name": "m", "parameters": {"tint": {"type": "vec3", "default": [0.5, 0.4, 0.3]}},
  "nodes": [
    {"id": "coords", "op": "texcoord"},
    {"id": "else", "op": "value_noise", "inputs": {"p": "coords.out", "scale": 8}},
    {"id": "t0", "op": "parameter", "param": "tint"},
    {"id": "Zz_mix", "op": "multiply", "inputs": {"a": "t0.out", "b": "else.out"}}],
  "output": {"baseColor": "Zz_mix.out", "roughness": "else.out"}})";

TEST(DumpIrCli, IsIndependentOfNodeIdsAndOfFileOrderOnceOrdered) {
  TempDir temp("dump-ir-names");
  writeFile(temp.path() / "a.json", kGraph);
  writeFile(temp.path() / "b.json", kRenamedAndShuffled);
  writeFile(temp.path() / "c.json", kRenamed);
  auto dump = [&](const char* file, const char* pass) {
    auto r = dumpStdout(shellQuote((temp.path() / file).string()) + " --dump-ir-after=" + pass);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return withoutHeaders(r.output);
  };
  EXPECT_EQ(dump("a.json", "topo-order"), dump("b.json", "topo-order"));
  EXPECT_EQ(dump("a.json", "all"), dump("c.json", "all"));
  std::string text = dump("a.json", "all");
  for (const char* id : {"idUv", "idNoise", "idTint", "idMix"}) EXPECT_EQ(text.find(id), std::string::npos) << id;
}

TEST(DumpIrCli, EscapesControlCharactersInNames) {
  TempDir temp("dump-ir-escape");
  writeFile(temp.path() / "esc.json",
            R"({"name": "esc", "parameters": {"tint\u001b[31m\nx": {"type": "float", "default": 0.5}},
                "nodes": [{"id": "p", "op": "parameter", "param": "tint\u001b[31m\nx"}],
                "output": {"roughness": "p.out"}})");
  auto r = dumpStdout(shellQuote((temp.path() / "esc.json").string()) + " --dump-ir-after=topo-order");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos);
  EXPECT_NE(r.output.find("'tint\\x1b[31m\\x0ax'"), std::string::npos) << r.output;
}

TEST(DumpIrCli, AGraphErrorIsReportedAsInACompile) {
  TempDir temp("dump-ir-bad");
  writeFile(temp.path() / "bad.json", R"({"name": "bad", "nodes": [{"id": "a", "op": "nope"}], "output": {}})");
  auto r = runCommand(shellQuote(kCli) + " compile " + shellQuote((temp.path() / "bad.json").string()) +
                      " --dump-ir-after=all 2>&1");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("WG2001"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("# "), std::string::npos) << "no IR is printed for a graph that does not build";
}

}  // namespace
}  // namespace wg::testing
