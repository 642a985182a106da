#include "host/sky_light_builder.hpp"

#include <glm/gtc/packing.hpp>

#include <memory>
#include <stdexcept>
#include <string>

#include "vulkan/compute_barriers.hpp"
#include "vulkan/runtime_shader.hpp"

namespace wg {

namespace {

constexpr std::uint32_t kFaces = 6;

std::uint32_t levelSize(std::uint32_t level) { return SkyLightBuilder::kReflectionFaceSize >> level; }

// Texels of every level before `level`, six faces each.
std::uint32_t reflectionTexelsBefore(std::uint32_t level) {
  std::uint32_t texels = 0;
  for (std::uint32_t l = 0; l < level; ++l) texels += kFaces * levelSize(l) * levelSize(l);
  return texels;
}

constexpr const char* kSkyPushConstants = R"(#version 440
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(push_constant) uniform Sky { vec4 sky; vec4 weather; } pc;
)";

// wg_sky (the radiance itself) towards each direction.
std::string skyRadianceShader() {
  std::string text = kSkyPushConstants;
  text += R"(layout(std430, set = 0, binding = 0) readonly buffer Directions { vec4 directions[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Radiance { vec4 radiance[]; };
)";
  text += skyLibraryText("pc", {"wg_sky"});
  text += R"(
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(directions.length())) return;
  radiance[i] = vec4(wg_sky(directions[i].xyz), 1.0);
}
)";
  return text;
}

// Every level of the reflection cube, one invocation a texel, packed as RGBA16F for a
// buffer-to-image copy. Level l is wg_sky prefiltered with GGX of roughness
// l / (levels - 1), taking normal = view = reflection (Karis 2013, "Real Shading in
// Unreal Engine 4", the split sum's first factor): importance-sampled half vectors,
// weighted by N.L. Level 0 is the sky itself. Rougher levels have fewer texels and a
// wider lobe, so they take more samples.
std::string skyReflectionShader() {
  std::string text = kSkyPushConstants;
  text += "const uint kFaceSize = " + std::to_string(SkyLightBuilder::kReflectionFaceSize) +
          "u;\nconst uint kLevels = " + std::to_string(SkyLightBuilder::kReflectionLevels) + "u;\n";
  text += "layout(std430, set = 0, binding = 0) writeonly buffer Texels { uvec2 texels[]; };\n";
  text += skyLibraryText("pc", {"wg_sky"});
  text += R"(
// The direction through a face's point st in [-1, 1]^2: Vulkan's cube map face selection
// (faces +x -x +y -y +z -z; s and t run along these axes).
vec3 cubeDirection(const uint face, const vec2 st) {
  if (face == 0u) return vec3(1.0, -st.y, -st.x);
  if (face == 1u) return vec3(-1.0, -st.y, st.x);
  if (face == 2u) return vec3(st.x, 1.0, st.y);
  if (face == 3u) return vec3(st.x, -1.0, -st.y);
  if (face == 4u) return vec3(st.x, -st.y, 1.0);
  return vec3(-st.x, -st.y, -1.0);
}
vec3 prefiltered(const vec3 n, const uint level) {
  if (level == 0u) return wg_sky(n);
  float a = float(level) / float(kLevels - 1u);
  a *= a;
  vec3 tx = normalize(cross(abs(n.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), n));
  vec3 ty = cross(n, tx);
  uint count = 16u << level;
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (uint i = 0u; i < count; ++i) {
    // Hammersley point i of count, mapped to a GGX-distributed half vector.
    vec2 xi = vec2(float(i) / float(count), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
    float phi = 6.28318531 * xi.x;
    float cosTheta = sqrt((1.0 - xi.y) / (1.0 + (a * a - 1.0) * xi.y));
    float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
    vec3 h = (tx * cos(phi) + ty * sin(phi)) * sinTheta + n * cosTheta;
    vec3 l = 2.0 * dot(n, h) * h - n;
    float NoL = dot(n, l);
    if (NoL > 0.0) {
      sum += wg_sky(l) * NoL;
      weight += NoL;
    }
  }
  return sum / max(weight, 1e-4);
}
void main() {
  uint i = gl_GlobalInvocationID.x;
  uint level = 0u, first = 0u, size = kFaceSize;
  while (level + 1u < kLevels && i >= first + 6u * size * size) {
    first += 6u * size * size;
    size >>= 1;
    ++level;
  }
  uint texel = i - first;
  if (texel >= 6u * size * size) return;
  uint face = texel / (size * size);
  texel -= face * size * size;
  vec2 st = (vec2(texel % size, texel / size) + 0.5) * (2.0 / float(size)) - 1.0;
  vec3 c = prefiltered(normalize(cubeDirection(face, st)), level);
  texels[i] = uvec2(packHalf2x16(c.rg), packHalf2x16(vec2(c.b, 1.0)));
}
)";
  return text;
}

}  // namespace

