// A device image with one view: textures, render targets, depth and shadow maps, and
// cube maps (six layers, a cube view).
#pragma once
#include <vector>

#include "vulkan/gpu_buffer.hpp"

namespace wg::vk {

class Image2D {
 public:
  Image2D() = default;
  // `mipLevels` levels (textures; the view covers them all) or `samples` samples per
  // texel (multisampled attachments), not both.
  Image2D(Context& ctx, std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage,
          std::uint32_t mipLevels = 1, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
  // A cube map of size x size texels a face and `mipLevels` levels.
  static Image2D cube(Context& ctx, std::uint32_t size, VkFormat format, VkImageUsageFlags usage,
                      std::uint32_t mipLevels);
  Image2D(Image2D&& other) noexcept;
  Image2D& operator=(Image2D&& other) noexcept;

  VkImage handle() const { return image_.get(); }
  VkImageView view() const { return view_.get(); }
  VkFormat format() const { return format_; }
  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::uint32_t mipLevels() const { return mipLevels_; }
  std::uint32_t layers() const { return layers_; }  // 6 for a cube map
  bool isDepth() const;
  VkDeviceSize byteSize() const;  // every mip level; one sample per texel

  // Uploads tightly packed texels and leaves the image shader-readable.
  void upload(Context& ctx, const void* texels, VkDeviceSize bytes);
  // The same for every mip level, largest first, each tightly packed (a cube map's
  // level: its six faces in Vulkan's order, +x -x +y -y +z -z).
  void uploadLevels(Context& ctx, const std::vector<const std::vector<unsigned char>*>& levels);
  // Reads level 0 back (the image must be in `layout`).
  std::vector<unsigned char> download(Context& ctx, VkImageLayout layout);

  // Every level and layer of `image`.
  static void transition(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                         VkImageLayout to);

 private:
  void create(Context& ctx, VkImageUsageFlags usage, VkSampleCountFlagBits samples, bool cube);
  // Destroyed view, image, memory.
  UniqueDeviceMemory memory_;
  UniqueImage image_;
  UniqueImageView view_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  std::uint32_t width_ = 0, height_ = 0;
  std::uint32_t mipLevels_ = 1;
  std::uint32_t layers_ = 1;
};

// Bytes per texel of the formats the runtime uses.
std::uint32_t texelSize(VkFormat format);

}  // namespace wg::vk
