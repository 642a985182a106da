// What a GPU's own shader compiler makes of a material: its lit colour pipeline built
// as the renderer builds it, and the driver's figures for each stage (registers, ISA
// instructions, waves per SIMD) read through VK_KHR_pipeline_executable_properties.
//
// With no GPU, Mesa's RADV compiles for an AMD GPU family it is told to pretend to
// have (RADV_FORCE_FAMILY): its null device runs AMD's real compiler, ACO, and nothing
// else. `weathergen stats --gpu FAMILY` and bench/gpu_shader_stats use it.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "backends/spirv/spirv_toolchain.hpp"

namespace wg {

// Statistic name ("VGPRs", "Instructions", "Subgroups per SIMD"...) to value.
using ExecutableStatistics = std::map<std::string, double>;

struct StageGpuStatistics {
  ExecutableStatistics vertex, fragment;
};

// The AMD GPU families forAmdFamily takes ("navi21", "gfx1100"...).
const std::vector<std::string_view>& amdGpuFamilies();

class GpuShaderCompiler {
 public:
  // RADV's null device for `family` (navi21, gfx1100, vega10...). Sets RADV_FORCE_FAMILY
  // for this process, so call it before any other Vulkan use. Null, with `error`, when
  // the driver offers no such device (the message leaves `family` for the caller to
  // quote).
  static std::unique_ptr<GpuShaderCompiler> forAmdFamily(const std::string& family, std::string& error);
  // The first device whose name holds `name` and that has the extension.
  static std::unique_ptr<GpuShaderCompiler> forDevice(const std::string& name, std::string& error);
  ~GpuShaderCompiler();
  GpuShaderCompiler(const GpuShaderCompiler&) = delete;
  GpuShaderCompiler& operator=(const GpuShaderCompiler&) = delete;

  std::string deviceName() const;
  // The lit colour pipeline (single-sampled) of the stages and their reflection JSON.
  // Throws std::runtime_error when the driver refuses them.
  StageGpuStatistics litPipeline(const std::string& reflectionJson, const SpirvWords& vertex,
                                 const SpirvWords& fragment);

  struct Device;  // the driver's handles

 private:
  explicit GpuShaderCompiler(std::unique_ptr<Device> device);
  std::unique_ptr<Device> device_;
};

}  // namespace wg
