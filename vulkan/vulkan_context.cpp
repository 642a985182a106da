#include "vulkan/vulkan_context.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "vulkan/sampler_anisotropy.hpp"

namespace wg::vk {

void check(VkResult result, const char* what) {
  if (result == VK_SUCCESS) return;
  const std::string message = std::string(what) + " failed (VkResult " + std::to_string(result) + ")";
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY) throw OutOfMemory(message);
  throw std::runtime_error(message);
}

namespace {
constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasLayer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

UniqueInstance createInstance(bool validation, std::string& error) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "weathergen";
  app.apiVersion = VK_API_VERSION_1_1;
  std::vector<const char*> layers, extensions;
  if (validation) {
    if (!hasLayer(kValidationLayer)) {
      error = "the Vulkan validation layers are not installed (Debian package vulkan-validationlayers)";
      return {};
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) {
    error = "no Vulkan 1.1 instance (is a driver installed? Debian: mesa-vulkan-drivers)";
    return {};
  }
  return UniqueInstance(instance);
}

bool matches(const VkPhysicalDeviceProperties& p, const std::string& selector) {
  if (selector.empty()) return true;
  std::string s = lower(selector);
  if (s == "cpu") return p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (s == "integrated") return p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU;
  if (s == "discrete") return p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  if (s == "gpu") return p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU || p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU;
  return lower(p.deviceName).find(s) != std::string::npos;
}
}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<Context*>(user);
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT)
    self->messages_.push_back(std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error: " : "warning: ") +
                              (data->pMessage ? data->pMessage : ""));
  return VK_FALSE;
}

std::vector<std::string> Context::listDevices(std::string& error) {
  std::vector<std::string> names;
  UniqueInstance instance = createInstance(false, error);
  if (!instance) return names;
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance.get(), &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance.get(), &count, devices.data());
  for (auto d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    names.emplace_back(p.deviceName);
  }
  return names;
}

std::unique_ptr<Context> Context::create(const ContextOptions& options, std::string& error) {
  std::unique_ptr<Context> ctx(new Context());
  ctx->instance_ = createInstance(options.validation, error);
  if (!ctx->instance_) return nullptr;
  if (options.validation && !ctx->attachMessenger(error)) return nullptr;
  if (!ctx->choosePhysicalDevice(options.device, error)) return nullptr;
  if (!ctx->createDevice(error)) return nullptr;
  return ctx;
}

bool Context::attachMessenger(std::string& error) {
  auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance(), "vkCreateDebugUtilsMessengerEXT"));
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onMessage;
  info.pUserData = this;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  if (!createMessenger || createMessenger(instance(), &info, nullptr, &messenger) != VK_SUCCESS) {
    error = "cannot attach to the validation layers";
    return false;
  }
  messenger_ = UniqueDebugMessenger(instance(), messenger);
  return true;
}

bool Context::choosePhysicalDevice(const std::string& selector, std::string& error) {
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance(), &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance(), &count, devices.data());
  // With no selector, prefer a CPU device: results then match CI's lavapipe.
  std::stable_sort(devices.begin(), devices.end(), [](VkPhysicalDevice a, VkPhysicalDevice b) {
    VkPhysicalDeviceProperties pa, pb;
    vkGetPhysicalDeviceProperties(a, &pa);
    vkGetPhysicalDeviceProperties(b, &pb);
    return (pa.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) > (pb.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU);
  });
  std::string available;
  for (auto d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    available += (available.empty() ? "" : ", ") + std::string(p.deviceName);
    if (physical_ || p.apiVersion < VK_API_VERSION_1_1 || !matches(p, selector)) continue;
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(d, &families, props.data());
    for (std::uint32_t i = 0; i < families; ++i)
      if (props[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
        physical_ = d;
        queueFamily_ = i;
        properties_ = p;
        break;
      }
  }
  if (!physical_)
    error = "no Vulkan 1.1 device matches '" + selector + "' (available: " + (available.empty() ? "none" : available) + ")";
  return physical_ != VK_NULL_HANDLE;
}

