// Shared fixtures for the Vulkan render tests: one validated lavapipe device, one
// renderer per scene, pixel access, probe projection and the CPU evaluator's view of
// a rendered pixel.
#pragma once
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <string>

#include "compiler/cpu_evaluator.hpp"
#include "host/scene_renderer.hpp"

namespace wg::testing {

// The device the tests render on: the CPU device (lavapipe) with the validation
// layers always on. Null (and a skip) only when no Vulkan driver exists.
vk::Context* renderContext();
SceneRenderer& sceneRenderer(const std::string& scene);

// A weather state with the scene's sun.
WeatherState weatherFor(const scene::Scene& scene);

glm::vec4 pixel(const RenderedFrame& frame, int x, int y);
bool isSurface(const RenderedFrame& frame, int x, int y);  // not background (alpha 0)
// The pixel a world point lands on; nullopt when it is off screen or behind the camera.
std::optional<glm::ivec2> project(const glm::mat4& viewProjection, glm::vec3 world, std::uint32_t width,
                                  std::uint32_t height);

// Fails the test when the last render produced validation messages.
void expectNoValidationMessages();

// Everything the CPU evaluator needs to reproduce one pixel of one object.
struct PixelSurface {
  SurfacePoint surface;
  glm::ivec2 at;
};
// Renders the geometry AOVs of one object and returns the covered pixels on a grid.
std::vector<PixelSurface> surfacePixels(SceneRenderer& renderer, RenderRequest request, int gridStep);
// The frame state the renderer uploaded for `weather` (for the CPU evaluator).
FrameState frameStateFor(const SceneRenderer& renderer, const WeatherState& weather);
// Sky exposure at a surface point, from the renderer's exposure map as the GPU looks it up.
float skyExposureAt(const SceneRenderer& renderer, glm::vec3 position, glm::vec3 normal);
// The CPU evaluator for a bundled graph, compiled with its own preset.
const CpuEvaluator& evaluatorFor(const std::string& graphStem);
// The scene's terrain height map as the CPU samples it.
const HeightField& terrainField(const SceneRenderer& renderer);

}  // namespace wg::testing
