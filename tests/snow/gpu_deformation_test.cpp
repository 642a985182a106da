// The deformation compute pass on lavapipe with the validation layers on: the map read
// back from the GPU against the CPU model and the scripted paths,
// a footprint's boot-sole shape, no deformation without snow, continuous trails at any
// speed, prints through recentring and a round trip, refill at the configured rate.
#include "snow/gpu_deformation_map.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <memory>

#include "backends/spirv/spirv_toolchain.hpp"
#include "snow/cpu_stamping.hpp"
#include "snow/deformation_map.hpp"
#include "snow/deformation_shaders.hpp"
#include "snow/deformation_texel.hpp"
#include "snow/snow_interactors.hpp"

#include "tests/snow/snow_gpu_support.hpp"

namespace wg::snow {
namespace {

const WindowSettings kSmall{128, 0.04f, 16};
// Refill reaches every tile of the 8 x 8 each call, so the rate is exact at every call.
const WindowSettings kEveryTileRefilled{128, 0.04f, 16, kSmall.printStoreBudget, 64};
const SnowCover kCover{0.12f};
constexpr double kFrame = 1.0 / 60.0;

using testing::snowContext;

using GpuDeformation = testing::ValidatedGpuTest;

// A walker, a second walker crossing it and a vehicle, over `seconds`.
std::vector<std::vector<Stamp>> scriptedFrames(double seconds, const SnowCover& cover) {
  Walker a, b;
  a.path = ScriptedPath({{-2.f, -1.5f}, {2.f, 1.f}}, 1.4f);
  b.path = ScriptedPath({{1.5f, -2.f}, {-1.f, 2.f}}, 1.1f);
  Vehicle v;
  v.path = ScriptedPath({{-2.4f, 0.6f}, {2.4f, -0.4f}}, 3.f);
  std::vector<std::vector<Stamp>> frames;
  for (double t = 0.0; t < seconds; t += kFrame) {
    std::vector<Stamp> stamps;
    walkerStamps(a, t - kFrame, t, cover, stamps);
    walkerStamps(b, t - kFrame, t, cover, stamps);
    vehicleStamps(v, t - kFrame, t, cover, stamps);
    frames.push_back(std::move(stamps));
  }
  return frames;
}

// Largest difference in quanta between two maps' depth and rim halves.
std::uint32_t maxQuantaDifference(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
  std::uint32_t worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    auto diff = [](std::uint32_t x, std::uint32_t y) { return x > y ? x - y : y - x; };
    worst = std::max({worst, diff(a[i] >> kDepthShift, b[i] >> kDepthShift), diff(a[i] & kMaxQuanta, b[i] & kMaxQuanta)});
  }
  return worst;
}

TEST(SnowShaders, LayoutComesFromReflection) {
  SpirvCompileResult stamp = compileComputeToSpirv(stampShaderSource());
  ASSERT_TRUE(stamp.ok) << stamp.log;
  EXPECT_EQ(validateSpirv(stamp.words), "");
  ModuleInterface i = reflectModule(stamp.words);
  EXPECT_EQ(i.pushConstantBytes, sizeof(WindowConstants));
  EXPECT_EQ(i.localSize[0], 8u);
  std::vector<std::string> names;
  for (const auto& b : i.bindings) names.push_back(b.name);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"Heights", "StampBoxes", "Stamps"}));
}

TEST_F(GpuDeformation, MatchesTheCpuModelTexelForTexel) {
  DeformationMap cpu(kSmall);
  GpuDeformationMap gpu(*snowContext(), kSmall);
  for (const auto& stamps : scriptedFrames(3.0, kCover)) {
    cpu.apply(stamps);
    gpu.apply(stamps);
  }
  // Float rounding may move a value across a quantum boundary, never more.
  EXPECT_LE(maxQuantaDifference(cpu.texels().heights, gpu.texels().heights), 1u);
  int deformed = 0;
  for (auto t : gpu.texels().heights) deformed += t != 0;
  EXPECT_GT(deformed, 500);
  for (std::size_t i = 0; i < cpu.window().texelCount(); ++i) {
    glm::vec3 a = unpackNormal(cpu.texels().normals[i]), b = unpackNormal(gpu.texels().normals[i]);
    ASSERT_GT(glm::dot(a, b), 0.999f) << "texel " << i;
  }
}

