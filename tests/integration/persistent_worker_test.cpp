// `weathergen compile --persistent_worker` (Bazel's JSON worker protocol) and
// `--flagfile`, as the Bazel rule in examples/bazel uses them. The rule's own test
// (examples/bazel/run-cache-test.sh) runs them under Bazel; these need no Bazel.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "process_support.hpp"

namespace {

namespace fs = std::filesystem;
using wg::testing::listFiles;
using wg::testing::readFile;
using wg::testing::runCommand;
using wg::testing::shellQuote;
using wg::testing::TempDir;
using wg::testing::writeFile;

const std::string kCli = shellQuote(WG_CLI_PATH);

std::string graph(const std::string& name) { return std::string(WG_SOURCE_DIR) + "/graphs/" + name + ".json"; }

std::string request(const std::vector<std::string>& arguments, int id) {
  return nlohmann::json{{"arguments", arguments}, {"requestId", id}}.dump() + "\n";
}

// The worker's stdout, one response a line; fails the test on anything else there.
std::vector<nlohmann::json> responses(const fs::path& stdoutFile) {
  std::vector<nlohmann::json> all;
  std::istringstream lines(readFile(stdoutFile));
  for (std::string line; std::getline(lines, line);) {
    auto response = nlohmann::json::parse(line, nullptr, false);
    EXPECT_TRUE(response.is_object()) << "not a response on the worker's stdout: " << line;
    if (response.is_object()) all.push_back(response);
  }
  return all;
}

// Runs a worker on `requests`; its stdout goes to dir/responses, and the result's
// output is its stderr (the worker's log).
wg::testing::CommandResult runWorker(const fs::path& dir, const std::string& requests) {
  writeFile(dir / "requests", requests);
  auto r = runCommand("(" + kCli + " compile --persistent_worker -q < " + shellQuote((dir / "requests").string()) +
                      " > " + shellQuote((dir / "responses").string()) + " 2> " + shellQuote((dir / "log").string()) + ")");
  r.output += readFile(dir / "log");
  return r;
}

void expectSameFiles(const fs::path& a, const fs::path& b) {
  ASSERT_EQ(listFiles(a), listFiles(b));
  for (const auto& name : listFiles(a)) EXPECT_EQ(readFile(a / name), readFile(b / name)) << name;
}

TEST(PersistentWorker, EachRequestIsTheCompileItsArgumentsAsk) {
  TempDir dir("wg-worker");
  const std::string out = (dir.path() / "worker").string();
  const std::string requests =
      request({graph("rock"), "-o", out + "/rock", "--no-cache", "-j", "1"}, 7) +
      request({(dir.path() / "missing.json").string(), "-o", out + "/missing", "--no-cache"}, 8) +
      request({graph("road"), "-o", out + "/road", "--no-cache", "--target", "glsl"}, 9);
  auto worker = runWorker(dir.path(), requests);
  ASSERT_EQ(worker.exitCode, 0) << worker.output;
  auto answers = responses(dir.path() / "responses");
  ASSERT_EQ(answers.size(), 3u);
  EXPECT_EQ(answers[0]["requestId"], 7);
  EXPECT_EQ(answers[0]["exitCode"], 0) << answers[0];
  EXPECT_EQ(answers[1]["requestId"], 8);
  EXPECT_EQ(answers[1]["exitCode"], 1) << answers[1];
  // The diagnostic reaches Bazel in the response, not the worker's log.
  EXPECT_NE(answers[1]["output"].get<std::string>().find("WG1002"), std::string::npos) << answers[1];
  EXPECT_EQ(worker.output.find("WG1002"), std::string::npos) << worker.output;
  EXPECT_FALSE(fs::exists(out + "/missing"));
  EXPECT_EQ(answers[2]["requestId"], 9);
  EXPECT_EQ(answers[2]["exitCode"], 0) << answers[2];

  // The same bytes as a compile of its own, and only the asked targets.
  auto rock = runCommand(kCli + " compile " + shellQuote(graph("rock")) + " -q --no-cache -o " +
                         shellQuote((dir.path() / "alone").string()));
  ASSERT_EQ(rock.exitCode, 0) << rock.output;
  expectSameFiles(out + "/rock", dir.path() / "alone");
  EXPECT_EQ(listFiles(out + "/road"),
            (std::vector<std::string>{"road.frag.glsl", "road.reflect.json", "road.vert.glsl"}));
}

TEST(PersistentWorker, WhatACommandPrintsGoesIntoItsResponseNotTheProtocol) {
  TempDir dir("wg-worker");
  auto worker = runWorker(dir.path(), request({"--help"}, 1) + request({"--no-such-option"}, 2));
  ASSERT_EQ(worker.exitCode, 0) << worker.output;
  auto answers = responses(dir.path() / "responses");
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_EQ(answers[0]["exitCode"], 0);
  EXPECT_NE(answers[0]["output"].get<std::string>().find("Usage: weathergen compile"), std::string::npos);
  EXPECT_EQ(answers[1]["exitCode"], 2);
  EXPECT_NE(answers[1]["output"].get<std::string>().find("--no-such-option"), std::string::npos);
}

TEST(PersistentWorker, ABadRequestIsAnsweredAndTheWorkerGoesOn) {
  TempDir dir("wg-worker");
  const std::string out = (dir.path() / "out").string();
  auto worker = runWorker(dir.path(), R"({"arguments": "not a list", "requestId": 3})" "\n" +
                                          request({graph("rock"), "-o", out, "--no-cache", "--target", "glsl"}, 4) +
                                          request({"--persistent_worker"}, 5) +
                                          request({graph("rock") + std::string(1, '\0') + "x", "-o", out + "2"}, 6));
  ASSERT_EQ(worker.exitCode, 0) << worker.output;
  auto answers = responses(dir.path() / "responses");
  ASSERT_EQ(answers.size(), 4u);
  EXPECT_EQ(answers[0]["requestId"], 3);
  EXPECT_EQ(answers[0]["exitCode"], 2);
  EXPECT_NE(answers[0]["output"].get<std::string>().find("arguments"), std::string::npos);
  EXPECT_EQ(answers[1]["exitCode"], 0) << answers[1];
  EXPECT_TRUE(fs::exists(out + "/rock.frag.glsl"));
  EXPECT_EQ(answers[2]["exitCode"], 2) << answers[2];
  // A path with a NUL in it is not cut short at the NUL and compiled.
  EXPECT_EQ(answers[3]["exitCode"], 2) << answers[3];
  EXPECT_NE(answers[3]["output"].get<std::string>().find("NUL"), std::string::npos) << answers[3];
  EXPECT_FALSE(fs::exists(out + "2"));
}

// Protobuf's JSON form may write an int32 as a string; an id that is no int32 cannot be
// echoed, so its request is refused rather than answered as request 0.
TEST(PersistentWorker, ARequestIdIsAnInt32AsANumberOrAString) {
  TempDir dir("wg-worker");
  const std::string out = (dir.path() / "out").string();
  auto withId = [&](const std::string& id, const std::string& subdir) {
    return R"({"arguments": [")" + graph("rock") + R"(", "-o", ")" + out + "/" + subdir +
           R"(", "--target", "glsl", "--no-cache"], "requestId": )" + id + "}\n";
  };
  auto worker = runWorker(dir.path(), withId(R"("12")", "string") + withId("2.5", "fraction") +
                                          withId("4294967296", "huge") + withId(R"("x")", "text") + withId("-3", "negative"));
  ASSERT_EQ(worker.exitCode, 0) << worker.output;
  auto answers = responses(dir.path() / "responses");
  ASSERT_EQ(answers.size(), 5u);
  EXPECT_EQ(answers[0]["requestId"], 12);
  EXPECT_EQ(answers[0]["exitCode"], 0) << answers[0];
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(answers[i]["exitCode"], 2) << answers[i];
    EXPECT_NE(answers[i]["output"].get<std::string>().find("\"requestId\""), std::string::npos) << answers[i];
  }
  EXPECT_EQ(listFiles(out), (std::vector<std::string>{"negative/rock.frag.glsl", "negative/rock.reflect.json",
                                                      "negative/rock.vert.glsl", "string/rock.frag.glsl",
                                                      "string/rock.reflect.json", "string/rock.vert.glsl"}));
  EXPECT_EQ(answers[4]["requestId"], -3);
}

