#include "host/bloom_pass.hpp"

#include <stdexcept>
#include <string>

#include "vulkan/compute_barriers.hpp"
#include "vulkan/runtime_shader.hpp"

namespace wg {

namespace {
struct BloomConstants {
  std::int32_t size[2];
  std::int32_t halfSize[2];
  float threshold;
  float intensity;
};

constexpr std::string_view kCommon = R"(#version 440
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(push_constant) uniform Bloom { ivec2 size; ivec2 halfSize; float threshold; float intensity; } bloom;
layout(set = 0, binding = 0, rgba16f) uniform image2D Colour;
layout(set = 0, binding = 1, rgba32f) uniform image2D HalfA;
layout(set = 0, binding = 2, rgba32f) uniform image2D HalfB;
)";

// Half-resolution bright pass: the 2x2 average, scaled so only what exceeds the
// threshold (by its brightest channel) remains.
constexpr std::string_view kBright = R"(
void main() {
  ivec2 h = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(h, bloom.halfSize))) return;
  vec3 sum = vec3(0.0);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) sum += imageLoad(Colour, min(2 * h + ivec2(x, y), bloom.size - 1)).rgb;
  vec3 c = 0.25 * sum;
  float peak = max(c.r, max(c.g, c.b));
  imageStore(HalfA, h, vec4(c * (max(peak - bloom.threshold, 0.0) / max(peak, 1e-4)), 1.0));
}
)";

// A 9-tap Gaussian (sigma 2 half-resolution texels), one axis per dispatch.
constexpr std::string_view kBlur = R"(
const float kWeights[5] = float[](0.2270, 0.1946, 0.1216, 0.0541, 0.0162);
void main() {
  ivec2 h = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(h, bloom.halfSize))) return;
  vec3 sum = kWeights[0] * imageLoad(SOURCE, h).rgb;
  for (int i = 1; i < 5; ++i) {
    sum += kWeights[i] * imageLoad(SOURCE, clamp(h + AXIS * i, ivec2(0), bloom.halfSize - 1)).rgb;
    sum += kWeights[i] * imageLoad(SOURCE, clamp(h - AXIS * i, ivec2(0), bloom.halfSize - 1)).rgb;
  }
  imageStore(TARGET, h, vec4(sum, 1.0));
}
)";

// Adds the blurred glow back, bilinearly upsampled.
constexpr std::string_view kComposite = R"(
vec3 glowAt(vec2 p) {
  ivec2 i = ivec2(floor(p));
  vec2 f = p - vec2(i);
  ivec2 hi = bloom.halfSize - 1;
  vec3 a = imageLoad(HalfA, clamp(i, ivec2(0), hi)).rgb, b = imageLoad(HalfA, clamp(i + ivec2(1, 0), ivec2(0), hi)).rgb;
  vec3 c = imageLoad(HalfA, clamp(i + ivec2(0, 1), ivec2(0), hi)).rgb, d = imageLoad(HalfA, clamp(i + ivec2(1, 1), ivec2(0), hi)).rgb;
  return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, bloom.size))) return;
  vec4 c = imageLoad(Colour, p);
  imageStore(Colour, p, vec4(c.rgb + bloom.intensity * glowAt((vec2(p) + 0.5) * 0.5 - 0.5), c.a));
}
)";

std::string blurSource(const char* source, const char* target, const char* axis) {
  std::string body(kBlur);
  for (auto [key, value] : {std::pair{"SOURCE", source}, std::pair{"TARGET", target}, std::pair{"AXIS", axis}})
    for (std::size_t at; (at = body.find(key)) != std::string::npos;) body.replace(at, std::string(key).size(), value);
  return std::string(kCommon) + body;
}

std::uint32_t groups(std::uint32_t extent, std::uint32_t local) { return (extent + local - 1) / local; }

}  // namespace

BloomPass::BloomPass(vk::Context& ctx) : ctx_(ctx) {
  std::vector<vk::CompiledModule> modules;
  modules.push_back(vk::compileRuntimeShader(std::string(kCommon) + std::string(kBright), vk::RuntimeStage::Compute, "bloom bright"));
  modules.push_back(vk::compileRuntimeShader(blurSource("HalfA", "HalfB", "ivec2(1, 0)"), vk::RuntimeStage::Compute, "bloom blur"));
  modules.push_back(vk::compileRuntimeShader(blurSource("HalfB", "HalfA", "ivec2(0, 1)"), vk::RuntimeStage::Compute, "bloom blur"));
  modules.push_back(vk::compileRuntimeShader(std::string(kCommon) + std::string(kComposite), vk::RuntimeStage::Compute,
                                             "bloom composite"));
  std::vector<ModuleInterface> interfaces;
  for (const auto& m : modules) interfaces.push_back(m.interface);
  set_ = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, interfaces, VK_SHADER_STAGE_COMPUTE_BIT);
  if (set_->pushConstantBytes() != sizeof(BloomConstants))
    throw std::runtime_error("bloom shaders: push constants are " + std::to_string(set_->pushConstantBytes()) + " bytes");
  Stage* stages[] = {&bright_, &blurH_, &blurV_, &composite_};
  for (std::size_t i = 0; i < modules.size(); ++i) {
    Stage& s = *stages[i];
    s.module = vk::createShaderModule(ctx_, modules[i].words);
    s.pipeline = vk::createComputePipeline(ctx_, s.module.get(), set_->pipelineLayout());
    s.localSize[0] = modules[i].interface.localSize[0];
    s.localSize[1] = modules[i].interface.localSize[1];
  }
}

BloomPass::~BloomPass() { vkDeviceWaitIdle(ctx_.device()); }

void BloomPass::record(VkCommandBuffer cmd, const vk::Image2D& colour, const BloomSettings& settings) {
  std::uint32_t w = colour.width(), h = colour.height(), hw = (w + 1) / 2, hh = (h + 1) / 2;
  if (halfA_.width() != hw || halfA_.height() != hh) {
    // The previous frame's submit has completed (every submit waits), so they can go.
    for (vk::Image2D* half : {&halfA_, &halfB_})
      *half = vk::Image2D(ctx_, hw, hh, VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT);
  }
  set_->bindImage("Colour", colour.view(), VK_IMAGE_LAYOUT_GENERAL);
  set_->bindImage("HalfA", halfA_.view(), VK_IMAGE_LAYOUT_GENERAL);
  set_->bindImage("HalfB", halfB_.view(), VK_IMAGE_LAYOUT_GENERAL);
  vk::Image2D::transition(cmd, colour.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_GENERAL);
  for (vk::Image2D* half : {&halfA_, &halfB_})
    vk::Image2D::transition(cmd, half->handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
  BloomConstants c{{std::int32_t(w), std::int32_t(h)}, {std::int32_t(hw), std::int32_t(hh)}, settings.threshold, settings.intensity};
  VkDescriptorSet set = set_->set();
  auto run = [&](const Stage& s, std::uint32_t x, std::uint32_t y) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, s.pipeline.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set_->pipelineLayout(), 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, set_->pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof c, &c);
    vkCmdDispatch(cmd, groups(x, s.localSize[0]), groups(y, s.localSize[1]), 1);
    vk::computeToComputeBarrier(cmd);
  };
  run(bright_, hw, hh);
  run(blurH_, hw, hh);
  run(blurV_, hw, hh);
  run(composite_, w, h);
  vk::Image2D::transition(cmd, colour.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
}

}  // namespace wg
