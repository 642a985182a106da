// Saving and loading prints: a round trip gives back every print, in the window and in
// the store, with the refill it had missed; truncated and hostile files are clear
// errors that change nothing.
#include "snow/print_store_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include "snow/deformation_map.hpp"
#include "snow/snow_interactors.hpp"

namespace wg::snow {
namespace {

const WindowSettings kSmall{128, 0.04f, 16};
const glm::vec2 kFar{40.f, -25.f};

// Prints near the origin (in the window) and far away (in the store), half refilled.
DeformationMap printedMap() {
  DeformationMap map(kSmall);
  std::vector<Stamp> stamps;
  for (glm::vec2 at : {glm::vec2(0.3f, -0.4f), kFar, kFar + glm::vec2(1.f, 0.5f)})
    stamps.push_back(capsule(at, at + glm::vec2(0.8f, 0.2f), 0.12f, SnowCover{0.3f}, 0.1f));
  map.apply(stamps);
  map.refill(0.003, 1.0);  // 3 mm owed; 4 tiles a call get it now
  return map;
}

std::vector<std::uint32_t> heights(DeformationMap& map) {
  return {map.texels().heights.begin(), map.texels().heights.end()};
}

std::string saved(const DeformationMap& map) {
  auto path = std::filesystem::temp_directory_path() / ("wg_prints_" + std::to_string(::getpid()) + ".bin");
  map.savePrints(path);
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  return bytes;
}

void loadBytes(DeformationMap& map, const std::string& bytes) {
  auto path = std::filesystem::temp_directory_path() / ("wg_prints_in_" + std::to_string(::getpid()) + ".bin");
  { std::ofstream(path, std::ios::binary) << bytes; }
  try {
    map.loadPrints(path);
  } catch (...) {
    std::filesystem::remove(path);
    throw;
  }
  std::filesystem::remove(path);
}

TEST(PrintStoreFile, SaveAndLoadRoundTripEveryPrintWithTheRefillItMissed) {
  DeformationMap original = printedMap();
  std::string bytes = saved(original);
  DeformationMap loaded(kSmall);
  loaded.refill(0.05, 1.0);  // a different refill counter: the file's refill is relative
  loadBytes(loaded, bytes);
  for (int frame = 0; frame < 20; ++frame) {  // both catch up on what they owe
    original.refill(0.0, 1.0);
    loaded.refill(0.0, 1.0);
  }
  EXPECT_EQ(heights(loaded), heights(original));
  EXPECT_GT(loaded.depthAt({0.7f, -0.3f}), 0.09f);
  original.follow(kFar);
  loaded.follow(kFar);
  for (int frame = 0; frame < 20; ++frame) {
    original.refill(0.0, 1.0);
    loaded.refill(0.0, 1.0);
  }
  EXPECT_EQ(heights(loaded), heights(original));
  EXPECT_NEAR(loaded.depthAt(kFar + glm::vec2(0.4f, 0.1f)), 0.097f, 1.5e-4f);
}

TEST(PrintStoreFile, ATruncatedFileIsAClearErrorAndChangesNothing) {
  std::string bytes = saved(printedMap());
  DeformationMap map = printedMap();
  const auto before = heights(map);
  for (std::size_t length = 0; length < bytes.size(); length += 1 + length / 8) {
    try {
      loadBytes(map, bytes.substr(0, length));
      ADD_FAILURE() << "a file cut at " << length << " of " << bytes.size() << " bytes loaded";
    } catch (const PrintFileError& e) {
      EXPECT_NE(std::string(e.what()).find("prints file: "), std::string::npos);
    }
  }
  EXPECT_EQ(heights(map), before);
  EXPECT_THROW(loadBytes(map, bytes + "x"), PrintFileError);
}

// The header, then one tile with `count` texels.
std::string tileFile(std::uint64_t tileCount, std::uint32_t count, std::uint16_t secondPosition = 2,
                     std::uint32_t texel = 0x00100000u) {
  std::ostringstream out;
  PrintTileStore empty;
  savePrints(empty, SnowWindow(kSmall), 0, out);
  std::string s = out.str();
  std::memcpy(&s[20], &tileCount, 8);
  auto put = [&](auto v) { s.append(reinterpret_cast<const char*>(&v), sizeof v); };
  put(std::int32_t(3));
  put(std::int32_t(-2));
  put(std::uint32_t(0));
  put(count);
  const std::uint32_t written = std::min(count, 8u);  // a hostile count claims more than is there
  for (std::uint32_t i = 0; i < written; ++i) put(std::uint16_t(i == 1 ? secondPosition : i * 3));
  for (std::uint32_t i = 0; i < written; ++i) put(texel);
  return s;
}

std::string loadError(const std::string& bytes) {
  std::istringstream in(bytes);
  PrintTileStore store;
  try {
    loadPrints(in, SnowWindow(kSmall), 0, store);
  } catch (const PrintFileError& e) {
    EXPECT_EQ(store.tileCount(), 0u) << "a file that fails adds nothing: " << e.what();
    return e.what();
  }
  return "";
}

TEST(PrintStoreFile, HostileFilesAreRejectedWithoutHugeAllocations) {
  ASSERT_EQ(loadError(tileFile(1, 3)), "");
  EXPECT_NE(loadError("GIF89a..........................").find("magic"), std::string::npos);
  std::string version = tileFile(1, 3);
  version[8] = 9;
  EXPECT_NE(loadError(version).find("version 9"), std::string::npos);
  std::string tiles = tileFile(1, 3);
  tiles[12] = 32;
  EXPECT_NE(loadError(tiles).find("32-texel tiles"), std::string::npos);
  EXPECT_NE(loadError(tileFile(~0ull, 3)).find("truncated"), std::string::npos) << "2^64 tiles claimed, one there";
  EXPECT_NE(loadError(tileFile(1, 0)).find("claims 0 texels"), std::string::npos);
  EXPECT_NE(loadError(tileFile(1, 0xFFFFFFFFu)).find("claims 4294967295 texels"), std::string::npos);
  EXPECT_NE(loadError(tileFile(1, 3, 0)).find("increase"), std::string::npos);
  EXPECT_NE(loadError(tileFile(1, 3, 999)).find("increase"), std::string::npos);
  EXPECT_NE(loadError(tileFile(1, 3, 2, 0)).find("untouched"), std::string::npos);
  std::string twice = tileFile(2, 3);
  twice += twice.substr(28);
  EXPECT_NE(loadError(twice).find("appears twice"), std::string::npos);
}

}  // namespace
}  // namespace wg::snow
