// The engine API (include/weathergen/weathergen.hpp): compiles from memory, reports
// diagnostics as values, never throws on any input, and gives byte-identical results
// from many threads at once after one initialize().
// The public header comes first: it must compile on its own, without internal headers.
#include <weathergen/weathergen.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kSpirvMagic = 0x07230203;

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Graph {
  std::string file, text;
};

std::vector<Graph> bundledGraphs() {
  std::vector<Graph> graphs;
  for (const auto& e : fs::directory_iterator(fs::path(WG_SOURCE_DIR) / "graphs"))
    if (e.is_regular_file() && e.path().extension() == ".json") graphs.push_back({e.path().string(), readText(e.path())});
  std::sort(graphs.begin(), graphs.end(), [](const Graph& a, const Graph& b) { return a.file < b.file; });
  return graphs;
}

Graph rock() {
  fs::path path = fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json";
  return {path.string(), readText(path)};
}

std::string describe(const weathergen::Result& r) {
  std::string out;
  for (const auto& d : r.diagnostics) out += d.file + ": " + d.severity + " " + d.code + ": " + d.message + "\n";
  return out;
}

bool hasCode(const weathergen::Result& r, std::string_view code) {
  return std::any_of(r.diagnostics.begin(), r.diagnostics.end(), [&](const auto& d) { return d.code == code; });
}

// Everything a compile produces, for byte-for-byte comparison.
std::string fingerprint(const weathergen::Result& r) {
  std::string out = (r.ok ? "ok\n" : "failed\n") + r.name + "\n" + r.contentHash + "\n" + r.reflectionJson;
  for (const auto& s : r.stages) {
    out += s.language + "." + s.stage + "\n" + s.source;
    out.append(reinterpret_cast<const char*>(s.spirv.data()), s.spirv.size() * sizeof(std::uint32_t));
  }
  for (const auto& d : r.diagnostics) out += d.code + d.message;
  return out;
}

TEST(PublicApi, InitializeIsIdempotentFromManyThreads) {
  constexpr int kThreads = 4;
  std::vector<std::thread> threads;
  std::vector<char> results(kThreads, 0);
  for (int t = 0; t < kThreads; ++t) threads.emplace_back([&, t] { results[t] = weathergen::initialize(); });
  for (auto& t : threads) t.join();
  for (char ok : results) EXPECT_TRUE(ok);
  EXPECT_TRUE(weathergen::initialize());
}

TEST(PublicApi, VersionIsTheProjectVersion) { EXPECT_EQ(weathergen::version(), WEATHERGEN_VERSION); }

TEST(PublicApi, CompilesAGraphFromMemoryToEveryStage) {
  Graph g = rock();
  weathergen::Result r = weathergen::compile(g.file, g.text);
  ASSERT_TRUE(r.ok) << describe(r);
  EXPECT_TRUE(r.diagnostics.empty()) << describe(r);
  EXPECT_EQ(r.name, "rock");
  EXPECT_FALSE(r.contentHash.empty());
  EXPECT_NE(r.reflectionJson.find("\"contentHash\": \"" + r.contentHash + "\""), std::string::npos);
  EXPECT_TRUE(r.cppHeader.empty());  // only on request
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"glsl", "vert"}, {"glsl", "frag"}, {"hlsl", "vert"}, {"hlsl", "frag"}};
  ASSERT_EQ(r.stages.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto& s = r.stages[i];
    EXPECT_EQ(s.language, expected[i].first);
    EXPECT_EQ(s.stage, expected[i].second);
    EXPECT_FALSE(s.source.empty());
    ASSERT_FALSE(s.spirv.empty()) << s.language << " " << s.stage;
    EXPECT_EQ(s.spirv.front(), kSpirvMagic);
  }
}

