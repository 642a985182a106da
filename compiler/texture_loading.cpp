#include "compiler/texture_loading.hpp"

#include <stdexcept>

#include "nodes/image_file.hpp"
#include "nodes/texture_generators.hpp"

namespace wg {

TextureLoadResult loadTextureSampler(const std::vector<TextureDecl>& textures) {
  TextureSampler sampler;
  for (const TextureDecl& decl : textures) {
    std::string reason;
    std::optional<Image> image;
    if (!decl.file.empty()) {
      image = loadImageFile(decl.resolvedPath, reason);
      if (!image) reason = "file '" + decl.file + "': " + reason;
    } else if (const GeneratorSpec* spec = findTextureGenerator(decl.generator)) {
      // The loader validated size and options; generateTexture rechecks and throws.
      try {
        image = generateTexture(*spec, decl.seed, decl.size, decl.options);
      } catch (const std::invalid_argument& e) {
        reason = e.what();
      }
    } else {
      reason = "unknown generator '" + decl.generator + "'";
    }
    if (!image) return {std::nullopt, decl.name, reason, decl.file.empty() ? decl.pointer : decl.pointer + "/file"};
    sampler.images.push_back(std::move(*image));
    sampler.states.push_back(decl.sampler);
  }
  return {std::move(sampler), {}, {}, {}};
}

}  // namespace wg
