// The deformable snow's GPU work, recorded into a command buffer the caller submits:
// stamps, mesh interactors, normals (and the surface image materials sample), refill,
// and recentring. Nothing here submits or waits, so an engine records it into its own
// frame; GpuDeformationMap submits and waits around the same calls for the renderer
// and the tests. The map's buffers and the surface image are device-local.
//
// Recentring needs the tiles that leave on the CPU (the print store): one frame records
// a copy of their rows into a host buffer, and the first frame that reuses that
// frame's index (so its commands have completed) moves the window on the CPU and
// records the entering tiles' upload; their normals follow over the next frames.
// Stamps on tiles that leave in between are lost; they are half a window from the
// camera.
#pragma once
#include <glm/glm.hpp>

#include <deque>
#include <memory>
#include <span>
#include <vector>

#include "snow/deformation_pass.hpp"
#include "snow/deformation_refill.hpp"
#include "snow/mesh_interactor_pass.hpp"
#include "snow/print_tile_store.hpp"
#include "snow/refill_schedule.hpp"
#include "snow/snow_stamp.hpp"
#include "snow/window_recentring.hpp"

namespace wg::snow {

// One frame's snow work, in the order recordFrame records it.
struct FrameWork {
  glm::vec2 camera{0.f};                     // the window follows it
  std::span<const Stamp> stamps;             // queued, pressed as the frame's work allows
  std::span<const MeshInteractor> meshes;    // drawn this frame
  SnowLevel level;                           // where the meshes press
  double refillMetresPerSecond = 0.0, seconds = 0.0;
  // Press every queued stamp this frame, whatever it costs (a frame whose map is read
  // back, for a save, holds every print).
  bool allStamps = false;
};

class DeformationRecorder {
 public:
  // `framesInFlight` frame indices guard the host readback buffer (at least 1).
  DeformationRecorder(vk::Context& ctx, const WindowSettings& settings, glm::vec2 camera,
                      std::uint32_t framesInFlight);
  ~DeformationRecorder();
  DeformationRecorder(const DeformationRecorder&) = delete;
  DeformationRecorder& operator=(const DeformationRecorder&) = delete;

  // Starts a frame. The caller guarantees that the commands recorded the last time
  // `frameIndex` (< framesInFlight) was used have completed.
  void beginFrame(std::uint32_t frameIndex);

  // A frame as engines record it, within WindowSettings::workPerFrame: recentring, the
  // oldest queued stamps (at least one), the meshes, then refill and the normals of
  // entered tiles in what is left.
  void recordFrame(VkCommandBuffer cmd, const FrameWork& work);
  std::size_t queuedStamps() const { return queued_.size(); }
  // Presses every queued stamp now.
  void recordQueuedStamps(VkCommandBuffer cmd);
  std::uint64_t invocations() const { return pass_.invocations(); }

  // Each records into `cmd` outside a render pass. The surface image is in
  // SHADER_READ_ONLY_OPTIMAL before and after; the first call also clears the map.
  Recentring recordFollow(VkCommandBuffer cmd, glm::vec2 camera);
  void recordStamps(VkCommandBuffer cmd, std::span<const Stamp> stamps);
  void recordMeshes(VkCommandBuffer cmd, std::span<const MeshInteractor> meshes, const SnowLevel& level);
  // Refill at `metresPerSecond` for `seconds`, over at most refillTilesPerFrame of the
  // tiles that hold prints and are owed a quantum (refill_schedule.hpp); records only
  // when one is.
  bool recordRefill(VkCommandBuffer cmd, double metresPerSecond, double seconds);
  // The same over at most `mostTiles` tiles (0: the time passes, nothing is recorded).
  bool recordRefill(VkCommandBuffer cmd, double metresPerSecond, double seconds, std::size_t mostTiles);
  // Replaces every print with `prints` (what loading a prints file read): the window's
  // tiles are rebuilt from it on the host, uploaded and re-normalled; the rest stays in
  // the store. Not while the window is moving (a readback in flight).
  void recordLoadPrints(VkCommandBuffer cmd, PrintTileStore prints);
  // Every print, in the window (`heights`: a host copy of the height plane) and in the
  // store, as saving writes them (print_store_file.hpp).
  PrintTileStore prints(std::span<const std::uint32_t> heights) const;
  std::uint64_t refillQuanta() const { return refill_.totalQuanta(); }
  // Normals and surface texels of the tiles that entered with the last recentring, at
  // most `most` tiles: recentring leaves them to the following frames (they lie past
  // the snow layer's border fade), so the frame that moves the window only uploads.
  // The remainder is flushed before the window moves again.
  bool recordDeferredNormals(VkCommandBuffer cmd, std::size_t most = kDeferredNormalTilesPerFrame);
  std::size_t deferredNormals() const { return deferredNormals_.size(); }
  static constexpr std::size_t kDeferredNormalTilesPerFrame = 8;
  // Makes every earlier write to the map and the surface image visible to `stages`.
  static void recordReadBarrier(VkCommandBuffer cmd, VkPipelineStageFlags stages, VkAccessFlags access);

