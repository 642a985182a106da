#include "host/material_resources.hpp"

#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "compiler/json_document.hpp"
#include "compiler/literal.hpp"
#include "nodes/image_file.hpp"
#include "host/image/mip_chain.hpp"
#include "host/material_compile_error.hpp"
#include "nodes/texture_generators.hpp"
#include "vulkan/texture_sampler.hpp"

namespace wg {

vk::UniqueSampler createSampler(vk::Context& ctx, std::string_view wrap, std::string_view filter) {
  return vk::createSampler(ctx, wrap, wrap, filter, filter);
}

namespace {

Image textureImage(const vk::ReflectedTexture& t, const std::string& graphPath) {
  const auto& source = t.source;
  if (source.value("kind", "") == "file") {
    std::string path = (std::filesystem::path(graphPath).parent_path() / source.at("file").get<std::string>()).string();
    std::string error;
    auto image = loadImageFile(path, error);
    if (!image) {
      // The file changed since the compile read it (or a truncated image decodes only
      // now): bad input, reported as the compiler would.
      DiagnosticList diagnostics;
      diagnostics.report(DiagCode::TextureUnsupported,
                         locateInJsonFile(graphPath, appendPointer(appendPointer("/textures", t.name), "file")),
                         {quoteUserText(t.name), "file '" + quoteUserText(path) + "': " + quoteUserText(error)});
      throw MaterialCompileError(graphPath, diagnostics.items());
    }
    return *image;
  }
  const GeneratorSpec* spec = findTextureGenerator(source.at("generator").get<std::string>());
  if (!spec) throw std::runtime_error("texture '" + t.name + "': unknown generator");
  return generateTexture(*spec, source.at("seed").get<std::uint32_t>(), source.at("size").get<int>(),
                         source.value("options", nlohmann::json::object()));
}

// The parameter block with every member at its reflected default, or at the value
// `parameters` gives a float member.
std::vector<unsigned char> parameterBytes(const vk::ReflectedBlock& block, const std::map<std::string, float>& parameters) {
  std::vector<unsigned char> bytes(block.size, 0);
  for (const auto& m : block.members) {
    if (auto given = parameters.find(m.name); given != parameters.end() && m.defaultValue.is_number()) {
      std::memcpy(bytes.data() + m.offset, &given->second, sizeof given->second);
      continue;
    }
    const auto& d = m.defaultValue;
    if (d.is_boolean()) {
      std::uint32_t v = d.get<bool>() ? 1u : 0u;
      std::memcpy(bytes.data() + m.offset, &v, sizeof v);
    } else if (d.is_number()) {
      float v = d.get<float>();
      std::memcpy(bytes.data() + m.offset, &v, sizeof v);
    } else if (d.is_array()) {
      for (std::size_t i = 0; i < d.size(); ++i) {
        float v = d[i].get<float>();
        std::memcpy(bytes.data() + m.offset + 4 * i, &v, sizeof v);
      }
    }
  }
  return bytes;
}

}  // namespace

MaterialResources::MaterialResources(vk::Context& ctx, const std::string& graphPath, const CompileOptions& options,
                                     const std::map<std::string, float>& parameters)
    : ctx_(ctx), graphPath_(graphPath) {
  CompileResult result = compileMaterialFile(graphPath, options);
  if (!result.material) throw MaterialCompileError(graphPath, std::move(result.diagnostics.items()));
  compiled_ = std::move(*result.material);
  reflection_ = vk::parseReflection(compiled_.reflectionJson);
  if (!reflection_.material.members.empty()) {
    auto bytes = parameterBytes(reflection_.material, parameters);
    parameters_ = std::make_unique<vk::Buffer>(ctx, bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    parameters_->write(bytes.data(), bytes.size());
  }
  for (const auto& t : reflection_.textures) {
    // The full mip chain, averaged in linear light for sRGB textures.
    Image pixels = textureImage(t, graphPath);
    const VkFormat format = vk::textureFormat(t);
    const std::vector<Image> below = mipLevelsBelow(pixels, format == VK_FORMAT_R8G8B8A8_SRGB);
    std::vector<const std::vector<unsigned char>*> levels{&pixels.rgba};
    for (const Image& level : below) levels.push_back(&level.rgba);
    vk::Image2D image(ctx, static_cast<std::uint32_t>(pixels.width), static_cast<std::uint32_t>(pixels.height), format,
                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                      static_cast<std::uint32_t>(levels.size()));
    image.uploadLevels(ctx, levels);
    textures_.push_back({&t, std::move(image), vk::createSampler(ctx, t, vk::MipSampling::FullChain),
                         vk::createSampler(ctx, t, vk::MipSampling::BaseLevel)});
  }
}

std::size_t MaterialResources::textureBytes() const {
  std::size_t n = 0;
  for (const auto& t : textures_) n += t.image.byteSize();
  return n;
}

vk::MaterialPipeline& MaterialResources::pipeline(ShaderLanguage backend, const vk::PipelinePasses& passes) {
  auto& slot = pipelines_[backend];
  if (!slot) {
    const auto& vert = compiled_.stage(backend, ShaderStage::Vertex).spirv;
    const auto& frag = compiled_.stage(backend, ShaderStage::Fragment).spirv;
    slot = std::make_unique<vk::MaterialPipeline>(ctx_, reflection_, vert, frag, passes);
  }
  return *slot;
}

}  // namespace wg
