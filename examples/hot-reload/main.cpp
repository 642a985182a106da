// What an engine's editor does when an artist edits a material: compile the graph from
// memory with weathergen::compile, build the Vulkan descriptor-set layouts and vertex
// format from the returned reflection JSON alone, and create the graphics pipelines from
// the returned SPIR-V. Then the "hot reload": edit the graph, compile it again and
// rebuild. Runs on lavapipe with the validation layers; any compile error, Vulkan error
// or validation message makes it exit 1.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include <weathergen/weathergen.hpp>

namespace {

using nlohmann::json;

// A small material as an editor would hold it: a tinted fBm texture, no weather yet.
constexpr const char* kGraph = R"({
  "name": "painted_crate",
  "parameters": {
    "tint": {"type": "vec3", "default": [0.55, 0.32, 0.2]},
    "roughness": {"type": "float", "default": 0.6}
  },
  "textures": {"grain": {"generator": "fbm", "seed": 3, "size": 64, "scale": 4, "octaves": 3}},
  "nodes": [
    {"id": "uv", "op": "texcoord"},
    {"id": "grain", "op": "sample", "inputs": {"texture": "grain", "uv": "uv.out"}},
    {"id": "tint", "op": "parameter", "param": "tint"},
    {"id": "albedo", "op": "multiply", "inputs": {"a": "grain.rgb", "b": "tint.out"}},
    {"id": "roughness", "op": "parameter", "param": "roughness"}
  ],
  "weather": {"preset": "none"},
  "output": {"baseColor": "albedo.out", "roughness": "roughness.out"}
})";

constexpr VkFormat kColourFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

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
  VkDevice device = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
};

// Instance with VK_LAYER_KHRONOS_validation, the CPU device (lavapipe), a device with a
// graphics queue, and a colour + depth render pass for the pipelines.
void createGpu(Gpu& gpu) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  const char* validation = "VK_LAYER_KHRONOS_validation";
  if (std::none_of(layers.begin(), layers.end(), [&](const auto& l) { return std::string(l.layerName) == validation; }))
    throw std::runtime_error("VK_LAYER_KHRONOS_validation is not installed (vulkan-validationlayers)");

  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = onValidationMessage;
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "weathergen hot-reload example";
  app.apiVersion = VK_API_VERSION_1_1;
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instanceInfo.pNext = &messengerInfo;  // also reports on vkCreateInstance and vkDestroyInstance
  instanceInfo.pApplicationInfo = &app;
  instanceInfo.enabledLayerCount = 1;
  instanceInfo.ppEnabledLayerNames = &validation;
  instanceInfo.enabledExtensionCount = 1;
  instanceInfo.ppEnabledExtensionNames = &extension;
  check(vkCreateInstance(&instanceInfo, nullptr, &gpu.instance), "vkCreateInstance");
  auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(gpu.instance, "vkCreateDebugUtilsMessengerEXT"));
  check(createMessenger(gpu.instance, &messengerInfo, nullptr, &gpu.messenger), "vkCreateDebugUtilsMessengerEXT");

  vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data());
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(d, &properties);
    if (properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU && !physical) {
      physical = d;
      std::printf("device: %s\n", properties.deviceName);
    }
  }
  if (!physical) throw std::runtime_error("no CPU Vulkan device (lavapipe: mesa-vulkan-drivers)");

  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  auto graphics = std::find_if(families.begin(), families.end(),
                               [](const auto& f) { return f.queueFlags & VK_QUEUE_GRAPHICS_BIT; });
  if (graphics == families.end()) throw std::runtime_error("the CPU device has no graphics queue");
  float priority = 1.f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = static_cast<std::uint32_t>(graphics - families.begin());
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  check(vkCreateDevice(physical, &deviceInfo, nullptr, &gpu.device), "vkCreateDevice");

  VkAttachmentDescription attachments[2] = {};
  VkFormat formats[2] = {kColourFormat, kDepthFormat};
  for (int i = 0; i < 2; ++i) {
    attachments[i].format = formats[i];
    attachments[i].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[i].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[i].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  }
  attachments[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
  subpass.pDepthStencilAttachment = &depth;
  VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  passInfo.attachmentCount = 2;
  passInfo.pAttachments = attachments;
  passInfo.subpassCount = 1;
  passInfo.pSubpasses = &subpass;
  check(vkCreateRenderPass(gpu.device, &passInfo, nullptr, &gpu.renderPass), "vkCreateRenderPass");
}