TEST_F(GpuDeformation, FootprintsReadBackWhereThePathPutsThem) {
  GpuDeformationMap gpu(*snowContext(), kSmall);
  Walker w;
  w.path = ScriptedPath({{-2.f, 1.f}, {2.f, -1.f}}, 1.4f);
  for (double t = 0.0; t < 4.0; t += kFrame) {
    std::vector<Stamp> stamps;
    walkerStamps(w, t - kFrame, t, kCover, stamps);
    gpu.apply(stamps);
  }
  float expected = std::min(w.sink, deepestPrint(kCover));
  glm::vec2 heading = w.path.headingAt(0.f);
  int prints = 0;
  for (int k = 0; k * w.stepLength <= w.path.length(); ++k, ++prints) {
    glm::vec2 heel = footfall(w, k) - heading * (0.5f * w.foot.length - w.foot.heelRadius);
    EXPECT_NEAR(gpu.depthAt(heel), expected, 0.05f * expected) << "footfall " << k;
    EXPECT_EQ(gpu.depthAt(w.path.pointAt((float(k) + 0.5f) * w.stepLength)), 0.f) << "between footfalls " << k;
  }
  EXPECT_GE(prints, 5);
}

// One footprint read back from the GPU, on a 1 cm map (its shape) and on the default
// 4 cm map (what the snow layer draws): a boot sole, heel and ball deeper than the
// arch and the sole narrowest at its waist; the CPU model agrees on both.
TEST_F(GpuDeformation, AFootprintReadsBackAsABootSole) {
  const FootShape foot;
  const glm::vec2 heading(0.f, 1.f);
  for (float texel : {0.01f, 0.04f}) {
    const glm::vec2 centre(0.5f * texel);  // the sole's axis on a column of texel centres
    Stamp print = footprint(centre, heading, foot, kCover, Walker{}.sink);
    const glm::vec2 heel = centre - heading * (0.5f * foot.length - foot.heelRadius);
    const glm::vec2 toe = centre + heading * (0.5f * foot.length - foot.toeRadius);
    const glm::vec2 arch = 0.5f * (heel + toe);
    const WindowSettings settings{128, texel, 16};
    DeformationMap cpu(settings);
    GpuDeformationMap gpu(*snowContext(), settings);
    cpu.apply(std::span(&print, 1));
    gpu.apply(std::span(&print, 1));
    EXPECT_LE(maxQuantaDifference(cpu.texels().heights, gpu.texels().heights), 1u) << texel;
    float atHeel = gpu.depthAt(heel), atArch = gpu.depthAt(arch), atToe = gpu.depthAt(toe);
    RecordProperty(texel < 0.02f ? "depths_1cm_heel_arch_toe_mm" : "depths_4cm_heel_arch_toe_mm",
                   std::to_string(int(1000.f * atHeel)) + " " + std::to_string(int(1000.f * atArch)) + " " +
                       std::to_string(int(1000.f * atToe)));
    EXPECT_GT(atArch, 0.f) << texel << ": the arch is part of the print";
    EXPECT_LT(atArch, 0.75f * atHeel) << texel;
    EXPECT_LT(atArch, 0.75f * atToe) << texel;
    // Width: texels across the sole deeper than a centimetre.
    auto width = [&](glm::vec2 at) {
      int n = 0;
      for (int k = -20; k <= 20; ++k) n += gpu.depthAt(at + glm::vec2(float(k) * texel, 0.f)) > 0.01f;
      return n;
    };
    int heelWidth = width(heel), archWidth = width(arch), toeWidth = width(toe);
    RecordProperty(texel < 0.02f ? "widths_1cm_heel_arch_toe_texels" : "widths_4cm_heel_arch_toe_texels",
                   std::to_string(heelWidth) + " " + std::to_string(archWidth) + " " + std::to_string(toeWidth));
    EXPECT_LE(archWidth, std::min(heelWidth, toeWidth)) << texel;
    if (texel < 0.02f) {  // 1 cm resolves the sole: 9, 7 and 11 cm across (on 4 cm, 1 to 3 texels)
      EXPECT_NEAR(heelWidth, 9, 1);
      EXPECT_NEAR(archWidth, 7, 1);
      EXPECT_NEAR(toeWidth, 11, 1);
    }
  }
}

