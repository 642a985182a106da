#include "host/snowfield/snow_puffs.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "nodes/lattice_noise.hpp"
#include "host/colour_overlay.hpp"
#include "host/material_resources.hpp"
#include "host/snowfield/snow_puff_shaders.hpp"
#include "vulkan/material_pipeline.hpp"
#include "vulkan/compute_barriers.hpp"
#include "vulkan/runtime_shader.hpp"

namespace wg::snow {

namespace {
constexpr std::uint32_t kVerticesPerParticle = 6;
constexpr float kTwoPi = 6.2831853f;
// Spread of each particle's attributes around the settings (uniform, +-).
constexpr float kLifeSpread = 0.3f, kSizeSpread = 0.3f, kSpeedLow = 0.5f, kJitter = 0.05f;
// Launch elevation: most snow is kicked up and forward, little sideways.
constexpr float kMinElevation = 0.7f, kMaxElevation = 1.35f;  // radians
// Albedo of the kicked-up snow, per particle: clumps and powder differ a little.
constexpr float kLowestShade = 0.85f, kBrightestShade = 1.f;
constexpr float kOpacity = 0.6f;

struct StepConstants {
  float wind[2];
  float dt, gravity, drag;
  std::uint32_t count;
};
struct ViewConstants {
  glm::mat4 viewProjection;
  glm::vec4 right, up;  // w: the sky's and the sun's light
  glm::vec4 sun;        // towards the sun in (right, up, towards the camera)
  glm::vec4 fade;       // near, far, softness, opacity
};

// Deterministic draws in [0, 1): the lattice-noise hash of (particle, draw number).
struct Draws {
  std::int32_t particle;
  std::int32_t next = 0;
  float unit() { return float(latticeHash(particle, next++) >> 8) / float(1u << 24); }
  float around(float spread) { return 1.f + spread * (2.f * unit() - 1.f); }
};

}  // namespace

SnowPuffs::SnowPuffs(vk::Context& ctx, const PuffSettings& settings)
    : ctx_(ctx), settings_(settings), overlay_(ctx.device()),
      particles_(ctx, settings.capacity * sizeof(Particle), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
  std::memset(particles_.mapped(), 0, particles_.size());
  auto simulate = vk::compileRuntimeShader(puffSimulateSource(), vk::RuntimeStage::Compute, "snow puff step");
  auto vertex = vk::compileRuntimeShader(puffVertexSource(), vk::RuntimeStage::Vertex, "snow puff vertex");
  auto fragment = vk::compileRuntimeShader(puffFragmentSource(), vk::RuntimeStage::Fragment, "snow puff fragment");
  simulateSet_ = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, std::vector{simulate.interface}, VK_SHADER_STAGE_COMPUTE_BIT);
  drawSet_ = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, std::vector{vertex.interface, fragment.interface},
                                                          VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  if (simulateSet_->pushConstantBytes() != sizeof(StepConstants) || drawSet_->pushConstantBytes() != sizeof(ViewConstants))
    throw std::runtime_error("snow puff shaders: push constants disagree with StepConstants / ViewConstants");
  simulateSet_->bindBuffer("Particles", particles_);
  drawSet_->bindBuffer("Particles", particles_);
  depthSampler_ = createSampler(ctx_, "clamp", "nearest");
  drawSet_->bindSampler("DepthSampler", depthSampler_.get());
  simulateLocalSize_ = simulate.interface.localSize[0];

  simulateModule_ = vk::createShaderModule(ctx_, simulate.words);
  simulatePipeline_ = vk::createComputePipeline(ctx_, simulateModule_.get(), simulateSet_->pipelineLayout());

  vertexModule_ = vk::createShaderModule(ctx_, vertex.words);
  fragmentModule_ = vk::createShaderModule(ctx_, fragment.words);
  // Camera-facing billboards, six vertices a particle from the particle buffer.
  drawPipeline_ = overlay_.pipeline(vertexModule_.get(), fragmentModule_.get(), drawSet_->pipelineLayout());
}

SnowPuffs::~SnowPuffs() { vkDeviceWaitIdle(ctx_.device()); }