SkyLightBuilder::SkyLightBuilder(vk::Context& ctx)
    : ctx_(ctx),
      samples_(cubeSkySamples(kIrradianceFaceSize)),
      directions_(ctx, samples_.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      radiance_(ctx, samples_.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      reflectionTexels_(ctx, reflectionTexelsBefore(kReflectionLevels) * sizeof(glm::uvec2),
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT),
      reflection_(vk::Image2D::cube(ctx, kReflectionFaceSize, VK_FORMAT_R16G16B16A16_SFLOAT,
                                    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, kReflectionLevels)) {
  auto* directions = static_cast<glm::vec4*>(directions_.mapped());
  for (std::size_t i = 0; i < samples_.size(); ++i) directions[i] = glm::vec4(samples_[i].direction, 0.f);
  // Black, so that frames before the first build (AOVs) bind a defined image.
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    vk::Image2D::transition(cmd, reflection_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    const VkClearColorValue black{};
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, kReflectionLevels, 0, kFaces};
    vkCmdClearColorImage(cmd, reflection_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &all);
    vk::Image2D::transition(cmd, reflection_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
}

SkyLightBuilder::~SkyLightBuilder() { vkDeviceWaitIdle(ctx_.device()); }

SkyLightBuilder::Pipeline SkyLightBuilder::makePipeline(const std::string& shader, const char* name) {
  auto module = vk::compileRuntimeShader(shader, vk::RuntimeStage::Compute, name);
  Pipeline p;
  p.set = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, std::vector{module.interface}, VK_SHADER_STAGE_COMPUTE_BIT);
  if (p.set->pushConstantBytes() != sizeof(SkyInputs))
    throw std::runtime_error(std::string(name) + " shader: push constants are " +
                             std::to_string(p.set->pushConstantBytes()) + " bytes");
  p.module = vk::createShaderModule(ctx_, module.words);
  p.pipeline = vk::createComputePipeline(ctx_, p.module.get(), p.set->pipelineLayout());
  p.localSize = module.interface.localSize[0];
  return p;
}

void SkyLightBuilder::record(VkCommandBuffer cmd, const Pipeline& p, const SkyInputs& inputs,
                             std::uint32_t invocations) const {
  VkDescriptorSet set = p.set->set();
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.set->pipelineLayout(), 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(cmd, p.set->pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof inputs, &inputs);
  vkCmdDispatch(cmd, (invocations + p.localSize - 1) / p.localSize, 1, 1);
}

void SkyLightBuilder::recordReflectionCopy(VkCommandBuffer cmd) const {
  std::vector<VkBufferImageCopy> regions;
  for (std::uint32_t level = 0; level < kReflectionLevels; ++level) {
    VkBufferImageCopy region{};
    region.bufferOffset = VkDeviceSize(reflectionTexelsBefore(level)) * sizeof(glm::uvec2);
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, kFaces};
    region.imageExtent = {levelSize(level), levelSize(level), 1};
    regions.push_back(region);
  }
  vk::Image2D::transition(cmd, reflection_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  vkCmdCopyBufferToImage(cmd, reflectionTexels_.handle(), reflection_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         static_cast<std::uint32_t>(regions.size()), regions.data());
  vk::Image2D::transition(cmd, reflection_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

const SkyIrradiance& SkyLightBuilder::lightFor(const FrameState& frame) {
  const SkyInputs inputs = skyInputs(frame);
  if (built_ == inputs) return irradiance_;
  if (!irradiancePipeline_) {
    irradiancePipeline_ = makePipeline(skyRadianceShader(), "sky irradiance");
    irradiancePipeline_->set->bindBuffer("Directions", directions_);
    irradiancePipeline_->set->bindBuffer("Radiance", radiance_);
    reflectionPipeline_ = makePipeline(skyReflectionShader(), "sky reflection");
    reflectionPipeline_->set->bindBuffer("Texels", reflectionTexels_);
  }
  const auto count = static_cast<std::uint32_t>(samples_.size());
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    record(cmd, *irradiancePipeline_, inputs, count);
    record(cmd, *reflectionPipeline_, inputs, reflectionTexelsBefore(kReflectionLevels));
    vk::computeToTransferAndHostBarrier(cmd);
    recordReflectionCopy(cmd);
  });
  const auto* texels = static_cast<const glm::vec4*>(radiance_.mapped());
  std::vector<glm::vec3> radiance(count);
  for (std::uint32_t i = 0; i < count; ++i) radiance[i] = glm::vec3(texels[i]);
  irradiance_ = projectSkyIrradiance(samples_, radiance);
  built_ = inputs;
  ++builds_;
  return irradiance_;
}

glm::vec3 SkyLightBuilder::reflectionTexel(std::uint32_t level, std::uint32_t face, std::uint32_t x,
                                           std::uint32_t y) const {
  const std::uint32_t size = levelSize(level);
  const auto* texels = static_cast<const glm::uvec2*>(reflectionTexels_.mapped());
  const glm::uvec2 t = texels[reflectionTexelsBefore(level) + (face * size + y) * size + x];
  const glm::vec2 rg = glm::unpackHalf2x16(t.x), ba = glm::unpackHalf2x16(t.y);
  return {rg.x, rg.y, ba.x};
}

}  // namespace wg