TEST_F(GpuDeformation, ZeroSnowDepthLeavesNoDeformation) {
  GpuDeformationMap gpu(*snowContext(), kSmall);
  for (const auto& stamps : scriptedFrames(2.0, SnowCover{0.f})) gpu.apply(stamps);
  auto t = gpu.texels();
  EXPECT_TRUE(std::all_of(t.heights.begin(), t.heights.end(), [](auto v) { return v == 0u; }));
  EXPECT_TRUE(std::all_of(t.normals.begin(), t.normals.end(), [](auto v) { return v == 0u; }));
}

TEST_F(GpuDeformation, FastMoversLeaveContinuousTrails) {
  GpuDeformationMap gpu(*snowContext(), kSmall);
  Walker sprinter;  // 40 m/s at 10 frames per second: five footfalls a frame
  sprinter.path = ScriptedPath({{-2.2f, 1.f}, {2.2f, 1.f}}, 40.f);
  Vehicle car;  // 30 m/s: half a metre a frame
  car.path = ScriptedPath({{-2.2f, -0.8f}, {2.2f, -0.8f}}, 30.f);
  for (double t = 0.0; t < 1.0; t += 0.1) {
    std::vector<Stamp> stamps;
    walkerStamps(sprinter, t - 0.1, t, kCover, stamps);
    vehicleStamps(car, t - 0.1, t, kCover, stamps);
    gpu.apply(stamps);
  }
  for (int k = 0; k * sprinter.stepLength <= sprinter.path.length(); ++k)
    EXPECT_GT(gpu.depthAt(footfall(sprinter, k)), 0.f) << "footfall " << k;
  for (float x = -2.2f; x <= 2.2f; x += kSmall.texelSize)
    for (float side : {0.5f, -0.5f}) EXPECT_GT(gpu.depthAt({x, -0.8f + side * car.track}), 0.f) << x;
}

TEST_F(GpuDeformation, PrintsSurviveRecentringAndARoundTrip) {
  GpuDeformationMap gpu(*snowContext(), kSmall);
  for (const auto& stamps : scriptedFrames(3.0, kCover)) gpu.apply(stamps);
  std::vector<std::uint32_t> before(gpu.texels().heights.begin(), gpu.texels().heights.end());
  std::vector<std::uint32_t> normalsBefore(gpu.texels().normals.begin(), gpu.texels().normals.end());
  for (float x = 0.f; x <= 40.f; x += 0.9f) gpu.follow({x, 0.5f * x});
  EXPECT_GT(gpu.store().tileCount(), 0u);
  // New prints far away do not disturb the stored ones.
  Stamp far = capsule({40.f, 20.f}, {41.f, 20.f}, 0.2f, kCover, 0.1f);
  gpu.apply(std::span(&far, 1));
  for (float x = 40.f; x >= 0.f; x -= 0.9f) gpu.follow({x, 0.5f * x});
  gpu.follow({0.f, 0.f});
  auto now = gpu.texels();
  EXPECT_TRUE(std::equal(now.heights.begin(), now.heights.end(), before.begin()));
  // Normals of restored tiles are regenerated from the same heights (by the CPU). The
  // window's outermost texels are left out: their outward neighbour is clamped, so their
  // normal depends on where the window stood when it was last computed.
  const SnowWindow& w = gpu.window();
  TexelRect inner = w.rect().grown(-1);
  for (int z = inner.min.y; z < inner.min.y + inner.size.y; ++z)
    for (int x = inner.min.x; x < inner.min.x + inner.size.x; ++x) {
      std::size_t i = w.storageIndex({x, z});
      ASSERT_GT(glm::dot(unpackNormal(now.normals[i]), unpackNormal(normalsBefore[i])), 0.999f) << x << "," << z;
    }
  // And the map still stamps correctly after the trip.
  Stamp again = capsule({0.f, 0.f}, {0.f, 0.f}, 0.1f, SnowCover{0.3f}, 0.1f);
  gpu.apply(std::span(&again, 1));
  EXPECT_NEAR(gpu.depthAt({0.f, 0.f}), 0.1f, kDepthQuantum);
}

