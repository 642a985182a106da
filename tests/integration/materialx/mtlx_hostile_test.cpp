// Hostile and broken MaterialX documents: each is a clear error with its code, file, line
// and column, and writes nothing; a failed import leaves an existing output directory as
// it was.
#include <gtest/gtest.h>

#include "mtlx_test_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;

// A document around `body`, the elements inside <materialx>.
std::string document(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n" + body +
         "</materialx>\n";
}

// A standard_surface material whose base_color comes from `connection` (attributes).
std::string material(const std::string& connection) {
  return "  <standard_surface name=\"SR\" type=\"surfaceshader\">\n"
         "    <input name=\"base_color\" type=\"color3\" " + connection + " />\n"
         "  </standard_surface>\n"
         "  <surfacematerial name=\"M\" type=\"material\">\n"
         "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"SR\" />\n"
         "  </surfacematerial>\n";
}

class MaterialXHostile : public ::testing::Test {
 protected:
  TempDir dir_{"mtlx-hostile"};

  fs::path write(const std::string& name, const std::string& text) {
    fs::path file = dir_.path() / name;
    writeFile(file, text);
    return file;
  }

  // The import fails with exactly `code`, each diagnostic located, and writes nothing.
  nlohmann::json expectRejected(const fs::path& doc, const std::string& code, const std::string& extra = "") {
    fs::path out = dir_.path() / "out";
    ImportResult run = importDocument(doc, out, extra);
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_EQ(codesOf(run.diagnostics), std::vector<std::string>{code}) << run.output;
    for (const auto& d : run.diagnostics) {
      EXPECT_GE(d.value("line", 0), 1) << d.dump();
      EXPECT_GE(d.value("column", 0), 1) << d.dump();
      EXPECT_FALSE(d.value("hint", "").empty()) << d.dump();
    }
    EXPECT_FALSE(fs::exists(out)) << "a failed import wrote its output directory";
    return run.diagnostics;
  }

  // A document of `element` (named `node`) feeding a material's base colour is rejected with `code`.
  void expectNodeRejected(const std::string& file, const std::string& element, const std::string& node, const std::string& code) {
    expectRejected(write(file, document("  " + element + "\n" + material("nodename=\"" + node + "\""))), code);
  }
};

// Thirty shaders that set two inputs the model cannot hold: sixty warnings of one code.
// The text shows the first twenty and counts the rest in one line; JSON lists all sixty.
TEST_F(MaterialXHostile, RepeatedWarningsAreCountedNotAllPrinted) {
  std::string body;
  for (int i = 0; i < 30; ++i) {
    const std::string n = std::to_string(i);
    body += "  <standard_surface name=\"S" + n + "\" type=\"surfaceshader\">\n"
            "    <input name=\"transmission\" type=\"float\" value=\"1\" />\n"
            "    <input name=\"coat\" type=\"float\" value=\"1\" />\n"
            "  </standard_surface>\n"
            "  <surfacematerial name=\"M" + n + "\" type=\"material\">\n"
            "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"S" + n + "\" />\n"
            "  </surfacematerial>\n";
  }
  const fs::path doc = write("many.mtlx", document(body));
  ImportResult json = importDocument(doc, dir_.path() / "json");
  ASSERT_EQ(json.exitCode, 0) << json.output;
  EXPECT_EQ(json.diagnostics.size(), 60u);
  CommandResult text = runCommand(shellQuote(WG_CLI_PATH) + " import -q " + shellQuote(doc.string()) + " -o " +
                                  shellQuote((dir_.path() / "text").string()) + " 2>&1");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  std::size_t shown = 0;
  for (std::size_t at = text.output.find("warning WG5301"); at != std::string::npos;
       at = text.output.find("warning WG5301", at + 1))
    ++shown;
  EXPECT_EQ(shown, 20u) << text.output;
  EXPECT_NE(text.output.find("note: 40 more WG5301 warnings are not shown"), std::string::npos) << text.output;
}

TEST_F(MaterialXHostile, MalformedXmlNamesLineAndColumn) {
  auto d = expectRejected(write("broken.mtlx", document("  <standard_surface name=\"SR\" type=\"surfaceshader\">\n"
                                                         "    <input name=\"base\" type=\"float\" value=\"1\">\n"
                                                         "  </standard_surface>\n")),
                          "WG5201");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]["line"], 5);  // where the mismatched end tag shows
}

