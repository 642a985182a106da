// readRegularFile while another process replaces the file (an editor's or a cache
// writer's rename): every read that succeeds holds one whole version of it.
#include "nodes/regular_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

TEST(RegularFile, AFileReplacedWhileReadIsReadWholeInOneVersion) {
  const fs::path dir = fs::temp_directory_path() / ("wg-regular-file-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string small(10, 's'), large(100000, 'L');
  writeFile(dir / "small", small);
  writeFile(dir / "large", large);
  const fs::path target = dir / "graph.json";
  writeFile(target, small);
  std::atomic<bool> stop{false};
  // Each version is hard-linked to a fresh name and renamed over the target.
  std::thread replacer([&] {
    for (std::size_t i = 0; !stop; ++i) {
      const fs::path next = dir / "next";
      if (::link((dir / (i % 2 ? "small" : "large")).c_str(), next.c_str()) != 0) continue;
      std::rename(next.c_str(), target.c_str());
    }
  });
  std::size_t wrong = 0, failed = 0;
  std::string firstWrong, bytes;
  for (int i = 0; i < 20000; ++i) {
    const wg::FileRead read = wg::readRegularFile(target.string(), 1 << 20, bytes);
    if (read.status != wg::FileReadStatus::Ok) {
      if (failed++ == 0) firstWrong = "failed: " + read.reason;
    } else if (bytes != small && bytes != large) {
      if (wrong++ == 0) firstWrong = std::to_string(bytes.size()) + " bytes starting '" + bytes.substr(0, 1) + "'";
    }
  }
  stop = true;
  replacer.join();
  fs::remove_all(dir);
  EXPECT_EQ(wrong + failed, 0u) << wrong << " mixed reads, " << failed << " failed reads of 20000; first: " << firstWrong;
}

}  // namespace
