// The sky-exposure map (docs/runtime.md, "What a frame is made of"): once per scene,
// an orthographic depth render from above of everything that keeps rain off, turned
// back into the height of the highest surface per texel, then lowered where slanting
// snow and rain reach under an overhang (weather/sky_exposure_reach.hpp).
#include "host/scene_renderer.hpp"

#include <cstring>

#include "host/descriptor_sets.hpp"
#include "host/frame_slices.hpp"
#include "host/pass_cameras.hpp"
#include "host/render_passes.hpp"
#include "weather/sky_exposure_reach.hpp"

namespace wg {

namespace {
// Extra height above and below the scene for the top-down exposure camera (metres).
constexpr float kExposureMargin = 1.f;
}  // namespace

void SceneRenderer::buildExposureMap() {
  const TopDownView view = topDownView(scene_, kExposureMargin);
  exposureRegion_ = view.region;
  std::vector<float> depths = drawSkyOccluders(view.viewProjection);
  exposureHeights_.resize(depths.size());
  for (std::size_t k = 0; k < depths.size(); ++k) exposureHeights_[k] = view.top - depths[k] * (view.top - view.bottom);
  const float texelsPerMetreX = kExposureResolution * view.region.z, texelsPerMetreZ = kExposureResolution * view.region.w;
  exposureHeights_ = reachUnderOverhangs(exposureHeights_, kExposureResolution, texelsPerMetreX, texelsPerMetreZ);
  exposureMap_ = vk::Image2D(ctx_, kExposureResolution, kExposureResolution, VK_FORMAT_R32_SFLOAT,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  exposureMap_.upload(ctx_, exposureHeights_.data(), exposureHeights_.size() * sizeof(float));
}

// The depth, from above, of everything that keeps rain off, drawn with unweathered
// materials: the map holds the scene's own geometry.
std::vector<float> SceneRenderer::drawSkyOccluders(const glm::mat4& topDown) {
  std::vector<std::size_t> drawn;
  for (std::size_t i = 0; i < scene_.objects.size(); ++i)
    if (scene_.objects[i].occludesSky) drawn.push_back(i);
  RenderRequest request;
  request.weatherPreset = "none";
  std::vector<MaterialResources*> mats = materialsFor(request);
  const vk::ReflectedBlock& block = mats.front()->reflection().frame;
  FrameSlices slices(ctx_, block, std::max<std::size_t>(drawn.size(), 1));
  std::vector<UploadedMesh> meshes;
  meshes.reserve(drawn.size());  // draws point into it
  auto pool = createMaterialDescriptorPool(ctx_.device(), static_cast<std::uint32_t>(2 * drawn.size() + 2), 64, 512);
  SharedMaps maps{terrainHeight_.view(), placeholderHeight_.view(), placeholderShadow_.view(), placeholderDeformation_.view(),
                  weatherNoise_.view(), linearClamp_.get(), nearestClamp_.get(), linearRepeat_.get()};
  DescriptorWriter writer;
  std::vector<ObjectDraw> draws;
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    const scene::SceneObject& object = scene_.objects[drawn[k]];
    FrameUniforms f(block);
    f.set("model", object.model);
    f.set("viewProjection", topDown);
    f.set("normalMatrix", glm::transpose(glm::inverse(object.model)));
    slices.write(k, f);
    meshes.push_back(uploadMesh(ctx_, object.mesh, vk::vertexLayoutFrom(mats[drawn[k]]->reflection())));
    auto& pipeline = pipelineOf(*mats[drawn[k]], request);
    draws.push_back({&pipeline, pipeline.depthPipeline(),
                     allocateMaterialSets(ctx_.device(), pool.get(), *mats[drawn[k]], pipeline, writer, slices.buffer(), slices.blockSize(), maps),
                     slices.offset(k), &meshes.back()});
  }
  writer.apply(ctx_.device());
  return depthFromAbove(draws);
}

std::vector<float> SceneRenderer::depthFromAbove(const std::vector<ObjectDraw>& draws) {
  // Sampled too: the depth-only pass leaves its target shader-readable.
  vk::Image2D depth(ctx_, kExposureResolution, kExposureResolution, vk::kDepthFormat,
                    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  vk::UniqueFramebuffer target = createFramebuffer(ctx_.device(), depthPass_.get(), {depth.view()}, kExposureResolution, kExposureResolution);
  VkClearValue clear;
  clear.depthStencil = {1.f, 0};
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    recordPass(cmd, {depthPass_.get(), target.get(), kExposureResolution, kExposureResolution, {clear}}, draws);
  });
  auto raw = depth.download(ctx_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  std::vector<float> depths(std::size_t(kExposureResolution) * kExposureResolution);
  std::memcpy(depths.data(), raw.data(), depths.size() * sizeof(float));
  return depths;
}

}  // namespace wg