TEST_F(MaterialXHostile, BillionLaughsIsRefusedAndNothingIsExpanded) {
  std::string entities = "<!DOCTYPE materialx [\n  <!ENTITY lol \"lol\">\n";
  for (int i = 1; i <= 9; ++i) {
    entities += "  <!ENTITY lol" + std::to_string(i) + " \"";
    for (int j = 0; j < 10; ++j) entities += "&lol" + (i == 1 ? std::string() : std::to_string(i - 1)) + ";";
    entities += "\">\n";
  }
  entities += "]>\n";
  std::string text = document(material("value=\"&lol9;\""));
  text.insert(text.find("<materialx"), entities);
  auto d = expectRejected(write("laughs.mtlx", text), "WG5201");
  EXPECT_NE(d[0]["message"].get<std::string>().find("DOCTYPE"), std::string::npos) << d.dump();
}

// pugixml expands only XML's five predefined entities and character references; a
// custom entity stays text, which is no colour.
TEST_F(MaterialXHostile, UndeclaredEntityStaysTextAndIsNoValue) {
  auto d = expectRejected(write("entity.mtlx", document(material("value=\"&lol9;\""))), "WG5202");
  EXPECT_NE(d[0]["message"].get<std::string>().find("&lol9;"), std::string::npos) << d.dump();
}

TEST_F(MaterialXHostile, IncludeLoopIsNamed) {
  write("b.mtlx", document("  <xi:include href=\"a.mtlx\" />\n"));
  auto d = expectRejected(write("a.mtlx", document("  <xi:include href=\"b.mtlx\" />\n" + material("value=\"1, 0, 0\""))), "WG5205");
  EXPECT_NE(d[0]["message"].get<std::string>().find("a.mtlx -> b.mtlx -> a.mtlx"), std::string::npos) << d.dump();
}

TEST_F(MaterialXHostile, IncludeOutsideTheSearchPathIsNotRead) {
  fs::create_directories(dir_.path() / "docs");
  write("outside.mtlx", document(material("value=\"1, 0, 0\"")));
  expectRejected(write("docs/inside.mtlx", document("  <xi:include href=\"../outside.mtlx\" />\n")), "WG5205");
  expectRejected(write("docs/absolute.mtlx", document("  <xi:include href=\"/etc/passwd\" />\n")), "WG5205");
}

TEST_F(MaterialXHostile, IncludeInsideASearchPathFolderIsRead) {
  fs::create_directories(dir_.path() / "docs");
  fs::create_directories(dir_.path() / "library");
  write("library/materials.mtlx", document(material("value=\"1, 0, 0\"")));
  fs::path doc = write("docs/look.mtlx", document("  <xi:include href=\"materials.mtlx\" />\n"
                                                  "  <look name=\"L\"><materialassign name=\"a\" geom=\"/g\" material=\"M\" /></look>\n"));
  ImportResult run = importDocument(doc, dir_.path() / "out", "--search-path " + shellQuote((dir_.path() / "library").string()));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto index = nlohmann::json::parse(readFile(dir_.path() / "out/look.import.json"));
  EXPECT_EQ(index["looks"][0]["assignments"][0]["graph"], "look_M.json") << index.dump(2);
}

TEST_F(MaterialXHostile, HugeAttributeIsAResourceLimit) {
  expectRejected(write("huge.mtlx", document(material("value=\"" + std::string(100000, '1') + "\""))), "WG1007");
}

TEST_F(MaterialXHostile, UnknownTypeIsASchemaError) {
  expectRejected(write("type.mtlx", document("  <constant name=\"m\" type=\"matrix44\">\n"
                                             "    <input name=\"value\" type=\"matrix44\" value=\"1\" />\n  </constant>\n" +
                                             material("nodename=\"m\""))),
                 "WG5202");
}

// strtod read "0x10" as 16 and "infinity" as a number; MaterialX reads decimal only
// (its stream parsing gives 0 for "0x10"), so a value meant one thing here and another there.
TEST_F(MaterialXHostile, HexAndNamedNumbersAreNoValues) {
  for (std::string value : {"0x10", "0x1p3", "infinity", "nan", "1e999"}) {
    SCOPED_TRACE(value);
    auto d = expectRejected(write("number.mtlx", document(material("value=\"" + value + ", 0.5, 0.5\""))), "WG5202");
    EXPECT_NE(d[0]["message"].get<std::string>().find(value), std::string::npos) << d.dump();
  }
  fs::path decimal = write("decimal.mtlx", document(material("value=\"+1.5e-1, .5, 5.\"")));
  EXPECT_EQ(importDocument(decimal, dir_.path() / "decimal").exitCode, 0);
}

