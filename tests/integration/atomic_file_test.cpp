// cli/atomic_file: the temporary is created exclusively and never through a link, so a
// symlink planted at its name in a shared output directory cannot redirect the write.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "cli/atomic_file.hpp"
#include "process_support.hpp"

namespace {

namespace fs = std::filesystem;
using wg::testing::readFile;
using wg::testing::TempDir;
using wg::testing::writeFile;

TEST(AtomicFile, PlantedSymlinksAtTheTemporaryNamesAreNeverFollowed) {
  TempDir dir("wg-atomic-file");
  fs::path victim = dir.path() / "victim.txt", out = dir.path() / "out.txt";
  writeFile(victim, "precious");
  // The next names this process will try (the counter only grows, so cover well ahead).
  for (int n = 0; n < 64; ++n) {
    std::error_code ec;
    fs::create_symlink(victim, out.string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(n), ec);
  }
  std::string error = wg::writeFileAtomically(out.string(), "output");
  EXPECT_FALSE(error.empty()) << "every temporary name was taken, so the write must fail";
  EXPECT_EQ(readFile(victim), "precious") << "the write went through a planted symlink";
  EXPECT_FALSE(fs::exists(out));
}

TEST(AtomicFile, WritesAndReportsTheSystemsReason) {
  TempDir dir("wg-atomic-file");
  fs::path out = dir.path() / "out.txt";
  EXPECT_EQ(wg::writeFileAtomically(out.string(), "bytes"), "");
  EXPECT_EQ(readFile(out), "bytes");
  fs::create_directory(dir.path() / "taken");
  std::string error = wg::writeFileAtomically((dir.path() / "taken").string(), "x");
  EXPECT_NE(error.find("Is a directory"), std::string::npos) << error;
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << "a temporary was left: " << e.path();
}

}  // namespace
