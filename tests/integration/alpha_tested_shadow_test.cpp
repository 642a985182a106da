// Alpha-tested materials cast shadows only where they are opaque: the shadow map runs
// their fragment stage for its discard, so a foliage card that snow has thinned away
// (or any cut-out texel) leaves no shadow behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "render_support.hpp"

namespace wg {
namespace {

namespace fs = std::filesystem;
using namespace testing;

constexpr std::uint32_t kWidth = 160, kHeight = 120;
const glm::vec3 kSolidCard{-1.5f, 2.f, 0.f}, kCutOutCard{1.5f, 2.f, 0.f}, kOpenFloor{0.f, 0.f, 1.5f};

// A horizontal square facing up.
scene::Mesh flatSquare(glm::vec3 centre, float half) {
  scene::Mesh m;
  const glm::vec3 up(0.f, 1.f, 0.f);
  auto corner = [&](float sx, float sz) {
    return scene::addVertex(m, centre + glm::vec3(sx * half, 0.f, sz * half), up, {(sx + 1.f) / 2.f, (sz + 1.f) / 2.f});
  };
  scene::addQuadFacing(m, corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1), up);
  scene::computeTangents(m);
  return m;
}

scene::Scene cardsOverAFloor() {
  scene::Scene s;
  s.name = "cards";
  auto add = [&](std::string name, std::string graph, scene::Mesh mesh, bool castsShadow) {
    scene::SceneObject o;
    o.name = std::move(name);
    o.graph = std::move(graph);
    o.mesh = std::move(mesh);
    o.castsShadow = castsShadow;
    o.occludesSky = false;
    s.objects.push_back(std::move(o));
  };
  add("floor", "floor", flatSquare({0.f, 0.f, 0.f}, 4.f), false);
  add("solid", "solid", flatSquare(kSolidCard, 0.5f), true);
  add("cutOut", "cut_out", flatSquare(kCutOutCard, 0.5f), true);
  s.cameras.push_back({"side", {0.f, 7.f, 7.f}, {0.f, 0.f, 0.f}, 50.f});
  s.towardsSun = glm::vec3(0.f, 1.f, 0.f);
  scene::Bounds b;
  for (const auto& o : s.objects) b.include(scene::bounds(o.mesh));
  s.boundsMin = b.min;
  s.boundsMax = b.max;
  return s;
}

TEST(AlphaTestedShadow, ACutOutCardCastsNoShadowAndAnOpaqueOneDoes) {
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)";
  const fs::path dir = fs::temp_directory_path() / ("wg_alpha_shadow_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "floor.json") << R"({"name": "floor", "nodes": [], "output": {"baseColor": 0.6}})";
  std::ofstream(dir / "solid.json") << R"({"name": "solid", "nodes": [], "output": {"baseColor": 0.3}})";
  std::ofstream(dir / "cut_out.json")
      << R"({"name": "cut_out", "nodes": [], "alphaMode": "mask", "output": {"baseColor": 0.3, "opacity": 0.0}})";
  {
    SceneRenderer renderer(*renderContext(), cardsOverAFloor(), dir.string());
    RenderRequest r;
    r.width = kWidth;
    r.height = kHeight;
    RenderedFrame frame = renderer.render(r);
    expectNoValidationMessages();
    const glm::mat4 vp = renderer.viewProjection("side", kWidth, kHeight);
    auto floorAt = [&](glm::vec3 p) {
      auto at = project(vp, {p.x, 0.f, p.z}, kWidth, kHeight);
      EXPECT_TRUE(at.has_value());
      return at ? pixel(frame, at->x, at->y) : glm::vec4(0.f);
    };
    const glm::vec4 open = floorAt(kOpenFloor), underSolid = floorAt(kSolidCard), underCutOut = floorAt(kCutOutCard);
    EXPECT_LT(underSolid.g, 0.7f * open.g) << "the opaque card's shadow";
    EXPECT_NEAR(underCutOut.g, open.g, 0.01f) << "the cut-out card casts no shadow";
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wg