  const SnowWindow& window() const { return window_; }
  const PrintTileStore& store() const { return store_; }
  bool meshInteractors() const { return static_cast<bool>(meshPass_); }
  const vk::Buffer& heightBuffer() const { return heights_; }
  const vk::Buffer& normalBuffer() const { return normals_; }
  const vk::Image2D& surfaceImage() const { return surface_; }
  std::size_t mapBytes() const { return heights_.size() + normals_.size(); }

 private:
  enum class Readback : std::uint8_t { Idle, Copying, Ready, Uploading };

  WindowConstants constants(std::uint32_t refillQuanta) const;
  // The map and the surface image start untouched: recorded by the first call.
  void clearOnce(VkCommandBuffer cmd);
  // Makes the surface image writable around `record`.
  template <typename Record>
  void withSurfaceWritable(VkCommandBuffer cmd, Record&& record);
  // Normals (and the surface image) over `rects`, in batches the rect buffer holds.
  void recordNormals(VkCommandBuffer cmd, const std::vector<TexelRect>& rects);
  Recentring harvestReadback(VkCommandBuffer cmd);
  // The oldest queued stamps whose dispatch fits `budget` invocations (at least one).
  std::vector<Stamp> takeQueuedStamps(std::uint64_t budget);
  // A queue longer than this (about a second of a busy scene) is pressed at once.
  static constexpr std::size_t kMostQueuedStamps = 256;
  // Flat snow in the host copy of a tile (one that leaves without prints).
  void zeroHostTile(glm::ivec2 tile);
  // Whether a tile of the window or a neighbour in the window may hold prints: if not,
  // its heights are 0 and its normals straight up.
  bool nearPrints(glm::ivec2 tile) const;
  // Whole tiles (x, z, size, 0) from the map to the host copy (`out`), or back.
  void recordTileTransfer(VkCommandBuffer cmd, const std::vector<glm::ivec4>& tiles, bool out);

  vk::Context& ctx_;
  SnowWindow window_;
  DeformationPass pass_;
  vk::Buffer heights_, normals_, stamps_, stampBoxes_, normalRects_, refillTiles_, transferTiles_;
  vk::Buffer readback_;  // host-visible copy of the height plane for recentring
  std::vector<std::uint32_t> scratchNormals_;  // the CPU's normals while recentring (the GPU redoes them)
  std::deque<Stamp> queued_;                   // stamps waiting for a frame's budget
  std::deque<TexelRect> deferredNormals_;      // entered tiles (grown by one texel) still to renormal
  vk::Image2D surface_;
  std::unique_ptr<MeshInteractorPass> meshPass_;  // null without fragmentStoresAndAtomics
  PrintTileStore store_;
  DeformationRefill refill_;
  RefillSchedule schedule_;
  std::uint32_t framesInFlight_, frame_ = 0;
  Readback readbackState_ = Readback::Idle;
  std::uint32_t readbackFrame_ = 0;
  glm::vec2 readbackCamera_{0.f};  // the window moves to centre this camera
  bool cleared_ = false;
};

}  // namespace wg::snow
