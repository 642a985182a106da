// On lavapipe with validation: the GPU map saves every print (window and store) and a
// fresh GPU map loads them back into its device-local buffers, texel for texel as the
// CPU model loads the same file.
#include <gtest/gtest.h>

#include <unistd.h>

#include "snow/deformation_map.hpp"
#include "snow/gpu_deformation_map.hpp"
#include "snow/print_store_file.hpp"
#include "tests/snow/snow_gpu_support.hpp"

namespace wg::snow {
namespace {

using GpuPrintStoreFile = testing::ValidatedGpuTest;

TEST_F(GpuPrintStoreFile, SavedPrintsLoadIntoAFreshMap) {
  const WindowSettings small{128, 0.04f, 16};
  const glm::vec2 far{30.f, 12.f};
  auto path = std::filesystem::temp_directory_path() / ("wg_gpu_prints_" + std::to_string(::getpid()) + ".bin");
  std::vector<Stamp> stamps;
  for (glm::vec2 at : {glm::vec2(-0.5f, 0.4f), far})
    stamps.push_back(capsule(at, at + glm::vec2(0.9f, -0.3f), 0.12f, SnowCover{0.3f}, 0.1f));
  {
    GpuDeformationMap original(*testing::snowContext(), small);
    original.apply(stamps);
    ASSERT_GT(original.store().tileCount(), 0u);
    original.savePrints(path);
  }
  GpuDeformationMap gpu(*testing::snowContext(), small);
  gpu.loadPrints(path);
  DeformationMap cpu(small);
  cpu.loadPrints(path);
  std::filesystem::remove(path);
  EXPECT_GT(gpu.depthAt({0.f, 0.25f}), 0.09f);
  auto heights = gpu.texels().heights;
  EXPECT_TRUE(std::equal(heights.begin(), heights.end(), cpu.texels().heights.begin()));
  auto normals = gpu.texels().normals;
  EXPECT_TRUE(std::equal(normals.begin(), normals.end(), cpu.texels().normals.begin()));
  gpu.follow(far);
  EXPECT_GT(gpu.depthAt(far + glm::vec2(0.45f, -0.15f)), 0.09f);
  EXPECT_EQ(gpu.store().tileCount(), cpu.store().tileCount());
}

}  // namespace
}  // namespace wg::snow