// Integer inputs beyond int range were converted to int as they were (undefined; on x86
// INT_MIN): octaves of 1e20 were reported as -2147483648, and a texcoord index of 2^32 + 1
// read set 0 without the warning every other set above 1 gets.
TEST_F(MaterialXHostile, IntegersBeyondIntRangeAreReportedAsWritten) {
  auto d = expectRejected(write("octaves.mtlx", document("  <fractal3d name=\"f\" type=\"float\"><input name=\"octaves\" type=\"integer\" "
                                                         "value=\"100000000000000000000\" /></fractal3d>\n"
                                                         "  <convert name=\"c\" type=\"color3\"><input name=\"in\" type=\"float\" nodename=\"f\" /></convert>\n" +
                                                         material("nodename=\"c\""))),
                          "WG5202");
  EXPECT_NE(d[0]["message"].get<std::string>().find("1e+20"), std::string::npos) << d.dump();
  for (std::string index : {"4294967297", "-1"}) {
    SCOPED_TRACE(index);
    fs::path doc = write("set.mtlx", document("  <texcoord name=\"t\" type=\"vector2\"><input name=\"index\" type=\"integer\" value=\"" + index +
                                              "\" /></texcoord>\n"
                                              "  <convert name=\"c\" type=\"color3\"><input name=\"in\" type=\"vector2\" nodename=\"t\" /></convert>\n" +
                                              material("nodename=\"c\"")));
    ImportResult run = importDocument(doc, dir_.path() / ("set" + index));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    ASSERT_EQ(codesOf(run.diagnostics), std::vector<std::string>{"WG5302"}) << run.output;
    EXPECT_NE(run.diagnostics[0]["message"].get<std::string>().find("reads set " + index), std::string::npos) << run.output;
  }
}

TEST_F(MaterialXHostile, NodeGraphCycleIsNamed) {
  auto d = expectRejected(write("cycle.mtlx", document("  <nodegraph name=\"NG\">\n"
                                                       "    <add name=\"a\" type=\"color3\"><input name=\"in1\" type=\"color3\" nodename=\"b\" /></add>\n"
                                                       "    <add name=\"b\" type=\"color3\"><input name=\"in1\" type=\"color3\" nodename=\"a\" /></add>\n"
                                                       "    <output name=\"out\" type=\"color3\" nodename=\"a\" />\n  </nodegraph>\n" +
                                                       material("nodegraph=\"NG\" output=\"out\""))),
                          "WG5203");
  EXPECT_NE(d[0]["message"].get<std::string>().find("a -> b -> a"), std::string::npos) << d.dump();
}

// An <output> naming no node was "input 'out' names node 'x', which does not exist".
TEST_F(MaterialXHostile, OutputNamingNoNodeIsCalledAnOutput) {
  auto d = expectRejected(write("output.mtlx", document("  <nodegraph name=\"NG\">\n"
                                                        "    <output name=\"out\" type=\"color3\" nodename=\"out\" />\n  </nodegraph>\n" +
                                                        material("nodegraph=\"NG\" output=\"out\""))),
                          "WG5203");
  EXPECT_NE(d[0]["message"].get<std::string>().find("output 'out' names node 'out'"), std::string::npos) << d.dump();
}

TEST_F(MaterialXHostile, WrongTypeConnectionIsASchemaError) {
  expectNodeRejected("wrong.mtlx", R"(<constant name="f" type="float"><input name="value" type="float" value="0.5" /></constant>)", "f",
                     "WG5202");
  expectNodeRejected("vector.mtlx", R"(<constant name="v" type="vector3"><input name="value" type="vector3" value="1, 0, 0" /></constant>)",
                     "v", "WG5202");
}

TEST_F(MaterialXHostile, UnsupportedNodeIsNamed) {
  auto d = expectRejected(write("cells.mtlx", document("  <cellnoise3d name=\"cells\" type=\"float\" />\n"
                                                       "  <convert name=\"c\" type=\"color3\"><input name=\"in\" type=\"float\" nodename=\"cells\" /></convert>\n" +
                                                       material("nodename=\"c\""))),
                          "WG5204");
  EXPECT_NE(d[0]["message"].get<std::string>().find("cellnoise3d"), std::string::npos);
}

