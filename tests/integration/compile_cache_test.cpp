// The persistent compile cache (compile --cache DIR): a warm run writes the files a
// cold one does, any change to a file the compile read misses, torn entries are
// misses, concurrent processes share a directory, and the bound evicts the least
// recently used entries.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

#include "driver/compile_cache.hpp"
#include "process_support.hpp"

namespace wg {
namespace {

using testing::listFiles;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
using testing::writeFile;
namespace fs = std::filesystem;

constexpr const char* kLibrary = R"({
  "textures": {"mud": {"file": "mud.png"}},
  "nodes": [
    {"id": "uv", "op": "texcoord"},
    {"id": "mud", "op": "sample", "inputs": {"texture": "mud", "uv": "uv.out"}},
    {"id": "tinted", "op": "multiply", "inputs": {"a": "mud.rgb", "b": [0.5, 0.5, 0.5]}}
  ]
})";

constexpr const char* kGraph = R"({"name": "wall", "include": {"stone": "lib/stone.json"},
  "nodes": [{"id": "rough", "op": "one_minus", "inputs": {"in": 0.3}}],
  "output": {"baseColor": "stone.tinted.out", "roughness": "rough.out"}})";

class CompileCacheCli : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_.path() / "lib");
    writeFile(dir_.path() / "lib" / "stone.json", kLibrary);
    fs::copy_file(fs::path(WG_SOURCE_DIR) / "examples/cmake-consumer/materials/textures/mud_albedo.png",
                  dir_.path() / "lib" / "mud.png");
    writeFile(dir_.path() / "wall.json", kGraph);
  }
  // Compiles the graph into `out`; `flags` chooses the cache.
  testing::CommandResult compile(const std::string& out, const std::string& flags,
                                 const std::string& environment = "") const {
    return runCommand(environment + shellQuote(WG_CLI_PATH) + " compile " + shellQuote(graph()) + " -o " +
                      shellQuote((dir_.path() / out).string()) + " -q " + flags + " 2>&1");
  }
  std::string graph() const { return (dir_.path() / "wall.json").string(); }
  std::string cacheFlag() const { return "--cache " + shellQuote(cache().string()); }
  fs::path cache() const { return dir_.path() / "cache"; }
  // Every output file's bytes, by name.
  std::map<std::string, std::string> outputs(const std::string& out) const {
    std::map<std::string, std::string> files;
    for (const auto& name : listFiles(dir_.path() / out)) files[name] = readFile(dir_.path() / out / name);
    return files;
  }
  std::vector<std::string> entries() const { return entriesIn(cache()); }
  static std::vector<std::string> entriesIn(const fs::path& directory) {
    std::vector<std::string> names;
    if (!fs::is_directory(directory)) return names;
    for (const auto& name : listFiles(directory))
      if (name.size() > 6 && name.substr(name.size() - 6) == ".entry") names.push_back(name);
    return names;
  }
  TempDir dir_{"compile-cache"};
};

TEST_F(CompileCacheCli, AWarmRunWritesTheFilesAColdOneDoes) {
  ASSERT_EQ(compile("plain", "--no-cache").exitCode, 0);
  EXPECT_FALSE(fs::exists(cache()));
  auto cold = compile("cold", cacheFlag());
  ASSERT_EQ(cold.exitCode, 0) << cold.output;
  ASSERT_EQ(entries().size(), 1u);
  auto warm = compile("warm", cacheFlag());
  ASSERT_EQ(warm.exitCode, 0) << warm.output;
  EXPECT_EQ(entries().size(), 1u);
  EXPECT_TRUE(outputs("cold") == outputs("plain"));
  EXPECT_TRUE(outputs("warm") == outputs("plain"));
}

