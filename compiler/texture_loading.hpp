// The images of a material's declared textures, made once for CPU evaluation:
// procedural ones generated from their seed and options (the bytes the runtime
// uploads), image files decoded from disk, each with its declared sampler settings.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "compiler/material_graph.hpp"
#include "nodes/texture_sampling.hpp"

namespace wg {

struct TextureLoadResult {
  std::optional<TextureSampler> sampler;  // one image per declaration, in order
  std::string texture;  // on failure: the texture that could not be made
  std::string reason;   // and why, in one line, naming the file ("file 'a.png': file not found")
  std::string pointer;  // the texture's JSON pointer in the graph
};

// Fails when an image cannot be made, e.g. a file that changed or vanished since the
// graph was validated.
TextureLoadResult loadTextureSampler(const std::vector<TextureDecl>& textures);

}  // namespace wg
