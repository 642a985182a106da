// The CLI's option table: one parser for every command, over the glslc-style grammar.
#include "cli/option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace wg {
namespace {

// A small command: -o/--output DIR, -j N (checked), --target (repeatable, joined),
// --quiet/-q, --help (ends the parse), and file operands.
struct Parsed {
  std::string output, targets;
  int jobs = 0;
  bool quiet = false, help = false;
  std::vector<std::string> files;
};

OptionTable testTable(Parsed& p) {
  return {.options = {
              {"--output", "-o", "DIR", "output directory", storeValue(p.output)},
              {"-j", "", "N", "jobs",
               [&p](const std::string& v) {
                 if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos) return std::string("-j takes a count");
                 p.jobs = std::stoi(v);
                 return std::string();
               }},
              {"--target", "", "LIST", "targets\nover two lines",
               [&p](const std::string& v) {
                 p.targets += (p.targets.empty() ? "" : ",") + v;
                 return std::string();
               }},
              {"--quiet", "-q", "", "no output", storeFlag(p.quiet)},
              {"--help", "-h", "", "", storeFlag(p.help), true},
          },
          .operand = [&p](const std::string& f) {
            p.files.push_back(f);
            return std::string();
          },
          .unknownSuffix = "; run --help"};
}

OptionParseResult parse(Parsed& p, std::vector<std::string> args) {
  CommandLine line(std::move(args));
  return parseOptions(testTable(p), line);
}

TEST(OptionTable, ValueAfterEqualsOrAsNextArgument) {
  Parsed p;
  EXPECT_EQ(parse(p, {"--output=out", "a.json"}).status, OptionParse::Finished);
  EXPECT_EQ(p.output, "out");
  Parsed q;
  EXPECT_EQ(parse(q, {"--output", "dir", "a.json"}).status, OptionParse::Finished);
  EXPECT_EQ(q.output, "dir");
  EXPECT_EQ(q.files, std::vector<std::string>{"a.json"});
}

TEST(OptionTable, ShortNameTakesAnAttachedValueOrTheNextArgument) {
  Parsed p;
  EXPECT_EQ(parse(p, {"-oDIR", "-j4"}).status, OptionParse::Finished);
  EXPECT_EQ(p.output, "DIR");
  EXPECT_EQ(p.jobs, 4);
  Parsed q;
  EXPECT_EQ(parse(q, {"-o", "x", "-j", "2"}).status, OptionParse::Finished);
  EXPECT_EQ(q.output, "x");
  EXPECT_EQ(q.jobs, 2);
}

TEST(OptionTable, TheNextArgumentIsAValueEvenWhenItLooksLikeAnOption) {
  Parsed p;
  EXPECT_EQ(parse(p, {"--output", "--quiet"}).status, OptionParse::Finished);
  EXPECT_EQ(p.output, "--quiet");
  EXPECT_FALSE(p.quiet);
}

TEST(OptionTable, MissingValueNamesTheOptionAsWritten) {
  Parsed p;
  auto r = parse(p, {"a.json", "-o"});
  EXPECT_EQ(r.status, OptionParse::Failed);
  EXPECT_EQ(r.error, "option '-o' needs a value");
  Parsed q;
  EXPECT_EQ(parse(q, {"--output"}).error, "option '--output' needs a value");
}

TEST(OptionTable, UnknownOptionIsQuotedWithADidYouMean) {
  Parsed p;
  auto r = parse(p, {"--outptu", "x"});
  EXPECT_EQ(r.status, OptionParse::Failed);
  EXPECT_EQ(r.error, "unknown option '--outptu'; did you mean '--output'?");
  Parsed q;
  EXPECT_EQ(parse(q, {"--frobnicate"}).error, "unknown option '--frobnicate'; run --help");
  Parsed e;
  EXPECT_EQ(parse(e, {"--\x1b[2J"}).error, "unknown option '--\\x1b[2J'; run --help");
}

TEST(OptionTable, DoubleDashEndsOptions) {
  Parsed p;
  EXPECT_EQ(parse(p, {"-q", "--", "-o", "--", "--quiet"}).status, OptionParse::Finished);
  EXPECT_TRUE(p.quiet);
  EXPECT_EQ(p.output, "");
  EXPECT_EQ(p.files, (std::vector<std::string>{"-o", "--", "--quiet"}));
}

TEST(OptionTable, AFlagGivenAValueIsAnError) {
  Parsed p;
  auto r = parse(p, {"--quiet=yes"});
  EXPECT_EQ(r.status, OptionParse::Failed);
  EXPECT_EQ(r.error, "unknown option '--quiet=yes'; did you mean '--quiet'?");
  EXPECT_FALSE(p.quiet);
  Parsed q;
  EXPECT_EQ(parse(q, {"-qx"}).status, OptionParse::Failed);
}

TEST(OptionTable, RepeatedOptionsGoThroughTheSetterEachTime) {
  Parsed p;
  EXPECT_EQ(parse(p, {"-o", "a", "--output=b", "--target", "glsl", "--target=hlsl"}).status, OptionParse::Finished);
  EXPECT_EQ(p.output, "b");  // the last one wins
  EXPECT_EQ(p.targets, "glsl,hlsl");
}

TEST(OptionTable, TheFirstBadValueEndsTheParse) {
  Parsed p;
  auto r = parse(p, {"-j", "x", "--bogus"});
  EXPECT_EQ(r.status, OptionParse::Failed);
  EXPECT_EQ(r.error, "-j takes a count");
}

TEST(OptionTable, AStoppingOptionEndsTheParse) {
  Parsed p;
  auto r = parse(p, {"--help", "--bogus"});
  EXPECT_EQ(r.status, OptionParse::Stopped);
  EXPECT_TRUE(p.help);
}

TEST(OptionTable, ALoneDashIsAnOperandUnlessTheTableSaysOtherwise) {
  Parsed p;
  EXPECT_EQ(parse(p, {"-", ""}).status, OptionParse::Finished);
  EXPECT_EQ(p.files, (std::vector<std::string>{"-", ""}));
  Parsed q;
  OptionTable table = testTable(q);
  table.dashIsOperand = false;
  CommandLine line(std::vector<std::string>{"-"});
  EXPECT_EQ(parseOptions(table, line).error, "unknown option '-'; run --help");
}

TEST(OptionTable, WithoutOperandsEveryArgumentIsAnOption) {
  Parsed p;
  OptionTable table = testTable(p);
  table.operand = nullptr;
  CommandLine line(std::vector<std::string>{"--", "a.json"});
  EXPECT_EQ(parseOptions(table, line).error, "unknown option '--'; run --help");
}

TEST(OptionTable, ListingAlignsDescriptionsAndLeavesOutUnlistedRows) {
  Parsed p;
  OptionTable table = testTable(p);
  table.helpColumn = 12;
  EXPECT_EQ(formatOptionList(table),
            "  -o DIR, --output DIR output directory\n"
            "  -j N        jobs\n"
            "  --target LIST targets\n"
            "              over two lines\n"
            "  -q, --quiet no output\n");
}

}  // namespace
}  // namespace wg