// A rebuild into the same folder leaves an output that already holds its bytes in
// place (same inode: not created again) but touches it, so make and ninja see it as
// fresh; an output that differs is replaced.
TEST_F(CompileCacheCli, ARebuildTouchesUnchangedOutputsAndReplacesChangedOnes) {
  ASSERT_EQ(compile("out", cacheFlag()).exitCode, 0);
  const fs::path reflection = dir_.path() / "out" / "wall.reflect.json", vertex = dir_.path() / "out" / "wall.vert.glsl";
  struct stat before {};
  ASSERT_EQ(::stat(reflection.c_str(), &before), 0);
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(1);
  fs::last_write_time(reflection, old);
  writeFile(vertex, "// edited by hand\n");
  auto rebuild = compile("out", cacheFlag());
  ASSERT_EQ(rebuild.exitCode, 0) << rebuild.output;
  struct stat after {};
  ASSERT_EQ(::stat(reflection.c_str(), &after), 0);
  EXPECT_EQ(after.st_ino, before.st_ino) << "an unchanged output is not written again";
  EXPECT_GT(fs::last_write_time(reflection), old + std::chrono::minutes(59)) << "but it is touched";
  auto plain = compile("plain", "--no-cache");
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_TRUE(outputs("out") == outputs("plain")) << "the edited output is replaced";
}

TEST_F(CompileCacheCli, AWarmRunWritesTheSameDepfile) {
  ASSERT_EQ(compile("cold", cacheFlag() + " --depfile " + shellQuote((dir_.path() / "cold.d").string())).exitCode, 0);
  ASSERT_EQ(compile("cold", cacheFlag() + " --depfile " + shellQuote((dir_.path() / "warm.d").string())).exitCode, 0);
  const std::string warm = readFile(dir_.path() / "warm.d");
  EXPECT_EQ(warm, readFile(dir_.path() / "cold.d"));
  EXPECT_NE(warm.find("lib/stone.json"), std::string::npos) << warm;
  EXPECT_NE(warm.find("lib/mud.png"), std::string::npos) << warm;
}

TEST_F(CompileCacheCli, ChangingALibraryOrAnImageMisses) {
  ASSERT_EQ(compile("cold", cacheFlag()).exitCode, 0);
  std::string library = kLibrary;
  library.replace(library.find("0.5, 0.5, 0.5"), 13, "0.25, 0.5, 1.0");
  writeFile(dir_.path() / "lib" / "stone.json", library);
  ASSERT_EQ(compile("library", cacheFlag()).exitCode, 0);
  ASSERT_EQ(compile("library-plain", "--no-cache").exitCode, 0);
  EXPECT_TRUE(outputs("library") == outputs("library-plain"));
  EXPECT_TRUE(outputs("library") != outputs("cold"));
  // The graph's text is the key, so the entry of the old library was replaced. Other
  // bytes in the image: the files written are alike, but the entry, which holds the
  // image's digest, is replaced again.
  ASSERT_EQ(entries().size(), 1u);
  std::map<std::string, std::string> before;
  for (const auto& name : entries()) before[name] = readFile(cache() / name);
  fs::copy_file(fs::path(WG_SOURCE_DIR) / "examples/cmake-consumer/materials/textures/mud_albedo.png",
                dir_.path() / "lib" / "mud.png", fs::copy_options::overwrite_existing);
  std::string png = readFile(dir_.path() / "lib" / "mud.png");
  png.back() ^= 1;  // the IEND chunk's CRC: stb_image ignores it, the digest does not
  writeFile(dir_.path() / "lib" / "mud.png", png);
  ASSERT_EQ(compile("image", cacheFlag()).exitCode, 0);
  EXPECT_TRUE(outputs("image") == outputs("library-plain"));
  ASSERT_EQ(entries().size(), 1u);
  std::size_t replaced = 0;
  for (const auto& name : entries()) replaced += before[name] != readFile(cache() / name);
  EXPECT_EQ(replaced, 1u);
}

TEST_F(CompileCacheCli, OptionsAreInTheKey) {
  ASSERT_EQ(compile("none", cacheFlag()).exitCode, 0);
  ASSERT_EQ(compile("rock", cacheFlag() + " --weather-preset rock").exitCode, 0);
  ASSERT_EQ(compile("rock-plain", "--no-cache --weather-preset rock").exitCode, 0);
  EXPECT_EQ(entries().size(), 2u);
  EXPECT_TRUE(outputs("rock") == outputs("rock-plain"));
  EXPECT_TRUE(outputs("rock") != outputs("none"));
}