TEST(PublicApi, OptionsAreHonoured) {
  Graph g = rock();
  weathergen::Options textOnly;
  textOnly.spirv = false;
  weathergen::Result r = weathergen::compile(g.file, g.text, textOnly);
  ASSERT_TRUE(r.ok) << describe(r);
  for (const auto& s : r.stages) EXPECT_TRUE(s.spirv.empty());

  weathergen::Options optimized;
  optimized.optimize = true;
  optimized.cppHeader = true;
  r = weathergen::compile(g.file, g.text, optimized);
  ASSERT_TRUE(r.ok) << describe(r);
  for (const auto& s : r.stages) EXPECT_EQ(s.spirv.front(), kSpirvMagic);
  EXPECT_NE(r.cppHeader.find("struct alignas(16) MaterialBlock"), std::string::npos);

  weathergen::Options unknownPreset;
  unknownPreset.weatherPreset = "no-such-preset";
  r = weathergen::compile(g.file, g.text, unknownPreset);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(hasCode(r, "WG4001")) << describe(r);
}

TEST(PublicApi, WhatIsNotAskedForIsLeftOut) {
  Graph g = rock();
  weathergen::Options full;
  full.spirv = false;
  const weathergen::Result all = weathergen::compile(g.file, g.text, full);
  ASSERT_TRUE(all.ok) << describe(all);
  ASSERT_EQ(all.stages.size(), 4u);
  EXPECT_FALSE(all.reflectionJson.empty());

  weathergen::Options glslOnly = full;
  glslOnly.hlsl = false;
  glslOnly.reflection = false;
  const weathergen::Result glsl = weathergen::compile(g.file, g.text, glslOnly);
  ASSERT_TRUE(glsl.ok) << describe(glsl);
  EXPECT_TRUE(glsl.reflectionJson.empty());
  EXPECT_EQ(glsl.contentHash, all.contentHash);
  ASSERT_EQ(glsl.stages.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(glsl.stages[i].language, "glsl");
    EXPECT_EQ(glsl.stages[i].stage, all.stages[i].stage);
    EXPECT_EQ(glsl.stages[i].source, all.stages[i].source);
  }

  glslOnly.spirv = true;  // SPIR-V of the GLSL stages alone
  const weathergen::Result spirv = weathergen::compile(g.file, g.text, glslOnly);
  ASSERT_TRUE(spirv.ok) << describe(spirv);
  ASSERT_EQ(spirv.stages.size(), 2u);
  for (const auto& s : spirv.stages) EXPECT_EQ(s.spirv.front(), kSpirvMagic);
}

