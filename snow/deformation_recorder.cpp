#include "snow/deformation_recorder.hpp"

#include <algorithm>
#include <stdexcept>

#include "snow/beyond_window_stamping.hpp"
#include "snow/deformation_texel.hpp"

namespace wg::snow {

namespace {
constexpr VkBufferUsageFlags kMapUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
constexpr VkBufferUsageFlags kUploadUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
// Stamps and rectangles go up with vkCmdUpdateBuffer (at most 64 KiB a call), so the
// upload is part of the recorded commands and needs no host buffer to guard; a frame
// with more stamps records several batches.
constexpr std::size_t kBatch = 1024;
static_assert(kBatch * sizeof(Stamp) <= 65536, "one vkCmdUpdateBuffer per batch");
// Half floats hold the height to ~0.2 mm and the normal to ~1e-3: plenty for shading,
// half the memory of RGBA32F.
constexpr VkFormat kSurfaceFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
// Everything that reads or writes the map: the compute passes, the mesh raster and
// the copies.
constexpr VkPipelineStageFlags kMapStages =
    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkAccessFlags kMapWrites = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
constexpr VkAccessFlags kMapAccess =
    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkAccessFlags srcAccess, VkPipelineStageFlags dst,
                   VkAccessFlags dstAccess) {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = srcAccess;
  b.dstAccessMask = dstAccess;
  vkCmdPipelineBarrier(cmd, src, dst, 0, 1, &b, 0, nullptr, 0, nullptr);
}

// Between any two steps: the map's earlier writes before its later reads and writes
// (and earlier reads before later writes: the upload buffers are reused each batch).
void mapBarrier(VkCommandBuffer cmd) { memoryBarrier(cmd, kMapStages, kMapWrites, kMapStages, kMapAccess); }

glm::ivec4 packRect(const TexelRect& r) { return {r.min.x, r.min.y, r.size.x, r.size.y}; }

template <typename T>
void update(VkCommandBuffer cmd, const vk::Buffer& buffer, const std::vector<T>& data, std::size_t first,
            std::size_t count) {
  vkCmdUpdateBuffer(cmd, buffer.handle(), 0, count * sizeof(T), data.data() + first);
}

// The tiles of `from` that are not in `to` (x, z of their first texel, size, 0): what
// leaves when the window moves from one to the other, or, swapped, what enters.
std::vector<glm::ivec4> tilesOutside(const SnowWindow& window, const TexelRect& from, const TexelRect& to) {
  std::vector<glm::ivec4> tiles;
  int n = window.tileTexels();
  for (int tz = from.min.y; tz < from.min.y + from.size.y; tz += n)
    for (int tx = from.min.x; tx < from.min.x + from.size.x; tx += n)
      if (!to.contains({tx, tz})) tiles.push_back({tx, tz, n, 0});
  return tiles;
}

// Uploads `data` in batches the upload buffer holds, each followed by
// dispatch(first, count).
template <typename T, typename Dispatch>
void inBatches(VkCommandBuffer cmd, const vk::Buffer& buffer, const std::vector<T>& data, Dispatch&& dispatch) {
  for (std::size_t first = 0; first < data.size(); first += kBatch) {
    std::size_t count = std::min(kBatch, data.size() - first);
    mapBarrier(cmd);
    update(cmd, buffer, data, first, count);
    mapBarrier(cmd);
    dispatch(first, static_cast<std::uint32_t>(count));
  }
}

glm::ivec2 largest(const std::vector<glm::ivec4>& rects, std::size_t first, std::size_t count) {
  glm::ivec2 extent(0);
  for (std::size_t i = first; i < first + count; ++i) extent = glm::max(extent, glm::ivec2(rects[i].z, rects[i].w));
  return extent;
}
}  // namespace