// A library included by absolute path records its texture relative to the graph's
// folder: one graph text at one relative path, compiled from two working directories,
// writes two different reflections, and the second must not be the first's entry.
TEST_F(CompileCacheCli, TheSameRelativePathFromAnotherFolderMisses) {
  std::string graph = kGraph;
  const std::string library = (dir_.path() / "lib" / "stone.json").string();
  graph.replace(graph.find("lib/stone.json"), 14, library);
  for (const char* folder : {"near", "far/away"}) {
    fs::create_directories(dir_.path() / folder);
    writeFile(dir_.path() / folder / "wall.json", graph);
  }
  auto compileIn = [&](const char* folder, const std::string& out, const std::string& flags) {
    return runCommand("cd " + shellQuote((dir_.path() / folder).string()) + " && " + shellQuote(WG_CLI_PATH) +
                      " compile wall.json -o " + shellQuote((dir_.path() / out).string()) + " -q " + flags + " 2>&1");
  };
  ASSERT_EQ(compileIn("near", "near-out", cacheFlag()).exitCode, 0);
  ASSERT_EQ(compileIn("far/away", "far-out", cacheFlag()).exitCode, 0);
  ASSERT_EQ(compileIn("far/away", "far-plain", "--no-cache").exitCode, 0);
  EXPECT_NE(readFile(dir_.path() / "far-plain" / "wall.reflect.json").find("../../lib/mud.png"), std::string::npos);
  EXPECT_TRUE(outputs("far-out") == outputs("far-plain"));
  EXPECT_TRUE(outputs("near-out") != outputs("far-plain"));
}

// A library replaced while the graph compiles, by a file with an old modification time
// (rsync, or `cp -p` then `mv`): the entry would pair the new library's digest with
// what the old one compiled to, so it is not stored, and the next compile is the new one.
TEST_F(CompileCacheCli, ALibraryReplacedDuringTheCompileIsNotStored) {
  std::string library = kLibrary;
  library.replace(library.find("0.5, 0.5, 0.5"), 13, "0.25, 0.5, 1.0");
  const fs::path replacement = dir_.path() / "stone.json.new";
  writeFile(replacement, library);
  const auto modified = fs::last_write_time(dir_.path() / "lib" / "stone.json");
  fs::last_write_time(replacement, modified - std::chrono::hours(1));
  const CompileCache cache(this->cache());
  ASSERT_EQ(cache.prepare(), "");
  CompileOptions racing{.emitSpirv = false};
  racing.passes.afterPass = [&](const Pass&, const IrGraph&) {
    if (!fs::exists(replacement)) return;
    // Files are stamped from a coarse clock (a tick): leave the tick the compile began in.
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    fs::rename(replacement, dir_.path() / "lib" / "stone.json");
  };
  ASSERT_TRUE(cache.compileFile(graph(), racing).material);
  ASSERT_FALSE(fs::exists(replacement));
  const CompileOptions options{.emitSpirv = false};
  const CompileResult fresh = compileMaterialFile(graph(), options);
  const CompileResult warm = cache.compileFile(graph(), options);
  ASSERT_TRUE(fresh.material && warm.material);
  EXPECT_EQ(warm.material->contentHash, fresh.material->contentHash);
  EXPECT_TRUE(warm.material->stages.at(1).source == fresh.material->stages.at(1).source) << "the old library's shader";
}

TEST_F(CompileCacheCli, ATornEntryIsAMiss) {
  ASSERT_EQ(compile("plain", "--no-cache").exitCode, 0);
  ASSERT_EQ(compile("cold", cacheFlag()).exitCode, 0);
  ASSERT_EQ(entries().size(), 1u);
  const fs::path entry = cache() / entries().front();
  std::string bytes = readFile(entry);
  writeFile(entry, bytes.substr(0, bytes.size() / 2));
  ASSERT_EQ(compile("torn", cacheFlag()).exitCode, 0);
  EXPECT_TRUE(outputs("torn") == outputs("plain"));
  bytes[bytes.size() / 2] ^= 0x20;  // one flipped bit in the body
  writeFile(entry, bytes);
  ASSERT_EQ(compile("flipped", cacheFlag()).exitCode, 0);
  EXPECT_TRUE(outputs("flipped") == outputs("plain"));
}