// The surface image the snow layer samples holds, per toroidal slot, the texel's height
// and normal: after stamps, a round trip out of the window and a refill.
TEST_F(GpuDeformation, SurfaceImageFollowsTheMap) {
  GpuDeformationMap gpu(*snowContext(), kSmall);
  auto expectSurfaceMatches = [&](const char* when) {
    auto t = gpu.texels();  // first: it finishes the normals recentring deferred
    // download() only reads the image (it is not const-qualified).
    auto& image = const_cast<vk::Image2D&>(gpu.surfaceImage());
    auto raw = image.download(*snowContext(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    const auto* halves = reinterpret_cast<const std::uint16_t*>(raw.data());
    int deformed = 0, wrong = 0;
    for (std::size_t i = 0; i < t.heights.size(); ++i) {
      glm::vec4 s(glm::unpackHalf1x16(halves[4 * i]), glm::unpackHalf1x16(halves[4 * i + 1]),
                  glm::unpackHalf1x16(halves[4 * i + 2]), glm::unpackHalf1x16(halves[4 * i + 3]));
      bool height = std::abs(s.x - texelHeight(t.heights[i])) <= 5e-4f;
      bool normal = glm::dot(glm::vec3(s.y, s.z, s.w), unpackNormal(t.normals[i])) > 0.999f;
      wrong += !(height && normal);
      deformed += t.heights[i] != 0;
    }
    EXPECT_EQ(wrong, 0) << when;
    return deformed;
  };
  for (const auto& stamps : scriptedFrames(3.0, kCover)) gpu.apply(stamps);
  EXPECT_GT(expectSurfaceMatches("after stamping"), 500);
  for (float x = 0.f; x <= 30.f; x += 0.9f) gpu.follow({x, 0.f});
  EXPECT_EQ(expectSurfaceMatches("away"), 0);
  for (float x = 30.f; x >= 0.f; x -= 0.9f) gpu.follow({x, 0.f});
  gpu.follow({0.f, 0.f});
  EXPECT_GT(expectSurfaceMatches("back"), 500);
  gpu.refill(0.01 / 3600.0, 3600.0);
  expectSurfaceMatches("refilled");
}

TEST_F(GpuDeformation, RefillReducesPrintDepthAtTheConfiguredRate) {
  GpuDeformationMap gpu(*snowContext(), kEveryTileRefilled);
  Stamp s = capsule({0.f, 0.f}, {0.f, 0.f}, 0.3f, SnowCover{0.3f}, 0.1f);
  gpu.apply(std::span(&s, 1));
  const double rate = 0.02 / 3600.0;  // 2 cm per hour
  for (int minute = 0; minute < 90; ++minute) gpu.refill(rate, 60.0);
  EXPECT_NEAR(gpu.depthAt({0.f, 0.f}), 0.07f, 1.5f * kDepthQuantum);
  // The wall is shallower now, so its normal tilts less.
  DeformationMap cpu(kEveryTileRefilled);
  cpu.apply(std::span(&s, 1));
  for (int minute = 0; minute < 90; ++minute) cpu.refill(rate, 60.0);
  EXPECT_LE(maxQuantaDifference(cpu.texels().heights, gpu.texels().heights), 0u);
  glm::vec3 wall = gpu.normalAt({0.26f, 0.f});
  EXPECT_NEAR(wall.x, cpu.normalAt({0.26f, 0.f}).x, 1e-3f);
}

}  // namespace
}  // namespace wg::snow