void destroyGpu(Gpu& gpu) {
  if (gpu.device) {
    vkDestroyRenderPass(gpu.device, gpu.renderPass, nullptr);
    vkDestroyDevice(gpu.device, nullptr);
  }
  if (gpu.messenger) {
    auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(gpu.instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroyMessenger(gpu.instance, gpu.messenger, nullptr);
  }
  if (gpu.instance) vkDestroyInstance(gpu.instance, nullptr);
}

// Vertex formats of the reflected input types ("vertexInputs" only uses these).
std::pair<VkFormat, std::uint32_t> vertexFormat(const std::string& type) {
  if (type == "float") return {VK_FORMAT_R32_SFLOAT, 4};
  if (type == "vec2") return {VK_FORMAT_R32G32_SFLOAT, 8};
  if (type == "vec3") return {VK_FORMAT_R32G32B32_SFLOAT, 12};
  if (type == "vec4") return {VK_FORMAT_R32G32B32A32_SFLOAT, 16};
  throw std::runtime_error("reflection: no vertex format for type " + type);
}

// Everything one compile produces on the GPU; rebuilt on every hot reload.
struct MaterialPipelines {
  std::vector<VkDescriptorSetLayout> setLayouts;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  std::vector<VkPipeline> pipelines;  // one per shader language
};

VkShaderModule shaderModule(VkDevice device, const std::vector<std::uint32_t>& spirv) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size() * sizeof(std::uint32_t);
  info.pCode = spirv.data();
  VkShaderModule module;
  check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

VkPipeline createPipeline(const Gpu& gpu, VkPipelineLayout layout, const weathergen::Stage& vertex,
                          const weathergen::Stage& fragment, const json& reflection) {
  // The vertex format: one interleaved buffer, attributes in location order.
  json inputs = reflection.at("vertexInputs");
  std::sort(inputs.begin(), inputs.end(), [](const json& a, const json& b) { return a.at("location") < b.at("location"); });
  std::vector<VkVertexInputAttributeDescription> attributes;
  std::uint32_t stride = 0;
  for (const json& input : inputs) {
    auto [format, size] = vertexFormat(input.at("type"));
    attributes.push_back({input.at("location"), 0, format, stride});
    stride += size;
  }
  VkVertexInputBindingDescription binding{0, stride, VK_VERTEX_INPUT_RATE_VERTEX};
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(attributes.size());
  vertexInput.pVertexAttributeDescriptions = attributes.data();

  VkShaderModule modules[2] = {shaderModule(gpu.device, vertex.spirv), shaderModule(gpu.device, fragment.spirv)};
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  for (int i = 0; i < 2; ++i) {
    stages[i].module = modules[i];
    stages[i].pName = "main";
  }
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  // Render state is the engine's choice; the reflection says what the material needs.
  const bool twoSided = reflection.at("alphaTested").get<bool>() || reflection.at("doubleSided").get<bool>();
  const bool blended = reflection.at("alphaMode") == "blend";  // straight alpha, no depth writes
  raster.cullMode = twoSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = blended ? VK_FALSE : VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.blendEnable = blended ? VK_TRUE : VK_FALSE;
  blendAttachment.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
  blendAttachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blendAttachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blendAttachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blendAttachment.colorWriteMask = 0xF;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blendAttachment;
  VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamicStates;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  info.renderPass = gpu.renderPass;
  VkPipeline pipeline;
  VkResult result = vkCreateGraphicsPipelines(gpu.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  for (VkShaderModule m : modules) vkDestroyShaderModule(gpu.device, m, nullptr);
  check(result, "vkCreateGraphicsPipelines");
  return pipeline;
}

// Descriptor-set layouts from the reflection: every uniform block with members is a
// uniform buffer, every texture (the material's and the weather maps) a sampled image
// plus a sampler, each at its reflected set and binding.
MaterialPipelines createMaterial(const Gpu& gpu, const weathergen::Result& compiled) {
  json reflection = json::parse(compiled.reflectionJson);
  std::vector<std::vector<VkDescriptorSetLayoutBinding>> sets;
  auto add = [&](const json& item, const char* bindingKey, VkDescriptorType type) {
    std::uint32_t set = item.at("set");
    if (set >= sets.size()) sets.resize(set + 1);
    sets[set].push_back({item.at(bindingKey), type, 1, kStages, nullptr});
  };
  for (const json& block : reflection.at("blocks"))
    if (!block.at("members").empty())  // a material without parameters has no block in its shaders
      add(block, "binding", VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  for (const char* list : {"textures", "weatherMaps"})
    for (const json& texture : reflection.at(list)) {
      add(texture, "binding", VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
      add(texture, "samplerBinding", VK_DESCRIPTOR_TYPE_SAMPLER);
    }

  MaterialPipelines material;
  for (const auto& bindings : sets) {
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = static_cast<std::uint32_t>(bindings.size());
    info.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(gpu.device, &info, nullptr, &material.setLayouts.emplace_back()),
          "vkCreateDescriptorSetLayout");
  }
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = static_cast<std::uint32_t>(material.setLayouts.size());
  layoutInfo.pSetLayouts = material.setLayouts.data();
  check(vkCreatePipelineLayout(gpu.device, &layoutInfo, nullptr, &material.layout), "vkCreatePipelineLayout");

  // stages: glsl vert, glsl frag, hlsl vert, hlsl frag. Both languages share the layout.
  for (std::size_t i = 0; i + 1 < compiled.stages.size(); i += 2)
    material.pipelines.push_back(createPipeline(gpu, material.layout, compiled.stages[i], compiled.stages[i + 1], reflection));

  // A weathered material samples the shared noise texture: the engine uploads its texels
  // once (R8G8B8A8_UNORM, a repeating linear sampler, maxLod 0) and binds it in set 0.
  for (const json& map : reflection.at("weatherMaps"))
    if (map.at("name") == "weatherNoise") {
      weathergen::NoiseTexture noise = weathergen::weatherNoiseTexture();
      if (noise.width <= 0 || noise.rgba8.size() != std::size_t(noise.width) * std::size_t(noise.height) * 4)
        throw std::runtime_error("weatherNoiseTexture() returned no texels");
      std::printf("weatherNoise: %dx%d RGBA8 from weathergen::weatherNoiseTexture()\n", noise.width, noise.height);
    }

  std::printf("%s %s: %zu pipelines;", compiled.name.c_str(), compiled.contentHash.c_str(), material.pipelines.size());
  for (std::size_t s = 0; s < sets.size(); ++s) std::printf(" set %zu: %zu bindings;", s, sets[s].size());
  std::printf(" %zu vertex inputs\n", reflection.at("vertexInputs").size());
  return material;
}

void destroyMaterial(const Gpu& gpu, MaterialPipelines& material) {
  for (VkPipeline p : material.pipelines) vkDestroyPipeline(gpu.device, p, nullptr);
  vkDestroyPipelineLayout(gpu.device, material.layout, nullptr);
  for (VkDescriptorSetLayout l : material.setLayouts) vkDestroyDescriptorSetLayout(gpu.device, l, nullptr);
  material = {};
}

// Diagnostics are values: an editor lists them next to the graph.
weathergen::Result compile(const json& graph) {
  weathergen::Result result = weathergen::compile("painted_crate.json", graph.dump());
  for (const weathergen::Diagnostic& d : result.diagnostics)
    std::printf("  %s:%d:%d: %s %s: %s\n", d.file.c_str(), d.line, d.column, d.severity.c_str(), d.code.c_str(),
                d.message.c_str());
  return result;
}

void run(Gpu& gpu) {
  weathergen::initialize();
  std::printf("weathergen %s\n", weathergen::version().c_str());
  json graph = json::parse(kGraph);
  weathergen::Result first = compile(graph);
  if (!first.ok) throw std::runtime_error("the material does not compile");
  MaterialPipelines material = createMaterial(gpu, first);

  // The artist breaks the graph: the editor shows the diagnostic and keeps the old pipelines.
  json broken = graph;
  broken["nodes"][1]["op"] = "smaple";
  std::printf("broken edit:\n");
  if (compile(broken).ok) throw std::runtime_error("a graph with an unknown op compiled");
  std::printf("  kept the previous pipelines\n");

  // The artist turns weather on and adds a cracks texture: new bindings in both sets.
  graph["weather"]["preset"] = "rock";
  graph["textures"]["cracks"] = {{"generator", "voronoi"}, {"seed", 5}, {"size", 64}, {"scale", 6}};
  graph["nodes"].push_back({{"id", "cracks"}, {"op", "sample"}, {"inputs", {{"texture", "cracks"}, {"uv", "uv.out"}}}});
  graph["nodes"].push_back({{"id", "cracked"}, {"op", "multiply"}, {"inputs", {{"a", "albedo.out"}, {"b", "cracks.rgb"}}}});
  graph["output"]["baseColor"] = "cracked.out";
  weathergen::Result second = compile(graph);
  if (!second.ok) throw std::runtime_error("the edited material does not compile");
  if (second.contentHash == first.contentHash) throw std::runtime_error("the edit did not change the material");
  MaterialPipelines reloaded = createMaterial(gpu, second);
  vkDeviceWaitIdle(gpu.device);  // an engine waits for frames still using the old pipelines
  destroyMaterial(gpu, material);
  destroyMaterial(gpu, reloaded);
}

}  // namespace

int main() {
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);  // keeps stdout and stderr in order in logs
  Gpu gpu;
  int status = 0;
  try {
    createGpu(gpu);
    run(gpu);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hot_reload: %s\n", e.what());
    status = 1;
  }
  destroyGpu(gpu);
  if (validationMessages > 0) {
    std::fprintf(stderr, "hot_reload: %d validation message(s)\n", validationMessages);
    status = 1;
  }
  if (status == 0) std::printf("hot_reload: pipelines built, hot reload done, no validation messages\n");
  return status;
}
