#include "snow/deformation_pass.hpp"

#include <stdexcept>

#include "vulkan/compute_barriers.hpp"
#include "vulkan/runtime_shader.hpp"
#include "snow/deformation_shaders.hpp"

namespace wg::snow {

namespace {
std::uint32_t groups(int extent, std::uint32_t local) {
  return extent <= 0 ? 0u : (static_cast<std::uint32_t>(extent) + local - 1) / local;
}
}  // namespace

DeformationPass::DeformationPass(vk::Context& ctx) : ctx_(ctx) {
  std::vector<vk::CompiledModule> modules;
  for (auto [source, what] : {std::pair{stampShaderSource(), "snow stamp"}, std::pair{normalShaderSource(), "snow normal"},
                              std::pair{refillShaderSource(), "snow refill"},
                              std::pair{tilesOutShaderSource(), "snow tiles out"},
                              std::pair{tilesInShaderSource(), "snow tiles in"}})
    modules.push_back(vk::compileRuntimeShader(source, vk::RuntimeStage::Compute, what));
  std::vector<ModuleInterface> interfaces;
  for (const auto& m : modules) interfaces.push_back(m.interface);
  set_ = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, interfaces, VK_SHADER_STAGE_COMPUTE_BIT);
  if (set_->pushConstantBytes() != sizeof(WindowConstants))
    throw std::runtime_error("snow shaders: push constants are " + std::to_string(set_->pushConstantBytes()) +
                             " bytes, WindowConstants " + std::to_string(sizeof(WindowConstants)));
  Pipeline* targets[] = {&stamp_, &normals_, &refill_, &tilesOut_, &tilesIn_};
  for (std::size_t i = 0; i < modules.size(); ++i) {
    Pipeline& p = *targets[i];
    p.module = vk::createShaderModule(ctx_, modules[i].words);
    p.pipeline = vk::createComputePipeline(ctx_, p.module.get(), set_->pipelineLayout());
    for (int axis = 0; axis < 3; ++axis) p.localSize[axis] = modules[i].interface.localSize[axis];
  }
}

// The owner makes sure the device is done with the pass (an engine, or GpuDeformationMap).
DeformationPass::~DeformationPass() = default;

void DeformationPass::bind(const std::string& block, const vk::Buffer& buffer) { set_->bindBuffer(block, buffer); }

void DeformationPass::bindSurface(const vk::Image2D& image) {
  set_->bindImage("Surface", image.view(), VK_IMAGE_LAYOUT_GENERAL);
}

void DeformationPass::dispatch(VkCommandBuffer cmd, const Pipeline& p, const WindowConstants& window,
                               glm::ivec2 extent, std::uint32_t layers) const {
  std::uint32_t gx = groups(extent.x, p.localSize[0]), gy = groups(extent.y, p.localSize[1]);
  if (gx == 0 || gy == 0 || layers == 0) return;
  invocations_ += std::uint64_t(gx) * p.localSize[0] * gy * p.localSize[1] * layers;  // as invocationsOf
  VkDescriptorSet set = set_->set();
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set_->pipelineLayout(), 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(cmd, set_->pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(WindowConstants), &window);
  vkCmdDispatch(cmd, gx, gy, layers);
}

std::uint64_t DeformationPass::invocationsOf(Stage stage, glm::ivec2 extent, std::uint32_t layers) const {
  const Pipeline& p = stage == Stage::Stamps ? stamp_ : stage == Stage::Normals ? normals_ : refill_;
  return std::uint64_t(groups(extent.x, p.localSize[0])) * p.localSize[0] * groups(extent.y, p.localSize[1]) *
         p.localSize[1] * layers;
}

void DeformationPass::recordStamps(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t stamps,
                                   glm::ivec2 stampExtent) const {
  dispatch(cmd, stamp_, window, stampExtent, stamps);
}

void DeformationPass::recordNormals(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t rects,
                                    glm::ivec2 rectExtent) const {
  dispatch(cmd, normals_, window, rectExtent, rects);
}

void DeformationPass::recordRefill(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t tiles,
                                   int tileTexels) const {
  dispatch(cmd, refill_, window, glm::ivec2(tileTexels), tiles);
}

void DeformationPass::recordTilesOut(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t tiles,
                                     int tileTexels) const {
  dispatch(cmd, tilesOut_, window, {(tileTexels + 3) / 4, tileTexels}, tiles);  // 4 texels an invocation
}

void DeformationPass::recordTilesIn(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t tiles,
                                    int tileTexels) const {
  dispatch(cmd, tilesIn_, window, {(tileTexels + 3) / 4, tileTexels}, tiles);
}

void DeformationPass::computeBarrier(VkCommandBuffer cmd) { vk::computeToComputeBarrier(cmd); }

}  // namespace wg::snow