TEST_F(MaterialXHostile, MissingImageIsAnErrorOrThePlaceholder) {
  fs::path doc = write("image.mtlx", document("  <image name=\"img\" type=\"color3\"><input name=\"file\" type=\"filename\" value=\"albedo.png\" /></image>\n" +
                                              material("nodename=\"img\"")));
  auto d = expectRejected(doc, "WG5205");
  EXPECT_NE(d[0]["hint"].get<std::string>().find("--missing-images placeholder"), std::string::npos);
  ImportResult run = importDocument(doc, dir_.path() / "placeholder", "--missing-images placeholder");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(codesOf(run.diagnostics), std::vector<std::string>{"WG5302"});
  EXPECT_EQ(listFiles(dir_.path() / "placeholder"),
            (std::vector<std::string>{"image.import.json", "image_M.json", "image_placeholder.png"}));
  EXPECT_EQ(compileAndValidate(dir_.path() / "placeholder/image_M.json", dir_.path() / "shaders"), "");
  // (128, 128, 255), linear: the document names no colour space
  auto got = evalOutputs(dir_.path() / "placeholder/image_M.json");
  EXPECT_NEAR(got["baseColor"][0].get<double>(), 128 / 255.0, 1e-4);
  EXPECT_NEAR(got["baseColor"][2].get<double>(), 1.0, 1e-4);
}

// A folder where an image or include should be was "not found in DIR", which sent the
// user looking for a file that is there; with --missing-images placeholder it even
// stood in for the image.
TEST_F(MaterialXHostile, ImageOrIncludeThatIsAFolderSaysSo) {
  fs::create_directory(dir_.path() / "albedo.png");
  fs::path image = write("image.mtlx", document("  <image name=\"img\" type=\"color3\"><input name=\"file\" type=\"filename\" value=\"albedo.png\" /></image>\n" +
                                                material("nodename=\"img\"")));
  for (std::string extra : {"", "--missing-images placeholder"}) {
    SCOPED_TRACE(extra);
    auto d = expectRejected(image, "WG5205", extra);
    EXPECT_NE(d[0]["message"].get<std::string>().find("a folder, FIFO or device, not a file"), std::string::npos) << d.dump();
  }
  auto d = expectRejected(write("include.mtlx", document("  <xi:include href=\"albedo.png\" />\n" + material("value=\"1, 1, 1\""))), "WG5205");
  EXPECT_NE(d[0]["message"].get<std::string>().find("a folder, FIFO or device, not a file"), std::string::npos) << d.dump();
}

TEST_F(MaterialXHostile, ImagePathLeavingTheSearchPathIsNotRead) {
  write("secret.png", "not read");
  fs::create_directories(dir_.path() / "docs");
  for (const char* path : {"../secret.png", "/etc/passwd"})
    expectNodeRejected("docs/escape.mtlx",
                       std::string(R"(<image name="img" type="color3"><input name="file" type="filename" value=")") + path + R"(" /></image>)",
                       "img", "WG5205");
}

TEST_F(MaterialXHostile, FailedImportLeavesTheOutputDirectoryAsItWas) {
  fs::path out = dir_.path() / "kept";
  fs::create_directories(out);
  writeFile(out / "mine.txt", "keep me");
  ImportResult run = importDocument(write("bad.mtlx", document(material("nodename=\"ghost\""))), out);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(listFiles(out), std::vector<std::string>{"mine.txt"});
  EXPECT_EQ(readFile(out / "mine.txt"), "keep me");
}

// An image named as the import would name its copy, in the output directory itself.
TEST_F(MaterialXHostile, OutputThatWouldReplaceAnImageItReadsIsRefused) {
  writeStandIn(dir_.path() / "x_image0.png", {{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12}}});
  std::string before = readFile(dir_.path() / "x_image0.png");
  fs::path doc = write("x.mtlx", document(R"(  <image name="img" type="color3"><input name="file" type="filename" value="x_image0.png" /></image>)"
                                          "\n" + material("nodename=\"img\"")));
  ImportResult run = importDocument(doc, dir_.path());
  EXPECT_EQ(run.exitCode, 2) << run.output;  // a usage error: choose another output directory
  EXPECT_EQ(readFile(dir_.path() / "x_image0.png"), before);
  EXPECT_EQ(listFiles(dir_.path()), (std::vector<std::string>{"x.mtlx", "x_image0.png"}));
}