// A changed byte in an entry, at the start of its body, in the middle or in the digest's
// own text, is a miss, which compiles and stores the entry again (a hit would leave the
// changed one in place). CompileCacheKey.EveryByteAndTheLengthCount covers the digest
// over every position.
TEST_F(CompileCacheCli, AnEntryWithAnyByteChangedIsAMiss) {
  ASSERT_EQ(compile("cold", cacheFlag()).exitCode, 0);
  ASSERT_EQ(entries().size(), 1u);
  const fs::path entry = cache() / entries().front();
  const std::string whole = readFile(entry);
  const std::size_t magic = std::string_view("weathergen compile cache entry 1\n").size(), digest = 32;
  ASSERT_GT(whole.size(), magic + digest + 64);
  ASSERT_EQ(whole.substr(0, magic), "weathergen compile cache entry 1\n");
  for (std::size_t at : {magic, magic + 9, whole.size() / 2, whole.size() - 1}) {
    std::string changed = whole;
    changed[at] ^= 0x01;
    writeFile(entry, changed);
    auto r = compile("out", cacheFlag());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(readFile(entry) == whole) << "the entry with byte " << at << " of " << whole.size() << " changed was used";
  }
}

TEST_F(CompileCacheCli, TheEnvironmentNamesTheDirectoryAndNoCacheWins) {
  const std::string environment = "WEATHERGEN_CACHE_DIR=" + shellQuote(cache().string()) + " ";
  ASSERT_EQ(compile("off", "--no-cache", environment).exitCode, 0);
  EXPECT_FALSE(fs::exists(cache()));
  ASSERT_EQ(compile("on", "", environment).exitCode, 0);
  EXPECT_EQ(entries().size(), 1u);
}

// Without --cache or WEATHERGEN_CACHE_DIR the user's cache directory holds the cache:
// $XDG_CACHE_HOME/weathergen, else ~/.cache/weathergen. (The suite runs with
// WEATHERGEN_CACHE_DIR=off, which these commands take away.)
TEST_F(CompileCacheCli, ByDefaultTheUsersCacheDirectoryHoldsIt) {
  ASSERT_EQ(compile("plain", "--no-cache").exitCode, 0);
  const fs::path xdg = dir_.path() / "xdg-cache-home", home = dir_.path() / "home-directory";
  ASSERT_EQ(compile("xdg", "", "env -u WEATHERGEN_CACHE_DIR XDG_CACHE_HOME=" + shellQuote(xdg.string()) + " ").exitCode, 0);
  EXPECT_EQ(entriesIn(xdg / "weathergen").size(), 1u);
  ASSERT_EQ(compile("home", "", "env -u WEATHERGEN_CACHE_DIR -u XDG_CACHE_HOME HOME=" + shellQuote(home.string()) + " ")
                .exitCode,
            0);
  EXPECT_EQ(entriesIn(home / ".cache" / "weathergen").size(), 1u);
  EXPECT_TRUE(outputs("xdg") == outputs("plain"));
  EXPECT_TRUE(outputs("home") == outputs("plain"));
}

TEST_F(CompileCacheCli, OffInTheEnvironmentTurnsTheDefaultOff) {
  const fs::path xdg = dir_.path() / "xdg";
  ASSERT_EQ(compile("out", "", "WEATHERGEN_CACHE_DIR=off XDG_CACHE_HOME=" + shellQuote(xdg.string()) + " ").exitCode, 0);
  EXPECT_FALSE(fs::exists(xdg));
}

// The default directory is a convenience: where it cannot be made, compile runs uncached.
TEST_F(CompileCacheCli, AnUnusableDefaultDirectoryCompilesUncached) {
  ASSERT_EQ(compile("plain", "--no-cache").exitCode, 0);
  writeFile(dir_.path() / "file", "not a directory");
  auto r = compile("out", "", "env -u WEATHERGEN_CACHE_DIR XDG_CACHE_HOME=" + shellQuote((dir_.path() / "file").string()) + " ");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output, "");
  EXPECT_TRUE(outputs("out") == outputs("plain"));
}