DeformationRecorder::DeformationRecorder(vk::Context& ctx, const WindowSettings& settings, glm::vec2 camera,
                                         std::uint32_t framesInFlight)
    : ctx_(ctx), window_(settings), pass_(ctx), store_(settings.printStoreBudget), schedule_(window_),
      framesInFlight_(std::max(framesInFlight, 1u)) {
  window_.setOrigin(window_.originFor(camera));
  VkDeviceSize bytes = window_.texelCount() * sizeof(std::uint32_t);
  heights_ = vk::Buffer(ctx_, bytes, kMapUsage, vk::BufferMemory::DeviceLocal);
  normals_ = vk::Buffer(ctx_, bytes, kMapUsage, vk::BufferMemory::DeviceLocal);
  stamps_ = vk::Buffer(ctx_, kBatch * sizeof(Stamp), kUploadUsage, vk::BufferMemory::DeviceLocal);
  stampBoxes_ = vk::Buffer(ctx_, kBatch * sizeof(glm::ivec4), kUploadUsage, vk::BufferMemory::DeviceLocal);
  normalRects_ = vk::Buffer(ctx_, kBatch * sizeof(glm::ivec4), kUploadUsage, vk::BufferMemory::DeviceLocal);
  refillTiles_ = vk::Buffer(ctx_, kBatch * sizeof(glm::ivec4), kUploadUsage, vk::BufferMemory::DeviceLocal);
  transferTiles_ = vk::Buffer(ctx_, kBatch * sizeof(glm::ivec4), kUploadUsage, vk::BufferMemory::DeviceLocal);
  readback_ = vk::Buffer(ctx_, bytes,
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                             VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  surface_ = vk::Image2D(ctx_, settings.resolution, settings.resolution, kSurfaceFormat,
                         VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                             VK_IMAGE_USAGE_TRANSFER_SRC_BIT);  // cleared on first use; read back by tests
  pass_.bind("Heights", heights_);
  pass_.bind("Normals", normals_);
  pass_.bind("Stamps", stamps_);
  pass_.bind("StampBoxes", stampBoxes_);
  pass_.bind("NormalRects", normalRects_);
  pass_.bind("RefillTiles", refillTiles_);
  pass_.bind("HostHeights", readback_);
  pass_.bind("TransferTiles", transferTiles_);
  pass_.bindSurface(surface_);
  if (ctx_.fragmentStoresAndAtomics())
    meshPass_ = std::make_unique<MeshInteractorPass>(ctx_, settings.resolution, heights_);
}

// The owner makes sure the device is done with the recorded work before this.
DeformationRecorder::~DeformationRecorder() = default;

void DeformationRecorder::beginFrame(std::uint32_t frameIndex) {
  if (frameIndex >= framesInFlight_)
    throw std::invalid_argument("snow frame index " + std::to_string(frameIndex) + " is not below the " +
                                std::to_string(framesInFlight_) + " frames in flight");
  frame_ = frameIndex;
  if (frameIndex != readbackFrame_) return;
  if (readbackState_ == Readback::Copying) readbackState_ = Readback::Ready;
  else if (readbackState_ == Readback::Uploading) readbackState_ = Readback::Idle;
}

WindowConstants DeformationRecorder::constants(std::uint32_t refillQuanta) const {
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

void DeformationRecorder::clearOnce(VkCommandBuffer cmd) {
  if (cleared_) return;
  // Untouched snow: no offset, normal straight up (packNormal of up is 0).
  vkCmdFillBuffer(cmd, heights_.handle(), 0, VK_WHOLE_SIZE, 0u);
  vkCmdFillBuffer(cmd, normals_.handle(), 0, VK_WHOLE_SIZE, 0u);
  vk::Image2D::transition(cmd, surface_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  VkClearColorValue flat{{0.f, 0.f, 1.f, 0.f}};
  VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, surface_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &flat, 1, &all);
  vk::Image2D::transition(cmd, surface_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  mapBarrier(cmd);
  cleared_ = true;
}

template <typename Record>
void DeformationRecorder::withSurfaceWritable(VkCommandBuffer cmd, Record&& record) {
  vk::Image2D::transition(cmd, surface_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                          VK_IMAGE_LAYOUT_GENERAL);
  mapBarrier(cmd);
  record();
  vk::Image2D::transition(cmd, surface_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void DeformationRecorder::recordNormals(VkCommandBuffer cmd, const std::vector<TexelRect>& rects) {
  std::vector<glm::ivec4> packed;
  for (const TexelRect& r : rects)
    if (!r.empty()) packed.push_back(packRect(r));
  WindowConstants c = constants(0);
  inBatches(cmd, normalRects_, packed, [&](std::size_t first, std::uint32_t count) {
    pass_.recordNormals(cmd, c, count, largest(packed, first, count));
  });
}

void DeformationRecorder::recordStamps(VkCommandBuffer cmd, std::span<const Stamp> stamps) {
  clearOnce(cmd);
  schedule_.stamped(window_, stamps, refill_.totalQuanta());
  stampBeyondWindow(window_, stamps, store_, refill_.totalQuanta());
  std::vector<Stamp> records;
  std::vector<glm::ivec4> boxes, rects;
  for (const Stamp& s : stamps) {
    TexelRect box = stampBounds(s, window_);
    if (box.empty()) continue;  // entirely outside the window: the store has it
    records.push_back(s);
    boxes.push_back(packRect(box));
    rects.push_back(packRect(box.grown(1).intersect(window_.rect())));
  }
  if (records.empty()) return;
  WindowConstants c = constants(0);
  withSurfaceWritable(cmd, [&] {
    for (std::size_t first = 0; first < records.size(); first += kBatch) {
      std::size_t count = std::min(kBatch, records.size() - first);
      update(cmd, stamps_, records, first, count);
      update(cmd, stampBoxes_, boxes, first, count);
      update(cmd, normalRects_, rects, first, count);
      mapBarrier(cmd);
      auto layers = static_cast<std::uint32_t>(count);
      pass_.recordStamps(cmd, c, layers, largest(boxes, first, count));
      mapBarrier(cmd);
      pass_.recordNormals(cmd, c, layers, largest(rects, first, count));
      mapBarrier(cmd);
    }
  });
}

void DeformationRecorder::recordFrame(VkCommandBuffer cmd, const FrameWork& work) {
  const std::uint64_t start = pass_.invocations(), budget = window_.settings().workPerFrame;
  auto left = [&] { return budget - std::min(budget, pass_.invocations() - start); };
  recordFollow(cmd, work.camera);
  const int n = window_.tileTexels();
  const std::uint64_t normalTile = pass_.invocationsOf(DeformationPass::Stage::Normals, glm::ivec2(n + 2), 1);
  const std::uint64_t refillTile = pass_.invocationsOf(DeformationPass::Stage::Refill, glm::ivec2(n), 1) + normalTile;
  // A tile owed refill keeps one tile's share from the stamps, so a scene that
  // stamps a whole budget every frame still fills its prints in.
  refill_.advance(work.refillMetresPerSecond, work.seconds);
  const std::uint64_t reserved = schedule_.owes(refill_.totalQuanta()) ? refillTile : 0;
  queued_.insert(queued_.end(), work.stamps.begin(), work.stamps.end());
  recordStamps(cmd, takeQueuedStamps(work.allStamps ? ~std::uint64_t(0) : left() - std::min(left(), reserved)));
  recordMeshes(cmd, work.meshes, work.level);  // the engine chooses how many
  recordRefill(cmd, 0.0, 0.0,
               std::min<std::uint64_t>(window_.settings().refillTilesPerFrame,
                                       std::max<std::uint64_t>(left() / refillTile, reserved != 0)));
  recordDeferredNormals(cmd, left() / normalTile);
}

void DeformationRecorder::recordQueuedStamps(VkCommandBuffer cmd) {
  recordStamps(cmd, takeQueuedStamps(~std::uint64_t(0)));
}

std::vector<Stamp> DeformationRecorder::takeQueuedStamps(std::uint64_t budget) {
  std::size_t count = 0, pressed = 0;
  glm::ivec2 box(0), rect(0);
  for (; count < queued_.size(); ++count) {
    TexelRect b = stampBounds(queued_[count], window_);
    if (b.empty()) continue;  // beyond the window: the store takes it, no GPU work
    glm::ivec2 nextBox = glm::max(box, b.size), nextRect = glm::max(rect, b.size + 2);
    auto layers = static_cast<std::uint32_t>(pressed + 1);
    std::uint64_t cost = pass_.invocationsOf(DeformationPass::Stage::Stamps, nextBox, layers) +
                         pass_.invocationsOf(DeformationPass::Stage::Normals, nextRect, layers);
    if (pressed != 0 && cost > budget) break;  // at least one a frame
    box = nextBox, rect = nextRect, ++pressed;
  }
  // Never more than a second behind: past that the queue is pressed at once.
  if (queued_.size() - count > kMostQueuedStamps) count = queued_.size();
  std::vector<Stamp> now(queued_.begin(), queued_.begin() + std::ptrdiff_t(count));
  queued_.erase(queued_.begin(), queued_.begin() + std::ptrdiff_t(count));
  return now;
}

void DeformationRecorder::recordMeshes(VkCommandBuffer cmd, std::span<const MeshInteractor> meshes,
                                       const SnowLevel& level) {
  clearOnce(cmd);
  if (meshes.empty()) return;
  if (!meshPass_) throw std::logic_error("mesh interactors need the device feature fragmentStoresAndAtomics");
  std::vector<TexelRect> rects;
  for (const MeshInteractor& m : meshes) {
    glm::ivec2 lo = window_.texelAt(m.footprintMin), hi = window_.texelAt(m.footprintMax);
    rects.push_back(TexelRect{lo, hi - lo + 1}.grown(1).intersect(window_.rect()));
    schedule_.pressed(window_, rects.back(), toQuanta(level.depth), refill_.totalQuanta());
  }
  withSurfaceWritable(cmd, [&] {
    meshPass_->record(cmd, constants(0), level, meshes);
    recordNormals(cmd, rects);
  });
}

bool DeformationRecorder::recordRefill(VkCommandBuffer cmd, double metresPerSecond, double seconds) {
  return recordRefill(cmd, metresPerSecond, seconds, window_.settings().refillTilesPerFrame);
}

bool DeformationRecorder::recordRefill(VkCommandBuffer cmd, double metresPerSecond, double seconds,
                                       std::size_t mostTiles) {
  clearOnce(cmd);
  refill_.advance(metresPerSecond, seconds);
  std::vector<TileRefill> due = schedule_.due(window_, refill_.totalQuanta(), mostTiles);
  if (due.empty()) return false;
  int n = window_.tileTexels();
  std::vector<glm::ivec4> tiles;
  std::vector<TexelRect> rects;
  for (const TileRefill& t : due) {
    tiles.push_back({t.tile.x * n, t.tile.y * n, n, static_cast<int>(t.quanta)});
    rects.push_back(TexelRect{t.tile * n, glm::ivec2(n)}.grown(1).intersect(window_.rect()));
  }
  WindowConstants c = constants(0);
  withSurfaceWritable(cmd, [&] {
    inBatches(cmd, refillTiles_, tiles,
              [&](std::size_t, std::uint32_t count) { pass_.recordRefill(cmd, c, count, n); });
    recordNormals(cmd, rects);
  });
  return true;
}

Recentring DeformationRecorder::recordFollow(VkCommandBuffer cmd, glm::vec2 camera) {
  clearOnce(cmd);
  if (readbackState_ == Readback::Ready) return harvestReadback(cmd);
  glm::ivec2 target = window_.originFor(camera);
  if (readbackState_ != Readback::Idle || target == window_.origin()) return {};
  // Only the tiles that will leave and may hold prints: the rest is flat snow, zeroed
  // in the host copy here. The window moves to where the camera is now, even if it
  // has gone further by the time the copy is read.
  std::vector<glm::ivec4> printed;
  for (const glm::ivec4& t : tilesOutside(window_, window_.rect(), {target, glm::ivec2(window_.resolution())})) {
    if (schedule_.holdsPrints(glm::ivec2(t) / t.z)) printed.push_back(t);
    else zeroHostTile(glm::ivec2(t) / t.z);
  }
  recordTileTransfer(cmd, printed, true);
  memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                VK_ACCESS_HOST_READ_BIT);
  readbackState_ = Readback::Copying;
  readbackFrame_ = frame_;
  readbackCamera_ = camera;
  return {};
}

void DeformationRecorder::zeroHostTile(glm::ivec2 tile) {
  auto* host = static_cast<std::uint32_t*>(readback_.mapped());
  int n = window_.tileTexels();
  for (int z = 0; z < n; ++z) std::fill_n(host + window_.storageIndex(tile * n + glm::ivec2(0, z)), n, 0u);
}

bool DeformationRecorder::nearPrints(glm::ivec2 tile) const {
  const int n = window_.tileTexels();
  for (int dz = -1; dz <= 1; ++dz)
    for (int dx = -1; dx <= 1; ++dx) {
      glm::ivec2 t = tile + glm::ivec2(dx, dz);
      if (window_.rect().contains(t * n) && schedule_.holdsPrints(t)) return true;
    }
  return false;
}

void DeformationRecorder::recordLoadPrints(VkCommandBuffer cmd, PrintTileStore prints) {
  if (readbackState_ != Readback::Idle)
    throw std::logic_error("snow prints can only be loaded on a frame where the window is not moving");
  clearOnce(cmd);
  store_ = std::move(prints);
  scratchNormals_.resize(window_.texelCount());
  MapTexels host{{static_cast<std::uint32_t*>(readback_.mapped()), window_.texelCount()}, scratchNormals_};
  restoreAll(window_, host, store_, schedule_, refill_.totalQuanta());
  withSurfaceWritable(cmd, [&] {
    VkBufferCopy all{0, 0, heights_.size()};
    vkCmdCopyBuffer(cmd, readback_.handle(), heights_.handle(), 1, &all);
    recordNormals(cmd, {window_.rect()});
  });
  readbackState_ = Readback::Uploading;  // the host copy is read until this frame's commands complete
  readbackFrame_ = frame_;
}

PrintTileStore DeformationRecorder::prints(std::span<const std::uint32_t> heights) const {
  return withWindowTiles(window_, heights, store_, schedule_, refill_.totalQuanta());
}

Recentring DeformationRecorder::harvestReadback(VkCommandBuffer cmd) {
  TexelRect before = window_.rect();
  scratchNormals_.resize(window_.texelCount());
  MapTexels texels{{static_cast<std::uint32_t*>(readback_.mapped()), window_.texelCount()}, scratchNormals_};
  recordDeferredNormals(cmd, deferredNormals_.size());  // the last ring, before the window moves on
  // Slots whose leaving tile is not flat snow with flat normals: the map must be reset
  // there whatever enters.
  std::vector<std::size_t> dirtySlots;
  glm::ivec2 target = window_.originFor(readbackCamera_);
  for (const glm::ivec4& t : tilesOutside(window_, before, {target, before.size}))
    if (nearPrints(glm::ivec2(t) / t.z)) dirtySlots.push_back(window_.storageIndex(glm::ivec2(t)));
  Recentring r = recentre(window_, texels, readbackCamera_, store_, schedule_, refill_.totalQuanta());
  readbackState_ = Readback::Idle;
  if (!r.moved()) return r;
  // The entering tiles took the leaving tiles' slots in the host copy. Only those near
  // prints, or in a dirty slot, are uploaded and get their normals redone.
  std::vector<glm::ivec4> upload;
  for (const glm::ivec4& t : tilesOutside(window_, window_.rect(), before)) {
    bool dirty = std::find(dirtySlots.begin(), dirtySlots.end(), window_.storageIndex(glm::ivec2(t))) != dirtySlots.end();
    if (!dirty && !nearPrints(glm::ivec2(t) / t.z)) continue;
    upload.push_back(t);
    deferredNormals_.push_back(TexelRect{glm::ivec2(t), glm::ivec2(t.z)}.grown(1).intersect(window_.rect()));
  }
  recordTileTransfer(cmd, upload, false);
  readbackState_ = Readback::Uploading;
  readbackFrame_ = frame_;
  return r;
}

void DeformationRecorder::recordTileTransfer(VkCommandBuffer cmd, const std::vector<glm::ivec4>& tiles, bool out) {
  WindowConstants c = constants(0);
  inBatches(cmd, transferTiles_, tiles, [&](std::size_t, std::uint32_t count) {
    if (out) pass_.recordTilesOut(cmd, c, count, window_.tileTexels());
    else pass_.recordTilesIn(cmd, c, count, window_.tileTexels());
  });
  mapBarrier(cmd);
}

bool DeformationRecorder::recordDeferredNormals(VkCommandBuffer cmd, std::size_t most) {
  std::size_t count = std::min(most, deferredNormals_.size());
  if (count == 0) return false;
  std::vector<TexelRect> rects(deferredNormals_.begin(), deferredNormals_.begin() + std::ptrdiff_t(count));
  deferredNormals_.erase(deferredNormals_.begin(), deferredNormals_.begin() + std::ptrdiff_t(count));
  withSurfaceWritable(cmd, [&] { recordNormals(cmd, rects); });
  return true;
}

void DeformationRecorder::recordReadBarrier(VkCommandBuffer cmd, VkPipelineStageFlags stages, VkAccessFlags access) {
  memoryBarrier(cmd, kMapStages, kMapWrites, stages, access);
}

}  // namespace wg::snow