TEST_F(MaterialXHostile, SearchPathMustBeAFolder) {
  ImportResult run = importDocument(write("plain.mtlx", document(material("value=\"1, 0, 0\""))), dir_.path() / "out",
                                    "--search-path " + shellQuote((dir_.path() / "missing").string()));
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
}

TEST_F(MaterialXHostile, DiagnosticsNameTheElementPath) {
  auto d = expectRejected(write("path.mtlx", document("  <nodegraph name=\"NG\">\n"
                                                      "    <multiply name=\"m\" type=\"color3\"><input name=\"in1\" type=\"color3\" nodename=\"nobody\" /></multiply>\n"
                                                      "    <output name=\"out\" type=\"color3\" nodename=\"m\" />\n  </nodegraph>\n" +
                                                      material("nodegraph=\"NG\" output=\"out\""))),
                          "WG5203");
  EXPECT_EQ(d[0]["pointer"], "/materialx/nodegraph[NG]/multiply[m]/input[in1]");
  EXPECT_EQ(d[0]["line"], 4);
  EXPECT_EQ(d[0]["column"], 38);  // the <input element's '<'

}

// The translation recurses along node chains: a deep chain is a limit, not a crash.
TEST_F(MaterialXHostile, DeepNodeChainIsAResourceLimit) {
  std::string body = "  <constant name=\"n0\" type=\"color3\"><input name=\"value\" type=\"color3\" value=\"0.5, 0.5, 0.5\" /></constant>\n";
  for (int i = 1; i < 5000; ++i)
    body += "  <add name=\"n" + std::to_string(i) + "\" type=\"color3\"><input name=\"in1\" type=\"color3\" nodename=\"n" +
            std::to_string(i - 1) + "\" /></add>\n";
  expectRejected(write("chain.mtlx", document(body + material("nodename=\"n4999\""))), "WG1007");
}

TEST_F(MaterialXHostile, ReimportIsByteIdenticalWherever) {
  std::string text = document("  <nodegraph name=\"NG\">\n"
                              "    <noise2d name=\"n\" type=\"float\" />\n"
                              "    <convert name=\"c\" type=\"color3\"><input name=\"in\" type=\"float\" nodename=\"n\" /></convert>\n"
                              "    <output name=\"out\" type=\"color3\" nodename=\"c\" />\n  </nodegraph>\n" +
                              material("nodegraph=\"NG\" output=\"out\""));
  fs::create_directories(dir_.path() / "elsewhere/deeper");
  importDocument(write("same.mtlx", text), dir_.path() / "first");
  importDocument(write("elsewhere/deeper/same.mtlx", text), dir_.path() / "second");
  auto files = listFiles(dir_.path() / "first");
  ASSERT_EQ(files, listFiles(dir_.path() / "second"));
  ASSERT_EQ(files.size(), 2u);
  for (const auto& f : files) EXPECT_EQ(readFile(dir_.path() / "first" / f), readFile(dir_.path() / "second" / f)) << f;
}

TEST_F(MaterialXHostile, PresetMapChoosesEachMaterialsWeather) {
  std::string two = material("value=\"1, 0, 0\"");
  std::string second = two;
  for (auto [from, to] : {std::pair<std::string, std::string>{"\"SR\"", "\"SR2\""}, {"\"M\"", "\"Ground\""}})
    for (std::size_t at; (at = second.find(from)) != std::string::npos;) second.replace(at, from.size(), to);
  ImportResult run = importDocument(write("two.mtlx", document(two + second)), dir_.path() / "out", "--preset-map '*Ground*=terrain'");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto index = nlohmann::json::parse(readFile(dir_.path() / "out/two.import.json"));
  EXPECT_EQ(index["materials"][0]["weatherPreset"], "none");
  EXPECT_EQ(index["materials"][1]["weatherPreset"], "terrain");
  EXPECT_EQ(nlohmann::json::parse(readFile(dir_.path() / "out/two_Ground.json"))["weather"]["preset"], "terrain");
}

TEST_F(MaterialXHostile, OtherVersionsAreReadWithAWarning) {
  std::string text = document(material("value=\"1, 0, 0\""));
  text.replace(text.find("1.39"), 4, "1.37");
  ImportResult run = importDocument(write("old.mtlx", text), dir_.path() / "out");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(codesOf(run.diagnostics), std::vector<std::string>{"WG5302"}) << run.output;
}

}  // namespace
}  // namespace wg::testing
