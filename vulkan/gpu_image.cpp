#include "vulkan/gpu_image.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace wg::vk {

std::uint32_t texelSize(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_D32_SFLOAT: return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT: return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
    default: throw std::runtime_error("texelSize: unsupported format");
  }
}

bool Image2D::isDepth() const { return format_ == VK_FORMAT_D32_SFLOAT; }

VkDeviceSize Image2D::byteSize() const {
  VkDeviceSize texels = 0;
  for (std::uint32_t level = 0; level < mipLevels_; ++level)
    texels += VkDeviceSize(std::max(1u, width_ >> level)) * std::max(1u, height_ >> level);
  return texels * texelSize(format_) * layers_;
}

Image2D::Image2D(Context& ctx, std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage,
                 std::uint32_t mipLevels, VkSampleCountFlagBits samples)
    : format_(format), width_(width), height_(height), mipLevels_(mipLevels) {
  create(ctx, usage, samples, false);
}

Image2D Image2D::cube(Context& ctx, std::uint32_t size, VkFormat format, VkImageUsageFlags usage,
                      std::uint32_t mipLevels) {
  Image2D image;
  image.format_ = format;
  image.width_ = image.height_ = size;
  image.mipLevels_ = mipLevels;
  image.layers_ = 6;
  image.create(ctx, usage, VK_SAMPLE_COUNT_1_BIT, true);
  return image;
}

void Image2D::create(Context& ctx, VkImageUsageFlags usage, VkSampleCountFlagBits samples, bool cube) {
  VkDevice device = ctx.device();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format_;
  info.extent = {width_, height_, 1};
  info.mipLevels = mipLevels_;
  info.arrayLayers = layers_;
  info.samples = samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image;
  check(vkCreateImage(device, &info, nullptr, &image), "vkCreateImage");
  image_ = UniqueImage(device, image);
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, image, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (alloc.memoryTypeIndex == UINT32_MAX) alloc.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, 0);
  VkDeviceMemory memory;
  check(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
  memory_ = UniqueDeviceMemory(device, memory);
  check(vkBindImageMemory(device, image, memory, 0), "vkBindImageMemory");
  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image;
  viewInfo.viewType = cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format_;
  viewInfo.subresourceRange = {static_cast<VkImageAspectFlags>(isDepth() ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT),
                               0, mipLevels_, 0, layers_};
  VkImageView view;
  check(vkCreateImageView(device, &viewInfo, nullptr, &view), "vkCreateImageView");
  view_ = UniqueImageView(device, view);
}

Image2D::Image2D(Image2D&& o) noexcept { *this = std::move(o); }

Image2D& Image2D::operator=(Image2D&& o) noexcept {
  if (this != &o) {
    view_ = std::move(o.view_);  // the old view, image and memory go in that order
    image_ = std::move(o.image_);
    memory_ = std::move(o.memory_);
    format_ = o.format_;
    width_ = o.width_;
    height_ = o.height_;
    mipLevels_ = o.mipLevels_;
    layers_ = o.layers_;
  }
  return *this;
}

void Image2D::transition(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                         VkImageLayout to) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
  // Conservative but simple: every transition waits for all earlier work.
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &barrier);
}

void Image2D::upload(Context& ctx, const void* texels, VkDeviceSize bytes) {
  Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  staging.write(texels, bytes);
  VkImageAspectFlags aspect = isDepth() ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    transition(cmd, handle(), aspect, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {aspect, 0, 0, 1};
    region.imageExtent = {width_, height_, 1};
    vkCmdCopyBufferToImage(cmd, staging.handle(), handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transition(cmd, handle(), aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
}

void Image2D::uploadLevels(Context& ctx, const std::vector<const std::vector<unsigned char>*>& levels) {
  if (levels.size() != mipLevels_) throw std::runtime_error("Image2D::uploadLevels: wrong number of levels");
  VkDeviceSize total = 0;
  for (const auto* level : levels) total += level->size();
  Buffer staging(ctx, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::vector<VkBufferImageCopy> regions;
  VkDeviceSize offset = 0;
  for (std::uint32_t i = 0; i < mipLevels_; ++i) {
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, layers_};
    region.imageExtent = {std::max(1u, width_ >> i), std::max(1u, height_ >> i), 1};
    const VkDeviceSize bytes =
        VkDeviceSize(region.imageExtent.width) * region.imageExtent.height * texelSize(format_) * layers_;
    if (levels[i]->size() != bytes) throw std::runtime_error("Image2D::uploadLevels: a level of the wrong size");
    std::memcpy(static_cast<unsigned char*>(staging.mapped()) + offset, levels[i]->data(), bytes);
    regions.push_back(region);
    offset += bytes;
  }
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    transition(cmd, handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    vkCmdCopyBufferToImage(cmd, staging.handle(), handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           static_cast<std::uint32_t>(regions.size()), regions.data());
    transition(cmd, handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
}

std::vector<unsigned char> Image2D::download(Context& ctx, VkImageLayout layout) {
  const VkDeviceSize bytes = VkDeviceSize(width_) * height_ * texelSize(format_);  // level 0
  Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  VkImageAspectFlags aspect = isDepth() ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    transition(cmd, handle(), aspect, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {aspect, 0, 0, 1};
    region.imageExtent = {width_, height_, 1};
    vkCmdCopyImageToBuffer(cmd, handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
    transition(cmd, handle(), aspect, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
  });
  std::vector<unsigned char> out(bytes);
  std::memcpy(out.data(), staging.mapped(), out.size());
  return out;
}

}  // namespace wg::vk
