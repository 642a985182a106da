// include/weathergen/snow.hpp over DeformationRecorder: converts the plain structs of
// the header to the runtime's and keeps exceptions inside. The device is borrowed, so
// nothing here submits, waits or destroys what the engine owns.
#include <weathergen/snow.hpp>

#include <algorithm>
#include <bit>
#include <cstring>
#include <exception>
#include <vector>

#include "snow/deformation_recorder.hpp"
#include "snow/print_store_file.hpp"
#include "snow/snow_interactors.hpp"

namespace weathergen::snow {

namespace {
static_assert(sizeof(Capsule) == sizeof(wg::snow::Stamp), "Capsule mirrors the runtime's Stamp");

// Both are trivially copyable with the same layout: bit_cast checks it at compile time.
wg::snow::Stamp toStamp(const Capsule& c) { return std::bit_cast<wg::snow::Stamp>(c); }
Capsule toCapsule(const wg::snow::Stamp& s) { return std::bit_cast<Capsule>(s); }

wg::snow::MeshInteractor toInteractor(const Mesh& m) {
  wg::snow::MeshInteractor i;
  i.vertices = m.vertexBuffer;
  i.vertexOffset = m.vertexOffset;
  i.vertexStride = m.vertexStride;
  i.indices = m.indexBuffer;
  i.indexOffset = m.indexOffset;
  i.indexType = m.indexType;
  i.indexCount = m.indexCount;
  std::memcpy(&i.model, m.model, sizeof m.model);
  i.footprintMin = {m.footprintMin[0], m.footprintMin[1]};
  i.footprintMax = {m.footprintMax[0], m.footprintMax[1]};
  i.surfaceHeight = m.snowSurfaceHeight;
  return i;
}
}  // namespace

struct DeformableSnow::State {
  std::unique_ptr<wg::vk::Context> device;  // borrowed: destroys nothing
  wg::snow::DeformationRecorder recorder;
  std::uint32_t framesInFlight;
  wg::vk::Buffer savedHeights;  // host copy for savePrints(), made on request
  bool saveReady = false;       // the last record() copied the heights into it
};

namespace {
// What record() refuses before recording anything, or "".
std::string invalidFrame(const Frame& frame, std::uint32_t framesInFlight, bool meshInteractors) {
  if (frame.frameIndex >= framesInFlight)
    return "Frame::frameIndex " + std::to_string(frame.frameIndex) + " is not below Settings::framesInFlight (" +
           std::to_string(framesInFlight) + ")";
  if (frame.capsuleCount != 0 && !frame.capsules) return "Frame::capsuleCount is set but capsules is null";
  if (frame.meshCount != 0 && !frame.meshes) return "Frame::meshCount is set but meshes is null";
  if (frame.meshCount != 0 && !meshInteractors)
    return "mesh interactors need the device feature fragmentStoresAndAtomics (Device::fragmentStoresAndAtomics)";
  for (std::size_t i = 0; i < frame.meshCount; ++i)
    if (frame.meshes[i].indexCount != 0 && (!frame.meshes[i].vertexBuffer || !frame.meshes[i].indexBuffer))
      return "Frame::meshes[" + std::to_string(i) + "] has no vertex or index buffer";
  return "";
}
}  // namespace

Capsule footprint(float x, float z, float headingX, float headingZ, float snowDepth) noexcept {
  return toCapsule(wg::snow::footprint({x, z}, {headingX, headingZ}, wg::snow::FootShape{},
                                       wg::snow::SnowCover{snowDepth}, wg::snow::Walker{}.sink));
}

Capsule drag(float fromX, float fromZ, float toX, float toZ, float radius, float snowDepth) noexcept {
  return toCapsule(wg::snow::capsule({fromX, fromZ}, {toX, toZ}, radius, wg::snow::SnowCover{snowDepth},
                                     wg::snow::Vehicle{}.sink));
}

std::unique_ptr<DeformableSnow> DeformableSnow::create(const Device& device, const Settings& settings,
                                                       std::string& error) noexcept {
  try {
    if (!device.device || !device.physicalDevice) throw std::invalid_argument("no Vulkan device given");
    if (settings.resolution == 0 || settings.tileTexels == 0 || settings.resolution % settings.tileTexels != 0 ||
        settings.tileTexels > wg::snow::kMaxTileTexels || !(settings.texelSize > 0.f))
      throw std::invalid_argument("Settings: resolution must be a multiple of tileTexels (at most " +
                                  std::to_string(wg::snow::kMaxTileTexels) + ") and texelSize positive");
    wg::snow::WindowSettings window;
    window.resolution = settings.resolution;
    window.texelSize = settings.texelSize;
    window.tileTexels = settings.tileTexels;
    window.printStoreBudget = settings.printStoreBytes;
    window.refillTilesPerFrame = settings.refillTilesPerFrame;
    window.workPerFrame = settings.workPerFrame;
    auto ctx = wg::vk::Context::borrow(device.physicalDevice, device.device, device.queueFamily,
                                       device.fragmentStoresAndAtomics);
    auto& borrowed = *ctx;
    auto state = std::unique_ptr<State>(new State{
        std::move(ctx),
        wg::snow::DeformationRecorder(borrowed, window, {settings.cameraX, settings.cameraZ}, settings.framesInFlight),
        std::max(settings.framesInFlight, 1u)});
    return std::unique_ptr<DeformableSnow>(new DeformableSnow(std::move(state)));
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown error";
  }
  return nullptr;
}

// The height plane into the host buffer savePrints() reads, after the frame's work.
void DeformableSnow::recordSaveCopy(VkCommandBuffer cmd) {
  State& state = *state_;
  const wg::vk::Buffer& heights = state.recorder.heightBuffer();
  if (!state.savedHeights.handle())
    state.savedHeights = wg::vk::Buffer(*state.device, heights.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  VkBufferCopy all{0, 0, heights.size()};
  vkCmdCopyBuffer(cmd, heights.handle(), state.savedHeights.handle(), 1, &all);
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                       nullptr);
  state.saveReady = true;
}

std::string DeformableSnow::savePrints(const std::string& path) noexcept {
  try {
    if (!state_->saveReady)
      return "savePrints needs the heights of the last record(): set Frame::readBackPrints and wait for that frame";
    const auto& r = state_->recorder;
    std::span<const std::uint32_t> heights(static_cast<const std::uint32_t*>(state_->savedHeights.mapped()),
                                           r.window().texelCount());
    wg::snow::savePrintsFile(path, r.prints(heights), r.window(), r.refillQuanta());
    return "";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown error";
  }
}

DeformableSnow::DeformableSnow(std::unique_ptr<State> state) : state_(std::move(state)) {}
DeformableSnow::~DeformableSnow() = default;

std::string DeformableSnow::record(VkCommandBuffer cmd, const Frame& frame) noexcept {
  try {
    auto& r = state_->recorder;
    if (std::string invalid = invalidFrame(frame, state_->framesInFlight, r.meshInteractors()); !invalid.empty())
      return invalid;
    r.beginFrame(frame.frameIndex);
    state_->saveReady = false;
    if (frame.loadPrintsFrom) {
      // The file is read and checked whole before anything changes or is recorded.
      wg::snow::PrintTileStore loaded(r.store().budgetBytes());
      wg::snow::loadPrintsFile(frame.loadPrintsFrom, r.window(), r.refillQuanta(), loaded);
      r.recordLoadPrints(cmd, std::move(loaded));
    }
    std::vector<wg::snow::Stamp> stamps;
    for (std::size_t i = 0; i < frame.capsuleCount; ++i) stamps.push_back(toStamp(frame.capsules[i]));
    std::vector<wg::snow::MeshInteractor> meshes;
    for (std::size_t i = 0; i < frame.meshCount; ++i) meshes.push_back(toInteractor(frame.meshes[i]));
    r.recordFrame(cmd, {.camera = {frame.cameraX, frame.cameraZ},
                        .stamps = stamps,
                        .meshes = meshes,
                        .level = {frame.snowSurfaceHeight, frame.snowDepth},
                        .refillMetresPerSecond = frame.refillMetresPerSecond,
                        .seconds = frame.seconds,
                        .allStamps = frame.readBackPrints});
    wg::snow::DeformationRecorder::recordReadBarrier(
        cmd,
        VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
    if (frame.readBackPrints) recordSaveCopy(cmd);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown error";
  }
}

ShadingInputs DeformableSnow::shadingInputs() const noexcept {
  const auto& r = state_->recorder;
  const wg::snow::SnowWindow& w = r.window();
  ShadingInputs s;
  s.surfaceImage = r.surfaceImage().handle();
  s.surfaceView = r.surfaceImage().view();
  s.surfaceFormat = r.surfaceImage().format();
  s.heightBuffer = r.heightBuffer().handle();
  s.normalBuffer = r.normalBuffer().handle();
  s.originX = float(w.origin().x) * w.texelSize();
  s.originZ = float(w.origin().y) * w.texelSize();
  s.texelSize = w.texelSize();
  s.extent = w.extent();
  s.resolution = std::uint32_t(w.resolution());
  return s;
}

std::size_t DeformableSnow::storedTiles() const noexcept { return state_->recorder.store().tileCount(); }
std::size_t DeformableSnow::storedBytes() const noexcept { return state_->recorder.store().memoryBytes(); }

}  // namespace weathergen::snow
