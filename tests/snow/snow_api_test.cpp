// The engine's snow API (include/weathergen/snow.hpp, libweathergen_snow.so) driven as
// an engine drives it, on lavapipe with the validation layers on: the test owns the
// command pool, two frames in flight with their fences, and waits only on the fence
// of the frame index it reuses. A scripted walk leaves its footprints where the walker
// went, through recentring; a torus pressed into the snow leaves a ring.
#include <weathergen/snow.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "snow/deformation_texel.hpp"
#include "vulkan/gpu_buffer.hpp"
#include "tests/snow/snow_gpu_support.hpp"

namespace wg::snow {
namespace {

using testing::snowContext;
using SnowApi = testing::ValidatedGpuTest;

constexpr std::uint32_t kFramesInFlight = 2;
// 128² texels of 4 cm: a 5.12 m window, so a 6 m walk makes it recentre.
weathergen::snow::Settings smallSettings() {
  weathergen::snow::Settings s;
  s.resolution = 128;
  s.texelSize = 0.04f;
  s.tileTexels = 16;
  s.framesInFlight = kFramesInFlight;
  return s;
}

// The engine's side: a command pool, a command buffer and a fence per frame in flight.
class EngineFrames {
 public:
  explicit EngineFrames(vk::Context& ctx) : ctx_(ctx) {
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = ctx.queueFamily();
    vk::check(vkCreateCommandPool(ctx.device(), &pool, nullptr, &pool_), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = kFramesInFlight;
    vk::check(vkAllocateCommandBuffers(ctx.device(), &alloc, cmds_), "vkAllocateCommandBuffers");
    for (VkFence& f : fences_) {
      VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
      info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
      vk::check(vkCreateFence(ctx.device(), &info, nullptr, &f), "vkCreateFence");
    }
  }
  ~EngineFrames() {
    vkDeviceWaitIdle(ctx_.device());
    for (VkFence f : fences_) vkDestroyFence(ctx_.device(), f, nullptr);
    vkDestroyCommandPool(ctx_.device(), pool_, nullptr);
  }

  // Waits for the frame that last used `index`, records into its command buffer, submits.
  void frame(std::uint32_t index, const std::function<void(VkCommandBuffer)>& record) {
    vk::check(vkWaitForFences(ctx_.device(), 1, &fences_[index], VK_TRUE, UINT64_MAX), "vkWaitForFences");
    vkResetFences(ctx_.device(), 1, &fences_[index]);
    VkCommandBuffer cmd = cmds_[index];
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &begin);
    record(cmd);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    vk::check(vkQueueSubmit(ctx_.queue(), 1, &submit, fences_[index]), "vkQueueSubmit");
  }

  // The map's height plane, read back once the device is idle.
  std::vector<std::uint32_t> heights(const weathergen::snow::ShadingInputs& in) {
    VkDeviceSize bytes = VkDeviceSize(in.resolution) * in.resolution * sizeof(std::uint32_t);
    vk::Buffer host(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    frame(0, [&](VkCommandBuffer cmd) {
      VkBufferCopy all{0, 0, bytes};
      vkCmdCopyBuffer(cmd, in.heightBuffer, host.handle(), 1, &all);
      VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                           0, nullptr);
    });
    vkDeviceWaitIdle(ctx_.device());
    const auto* p = static_cast<const std::uint32_t*>(host.mapped());
    return {p, p + bytes / sizeof(std::uint32_t)};
  }