TEST(PublicApi, ACacheDirectoryGivesTheSameResultsFromItsEntries) {
  const fs::path dir = fs::temp_directory_path() / ("weathergen-api-cache-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  Graph g = rock();
  const weathergen::Result plain = weathergen::compile(g.file, g.text);
  weathergen::Options cached;
  cached.cacheDirectory = dir.string();
  const weathergen::Result cold = weathergen::compile(g.file, g.text, cached);
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.path().extension() == ".entry";
  EXPECT_EQ(entries, 1u);
  const weathergen::Result warm = weathergen::compile(g.file, g.text, cached);
  EXPECT_EQ(fingerprint(cold), fingerprint(plain));
  EXPECT_EQ(fingerprint(warm), fingerprint(plain));
  // A directory that cannot be made leaves the cache out, not the compile.
  cached.cacheDirectory = (dir / "entry-is-not-a-directory").string();
  std::ofstream(cached.cacheDirectory) << "a file";
  EXPECT_EQ(fingerprint(weathergen::compile(g.file, g.text, cached)), fingerprint(plain));
  fs::remove_all(dir);
}

// A preset or tier of one NUL character is unknown, and is refused even when the cache
// holds the graph compiled without one: the key tells "unset" from any text.
TEST(PublicApi, ACachedCompileDoesNotAnswerForAnUnknownPresetOrTier) {
  const fs::path dir = fs::temp_directory_path() / ("weathergen-api-cache-nul-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  Graph g = rock();
  weathergen::Options options;
  options.spirv = false;
  options.cacheDirectory = dir.string();
  ASSERT_TRUE(weathergen::compile(g.file, g.text, options).ok);
  const std::string nul(1, '\0');
  weathergen::Options preset = options, tier = options;
  preset.weatherPreset = nul;
  tier.quality = nul;
  for (const weathergen::Options& hostile : {preset, tier}) {
    weathergen::Options uncached = hostile;
    uncached.cacheDirectory.clear();
    const weathergen::Result plain = weathergen::compile(g.file, g.text, uncached);
    EXPECT_FALSE(plain.ok);
    ASSERT_FALSE(plain.diagnostics.empty());
    EXPECT_EQ(fingerprint(weathergen::compile(g.file, g.text, hostile)), fingerprint(plain)) << describe(plain);
  }
  fs::remove_all(dir);
}

TEST(PublicApi, SwitchesChooseTheVariant) {
  Graph g = rock();
  weathergen::Options options;
  options.spirv = false;
  weathergen::Result high = weathergen::compile(g.file, g.text, options);
  options.switches = {{"quality", "low"}};
  weathergen::Result low = weathergen::compile(g.file, g.text, options);
  ASSERT_TRUE(high.ok && low.ok) << describe(low);
  EXPECT_NE(high.contentHash, low.contentHash);
  options.switches = {{"quality", "ultra"}};
  EXPECT_TRUE(hasCode(weathergen::compile(g.file, g.text, options), "WG2017"));
  options.switches = {{"qualty", "low"}};
  EXPECT_TRUE(hasCode(weathergen::compile(g.file, g.text, options), "WG2015"));
}

TEST(PublicApi, EffectsSwitchTheGraphsOwn) {
  Graph g = rock();
  weathergen::Options options;
  options.spirv = false;
  weathergen::Result full = weathergen::compile(g.file, g.text, options);
  options.effects = {{"specularAntiAliasing", false}};
  weathergen::Result lean = weathergen::compile(g.file, g.text, options);
  ASSERT_TRUE(full.ok && lean.ok) << describe(lean);
  EXPECT_NE(full.contentHash, lean.contentHash);
  auto fragment = [](const weathergen::Result& r) {
    for (const auto& s : r.stages)
      if (s.language == "glsl" && s.stage == "frag") return s.source;
    return std::string();
  };
  EXPECT_NE(fragment(full).find("wg_specular_aa("), std::string::npos);
  EXPECT_EQ(fragment(lean).find("wg_specular_aa("), std::string::npos);
  options.effects = {{"specularAA", false}};
  weathergen::Result unknown = weathergen::compile(g.file, g.text, options);
  EXPECT_FALSE(unknown.ok);
  EXPECT_TRUE(hasCode(unknown, "WG4006")) << describe(unknown);
}

TEST(PublicApi, BadInputComesBackAsDiagnostics) {
  weathergen::Result r = weathergen::compile("broken.json", "{ \"name\": ");
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  const weathergen::Diagnostic& d = r.diagnostics.front();
  EXPECT_EQ(d.code, "WG1001");
  EXPECT_EQ(d.severity, "error");
  EXPECT_EQ(d.file, "broken.json");
  EXPECT_GT(d.line, 0);
  EXPECT_FALSE(d.message.empty());
  EXPECT_TRUE(r.stages.empty());
  EXPECT_TRUE(r.reflectionJson.empty());

  r = weathergen::compile("empty-object.json", "{}");
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(hasCode(r, "WG1004")) << describe(r);

  r = weathergen::compile("empty.json", "");
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(r.diagnostics.empty());
}

// Random bytes, and a real graph with random bytes overwritten: each compile must
// return (no exception, no crash), and a failure must say why.
TEST(PublicApi, HostileInputNeverThrows) {
  constexpr int kRandomInputs = 100;
  constexpr int kMutatedGraphs = 30;
  constexpr std::size_t kMaxRandomLength = 512;
  constexpr int kMaxFlips = 8;
  std::mt19937 rng(20240606);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> byte(0, 255);
  weathergen::Options textOnly;
  textOnly.spirv = false;  // the front end is what parses hostile text; keep the test fast
  for (int i = 0; i < kRandomInputs; ++i) {
    std::string input(std::uniform_int_distribution<std::size_t>(0, kMaxRandomLength)(rng), '\0');
    for (char& c : input) c = static_cast<char>(byte(rng));
    if (i % 2) input = "{\"name\": \"" + input + "\"}";  // reach past the JSON parser too
    weathergen::Result r;
    EXPECT_NO_THROW(r = weathergen::compile("random.json", input, textOnly)) << "input " << i;
    EXPECT_FALSE(r.ok) << "input " << i;
    EXPECT_FALSE(r.diagnostics.empty()) << "input " << i;
  }
  Graph g = rock();
  for (int i = 0; i < kMutatedGraphs; ++i) {
    std::string input = g.text;
    int flips = std::uniform_int_distribution<int>(1, kMaxFlips)(rng);
    for (int f = 0; f < flips; ++f)
      input[std::uniform_int_distribution<std::size_t>(0, input.size() - 1)(rng)] = static_cast<char>(byte(rng));
    weathergen::Result r;
    EXPECT_NO_THROW(r = weathergen::compile(g.file, input)) << "mutation " << i;
    EXPECT_TRUE(r.ok || !r.diagnostics.empty()) << "mutation " << i;
    for (const auto& d : r.diagnostics) EXPECT_NE(d.code, "WG9900") << "mutation " << i << ": " << d.message;
  }
}

// Every JSON pointer in a document, for picking a value to replace.
void collectPointers(const nlohmann::json& j, const nlohmann::json::json_pointer& at,
                     std::vector<nlohmann::json::json_pointer>& out) {
  out.push_back(at);
  if (j.is_object())
    for (const auto& [key, value] : j.items()) collectPointers(value, at / key, out);
  else if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i) collectPointers(j[i], at / i, out);
}

// nlohmann refuses to write invalid UTF-8, so strings carry this marker and the dumped
// text gets the raw bytes.
constexpr std::string_view kInvalidUtf8Marker = "@invalid-utf8@";

std::string dumpWithInvalidUtf8(const nlohmann::json& j) {
  std::string text = j.dump();
  for (std::size_t at; (at = text.find(kInvalidUtf8Marker)) != std::string::npos;)
    text.replace(at, kInvalidUtf8Marker.size(), "\xff\xfe");
  return text;
}

nlohmann::json hostileValue(std::mt19937& rng) {
  const std::vector<nlohmann::json> kValues = {
      nullptr, true, false, 0, 0.5, 2, 1e-38, 64, -1, 1e39, -1e308, 4294967296LL, -0.0, "", "x.out", "nope.out", std::string(4096, 'a'),
      kInvalidUtf8Marker, nlohmann::json::array(), nlohmann::json::object(), {1, 2, 3}, {1e30, -1e30, 0, 5, 6},
      {{"op", "add"}}, "uv.out", "uvScale", "albedo"};
  return kValues[std::uniform_int_distribution<std::size_t>(0, kValues.size() - 1)(rng)];
}

// Valid JSON with hostile values in random places: reaches the loader, the validator,
// the IR builder and, when it still compiles, the backends.
TEST(PublicApi, HostileGraphValuesNeverThrow) {
  constexpr int kMutations = 200;
  constexpr int kMaxEdits = 2;
  std::mt19937 rng(7);
  Graph g = rock();
  const nlohmann::json original = nlohmann::json::parse(g.text);
  std::vector<nlohmann::json::json_pointer> pointers;
  collectPointers(original, nlohmann::json::json_pointer(), pointers);
  int compiled = 0;
  for (int i = 0; i < kMutations; ++i) {
    nlohmann::json mutated = original;
    int edits = std::uniform_int_distribution<int>(1, kMaxEdits)(rng);
    for (int e = 0; e < edits; ++e) {
      const auto& at = pointers[std::uniform_int_distribution<std::size_t>(1, pointers.size() - 1)(rng)];
      if (mutated.contains(at)) mutated[at] = hostileValue(rng);
    }
    weathergen::Result r;
    EXPECT_NO_THROW(r = weathergen::compile(g.file, dumpWithInvalidUtf8(mutated))) << "mutation " << i;
    EXPECT_TRUE(r.ok || !r.diagnostics.empty()) << "mutation " << i;
    for (const auto& d : r.diagnostics) EXPECT_NE(d.code, "WG9900") << "mutation " << i << ": " << d.message;
    compiled += r.ok;
  }
  RecordProperty("compiled", compiled);
  // Some mutations must survive validation, or the backends were never exercised.
  EXPECT_GT(compiled, 0);
}

// After one initialize(), concurrent compiles share no mutable state: every thread
// gets exactly what a single-threaded compile gives.
TEST(PublicApi, ConcurrentCompilesAreByteIdentical) {
  constexpr int kThreads = 8;
  constexpr int kCompilesPerThread = 20;
  ASSERT_TRUE(weathergen::initialize());
  std::vector<Graph> graphs = bundledGraphs();
  ASSERT_FALSE(graphs.empty());
  std::vector<std::string> expected;
  for (const auto& g : graphs) {
    weathergen::Result r = weathergen::compile(g.file, g.text);
    ASSERT_TRUE(r.ok) << g.file << "\n" << describe(r);
    expected.push_back(fingerprint(r));
  }
  std::mutex failuresMutex;
  std::vector<std::string> failures;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < kCompilesPerThread; ++i) {
        std::size_t which = static_cast<std::size_t>(t + i) % graphs.size();  // threads overlap on every graph
        std::string got = fingerprint(weathergen::compile(graphs[which].file, graphs[which].text));
        if (got != expected[which]) {
          std::lock_guard<std::mutex> lock(failuresMutex);
          failures.push_back("thread " + std::to_string(t) + ", compile " + std::to_string(i) + ": " +
                             graphs[which].file);
        }
      }
    });
  for (auto& t : threads) t.join();
  if (!failures.empty()) ADD_FAILURE() << failures.size() << " differing compiles, first: " << failures.front();
}