void SnowPuffs::emit(std::span<const glm::vec3> footfalls) {
  auto* slots = static_cast<Particle*>(particles_.mapped());
  for (glm::vec3 at : footfalls)
    for (int i = 0; i < settings_.particlesPerFootfall; ++i) {
      Draws draw{static_cast<std::int32_t>(++emitted_)};
      float azimuth = kTwoPi * draw.unit();
      float elevation = kMinElevation + (kMaxElevation - kMinElevation) * draw.unit();
      float speed = settings_.launchSpeed * (kSpeedLow + (1.f - kSpeedLow) * draw.unit());
      glm::vec3 direction(std::cos(azimuth) * std::cos(elevation), std::sin(elevation), std::sin(azimuth) * std::cos(elevation));
      glm::vec3 jitter(draw.unit() - 0.5f, 0.f, draw.unit() - 0.5f);
      Particle& p = slots[next_];
      p.positionAge = glm::vec4(at + jitter * (2.f * kJitter), 0.f);
      p.velocityLife = glm::vec4(direction * speed, settings_.lifetime * draw.around(kLifeSpread));
      p.sizeShade = glm::vec4(settings_.radius * draw.around(kSizeSpread),
                              kLowestShade + (kBrightestShade - kLowestShade) * draw.unit(), at.y, 0.f);
      next_ = (next_ + 1) % settings_.capacity;
    }
}

void SnowPuffs::simulate(double seconds, glm::vec2 wind) {
  if (!(seconds > 0.0)) return;
  StepConstants c{{wind.x, wind.y}, float(seconds), settings_.gravity, settings_.drag, settings_.capacity};
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    VkDescriptorSet set = simulateSet_->set();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, simulatePipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, simulateSet_->pipelineLayout(), 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, simulateSet_->pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof c, &c);
    vkCmdDispatch(cmd, (settings_.capacity + simulateLocalSize_ - 1) / simulateLocalSize_, 1, 1);
    vk::computeToHostBarrier(cmd);  // emit() writes the ring from the host
  });
}

void SnowPuffs::record(const ColourPassTargets& t) {
  drawSet_->bindImage("SceneDepth", t.depth->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  // Billboards face the camera: its right and up directions, unprojected from the
  // centre of the screen.
  glm::mat4 inverse = glm::inverse(t.viewProjection);
  auto unproject = [&](glm::vec3 ndc) {
    glm::vec4 p = inverse * glm::vec4(ndc, 1.f);
    return glm::vec3(p) / p.w;
  };
  glm::vec3 centre = unproject({0.f, 0.f, 0.5f});
  glm::vec3 right = glm::normalize(unproject({1.f, 0.f, 0.5f}) - centre);
  glm::vec3 up = glm::normalize(unproject({0.f, -1.f, 0.5f}) - centre);  // clip y points down
  glm::vec3 back = glm::normalize(glm::cross(right, up));  // towards the camera
  glm::vec3 sun = glm::normalize(settings_.towardsSun);
  ViewConstants c{t.viewProjection,
                  glm::vec4(right, settings_.skyLight),
                  glm::vec4(up, settings_.sunLight),
                  glm::vec4(glm::dot(sun, right), glm::dot(sun, up), glm::dot(sun, back), 0.f),
                  {t.nearPlane, t.farPlane, settings_.softness, kOpacity}};
  overlay_.begin(t);
  VkDescriptorSet set = drawSet_->set();
  vkCmdBindPipeline(t.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, drawPipeline_.get());
  vkCmdBindDescriptorSets(t.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, drawSet_->pipelineLayout(), 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(t.cmd, drawSet_->pipelineLayout(), drawSet_->stages(), 0, sizeof c, &c);
  vkCmdDraw(t.cmd, settings_.capacity * kVerticesPerParticle, 1, 0, 0);
  overlay_.end(t);
}

std::span<const Particle> SnowPuffs::particles() const {
  return {static_cast<const Particle*>(particles_.mapped()), settings_.capacity};
}

std::size_t SnowPuffs::live() const {
  std::size_t n = 0;
  for (const Particle& p : particles()) n += p.velocityLife.w > 0.f;
  return n;
}

}  // namespace wg::snow
