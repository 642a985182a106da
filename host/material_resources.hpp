// Everything one material needs on the GPU: its compiled shaders (both languages),
// reflection, parameter block filled with the reflected defaults, textures made from
// the reflected sources, samplers, and a pipeline per backend.
#pragma once
#include <map>
#include <memory>
#include <string>

#include "driver/material_compiler.hpp"
#include "vulkan/gpu_image.hpp"
#include "vulkan/material_pipeline.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg {

class MaterialResources {
 public:
  // Compiles graphPath (throws MaterialCompileError with the diagnostics on failure).
  // `parameters` replace the reflected defaults of the members they name; names the
  // material lacks are skipped.
  MaterialResources(vk::Context& ctx, const std::string& graphPath, const CompileOptions& options,
                    const std::map<std::string, float>& parameters = {});
  MaterialResources(const MaterialResources&) = delete;
  MaterialResources& operator=(const MaterialResources&) = delete;

  // Built on first use for each backend.
  vk::MaterialPipeline& pipeline(ShaderLanguage backend, const vk::PipelinePasses& passes);
  const vk::MaterialReflection& reflection() const { return reflection_; }
  const CompiledMaterial& compiled() const { return compiled_; }
  const std::string& graphPath() const { return graphPath_; }
  const vk::Buffer* parameterBuffer() const { return parameters_.get(); }

  // Each texture has its full mip chain; `sampler` reads it trilinear (and anisotropic
  // where the device allows), `baseLevelSampler` reads level 0 only, as the CPU
  // evaluator does: the AOV renders bind that one (docs/runtime.md).
  struct BoundTexture {
    const vk::ReflectedTexture* reflected;
    vk::Image2D image;
    vk::UniqueSampler sampler;
    vk::UniqueSampler baseLevelSampler;
    VkSampler samplerFor(bool baseLevel) const { return baseLevel ? baseLevelSampler.get() : sampler.get(); }
  };
  const std::vector<BoundTexture>& textures() const { return textures_; }
  std::size_t textureBytes() const;

 private:
  vk::Context& ctx_;
  std::string graphPath_;
  CompiledMaterial compiled_;
  vk::MaterialReflection reflection_;
  std::unique_ptr<vk::Buffer> parameters_;
  std::vector<BoundTexture> textures_;
  std::map<ShaderLanguage, std::unique_ptr<vk::MaterialPipeline>> pipelines_;
};

// A sampler for a reflected wrap/filter pair.
vk::UniqueSampler createSampler(vk::Context& ctx, std::string_view wrap, std::string_view filter);

}  // namespace wg
