#include "runtime/snow/gpu_deformation_map.hpp"

#include <algorithm>
#include <cstring>

#include "runtime/snow/beyond_window_stamping.hpp"
#include "runtime/snow/deformation_texel.hpp"
#include "runtime/snow/map_lookup.hpp"
#include "runtime/vulkan/compute_barriers.hpp"

namespace wg::snow {

namespace {
constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
// Stamp buffers start with room for this many and double when a frame needs more.
constexpr std::size_t kInitialStamps = 64;
// Half floats hold the height to ~0.2 mm and the normal to ~1e-3: plenty for shading,
// half the memory of RGBA32F.
constexpr VkFormat kSurfaceFormat = VK_FORMAT_R16G16B16A16_SFLOAT;


glm::ivec4 packRect(const TexelRect& r) { return {r.min.x, r.min.y, r.size.x, r.size.y}; }
}  // namespace

GpuDeformationMap::GpuDeformationMap(vk::Context& ctx, const WindowSettings& settings, glm::vec2 camera)
    : ctx_(ctx), window_(settings), pass_(ctx), store_(settings.printStoreBudget), timer_(ctx) {
  window_.setOrigin(window_.originFor(camera));
  VkDeviceSize bytes = window_.texelCount() * sizeof(std::uint32_t);
  heights_ = vk::Buffer(ctx_, bytes, kStorage);
  normals_ = vk::Buffer(ctx_, bytes, kStorage);
  std::memset(heights_.mapped(), 0, bytes);
  std::memset(normals_.mapped(), 0, bytes);
  pass_.bind("Heights", heights_);
  pass_.bind("Normals", normals_);
  surface_ = vk::Image2D(ctx_, settings.resolution, settings.resolution, kSurfaceFormat,
                         VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                             VK_IMAGE_USAGE_TRANSFER_SRC_BIT);  // cleared at start; read back by tests
  pass_.bindSurface(surface_);
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    // Untouched snow: no offset, normal straight up.
    vk::Image2D::transition(cmd, surface_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_GENERAL);
    VkClearColorValue flat{{0.f, 0.f, 1.f, 0.f}};
    VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, surface_.handle(), VK_IMAGE_LAYOUT_GENERAL, &flat, 1, &all);
    vk::Image2D::transition(cmd, surface_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
  reserve(kInitialStamps);
}

GpuDeformationMap::~GpuDeformationMap() { vkDeviceWaitIdle(ctx_.device()); }

void GpuDeformationMap::reserve(std::size_t stamps) {
  if (stamps <= capacity_) return;
  capacity_ = std::max(stamps, 2 * capacity_);
  stamps_ = vk::Buffer(ctx_, capacity_ * sizeof(Stamp), kStorage);
  stampBoxes_ = vk::Buffer(ctx_, capacity_ * sizeof(glm::ivec4), kStorage);
  // One more rectangle than stamps: the whole window, for the refill pass.
  normalRects_ = vk::Buffer(ctx_, (capacity_ + 1) * sizeof(glm::ivec4), kStorage);
  pass_.bind("Stamps", stamps_);
  pass_.bind("StampBoxes", stampBoxes_);
  pass_.bind("NormalRects", normalRects_);
}

WindowConstants GpuDeformationMap::constants(std::uint32_t refillQuanta) const {
  WindowConstants c{};
  int n = window_.resolution();
  c.origin[0] = window_.origin().x;
  c.origin[1] = window_.origin().y;
  c.originSlot[0] = floorMod(window_.origin().x, n);
  c.originSlot[1] = floorMod(window_.origin().y, n);
  c.resolution = n;
  c.texelSize = window_.texelSize();
  c.refillQuanta = refillQuanta;
  return c;
}

double GpuDeformationMap::submit(const std::function<void(VkCommandBuffer)>& record) {
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    timer_.reset(cmd);
    vk::Image2D::transition(cmd, surface_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                            VK_IMAGE_LAYOUT_GENERAL);
    timer_.start(cmd);
    record(cmd);
    timer_.stop(cmd);
    vk::Image2D::transition(cmd, surface_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    vk::computeToHostBarrier(cmd);  // host reads of the map (recentring, tests)
  });
  return timer_.milliseconds();
}

double GpuDeformationMap::apply(std::span<const Stamp> stamps) {
  stampBeyondWindow(window_, stamps, store_, refill_.totalQuanta());
  reserve(stamps.size());
  auto* records = static_cast<Stamp*>(stamps_.mapped());
  auto* boxes = static_cast<glm::ivec4*>(stampBoxes_.mapped());
  auto* rects = static_cast<glm::ivec4*>(normalRects_.mapped());
  std::uint32_t count = 0;
  glm::ivec2 stampExtent(0), rectExtent(0);
  for (const Stamp& s : stamps) {
    TexelRect box = stampBounds(s, window_);
    if (box.empty()) continue;  // entirely outside the window
    TexelRect rect = box.grown(1).intersect(window_.rect());
    records[count] = s;
    boxes[count] = packRect(box);
    rects[count] = packRect(rect);
    stampExtent = glm::max(stampExtent, box.size);
    rectExtent = glm::max(rectExtent, rect.size);
    ++count;
  }
  if (count == 0) return 0.0;
  WindowConstants c = constants(0);
  return submit([&](VkCommandBuffer cmd) {
    pass_.recordStamps(cmd, c, count, stampExtent);
    DeformationPass::computeBarrier(cmd);
    pass_.recordNormals(cmd, c, count, rectExtent);
  });
}

double GpuDeformationMap::refill(double metresPerSecond, double seconds) {
  std::uint32_t quanta = refill_.advance(metresPerSecond, seconds);
  if (quanta == 0) return 0.0;
  static_cast<glm::ivec4*>(normalRects_.mapped())[0] = packRect(window_.rect());
  WindowConstants c = constants(quanta);
  return submit([&](VkCommandBuffer cmd) {
    pass_.recordRefill(cmd, c);
    DeformationPass::computeBarrier(cmd);
    pass_.recordNormals(cmd, c, 1, window_.rect().size);
  });
}

Recentring GpuDeformationMap::follow(glm::vec2 camera) {
  Recentring r = recentre(window_, texels(), camera, store_, refill_.totalQuanta());
  if (r.moved()) renormal(r.enteredRects);
  return r;
}

void GpuDeformationMap::renormal(const std::vector<TexelRect>& rects) {
  reserve(rects.size());
  auto* out = static_cast<glm::ivec4*>(normalRects_.mapped());
  glm::ivec2 extent(0);
  std::uint32_t count = 0;
  for (const TexelRect& r : rects) {
    if (r.empty()) continue;
    out[count++] = packRect(r);
    extent = glm::max(extent, r.size);
  }
  if (count == 0) return;
  WindowConstants c = constants(0);
  submit([&](VkCommandBuffer cmd) { pass_.recordNormals(cmd, c, count, extent); });
}

MapTexels GpuDeformationMap::texels() {
  return {{static_cast<std::uint32_t*>(heights_.mapped()), window_.texelCount()},
          {static_cast<std::uint32_t*>(normals_.mapped()), window_.texelCount()}};
}

float GpuDeformationMap::depthAt(glm::vec2 world) { return texelDepth(heightTexelAt(window_, texels().heights, world)); }
float GpuDeformationMap::heightAt(glm::vec2 world) { return texelHeight(heightTexelAt(window_, texels().heights, world)); }
glm::vec3 GpuDeformationMap::normalAt(glm::vec2 world) { return snow::normalAt(window_, texels().normals, world); }

}  // namespace wg::snow
