// weathergen_gpu_shader_stats: what a GPU's own shader compiler makes of a material's
// lit pipeline: registers, instructions, code size and waves per SIMD of its vertex and
// fragment stages, from VK_KHR_pipeline_executable_properties, for the graph's weather
// and for preset none at each quality tier, as a markdown table.
//
// With no GPU, Mesa's RADV compiles for an AMD GPU it does not have: its null device
// (RADV_FORCE_FAMILY) runs the real compiler, ACO, so the figures are the ones that GPU
// would run; scripts/gpu-shader-stats.sh sets it up.
//
//   weathergen_gpu_shader_stats [--device NAME] [--quality TIER] [--effects NAME=on|off,...] GRAPH...
//   --fragment-spirv FILE.spv  the weathered fragment stage read from FILE (a hand edit of
//                              the emitted GLSL through glslangValidator -V), to try a change
//                              of the shader library before making it
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/quality_tiers.hpp"
#include "driver/material_compiler.hpp"
#include "host/render_passes.hpp"
#include "vulkan/material_pipeline.hpp"
#include "vulkan/material_reflection.hpp"

namespace {

struct Options {
  std::string device;
  std::vector<std::string> tiers;
  wg::WeatherEffectOverrides effects;
  std::vector<std::string> graphs;
  std::string fragmentSpirv;  // a hand-edited fragment stage in place of the weathered one
};

struct Gpu {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  PFN_vkGetPipelineExecutablePropertiesKHR properties = nullptr;
  PFN_vkGetPipelineExecutableStatisticsKHR statistics = nullptr;
};

// The first device whose name holds `name` ("" : the first) and has the extension.
bool openGpu(const std::string& name, Gpu& gpu) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instanceInfo.pApplicationInfo = &app;
  if (vkCreateInstance(&instanceInfo, nullptr, &gpu.instance) != VK_SUCCESS) return false;
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data());
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    std::uint32_t extensionCount = 0;
    vkEnumerateDeviceExtensionProperties(d, nullptr, &extensionCount, nullptr);
    std::vector<VkExtensionProperties> extensions(extensionCount);
    vkEnumerateDeviceExtensionProperties(d, nullptr, &extensionCount, extensions.data());
    bool has = false;
    for (const auto& e : extensions)
      has = has || std::string(e.extensionName) == VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
    std::fprintf(stderr, "device: %s%s\n", p.deviceName, has ? "" : " (no VK_KHR_pipeline_executable_properties)");
    if (has && !gpu.physical && std::string(p.deviceName).find(name) != std::string::npos) gpu.physical = d;
  }
  if (!gpu.physical) return false;
  const float priority = 1.f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = gpu.queueFamily;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR feature{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  feature.pipelineExecutableInfo = VK_TRUE;
  const char* extension = VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.pNext = &feature;
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queue;
  deviceInfo.enabledExtensionCount = 1;
  deviceInfo.ppEnabledExtensionNames = &extension;
  if (vkCreateDevice(gpu.physical, &deviceInfo, nullptr, &gpu.device) != VK_SUCCESS) return false;
  gpu.properties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
      vkGetDeviceProcAddr(gpu.device, "vkGetPipelineExecutablePropertiesKHR"));
  gpu.statistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
      vkGetDeviceProcAddr(gpu.device, "vkGetPipelineExecutableStatisticsKHR"));
  return gpu.properties && gpu.statistics;
}