 private:
  vk::Context& ctx_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmds_[kFramesInFlight]{};
  VkFence fences_[kFramesInFlight]{};
};

std::unique_ptr<weathergen::snow::DeformableSnow> createSnow(const weathergen::snow::Settings& settings) {
  vk::Context& ctx = *snowContext();
  std::string error;
  auto snow = weathergen::snow::DeformableSnow::create(
      {ctx.physicalDevice(), ctx.device(), ctx.queueFamily(), ctx.fragmentStoresAndAtomics()}, settings, error);
  EXPECT_TRUE(snow) << error;
  return snow;
}

// Print depth (metres) at world (x, z) in a read-back height plane, 0 outside the window.
float depthAt(const std::vector<std::uint32_t>& heights, const weathergen::snow::ShadingInputs& in, float x, float z) {
  int n = int(in.resolution);
  glm::ivec2 t(int(std::floor(x / in.texelSize)), int(std::floor(z / in.texelSize)));
  glm::ivec2 origin(int(std::lround(in.originX / in.texelSize)), int(std::lround(in.originZ / in.texelSize)));
  if (glm::any(glm::lessThan(t, origin)) || glm::any(glm::greaterThanEqual(t, origin + n))) return 0.f;
  glm::ivec2 slot((t.x % n + n) % n, (t.y % n + n) % n);
  return texelDepth(heights[std::size_t(slot.y) * std::size_t(n) + std::size_t(slot.x)]);
}

TEST_F(SnowApi, AScriptedWalkLeavesItsFootprintsThroughRecentring) {
  auto snow = createSnow(smallSettings());
  ASSERT_TRUE(snow);
  EngineFrames engine(*snowContext());
  // A walker along +x at 1.4 m/s, a footfall every 0.75 m alternating left and right;
  // the camera follows 1 m behind, so the window recentres and the first prints leave.
  constexpr float kSnowDepth = 0.2f, kStep = 0.75f, kSpeed = 1.4f, kSide = 0.09f;
  constexpr double kFrame = 1.0 / 30.0;
  std::vector<glm::vec2> footfalls;
  int frames = int(6.0f / kSpeed / float(kFrame));
  for (int f = 0; f <= frames; ++f) {
    float walked = kSpeed * float(f * kFrame);
    std::vector<weathergen::snow::Capsule> capsules;
    while (float(footfalls.size()) * kStep <= walked) {
      float side = footfalls.size() % 2 == 0 ? kSide : -kSide;
      glm::vec2 at(float(footfalls.size()) * kStep, side);
      footfalls.push_back(at);
      capsules.push_back(weathergen::snow::footprint(at.x, at.y, 1.f, 0.f, kSnowDepth));
    }
    weathergen::snow::Frame frame;
    frame.frameIndex = std::uint32_t(f) % kFramesInFlight;
    frame.cameraX = walked - 1.f;
    frame.capsules = capsules.data();
    frame.capsuleCount = capsules.size();
    frame.refillMetresPerSecond = 1e-5;  // 1 cm in 17 minutes: records refill, fills nothing visible
    frame.seconds = kFrame;
    engine.frame(frame.frameIndex, [&](VkCommandBuffer cmd) { ASSERT_EQ(snow->record(cmd, frame), ""); });
  }
  vkDeviceWaitIdle(snowContext()->device());
  auto in = snow->shadingInputs();
  EXPECT_GT(in.originX, 0.f) << "the window followed the camera";
  EXPECT_GT(snow->storedTiles(), 0u) << "the first prints left the window for the print store";
  auto heights = engine.heights(in);
  int inWindow = 0;
  for (std::size_t k = 0; k < footfalls.size(); ++k) {
    glm::vec2 at = footfalls[k];
    if (at.x < in.originX + 0.2f || at.x > in.originX + in.extent - 0.2f) continue;
    ++inWindow;
    EXPECT_GT(depthAt(heights, in, at.x, at.y), 0.05f) << "footfall " << k;
    // Half a step on, between the prints, the snow is untouched.
    EXPECT_EQ(depthAt(heights, in, at.x + 0.5f * kStep, 0.f), 0.f) << "after footfall " << k;
    EXPECT_EQ(depthAt(heights, in, at.x, at.y + 0.5f), 0.f) << "beside footfall " << k;
  }
  EXPECT_GE(inWindow, 4);
}

// A torus around the vertical axis, `rings` x `sides` quads: (x, y, z) per vertex.
struct TorusMesh {
  std::vector<float> positions;
  std::vector<std::uint32_t> indices;
};
TorusMesh torus(float major, float minor, int rings, int sides) {
  TorusMesh m;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      float u = glm::two_pi<float>() * float(i) / float(rings), v = glm::two_pi<float>() * float(j) / float(sides);
      float r = major + minor * std::cos(v);
      m.positions.insert(m.positions.end(), {r * std::cos(u), minor * std::sin(v), r * std::sin(u)});
      auto at = [&](int a, int b) { return std::uint32_t((a % rings) * sides + (b % sides)); };
      m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// A torus pressed 10 cm into the snow leaves a ring. `hill` raises the snow surface
// under the mesh (Mesh::snowSurfaceHeight) above the frame's, and the torus with it.
void pressTorus(float hill) {
  vk::Context& ctx = *snowContext();
  auto snow = createSnow(smallSettings());
  ASSERT_TRUE(snow);
  EngineFrames engine(ctx);
  // Tube radius 15 cm around a 60 cm ring, its bottom 10 cm into snow 30 cm deep whose
  // surface is at y = 0.3. The print is a ring between the radii where the tube's
  // underside is below the surface: 0.6 ± sqrt(0.15² - 0.05²).
  constexpr float kMajor = 0.6f, kMinor = 0.15f, kSurface = 0.3f, kPress = 0.1f;
  const glm::vec2 centre(0.3f, -0.2f);
  TorusMesh mesh = torus(kMajor, kMinor, 96, 24);
  vk::Buffer vertices(ctx, mesh.positions.size() * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  vk::Buffer indices(ctx, mesh.indices.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  vertices.write(mesh.positions.data(), vertices.size());
  indices.write(mesh.indices.data(), indices.size());
  weathergen::snow::Mesh m;
  m.vertexBuffer = vertices.handle();
  m.indexBuffer = indices.handle();
  m.indexCount = std::uint32_t(mesh.indices.size());
  float y = kSurface + hill - kPress + kMinor;  // the torus's centre height
  if (hill != 0.f) m.snowSurfaceHeight = kSurface + hill;
  float model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, centre.x, y, centre.y, 1};
  std::copy(model, model + 16, m.model);
  float reach = kMajor + kMinor;
  m.footprintMin[0] = centre.x - reach, m.footprintMin[1] = centre.y - reach;
  m.footprintMax[0] = centre.x + reach, m.footprintMax[1] = centre.y + reach;
  weathergen::snow::Frame frame;
  frame.meshes = &m;
  frame.meshCount = 1;
  frame.snowSurfaceHeight = kSurface;
  frame.snowDepth = 0.3f;
  engine.frame(0, [&](VkCommandBuffer cmd) { ASSERT_EQ(snow->record(cmd, frame), ""); });
  auto in = snow->shadingInputs();
  auto heights = engine.heights(in);

  float halfWidth = std::sqrt(kMinor * kMinor - (kMinor - kPress) * (kMinor - kPress));
  float inner = kMajor - halfWidth, outer = kMajor + halfWidth;
  float slack = 2.f * in.texelSize;  // a texel's centre decides, and the tube is a polygon
  for (int a = 0; a < 16; ++a) {
    glm::vec2 dir(std::cos(glm::two_pi<float>() * float(a) / 16.f), std::sin(glm::two_pi<float>() * float(a) / 16.f));
    auto depth = [&](float radius) {
      glm::vec2 p = centre + dir * radius;
      return depthAt(heights, in, p.x, p.y);
    };
    EXPECT_NEAR(depth(kMajor), kPress, 0.005f) << "under the tube's lowest line, direction " << a;
    EXPECT_EQ(depth(0.f), 0.f) << "the centre is undisturbed";
    EXPECT_EQ(depth(inner - slack), 0.f) << "inside the ring, direction " << a;
    EXPECT_GT(depth(inner + slack), 0.f) << "the ring's inner edge, direction " << a;
    EXPECT_GT(depth(outer - slack), 0.f) << "the ring's outer edge, direction " << a;
    EXPECT_EQ(depth(outer + slack), 0.f) << "outside the ring, direction " << a;
  }
}

TEST_F(SnowApi, ATorusPressedIntoTheSnowLeavesARing) {
  if (!snowContext()->fragmentStoresAndAtomics()) GTEST_SKIP() << "no fragmentStoresAndAtomics";
  pressTorus(0.f);
}

// On a 2 m hill the torus is far above the frame's snow surface; its own surface
// height makes it press the same ring.
TEST_F(SnowApi, AMeshPressesIntoTheSnowUnderItOnAHill) {
  if (!snowContext()->fragmentStoresAndAtomics()) GTEST_SKIP() << "no fragmentStoresAndAtomics";
  pressTorus(2.f);
}

TEST_F(SnowApi, SavedPrintsLoadIntoAnotherField) {
  auto saved = createSnow(smallSettings()), loaded = createSnow(smallSettings());
  ASSERT_TRUE(saved && loaded);
  EngineFrames engine(*snowContext());
  std::vector<weathergen::snow::Capsule> capsules = {weathergen::snow::footprint(0.5f, 0.2f, 1.f, 0.f, 0.2f),
                                                     weathergen::snow::drag(-1.f, -1.f, 1.f, -0.5f, 0.15f, 0.2f)};
  weathergen::snow::Frame frame;
  frame.capsules = capsules.data();
  frame.capsuleCount = capsules.size();
  frame.readBackPrints = true;
  EXPECT_NE(saved->savePrints("/nonexistent"), "") << "nothing read back yet";
  engine.frame(0, [&](VkCommandBuffer cmd) { ASSERT_EQ(saved->record(cmd, frame), ""); });
  vkDeviceWaitIdle(snowContext()->device());
  std::string path = ::testing::TempDir() + "snow_api_prints.wgprints";
  ASSERT_EQ(saved->savePrints(path), "");

  weathergen::snow::Frame bad;
  bad.loadPrintsFrom = WG_SOURCE_DIR "/README.md";
  engine.frame(0, [&](VkCommandBuffer cmd) { EXPECT_NE(loaded->record(cmd, bad), ""); });
  weathergen::snow::Frame load;
  load.frameIndex = 1;
  load.loadPrintsFrom = path.c_str();
  engine.frame(1, [&](VkCommandBuffer cmd) { ASSERT_EQ(loaded->record(cmd, load), ""); });
  auto expected = engine.heights(saved->shadingInputs()), got = engine.heights(loaded->shadingInputs());
  EXPECT_GT(std::count_if(expected.begin(), expected.end(), [](std::uint32_t t) { return t != 0; }), 100);
  EXPECT_EQ(got, expected);
  std::remove(path.c_str());
}

TEST_F(SnowApi, RefusesInvalidSettingsAndFramesWithAMessage) {
  vk::Context& ctx = *snowContext();
  weathergen::snow::Device device{ctx.physicalDevice(), ctx.device(), ctx.queueFamily(), false};
  std::string error;
  weathergen::snow::Settings uneven = smallSettings();
  uneven.tileTexels = 24;  // does not divide 128
  EXPECT_FALSE(weathergen::snow::DeformableSnow::create(device, uneven, error));
  EXPECT_NE(error.find("multiple of tileTexels"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(weathergen::snow::DeformableSnow::create({}, smallSettings(), error));
  EXPECT_NE(error.find("no Vulkan device"), std::string::npos) << error;

  auto snow = weathergen::snow::DeformableSnow::create(device, smallSettings(), error);
  ASSERT_TRUE(snow) << error;
  EngineFrames engine(ctx);
  weathergen::snow::Frame late;
  late.frameIndex = kFramesInFlight;
  weathergen::snow::Mesh mesh;
  mesh.indexCount = 3;
  weathergen::snow::Frame withMesh;
  withMesh.meshes = &mesh;
  withMesh.meshCount = 1;
  weathergen::snow::Frame nullCapsules;
  nullCapsules.capsuleCount = 2;
  engine.frame(0, [&](VkCommandBuffer cmd) {
    EXPECT_NE(snow->record(cmd, late).find("not below Settings::framesInFlight"), std::string::npos);
    EXPECT_NE(snow->record(cmd, withMesh).find("fragmentStoresAndAtomics"), std::string::npos);
    EXPECT_NE(snow->record(cmd, nullCapsules).find("capsules is null"), std::string::npos);
  });
}

}  // namespace
}  // namespace wg::snow