bool Context::createDevice(std::string& error) {
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  float priority = 1.f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(physical_, &supported);
  VkPhysicalDeviceFeatures features{};
  samplerAnisotropy_ = samplerAnisotropyFor(properties_.deviceType, supported.samplerAnisotropy == VK_TRUE,
                                            properties_.limits.maxSamplerAnisotropy);
  features.samplerAnisotropy = samplerAnisotropy_ > 1.f ? VK_TRUE : VK_FALSE;
  features.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
  fragmentStoresAndAtomics_ = supported.fragmentStoresAndAtomics == VK_TRUE;
  std::uint32_t extensionCount = 0;
  vkEnumerateDeviceExtensionProperties(physical_, nullptr, &extensionCount, nullptr);
  std::vector<VkExtensionProperties> available(extensionCount);
  vkEnumerateDeviceExtensionProperties(physical_, nullptr, &extensionCount, available.data());
  auto has = [&](const char* name) {
    return std::any_of(available.begin(), available.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
  };
  std::vector<const char*> extensions;
  if (has(VK_KHR_CREATE_RENDERPASS_2_EXTENSION_NAME) && has(VK_KHR_DEPTH_STENCIL_RESOLVE_EXTENSION_NAME)) {
    extensions = {VK_KHR_CREATE_RENDERPASS_2_EXTENSION_NAME, VK_KHR_DEPTH_STENCIL_RESOLVE_EXTENSION_NAME};
    depthStencilResolve_ = true;
  }
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  deviceInfo.pEnabledFeatures = &features;
  deviceInfo.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  deviceInfo.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  if (vkCreateDevice(physical_, &deviceInfo, nullptr, &device) != VK_SUCCESS) {
    error = "cannot create a logical device on " + deviceName();
    return false;
  }
  device_ = UniqueDevice(device);
  vkGetDeviceQueue(device, queueFamily_, 0, &queue_);
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.queueFamilyIndex = queueFamily_;
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  VkCommandPool pool = VK_NULL_HANDLE;
  check(vkCreateCommandPool(device, &poolInfo, nullptr, &pool), "vkCreateCommandPool");
  commandPool_ = UniqueCommandPool(device, pool);
  return true;
}

Context::~Context() {
  if (borrowed_) device_.release();
  if (device_) vkDeviceWaitIdle(device_.get());
}

std::unique_ptr<Context> Context::borrow(VkPhysicalDevice physical, VkDevice device, std::uint32_t queueFamily,
                                         bool fragmentStoresAndAtomics) {
  std::unique_ptr<Context> ctx(new Context());
  ctx->borrowed_ = true;
  ctx->physical_ = physical;
  ctx->device_ = UniqueDevice(device);
  ctx->queueFamily_ = queueFamily;
  ctx->fragmentStoresAndAtomics_ = fragmentStoresAndAtomics;
  vkGetPhysicalDeviceProperties(physical, &ctx->properties_);
  vkGetPhysicalDeviceMemoryProperties(physical, &ctx->memory_);
  return ctx;
}

Context::MemoryLimits Context::memoryLimits() const {
  VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &maintenance3;
  vkGetPhysicalDeviceProperties2(physical_, &properties);
  MemoryLimits limits;
  limits.largestAllocation = maintenance3.maxMemoryAllocationSize;
  for (std::uint32_t i = 0; i < memory_.memoryHeapCount; ++i)
    if (memory_.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      limits.deviceLocalHeap = std::max(limits.deviceLocalHeap, memory_.memoryHeaps[i].size);
  return limits;
}

std::uint32_t Context::findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags flags) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & flags) == flags) return i;
  return UINT32_MAX;
}

UniqueCommandBuffer Context::beginOneTime() {
  if (borrowed_) throw std::logic_error("submitAndWait on an engine's device: record into its command buffers instead");
  VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  info.commandPool = commandPool_.get();
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer raw;
  check(vkAllocateCommandBuffers(device(), &info, &raw), "vkAllocateCommandBuffers");
  UniqueCommandBuffer cmd({device(), commandPool_.get()}, raw);
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(raw, &begin), "vkBeginCommandBuffer");
  return cmd;
}

void Context::endOneTime(VkCommandBuffer cmd) {
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  check(vkQueueWaitIdle(queue_), "vkQueueWaitIdle");
}

}  // namespace wg::vk
