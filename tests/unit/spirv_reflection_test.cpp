// The offset check's reflection: SPIRV-Cross finds every uniform block member of every
// module where the reflection JSON publishes it.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "backends/spirv/spirv_toolchain.hpp"
#include "driver/material_compiler.hpp"

namespace wg {
namespace {

const nlohmann::json* publishedBlock(const nlohmann::json& reflection, const ReflectedBlock& block) {
  for (const auto& published : reflection.at("blocks"))
    if (published.at("set") == block.set && published.at("binding") == block.binding) return &published;
  return nullptr;
}

TEST(SpirvReflection, EveryModuleHasItsBlocksAtThePublishedOffsets) {
  std::size_t modules = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(WG_SOURCE_DIR) + "/graphs")) {
    if (entry.path().extension() != ".json") continue;
    auto result = compileMaterialFile(entry.path().string(), CompileOptions{});
    ASSERT_TRUE(result.material) << entry.path();
    const auto reflection = nlohmann::json::parse(result.material->reflectionJson);
    for (const auto& stage : result.material->stages) {
      ++modules;
      const auto blocks = reflectUniformBlocks(stage.spirv);
      bool frame = false;
      for (const auto& block : blocks) {
        const nlohmann::json* published = publishedBlock(reflection, block);
        ASSERT_NE(published, nullptr) << entry.path().filename() << " set " << block.set << " binding " << block.binding;
        frame = frame || published->at("name") == "Frame";
        EXPECT_EQ(block.members.size(), published->at("members").size()) << entry.path().filename();
        for (const auto& member : block.members) {
          std::uint32_t offset = ~0u;
          for (const auto& m : published->at("members"))
            if (m.at("identifier") == member.name) offset = m.at("offset");
          EXPECT_EQ(member.offset, offset) << entry.path().filename() << " " << member.name;
        }
      }
      EXPECT_TRUE(frame) << entry.path().filename() << ": every stage reads the frame block";
    }
  }
  EXPECT_EQ(modules, 32u);
}

}  // namespace
}  // namespace wg
