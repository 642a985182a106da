// The list commands: each prints its table as text or, with --json, as one JSON array
// for tools, and refuses what it does not take instead of ignoring it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "process_support.hpp"

namespace {

using wg::testing::runCommand;
using wg::testing::shellQuote;

const std::vector<std::string> kListCommands = {"list-ops", "list-passes", "list-diagnostics", "list-generators",
                                                "list-scenes"};

wg::testing::CommandResult cli(const std::string& args) {
  return runCommand(shellQuote(WG_CLI_PATH) + " " + args + " 2>&1");
}

nlohmann::json listJson(const std::string& command) {
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " " + command + " --json");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  auto json = nlohmann::json::parse(r.output, nullptr, false);
  EXPECT_TRUE(json.is_array() && !json.empty()) << command << ": " << r.output.substr(0, 500);
  return json;
}

// The first word of each text line that starts at column 0.
std::vector<std::string> textNames(const std::string& command, char separator) {
  auto r = cli(command);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::vector<std::string> names;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] != ' ') names.push_back(line.substr(0, line.find(separator)));
  return names;
}

std::vector<std::string> jsonField(const nlohmann::json& rows, const std::string& field) {
  std::vector<std::string> values;
  for (const auto& row : rows) values.push_back(row.at(field).get<std::string>());
  return values;
}

TEST(ListCommands, JsonListsWhatTheTextLists) {
  EXPECT_EQ(jsonField(listJson("list-scenes"), "name"), textNames("list-scenes", '\t'));
  EXPECT_EQ(jsonField(listJson("list-ops"), "name"), textNames("list-ops", ' '));
  EXPECT_EQ(jsonField(listJson("list-diagnostics"), "code"), textNames("list-diagnostics", ' '));
  EXPECT_EQ(jsonField(listJson("list-generators"), "name"), textNames("list-generators", ':'));
  // "1. weather-inject  summary": the JSON array is in the same order.
  const auto passNames = jsonField(listJson("list-passes"), "name");
  const std::string passes = cli("list-passes").output;
  ASSERT_FALSE(passNames.empty());
  for (std::size_t i = 0; i < passNames.size(); ++i)
    EXPECT_NE(passes.find(std::to_string(i + 1) + ". " + passNames[i] + " "), std::string::npos) << passes;
}

TEST(ListCommands, DiagnosticsJsonSaysEachCodesExitCodeAndArguments) {
  std::set<int> exitCodes;
  for (const auto& d : listJson("list-diagnostics")) {
    const std::string category = d.at("category");
    const int exitCode = d.at("exitCode");
    exitCodes.insert(exitCode);
    EXPECT_EQ(exitCode, category == "input" ? 1 : category == "usage" ? 2 : 3) << d;
    EXPECT_TRUE(d.at("severity") == "error" || d.at("severity") == "warning") << d;
    const std::string text = d.at("message").get<std::string>() + d.at("hint").get<std::string>();
    for (const auto& argument : d.at("arguments"))
      EXPECT_NE(text.find("{" + argument.get<std::string>() + "}"), std::string::npos) << d;
    if (d.at("code") == "WG1002") EXPECT_EQ(d.at("arguments"), nlohmann::json::parse(R"(["path", "reason", "fix"])"));
  }
  EXPECT_EQ(exitCodes, (std::set<int>{1, 2, 3}));
}

TEST(ListCommands, WhatTheyDoNotTakeIsAUsageError) {
  for (const std::string& command : kListCommands) {
    for (const std::string& args : {"--bogus", "extra", "--json --bogus", "--jsn"}) {
      auto r = cli(command + " " + args);
      EXPECT_EQ(r.exitCode, 2) << command << " " << args << ": " << r.output.substr(0, 300);
      EXPECT_NE(r.output.find("WG9001"), std::string::npos) << command << " " << args;
    }
    auto help = cli(command + " --help");
    EXPECT_EQ(help.exitCode, 0) << help.output;
    EXPECT_NE(help.output.find("Usage: weathergen " + command), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("--json"), std::string::npos) << help.output;
    if (command != "list-diagnostics") EXPECT_EQ(cli(command + " --markdown").exitCode, 2) << command;
  }
  EXPECT_EQ(cli("list-diagnostics --json --markdown").exitCode, 2);
  auto markdown = cli("list-diagnostics --markdown");
  EXPECT_EQ(markdown.exitCode, 0);
  EXPECT_EQ(markdown.output.rfind("# Diagnostics", 0), 0u) << markdown.output.substr(0, 200);
}

}  // namespace
