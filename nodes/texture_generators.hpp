// Procedural textures generated at compile time (a texture declared with a
// "generator" instead of a file): deterministic and seamlessly tileable.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "nodes/texture_image.hpp"

namespace wg {

// Generated textures are square with a power-of-two side in this range.
inline constexpr int kMinGeneratorSize = 16;
inline constexpr int kMaxGeneratorSize = 2048;
bool isValidGeneratorSize(int size);

struct GeneratorOption {
  std::string_view name;
  enum class Kind { Number, Integer, Color3 } kind;
  std::array<float, 3> defaultValue;  // Number and Integer use element 0
  float min, max;                     // inclusive; for Color3, per component
  std::string_view doc;
};

struct GeneratorSpec {
  std::string_view name;
  std::string_view summary;
  std::vector<GeneratorOption> options;

  const GeneratorOption* findOption(std::string_view option) const;
};

// Every generator, in documentation order.
std::span<const GeneratorSpec> textureGenerators();
const GeneratorSpec* findTextureGenerator(std::string_view name);

// Checks `options`, a JSON object mapping the generator's option names to values (null
// counts as an empty object). The texture-level keys ("generator", "seed", "size",
// "wrap", "filter") are not options and are rejected like any unknown key. Returns ""
// when valid, else one line naming the option and the fix.
std::string validateGeneratorOptions(const GeneratorSpec& spec, const nlohmann::json& options);

// Generates a size x size image. The same (generator, seed, size, options) gives the
// same bytes on every run and every x86-64 machine: only integer hashing and IEEE
// float +, -, *, / and sqrt are used (no libm transcendentals, no global state); builds
// must not enable FMA contraction (GCC's ISO mode, used here, keeps it off). Every
// generator wraps its lattice by the tile's period, so the image tiles seamlessly.
// Throws std::invalid_argument if size is not valid or the options do not validate.
Image generateTexture(const GeneratorSpec& spec, std::uint32_t seed, int size,
                      const nlohmann::json& options);

}  // namespace wg