// A rule that names --persistent_worker itself gets it twice once Bazel adds its own.
TEST(PersistentWorker, TheFlagTwiceOnTheWorkersCommandLineIsOneWorker) {
  TempDir dir("wg-worker");
  writeFile(dir.path() / "requests",
            request({graph("rock"), "-o", (dir.path() / "out").string(), "--target", "glsl", "--no-cache"}, 1));
  auto r = runCommand(kCli + " compile --persistent_worker -q --persistent_worker < " +
                      shellQuote((dir.path() / "requests").string()) + " > " + shellQuote((dir.path() / "responses").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto answers = responses(dir.path() / "responses");
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(answers[0]["exitCode"], 0) << answers[0];
}

TEST(PersistentWorker, StdinThatIsNotTheProtocolIsAUsageError) {
  TempDir dir("wg-worker");
  auto worker = runWorker(dir.path(), "graphs/rock.json -o out\n");
  EXPECT_EQ(worker.exitCode, 2) << worker.output;
  EXPECT_NE(worker.output.find("WG9001"), std::string::npos) << worker.output;
  EXPECT_NE(worker.output.find("worker protocol"), std::string::npos) << worker.output;
  EXPECT_EQ(readFile(dir.path() / "responses"), "");
}

// Bazel's default worker protocol is protobuf: the message says which request broke
// and what the action must declare.
TEST(PersistentWorker, ABrokenRequestIsNamedAndTheJsonProtocolHinted) {
  TempDir dir("wg-worker");
  auto truncated = runWorker(dir.path(), request({"--help"}, 1) + R"({"arguments": ["a.json", "-o")");
  EXPECT_EQ(truncated.exitCode, 2) << truncated.output;
  EXPECT_NE(truncated.output.find("request 2 on stdin"), std::string::npos) << truncated.output;
  EXPECT_EQ(responses(dir.path() / "responses").size(), 1u);
  auto protobuf = runWorker(dir.path(), std::string("\x0c\x0a\x06--help", 9));
  EXPECT_EQ(protobuf.exitCode, 2) << protobuf.output;
  EXPECT_NE(protobuf.output.find("request 1 on stdin"), std::string::npos) << protobuf.output;
  EXPECT_NE(protobuf.output.find("requires-worker-protocol"), std::string::npos) << protobuf.output;
}

// One request may be at most 16 MiB: an endless one ends the worker with a message, not
// with all of the machine's memory.
TEST(PersistentWorker, ARequestLongerThan16MiBIsRefused) {
  TempDir dir("wg-worker");
  auto worker = runWorker(dir.path(), request({"--help"}, 1) + request({std::string(17u << 20, 'a')}, 2));
  EXPECT_EQ(worker.exitCode, 2) << worker.output.substr(0, 2000);
  EXPECT_NE(worker.output.find("request 2 on stdin"), std::string::npos) << worker.output.substr(0, 2000);
  EXPECT_NE(worker.output.find("longer than 16 MiB"), std::string::npos) << worker.output.substr(0, 2000);
  EXPECT_EQ(responses(dir.path() / "responses").size(), 1u);
}

// A response keeps the first MiB of what its command printed, cut at a line's end.
TEST(PersistentWorker, LongOutputIsCutAtALinesEnd) {
  TempDir dir("wg-worker");
  std::vector<std::string> arguments;
  for (int i = 0; i < 15000; ++i) arguments.push_back((dir.path() / ("missing" + std::to_string(i) + ".json")).string());
  arguments.insert(arguments.end(), {"-o", (dir.path() / "out").string()});
  auto worker = runWorker(dir.path(), request(arguments, 1));
  EXPECT_EQ(worker.exitCode, 0) << worker.output;
  auto answers = responses(dir.path() / "responses");
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(answers[0]["exitCode"], 1);
  const std::string output = answers[0]["output"];
  EXPECT_LE(output.size(), (1u << 20) + 100);
  const std::size_t note = output.rfind("more bytes of output left out)\n");
  ASSERT_NE(note, std::string::npos) << output.substr(output.size() - 300);
  const std::size_t noteLine = output.rfind('\n', note);
  ASSERT_NE(noteLine, std::string::npos);
  // The line before the note is a whole line of a diagnostic.
  const std::size_t lastLine = output.rfind('\n', noteLine - 1) + 1;
  const std::string line = output.substr(lastLine, noteLine - lastLine);
  EXPECT_TRUE(line.find("WG1002") != std::string::npos || line.find("hint:") != std::string::npos) << line;
  EXPECT_EQ(line.back(), line.find("hint:") != std::string::npos ? 'y' : ']') << line;
}

TEST(FlagFile, ItsLinesAreTheArguments) {
  TempDir dir("wg-flagfile");
  const fs::path flags = dir.path() / "rock.params";
  writeFile(flags, graph("rock") + "\n-o\n" + (dir.path() / "from-file").string() + "\n--target\nglsl\n--no-cache\n");
  auto fromFile = runCommand(kCli + " compile -q --flagfile=" + shellQuote(flags.string()));
  ASSERT_EQ(fromFile.exitCode, 0) << fromFile.output;
  auto direct = runCommand(kCli + " compile -q " + shellQuote(graph("rock")) + " -o " +
                           shellQuote((dir.path() / "direct").string()) + " --target glsl --no-cache");
  ASSERT_EQ(direct.exitCode, 0) << direct.output;
  expectSameFiles(dir.path() / "from-file", dir.path() / "direct");
}

// A flag file written by hand may have CRLF line ends: "-o\r" is not an unknown option
// and "out\r" not the output directory.
TEST(FlagFile, CrlfLineEndsAndAByteOrderMarkAreRead) {
  TempDir dir("wg-flagfile");
  const fs::path flags = dir.path() / "crlf.params";
  // As a Windows editor saves it: a byte-order mark, then CRLF line ends.
  writeFile(flags, "\xEF\xBB\xBF" + graph("rock") + "\r\n-o\r\n" + (dir.path() / "out").string() +
                       "\r\n--target\r\nglsl\r\n--no-cache");
  auto r = runCommand(kCli + " compile -q --flagfile " + shellQuote(flags.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(listFiles(dir.path() / "out"),
            (std::vector<std::string>{"rock.frag.glsl", "rock.reflect.json", "rock.vert.glsl"}));
  EXPECT_FALSE(fs::exists(dir.path() / "out\r"));
}

TEST(FlagFile, AnEmptyNameOrAWorkerFlagInsideSaysWhatToChange) {
  TempDir dir("wg-flagfile");
  auto empty = runCommand(kCli + " compile " + shellQuote(graph("rock")) + " -o out --flagfile=");
  EXPECT_EQ(empty.exitCode, 2) << empty.output;
  EXPECT_NE(empty.output.find("--flagfile takes a file name (it is empty"), std::string::npos) << empty.output;
  writeFile(dir.path() / "worker.params", "--persistent_worker\n");
  auto worker = runCommand(kCli + " compile --flagfile " + shellQuote((dir.path() / "worker.params").string()));
  EXPECT_EQ(worker.exitCode, 2) << worker.output;
  EXPECT_NE(worker.output.find("not in a request or a flag file"), std::string::npos) << worker.output;
}

// Bazel writes an empty argument as an empty line; where a graph was expected, the
// message says where an empty argument comes from.
TEST(FlagFile, AnEmptyLineIsAnEmptyArgument) {
  TempDir dir("wg-flagfile");
  writeFile(dir.path() / "gap.params", graph("rock") + "\n\n-o\n" + (dir.path() / "out").string() + "\n--no-cache\n");
  auto r = runCommand(kCli + " compile --flagfile " + shellQuote((dir.path() / "gap.params").string()));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("an empty argument where a graph file was expected"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(FlagFile, AnUnreadableOrNestedOneIsAUsageErrorNamingIt) {
  TempDir dir("wg-flagfile");
  auto missing = runCommand(kCli + " compile --flagfile " + shellQuote((dir.path() / "none.params").string()));
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
  EXPECT_NE(missing.output.find("none.params"), std::string::npos) << missing.output;
  auto directory = runCommand(kCli + " compile --flagfile=" + shellQuote(dir.path().string()));
  EXPECT_EQ(directory.exitCode, 2) << directory.output;
  EXPECT_NE(directory.output.find("directory"), std::string::npos) << directory.output;
  writeFile(dir.path() / "binary.params", graph("rock") + std::string(1, '\0') + "\n-o\n" + dir.path().string() + "/out\n");
  auto binary = runCommand(kCli + " compile --flagfile " + shellQuote((dir.path() / "binary.params").string()));
  EXPECT_EQ(binary.exitCode, 2) << binary.output;
  EXPECT_NE(binary.output.find("NUL"), std::string::npos) << binary.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  writeFile(dir.path() / "outer.params", "--flagfile\n" + (dir.path() / "outer.params").string() + "\n");
  auto nested = runCommand(kCli + " compile --flagfile " + shellQuote((dir.path() / "outer.params").string()));
  EXPECT_EQ(nested.exitCode, 2) << nested.output;
  EXPECT_NE(nested.output.find("inside a flag file"), std::string::npos) << nested.output;
}

}  // namespace