double statisticValue(const VkPipelineExecutableStatisticKHR& s) {
  switch (s.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR: return s.value.b32;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR: return static_cast<double>(s.value.i64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR: return static_cast<double>(s.value.u64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR: return s.value.f64;
    default: return 0;
  }
}

// Statistic name -> value, for each executable ("vertex", "fragment", by its stages).
using StageStatistics = std::map<std::string, std::map<std::string, double>>;

StageStatistics pipelineStatistics(const Gpu& gpu, VkPipeline pipeline) {
  VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  info.pipeline = pipeline;
  std::uint32_t count = 0;
  gpu.properties(gpu.device, &info, &count, nullptr);
  std::vector<VkPipelineExecutablePropertiesKHR> executables(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
  gpu.properties(gpu.device, &info, &count, executables.data());
  StageStatistics out;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::string stage = executables[i].stages & VK_SHADER_STAGE_FRAGMENT_BIT ? "frag"
                              : executables[i].stages & VK_SHADER_STAGE_VERTEX_BIT ? "vert"
                                                                                   : executables[i].name;
    VkPipelineExecutableInfoKHR executable{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
    executable.pipeline = pipeline;
    executable.executableIndex = i;
    std::uint32_t statCount = 0;
    gpu.statistics(gpu.device, &executable, &statCount, nullptr);
    std::vector<VkPipelineExecutableStatisticKHR> stats(statCount, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
    gpu.statistics(gpu.device, &executable, &statCount, stats.data());
    for (const auto& s : stats) out[stage][s.name] = statisticValue(s);
  }
  return out;
}

// The lit colour pipeline of one compile, as the renderer builds it (single-sampled).
std::optional<StageStatistics> materialStatistics(const Gpu& gpu, wg::vk::Context& ctx, const std::string& graph,
                                                  const std::string& tier, const std::optional<std::string>& preset,
                                                  const Options& o) {
  wg::CompileOptions options;
  options.emitHlsl = false;
  options.weatherPreset = preset;
  options.quality.requested = tier;
  options.weatherEffects = o.effects;
  wg::CompileResult result = wg::compileMaterialFile(graph, options);
  for (const auto& d : result.diagnostics.items()) std::fputs(wg::formatDiagnosticText(d).c_str(), stderr);
  if (!result.material) return std::nullopt;
  const wg::CompiledMaterial& m = *result.material;
  wg::SpirvWords fragment = m.stage(wg::ShaderLanguage::Glsl, wg::ShaderStage::Fragment).spirv;
  if (!o.fragmentSpirv.empty() && !preset) {
    std::ifstream in(o.fragmentSpirv, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fragment.assign(bytes.size() / 4, 0);
    std::memcpy(fragment.data(), bytes.data(), fragment.size() * 4);
  }
  wg::vk::UniqueRenderPass colour = wg::createColourPass(gpu.device, wg::vk::kColourFormat);
  wg::vk::UniqueRenderPass depth = wg::createDepthOnlyPass(gpu.device);
  wg::vk::PipelinePasses passes{.lit = colour.get(), .depth = depth.get(),
                                .flags = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR};
  wg::vk::MaterialPipeline pipeline(ctx, wg::vk::parseReflection(m.reflectionJson),
                                    m.stage(wg::ShaderLanguage::Glsl, wg::ShaderStage::Vertex).spirv,
                                    fragment, passes);
  return pipelineStatistics(gpu, pipeline.colourPipeline());
}

const char* const kColumns[] = {"VGPRs", "SGPRs", "Instructions", "Code size", "Subgroups per SIMD", "Latency",
                                "Inverse Throughput", "Branches", "Spilled VGPRs", "Pre-Sched VGPRs"};

void printRow(const std::string& material, const std::string& tier, const std::string& stage, const char* weather,
              const std::map<std::string, double>& stats) {
  std::printf("| %s | %s | %s | %s |", material.c_str(), tier.c_str(), stage.c_str(), weather);
  for (const char* column : kColumns) {
    auto it = stats.find(column);
    if (it == stats.end()) std::printf(" - |");
    else std::printf(" %.0f |", it->second);
  }
  std::printf("\n");
}

bool parseArguments(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--device" || a == "--quality" || a == "--effects" || a == "--fragment-spirv") && i + 1 < argc) {
      const std::string v = argv[++i];
      if (a == "--device") o.device = v;
      if (a == "--fragment-spirv") o.fragmentSpirv = v;
      if (a == "--quality") o.tiers = {v};
      for (std::size_t at = 0; a == "--effects" && at < v.size();) {
        const std::size_t end = std::min(v.find(',', at), v.size());
        const std::string item = v.substr(at, end - at);
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos) return false;
        o.effects.emplace_back(item.substr(0, eq), item.substr(eq + 1) == "on");
        at = end + 1;
      }
    } else if (a.starts_with("-")) {
      return false;
    } else {
      o.graphs.push_back(a);
    }
  }
  if (o.tiers.empty())
    for (const auto& t : wg::qualityTiers()) o.tiers.emplace_back(t.name);
  return !o.graphs.empty();
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parseArguments(argc, argv, o)) {
    std::fprintf(stderr, "usage: %s [--device NAME] [--quality TIER] [--effects NAME=on|off,...] [--fragment-spirv FILE] GRAPH...\n", argv[0]);
    return 2;
  }
  Gpu gpu;
  if (!openGpu(o.device, gpu)) {
    std::fprintf(stderr, "no Vulkan device named '%s' with VK_KHR_pipeline_executable_properties\n", o.device.c_str());
    return 1;
  }
  VkPhysicalDeviceProperties p;
  vkGetPhysicalDeviceProperties(gpu.physical, &p);
  std::printf("Device: %s. Lit colour pipeline, single-sampled, GLSL.\n\n| material | tier | stage | weather |", p.deviceName);
  for (const char* column : kColumns) std::printf(" %s |", column);
  std::printf("\n|---|---|---|---|");
  for (std::size_t i = 0; i < std::size(kColumns); ++i) std::printf("---:|");
  std::printf("\n");
  int failures = 0;
  {
    auto ctx = wg::vk::Context::borrow(gpu.physical, gpu.device, gpu.queueFamily, false);
    for (const std::string& graph : o.graphs)
      for (const std::string& tier : o.tiers) {
        auto weathered = materialStatistics(gpu, *ctx, graph, tier, std::nullopt, o);
        auto none = materialStatistics(gpu, *ctx, graph, tier, "none", o);
        if (!weathered || !none) {
          ++failures;
          continue;
        }
        const std::string material = std::filesystem::path(graph).stem().string();
        for (const char* stage : {"vert", "frag"}) {
          printRow(material, tier, stage, "none", (*none)[stage]);
          printRow(material, tier, stage, "graph's", (*weathered)[stage]);
        }
      }
  }
  // The device is left to the process's end: RADV's null device (Mesa 22.3) crashes in
  // vkDestroyDevice.
  std::fflush(stdout);
  std::_Exit(failures ? 1 : 0);
}