TEST_F(CompileCacheCli, ADirectoryThatCannotBeMadeIsAUsageError) {
  writeFile(dir_.path() / "file", "not a directory");
  auto r = compile("out", "--cache " + shellQuote((dir_.path() / "file").string()));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--cache"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
}

TEST_F(CompileCacheCli, ConcurrentProcessesShareADirectory) {
  ASSERT_EQ(compile("plain", "--no-cache").exitCode, 0);
  std::vector<std::thread> runs;
  std::vector<int> exits(4, -1);
  for (int i = 0; i < 4; ++i)
    runs.emplace_back([&, i] { exits[i] = compile("run" + std::to_string(i), cacheFlag()).exitCode; });
  for (auto& run : runs) run.join();
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(exits[i], 0);
    EXPECT_TRUE(outputs("run" + std::to_string(i)) == outputs("plain"));
  }
  EXPECT_EQ(listFiles(cache()), entries());  // no temporary file left behind
}

// The files in `dir` that are not in `before`.
std::vector<std::string> newFiles(const fs::path& dir, const std::vector<std::string>& before) {
  std::vector<std::string> names;
  for (const auto& name : listFiles(dir))
    if (std::find(before.begin(), before.end(), name) == before.end()) names.push_back(name);
  return names;
}

// The digest reads whole blocks, then words, then a tail: one bit changed anywhere in a
// text of any length changes the key, and so does a trailing zero byte.
TEST(CompileCacheKey, EveryByteAndTheLengthCount) {
  const CompileOptions options;
  std::set<std::string> byLength;
  for (std::size_t length = 0; length <= 100; ++length) {
    std::string text(length, '\0');
    for (std::size_t i = 0; i < length; ++i) text[i] = static_cast<char>('a' + i % 26);
    const std::string key = compileCacheKey("g.json", text, options);
    byLength.insert(compileCacheKey("g.json", std::string(length, '\0'), options));
    for (std::size_t i = 0; i < length; ++i)
      for (int bit : {0, 7}) {
        std::string changed = text;
        changed[i] = static_cast<char>(changed[i] ^ (1 << bit));
        EXPECT_NE(compileCacheKey("g.json", changed, options), key) << "byte " << i << " of " << length;
      }
  }
  EXPECT_EQ(byLength.size(), 101u) << "texts of zero bytes that differ only in length share a key";
}

// The engine API passes any string as a preset or tier, to be refused when unknown: a
// NUL character is not the absence of one, nor is an empty string.
TEST(CompileCacheKey, AnUnsetPresetOrTierIsNoText) {
  const CompileOptions unset;
  const std::string key = compileCacheKey("g.json", "{}", unset);
  for (const std::string& text : {std::string(1, '\0'), std::string()}) {
    CompileOptions preset, tier;
    preset.weatherPreset = text;
    tier.quality.requested = text;
    EXPECT_NE(compileCacheKey("g.json", "{}", preset), key) << text.size();
    EXPECT_NE(compileCacheKey("g.json", "{}", tier), key) << text.size();
  }
}

// --cache may name a folder that holds other files: trimming removes the cache's
// entries and the temporary files its writers abandoned, never a user's file whose name
// merely starts with "tmp." or ends in ".entry".
TEST(CompileCache, TrimRemovesOnlyTheCachesOwnFiles) {
  TempDir dir("compile-cache-foreign");
  const auto longAgo = fs::file_time_type::clock::now() - std::chrono::hours(3);
  const std::vector<std::string> foreign = {"tmp.log", "notes.entry", "tmp.1.2", "0123456789abcdef0123456789ABCDEF.entry"};
  for (const std::string& name : foreign) writeFile(dir.path() / name, "the user's own");
  writeFile(dir.path() / "tmp.123.456.7", "a killed writer's");
  for (const auto& name : listFiles(dir.path())) fs::last_write_time(dir.path() / name, longAgo);
  const CompileCache tiny(dir.path(), 1);  // any entry is beyond the bound
  ASSERT_TRUE(tiny.compileFile(testing::bundledGraphs().front().string(), CompileOptions{.emitSpirv = false}).material);
  ASSERT_EQ(listFiles(dir.path()).size(), foreign.size() + 2);  // the new entry is stored
  tiny.trim();
  std::vector<std::string> left = listFiles(dir.path());
  std::sort(left.begin(), left.end());
  std::vector<std::string> expected = foreign;
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(left, expected);
}