// Threads sharing one cache directory, each compiling every graph twice from its own
// starting point: misses, stores of one key racing each other and hits all give what an
// uncached compile gives, and the directory ends with one whole entry a graph.
TEST(PublicApi, ConcurrentCompilesShareACacheDirectory) {
  constexpr int kThreads = 4;
  constexpr int kRounds = 2;
  ASSERT_TRUE(weathergen::initialize());
  const fs::path dir = fs::temp_directory_path() / ("weathergen-api-cache-threads-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::vector<Graph> graphs = bundledGraphs();
  weathergen::Options options;
  options.spirv = false;  // the cache, not glslang, is under test
  std::vector<std::string> expected;
  for (const auto& g : graphs) expected.push_back(fingerprint(weathergen::compile(g.file, g.text, options)));
  options.cacheDirectory = dir.string();
  std::mutex failuresMutex;
  std::vector<std::string> failures;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = 0; i < kRounds * graphs.size(); ++i) {
        const std::size_t which = (t + i) % graphs.size();
        if (fingerprint(weathergen::compile(graphs[which].file, graphs[which].text, options)) == expected[which]) continue;
        std::lock_guard<std::mutex> lock(failuresMutex);
        failures.push_back("thread " + std::to_string(t) + ": " + graphs[which].file);
      }
    });
  for (auto& t : threads) t.join();
  if (!failures.empty()) ADD_FAILURE() << failures.size() << " differing compiles, first: " << failures.front();
  std::size_t entries = 0, others = 0;
  for (const auto& e : fs::directory_iterator(dir)) (e.path().extension() == ".entry" ? entries : others) += 1;
  EXPECT_EQ(entries, graphs.size());
  EXPECT_EQ(others, 0u) << "a temporary file was left behind";
  fs::remove_all(dir);
}

// Options::threads spreads one material's stages over threads: the result is the same
// as with one, stage for stage and in the same order.
TEST(PublicApi, ThreadsPerCompileGiveTheSameResult) {
  ASSERT_TRUE(weathergen::initialize());
  weathergen::Options threaded;
  threaded.threads = 4;
  for (const auto& g : bundledGraphs()) {
    weathergen::Result one = weathergen::compile(g.file, g.text);
    ASSERT_TRUE(one.ok) << g.file << "\n" << describe(one);
    weathergen::Result four = weathergen::compile(g.file, g.text, threaded);
    ASSERT_EQ(four.stages.size(), 4u) << g.file;
    EXPECT_EQ(fingerprint(four), fingerprint(one)) << g.file;
  }
  // Counts out of range: none, negative, far more than the stages.
  const auto graphs = bundledGraphs();
  const auto& g = graphs.front();
  const std::string one = fingerprint(weathergen::compile(g.file, g.text));
  for (int count : {0, -5, 10000}) {
    threaded.threads = count;
    EXPECT_EQ(fingerprint(weathergen::compile(g.file, g.text, threaded)), one) << count << " threads";
  }
}

}  // namespace
