#include "host/gpu_shader_statistics.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "host/render_passes.hpp"
#include "vulkan/material_pipeline.hpp"
#include "vulkan/material_reflection.hpp"

namespace wg {

// The instance and device are never destroyed: RADV's null device (Mesa 22.3) crashes in
// its own vkDestroyDevice. They are kept reachable here until the process ends.
struct GpuShaderCompiler::Device {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::string name;
  PFN_vkGetPipelineExecutablePropertiesKHR properties = nullptr;
  PFN_vkGetPipelineExecutableStatisticsKHR statistics = nullptr;
  std::unique_ptr<vk::Context> context;  // borrows `device`
};

namespace {

// Never destroyed (see Device), and reachable from a global, so that leak checkers see
// nothing lost.
void keepUntilExit(std::unique_ptr<GpuShaderCompiler::Device> device) {
  static auto* kept = new std::vector<std::unique_ptr<GpuShaderCompiler::Device>>;
  kept->push_back(std::move(device));
}

bool hasExecutableProperties(VkPhysicalDevice d) {
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(d, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(d, nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
    return std::string(e.extensionName) == VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
  });
}

bool createDevice(GpuShaderCompiler::Device& d) {
  const float priority = 1.f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR feature{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  feature.pipelineExecutableInfo = VK_TRUE;
  const char* extension = VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &feature;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = &extension;
  if (vkCreateDevice(d.physical, &info, nullptr, &d.device) != VK_SUCCESS) return false;
  d.properties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
      vkGetDeviceProcAddr(d.device, "vkGetPipelineExecutablePropertiesKHR"));
  d.statistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
      vkGetDeviceProcAddr(d.device, "vkGetPipelineExecutableStatisticsKHR"));
  d.context = vk::Context::borrow(d.physical, d.device, 0, false);
  return d.properties && d.statistics;
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

ExecutableStatistics executableStatistics(const GpuShaderCompiler::Device& d, VkPipeline pipeline,
                                          std::uint32_t index) {
  VkPipelineExecutableInfoKHR executable{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
  executable.pipeline = pipeline;
  executable.executableIndex = index;
  std::uint32_t count = 0;
  d.statistics(d.device, &executable, &count, nullptr);
  std::vector<VkPipelineExecutableStatisticKHR> stats(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
  d.statistics(d.device, &executable, &count, stats.data());
  ExecutableStatistics out;
  for (const auto& s : stats) out[s.name] = statisticValue(s);
  return out;
}

}  // namespace

GpuShaderCompiler::GpuShaderCompiler(std::unique_ptr<Device> device) : device_(std::move(device)) {}

GpuShaderCompiler::~GpuShaderCompiler() { keepUntilExit(std::move(device_)); }

std::unique_ptr<GpuShaderCompiler> GpuShaderCompiler::forDevice(const std::string& name, std::string& error) {
  auto d = std::make_unique<Device>();
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instanceInfo.pApplicationInfo = &app;
  if (vkCreateInstance(&instanceInfo, nullptr, &d->instance) != VK_SUCCESS) {
    error = "no Vulkan 1.1 driver";
    return nullptr;
  }
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(d->instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(d->instance, &count, devices.data());
  std::string seen;
  for (VkPhysicalDevice physical : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(physical, &p);
    const bool usable = hasExecutableProperties(physical);
    seen += std::string(seen.empty() ? "" : ", ") + p.deviceName + (usable ? "" : " (no statistics)");
    if (!d->physical && usable && std::string(p.deviceName).find(name) != std::string::npos) {
      d->physical = physical;
      d->name = p.deviceName;
    }
  }
  if (!d->physical || !createDevice(*d)) {
    error = "no Vulkan device named '" + name + "' reports its shaders' statistics (devices: " +
            (seen.empty() ? "none" : seen) + ")";
    keepUntilExit(std::move(d));
    return nullptr;
  }
  return std::unique_ptr<GpuShaderCompiler>(new GpuShaderCompiler(std::move(d)));
}

const std::vector<std::string_view>& amdGpuFamilies() {
  // Mesa 22.3's names with graphics (ARCTURUS and ALDEBARAN compute only); RADV aborts
  // the process on a name it does not know, so nothing else reaches it.
  static const std::vector<std::string_view> kFamilies = {
      "tahiti",    "pitcairn", "verde",   "oland",   "hainan",  "bonaire", "kabini",    "kaveri",    "hawaii",
      "tonga",     "iceland",  "carrizo", "fiji",    "stoney",  "polaris10", "polaris11", "polaris12", "vegam",
      "vega10",    "vega12",   "vega20",  "raven",   "raven2",  "renoir",  "navi10",    "navi12",    "navi14",
      "navi21",    "navi22",   "navi23",  "navi24",  "vangogh", "rembrandt", "gfx1036", "gfx1100",   "gfx1101",
      "gfx1102"};
  return kFamilies;
}

std::unique_ptr<GpuShaderCompiler> GpuShaderCompiler::forAmdFamily(const std::string& family, std::string& error) {
  std::string lower = family, upper = family;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  const auto& families = amdGpuFamilies();
  if (std::find(families.begin(), families.end(), lower) == families.end()) {
    error = "unknown AMD GPU family (families: ";
    for (std::size_t i = 0; i < families.size(); ++i) error += std::string(i ? ", " : "") + std::string(families[i]);
    error += ")";
    return nullptr;
  }
  ::setenv("RADV_FORCE_FAMILY", lower.c_str(), 1);
  auto compiler = forDevice("(RADV " + upper + ")", error);
  if (!compiler) error = "Mesa's RADV offers no null device for this AMD GPU family: " + error;
  return compiler;
}

std::string GpuShaderCompiler::deviceName() const { return device_->name; }

StageGpuStatistics GpuShaderCompiler::litPipeline(const std::string& reflectionJson, const SpirvWords& vertex,
                                                  const SpirvWords& fragment) {
  const Device& d = *device_;
  vk::UniqueRenderPass colour = createColourPass(d.device, vk::kColourFormat);
  vk::UniqueRenderPass depth = createDepthOnlyPass(d.device);
  vk::PipelinePasses passes{.lit = colour.get(), .depth = depth.get(),
                            .flags = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR};
  vk::MaterialPipeline pipeline(*d.context, vk::parseReflection(reflectionJson), vertex, fragment, passes);
  VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  info.pipeline = pipeline.colourPipeline();
  std::uint32_t count = 0;
  d.properties(d.device, &info, &count, nullptr);
  std::vector<VkPipelineExecutablePropertiesKHR> executables(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
  d.properties(d.device, &info, &count, executables.data());
  StageGpuStatistics out;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (executables[i].stages & VK_SHADER_STAGE_FRAGMENT_BIT) out.fragment = executableStatistics(d, info.pipeline, i);
    else if (executables[i].stages & VK_SHADER_STAGE_VERTEX_BIT) out.vertex = executableStatistics(d, info.pipeline, i);
  }
  if (out.vertex.empty() || out.fragment.empty()) throw std::runtime_error(d.name + " reported no statistics");
  return out;
}

}  // namespace wg