// Writers in other pid namespaces (containers sharing a cache volume) can choose the
// temporary name this one does: a writer that finds its name taken stores nothing and
// leaves the other's file alone, or the other's rename would find it gone.
TEST(CompileCache, AWriterLeavesATemporaryFileItDidNotCreate) {
  TempDir dir("compile-cache-taken");
  const std::string thread = std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()));
  constexpr int kNames = 64;  // more than this process's writers store before this test
  for (int n = 0; n < kNames; ++n)
    writeFile(dir.path() / ("tmp." + std::to_string(::getpid()) + "." + thread + "." + std::to_string(n)), "another's");
  const CompileCache cache(dir.path());
  ASSERT_TRUE(cache.compileFile(testing::bundledGraphs().front().string(), CompileOptions{.emitSpirv = false}).material);
  const std::vector<std::string> left = listFiles(dir.path());
  ASSERT_EQ(left.size(), std::size_t(kNames)) << "no name was taken: the test did not reach the collision";
  for (const auto& name : left) EXPECT_EQ(readFile(dir.path() / name), "another's") << name;
}

TEST(CompileCache, TrimEvictsTheLeastRecentlyUsedBeyondItsBound) {
  TempDir dir("compile-cache-trim");
  const auto graphs = testing::bundledGraphs();
  ASSERT_GE(graphs.size(), 3u);
  const CompileOptions options{.emitSpirv = false};
  const CompileOptions noWeather{.emitSpirv = false, .weatherPreset = "none"};
  std::vector<std::string> names;  // the entries of graphs 0, 1 and 2, in turn
  std::uintmax_t threeEntries = 0;
  {
    CompileCache unbounded(dir.path());
    ASSERT_EQ(unbounded.prepare(), "");
    for (int i = 0; i < 3; ++i) {
      auto before = listFiles(dir.path());
      ASSERT_TRUE(unbounded.compileFile(graphs[i].string(), options).material);
      auto added = newFiles(dir.path(), before);
      ASSERT_EQ(added.size(), 1u);
      names.push_back(added.front());
      threeEntries += fs::file_size(dir.path() / names.back());
    }
    const auto now = fs::file_time_type::clock::now();
    for (const auto& name : names) fs::last_write_time(dir.path() / name, now - std::chrono::hours(3));
    // A hit refreshes its entry's time.
    ASSERT_TRUE(unbounded.compileFile(graphs[0].string(), options).material);
    EXPECT_GT(fs::last_write_time(dir.path() / names[0]), now - std::chrono::hours(1));
    // Graph 1's entry the least recently used, the new one below the most (the file
    // system's clock is too coarse to order entries touched within a few milliseconds).
    fs::last_write_time(dir.path() / names[0], now - std::chrono::hours(2));
    fs::last_write_time(dir.path() / names[2], now - std::chrono::hours(2));
  }
  CompileCache bounded(dir.path(), threeEntries);
  auto before = listFiles(dir.path());
  ASSERT_TRUE(bounded.compileFile(graphs[0].string(), noWeather).material);
  const auto added = newFiles(dir.path(), before);
  ASSERT_EQ(added.size(), 1u);
  const std::string newest = added.front();
  bounded.trim();
  std::uintmax_t total = 0;
  for (const auto& name : listFiles(dir.path())) total += fs::file_size(dir.path() / name);
  EXPECT_LE(total, threeEntries / 4 * 3);
  EXPECT_FALSE(fs::exists(dir.path() / names[1]));
  EXPECT_TRUE(fs::exists(dir.path() / newest));
  // A hit returns the stored files without compiling: its material has no IR.
  CompileResult again = bounded.compileFile(graphs[0].string(), noWeather);
  ASSERT_TRUE(again.material);
  EXPECT_TRUE(again.material->ir.nodes.empty());
  EXPECT_FALSE(again.material->stages.front().source.empty());
}

}  // namespace
}  // namespace wg
