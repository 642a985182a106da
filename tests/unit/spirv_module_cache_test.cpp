// A batch compiles a stage text once however many variants emit it, and the results
// are those of compiling each material alone.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "backends/reference_host.hpp"
#include "driver/batch_compile.hpp"
#include "driver/spirv_module_cache.hpp"

namespace wg {
namespace {

const std::string kRock = std::string(WG_SOURCE_DIR) + "/graphs/rock.json";

TEST(SpirvModuleCache, SharesTextsThatDifferOnlyInTheBanner) {
  SpirvModuleCache cache;
  int made = 0;
  auto make = [&] {
    ++made;
    SpirvModule m;
    m.compiled = true;
    m.words = {1, 2, 3};
    return m;
  };
  const std::string a1 = "#version 440\n" + std::string(kStageBannerPrefix) + "0.1 from material aaaa\nvoid main() {}\n";
  const std::string b1 = "#version 440\n" + std::string(kStageBannerPrefix) + "0.1 from material bbbb\nvoid main() {}\n";
  const std::string c1 = "#version 440\n" + std::string(kStageBannerPrefix) + "0.1 from material aaaa\nvoid main() { }\n";
  auto a = cache.get(a1, "frag.glsl", make);
  auto b = cache.get(b1, "frag.glsl", make);
  auto c = cache.get(c1, "frag.glsl", make);
  auto d = cache.get(a1, "frag.glsl -O", make);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_NE(a, d);
  EXPECT_EQ(made, 3);
  EXPECT_EQ(cache.counts().lookups, 4u);
  EXPECT_EQ(cache.counts().compiled, 3u);
}

TEST(SpirvModuleCache, ConcurrentRequestsForOneTextMakeItOnce) {
  SpirvModuleCache cache;
  std::atomic<int> made{0};
  auto make = [&] {
    ++made;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return SpirvModule{};
  };
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i) threads.emplace_back([&] { cache.get("// x\nbody\n", "vert.glsl", make); });
  for (auto& t : threads) t.join();
  EXPECT_EQ(made.load(), 1);
  EXPECT_EQ(cache.counts().lookups, 4u);
}

TEST(SpirvModuleCache, ABatchCompilesASharedStageOnceWithTheSameResult) {
  CompileOptions options;
  options.emitDisassembly = true;
  auto alone = compileMaterialFile(kRock, options);
  ASSERT_TRUE(alone.material);

  SpirvModuleCache modules;
  options.modules = &modules;
  // rock under two presets: the fragment stages differ, and so do the banners.
  std::vector<CompileJob> jobs = {{kRock, {}, std::nullopt}, {kRock, {}, std::string("none")}, {kRock, {}, std::nullopt}};
  auto results = compileBatch(jobs, options, 2);
  ASSERT_TRUE(results[0].material && results[1].material && results[2].material);
  EXPECT_EQ(modules.counts().lookups, 12u);
  EXPECT_EQ(modules.counts().compiled, 8u);  // the third job shares all four stages with the first
  for (std::size_t s = 0; s < alone.material->stages.size(); ++s) {
    EXPECT_EQ(results[0].material->stages[s].spirv, alone.material->stages[s].spirv);
    EXPECT_EQ(results[0].material->stages[s].disassembly, alone.material->stages[s].disassembly);
    EXPECT_EQ(results[2].material->stages[s].spirv, alone.material->stages[s].spirv);
  }
  EXPECT_NE(results[1].material->stage(ShaderLanguage::Glsl, ShaderStage::Fragment).spirv,
            alone.material->stage(ShaderLanguage::Glsl, ShaderStage::Fragment).spirv);
}

TEST(SpirvModuleCache, DisassemblyOnlyWhenAskedFor) {
  CompileOptions options;
  auto plain = compileMaterialFile(kRock, options);
  ASSERT_TRUE(plain.material);
  for (const auto& s : plain.material->stages) {
    EXPECT_FALSE(s.spirv.empty());
    EXPECT_TRUE(s.disassembly.empty());
  }
}

}  // namespace
}  // namespace wg
