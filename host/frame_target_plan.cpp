#include "host/frame_target_plan.hpp"

#include <algorithm>
#include <cmath>

#include "host/render_passes.hpp"
#include "vulkan/material_pipeline.hpp"

namespace wg {

namespace {

// Bytes a sample of each target. Lit frames, the only multisampled ones, are RGBA16F; a
// debug view's single-sample target is RGBA32F, the widest.
constexpr std::uint64_t kLitColourBytes = 8, kWidestColourBytes = 16, kDepthBytes = 4;
static_assert(vk::kColourFormat == VK_FORMAT_R16G16B16A16_SFLOAT && vk::kAovFormat == VK_FORMAT_R32G32B32A32_SFLOAT &&
                  vk::kDepthFormat == VK_FORMAT_D32_SFLOAT,
              "the byte counts above follow the renderer's target formats");

// The largest image a frame allocates alone: the multisampled colour, or the resolved
// (or debug view's) colour; its read-back buffer is no larger.
std::uint64_t largestTargetBytes(std::uint64_t pixels, unsigned samples) {
  return pixels * std::max(kLitColourBytes * samples, kWidestColourBytes);
}

// The device-local targets: the resolved colour and depth, and the multisampled pair.
// (The read-back buffer is host memory.)
std::uint64_t frameBytes(std::uint64_t pixels, unsigned samples) {
  const std::uint64_t single = pixels * (kWidestColourBytes + kDepthBytes);
  return samples > 1 ? single + pixels * samples * (kLitColourBytes + kDepthBytes) : single;
}

bool fits(std::uint32_t width, std::uint32_t height, unsigned samples, const FrameLimits& limits) {
  const std::uint64_t pixels = std::uint64_t(width) * height;
  return width <= limits.largestSide && height <= limits.largestSide &&
         largestTargetBytes(pixels, samples) <= limits.largestAllocation && frameBytes(pixels, samples) <= limits.budget;
}

std::string sizeText(std::uint32_t width, std::uint32_t height) { return std::to_string(width) + "x" + std::to_string(height); }

// The largest frame of the same shape that fits at one sample.
std::string largestFittingSize(std::uint32_t width, std::uint32_t height, const FrameLimits& limits) {
  double scale = 1.0;
  while (scale > 0.0) {
    const auto w = static_cast<std::uint32_t>(std::floor(width * scale)), h = static_cast<std::uint32_t>(std::floor(height * scale));
    if (w >= 1 && h >= 1 && fits(w, h, 1, limits)) return sizeText(w, h);
    scale -= 1.0 / 256;
  }
  return "";
}

}  // namespace

FrameLimits frameLimits(const vk::Context& ctx) {
  const VkPhysicalDeviceLimits& device = ctx.properties().limits;
  const vk::Context::MemoryLimits memory = ctx.memoryLimits();
  FrameLimits limits;
  limits.largestSide = std::min({device.maxImageDimension2D, device.maxFramebufferWidth, device.maxFramebufferHeight});
  limits.largestAllocation = memory.largestAllocation;
  limits.budget = memory.deviceLocalHeap;
  limits.samples = static_cast<unsigned>(colourPassSamples(ctx, VK_SAMPLE_COUNT_64_BIT));
  return limits;
}

FrameTargetPlan planFrameTargets(std::uint32_t width, std::uint32_t height, unsigned samples, const FrameLimits& limits) {
  const unsigned wanted = std::max(1u, std::min(samples, limits.samples));
  for (unsigned s = wanted; s >= 1; s /= 2)
    if (fits(width, height, s, limits)) {
      if (s == wanted) return {s, ""};
      return {s, sizeText(width, height) + " at " + std::to_string(wanted) + " MSAA samples does not fit the device's memory; "
                     "rendering with " + std::to_string(s) + (s == 1 ? " sample" : " samples")};
    }
  const std::string largest = largestFittingSize(width, height, limits);
  return {0, "a " + sizeText(width, height) + " frame does not fit the device, even without MSAA; " +
                 (largest.empty() ? std::string("no frame of this shape does") : "the largest of this shape that fits is " + largest) +
                 ": pass a smaller --size"};
}

}  // namespace wg
