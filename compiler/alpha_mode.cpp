#include "compiler/alpha_mode.hpp"

namespace wg {

std::optional<AlphaMode> parseAlphaMode(std::string_view name) {
  if (name == "opaque") return AlphaMode::Opaque;
  if (name == "mask") return AlphaMode::Mask;
  if (name == "blend") return AlphaMode::Blend;
  return std::nullopt;
}

std::string_view alphaModeName(AlphaMode mode) {
  switch (mode) {
    case AlphaMode::Opaque: return "opaque";
    case AlphaMode::Mask: return "mask";
    case AlphaMode::Blend: return "blend";
  }
  return "opaque";
}

}  // namespace wg
