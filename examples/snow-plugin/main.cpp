// An engine's frame loop with weathergen's deformable snow: the engine creates the
// Vulkan device (validation layers on), owns two frames in flight (command buffer and
// fence each) and records DeformableSnow's work into each frame's command buffer before
// its own. A walker crosses the snow with a sled box dragged behind it (a mesh
// interactor), the camera follows, and on the last frame the "renderer" copies the
// surface image the snow material would sample. At the end it saves the prints (as a
// game keeping its world's state would), reports the prints it saw and writes the
// height channel as a PGM. Any Vulkan error, any validation message or a walk that
// left no prints makes it exit 1.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>
#include <weathergen/snow.hpp>

namespace {

constexpr std::uint32_t kFramesInFlight = 2;
constexpr int kFrames = 90;  // three seconds at 30 frames per second
constexpr float kFrameSeconds = 1.f / 30.f;
constexpr float kSnowDepth = 0.25f, kSnowSurface = 0.25f;  // snow on flat ground at y = 0

int validationMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  std::fprintf(stderr, "validation: %s\n", data->pMessage);
  ++validationMessages;
  return VK_FALSE;
}

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed: VkResult " + std::to_string(result));
}

struct Gpu {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  bool fragmentStoresAndAtomics = false;
  VkPhysicalDeviceMemoryProperties memory{};
};

// Instance with VK_LAYER_KHRONOS_validation, the CPU device (lavapipe) if there is one,
// a graphics queue, and fragmentStoresAndAtomics where the device has it.
void createGpu(Gpu& gpu) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "snow_plugin";
  app.apiVersion = VK_API_VERSION_1_1;
  const char* layer = "VK_LAYER_KHRONOS_validation";
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = onValidationMessage;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = &messengerInfo;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = 1;
  info.ppEnabledLayerNames = &layer;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = &extension;
  check(vkCreateInstance(&info, nullptr, &gpu.instance), "vkCreateInstance (are vulkan-validationlayers installed?)");
  auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(gpu.instance, "vkCreateDebugUtilsMessengerEXT"));
  check(createMessenger(gpu.instance, &messengerInfo, nullptr, &gpu.messenger), "vkCreateDebugUtilsMessengerEXT");

  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data());
  if (devices.empty()) throw std::runtime_error("no Vulkan device");
  gpu.physical = devices[0];
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) gpu.physical = d;
  }
  vkGetPhysicalDeviceMemoryProperties(gpu.physical, &gpu.memory);
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &count, families.data());
  auto graphics = std::find_if(families.begin(), families.end(),
                               [](const VkQueueFamilyProperties& f) { return f.queueFlags & VK_QUEUE_GRAPHICS_BIT; });
  if (graphics == families.end()) throw std::runtime_error("no graphics queue");
  gpu.queueFamily = std::uint32_t(graphics - families.begin());

  VkPhysicalDeviceFeatures supported{}, enabled{};
  vkGetPhysicalDeviceFeatures(gpu.physical, &supported);
  enabled.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
  gpu.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics == VK_TRUE;
  float priority = 1.f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = gpu.queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  deviceInfo.pEnabledFeatures = &enabled;
  check(vkCreateDevice(gpu.physical, &deviceInfo, nullptr, &gpu.device), "vkCreateDevice");
  vkGetDeviceQueue(gpu.device, gpu.queueFamily, 0, &gpu.queue);
}

// A host-visible buffer (the engine's own allocator would do this).
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
};

