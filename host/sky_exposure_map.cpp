// The sky-exposure map (docs/runtime.md, "What a frame is made of"): once per scene,
// the height of the highest surface that keeps rain off above each texel, lowered where
// slanting snow and rain reach under an overhang; built by the weather library, as an
// engine builds it (weather/sky_exposure_builder.hpp).
#include "host/scene_renderer.hpp"

#include "weather/sky_exposure_builder.hpp"

namespace wg {

namespace {
// How far the map reaches beyond the scene's bounds, and its floor below them (metres).
constexpr float kExposureMargin = 1.f;
}  // namespace

void SceneRenderer::buildExposureMap() {
  // World-space copies: the builder takes triangles as engines hand them over. Reserved
  // up front, so the spans into them stay valid.
  std::vector<std::vector<glm::vec3>> worldPositions;
  worldPositions.reserve(scene_.objects.size());
  std::vector<OccluderTriangles> occluders;
  for (const scene::SceneObject& object : scene_.objects) {
    if (!object.occludesSky) continue;
    std::vector<glm::vec3>& world = worldPositions.emplace_back();
    world.reserve(object.mesh.positions.size());
    for (const glm::vec3& p : object.mesh.positions) world.push_back(glm::vec3(object.model * glm::vec4(p, 1.f)));
    occluders.push_back({world, object.mesh.indices});
  }
  const glm::vec3 margin(kExposureMargin);
  SkyExposureHeights map = buildSkyExposure(occluders, scene_.boundsMin - margin, scene_.boundsMax + margin,
                                            kExposureResolution);
  exposureRegion_ = map.region;
  exposureHeights_ = std::move(map.heights);
  exposureMap_ = vk::Image2D(ctx_, kExposureResolution, kExposureResolution, VK_FORMAT_R32_SFLOAT,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  exposureMap_.upload(ctx_, exposureHeights_.data(), exposureHeights_.size() * sizeof(float));
}

}  // namespace wg
