// weathergen's deformable snow for an engine: footprints, capsules and any mesh press
// prints into a camera-following height map that the snow material samples.
//
// The engine owns the Vulkan device, its queues and command buffers. DeformableSnow
// records its work into a command buffer the engine passes in and never submits, waits
// or touches a queue itself (docs/engine-api.md, "Deformable snow").
//  - Needs Vulkan 1.1 and the engine's <vulkan/vulkan.h>; link weathergen::snow.
//  - Mesh interactors need the device feature fragmentStoresAndAtomics enabled.
//  - One DeformableSnow is used from one thread at a time; several may live side by side.
//  - No exception leaves this API: failures come back as error strings.
#pragma once
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

namespace weathergen::snow {

// The engine's device. The queue family is the one the recorded commands are submitted to.
struct Device {
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  bool fragmentStoresAndAtomics = false;  // enabled on `device`: mesh interactors work
};

struct Settings {
  // The window of world the map covers, centred on the camera: resolution² texels of
  // texelSize metres (the default: 1024² at 4 cm, about 41 m), moved in tiles of
  // tileTexels texels (a divisor of resolution).
  std::uint32_t resolution = 1024;
  float texelSize = 0.04f;
  std::uint32_t tileTexels = 32;
  // Frames the engine may have in flight: record()'s frameIndex is below this.
  std::uint32_t framesInFlight = 2;
  // Memory for prints outside the window; the tiles stored longest ago go first.
  std::size_t printStoreBytes = std::size_t(16) << 20;
  // Refill (fresh snow in the prints) visits at most this many printed tiles a frame,
  // each catching up on what it is owed, so no frame rewrites the whole map.
  std::uint32_t refillTilesPerFrame = 4;
  // A frame's snow work in shader invocations: capsules beyond it wait, oldest first,
  // for the next frames (at least one is pressed a frame), and refill and recentring's
  // normals take what is left, so a frame where many feet land costs about what any
  // other does. See docs/engine-api.md.
  std::uint32_t workPerFrame = 8192;
  // World x and z (metres) of the camera at creation.
  float cameraX = 0.f, cameraZ = 0.f;
};

// A cheap shape: an uneven capsule in the ground plane from `a` (radius and depth A) to
// `b` (radius and depth B), with a raised rim just outside it. World x, z in metres;
// depths already limited by the snow's depth. A point stamp has a == b. A waist above
// 0 makes it a boot sole: its middle narrows to that half-width and its depth there
// goes to archDepth (footprint() sets both).
struct Capsule {
  float a[2] = {0.f, 0.f}, b[2] = {0.f, 0.f};
  float radiusA = 0.f, radiusB = 0.f;
  float depthA = 0.f, depthB = 0.f;
  float rimWidth = 0.f, rimHeight = 0.f;
  float waist = 0.f, archDepth = 0.f;
};

// A boot print centred at (x, z), heel behind and toe ahead along the heading, as deep
// as a foot sinks into snow `snowDepth` metres deep.
Capsule footprint(float x, float z, float headingX, float headingZ, float snowDepth) noexcept;
// A body or wheel of the given radius dragged from (fromX, fromZ) to (toX, toZ).
Capsule drag(float fromX, float fromZ, float toX, float toZ, float radius, float snowDepth) noexcept;

// Any mesh as an interactor: its depth seen from below is pressed into the snow. Only
// positions are read: three floats at vertexOffset + i * vertexStride, drawn as an
// indexed triangle list with `model` (column-major, to world, y up).
struct Mesh {
  VkBuffer vertexBuffer = VK_NULL_HANDLE;  // usage VERTEX_BUFFER
  VkDeviceSize vertexOffset = 0;
  std::uint32_t vertexStride = 3 * sizeof(float);
  VkBuffer indexBuffer = VK_NULL_HANDLE;   // usage INDEX_BUFFER
  VkDeviceSize indexOffset = 0;
  VkIndexType indexType = VK_INDEX_TYPE_UINT32;
  std::uint32_t indexCount = 0;
  float model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  // World x, z the mesh covers this frame (its bounds): the only texels it is drawn
  // into (parts outside are cut) and whose normals are redone.
  float footprintMin[2] = {0.f, 0.f}, footprintMax[2] = {0.f, 0.f};
  // World y of the undisturbed snow surface under this mesh, where the terrain under it
  // differs from Frame::snowSurfaceHeight (a vehicle on a hill); NaN: the frame's.
  float snowSurfaceHeight = std::numeric_limits<float>::quiet_NaN();
};

// One frame's work.
struct Frame {
  // Below Settings::framesInFlight. The engine promises that the commands recorded the
  // last time this index was used have completed (it waited on that frame's fence).
  std::uint32_t frameIndex = 0;
  float cameraX = 0.f, cameraZ = 0.f;  // the window follows the camera
  const Capsule* capsules = nullptr;
  std::size_t capsuleCount = 0;
  const Mesh* meshes = nullptr;
  std::size_t meshCount = 0;
  // World y of the undisturbed snow surface, and the snow's depth: a mesh reaching
  // below the surface presses a print, at most snowDepth deep.
  float snowSurfaceHeight = 0.f;
  float snowDepth = 0.f;
  // Fresh snow filling the prints in, metres per second, over `seconds` of game time.
  double refillMetresPerSecond = 0.0;
  double seconds = 0.0;
  // Saved prints to start this frame from (a file savePrints() wrote): every print is
  // replaced by the file's. Refused while the window is moving (try the next frame).
  const char* loadPrintsFrom = nullptr;
  // Copy the map's heights to the host at the end of this frame, so that savePrints()
  // can write them once the engine knows this frame's commands completed. Such a
  // frame presses every waiting capsule first, whatever Settings::workPerFrame says.
  bool readBackPrints = false;
};

// What the snow material samples. The surface image (RGBA16F: height offset in metres,
// then the world normal) is stored toroidally: sample it with a REPEAT sampler at
// world (x, z) / extent. Texels outside the window [origin, origin + extent) are
// undisturbed snow: height 0, normal up.
struct ShadingInputs {
  VkImage surfaceImage = VK_NULL_HANDLE;
  VkImageView surfaceView = VK_NULL_HANDLE;
  VkFormat surfaceFormat = VK_FORMAT_UNDEFINED;
  VkImageLayout surfaceLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;  // between record() calls
  // The packed map itself (uint32 per texel, same toroidal order), device-local.
  VkBuffer heightBuffer = VK_NULL_HANDLE;
  VkBuffer normalBuffer = VK_NULL_HANDLE;
  float originX = 0.f, originZ = 0.f;  // world metres of the window's lowest corner
  float texelSize = 0.f;
  float extent = 0.f;  // resolution * texelSize
  std::uint32_t resolution = 0;
};

class DeformableSnow {
 public:
  // Creates the map's buffers and pipelines on the engine's device; null and `error`
  // set when that fails. Records nothing yet: call record() before sampling.
  static std::unique_ptr<DeformableSnow> create(const Device& device, const Settings& settings,
                                                std::string& error) noexcept;
  // The device must be done with every recorded command first (the engine waits).
  ~DeformableSnow();
  DeformableSnow(const DeformableSnow&) = delete;
  DeformableSnow& operator=(const DeformableSnow&) = delete;

  // Records the frame's snow work into `cmd` (recording, outside a render pass, on
  // Device::queueFamily): recentring, capsules, meshes, normals and refill. Afterwards
  // the surface image and the map are ready for vertex, fragment and compute shader
  // reads later in `cmd` or in later submissions. Returns "" or what went wrong; an
  // invalid frame (index out of range, null arrays, meshes without the feature) is
  // refused before anything is recorded.
  std::string record(VkCommandBuffer cmd, const Frame& frame) noexcept;

  // Writes every print (the window's and the print store's) to `path`, for games that
  // keep the world's state. Valid after a record() with Frame::readBackPrints once its
  // commands have completed, and before the next record(). Returns "" or the error.
  std::string savePrints(const std::string& path) noexcept;

  ShadingInputs shadingInputs() const noexcept;
  // Tiles of prints kept outside the window, and their bytes.
  std::size_t storedTiles() const noexcept;
  std::size_t storedBytes() const noexcept;

 private:
  struct State;
  explicit DeformableSnow(std::unique_ptr<State> state);
  void recordSaveCopy(VkCommandBuffer cmd);
  std::unique_ptr<State> state_;
};

}  // namespace weathergen::snow