Buffer createBuffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage) {
  Buffer b;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  check(vkCreateBuffer(gpu.device, &info, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(gpu.device, b.buffer, &req);
  VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = UINT32_MAX;
  for (std::uint32_t i = 0; i < gpu.memory.memoryTypeCount && alloc.memoryTypeIndex == UINT32_MAX; ++i)
    if ((req.memoryTypeBits & (1u << i)) && (gpu.memory.memoryTypes[i].propertyFlags & want) == want)
      alloc.memoryTypeIndex = i;
  check(vkAllocateMemory(gpu.device, &alloc, nullptr, &b.memory), "vkAllocateMemory");
  check(vkBindBufferMemory(gpu.device, b.buffer, b.memory, 0), "vkBindBufferMemory");
  check(vkMapMemory(gpu.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  return b;
}

void destroyBuffer(const Gpu& gpu, Buffer& b) {
  vkDestroyBuffer(gpu.device, b.buffer, nullptr);
  vkFreeMemory(gpu.device, b.memory, nullptr);
}

float halfToFloat(std::uint16_t h) {
  int exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  float magnitude = exponent == 0 ? std::ldexp(float(mantissa), -24) : std::ldexp(float(mantissa | 0x400), exponent - 25);
  return (h & 0x8000) ? -magnitude : magnitude;
}

// The sled: a 0.4 x 0.2 x 0.6 m box whose underside rides 5 cm into the snow.
const float kSledCorners[8][3] = {{-0.2f, 0.f, -0.3f}, {0.2f, 0.f, -0.3f}, {0.2f, 0.f, 0.3f}, {-0.2f, 0.f, 0.3f},
                                  {-0.2f, 0.2f, -0.3f}, {0.2f, 0.2f, -0.3f}, {0.2f, 0.2f, 0.3f}, {-0.2f, 0.2f, 0.3f}};
const std::uint16_t kSledTriangles[36] = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 0, 4, 5, 0, 5, 1,
                                          1, 5, 6, 1, 6, 2, 2, 6, 7, 2, 7, 3, 3, 7, 4, 3, 4, 0};

int run() {
  Gpu gpu;
  createGpu(gpu);

  weathergen::snow::Settings settings;
  settings.resolution = 256;  // 10 m at 4 cm: small and cheap on lavapipe
  settings.tileTexels = 32;
  settings.framesInFlight = kFramesInFlight;
  std::string error;
  auto snow = weathergen::snow::DeformableSnow::create(
      {gpu.physical, gpu.device, gpu.queueFamily, gpu.fragmentStoresAndAtomics}, settings, error);
  if (!snow) throw std::runtime_error("DeformableSnow::create: " + error);

  Buffer sledVertices = createBuffer(gpu, sizeof kSledCorners, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  Buffer sledIndices = createBuffer(gpu, sizeof kSledTriangles, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  std::memcpy(sledVertices.mapped, kSledCorners, sizeof kSledCorners);
  std::memcpy(sledIndices.mapped, kSledTriangles, sizeof kSledTriangles);
  const std::uint32_t n = settings.resolution;
  const VkDeviceSize surfaceBytes = VkDeviceSize(n) * n * 4 * sizeof(std::uint16_t);
  Buffer surfaceCopy = createBuffer(gpu, surfaceBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = gpu.queueFamily;
  VkCommandPool pool;
  check(vkCreateCommandPool(gpu.device, &poolInfo, nullptr, &pool), "vkCreateCommandPool");
  VkCommandBuffer cmds[kFramesInFlight];
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = kFramesInFlight;
  check(vkAllocateCommandBuffers(gpu.device, &alloc, cmds), "vkAllocateCommandBuffers");
  VkFence fences[kFramesInFlight];
  for (VkFence& f : fences) {
    VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    check(vkCreateFence(gpu.device, &info, nullptr, &f), "vkCreateFence");
  }

  // The scripted walk: straight along +x at 1.4 m/s, a footfall every 0.75 m, the sled
  // 1.2 m behind the walker and the camera 2 m behind.
  int footfalls = 0;
  for (int frame = 0; frame < kFrames; ++frame) {
    std::uint32_t index = std::uint32_t(frame) % kFramesInFlight;
    check(vkWaitForFences(gpu.device, 1, &fences[index], VK_TRUE, UINT64_MAX), "vkWaitForFences");
    vkResetFences(gpu.device, 1, &fences[index]);

    float walked = 1.4f * kFrameSeconds * float(frame);
    std::vector<weathergen::snow::Capsule> capsules;
    for (; float(footfalls) * 0.75f <= walked; ++footfalls)
      capsules.push_back(weathergen::snow::footprint(float(footfalls) * 0.75f, footfalls % 2 ? -0.09f : 0.09f, 1.f, 0.f,
                                                     kSnowDepth));
    weathergen::snow::Mesh sled;
    sled.vertexBuffer = sledVertices.buffer;
    sled.indexBuffer = sledIndices.buffer;
    sled.indexType = VK_INDEX_TYPE_UINT16;
    sled.indexCount = 36;
    float sledX = walked - 1.2f, sledY = kSnowSurface - 0.05f;
    float model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, sledX, sledY, 0.f, 1};
    std::memcpy(sled.model, model, sizeof model);
    sled.footprintMin[0] = sledX - 0.2f, sled.footprintMin[1] = -0.3f;
    sled.footprintMax[0] = sledX + 0.2f, sled.footprintMax[1] = 0.3f;

    weathergen::snow::Frame work;
    work.frameIndex = index;  // its fence was waited on above
    work.cameraX = walked - 2.f;
    work.capsules = capsules.data();
    work.capsuleCount = capsules.size();
    work.meshes = &sled;
    work.meshCount = gpu.fragmentStoresAndAtomics ? 1 : 0;
    work.snowSurfaceHeight = kSnowSurface;
    work.snowDepth = kSnowDepth;
    work.refillMetresPerSecond = 0.01 / 3600.0;  // 1 cm an hour of fresh snow
    work.seconds = kFrameSeconds;
    work.readBackPrints = frame == kFrames - 1;  // the game saves its world after the walk

    VkCommandBuffer cmd = cmds[index];
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    std::string failed = snow->record(cmd, work);
    if (!failed.empty()) throw std::runtime_error("DeformableSnow::record: " + failed);
    // The engine's own work reads the shading inputs; here it copies the surface image
    // (SHADER_READ_ONLY_OPTIMAL between record() calls) on the last frame.
    if (frame == kFrames - 1) {
      weathergen::snow::ShadingInputs in = snow->shadingInputs();
      VkImageMemoryBarrier toCopy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
      toCopy.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      toCopy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
      toCopy.oldLayout = in.surfaceLayout;
      toCopy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      toCopy.srcQueueFamilyIndex = toCopy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      toCopy.image = in.surfaceImage;
      toCopy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                           nullptr, 1, &toCopy);
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {n, n, 1};
      vkCmdCopyImageToBuffer(cmd, in.surfaceImage, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, surfaceCopy.buffer, 1, &region);
      VkImageMemoryBarrier back = toCopy;
      back.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
      back.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
      back.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      back.newLayout = in.surfaceLayout;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0,
                           nullptr, 1, &back);
      VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                           nullptr);
    }
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    check(vkQueueSubmit(gpu.queue, 1, &submit, fences[index]), "vkQueueSubmit");
  }
  check(vkDeviceWaitIdle(gpu.device), "vkDeviceWaitIdle");
  std::string saved = snow->savePrints("snow_prints.wgprints");  // the last frame read the heights back
  if (!saved.empty()) throw std::runtime_error("DeformableSnow::savePrints: " + saved);

  // What the material would sample: height offsets below the surface are prints.
  weathergen::snow::ShadingInputs in = snow->shadingInputs();
  const auto* texels = static_cast<const std::uint16_t*>(surfaceCopy.mapped);
  int printed = 0;
  float deepest = 0.f;
  std::vector<unsigned char> grey(std::size_t(n) * n);
  for (std::size_t i = 0; i < grey.size(); ++i) {
    float height = halfToFloat(texels[4 * i]);
    printed += height < -0.01f;
    deepest = std::min(deepest, height);
    grey[i] = static_cast<unsigned char>(std::clamp(128.f + height * 800.f, 0.f, 255.f));
  }
  if (FILE* f = std::fopen("snow_surface.pgm", "wb")) {
    std::fprintf(f, "P5\n%u %u\n255\n", n, n);
    std::fwrite(grey.data(), 1, grey.size(), f);
    std::fclose(f);
  }
  std::printf("snow_plugin: %d frames, %d footfalls, sled %s; window at x %.2f m; %d texels pressed, deepest %.3f m; "
              "%zu tiles stored; %d validation messages\n",
              kFrames, footfalls, gpu.fragmentStoresAndAtomics ? "on" : "off (no fragmentStoresAndAtomics)",
              double(in.originX), printed, double(-deepest), snow->storedTiles(), validationMessages);

  snow.reset();  // the device is idle: nothing recorded is pending
  for (VkFence f : fences) vkDestroyFence(gpu.device, f, nullptr);
  vkDestroyCommandPool(gpu.device, pool, nullptr);
  destroyBuffer(gpu, surfaceCopy);
  destroyBuffer(gpu, sledIndices);
  destroyBuffer(gpu, sledVertices);
  vkDestroyDevice(gpu.device, nullptr);
  auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(gpu.instance, "vkDestroyDebugUtilsMessengerEXT"));
  destroyMessenger(gpu.instance, gpu.messenger, nullptr);
  vkDestroyInstance(gpu.instance, nullptr);
  if (printed < 50) throw std::runtime_error("the walk left too few prints");
  return validationMessages == 0 ? 0 : 1;
}

}  // namespace

int main() {
  try {
    return run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snow_plugin: %s\n", e.what());
    return 1;
  }
}
